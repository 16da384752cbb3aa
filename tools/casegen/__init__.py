"""The shared pieces of the case generators (tools/gen_*.py).

Python 3 standard library only. What lives here is used by more than one
generator: exact JSON numbers (exactjson.py), static primitives and the
writer of a static case file (casefile.py), snapping with every tie mode
(snapping.py), the sample patterns and SplitMix64 (samples.py). Each
generator's own cases and exact checker sit in its subpackage (triangles/,
lines/, antialias/, hard/, motion/); the entry points in tools/ only parse
their flags and write the files.
"""

import os

# The repository root: tools/casegen/__init__.py is two folders below it.
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
