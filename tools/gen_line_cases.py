#!/usr/bin/env python3
"""Writes the bundled line cases: cases/lines/*.json (SPEC.md section 4).

Python 3 standard library only. Geometry is exact (fractions.Fraction) and is
written as in tools/gen_cases.py:

- integers as JSON integers,
- terminating decimals as JSON numbers (3.1015625),
- other rationals as strings "p/q".

The diamond-exit cases (diamond_*.json, SPEC.md section 4.2) are section 12.

Every case has a description saying what it tests and why it is hard.
`expect.samples_covered` is derived by the small exact checker at the bottom of
this file, an implementation of the four line rules of SPEC.md section 4 and
of the line interpolation of section 5 written from the spec alone (it shares
no code with rastercheck). It runs with `--check`, which also proves that each
case is sensitive to what it claims to test (a flipped tie rule, the fill rule,
snapping, x-major at slope 1, major vs projected parameter, linear vs
perspective), that reversed lines light the same pixels, and that strips with
`last_pixel: exclude` cover no sample twice.

`--compare` additionally runs `./target/release/rastercheck run cases/lines -r
reference` (target/debug when there is no release build) and checks that the reference's coverage count of every case equals
the checker's. `--compare-dump FILE` compares whole frames (coverage, last
primitive, depth, attributes) with a JSON dump of the reference's frames: a
list of {"path", "width", "height", "coverage", "last", "depth",
"attributes"}, as written by a throwaway program that calls
rastercheck::reference::Reference on each case.

Usage: python3 tools/gen_line_cases.py [--check] [--compare] [--compare-dump FILE]
"""

import json
import math
import os
import re
import subprocess
import sys
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exactjson import exact, js, num  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT_DIR = os.path.join(ROOT, "cases", "lines")

HALF = F(1, 2)

# ---------------------------------------------------------------------------
# Exact number formatting and a hand-rolled JSON writer (as in gen_cases.py).


def P(x, y):
    return (exact(x), exact(y))


# ---------------------------------------------------------------------------
# Case building.


class V:
    """A vertex with depth, w and attributes (the object form)."""

    def __init__(self, x, y, z=None, w=None, attributes=None):
        self.x, self.y = exact(x), exact(y)
        self.z = None if z is None else exact(z)
        self.w = None if w is None else exact(w)
        self.attributes = None if attributes is None else [exact(a) for a in attributes]

    def pos(self):
        return (self.x, self.y)

    def json(self):
        d = {"position": [self.x, self.y]}
        if self.z is not None:
            d["z"] = self.z
        if self.w is not None:
            d["w"] = self.w
        if self.attributes is not None:
            d["attributes"] = list(self.attributes)
        return d


def pos_of(v):
    return v.pos() if isinstance(v, V) else (exact(v[0]), exact(v[1]))


def vjson(v):
    return v.json() if isinstance(v, V) else [exact(v[0]), exact(v[1])]


class Line:
    def __init__(self, a, b, rule="midpoint", width=None, last_pixel=None, parameter=None,
                 interpolation=None):
        assert rule in ("midpoint", "rectangle", "parallelogram", "diamond-exit")
        assert width is None or rule not in ("midpoint", "diamond-exit")
        assert last_pixel is None or rule == "midpoint"
        self.v = [a, b]
        self.rule = rule
        self.width = None if width is None else exact(width)
        self.last_pixel = last_pixel
        self.parameter = parameter
        self.interpolation = interpolation

    def reversed(self):
        return Line(self.v[1], self.v[0], self.rule, self.width, self.last_pixel, self.parameter,
                    self.interpolation)

    def with_(self, **kw):
        d = dict(rule=self.rule, width=self.width, last_pixel=self.last_pixel,
                 parameter=self.parameter, interpolation=self.interpolation)
        d.update(kw)
        return Line(self.v[0], self.v[1], **d)

    def json(self):
        d = {"line": [vjson(v) for v in self.v], "rule": self.rule}
        if self.width is not None:
            d["width"] = self.width
        if self.last_pixel is not None:
            d["last_pixel"] = self.last_pixel
        if self.parameter is not None:
            d["parameter"] = self.parameter
        if self.interpolation is not None:
            d["interpolation"] = self.interpolation
        return d


def mid(a, b, **kw):
    return Line(P(*a) if not isinstance(a, V) else a, P(*b) if not isinstance(b, V) else b,
                "midpoint", **kw)


def rect(a, b, width=None, **kw):
    return Line(P(*a) if not isinstance(a, V) else a, P(*b) if not isinstance(b, V) else b,
                "rectangle", width=width, **kw)


def para(a, b, width=None, **kw):
    return Line(P(*a) if not isinstance(a, V) else a, P(*b) if not isinstance(b, V) else b,
                "parallelogram", width=width, **kw)


def dia(a, b, **kw):
    return Line(P(*a) if not isinstance(a, V) else a, P(*b) if not isinstance(b, V) else b,
                "diamond-exit", **kw)


CASES = []
LONG_CASES = {"midpoint_long_shallow_2048", "midpoint_long_steep_2048", "rectangle_width_64",
              "diamond_long_shallow_1200", "diamond_long_steep_1200"}


def case(name, description, width, height, prims, bits=8, fill_rule="top-left", covered=True,
         checks=(), pixels=None):
    """Registers a case.

    covered: write expect.samples_covered, as counted by the checker.
    checks: extra claims the checker must prove, each a tuple:
      ("ties",)                 a flipped midpoint tie rule changes coverage
      ("fill_rule",)            the flipped fill rule changes coverage
      ("snap",)                 some other rounding of the snapping changes coverage
      ("xmajor_at_one",)        treating |slope| = 1 as y-major changes coverage
      ("same_as", other_name)   same coverage counts and same covered set as another case
      ("max_coverage", k)       no sample is covered more than k times
      ("uncovered", x, y)       pixel (x, y) is not covered
      ("min_coverage_max", k)   some sample is covered at least k times
      ("parameter",)            major vs projected parameter changes some value
      ("perspective",)          linear vs perspective changes some value
      ("clamp",)                some sample's parameter is clamped
      ("diamond", variant)      a wrong diamond (see diamond_shape) changes coverage
      ("differs_from", name)    the covered set differs from another case's
      ("lit", i, x, y)          primitive i lights pixel (x, y); ("unlit", i, x, y) it does not
    pixels: {primitive index: [(x, y), ...]} the exact pixel list the
      description states, verified by the checker.
    """
    if name not in LONG_CASES:
        assert 1 <= width <= 64 and 1 <= height <= 64, name
    assert width * height <= 2**20, name
    CASES.append(dict(name=name, description=description, width=width, height=height,
                      prims=prims, bits=bits, fill_rule=fill_rule, covered=covered,
                      checks=list(checks), pixels=pixels or {}))


def render(c, expect):
    lines = ["{"]
    lines.append('  "name": %s,' % js(c["name"]))
    lines.append('  "description": %s,' % js(c["description"]))
    lines.append('  "canvas": %s,' % js({"width": c["width"], "height": c["height"]}))
    lines.append('  "rules": %s,' % js({"subpixel_bits": c["bits"], "fill_rule": c["fill_rule"],
                                          "cull": "none"}))
    lines.append('  "primitives": [')
    lines.append(",\n".join("    " + js(p.json()) for p in c["prims"]))
    if expect:
        lines.append("  ],")
        lines.append('  "expect": %s' % js(expect))
    else:
        lines.append("  ]")
    lines.append("}")
    text = "\n".join(lines) + "\n"
    json.loads(text)
    return text


def fmt_px(px):
    return " ".join("(%d,%d)" % p for p in px)


# ---------------------------------------------------------------------------
# 1. Worked examples (SPEC.md section 4 points at these three files).

WE_MID_A = [(1, 1), (2, 1), (3, 2), (4, 2), (5, 3), (6, 3), (7, 4), (8, 4), (9, 5)]
WE_MID_B = [(2, 6), (2, 7), (3, 8), (3, 9), (4, 10)]
case("midpoint_worked_example",
     "Worked example of the midpoint rule (SPEC 4.1), two lines on a 12x12 canvas. "
     "Line 1 runs from the pixel centre (1.5, 1.5) to the pixel centre (9.5, 5.5): d = (8, 4), |dx| >= |dy|, "
     "so it is x-major and draws one pixel per column. The columns drawn are those whose centre c = i + 0.5 "
     "lies in the closed interval [1.5, 9.5]: columns 1 to 9, both end columns included (last_pixel: include). "
     "In column i the line's height is y(c) = 1.5 + (c - 1.5) * 4/8, and the row drawn is ceil(y(c)) - 1, the "
     "row whose centre is nearest. Column 1: y = 1.5, row 1. Column 2: y = 2.0, an integer: the centres of "
     "rows 1 (1.5) and 2 (2.5) are equally near, a tie, and the rule gives it to the UPPER row (smaller y), "
     "row 1 = ceil(2.0) - 1. Column 3: y = 2.5, row 2. Column 4: y = 3.0, tie again, upper row 2. And so on: "
     "every even column is a tie, so the line draws pixel pairs " + fmt_px(WE_MID_A) + ". A Bresenham that "
     "breaks ties downwards draws (2,2) (4,3) (6,4) (8,5) instead. "
     "Line 2 runs from (2.5, 6.5) to (4.5, 10.5): d = (2, 4), |dy| > |dx|, so it is y-major and the axes swap: "
     "rows 6 to 10 (centres 6.5 to 10.5), and in row j the column ceil(x(r)) - 1 with x(r) = 2.5 + (r - 6.5) * 2/4. "
     "Row 6: x = 2.5, column 2. Row 7: x = 3.0, a tie between columns 2 and 3, which goes to the LEFT column 2. "
     "Row 8: x = 3.5, column 3. Row 9: x = 4.0, tie, left column 3. Row 10: x = 4.5, column 4. Pixels: "
     + fmt_px(WE_MID_B) + ". Drawing either line from its other end gives the same pixels: the rule depends "
     "only on the points of the segment. 14 samples in all.",
     12, 12, [mid((1.5, 1.5), (9.5, 5.5)), mid((2.5, 6.5), (4.5, 10.5))],
     checks=[("ties",)], pixels={0: WE_MID_A, 1: WE_MID_B})

WE_RECT = [(1, 1), (1, 2), (2, 1), (2, 2), (2, 3), (3, 2), (3, 3), (4, 3), (4, 4), (5, 3), (5, 4),
           (5, 5), (6, 4), (6, 5), (6, 6), (7, 5), (7, 6), (8, 6), (8, 7), (9, 6)]
case("rectangle_worked_example",
     "Worked example of the rectangle rule (SPEC 4.3): one line of width 2 from the pixel centre v0 = (1.5, 1.5) "
     "to the pixel centre v1 = (9.5, 7.5) on a 12x10 canvas. d = v1 - v0 = (8, 6), so |d|^2 = 100 and |d| = 10. "
     "A sample p is covered when, with q = p - v0, the projection q.d = 8qx + 6qy lies in [0, 100] (between "
     "the two end caps, which are perpendicular to the line through v0 and v1) and the cross product "
     "q x d = 6qx - 8qy satisfies |q x d| <= (width/2)|d| = 10, compared squared: (6qx - 8qy)^2 <= 100 (the two "
     "long sides, 1 pixel either side of the segment). Because v0 is a pixel centre, q is a pair of integers "
     "for every sample, so many samples land exactly ON the border, and the fill rule decides them. Each border "
     "edge is classified by its outward normal n: the side where q x d = +10 has n = (dy, -dx) = (6, -8), nx > 0, "
     "a RIGHT edge; the side q x d = -10 has n = (-6, 8), a LEFT edge; the cap at v0 has n = -d = (-8, -6), a LEFT "
     "edge; the cap at v1 has n = d, a RIGHT edge. Under top-left, left edges own their samples and right edges "
     "do not. Examples: v0's own sample (1,1) has q = (0,0), on the v0 cap (left): covered. Sample (4,2): "
     "q = (3,1), q.d = 30, q x d = 18 - 8 = 10: on the right side, not covered. Sample (2,3): q = (1,2), "
     "q x d = -10, on the left side: covered. Sample (9,7) is v1 itself: q = d, on the v1 cap (right): NOT "
     "covered, so the rectangle stops one sample short there; its neighbour (9,6) has q = (8,5), q.d = 94, "
     "q x d = 8: inside. Sample (10,7): q = (9,6), q.d = 108 > 100, beyond the v1 cap. Sample (3,1): q = (2,0), "
     "q x d = 12 > 10, outside. The 20 samples covered: " + fmt_px(WE_RECT) + ". Note the apparent thickness: the "
     "vertical extent of the band is width * |d|/|dx| = 2.5 pixels, so full columns get 2 or 3 samples.",
     12, 10, [rect((1.5, 1.5), (9.5, 7.5), width=2)], checks=[("fill_rule",)], pixels={0: WE_RECT})

