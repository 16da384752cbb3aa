"""Screen space, written apart from the homogeneous model: the sample test of
SPEC sections 2 and 3 on snapped screen vertices (twice-signed area, edge
functions, the fill rule by the edge's direction), used to check section
16.7 (a triangle inside the clip volume is drawn as its screen-space
triangle), and the screen-space worked example of section 16.6,
cases/triangles/spec_provoking_last.json.
"""

import json
import os
from fractions import Fraction as F

from casegen.casefile import V
from casegen.exactjson import js
from casegen.snapping import snap


def owned(dx, dy, area, fill_rule):
    """Does the edge with direction (dx, dy), walked with the triangle's
    winding made clockwise (area > 0), own its samples? Clockwise with y down:
    a top edge runs to +x, a bottom edge to -x, a left edge upward (dy < 0),
    a right edge downward."""
    if area < 0:
        dx, dy = -dx, -dy
    top, bottom = dy == 0 and dx > 0, dy == 0 and dx < 0
    left, right = dy < 0, dy > 0
    return {"top-left": top or left, "bottom-right": bottom or right,
            "top-right": top or right, "bottom-left": bottom or left,
            "all-edges": True}[fill_rule]


def covers(p, s, fill_rule, cull="none"):
    """Does the screen triangle p (three snapped (x, y)) cover sample s?"""
    area = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0])
    if area == 0 or (cull == "cw" and area > 0) or (cull == "ccw" and area < 0):
        return False
    for i in range(3):
        a, b = p[i], p[(i + 1) % 3]
        e = (b[0] - a[0]) * (s[1] - a[1]) - (b[1] - a[1]) * (s[0] - a[0])
        e = e if area > 0 else -e
        if e < 0 or (e == 0 and not owned(b[0] - a[0], b[1] - a[1], area, fill_rule)):
            return False
    return True


def coverage(tris, width, height, bits, fill_rule, cull="none"):
    """{(i, j): (count, last)} of screen triangles, each three (x, y)."""
    frame = {}
    snapped = [[(snap(x, bits), snap(y, bits)) for x, y in t] for t in tris]
    for j in range(height):
        for i in range(width):
            s = (F(2 * i + 1, 2), F(2 * j + 1, 2))
            for index, p in enumerate(snapped):
                if covers(p, s, fill_rule, cull):
                    count, _ = frame.get((i, j), (0, None))
                    frame[(i, j)] = (count + 1, index)
    return frame


PROVOKING = [V("1.5", 1, z="0.25", attributes=[1, 0, 0]),
             V(14, "3.5", z="0.5", attributes=[0, 1, 0]),
             V(4, "14.5", z="0.75", attributes=["1/3", "2/3", 5])]


def provoking_last_case():
    """(path, text) of cases/triangles/spec_provoking_last.json."""
    n = len(coverage([[v.pos() for v in PROVOKING]], 16, 16, 8, "top-left"))
    description = (
        "SPEC 5 and 16.6: a flat triangle under rules.provoking_vertex: last (OpenGL's default) "
        "takes the values of its third vertex, (1/3, 2/3, 5), at every one of its %d samples; "
        "under Vulkan's and D3D's first it would take (1, 0, 0). The depth stays screen-space "
        "linear (0.25 to 0.75) whatever the interpolation. A rasterizer that ignores the rule "
        "gets every attribute wrong at every sample." % n)
    rules = {"subpixel_bits": 8, "fill_rule": "top-left", "cull": "none",
             "provoking_vertex": "last"}
    lines = ["{",
             '  "name": "spec_provoking_last_screen_space",',
             '  "description": %s,' % js(description),
             '  "canvas": {"width": 16, "height": 16},',
             '  "rules": %s,' % js(rules),
             '  "primitives": [',
             "    " + js({"triangle": [v.json() for v in PROVOKING], "interpolation": "flat"}),
             "  ],",
             '  "expect": %s' % js({"samples_covered": n}),
             "}"]
    text = "\n".join(lines) + "\n"
    json.loads(text)
    return os.path.join("cases", "triangles", "spec_provoking_last.json"), text
