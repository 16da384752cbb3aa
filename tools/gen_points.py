#!/usr/bin/env python3
"""Writes the point cases: cases/points/*.json (SPEC.md section 17).

Python 3 standard library only. Every `expect.samples_covered` is computed
here by an exact model of section 17 written from SPEC.md alone, with
Fractions: the centre snapped to subpixel_bits (ties to even, section 2),
in clip space first divided and put through the viewport (section 16.1);
the square [X - h, X + h] x [Y - h, Y + h] with h = size / 2; a pixel
centre (i + 1/2) inside it when it lies between the two sides, each side
closed when the fill rule owns it (left and top for top-left, ...);
clip-space points discarded whole by their centre (w <= 0; z outside
[0, w] under depth clip; x or y outside [-w, w] under clip_points: pop);
and a kept square limited by the canvas, and under point_bounds: viewport
by the viewport rectangle too (pixel centres in [x, x + width) x
[y, y + height)). A case that mixes in a
triangle places it so that no pixel centre lies on its edges (the model
asserts so), so the triangle needs no tie rule here.

Usage: python3 tools/gen_points.py [-v] [--check]
  -v       one line per case: its name and samples_covered
  --check  write nothing: compare the generated cases with the files in
           cases/points; exit 1 naming each file that differs, is missing,
           or is in cases/points but not generated
Before writing, the model is checked against three wrong models (the
square not snapped; popping under guard-band; point_bounds: viewport
ignored): each must change some case's pin.
"""

import math
import os
import sys
from fractions import Fraction as F

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "cases", "points")

# Which sides own their samples: (left, right, top, bottom).
OWNS = {
    "top-left": (True, False, True, False),
    "bottom-right": (False, True, False, True),
    "top-right": (False, True, True, False),
    "bottom-left": (True, False, False, True),
    "all-edges": (True, True, True, True),
}


def snap(v, bits):
    """v rounded to a multiple of 2^-bits, ties to even (section 2)."""
    if bits is None:
        return v
    s = v * 2**bits
    fl = math.floor(s)
    r = s - fl
    n = fl + 1 if r > F(1, 2) or (r == F(1, 2) and fl % 2 == 1) else fl
    return F(n, 2**bits)


def inside(c, low, high, low_closed, high_closed):
    above = c >= low if low_closed else c > low
    below = c <= high if high_closed else c < high
    return above and below


class Case:
    def __init__(self, name, description, primitives, width=16, height=16,
                 bits=8, fill_rule="top-left", clip=None, viewport=None,
                 watertight=False):
        self.name, self.description = name, description
        self.watertight = watertight
        self.primitives = primitives
        self.width, self.height = width, height
        self.bits, self.fill_rule = bits, fill_rule
        self.clip = clip  # None: screen space; else the clip rules
        self.viewport = viewport


def centre_of(case, vertex, wrong):
    """The snapped centre, or None when the point is discarded."""
    bits = None if wrong == "unsnapped" else case.bits
    if case.clip is None:
        x, y = F(vertex["position"][0]), F(vertex["position"][1])
        return snap(x, bits), snap(y, bits)
    x, y, z, w = (F(c) for c in vertex["clip"])
    if w <= 0:
        return None
    rules = case.clip
    if rules.get("depth", "clip") == "clip" and (z < 0 or z > w):
        return None
    pop = rules.get("clip_points", "pop") == "pop" or wrong == "pops"
    if pop and (x < -w or x > w or y < -w or y > w):
        return None
    vp = {"x": 0, "y": 0, "width": case.width, "height": case.height}
    vp.update(case.viewport or {})
    vx, vy, vw, vh = (F(vp[k]) for k in ("x", "y", "width", "height"))
    return snap(vx + vw / 2 * (x / w + 1), bits), snap(vy + vh / 2 * (y / w + 1), bits)