WE_PARA = [(1, 1), (1, 2), (2, 2), (2, 3), (3, 2), (3, 3), (4, 3), (4, 4), (5, 3), (5, 4), (6, 4),
           (6, 5), (7, 4), (7, 5), (8, 5), (8, 6)]
case("parallelogram_worked_example",
     "Worked example of the parallelogram rule (SPEC 4.4): one line of width 2 from (1.5, 2) to (9.5, 6) on "
     "a 12x9 canvas. d = (8, 4) is x-major, so the line is the segment swept vertically: a sample p is covered "
     "when p.x lies in [1.5, 9.5] and |p.y - y(p.x)| <= 1, with y(x) = 2 + (x - 1.5)/2. Its ends are vertical "
     "(x = 1.5 and x = 9.5) and its width is measured vertically, so each column holds a band exactly 2 "
     "pixels tall whatever the slope. Both ends run through sample centres: the end x = 1.5 has outward normal "
     "(-1, 0), a LEFT edge, owned under top-left, so column 1 is drawn; the end x = 9.5 has normal (1, 0), a "
     "RIGHT edge, not owned, so column 9 is not drawn at all. Column by column, samples at y = j + 0.5: "
     "column 1, y(1.5) = 2: the band is [1, 3], samples 1.5 and 2.5 inside: rows 1, 2. Column 2, y(2.5) = 2.5: "
     "band [1.5, 3.5], sample 2.5 inside, and 1.5 and 3.5 exactly on the sides. The upper side "
     "p.y - y(p.x) = -1 has outward normal (dy/dx, -1) = (0.5, -1), nx > 0, a RIGHT edge: row 1 not covered. "
     "The lower side p.y - y(p.x) = +1 has normal (-0.5, 1), a LEFT edge: row 3 covered. So column 2 gets "
     "rows 2, 3. Odd columns are like column 1, even ones like column 2, and every column gets exactly 2 "
     "samples: " + fmt_px(WE_PARA) + ", 16 in all. Under bottom-right the ownership flips: column 9 is drawn, "
     "column 1 is not, and the even columns take their upper border sample instead of the lower one.",
     12, 9, [para((1.5, 2), (9.5, 6), width=2)], checks=[("fill_rule",)], pixels={0: WE_PARA})

# ---------------------------------------------------------------------------
# 2. Stars: slopes 0, +-1/2, +-1, +-2 and vertical in every octant.

STAR_DIRS = [(2, 0), (2, 1), (2, 2), (1, 2), (0, 2), (-1, 2), (-2, 2), (-2, 1),
             (-2, 0), (-2, -1), (-2, -2), (-1, -2), (0, -2), (1, -2), (2, -2), (2, -1)]
C = (F(65, 2), F(65, 2))


def star_lines(maker, centre=C, scale=12, inward=False, **kw):
    out = []
    for dx, dy in STAR_DIRS:
        tip = (centre[0] + dx * scale, centre[1] + dy * scale)
        a, b = (tip, centre) if inward else (centre, tip)
        out.append(maker(a, b, **kw))
    return out


STAR_TEXT = ("16 lines from the pixel centre (32.5, 32.5) of a 64x64 canvas, in the directions (2,0) (2,1) "
             "(2,2) (1,2) (0,2) (-1,2) (-2,2) (-2,1) (-2,0) (-2,-1) (-2,-2) (-1,-2) (0,-2) (1,-2) (2,-2) "
             "(2,-1) scaled by 12: slopes 0, +-1/2, +-1, +-2 and vertical, two lines in every octant, "
             "every sign of dx and dy. ")

case("midpoint_star_16",
     STAR_TEXT + "Each line is drawn outward, centre to tip, with last_pixel include: 25 pixels per line, and "
     "the centre pixel (32,32) is covered 16 times. The slope +-1/2 and +-2 lines start on a pixel centre, so "
     "every other column (row) is an exact tie, broken to the upper row (left column); a rasterizer that "
     "breaks ties by the direction of travel, or uses a DDA that rounds y(c) to nearest-up, draws them on the "
     "other side in some octants. The |slope| = 1 lines are x-major.",
     64, 64, star_lines(mid), checks=[("ties",), ("min_coverage_max", 16)])

case("midpoint_star_16_reversed",
     "The same 16 lines as midpoint_star_16, each drawn from its tip to the centre. The midpoint rule "
     "depends only on the set of points of the segment, so every pixel and every coverage count must equal "
     "those of midpoint_star_16: A->B = B->A. A Bresenham that always starts at v0 and breaks ties by the "
     "sign of its error term draws the tie pixels of the reversed slope-1/2 and slope-2 lines on the other "
     "side. " + STAR_TEXT,
     64, 64, star_lines(mid, inward=True),
     checks=[("ties",), ("same_as", "midpoint_star_16")])

case("midpoint_star_16_exclude_outward",
     STAR_TEXT + "Drawn outward with last_pixel: exclude: the interval of columns (rows for y-major lines) is "
     "half-open at v1, so the tip pixel of every line, whose centre is exactly v1, is not drawn, while the "
     "centre pixel is still covered 16 times. The tips lie in every octant, so an implementation that "
     "excludes 'the last column' in the wrong direction, or the first pixel instead of the last, fails.",
     64, 64, star_lines(mid, last_pixel="exclude"), checks=[("min_coverage_max", 16)])

case("midpoint_star_16_exclude_inward",
     STAR_TEXT + "Drawn inward (tip to centre) with last_pixel: exclude: every line ends on the centre "
     "pixel's centre, so none of them draws it, and the centre pixel (32,32) stays uncovered while all 16 tips "
     "are drawn. (Near the centre, lines of neighbouring directions share some pixels, so a few samples are "
     "covered 2 or 3 times.) Reversing a line changes which end is excluded: compare midpoint_star_16_exclude_outward.",
     64, 64, star_lines(mid, inward=True, last_pixel="exclude"), checks=[("uncovered", 32, 32)])

case("rectangle_star_16",
     STAR_TEXT + "Rule rectangle, width 1, drawn outward. The long sides of the axis-aligned lines lie on "
     "pixel edges, half way between sample rows (columns), and those of the other lines, at an irrational "
     "distance |d|/2 from the axis in q x d units, never meet a sample. The caps are perpendicular to each "
     "line through its ends, both sample centres: the centre sample lies on all 16 v0 caps and is covered only by the lines whose v0 "
     "cap is a left or top edge under top-left. The apparent thickness varies with slope: 1 sample per column "
     "for the horizontal line, 1 or 2 for the diagonals.",
     64, 64, star_lines(rect, width=1), checks=[("fill_rule",)])

case("rectangle_star_16_reversed",
     "The lines of rectangle_star_16 drawn tip to centre. The rectangle is the same set with the same "
     "border edges whichever end is v0, so every sample and every coverage count must equal those of "
     "rectangle_star_16. " + STAR_TEXT,
     64, 64, star_lines(rect, width=1, inward=True), checks=[("same_as", "rectangle_star_16")])

case("parallelogram_star_16",
     STAR_TEXT + "Rule parallelogram, width 2, drawn outward. Each band is exactly 2 samples tall in every "
     "column (x-major) or wide in every row (y-major) away from the ends, and its ends run through sample "
     "centres (the centre and the tips), so the fill rule decides the first and last column or row. At the "
     "centre the 16 ends meet and the centre sample is covered only by the lines whose end there is owned.",
     64, 64, star_lines(para, width=2), checks=[("fill_rule",)])

case("parallelogram_star_16_reversed",
     "The lines of parallelogram_star_16 drawn tip to centre: the same sets with the same borders, so every "
     "coverage count must equal those of parallelogram_star_16. " + STAR_TEXT,
     64, 64, star_lines(para, width=2, inward=True), checks=[("same_as", "parallelogram_star_16")])

# ---------------------------------------------------------------------------
# 3. Exact midpoint ties.

TIE_X = [mid((1.5, 1.5), (17.5, 9.5)), mid((38.5, 1.5), (22.5, 9.5)),
         mid((1.5, 38.5), (17.5, 30.5)), mid((38.5, 38.5), (22.5, 30.5))]
case("midpoint_tie_slope_half",
     "Four x-major lines of slope +-1/2 on a 40x40 canvas, one in each x-major octant pair and each direction "
     "of travel: (1.5,1.5)->(17.5,9.5), (38.5,1.5)->(22.5,9.5), (1.5,38.5)->(17.5,30.5), "
     "(38.5,38.5)->(22.5,30.5). Each starts on a pixel centre, so at every other column y(c) is an integer "
     "and the two nearest row centres tie. The tie rule for x-major lines: the UPPER row (the smaller y, "
     "ceil(y(c)) - 1) wins, whichever way the line runs and whether it rises or falls. A Bresenham whose "
     "decision variable is tested with > instead of >= (or vice versa) in some octant, or an implementation "
     "that rounds y(c) half-up (floor(y + 0.5)), draws the lower row. 17 columns each, 68 samples.",
     40, 40, TIE_X, checks=[("ties",)])

TIE_Y = [mid((3.5, 3.5), (11.5, 19.5)), mid((11.5, 28.5), (3.5, 12.5)),
         mid((28.5, 3.5), (20.5, 19.5)), mid((20.5, 28.5), (28.5, 12.5))]
case("midpoint_tie_slope_two",
     "Four y-major lines of slope +-2 on a 32x32 canvas, in each y-major octant pair and each direction of "
     "travel: (3.5,3.5)->(11.5,19.5), (11.5,28.5)->(3.5,12.5), (28.5,3.5)->(20.5,19.5), "
     "(20.5,28.5)->(28.5,12.5). Each starts on a pixel centre, so at every other row x(r) is an integer and "
     "two column centres tie. The tie rule for y-major lines: the LEFT column (ceil(x(r)) - 1) wins in every "
     "octant. Rounding x half-up, or mirroring the x-major code with the wrong sign, draws the right column. "
     "17 rows each, 68 samples.",
     32, 32, TIE_Y, checks=[("ties",)])

case("midpoint_tie_edge_endpoints",
     "Ties from endpoints on pixel edges rather than centres, on a 24x24 canvas: (0.5, 1)->(16.5, 9) has "
     "y(c) = 1 + (c - 0.5)/2, an integer in every even column, ties to the upper row; (23, 22.5)->(15, 6.5) "
     "is y-major with x(r) = 23 - (22.5 - r)/2, an integer in every other row, ties to the left column; "
     "(2, 20.5)->(10, 16.5) falls with slope -1/2 and starts on a vertical pixel edge, so y(c) is never an "
     "integer there (no ties) but the first column is 2 (centre 2.5), not 1. Endpoints on edges and corners "
     "are exactly where fixed-point setups that bias the start by half a pixel disagree.",
     24, 24, [mid((0.5, 1), (16.5, 9)), mid((23, 22.5), (15, 6.5)), mid((2, 20.5), (10, 16.5))],
     checks=[("ties",)])

case("midpoint_slope_one_is_x_major",
     "Lines with |slope| exactly 1 are x-major (|dx| >= |dy|), and here it matters: (0.5, 0)->(8.5, 8) "
     "passes through the points (i + 0.5, i), so in every column y(c) is an integer and the tie goes to the "
     "upper row: pixels (i, i - 1) for columns 0 to 8 (the first is above the canvas). Treated as y-major, "
     "rows 0 to 7 would tie to the left column and draw (i, i) instead. The other three lines are the same "
     "test in the other diagonal directions: (15.5, 8)->(7.5, 16) runs down-left, (16.5, 23)->(24.5, 15) "
     "up-right, and (31, 24.5)->(23, 32.5) down-left from a vertical pixel edge; each ties in every column. "
     "32x32 canvas.",
     32, 32, [mid((0.5, 0), (8.5, 8)), mid((15.5, 8), (7.5, 16)), mid((16.5, 23), (24.5, 15)),
              mid((31, 24.5), (23, 32.5))],
     checks=[("ties",), ("xmajor_at_one",)])

# ---------------------------------------------------------------------------
# 4. Endpoints: centres, corners, edges, sub-pixel.

case("midpoint_endpoints_centres",
     "Lines whose endpoints are all pixel centres, at assorted slopes (3/7, -5/2, 1, 0, -2/9) on a 24x24 "
     "canvas: both end columns (rows) are drawn and both end pixels are the endpoints' own pixels, however "
     "the line runs. A rasterizer that drops the last pixel (half-open like Vulkan) fails on every line.",
     24, 24, [mid((1.5, 1.5), (15.5, 7.5)), mid((20.5, 2.5), (16.5, 12.5)), mid((2.5, 10.5), (12.5, 20.5)),
              mid((22.5, 22.5), (14.5, 22.5)), mid((4.5, 22.5), (22.5, 18.5))])

