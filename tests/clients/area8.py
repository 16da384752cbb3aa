#!/usr/bin/env python3
"""An 8-bit area-coverage rasterizer speaking protocol v2 coverage only
(SPEC.md §12.9), for tests/external_coverage.rs.

It is what a 2D antialiasing library computes: each triangle's exact area
in each pixel (Sutherland-Hodgman clipping to the pixel square, in exact
fractions), rounded to a multiple of 1/255 before the primitives are added,
so two triangles that share an edge through a pixel can give 256/255 there.
Without antialiasing it point-samples pixel centres, exactly, with the
top-left rule, and gives no depth and no attributes.

Flags (each makes it wrong, or undeclared, in one way):
  --no-bits     declare no coverage_bits: its rounding is then undeclared
  --swap        move 8/255 of coverage from primitive 0 to primitive 1 on
                pixels both partly cover (the sum is unchanged)
  --no-coverage-only  do not declare coverage_only (fragments then lack
                the values the plan asks for: an error)
  --rule R      follow the fill rule R whatever the case states, and
                declare it as its convention (conventions.fill_rule)
  --declare D   declare D as its convention, whatever it follows
"""

import json
import sys
from fractions import Fraction

ARGS = sys.argv[1:]
FLAGS = set(ARGS)
STEP = 255


def option(name):
    return ARGS[ARGS.index(name) + 1] if name in ARGS else None


RULE = option("--rule")
DECLARED = option("--declare") or RULE
# The nudge of SPEC.md §3: a sample on an edge is inside when the sample
# moved by (sx·e, sy·e²) is.
NUDGE = {"top-left": (1, 1), "bottom-right": (-1, -1), "top-right": (-1, 1), "bottom-left": (1, -1)}


def exact(v):
    return Fraction(v)


def snap(v, bits):
    if bits is None:
        return v
    scale = 2 ** bits
    return Fraction(round(v * scale), scale)  # round() on a Fraction is half-even


def vertices(tri, bits):
    return [(snap(exact(v["exact"]["x"]), bits), snap(exact(v["exact"]["y"]), bits)) for v in tri]


def twice_area(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def culled(pts, cull):
    area = twice_area(*pts)
    return area == 0 or (cull == "cw" and area > 0) or (cull == "ccw" and area < 0)


def clip(poly, inside, cross):
    out = []
    for i, p in enumerate(poly):
        q = poly[(i + 1) % len(poly)]
        if inside(p):
            out.append(p)
            if not inside(q):
                out.append(cross(p, q))
        elif inside(q):
            out.append(cross(p, q))
    return out


def pixel_area(pts, x, y):
    poly = list(pts)
    for axis, bound, keep_above in ((0, x, True), (0, x + 1, False), (1, y, True), (1, y + 1, False)):
        def inside(p, axis=axis, bound=bound, keep_above=keep_above):
            return p[axis] >= bound if keep_above else p[axis] <= bound

        def cross(p, q, axis=axis, bound=bound):
            t = (bound - p[axis]) / (q[axis] - p[axis])
            return (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))

        poly = clip(poly, inside, cross)
        if not poly:
            return Fraction(0)
    s = sum(poly[i][0] * poly[(i + 1) % len(poly)][1] - poly[(i + 1) % len(poly)][0] * poly[i][1]
            for i in range(len(poly)))
    return abs(s) / 2


def box(pts, width, height):
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    x0, x1 = max(0, int(min(xs)) - 1), min(width, int(max(xs)) + 2)
    y0, y1 = max(0, int(min(ys)) - 1), min(height, int(max(ys)) + 2)
    return range(x0, x1), range(y0, y1)


def coverage(pts, width, height):
    """{(x, y): k} with k/255 the 8-bit coverage of each touched pixel."""
    xs, ys = box(pts, width, height)
    out = {}
    for y in ys:
        for x in xs:
            k = round(pixel_area(pts, x, y) * STEP)
            if k:
                out[(x, y)] = k
    return out


def covers(pts, sx, sy, rule, y_up=False):
    """An edge owns a sample on it when the sample nudged as the rule says
    is inside (SPEC.md §3): top-left nudges it right by e and down by e^2
    (up on screen for a rasterizer whose y axis points up, `y_up`)."""
    nx, ny = NUDGE[rule]
    if y_up:
        ny = -ny
    a, b, c = pts
    sign = 1 if twice_area(a, b, c) > 0 else -1
    for p, q in ((a, b), (b, c), (c, a)):
        # Edge function, positive inside.
        dx, dy = -(q[1] - p[1]) * sign, (q[0] - p[0]) * sign
        e = dx * (sx - p[0]) + dy * (sy - p[1])
        if e < 0 or (e == 0 and not (nx * dx > 0 or (dx == 0 and ny * dy > 0))):
            return False
    return True


def answer(req):
    width, height = req["canvas"]["width"], req["canvas"]["height"]
    bits = req["rules"]["subpixel_bits"]
    cull = req["rules"]["cull"]
    tris = []
    for prim in req["primitives"]:
        if "triangle" not in prim:
            return {"unsupported": "triangles only"}
        pts = vertices(prim["triangle"], bits)
        tris.append(None if culled(pts, cull) else pts)
    if "antialias" in req["plan"]:
        parts = [coverage(t, width, height) if t else {} for t in tris]
        if "--swap" in FLAGS and len(parts) >= 2:
            for px in parts[0]:
                k0, k1 = parts[0][px], parts[1].get(px, 0)
                if 8 <= k0 < STEP and 0 < k1 <= STEP - 8:
                    parts[0][px], parts[1][px] = k0 - 8, k1 + 8
        return {"primitives": [{"coverage": [[x, y, k / STEP] for (x, y), k in sorted(p.items())]}
                               for p in parts]}
    out = []
    for t in tris:
        frags = []
        if t:
            xs, ys = box(t, width, height)
            for y in ys:
                for x in xs:
                    if covers(t, Fraction(2 * x + 1, 2), Fraction(2 * y + 1, 2), RULE or "top-left"):
                        frags.append([x, y])
        out.append({"fragments": frags})
    return {"primitives": out}


def main():
    caps = {"primitives": ["triangles"], "antialias": True}
    hello = {"protocol": 2, "name": "area8", "version": "1", "capabilities": caps}
    if DECLARED:
        hello["conventions"] = {"fill_rule": DECLARED}
    else:
        caps["fill_rules"] = ["top-left"]
    if "--no-coverage-only" not in FLAGS:
        caps["coverage_only"] = True
    if "--no-bits" not in FLAGS:
        caps["coverage_bits"] = 8
    serve(hello, answer)


def serve(hello, answer):
    """Protocol v2 (SPEC.md §12.7): the hello, then answer(request) for each
    request line, its id echoed, until "bye". The other clients here serve
    through it too."""
    print(json.dumps({"hello": hello}), flush=True)
    for line in sys.stdin:
        if not line.strip():
            continue
        req = json.loads(line)
        if req.get("bye"):
            break
        reply = answer(req)
        if "id" in req:  # a request sent before the hello was read has none
            reply["id"] = req["id"]
        print(json.dumps(reply), flush=True)


if __name__ == "__main__":
    main()