def triangle_covers(case, tri, px, py):
    """A screen-space triangle's cover of pixel centre (px, py); asserts
    the centre is on no edge, so that no tie rule is needed."""
    def place(v):
        if isinstance(v, list):
            return snap(F(v[0]), case.bits), snap(F(v[1]), case.bits)
        # A clip-space vertex inside the clip volume, default viewport.
        x, y, _, w = (F(c) for c in v["clip"])
        assert -w < x < w and -w < y < w and case.viewport is None
        return (snap(F(case.width, 2) * (x / w + 1), case.bits),
                snap(F(case.height, 2) * (y / w + 1), case.bits))
    pts = [place(v) for v in tri]
    c = (F(px) + F(1, 2), F(py) + F(1, 2))
    signs = []
    for i in range(3):
        a, b = pts[i], pts[(i + 1) % 3]
        e = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        assert e != 0, "a pixel centre on a triangle edge in %s" % case.name
        signs.append(e > 0)
    return all(signs) or not any(signs)


def coverage(case, wrong=None):
    """Each pixel's covering primitives' count, row by row."""
    owns = OWNS[case.fill_rule]
    counts = [[0] * case.width for _ in range(case.height)]
    for p in case.primitives:
        if "triangle" in p:
            for py in range(case.height):
                for px in range(case.width):
                    counts[py][px] += triangle_covers(case, p["triangle"], px, py)
            continue
        centre = centre_of(case, p["point"], wrong)
        if centre is None:
            continue
        h = F(p.get("size", 1)) / 2
        bounded = case.clip is not None and wrong != "unbounded" and \
            case.clip.get("point_bounds", "canvas") == "viewport"
        vp = {"x": 0, "y": 0, "width": case.width, "height": case.height}
        vp.update(case.viewport or {})
        vx, vy, vw, vh = (F(vp[k]) for k in ("x", "y", "width", "height"))
        for py in range(case.height):
            for px in range(case.width):
                cx, cy = F(px) + F(1, 2), F(py) + F(1, 2)
                if bounded and not (vx <= cx < vx + vw and vy <= cy < vy + vh):
                    continue
                if inside(cx, centre[0] - h, centre[0] + h, owns[0], owns[1]) and \
                        inside(cy, centre[1] - h, centre[1] + h, owns[2], owns[3]):
                    counts[py][px] += 1
    return counts


def covered(case, wrong=None):
    return sum(1 for row in coverage(case, wrong) for c in row if c > 0)


# --- The cases -------------------------------------------------------------

def pt(x, y, size=None, **more):
    v = {"position": [x, y]}
    v.update(more)
    d = {"point": v}
    if size is not None:
        d["size"] = size
    return d


def cpt(x, y, z, w, size=None, attributes=None):
    v = {"clip": [x, y, z, w]}
    if attributes is not None:
        v["attributes"] = attributes
    d = {"point": v}
    if size is not None:
        d["size"] = size
    return d


CLIP = {"clip_xy": "guard-band", "depth": "clip"}
GB = {"clip_xy": "guard-band", "depth": "clip", "clip_points": "guard-band"}