case("midpoint_endpoints_corners",
     "Lines whose endpoints are all pixel corners (integers) on a 24x24 canvas: (1,1)->(15,7), "
     "(21,2)->(17,13), (3,10)->(13,21), (23,22)->(14,22), (4,23)->(22,18). No column centre is ever an "
     "endpoint, so the first column drawn is the one just inside v0 and the last the one just inside v1; "
     "(23,22)->(14,22) is horizontal on a pixel edge, where y(c) = 22 is an integer in every column and the "
     "whole line goes to the upper row 21.",
     24, 24, [mid((1, 1), (15, 7)), mid((21, 2), (17, 13)), mid((3, 10), (13, 21)), mid((23, 22), (14, 22)),
              mid((4, 23), (22, 18))], checks=[("ties",)])

case("midpoint_endpoints_edges",
     "Endpoints in the middle of pixel edges on a 24x24 canvas: (1.5,1)->(15.5,7) and (20,2.5)->(16,12.5) "
     "have their major coordinate on a centre and their minor one on an edge, (1,10.5)->(11,20.5) the other "
     "way round, and the vertical (12.5,3)->(12.5,9) and horizontal (3,14.5)->(9,14.5) ones run along sample "
     "centres with ends on pixel edges. Whether an end column is drawn depends on comparing its centre with "
     "the endpoint exactly.",
     24, 24, [mid((1.5, 1), (15.5, 7)), mid((20, 2.5), (16, 12.5)), mid((1, 10.5), (11, 20.5)),
              mid((12.5, 3), (12.5, 9)), mid((3, 14.5), (9, 14.5))], checks=[("ties",)])

SUB8 = [mid((3.1015625, 2.7109375), (27.49609375, 9.50390625)),
        mid((28.8984375, 3.125), (22.50390625, 29.49609375)),
        mid((2.50390625, 29.2890625), (30.49609375, 16.5)),
        mid(("123457/1000", "8.0001"), ("17.234567", "21.98765")),
        mid((9.501953125, 29.498046875), (12.498046875, 20.501953125))]
case("midpoint_subpixel_8bits",
     "Sub-pixel endpoints with subpixel_bits 8 on a 32x32 canvas. The first three lines have coordinates "
     "already on the 1/256 grid (3.1015625 = 3 + 26/256, 27.49609375 = 27.5 - 1/256, 22.50390625 = 22.5 + "
     "1/256): their end columns start or stop one 1/256 step away from a column centre, so an end column is "
     "drawn or not by a margin of 1/256. The fourth line has coordinates off the grid (123.457, 8.0001, "
     "17.234567, 21.98765) that must first be snapped to the nearest multiple of 1/256. The fifth is a short "
     "steep line (9.501953125, 29.498046875)->(12.498046875, 20.501953125) whose coordinates all lie exactly "
     "half way between grid points (9.5 + 1/512 is 128.5/256 past 9, 29.5 - 1/512 is 127.5/256 past 29): "
     "ties-to-even snaps each to 128/256, so the line runs from the pixel centre (9.5, 29.5) to the pixel "
     "centre (12.5, 20.5) and draws both end rows, 10 in all. Snapping half down puts its lower end at "
     "29.49609375, above the centre of row 29, which is then not drawn; snapping half up puts its upper "
     "end at 20.50390625, below the centre of row 20; no snapping at all loses both end rows.",
     32, 32, SUB8, checks=[("snap",)])

SUB4 = [mid((2.53125, 3.46875), (29.46875, 11.53125)),
        mid((4.21875, 28.53125), (11.46875, 4.46875)),
        mid((20.46875, 30.03125), (29.53125, 16.96875))]
case("midpoint_subpixel_4bits",
     "subpixel_bits 4 (Vulkan's minimum sub-pixel precision): coordinates snap to multiples of 1/16, ties "
     "to even. Every coordinate here is an odd multiple of 1/32, exactly half way between two 1/16 grid "
     "points: 2.53125 = 2 + 8.5/16 snaps to 2.5 (8 is even), 29.46875 = 29 + 7.5/16 snaps to 29.5, 3.46875 "
     "to 3.5, 4.21875 = 4 + 3.5/16 to 4.25, 16.96875 = 16 + 15.5/16 to 17, and so on, so most endpoints land "
     "on pixel centres or edges, and the end columns and the midpoint ties "
     "depend on the tie rule of the snapping: rounding half up, half down or half away from zero moves an "
     "endpoint off the centre and drops or adds an end pixel or flips a tie. 32x32 canvas.",
     32, 32, SUB4, bits=4, checks=[("snap",), ("ties",)])

# ---------------------------------------------------------------------------
# 5. Long lines.

case("midpoint_long_shallow_2048",
     "Three x-major lines across a 2048x32 canvas. (0.5, 8.5)->(2046.5, 9.5) has slope 1/2046 and is "
     "exactly half way between rows 8 and 9 at column 1023 (c = 1023.5, y = 9): a tie, upper row 8, so the "
     "line steps down at column 1024, not 1023. (2047.5, 2.5)->(0.5, 3.5) runs right to left with slope "
     "-1/2047 and passes y = 3 at c = 1024 (no centre, no tie). (0, 20.00390625)->(2048, 27.99609375) "
     "descends 8 rows less two 1/256 steps over 2048 columns, starting and ending one grid step inside a row. "
     "An incremental DDA in f32 (steps of 1/2046) accumulates rounding error over 2000 steps and can get a "
     "step or the tie wrong; exact (or wide enough fixed-point) arithmetic "
     "gets all {N} pixels right.",
     2048, 32, [mid((0.5, 8.5), (2046.5, 9.5)), mid((2047.5, 2.5), (0.5, 3.5)),
                mid((0, 20.00390625), (2048, 27.99609375))], checks=[("ties",)])

case("midpoint_long_steep_2048",
     "The transpose of midpoint_long_shallow_2048 on a 32x2048 canvas: three y-major lines 2000+ rows long. "
     "(8.5, 0.5)->(9.5, 2046.5) is half way between columns 8 and 9 at row 1023, a tie that goes to the LEFT "
     "column 8; (2.5, 2047.5)->(3.5, 0.5) runs bottom to top; (20.00390625, 0)->(27.99609375, 2048) drifts "
     "8 columns less two grid steps. Error accumulation in a DDA stepping 1/2046 per row gets a step or the "
     "tie wrong.",
     32, 2048, [mid((8.5, 0.5), (9.5, 2046.5)), mid((2.5, 2047.5), (3.5, 0.5)),
                mid((20.00390625, 0), (27.99609375, 2048))], checks=[("ties",)])

# ---------------------------------------------------------------------------
# 6. Zero-length lines.

case("zero_length_lines",
     "Lines with v0 = v1 cover nothing (SPEC 4), whatever the rule: a midpoint line on the pixel centre "
     "(2.5, 2.5) (whose one column centre would otherwise be in the closed interval [2.5, 2.5]), one on the "
     "corner (5, 5), one with last_pixel exclude on (6.5, 1.5), one whose endpoints differ by 1/1024 but snap "
     "to the same point (7.5, 3.5) at 8 subpixel bits, a rectangle of width 5 on (4, 4) and a parallelogram "
     "of width 3 on (3.5, 6.5) (a rectangle or parallelogram of length 0 has no direction). 8x8 canvas, "
     "0 samples covered: a rasterizer that draws a dot, or divides by zero, fails.",
     8, 8, [mid((2.5, 2.5), (2.5, 2.5)), mid((5, 5), (5, 5)), mid((6.5, 1.5), (6.5, 1.5), last_pixel="exclude"),
            mid((7.5, 3.5), (7.5 + 1 / 1024, 3.5)), rect((4, 4), (4, 4), width=5),
            para((3.5, 6.5), (3.5, 6.5), width=3)])

# ---------------------------------------------------------------------------
# 7. Strips and loops.

STRIP = [P(2.5, 2.5), P(20.5, 11.5), P(26.5, 29.5), P(8.5, 37.5), P(3.5, 55.5), P(29.5, 61.5)]
STRIP_TEXT = ("A polyline of 5 segments on a 32x64 canvas through the pixel centres (2.5,2.5) (20.5,11.5) "
              "(26.5,29.5) (8.5,37.5) (3.5,55.5) (29.5,61.5): consecutive segments share their endpoints "
              "exactly, and the segments alternate x-major and y-major and turn through several octants. ")
case("strip_exclude_joints",
     STRIP_TEXT + "With last_pixel: exclude the interval of each segment is half-open at its v1, so the joint "
     "pixel, whose centre is the shared vertex, is drawn once, by the segment that starts there: no sample "
     "is covered twice. The last vertex (29.5, 61.5) is not drawn at all. Vulkan's Bresenham lines behave "
     "this way; a rasterizer that ignores last_pixel draws 4 doubles.",
     32, 64, [mid(STRIP[i], STRIP[i + 1], last_pixel="exclude") for i in range(5)],
     checks=[("max_coverage", 1)])

case("strip_include_joints",
     STRIP_TEXT + "With last_pixel: include (the default) every segment draws both its end pixels, so each "
     "of the 4 joint pixels is covered twice (coverage 2, last primitive the later segment): the doubles are "
     "what the rule says, and a rasterizer that silently drops the last pixel fails here. Compare "
     "strip_exclude_joints.",
     32, 64, [mid(STRIP[i], STRIP[i + 1], last_pixel="include") for i in range(5)],
     checks=[("min_coverage_max", 2), ("max_coverage", 2)])

LOOP = [P(8.5, 8.5), P(40.5, 14.5), P(55.5, 44.5), P(14.5, 53.5)]
case("loop_exclude_quad",
     "A closed quadrilateral drawn as 4 midpoint lines with last_pixel: exclude, each starting where the "
     "previous ended: (8.5,8.5) (40.5,14.5) (55.5,44.5) (14.5,53.5) and back to (8.5,8.5), on a 64x64 canvas. "
     "Two sides are x-major and two y-major, running in all four quadrant directions. Each corner pixel is "
     "drawn exactly once (by the line leaving it) and no sample is covered twice, so a loop of half-open "
     "lines is a clean outline; with include every corner would double.",
     64, 64, [mid(LOOP[i], LOOP[(i + 1) % 4], last_pixel="exclude") for i in range(4)],
     checks=[("max_coverage", 1)])

# ---------------------------------------------------------------------------
# 8. Rectangle lines.

case("rectangle_width_5",
     "Two rectangle lines of width 5 on a 64x64 canvas at non-axis angles, (10.25, 12.75)->(50.5, 40.125) "
     "and (56.75, 8.5)->(40.0078125, 58.9921875): wide rotated rectangles whose corners are irrational. "
     "The side test |q x d| <= (w/2)|d| must be compared squared to stay exact; a rasterizer that expands "
     "the line into two triangles with rounded corners gets border samples wrong.",
     64, 64, [rect((10.25, 12.75), (50.5, 40.125), width=5),
              rect((56.75, 8.5), (40.0078125, 58.9921875), width=5)])

case("rectangle_width_10",
     "A rectangle line of width 10 from (8.5, 50.5) to (56.25, 14.75) on a 64x64 canvas, and one of width "
     "10 whose length 10 is exact (d = (8, -6)) from (20.5, 20.5) to (28.5, 14.5): its caps and sides run "
     "through sample centres (a 3-4-5 triangle), so the fill rule decides many border samples, including "
     "corner samples where a cap meets a side.",
     64, 64, [rect((8.5, 50.5), (56.25, 14.75), width=10), rect((20.5, 20.5), (28.5, 14.5), width=10)],
     checks=[("fill_rule",)])

case("rectangle_width_64",
     "One rectangle line of width 64 on a 128x128 canvas, from (30.5, 40.25) to (97.75, 88.5): a rotated "
     "rectangle about 83 by 64 pixels whose corners reach outside the canvas. Wide lines stress setup "
     "precision: the side test multiplies coordinates by |d|^2 and width^2.",
     128, 128, [rect((30.5, 40.25), (97.75, 88.5), width=64)])

THIN = [rect((1.25, 2.75), (30.75, 2.75), width=1), rect((1.25, 6.125), (30.75, 13.5), width=1),
        rect((1.25, 16.25), (21.25, 26.25), width=1), rect((1.25, 29.5), (23.75, 52), width=1),
        rect((26.125, 30.25), (37.375, 52.75), width=1), rect((40.75, 30.25), (40.75, 60.5), width=1),
        rect((46.75, 2.25), (60.25, 58.25), width=1)]
case("rectangle_thin_slopes",
     "Rectangle lines of width 1 at slopes 0, 1/4, 1/2, 1, 2, vertical and about 4 on a 64x64 canvas. The "
     "thin rectangle's vertical extent in a column is width * sqrt(1 + m^2) for slope m: exactly 1 sample "
     "per column for the horizontal line, 1 or 2 for the slope-1 line (extent 1.414), and for the steep lines "
     "the horizontal extent per row grows the same way. This slope-dependent thickness is what distinguishes "
     "the rectangle rule from the midpoint rule (always 1 per column) and the parallelogram rule (always "
     "width per column).",
     64, 64, THIN)


