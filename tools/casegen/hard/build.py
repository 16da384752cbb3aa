"""The hard cases' model: the coordinate limit, lines with a last pixel, the
registry of triangle and line cases with its checks, and the output folder.
Triangles and vertices are casefile's; the cases are in cases.py.
"""

import os
from fractions import Fraction as F

from casegen import ROOT
from casegen.casefile import pos_of, vjson

OUT_DIR = os.path.join(ROOT, "cases", "hard")

HALF = F(1, 2)
COORD_LIMIT = 32768


def add(p, q, k=1):
    return (p[0] + k * q[0], p[1] + k * q[1])


class Line:
    def __init__(self, a, b, last_pixel=None):
        self.v = [a, b]
        self.last_pixel = last_pixel

    def json(self):
        d = {"line": [vjson(v) for v in self.v]}
        if self.last_pixel is not None:
            d["last_pixel"] = self.last_pixel
        return d


CASES = []


def case(name, description, width, height, prims, bits=8, fill_rule="top-left", cull="none",
         watertight=False, checks=(), long_line=False):
    """Registers a case. `checks` are claims the checker must prove (see
    check_claims)."""
    if not long_line:
        assert 1 <= width <= 128 and 1 <= height <= 128, name
    for p in prims:
        for v in p.v:
            for q in pos_of(v):
                assert abs(q) <= COORD_LIMIT, (name, q)
    CASES.append(dict(name=name, description=description, width=width, height=height,
                      prims=prims, bits=bits, fill_rule=fill_rule, cull=cull,
                      watertight=watertight, checks=list(checks)))