def cases():
    out = [
        Case("spec_square", "SPEC.md section 17.1's worked example: size 3 centred on the pixel corner (4, 4). h = 3/2, the square [2.5, 5.5]^2; under top-left its left and top sides (through the centres of column and row 2) own their samples, its right and bottom sides (through column and row 5) do not: columns and rows 2, 3, 4, 9 samples.",
             [pt(4, 4, 3)]),
        Case("spec_square_all_edges", "The square of spec_square under all-edges: every side owns its samples, columns and rows 2 to 5, 16 samples.",
             [pt(4, 4, 3)], fill_rule="all-edges"),
        Case("size1_pixel_centre", "Size 1 centred on the centre of pixel (2, 2): the square [2, 3]^2 holds that centre only.",
             [pt("2.5", "2.5")]),
        Case("size2_pixel_centre", "Size 2 centred on the centre of pixel (4, 4): [3.5, 5.5]^2 passes through the centres of columns and rows 3 and 5; top-left keeps 3 and 4: 4 samples.",
             [pt("4.5", "4.5", 2)]),
        Case("size3_pixel_centre", "Size 3 (odd) centred on a pixel centre: [3, 6]^2 holds columns and rows 3, 4, 5 with no sample on a side: 9 samples.",
             [pt("4.5", "4.5", 3)]),
        Case("size4_pixel_corner", "Size 4 (even) centred on the pixel corner (8, 8): [6, 10]^2 holds columns and rows 6 to 9 with no sample on a side: 16 samples.",
             [pt(8, 8, 4)]),
        Case("size_half_centre", "Size 0.5 centred on the centre of pixel (3, 3): [3.25, 3.75]^2 holds it: 1 sample.",
             [pt("3.5", "3.5", "0.5")]),
        Case("size_half_corner", "Size 0.5 centred on the pixel corner (3, 3): [2.75, 3.25]^2 holds no pixel centre: a point that covers nothing.",
             [pt(3, 3, "0.5")]),
        Case("size_4_75", "Size 4.75 centred at (5.25, 6.5): h = 2.375, x in [2.875, 7.625] holds the centres of columns 3 to 7, y in [4.125, 8.875] rows 4 to 8: 25 samples.",
             [pt("5.25", "6.5", "4.75")]),
        Case("size_third", "Size 1/3, not a multiple of any power of two: h = 1/6, the square [7/3, 8/3]^2 around the centre of pixel (2, 2) holds it: 1 sample.",
             [pt("2.5", "2.5", "1/3")]),
        Case("exact_tie_top_left", "subpixel_bits null: the exact centre (3.375, 2.375) and size 0.25 put the right and bottom sides through the pixel centre (3.5, 2.5), which top-left leaves open: nothing.",
             [pt("3.375", "2.375", "0.25")], bits=None),
        Case("exact_tie_bottom_right", "exact_tie_top_left under bottom-right: its right and bottom sides own the centre (3.5, 2.5): 1 sample.",
             [pt("3.375", "2.375", "0.25")], bits=None, fill_rule="bottom-right"),
        Case("snap_moves_centre", "subpixel_bits 2: x = 3.3 snaps to 3.25 (13.2 quarter pixels round to 13), so the size-1.5 square is [2.5, 4] x [1.75, 3.25] and top-left covers columns 2 and 3 (2.5 on its owned left side) of row 2; unsnapped it would be [2.55, 4.05] and cover column 3 only.",
             [pt("3.3", "2.5", "1.5")], bits=2),
        Case("snap_tie_to_even", "subpixel_bits 1: x = 3.25 is 6.5 half pixels, a tie, rounded to even 6: X = 3, the size-1 square's left side through column 2's centre, kept by top-left. Rounding the tie up would move it to 3.5 and cover column 3 instead.",
             [pt("3.25", "5.5")], bits=1),
        Case("snap_subpixel_fraction", "subpixel_bits 4: (5.53, 4.47) snaps to (5.5, 4.5) (88.48 and 71.52 sixteenths round to 88 and 72): size 2 gives [4.5, 6.5] x [3.5, 5.5], columns 4, 5 and rows 3, 4 under top-left.",
             [pt("5.53", "4.47", 2)], bits=4),
        Case("off_canvas_left", "Size 4 centred at (-1, 4), left of the canvas: [-3, 1] x [2, 6] reaches column 0 only; rows 2 to 5: 4 samples.",
             [pt(-1, 4, 4)]),
        Case("off_canvas_corner", "Size 6 centred at (17, 17), beyond the bottom-right corner of the 16 x 16 canvas: [14, 20]^2 covers columns and rows 14 and 15: 4 samples.",
             [pt(17, 17, 6)]),
        Case("size_1024", "The largest size, 1024, centred on the canvas: the whole 16 x 16 canvas.",
             [pt(8, 8, 1024)]),
        Case("overlap_last_wins", "Three overlapping points: sizes 6, 4 and 2 centred at (8, 8); each later one draws over the earlier, so the owner of the middle 2 x 2 samples is the last (the golden file holds the owners): 36 samples covered.",
             [pt(8, 8, 6, attributes=[1]), pt(8, 8, 4, attributes=[2]), pt(8, 8, 2, attributes=[3])]),
        Case("depth_and_attributes", "A size-3 point with z = 0.25 and attributes [1, -2.5]: the same depth and attributes at its 9 samples.",
             [pt("4.5", "4.5", 3, z="0.25", attributes=[1, "-2.5"])]),
        Case("with_triangle", "A point drawn over a triangle: the triangle (1.2, 1.3), (14.2, 2.1), (3.3, 13.1) and a size-4 point at (10, 10) partly outside it.",
             [{"triangle": [["1.2", "1.3"], ["14.2", "2.1"], ["3.3", "13.1"]]}, pt(10, 10, 4)]),
        # Clip space: the default viewport maps x = -w..w onto 0..16.
        Case("spec_clip_on_plane", "SPEC.md section 17.2's worked example: a centre exactly on the plane x = w (clip (1, 0, 0.5, 1)) is inside and kept under pop: x_f = 16, y_f = 8, size 4 gives [14, 18] x [6, 10]; the canvas keeps columns 14 and 15, rows 6 to 9: 8 samples.",
             [cpt(1, 0, "0.5", 1, 4)], clip=CLIP),
        Case("spec_clip_pop", "SPEC.md section 17.2: just outside x = w (x = 1.25, x_f = 18) the centre is outside and pop discards the point whole, though its square [15, 21] would reach column 15.",
             [cpt("1.25", 0, "0.5", 1, 6)], clip=CLIP),
        Case("spec_clip_guard_band", "SPEC.md section 17.2: spec_clip_pop under clip_points: guard-band: nothing is discarded, the square [15, 21] x [5, 11] reaches column 15, rows 5 to 10: 6 samples.",
             [cpt("1.25", 0, "0.5", 1, 6)], clip=GB),
        Case("clip_x_minus_w", "Centre on x = -w (clip (-2, 0, 1, 2)): kept; x_f = 0, size 4: columns 0 and 1, rows 6 to 9: 8 samples.",
             [cpt(-2, 0, 1, 2, 4)], clip=CLIP),
        Case("clip_y_plus_w", "Centre on y = w: kept; y_f = 16, size 4: rows 14 and 15, columns 6 to 9: 8 samples.",
             [cpt(0, 1, "0.5", 1, 4)], clip=CLIP),
        Case("clip_y_minus_w_outside", "Centre just outside y = -w (y = -1.0625 w): popped, nothing drawn.",
             [cpt(0, "-1.0625", "0.5", 1, 4)], clip=CLIP),
        Case("clip_y_minus_w_outside_guard_band", "clip_y_minus_w_outside under clip_points: guard-band: y_f = -0.5, the square [-2.5, 1.5] reaches row 0 (row 1's centre 1.5 lies on its open bottom side), columns 6 to 9: 4 samples.",
             [cpt(0, "-1.0625", "0.5", 1, 4)], clip=GB),
        Case("clip_z_zero", "z = 0 on the near plane: kept, depth 0.",
             [cpt(0, 0, 0, 1, 2)], clip=CLIP),
        Case("clip_z_w", "z = w on the far plane: kept, depth 1.",
             [cpt(0, 0, 2, 2, 2)], clip=CLIP),
        Case("clip_z_near_clip", "z just below 0 under depth clip (clip_z: clip-then-snap): the centre is outside, the point discarded.",
             [cpt(0, 0, "-0.001", 1, 2)], clip=dict(CLIP, clip_z="clip-then-snap")),
        Case("clip_z_near_per_sample", "z just below 0 under depth clip with clip_z: per-sample: a point is discarded by its centre whatever clip_z says.",
             [cpt(0, 0, "-0.001", 1, 2)], clip=dict(CLIP, clip_z="per-sample")),
        Case("clip_z_near_clamp", "z just below 0 under depth clamp: drawn, its depth clamped to 0.",
             [cpt(0, 0, "-0.001", 1, 2)], clip={"clip_xy": "guard-band", "depth": "clamp"}),
        Case("clip_z_far_clamp", "z = 1.5 w beyond the far plane under depth clamp, viewport depth range [0.25, 0.75]: drawn, its depth 0.25 + 0.5 * 1.5 = 1 clamped to 0.75.",
             [cpt(0, 0, 3, 2, 2)], clip={"clip_xy": "guard-band", "depth": "clamp"},
             viewport={"min_depth": "0.25", "max_depth": "0.75"}),
        Case("clip_w_zero", "w = 0: discarded, even under clip_points: guard-band.",
             [cpt(0, 0, 0, 0, 4)], clip=GB),
        Case("clip_w_negative", "w = -1, the point behind the eye: discarded, even under clip_points: guard-band and depth clamp.",
             [cpt(0, 0, "-0.5", -1, 4)], clip={"clip_xy": "guard-band", "depth": "clamp", "clip_points": "guard-band"}),
        Case("clip_w_tiny", "w = 10^-6, x = 5 * 10^-7: x/w = 1/2, x_f = 12, y_f = 8; size 2: columns 11 and 12, rows 7 and 8.",
             [cpt("0.0000005", 0, 0, "0.000001", 2)], clip=CLIP),
        Case("clip_w_huge", "w = 10^6, x = -250000 w/10^6: x/w = -1/4, x_f = 6, y_f = 8; size 3: [4.5, 7.5] holds columns 4 to 6 (4.5 owned by top-left), [6.5, 9.5] rows 6 to 8: 9 samples.",
             [cpt(-250000, 0, 500000, 1000000, 3)], clip=CLIP),
        Case("clip_perspective_attributes", "w = 2 and attributes [4, 8]: a point's attributes are the vertex's, not divided by w (it takes no interpolation); depth z/w = 0.25.",
             [cpt("0.5", "-0.5", "0.5", 2, 2, attributes=[4, 8])], clip=CLIP),
        Case("clip_viewport_not_a_scissor", "Viewport (4, 4, 8, 8); a centre on x = w lands on its right side x_f = 12, y_f = 8; size 6 gives [9, 15] x [5, 11]: the square reaches 3 columns outside the viewport and is drawn whole: 36 samples.",
             [cpt(1, 0, "0.5", 1, 6)], clip=CLIP, viewport={"x": 4, "y": 4, "width": 8, "height": 8}),
        Case("spec_bounds_viewport", "SPEC.md section 17.2's worked example of point_bounds: clip_viewport_not_a_scissor under point_bounds: viewport. The square [9, 15] x [5, 11] is limited to the viewport rectangle [4, 12) x [4, 12): columns 9 to 11, rows 5 to 10: 18 samples (36 under canvas).",
             [cpt(1, 0, "0.5", 1, 6)], clip=dict(CLIP, point_bounds="viewport"), viewport={"x": 4, "y": 4, "width": 8, "height": 8}),
        Case("clip_bounds_guard_band_outside", "clip_points: guard-band with point_bounds: viewport, as Mesa's lavapipe draws: viewport (4, 4, 8, 8), a centre outside x = w (x = 1.25 w) is kept at x_f = 13, y_f = 8; size 6 gives [10, 16] x [5, 11], limited to the viewport's columns 10 and 11, rows 5 to 10: 12 samples (36 under canvas; none under pop).",
             [cpt("1.25", 0, "0.5", 1, 6)], clip=dict(GB, point_bounds="viewport"), viewport={"x": 4, "y": 4, "width": 8, "height": 8}),
        Case("clip_bounds_fractional_viewport", "point_bounds: viewport with a viewport edge through pixel centres: viewport (4.5, 4, 8, 8), a centre on x = -w lands on its left side x_f = 4.5, y_f = 8; size 4 gives [2.5, 6.5] x [6, 10]. The rectangle [4.5, 12.5) holds the centre 4.5 of column 4 (closed at its left) and not 12.5: columns 4 and 5, rows 6 to 9: 8 samples.",
             [cpt(-1, 0, "0.5", 1, 4)], clip=dict(CLIP, point_bounds="viewport"), viewport={"x": "4.5", "y": 4, "width": 8, "height": 8}),
        Case("clip_with_triangle", "A clip-space triangle wholly inside the clip volume, and a point over it: x_f = 8 (1 + x), so the triangle lands at (1.6, 2.4), (14.4, 3.2), (4, 13.6); the point at (12, 12), size 4.",
             [{"triangle": [{"clip": ["-0.8", "-0.7", "0.5", 1]}, {"clip": ["0.8", "-0.6", "0.5", 1]}, {"clip": ["-0.5", "0.7", "0.5", 1]}]},
              cpt("0.5", "0.5", "0.25", 1, 4)], clip=CLIP),
    ]
    out.append(Case("tiling_size2", "Sixteen size-2 points centred on the odd pixel corners (1, 1), (3, 1), ..., (7, 7) tile the 8 x 8 canvas: the squares [2i, 2i + 2] x [2j, 2j + 2] meet on pixel edges, no pixel centre lies on a side, and each of the 64 centres is covered exactly once (watertight).",
                    [pt(2 * i + 1, 2 * j + 1, 2) for j in range(4) for i in range(4)],
                    width=8, height=8, watertight=True))
    out.append(Case("tiling_size1_ties", "Size-1 points centred on the pixel corners (i, j), i, j = 1..4: every side passes through pixel centres, and top-left gives each centre to exactly one square (the one whose left and top sides hold it): the 4 x 4 block of pixels 0..3 covered once each, watertight.",
                    [pt(i, j) for j in range(1, 5) for i in range(1, 5)],
                    width=6, height=6, watertight=True))
    for rule in ["top-left", "bottom-right", "top-right", "bottom-left", "all-edges"]:
        out.append(Case("ties_%s" % rule.replace("-", "_"),
                        "Size 1 centred on the pixel corner (3, 6): every side passes through pixel centres (columns 2 and 3, rows 5 and 6); %s owns %s." % (
                            rule, {"top-left": "the left and top sides: pixel (2, 5)",
                                   "bottom-right": "the right and bottom sides: pixel (3, 6)",
                                   "top-right": "the right and top sides: pixel (3, 5)",
                                   "bottom-left": "the left and bottom sides: pixel (2, 6)",
                                   "all-edges": "all four: 4 pixels"}[rule]),
                        [pt(3, 6)], fill_rule=rule))
    return out