def border_case(rule_name):
    return [rect((2, 8.5), (14, 8.5), width=2), rect((20, 2.5), (20, 12.5), width=1),
            rect((24.5, 2.5), (32.5, 8.5), width=2)]


BORDER_TEXT = {
    "top-left": "top and left edges own their samples: the horizontal line covers rows 7 and 8 (its top "
                "border y = 7.5 owns row 7; its bottom border y = 9.5 does not own row 9), 24 samples; the "
                "vertical line covers column 19 (left border) from row 2 (its top cap y = 2.5 is owned) to row "
                "11 (its bottom cap y = 12.5 is not), 10 samples",
    "bottom-right": "bottom and right edges own their samples: the horizontal line covers rows 8 and 9, 24 "
                    "samples; the vertical line covers column 20 (right border x = 20.5) from row 3 to row 12 "
                    "(bottom cap y = 12.5 owned, top cap not), 10 samples",
    "top-right": "top and right edges own their samples: the horizontal line covers rows 7 and 8; the "
                 "vertical line covers column 20 from row 2 to row 11",
    "bottom-left": "bottom and left edges own their samples: the horizontal line covers rows 8 and 9; the "
                   "vertical line covers column 19 from row 3 to row 12",
}
def box(xs, ys):
    return [(x, y) for x in xs for y in ys]


BORDER_PIXELS = {  # (rows of the horizontal line, column and rows of the vertical line)
    "top-left": ((7, 8), 19, range(2, 12)), "bottom-right": ((8, 9), 20, range(3, 13)),
    "top-right": ((7, 8), 20, range(2, 12)), "bottom-left": ((8, 9), 19, range(3, 13)),
}
for fr in ("top-left", "bottom-right", "top-right", "bottom-left"):
    rows, col, vrows = BORDER_PIXELS[fr]
    case("rectangle_border_centres_" + fr.replace("-", "_"),
         "Rectangle lines whose borders run exactly through sample centres, so the fill rule %s decides "
         "every border sample. On a 40x16 canvas: a horizontal line (2, 8.5)->(14, 8.5) of width 2 has its "
         "long sides at y = 7.5 and y = 9.5, through the centres of rows 7 and 9 (its caps x = 2 and 14 miss "
         "the centres); a vertical line (20, 2.5)->(20, 12.5) of width 1 has sides x = 19.5 and 20.5 and "
         "caps y = 2.5 and 12.5, all through centres, so its 4 corner samples lie on two border edges each "
         "and are covered only when both edges are owned; and a line (24.5, 2.5)->(32.5, 8.5) of width 2 "
         "with d = (8, 6), |d| = 10, whose sides 6qx - 8qy = +-10 and caps pass through sample centres. "
         "Under %s the %s. The outward normal classifies each edge: (0, -1) top, (0, 1) bottom, nx < 0 left, "
         "nx > 0 right." % (fr, fr, BORDER_TEXT[fr]),
         40, 16, border_case(fr), fill_rule=fr, checks=[("fill_rule",)],
         pixels={0: box(range(2, 14), rows), 1: box([col], vrows)})

# ---------------------------------------------------------------------------
# 9. Parallelogram lines.

case("parallelogram_x_major",
     "X-major parallelogram lines on a 64x64 canvas at several slopes and widths: slope 1/3 width 1, "
     "slope -3/4 width 2.5, slope 0 width 3 (through sample rows: borders at y = 40 and 43 miss the centres), "
     "slope 1 width 1.5 from (4.25, 44.75) (|slope| = 1 is x-major: vertical ends, width measured "
     "vertically), and slope -1/8 width 7. Each column holds a vertical band of exactly `width` whatever the "
     "slope, unlike the rectangle rule.",
     64, 64, [para((2.5, 3.25), (32.5, 13.25), width=1), para((36.125, 30.5), (60.125, 12.5), width=2.5),
              para((3, 41.5), (28.75, 41.5), width=3), para((4.25, 44.75), (18.25, 58.75), width=1.5),
              para((62, 40.25), (30, 44.25), width=7)], checks=[("fill_rule",)])

case("parallelogram_y_major",
     "Y-major parallelogram lines on a 64x64 canvas: slope 3 width 1, slope 4/3 width 2.5 (run bottom to "
     "top), vertical width 3, slope 2 width 2 from the pixel centre (44.5, 30.5) (its sides x(r) +- 1 and "
     "its ends y = 30.5 and 62.5 run through sample centres) and slope 8 width 7 (run bottom to top). The ends are horizontal "
     "and the width is measured horizontally, so each row holds exactly `width` of band.",
     64, 64, [para((3.25, 2.5), (13.25, 32.5), width=1), para((30.5, 60.125), (12.5, 36.125), width=2.5),
              para((41.5, 3), (41.5, 28.75), width=3), para((44.5, 30.5), (60.5, 62.5), width=2),
              para((60.25, 62), (56.25, 30), width=7)], checks=[("fill_rule",)])

for fr in ("top-left", "bottom-right"):
    case("parallelogram_border_centres_" + fr.replace("-", "_"),
         "Parallelogram lines whose borders run through sample centres, fill rule %s, on a 32x16 canvas. "
         "(2.5, 8.5)->(13.5, 8.5) of width 2: sides y = 7.5 and 9.5 and vertical ends x = 2.5 and 13.5, all "
         "through centres; the top side and left end are owned under top-left, the bottom side and right end "
         "under bottom-right, so 22 samples either way but shifted by one row and one column. "
         "(16.5, 2)->(28.5, 8) of width 2, slope 1/2: every other column has both sides on centres, the upper "
         "side's outward normal (1/2, -1) makes it a right edge and the lower side's (-1/2, 1) a left edge. "
         "(18.5, 9.5)->(21.5, 15.5) of width 2, y-major with dx/dy = 1/2: "
         "horizontal ends y = 9.5 (top edge) and 15.5 (bottom edge) through centres, and sides "
         "x(r) +- 1 through centres in every other row, a left side and a right side." % fr,
         32, 16, [para((2.5, 8.5), (13.5, 8.5), width=2), para((16.5, 2), (28.5, 8), width=2),
                  para((18.5, 9.5), (21.5, 15.5), width=2)], fill_rule=fr, checks=[("fill_rule",)],
         pixels={0: box(range(2, 13), (7, 8)) if fr == "top-left" else box(range(3, 14), (8, 9))})

case("parallelogram_slope_one_is_x_major",
     "A parallelogram line with |slope| exactly 1 is x-major: its ends are vertical and its width is measured "
     "vertically. (2.25, 2)->(12.25, 12) of width 4 on a 32x32 canvas covers x in [2.25, 12.25] and "
     "|p.y - y(p.x)| <= 2; read as y-major its ends would be horizontal (y in [2, 12]) and the two end "
     "triangles would differ. A second line (29.75, 18)->(19.75, 28) of width 3 checks the other diagonal.",
     32, 32, [para((2.25, 2), (12.25, 12), width=4), para((29.75, 18), (19.75, 28), width=3)],
     checks=[("xmajor_at_one",)])

# ---------------------------------------------------------------------------
# 10. Interpolation along lines.


def iv(x, y, z, w, attrs):
    return V(x, y, z=z, w=w, attributes=attrs)


def interp_lines(parameter, interpolation):
    kw = dict(parameter=parameter, interpolation=interpolation)
    return [
        mid(iv(2.5, 3.25, 0.25, 0.5, [1, 0, 0.5]), iv(61.5, 20.75, 0.75, 4, [0, 1, -2]), **kw),
        mid(iv(60.25, 26.5, -1, 4, [0, 0, 1]), iv(44.75, 62.5, 3, 0.5, [1, 1, 0]), **kw),
        rect(iv(6.5, 30.5, 0, 0.5, [1, 0, 0]), iv(30.5, 48.5, 1, 4, [0, 0, 1]), width=12, **kw),
        para(iv(34.25, 30.125, 0.5, 1, [0, 1, 0]), iv(40.75, 58.625, 0.125, 3, [1, 0, "1/3"]), width=6, **kw),
        para(iv(4.5, 57.5, 2, 2, [0.25, 0.5, 0.75]), iv(31.5, 61.5, -2, 0.75, [0.75, 0.5, 0.25]), width=3, **kw),
    ]


INTERP_TEXT = ("Five lines on a 64x64 canvas carrying depth z and three attributes (r, g, b), with w from "
               "0.5 to 4: two midpoint lines (x-major and y-major), a rectangle of width 12 and two "
               "parallelograms of widths 6 and 3. The parameter t is clamped to [0, 1]: with parameter major "
               "the rectangle's corner samples lie beyond its ends along the major axis; with parameter "
               "projected the parallelograms' end samples (and an end sample of the y-major midpoint line) "
               "project beyond the segment. ")
PARAM_TEXT = {
    "major": "parameter: major: t = (c - x0)/(x1 - x0) for the sample's x (y for y-major lines), the value "
             "an incremental midpoint algorithm steps; samples off the segment still get the t of their "
             "column. ",
    "projected": "parameter: projected: t = ((p - v0).d)/|d|^2, the exact projection of the sample onto the "
                 "segment, which differs from the major-axis parameter for every sample off the line's axis. ",
}
INTERP_KIND = {
    "linear": "interpolation: linear: each attribute is (1 - t) a0 + t a1 in screen space. ",
    "perspective": "interpolation: perspective: ((1-t) a0/w0 + t a1/w1)/((1-t)/w0 + t/w1); with w ratios of "
                   "8 the perspective and linear values differ by far more than the tolerance. ",
}
for parameter in ("major", "projected"):
    for interpolation in ("linear", "perspective"):
        checks = [("parameter",), ("clamp",)]
        if interpolation == "perspective":
            checks.append(("perspective",))
        case("interpolation_%s_%s" % (parameter, interpolation),
             INTERP_TEXT + PARAM_TEXT[parameter] + INTERP_KIND[interpolation] +
             "Depth is always (1 - t) z0 + t z1. A rasterizer that interpolates with the other parameter, "
             "does not clamp, or confuses linear and perspective, fails the interpolation check.",
             64, 64, interp_lines(parameter, interpolation), checks=checks)

case("interpolation_flat",
     INTERP_TEXT + "interpolation: flat: every covered sample takes the first vertex's attributes exactly as "
     "written (1/3 included), but depth is still interpolated linearly, (1 - t) z0 + t z1, with the "
     "projected parameter. No two of the lines overlap.",
     64, 64, [p.with_(interpolation="flat", parameter="projected") for p in interp_lines(None, None)])

# ---------------------------------------------------------------------------
# 11. Canvas borders and far endpoints.

case("lines_cross_canvas_border",
     "Lines that start or end outside a 32x32 canvas: a midpoint line (-10.5, 5.25)->(40.75, 20.5) crossing "
     "it left to right, a steep one (16.5, -8)->(20.25, 45) crossing top to bottom, one with last_pixel "
     "exclude whose excluded end (31.5, 40.5) lies outside (so nothing inside is excluded), a rectangle of "
     "width 4 from (-5, -5) to (40, 30) and a parallelogram of width 3 from (-3, 28.5) to (35, 31.5). Only "
     "the samples inside the canvas count; a rasterizer that starts its columns at the clipped edge "
     "instead of at the true v0 computes y(c) from the wrong origin.",
     32, 32, [mid((-10.5, 5.25), (40.75, 20.5)), mid((16.5, -8), (20.25, 45)),
              mid((2.5, -3.5), (31.5, 40.5), last_pixel="exclude"), rect((-5, -5), (40, 30), width=4),
              para((-3, 28.5), (35, 31.5), width=3)])

case("lines_far_endpoints",
     "Lines with endpoints at the coordinate limits +-32768 (SPEC 8) crossing a 64x64 canvas: the diagonal "
     "(-32768, -32768)->(32768, 32768) through the sample centres (i + 0.5, i + 0.5); the anti-diagonal "
     "(-32704.5, 32768)->(32767.5, -32704), on which y(c) = 63.5 - c is an integer in every column, a tie that "
     "goes to the upper row 62 - i; a very shallow line (-32768, 20.25)->(32768, 43.75) that rises 23.5 "
     "rows over 65536 columns, only about 0.023 rows across the canvas; a steep rectangle of width 3 "
     "(30.125, -32768)->(33.875, 32768) and a parallelogram of width 5 (32768, 50.5)->(-32768, 10.5). "
     "Squared lengths reach 2^33 and the rectangle's squared side test about 2^70 in units of 1/256: "
     "fixed-point setups with 32-bit or even 64-bit intermediates overflow, and f32 slopes lose the tiny rise.",
     64, 64, [mid((-32768, -32768), (32768, 32768)), mid((-32704.5, 32768), (32767.5, -32704)),
              mid((-32768, 20.25), (32768, 43.75)), rect((30.125, -32768), (33.875, 32768), width=3),
              para((32768, 50.5), (-32768, 10.5), width=5)], checks=[("ties",)])

