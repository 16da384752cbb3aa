#!/usr/bin/env python3
"""Writes the bundled triangle cases: cases/triangles/*.json and cases/readme.json.

Python 3 standard library only. Geometry is built with fractions.Fraction, so
every coordinate is written exactly as it was meant:

- integers as JSON integers,
- terminating decimals as JSON numbers (2.5, 0.00390625),
- other rationals as strings "p/q".

Irrational geometry (rotations, circles) is rounded once, to a decimal with 6
fractional digits, and every vertex that two triangles share is computed once
and written identically in both, so that meshes stay closed after snapping.

`expect.samples_covered` is only given where the count follows from the
geometry by hand (a canvas lying strictly inside a mesh, an axis-aligned
rectangle whose sides run through sample centres, ...). The small exact
checker (`--check`) recomputes those counts
independently of rastercheck, and also proves that every tie case is sensitive
to the fill rule and every snapping case to the tie rule of the snapping.

The cases are in casegen/triangles/cases.py, the readme in
casegen/triangles/readme.py and the checker in casegen/triangles/check.py;
this file writes them.

Usage: python3 tools/gen_cases.py [--check]   (run from anywhere)
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from casegen import ROOT  # noqa: E402
from casegen.casefile import render  # noqa: E402
from casegen.triangles.cases import CASES  # noqa: E402
from casegen.triangles.check import check  # noqa: E402
from casegen.triangles.readme import write_readme  # noqa: E402

OUT_DIR = os.path.join(ROOT, "cases", "triangles")


def main():
    names = [c["name"] for c in CASES]
    assert len(names) == len(set(names)), "duplicate case names"
    os.makedirs(OUT_DIR, exist_ok=True)
    for c in CASES:
        with open(os.path.join(OUT_DIR, c["name"] + ".json"), "w") as f:
            f.write(render(c, c["expect"]))
    write_readme()
    print("wrote %d cases to %s and cases/readme.json" % (len(CASES), OUT_DIR))
    if "--check" in sys.argv[1:]:
        sys.exit(0 if check() else 1)


if __name__ == "__main__":
    main()