# --- Writing ---------------------------------------------------------------

def js(v, indent=""):
    """JSON text with numbers exact: a decimal string is written as a JSON
    number, a fraction "p/q" as a string."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, str):
        if "/" not in v:
            try:
                F(v)
                return v
            except ValueError:
                pass
        return '"%s"' % v.replace("\\", "\\\\").replace('"', '\\"')
    if isinstance(v, list):
        return "[" + ", ".join(js(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join('"%s": %s' % (k, js(x)) for k, x in v.items()) + "}"
    if v is None:
        return "null"
    raise TypeError(v)


def text(case):
    rules = {"subpixel_bits": case.bits, "fill_rule": case.fill_rule, "cull": "none"}
    rules.update(case.clip or {})
    lines = ["{",
             '  "name": %s,' % js(case.name),
             '  "description": "%s",' % case.description.replace('"', '\\"'),
             '  "canvas": {"width": %d, "height": %d},' % (case.width, case.height),
             '  "rules": %s,' % js(rules)]
    if case.viewport:
        lines.append('  "viewport": %s,' % js(case.viewport))
    lines.append('  "primitives": [')
    lines.append(",\n".join("    " + js(p) for p in case.primitives))
    lines.append("  ],")
    if case.watertight:
        # A mesh of squares: no sample covered twice, none left inside.
        assert max(c for row in coverage(case) for c in row) == 1, case.name
        lines.append('  "expect": {"watertight": true, "samples_covered": %d}' % covered(case))
    else:
        lines.append('  "expect": {"samples_covered": %d}' % covered(case))
    lines.append("}")
    return "\n".join(lines) + "\n"


def main():
    args = sys.argv[1:]
    all_cases = cases()
    # Each wrong model must change some pin, or the cases do not tell it.
    for wrong in ["unsnapped", "pops", "unbounded"]:
        changed = [c.name for c in all_cases if covered(c, wrong) != covered(c)]
        assert changed, "no case tells the %s model from the right one" % wrong
        if "-v" in args:
            print("wrong model %s changes %s" % (wrong, ", ".join(changed)))
    files = {c.name + ".json": text(c) for c in all_cases}
    if "-v" in args:
        for c in all_cases:
            print("%-40s %d" % (c.name, covered(c)))
    if "--check" in args:
        bad = []
        present = set(os.listdir(OUT)) if os.path.isdir(OUT) else set()
        for name, body in files.items():
            path = os.path.join(OUT, name)
            if not os.path.exists(path):
                bad.append("missing: " + name)
            elif open(path).read() != body:
                bad.append("differs: " + name)
        for name in sorted(present - set(files)):
            if name.endswith(".json"):
                bad.append("not generated: " + name)
        for b in bad:
            print(b)
        sys.exit(1 if bad else 0)
    os.makedirs(OUT, exist_ok=True)
    for name, body in files.items():
        with open(os.path.join(OUT, name), "w") as f:
            f.write(body)
    print("wrote %d cases to %s" % (len(files), OUT))


if __name__ == "__main__":
    main()