# ---------------------------------------------------------------------------
# 12. Diamond-exit lines (SPEC.md section 4.2).

DIAMOND_TEXT = ("Rule diamond-exit (SPEC 4.2): each pixel has a diamond |u| + |v| < 1/2 around its centre, "
                "plus its lower-left and lower-right edges and bottom corner (and, for y-major lines, its "
                "right corner; never its upper edges, top or left corner); a pixel is lit when the segment "
                "meets its diamond and v1 does not lie in it. ")

WE_DIA_A = [(1, 1), (2, 1), (3, 2), (4, 2), (5, 3), (6, 3), (7, 4), (8, 4)]
WE_DIA_B = [(2, 6), (2, 7), (3, 8), (3, 9)]
case("diamond_exit_worked_example",
     "Worked example of the diamond-exit rule (SPEC 4.2), two lines on a 12x12 canvas. The diamond of the "
     "pixel with centre (xc, yc) is, with u = x - xc and v = y - yc (y down), the points with -u - v < 1/2 "
     "and u - v < 1/2 (the upper-left and upper-right edges excluded), -u + v <= 1/2 and u + v <= 1/2 (the "
     "lower-left and lower-right edges included): its bottom corner (0, 1/2) is in it, its top (0, -1/2) and "
     "left (-1/2, 0) corners are not, and its right corner (1/2, 0) is in it only for y-major lines. A "
     "pixel is lit when the segment meets its diamond and the second endpoint v1 is not in it. "
     "Line 1 runs from the pixel centre v0 = (1.5, 1.5) to the pixel centre v1 = (9.5, 5.5): d = (8, 4), "
     "x-major. At the column centres c = 1.5, 3.5, 5.5, 7.5, 9.5 it passes through the pixel centres of "
     "(1,1) (3,2) (5,3) (7,4) (9,5), crossing the inside of their diamonds. At c = 2.5, 4.5, 6.5, 8.5 its "
     "height y = 1.5 + (c - 1.5)/2 is an integer (2, 3, 4, 5): the point (2.5, 2) is the BOTTOM corner of "
     "the diamond of (2,1) and the TOP corner of the diamond of (2,2). The line's slope 1/2 is shallower than "
     "the diamond edges (slope +-1), so it touches each of the two diamonds at that one point and enters "
     "neither: (2,1) is lit because its bottom corner belongs to its diamond, (2,2) is not because its top "
     "corner does not. The same happens at (4,2)/(4,3), (6,3)/(6,4) and (8,4)/(8,5). Between those points "
     "the line meets no other diamond. The first pixel (1,1) contains v0 and is lit: only v1 is excluded. "
     "The last pixel (9,5) has v1 = (9.5, 5.5) at its centre, inside its diamond: the line never exits it, "
     "so it is NOT lit. Line 1 lights " + fmt_px(WE_DIA_A) + ". "
     "Line 2 runs from (2.5, 6.5) to (4.5, 10.5): d = (2, 4), y-major. At the row centres 6.5, 8.5, 10.5 "
     "it passes the pixel centres of (2,6) (3,8) (4,10); at r = 7.5 and 9.5 its x = 2.5 + (r - 6.5)/2 is an "
     "integer (3 and 4): (3, 7.5) is the RIGHT corner of the diamond of (2,7) and the LEFT corner of that of "
     "(3,7), and the line (slope 2, steeper than the edges) touches both only there. The line is y-major, so "
     "the right corner belongs to the diamond: (2,7) is lit; the left corner never does: (3,7) is not. (An "
     "x-major line through that corner would light neither.) Again the last pixel (4,10) contains v1 and is "
     "not lit. Line 2 lights " + fmt_px(WE_DIA_B) + ". 12 samples in all: the pixels of "
     "midpoint_worked_example less the two last pixels. Drawn from v1 to v0 the lines would light (9,5) and "
     "(4,10) instead of (1,1) and (2,6).",
     12, 12, [dia((1.5, 1.5), (9.5, 5.5)), dia((2.5, 6.5), (4.5, 10.5))],
     checks=[("diamond", "include_last"), ("diamond", "no_right_corner"), ("diamond", "upper"),
             ("diamond", "closed"), ("unlit", 0, 2, 2), ("unlit", 0, 9, 5), ("unlit", 1, 3, 7)],
     pixels={0: WE_DIA_A, 1: WE_DIA_B})

case("diamond_endpoints_centres",
     DIAMOND_TEXT + "Eight lines on a 24x24 canvas whose endpoints are all pixel centres, one in each octant: "
     "x-major (1.5,1.5)->(9.5,4.5) right-down, (22.5,1.5)->(14.5,4.5) left-down, (9.5,22.5)->(1.5,19.5) "
     "left-up, (14.5,22.5)->(22.5,19.5) right-up; y-major (2.5,7.5)->(5.5,16.5) down-right, "
     "(21.5,16.5)->(18.5,7.5) up-left, (8.5,16.5)->(11.5,7.5) up-right, (15.5,7.5)->(12.5,16.5) down-left. "
     "A centre is inside its pixel's diamond, so every line lights its v0 pixel and not its v1 pixel, "
     "whichever way it runs: 8 or 9 pixels each, one fewer than the midpoint rule. A rasterizer that keeps "
     "the last pixel, or drops the first one instead (an entry rule), fails every line.",
     24, 24, [dia((1.5, 1.5), (9.5, 4.5)), dia((22.5, 1.5), (14.5, 4.5)), dia((9.5, 22.5), (1.5, 19.5)),
              dia((14.5, 22.5), (22.5, 19.5)), dia((2.5, 7.5), (5.5, 16.5)), dia((21.5, 16.5), (18.5, 7.5)),
              dia((8.5, 16.5), (11.5, 7.5)), dia((15.5, 7.5), (12.5, 16.5))],
     checks=[("diamond", "include_last"), ("diamond", "exclude_first"), ("lit", 0, 1, 1),
             ("unlit", 0, 9, 4), ("lit", 5, 21, 16), ("unlit", 5, 18, 7)])

case("diamond_endpoints_edges",
     DIAMOND_TEXT + "Eight lines on a 24x24 canvas with one endpoint on a diamond edge, a quarter pixel from "
     "the centre along each axis (u, v = +-1/4). Lower edges are in the diamond, upper ones are not. "
     "(10.5,1.5)->(2.25,4.75), x-major: it crosses the inside of the diamond of (2,4) and ends on its "
     "lower-left edge: v1 is in that diamond, so (2,4) is not lit (with v1 1/256 further out it would be). "
     "(13.75,1.75)->(21.5,4.5), x-major: v0 on the lower-right edge of (13,1), and the line leaves away from "
     "the diamond at once: it meets the diamond only at v0, which is in it, so (13,1) is lit. (2.5,12.5)->(12.75,8.25), x-major: v1 on the upper-right edge of "
     "(12,8); the line arrives through the inside of that diamond and v1 is not in it (upper edge), so "
     "(12,8) IS lit. (20.25,12.25)->(14.5,8.5), x-major: v0 on the upper-left edge of (20,12), and the line "
     "leaves away from the diamond: it touches the closed diamond only at v0, which is not in it, so (20,12) "
     "is not lit. The y-major lines repeat this: (2.5,14.5)->(5.75,22.75) ends on the lower-right edge of "
     "(5,22) (not lit), (10.25,14.75)->(13.5,22.5) starts on the lower-left edge of (10,14) (lit), "
     "(16.5,22.5)->(18.25,14.25) ends on the upper-left edge of (18,14) arriving through its inside (lit), "
     "(22.75,14.25)->(21.5,3.5) starts on the upper-right edge of (22,14) leaving upward (not lit). A closed "
     "or an open diamond, or one whose upper edges are included instead (y up), gets some of these wrong.",
     24, 24, [dia((10.5, 1.5), (2.25, 4.75)), dia((13.75, 1.75), (21.5, 4.5)), dia((2.5, 12.5), (12.75, 8.25)),
              dia((20.25, 12.25), (14.5, 8.5)), dia((2.5, 14.5), (5.75, 22.75)),
              dia((10.25, 14.75), (13.5, 22.5)), dia((16.5, 22.5), (18.25, 14.25)),
              dia((22.75, 14.25), (21.5, 3.5))],
     checks=[("diamond", "closed"), ("diamond", "open"), ("diamond", "upper"),
             ("unlit", 0, 2, 4), ("lit", 1, 13, 1), ("lit", 2, 12, 8), ("unlit", 3, 20, 12),
             ("unlit", 4, 5, 22), ("lit", 5, 10, 14), ("lit", 6, 18, 14), ("unlit", 7, 22, 14)])

case("diamond_endpoints_corners",
     DIAMOND_TEXT + "Seven lines on a 24x24 canvas with an endpoint on a diamond corner, the middle of a "
     "pixel edge, which is the corner of two diamonds at once. (2.5,1.5)->(10.5,3), x-major: v1 is the "
     "bottom corner of (10,2), in its diamond, so (10,2) is not lit, and the top corner of (10,3), which the "
     "line touches only there (not in it): not lit either. (5.5,20.5)->(6.5,12), y-major upward: v1 is the "
     "top corner of (6,12), which the line reaches through the inside of that diamond: (6,12) lit, while "
     "(6,11), whose bottom corner v1 is, is not. (14.5,12)->(16.5,3.5), upward: v0 is the top corner of "
     "(14,12) (the line leaves it at once: not lit) and the bottom corner of (14,11) (in it: lit). "
     "(12,16.5)->(2.5,18.5), x-major leftward: v0 is the left corner of (12,16) (never in it: not lit) and the "
     "right corner of (11,16), not in it for an x-major line, but the line crosses that diamond's inside: "
     "lit. (19.5,13.5)->(21,20.5), y-major: v1 is the right corner of (20,20), in it for a y-major line: "
     "(20,20) not lit. (12.5,22.5)->(18,21.5), x-major: v1 is the right corner of (17,21), NOT in it for an "
     "x-major line: (17,21) lit. (3,2.5)->(5,10.5), y-major: v0 is the right corner of (2,2), in its diamond "
     "for a y-major line, and the segment meets that diamond only there: (2,2) is lit although the line never "
     "enters the pixel's square; (3,2), whose left corner v0 is, is not. Including or excluding the right "
     "corner for every line, or closing, opening or flipping the diamond, changes the result.",
     24, 24, [dia((2.5, 1.5), (10.5, 3)), dia((5.5, 20.5), (6.5, 12)), dia((14.5, 12), (16.5, 3.5)),
              dia((12, 16.5), (2.5, 18.5)), dia((19.5, 13.5), (21, 20.5)), dia((12.5, 22.5), (18, 21.5)),
              dia((3, 2.5), (5, 10.5))],
     checks=[("diamond", "no_right_corner"), ("diamond", "right_corner_always"), ("diamond", "closed"),
             ("diamond", "open"), ("diamond", "upper"),
             ("unlit", 0, 10, 2), ("unlit", 0, 10, 3), ("lit", 1, 6, 12), ("unlit", 1, 6, 11),
             ("unlit", 2, 14, 12), ("lit", 2, 14, 11), ("unlit", 3, 12, 16), ("lit", 3, 11, 16),
             ("unlit", 4, 20, 20), ("unlit", 4, 21, 20), ("lit", 5, 17, 21), ("lit", 6, 2, 2),
             ("unlit", 6, 3, 2)])

case("diamond_diagonals",
     DIAMOND_TEXT + "Lines of slope +-1 (x-major: |dx| >= |dy|) on a 32x32 canvas. (0.5,0.5)->(10.5,10.5) "
     "runs through the pixel centres and the pixel corners (i, i), which lie in no diamond: it lights "
     "(0,0)...(9,9), not (10,10) which holds v1. (2,14.5)->(12,24.5), half a pixel off (y = x + 12.5), runs "
     "exactly ALONG the lower-left edges of the diamonds of (i, i+12), which are included, and along the "
     "upper-right edges of (i, i+13), which are not, through the diamond corners (i, i+12.5) and "
     "(i+0.5, i+13): it lights (2,14)...(11,23). Its v0 is the left corner of (2,14) (excluded, but the "
     "segment goes on along that diamond's lower-left edge) and its v1 is the left corner of (12,24) and the "
     "right corner of (11,24), in neither for an x-major line. Read as y-major, the right corners on the line "
     "would light (i, i+13) too. (24.5,14)->(14.5,4) runs up-left along y = x - 10.5, the lower-left edges "
     "of (i+11, i): v0 is the bottom corner of (24,13) (lit), v1 the bottom corner of (14,3) (not lit: v1 "
     "is in it). (31.5,0.5)->(21.5,10.5) is the anti-diagonal through centres. (20,30.5)->(30,20.5) runs along "
     "y = 50.5 - x, the lower-right edges of the pixels with x + y = 49 (included) and the upper-left edges "
     "of those with x + y = 50 (excluded): it lights (20,29)...(29,20); its v1 is the right corner of "
     "(29,20), not in it for an x-major line, so (29,20) is lit.",
     32, 32, [dia((0.5, 0.5), (10.5, 10.5)), dia((2, 14.5), (12, 24.5)), dia((24.5, 14), (14.5, 4)),
              dia((31.5, 0.5), (21.5, 10.5)), dia((20, 30.5), (30, 20.5))],
     checks=[("xmajor_at_one",), ("diamond", "upper"), ("diamond", "closed"), ("diamond", "open"),
             ("unlit", 0, 10, 10), ("lit", 1, 11, 23), ("unlit", 1, 11, 24), ("lit", 2, 24, 13),
             ("unlit", 2, 14, 3), ("unlit", 2, 14, 4), ("lit", 4, 29, 20)],
     pixels={1: [(i, i + 12) for i in range(2, 12)], 4: [(i, 49 - i) for i in range(20, 30)]})

