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

import os
import sys
from fractions import Fraction
from math import floor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import area8  # noqa: E402  (beside this file: exact areas, boxes, ties, the loop)

ARGS = sys.argv[1:]
FLAGS = set(ARGS)


def option(name):
    return ARGS[ARGS.index(name) + 1] if name in ARGS else None


CENTRE = option("--centre") or "half"
Y = option("--y") or "down"
SNAP = option("--snap")
ENCODING = option("--encoding") or "unorm"


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


def culled(pts, cull):
    area = area8.twice_area(*pts)
    if Y == "up":  # clockwise read with y up is counter-clockwise on screen
        area = -area
    return area == 0 or (cull == "cw" and area > 0) or (cull == "ccw" and area < 0)


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
                xs, ys = area8.box(t, width, height)
                for y in ys:
                    for x in xs:
                        a = area8.pixel_area(t, x + c - Fraction(1, 2), y + c - Fraction(1, 2))
                        if a:
                            cov.append([x, y, encode(a)])
            out.append({"coverage": cov})
        return {"primitives": out}
    out = []
    for t in tris:
        frags = []
        if t:
            xs, ys = area8.box(t, width, height)
            for y in ys:
                for x in xs:
                    if area8.covers(t, x + c, y + c, rule, y_up=Y == "up"):
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
    area8.serve(hello, answer)


if __name__ == "__main__":
    main()
