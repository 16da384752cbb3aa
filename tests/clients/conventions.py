#!/usr/bin/env python3
"""An exact point-sampling (and exact-area) rasterizer whose conventions are
not SPEC's, speaking protocol v2, for tests/declared_conventions.rs.

It reads every request in its own terms and declares them in its hello's
`conventions` (SPEC.md §2.1, §3.2, §14.2.1) and `coverage_encoding`
(§12.9):

  --centre integer   its pixel (x, y) has its sample at (x, y), and its
                     antialiased pixel is the square [x - 1/2, x + 1/2] x
                     [y - 1/2, y + 1/2]
  --y up             its y axis points up: it reads the case's fill rule
                     and cull in y-up terms (a "top" edge is one with the
                     triangle below it in y-up terms, above it on screen)
  --snap S           it snaps vertices its own way whatever the case
                     states: "none" (exact), "truncate" (floor to whole
                     pixels) or a number of bits
  --encoding fraction  its coverage is round(area * 256) / 256 capped at
                     255/256 (else round(area * 255) / 255)
  --undeclared       declare none of the above (it still does them): caught
  --undeclared-encoding  do not declare the coverage encoding
  --lie-centre       declare the integer centre but sample at the centre

Triangles only; exact throughout (fractions).
"""

import json
import sys
from fractions import Fraction
from math import floor

ARGS = sys.argv[1:]
FLAGS = set(ARGS)


def option(name):
    return ARGS[ARGS.index(name) + 1] if name in ARGS else None


CENTRE = option("--centre") or "half"
Y = option("--y") or "down"
SNAP = option("--snap")
ENCODING = option("--encoding") or "unorm"
# The nudge of SPEC.md §3 in y-down numbers: a sample on an edge is inside
# when the sample moved by (sx e, sy e^2) is.
NUDGE = {"top-left": (1, 1), "bottom-right": (-1, -1), "top-right": (-1, 1), "bottom-left": (1, -1)}


def snap(v, bits):
    if SNAP == "none":
        return v
    if SNAP == "truncate":
        return Fraction(floor(v))
    if SNAP is not None:
        bits = int(SNAP)
    if bits is None:
        return v
    scale = 2 ** bits
    return Fraction(round(v * scale), scale)  # half-even


def twice_area(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def culled(pts, cull):
    area = twice_area(*pts)
    if Y == "up":  # clockwise read with y up is counter-clockwise on screen
        area = -area
    return area == 0 or (cull == "cw" and area > 0) or (cull == "ccw" and area < 0)


def covers(pts, sx, sy, rule):
    nx, ny = NUDGE[rule]
    if Y == "up":  # "down" in its terms is up on screen
        ny = -ny
    a, b, c = pts
    sign = 1 if twice_area(a, b, c) > 0 else -1
    for p, q in ((a, b), (b, c), (c, a)):
        dx, dy = -(q[1] - p[1]) * sign, (q[0] - p[0]) * sign
        e = dx * (sx - p[0]) + dy * (sy - p[1])
        if e < 0 or (e == 0 and not (nx * dx > 0 or (dx == 0 and ny * dy > 0))):
            return False
    return True


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


def square_area(pts, x0, y0):
    poly = list(pts)
    for axis, bound, keep_above in ((0, x0, True), (0, x0 + 1, False), (1, y0, True), (1, y0 + 1, False)):
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
    x0, x1 = max(0, floor(min(xs)) - 1), min(width, floor(max(xs)) + 2)
    y0, y1 = max(0, floor(min(ys)) - 1), min(height, floor(max(ys)) + 2)
    return range(x0, x1), range(y0, y1)


def encode(area):
    if ENCODING == "fraction":
        return min(round(area * 256), 255) / 256
    return round(area * 255) / 255


def answer(req):
    width, height = req["canvas"]["width"], req["canvas"]["height"]
    bits = req["rules"]["subpixel_bits"]
    cull = req["rules"]["cull"]
    rule = req["rules"]["fill_rule"]
    tris = []
    for prim in req["primitives"]:
        if "triangle" not in prim:
            return {"unsupported": "triangles only"}
        pts = [(snap(Fraction(v["exact"]["x"]), bits), snap(Fraction(v["exact"]["y"]), bits))
               for v in prim["triangle"]]
        tris.append(None if culled(pts, cull) else pts)
    c = Fraction(0) if CENTRE == "integer" and "--lie-centre" not in FLAGS else Fraction(1, 2)
    if "antialias" in req["plan"]:
        out = []
        for t in tris:
            cov = []
            if t:
                xs, ys = box(t, width, height)
                for y in ys:
                    for x in xs:
                        a = square_area(t, x + c - Fraction(1, 2), y + c - Fraction(1, 2))
                        if a:
                            cov.append([x, y, encode(a)])
            out.append({"coverage": cov})
        return {"primitives": out}
    out = []
    for t in tris:
        frags = []
        if t:
            xs, ys = box(t, width, height)
            for y in ys:
                for x in xs:
                    if covers(t, x + c, y + c, rule):
                        frags.append([x, y])
        out.append({"fragments": frags})
    return {"primitives": out}


def main():
    caps = {"primitives": ["triangles"], "antialias": True, "coverage_only": True,
            "coverage_bits": 8, "fill_rules": ["top-left", "bottom-right", "top-right", "bottom-left"]}
    conventions = {}
    if CENTRE != "half":
        conventions["pixel_centre"] = CENTRE
    if Y != "down":
        conventions["y"] = Y
    if SNAP is not None:
        conventions["snapping"] = int(SNAP) if SNAP.isdigit() else SNAP
    if ENCODING != "unorm" and "--undeclared-encoding" not in FLAGS:
        caps["coverage_encoding"] = ENCODING
    hello = {"protocol": 2, "name": "conventions", "version": "1", "capabilities": caps}
    if "--undeclared" not in FLAGS:
        hello["conventions"] = conventions
    print(json.dumps({"hello": hello}), flush=True)
    for line in sys.stdin:
        if not line.strip():
            continue
        req = json.loads(line)
        if req.get("bye"):
            break
        reply = answer(req)
        if "id" in req:
            reply["id"] = req["id"]
        print(json.dumps(reply), flush=True)


if __name__ == "__main__":
    main()