case("diamond_axis_lines",
     DIAMOND_TEXT + "Horizontal and vertical lines on a 24x16 canvas. (1.5,2.5)->(10.5,2.5) runs through "
     "the centres of row 2 and lights columns 1 to 9 (v1 holds (10,2)). (1,5)->(11,5) runs along the pixel "
     "border y = 5, through the bottom corners of row 4 (included) and the top corners of row 5 (excluded), "
     "touching each diamond in one point: it lights row 4, columns 1 to 10 (its endpoints are pixel corners, "
     "in no diamond). (11.5,8)->(1.5,8) runs leftward along y = 8 from the bottom corner of (11,7) (lit) to "
     "the bottom corner of (1,7) (v1 is in it: not lit): row 7, columns 2 to 11. (14.5,1.5)->(14.5,10.5) "
     "runs through the centres of column 14, rows 1 to 9. (17,1)->(17,11) is y-major along the pixel border "
     "x = 17, through the right corners of column 16 (included for a y-major line) and the left corners of "
     "column 17 (never): it lights column 16, rows 1 to 10; a rasterizer that never includes the right "
     "corner lights nothing. (20,12.5)->(20,2.5) runs upward along x = 20 from the right corner of (19,12) "
     "(lit) to the right corner of (19,2) (v1 is in it: not lit): column 19, rows 3 to 12.",
     24, 16, [dia((1.5, 2.5), (10.5, 2.5)), dia((1, 5), (11, 5)), dia((11.5, 8), (1.5, 8)),
              dia((14.5, 1.5), (14.5, 10.5)), dia((17, 1), (17, 11)), dia((20, 12.5), (20, 2.5))],
     checks=[("diamond", "no_right_corner"), ("diamond", "upper")],
     pixels={0: [(i, 2) for i in range(1, 10)], 1: [(i, 4) for i in range(1, 11)],
             2: [(i, 7) for i in range(2, 12)], 3: [(14, j) for j in range(1, 10)],
             4: [(16, j) for j in range(1, 11)], 5: [(19, j) for j in range(3, 13)]})

DSTRIP = [P(2.5, 2.5), P(10, 20.5), P(26.5, 26), P(8.25, 37.75), P(3.75, 55.25), P(29.5, 61.5)]
DSTRIP_TEXT = ("A polyline of 5 diamond-exit segments on a 32x64 canvas through (2.5,2.5) (10,20.5) (26.5,26) "
               "(8.25,37.75) (3.75,55.25) (29.5,61.5): consecutive segments share their endpoints exactly, "
               "mix y-major and x-major, and the joints are of every kind: (10,20.5) the right corner "
               "of (9,20) and left corner of (10,20), (26.5,26) the top corner of (26,26) and bottom corner "
               "of (26,25), (8.25,37.75) on the lower-left edge of (8,37), (3.75,55.25) on the upper-right "
               "edge of (3,55). " + DIAMOND_TEXT)
case("diamond_strip",
     DSTRIP_TEXT + "Drawn forward, each segment ends where the next starts: a joint pixel whose diamond "
     "holds the joint is lit only by the segment leaving it ((26,25) by the third segment, (8,37) by the fourth), "
     "and no sample is covered twice. At (10,20.5) the y-major segment 1 ends on the right corner of (9,20), "
     "in its diamond, and the x-major segment 2 leaves it away from (9,20), whose right corner is not in its "
     "diamond: (9,20) is lit by neither. (3,55) is lit by neither: the joint is on its excluded upper edge "
     "and both segments stay outside its diamond. The first vertex's pixel (2,2) is lit, the last one's "
     "(29,61) is not. Compare diamond_strip_reversed.",
     32, 64, [dia(DSTRIP[i], DSTRIP[i + 1]) for i in range(5)],
     checks=[("max_coverage", 1), ("lit", 0, 2, 2), ("unlit", 4, 29, 61), ("unlit", 0, 9, 20),
             ("unlit", 1, 9, 20), ("unlit", 1, 26, 25), ("lit", 2, 26, 25), ("unlit", 2, 8, 37),
             ("lit", 3, 8, 37), ("unlit", 3, 3, 55), ("unlit", 4, 3, 55)])
case("diamond_strip_reversed",
     "The segments of diamond_strip, each drawn in the other direction (segment i from vertex i+1 to "
     "vertex i). The diamond-exit rule depends on the direction, and the reversed set DIFFERS: the pixel "
     "(2,2) of the first vertex is no longer lit, the pixel (29,61) of the last vertex now is, and (9,20) is "
     "now lit: the reversed first segment is y-major and STARTS on the right corner of (9,20), which a "
     "y-major line's diamond includes, while the reversed second segment is x-major and ends there, "
     "arriving from the right without entering that diamond. The joint pixels (26,25) and (8,37) are lit once as before but by the other segment (the "
     "one that now starts there), and no sample is covered twice. " + DSTRIP_TEXT,
     32, 64, [dia(DSTRIP[i + 1], DSTRIP[i]) for i in range(5)],
     checks=[("max_coverage", 1), ("differs_from", "diamond_strip"), ("unlit", 0, 2, 2),
             ("lit", 4, 29, 61), ("lit", 0, 9, 20), ("lit", 1, 26, 25), ("lit", 2, 8, 37)])

case("diamond_joint_right_corner",
     DIAMOND_TEXT + "Two 2-segment polylines on a 12x12 canvas whose joint is a right corner, where x-major "
     "and y-major diamonds differ. (1.5,3.5)->(6,5.5) is x-major and ends on the right corner of (5,5): not "
     "in its diamond for an x-major line, and the line crosses that diamond's inside, so it lights (5,5). "
     "(6,5.5)->(8,10.5) is y-major and starts on the same right corner, which is in (5,5)'s diamond for a "
     "y-major line, so it lights (5,5) as well: (5,5) is covered TWICE. Sharing an endpoint does not always "
     "prevent a double pixel under the rule as written: an x-major segment followed by a y-major one at a "
     "right corner doubles it. The other polyline, (11.5,5.5)->(10,10.5)->(5.5,11.5), is the opposite order: "
     "the y-major segment ends on the right corner of (9,10), in its diamond (not lit), and the x-major one "
     "lights (9,10) as it leaves through that diamond's inside: no double.",
     12, 12, [dia((1.5, 3.5), (6, 5.5)), dia((6, 5.5), (8, 10.5)),
              dia((11.5, 5.5), (10, 10.5)), dia((10, 10.5), (5.5, 11.5))],
     checks=[("min_coverage_max", 2), ("max_coverage", 2), ("diamond", "no_right_corner"),
             ("lit", 0, 5, 5), ("lit", 1, 5, 5), ("unlit", 2, 9, 10), ("lit", 3, 9, 10)])

case("diamond_star_16",
     STAR_TEXT + DIAMOND_TEXT + "Drawn outward, centre to tip: every line lights the centre pixel (32,32), "
     "which holds its v0, so it is covered 16 times, and no line lights its tip pixel, which holds its v1: "
     "24 pixels per line. The slope +-1/2 and +-2 lines pass exactly through diamond corners in every other "
     "column (row): the bottom corner is lit and the top corner is not for x-major lines, and the right "
     "corner is lit and the left corner is not for y-major lines, in every octant.",
     64, 64, star_lines(dia), checks=[("min_coverage_max", 16), ("diamond", "no_right_corner"),
                                      ("diamond", "upper"), ("diamond", "include_last")])
case("diamond_star_16_reversed",
     "The 16 lines of diamond_star_16 drawn inward, tip to centre. The rule depends on the direction: now "
     "every tip pixel is lit and the centre pixel (32,32) is lit by none, so the set differs from "
     "diamond_star_16 by exactly those 17 pixels; the pixels between the ends are the same. Near the centre "
     "lines of neighbouring directions share some pixels, covered 2 or 3 times. " + STAR_TEXT,
     64, 64, star_lines(dia, inward=True),
     checks=[("differs_from", "diamond_star_16"), ("uncovered", 32, 32)])

case("diamond_subpixel_8bits",
     DIAMOND_TEXT + "Sub-pixel endpoints with subpixel_bits 8 on a 32x32 canvas; coordinates snap to "
     "multiples of 1/256, ties to even. (20.5,1.5)->(12.248046875,4.751953125) crosses the inside of the "
     "diamond of (12,4); its v1 is half way between grid points on both axes (3135.5/256 and 1216.5/256) and "
     "snaps to (12.25, 4.75), on the lower-left edge of (12,4): in its diamond, not lit; snapped half up or "
     "half down it moves 1/256 off the edge, outside the diamond, and (12,4) is lit. "
     "(16.5,12.5)->(20.498046875,6.001953125) snaps v1 to (20.5, 6), the top corner of (20,6), reached "
     "through its inside: lit; with y rounded half up v1 lands 1/256 inside that diamond and (20,6) is not "
     "lit. (9.998046875,24.501953125)->(12,31.5) snaps v0 to (10, 24.5), the right corner of (9,24), "
     "which this y-major line lights through that corner alone; a y rounded up leaves the diamond. The last "
     "line has endpoints off the grid (3.10156, 20.7109)->(27.4987, 28.0001), which must be snapped before "
     "anything else. Left unsnapped, the first line's v1 lies off the edge and (12,4) is lit.",
     32, 32, [dia((20.5, 1.5), (12.248046875, 4.751953125)), dia((16.5, 12.5), (20.498046875, 6.001953125)),
              dia((9.998046875, 24.501953125), (12, 31.5)), dia(("3.10156", "20.7109"), ("27.4987", "28.0001"))],
     checks=[("snap",), ("unlit", 0, 12, 4), ("lit", 1, 20, 6), ("lit", 2, 9, 24)])

case("diamond_subpixel_4bits",
     DIAMOND_TEXT + "subpixel_bits 4 (Vulkan's minimum): every coordinate is an odd multiple of 1/32, half "
     "way between two 1/16 grid points, and snaps to the even one. (20.46875,1.53125)->(12.28125,4.71875) "
     "becomes (20.5,1.5)->(12.25,4.75), crossing the inside of the diamond of (12,4) and ending on its "
     "lower-left edge: not lit. "
     "(26.53125,12.46875)->(20.46875,3.96875) becomes (26.5,12.5)->(20.5,4), y-major, ending on the bottom "
     "corner of (20,3) (in it: not lit) after crossing the inside of (20,4), whose top corner v1 is (lit). "
     "(16.03125,14.53125)->(16.03125,30.46875) becomes the vertical (16,14.5)->(16,30.5) along the pixel "
     "border x = 16: through the right corners of column 15, which this y-major line lights, rows 14 to 29 "
     "(v1 is the right corner of (15,30): not lit). Rounding half up, away from zero or to odd, or not "
     "snapping at all, moves ends off the corners and edges, or the vertical line off the border into "
     "column 16.",
     32, 32, [dia((20.46875, 1.53125), (12.28125, 4.71875)), dia((26.53125, 12.46875), (20.46875, 3.96875)),
              dia((16.03125, 14.53125), (16.03125, 30.46875))], bits=4,
     checks=[("snap",), ("unlit", 0, 12, 4), ("unlit", 1, 20, 3), ("lit", 1, 20, 4)],
     pixels={2: [(15, j) for j in range(14, 30)]})

case("diamond_long_shallow_1200",
     DIAMOND_TEXT + "Three x-major lines across a 1200x8 canvas. (0.5,1.5)->(1100.5,2.5) has slope 1/1100 "
     "and crosses y = 2 exactly at x = 550.5, the bottom corner of (550,1) (lit) and top corner of (550,2) "
     "(not lit): row 1 for columns 0 to 550, row 2 for columns 551 to 1099, and not (1100,2), which holds "
     "v1: 1100 pixels. (1199.5,5.5)->(0.5,4.5) runs right to left with slope 1/1199 and crosses y = 5 at the "
     "pixel corner x = 600, in no diamond; it lights 1199 pixels, all but its v1 pixel (0,4). "
     "(0,6.00390625)->(1200,7.99609375) descends almost two rows over 1200 columns, starting and ending "
     "1/256 inside rows 6 and 7. An incremental DDA in f32 drifts over 1000+ steps and gets the corner "
     "crossing or a step wrong; exact arithmetic gets all {N} pixels.",
     1200, 8, [dia((0.5, 1.5), (1100.5, 2.5)), dia((1199.5, 5.5), (0.5, 4.5)),
               dia((0, 6.00390625), (1200, 7.99609375))],
     checks=[("lit", 0, 550, 1), ("unlit", 0, 550, 2), ("lit", 0, 551, 2), ("unlit", 0, 1100, 2),
             ("unlit", 1, 0, 4), ("diamond", "upper")])

case("diamond_long_steep_1200",
     DIAMOND_TEXT + "The transpose of diamond_long_shallow_1200 on an 8x1200 canvas: three y-major lines "
     "1100 to 1200 rows long. (1.5,0.5)->(2.5,1100.5) crosses x = 2 exactly at y = 550.5, the right corner "
     "of (1,550), which a y-major line's diamond includes (lit), and the left corner of (2,550) (not lit); "
     "(5.5,1199.5)->(4.5,0.5) runs bottom to top; (6.00390625,0)->(7.99609375,1200) drifts almost two "
     "columns. {N} pixels.",
     8, 1200, [dia((1.5, 0.5), (2.5, 1100.5)), dia((5.5, 1199.5), (4.5, 0.5)),
               dia((6.00390625, 0), (7.99609375, 1200))],
     checks=[("lit", 0, 1, 550), ("unlit", 0, 2, 550), ("lit", 0, 2, 551), ("unlit", 0, 2, 1100),
             ("diamond", "no_right_corner")])

case("diamond_far_endpoints",
     DIAMOND_TEXT + "Lines with endpoints at the coordinate limits +-32768 (SPEC 8) crossing a 64x64 canvas, "
     "so neither endpoint's diamond is on the canvas and every canvas pixel the line meets is lit. The "
     "diagonal (-32768,-32768)->(32768,32768) through the pixel centres lights (i, i). The anti-diagonal "
     "(-32704.5,32768)->(32767.5,-32704), y = 63.5 - x, runs along the lower-right edges of the pixels with "
     "x + y = 62 (lit) and the upper-left edges of those with x + y = 63 (not lit). The very shallow "
     "(-32768,20.25)->(32768,43.75) rises 23.5 rows over 65536 columns. The steep (30.125,-32768)->"
     "(33.875,32768) stays within 0.004 of x = 32 on the canvas. The vertical (40,32768)->(40,-32768) runs "
     "up the pixel border x = 40, through the right corners of column 39, which this y-major line lights. "
     "In units of 1/256 the coordinates reach 2^23 and their products 2^46: 32-bit setups overflow, and f32 "
     "slopes lose the shallow line's rise.",
     64, 64, [dia((-32768, -32768), (32768, 32768)), dia((-32704.5, 32768), (32767.5, -32704)),
              dia((-32768, 20.25), (32768, 43.75)), dia((30.125, -32768), (33.875, 32768)),
              dia((40, 32768), (40, -32768))],
     checks=[("diamond", "no_right_corner"), ("diamond", "upper")],
     pixels={0: [(i, i) for i in range(64)], 1: [(i, 62 - i) for i in range(63)],
             4: [(39, j) for j in range(64)]})

case("diamond_colour_interpolation",
     DIAMOND_TEXT + "Colour along diamond-exit lines (SPEC 5) on a 32x32 canvas: four lines carrying depth z "
     "and three attributes (r, g, b), with w from 0.5 to 4. Lines 1 and 2 use parameter major, "
     "t = (c - x0)/(x1 - x0) for the pixel centre's x (y for the y-major line 2), and perspective "
     "interpolation; line 1 starts at (2.75, 3.5), a quarter pixel right of the centre of (2,3), which it "
     "lights (v0 is in its diamond), so that pixel's t is negative and clamped to 0. Lines 3 and 4 use "
     "parameter projected, the exact projection of the pixel centre onto the segment; line 3 is perspective "
     "and line 4 linear. Depth is always (1 - t) z0 + t z1. Lines 3 and 4 cross at (12,20), which takes line 4's values.",
     32, 32, [dia(iv(2.75, 3.5, 0.25, 0.5, [1, 0, 0.5]), iv(29.5, 12.25, 0.75, 4, [0, 1, -2]),
                  parameter="major"),
              dia(iv(28.25, 16.5, -1, 4, [0, 0, 1]), iv(20.5, 30.75, 3, 0.5, [1, 1, 0]), parameter="major"),
              dia(iv(2.5, 28, 0.5, 1, [0, 1, 0]), iv(16, 17.5, 0.125, 3, [1, 0, "1/3"]),
                  parameter="projected"),
              dia(iv(4, 12.5, 2, 2, [0.25, 0.5, 0.75]), iv(14, 22.5, -2, 0.75, [0.75, 0.5, 0.25]),
                  parameter="projected", interpolation="linear")],
     checks=[("parameter",), ("perspective",), ("clamp",), ("lit", 0, 2, 3)])

# ---------------------------------------------------------------------------
# An independent exact checker of SPEC.md sections 4 and 5.


def snap(v, bits, mode="even"):
    if bits is None:
        return v
    s = v * 2**bits
    fl = math.floor(s)
    r = s - fl
    if r > HALF:
        n = fl + 1
    elif r < HALF:
        n = fl
    elif mode == "even":
        n = fl if fl % 2 == 0 else fl + 1
    elif mode == "up":
        n = fl + 1
    elif mode == "down":
        n = fl
    elif mode == "away":
        n = fl + 1 if v > 0 else fl
    elif mode == "toward":
        n = fl if v > 0 else fl + 1
    elif mode == "odd":
        n = fl if fl % 2 == 1 else fl + 1
    else:
        raise ValueError(mode)
    return F(n, 2**bits)


OWNERS = {"top-left": {"top", "left"}, "bottom-right": {"bottom", "right"},
          "top-right": {"top", "right"}, "bottom-left": {"bottom", "left"},
          "all-edges": {"top", "left", "bottom", "right"}}
FLIP = {"top-left": "bottom-right", "bottom-right": "top-left", "top-right": "bottom-left",
        "bottom-left": "top-right", "all-edges": "all-edges"}


def edge_kind(nx, ny):
    if nx == 0:
        return "top" if ny < 0 else "bottom"
    return "left" if nx < 0 else "right"


def ceil(q):
    return -((-q.numerator) // q.denominator)


class Opts:
    """Knobs that model a wrong rasterizer, used to prove a case is sensitive."""

    def __init__(self, rule=None, snap_mode="even", tie="spec", xmajor_at_one=True,
                 parameter=None, interpolation=None, clamp=True, diamond="spec"):
        self.rule, self.snap_mode, self.tie = rule, snap_mode, tie
        self.diamond = diamond
        self.xmajor_at_one = xmajor_at_one
        self.parameter, self.interpolation, self.clamp = parameter, interpolation, clamp


def line_samples(c, ln, o, bits):
    """Yields (x, y, px, py) for every canvas sample the line covers, px, py
    the sample point."""
    W, H = c["width"], c["height"]
    (x0, y0), (x1, y1) = [tuple(snap(q, bits, o.snap_mode) for q in pos_of(v)) for v in ln.v]
    dx, dy = x1 - x0, y1 - y0
    if dx == 0 and dy == 0:
        return
    xmajor = abs(dx) > abs(dy) or (abs(dx) == abs(dy) and o.xmajor_at_one)
    fill = o.rule or c["fill_rule"]
    owners = OWNERS[fill]
    if ln.rule == "diamond-exit":
        yield from diamond_samples(c, (x0, y0), (x1, y1), xmajor, o.diamond)
        return
    if ln.rule == "midpoint":
        exclude = ln.last_pixel == "exclude"
        # Work in (major, minor) coordinates.
        if xmajor:
            a0, b0, a1, b1, n_major, n_minor = x0, y0, x1, y1, W, H
        else:
            a0, b0, a1, b1, n_major, n_minor = y0, x0, y1, x1, H, W
        lo, hi = min(a0, a1), max(a0, a1)
        first = max(0, ceil(lo - HALF))
        last = min(n_major - 1, math.floor(hi - HALF))
        for i in range(first, last + 1):
            m = i + HALF
            if exclude and m == a1:
                continue
            b = b0 + (m - a0) * (b1 - b0) / (a1 - a0)
            if o.tie == "spec":
                j = ceil(b) - 1
            else:  # the other row/column on a tie
                j = math.floor(b)
            if 0 <= j < n_minor:
                if xmajor:
                    yield i, j, m, j + HALF
                else:
                    yield j, i, j + HALF, m
        return
    w = ln.width if ln.width is not None else F(1)
    hw = w / 2
    for yy in range(H):
        py = yy + HALF
        for xx in range(W):
            px = xx + HALF
            on = []
            if ln.rule == "rectangle":
                qx, qy = px - x0, py - y0
                L = dx * dx + dy * dy
                a = qx * dx + qy * dy
                cr = qx * dy - qy * dx
                h2 = hw * hw * L
                if a < 0 or a > L or cr * cr > h2:
                    continue
                if a == 0:
                    on.append((-dx, -dy))
                if a == L:
                    on.append((dx, dy))
                if cr * cr == h2:
                    on.append((dy, -dx) if cr > 0 else (-dy, dx))
            else:
                if xmajor:
                    xl, xr = min(x0, x1), max(x0, x1)
                    if px < xl or px > xr:
                        continue
                    s = dy / dx
                    e = py - (y0 + (px - x0) * s)
                    if abs(e) > hw:
                        continue
                    if px == xl:
                        on.append((-1, 0))
                    if px == xr:
                        on.append((1, 0))
                    if e == hw:
                        on.append((-s, 1))
                    if e == -hw:
                        on.append((s, -1))
                else:
                    yt, yb = min(y0, y1), max(y0, y1)
                    if py < yt or py > yb:
                        continue
                    s = dx / dy
                    f = px - (x0 + (py - y0) * s)
                    if abs(f) > hw:
                        continue
                    if py == yt:
                        on.append((0, -1))
                    if py == yb:
                        on.append((0, 1))
                    if f == hw:
                        on.append((1, -s))
                    if f == -hw:
                        on.append((-1, s))
            if all(edge_kind(nx, ny) in owners for nx, ny in on):
                yield xx, yy, px, py


# The diamond-exit rule (SPEC 4.2). A diamond is the intersection of four
# half-planes a*u + b*v < 1/2 (strict) or <= 1/2 around the pixel centre, plus
# a list of extra points (the right corner of a y-major line's diamond). The
# variants other than "spec" model wrong rasterizers, to prove a case sensitive.

def diamond_shape(xmajor, variant):
    """([(a, b, strict)], [extra (u, v) points]) for the diamond of a line."""
    lower = [(-1, -1, True), (1, -1, True), (-1, 1, False), (1, 1, False)]
    right = [(HALF, F(0))]
    if variant in ("spec", "include_last", "exclude_first"):
        return lower, ([] if xmajor else right)
    if variant == "no_right_corner":       # the right corner never included
        return lower, []
    if variant == "right_corner_always":   # the right corner included for x-major lines too
        return lower, right
    if variant == "closed":                # every border point included
        return [(a, b, False) for a, b, _ in lower], []
    if variant == "open":                  # no border point included
        return [(a, b, True) for a, b, _ in lower], []
    if variant == "upper":                 # y up: upper edges and top corner instead
        return [(a, -b, st) for a, b, st in lower], ([] if xmajor else right)
    raise ValueError(variant)


def in_diamond(u, v, shape):
    planes, extra = shape
    if all((a * u + b * v < HALF) if st else (a * u + b * v <= HALF) for a, b, st in planes):
        return True
    return (u, v) in extra


def segment_meets_diamond(p0, p1, shape):
    """Whether the closed segment p0-p1 (relative to the pixel centre) has a
    point in the diamond: the parameter t in [0, 1] of p0 + t (p1 - p0) must
    satisfy every half-plane; each gives a bound on t, open or closed."""
    planes, extra = shape
    (u0, v0), (u1, v1) = p0, p1
    du, dv = u1 - u0, v1 - v0
    lo, lo_open, hi, hi_open = F(0), False, F(1), False
    feasible = True
    for a, b, st in planes:
        f0 = a * u0 + b * v0          # a*u + b*v at t = 0
        k = a * du + b * dv           # its rate in t
        if k == 0:
            if not ((f0 < HALF) if st else (f0 <= HALF)):
                feasible = False
            continue
        t = (HALF - f0) / k
        if k > 0:                     # t < bound (strict) or t <= bound
            if t < hi or (t == hi and st):
                hi, hi_open = t, (hi_open or st) if t == hi else st
        else:                         # t > bound (strict) or t >= bound
            if t > lo or (t == lo and st):
                lo, lo_open = t, (lo_open or st) if t == lo else st
    if feasible and (lo < hi or (lo == hi and not lo_open and not hi_open)):
        return True
    for eu, ev in extra:              # a lone border point on the segment
        qu, qv = eu - u0, ev - v0
        if qu * dv - qv * du == 0 and 0 <= qu * du + qv * dv <= du * du + dv * dv:
            return True
    return False


def diamond_samples(c, p0, p1, xmajor, variant):
    """Yields (x, y, px, py) for the canvas pixels a diamond-exit line lights."""
    W, H = c["width"], c["height"]
    shape = diamond_shape(xmajor, variant)
    (x0, y0), (x1, y1) = p0, p1
    excluded = p0 if variant == "exclude_first" else p1
    xa = max(0, math.floor(min(x0, x1)) - 1)
    xb = min(W - 1, math.floor(max(x0, x1)) + 1)
    ya = max(0, math.floor(min(y0, y1)) - 1)
    yb = min(H - 1, math.floor(max(y0, y1)) + 1)
    for yy in range(ya, yb + 1):
        cy = yy + HALF
        for xx in range(xa, xb + 1):
            cx = xx + HALF
            if not segment_meets_diamond((x0 - cx, y0 - cy), (x1 - cx, y1 - cy), shape):
                continue
            if variant != "include_last" and in_diamond(excluded[0] - cx, excluded[1] - cy, shape):
                continue
            yield xx, yy, cx, cy


def values_at(c, ln, o, bits, px, py):
    """(z or None, [attributes]) at the sample, exact (SPEC 5), and whether t was clamped."""
    (x0, y0), (x1, y1) = [tuple(snap(q, bits, o.snap_mode) for q in pos_of(v)) for v in ln.v]
    dx, dy = x1 - x0, y1 - y0
    parameter = o.parameter or ln.parameter or "major"
    interpolation = o.interpolation or ln.interpolation or "perspective"
    if parameter == "major":
        t = (px - x0) / dx if abs(dx) >= abs(dy) else (py - y0) / dy
    else:
        t = ((px - x0) * dx + (py - y0) * dy) / (dx * dx + dy * dy)
    clamped = t < 0 or t > 1
    if o.clamp:
        t = min(max(t, F(0)), F(1))
    v0, v1 = ln.v

    def get(v, what, default):
        if not isinstance(v, V):
            return default
        val = getattr(v, what)
        return default if val is None else val

    z0, z1 = get(v0, "z", F(0)), get(v1, "z", F(0))
    w0, w1 = get(v0, "w", F(1)), get(v1, "w", F(1))
    a0, a1 = get(v0, "attributes", []), get(v1, "attributes", [])
    z = (1 - t) * z0 + t * z1
    attrs = []
    for p, q in zip(a0, a1):
        if interpolation == "flat":
            attrs.append(p)
        elif interpolation == "linear":
            attrs.append((1 - t) * p + t * q)
        else:
            attrs.append(((1 - t) * p / w0 + t * q / w1) / ((1 - t) / w0 + t / w1))
    return z, attrs, clamped


def render_frame(c, o=None, bits="same", values=False):
    """{(x, y): [count, last index, z, attrs]} for every covered sample."""
    o = o or Opts()
    bits = c["bits"] if bits == "same" else bits
    out = {}
    clamped_any = False
    for idx, ln in enumerate(c["prims"]):
        seen = set()
        for x, y, px, py in line_samples(c, ln, o, bits):
            assert (x, y) not in seen, "a line covered a sample twice"
            seen.add((x, y))
            slot = out.setdefault((x, y), [0, None, None, None])
            slot[0] += 1
            slot[1] = idx
            if values:
                z, attrs, cl = values_at(c, ln, o, bits, px, py)
                slot[2], slot[3] = z, attrs
                clamped_any = clamped_any or cl
    if values:
        return out, clamped_any
    return out


def cover_sig(fr):
    return {k: (v[0], v[1]) for k, v in fr.items()}


def value_sig(fr):
    return {k: (v[0], v[1], v[2], tuple(v[3])) for k, v in fr.items()}


def has_values(c):
    return any(isinstance(v, V) for ln in c["prims"] for v in ln.v)


def check():
    ok = True
    frames = {}
    for c in CASES:
        notes = []
        fr = render_frame(c)
        frames[c["name"]] = fr
        n = len(fr)
        maxcov = max((v[0] for v in fr.values()), default=0)
        for kind, *arg in c["checks"]:
            if kind == "ties":
                diff = cover_sig(render_frame(c, Opts(tie="other"))) != cover_sig(fr)
                notes.append("ties %s" % ("hit" if diff else "NOT HIT"))
                ok &= diff
            elif kind == "fill_rule":
                diff = cover_sig(render_frame(c, Opts(rule=FLIP[c["fill_rule"]]))) != cover_sig(fr)
                notes.append("fill rule %s" % ("decides" if diff else "DOES NOT DECIDE"))
                ok &= diff
            elif kind == "snap":
                sens = [m for m in ("up", "down", "away", "toward", "odd")
                        if cover_sig(render_frame(c, Opts(snap_mode=m))) != cover_sig(fr)]
                if cover_sig(render_frame(c, bits=None)) != cover_sig(fr):
                    sens.append("unsnapped")
                notes.append("snap-sensitive to %s" % (",".join(sens) or "NOTHING"))
                ok &= bool(sens)
            elif kind == "xmajor_at_one":
                diff = cover_sig(render_frame(c, Opts(xmajor_at_one=False))) != cover_sig(fr)
                notes.append("x-major at slope 1 %s" % ("matters" if diff else "DOES NOT MATTER"))
                ok &= diff
            elif kind == "same_as":
                other = frames[arg[0]]
                same = {k: v[0] for k, v in other.items()} == {k: v[0] for k, v in fr.items()}
                notes.append("same pixels and counts as %s: %s" % (arg[0], same))
                ok &= same
            elif kind == "diamond":
                diff = cover_sig(render_frame(c, Opts(diamond=arg[0]))) != cover_sig(fr)
                notes.append("diamond %s %s" % (arg[0], "matters" if diff else "DOES NOT MATTER"))
                ok &= diff
            elif kind == "differs_from":
                other = frames[arg[0]]
                mine_px, theirs_px = set(fr), set(other)
                notes.append("differs from %s: only here %s, only there %s" % (
                    arg[0], fmt_px(sorted(mine_px - theirs_px)) or "-",
                    fmt_px(sorted(theirs_px - mine_px)) or "-"))
                ok &= mine_px != theirs_px
            elif kind in ("lit", "unlit"):
                idx, x, y = arg
                got = (x, y) in {(p[0], p[1]) for p in line_samples(c, c["prims"][idx], Opts(), c["bits"])}
                good = got == (kind == "lit")
                notes.append("%s (%d,%d) by %d: %s" % (kind, x, y, idx, good))
                ok &= good
            elif kind == "uncovered":
                good = (arg[0], arg[1]) not in fr
                notes.append("(%d,%d) uncovered: %s" % (arg[0], arg[1], good))
                ok &= good
            elif kind == "max_coverage":
                good = maxcov <= arg[0]
                notes.append("max coverage %d <= %d: %s" % (maxcov, arg[0], good))
                ok &= good
            elif kind == "min_coverage_max":
                good = maxcov >= arg[0]
                notes.append("max coverage %d >= %d: %s" % (maxcov, arg[0], good))
                ok &= good
            elif kind == "parameter":
                base, _ = render_frame(c, values=True)
                other_p = "major" if c["prims"][0].parameter == "projected" else "projected"
                alt, _ = render_frame(c, Opts(parameter=other_p), values=True)
                diff = value_sig(base) != value_sig(alt)
                notes.append("parameter %s" % ("matters" if diff else "DOES NOT MATTER"))
                ok &= diff
            elif kind == "perspective":
                base, _ = render_frame(c, values=True)
                alt, _ = render_frame(c, Opts(interpolation="linear"), values=True)
                diff = value_sig(base) != value_sig(alt)
                notes.append("perspective %s" % ("matters" if diff else "DOES NOT MATTER"))
                ok &= diff
            elif kind == "clamp":
                _, cl = render_frame(c, values=True)
                notes.append("clamping %s" % ("happens" if cl else "NEVER HAPPENS"))
                ok &= cl
        for idx, px in c["pixels"].items():
            got = sorted((x, y) for x, y, _, _ in line_samples(c, c["prims"][idx], Opts(), c["bits"]))
            if got != sorted(px):
                notes.append("DESCRIPTION PIXELS OF PRIMITIVE %d WRONG: checker %s" % (idx, fmt_px(got)))
                ok = False
        print("%-44s %5d covered, max %2d  %s" % (c["name"], n, maxcov, "; ".join(notes)))
    return ok


def compare_run():
    """Compares the checker's count with what `rastercheck run -r reference` prints."""
    exe = os.path.join(ROOT, "target", "release", "rastercheck")
    if not os.path.exists(exe):
        exe = os.path.join(ROOT, "target", "debug", "rastercheck")
    res = subprocess.run([exe, "run", os.path.join(ROOT, "cases", "lines"), "-r", "reference"],
                         capture_output=True, text=True)
    got = {}
    for line in res.stdout.splitlines():
        m = re.match(r"\s*(\S+)\s+lines/(\S+)\s+reference\s+coverage (\d+)/(\d+) samples", line)
        if m:
            got[m.group(2)] = int(m.group(3))
    ok = True
    for c in CASES:
        mine = len(render_frame(c))
        theirs = got.get(c["name"])
        if theirs != mine:
            print("COUNT MISMATCH %s: checker %d, rastercheck %s" % (c["name"], mine, theirs))
            ok = False
    print("run: %d cases compared by count, %s" % (len(got), "all agree" if ok else "DISAGREEMENT"))
    print("\n".join(res.stdout.splitlines()[-3:]))
    return ok


def compare_dump(path):
    """Compares whole frames with a JSON dump of the reference's frames."""
    with open(path) as f:
        dumps = {os.path.splitext(os.path.basename(d["path"]))[0]: d for d in json.load(f)}
    ok = True
    for c in CASES:
        d = dumps.get(c["name"])
        if d is None:
            print("NOT IN DUMP %s" % c["name"])
            ok = False
            continue
        fr, _ = render_frame(c, values=True)
        W = c["width"]
        bad = []
        for i, (cov, last) in enumerate(zip(d["coverage"], d["last"])):
            key = (i % W, i // W)
            mine = fr.get(key)
            if (mine[0] if mine else 0) != cov or (mine[1] + 1 if mine else 0) != last:
                bad.append("(%d,%d) checker %s reference %d/%d" % (
                    key[0], key[1], "%d/%d" % (mine[0], mine[1] + 1) if mine else "0/0", cov, last))
                continue
            if not mine or not has_values(c):
                continue
            chans = ([("depth", mine[2], d["depth"][i])] if d["depth"] else []) + \
                    [("attribute.%d" % k, mine[3][k], d["attributes"][k][i]) for k in range(len(mine[3]))]
            for name, ex, got in chans:
                g = F(float(got))
                tol = abs(ex) * F(1, 2**50) if ex != 0 else F(0)
                if abs(g - ex) > tol:
                    bad.append("(%d,%d) %s checker %s reference %r" % (key[0], key[1], name, float(ex), got))
        if bad:
            ok = False
            mine_px = sorted(fr)
            theirs_px = sorted((i % W, i // W) for i, cov in enumerate(d["coverage"]) if cov)
            print("FRAME MISMATCH %s: %d samples differ\n  %s" % (c["name"], len(bad), "\n  ".join(bad[:40])))
            print("  checker pixels:   %s" % fmt_px(mine_px))
            print("  reference pixels: %s" % fmt_px(theirs_px))
        else:
            print("frame agrees %s" % c["name"])
    return ok


def main():
    names = [c["name"] for c in CASES]
    assert len(names) == len(set(names)), "duplicate case names"
    os.makedirs(OUT_DIR, exist_ok=True)
    for c in CASES:
        expect = {}
        n = len(render_frame(c))
        if c["covered"]:
            expect["samples_covered"] = n
        c["description"] = c["description"].replace("{N}", str(n))
        with open(os.path.join(OUT_DIR, c["name"] + ".json"), "w") as f:
            f.write(render(c, expect))
    print("wrote %d cases to %s" % (len(CASES), OUT_DIR))
    args = sys.argv[1:]
    ok = True
    if "--check" in args:
        ok &= check()
    if "--compare" in args:
        ok &= compare_run()
    if "--compare-dump" in args:
        ok &= compare_dump(args[args.index("--compare-dump") + 1])
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
