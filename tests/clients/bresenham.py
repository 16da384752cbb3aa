#!/usr/bin/env python3
"""A line rasterizer that draws `diamond-exit` lines as a GPU's Bresenham
lines may (SPEC.md §4.2.1), speaking protocol v2, for
tests/hello_latitude.rs.

Each line lights one fragment in every column of an x-major line (row of a
y-major one) whose centre lies between its (snapped) ends, half-open at
the second unless `last_pixel` is `include`: the pixel nearest the segment
there. That is not the exact diamond-exit set, but it keeps to the
latitude the APIs allow (each fragment within one unit of the exact
rule's, the count within one).

  --latitude       declare it: `"conventions": {"diamond_exit": "latitude"}`
  --shift N        move every fragment N rows down (N = 2 is outside the
                   latitude: caught whether declared or not)

Lines only, single-sample, coverage only; exact (fractions).
"""

import os
import sys
from fractions import Fraction
from math import ceil, floor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from area8 import serve  # noqa: E402  (beside this file: the protocol loop)

ARGS = sys.argv[1:]
SHIFT = int(ARGS[ARGS.index("--shift") + 1]) if "--shift" in ARGS else 0


def snapped(v, bits):
    x = Fraction(v["exact"]["x"]), Fraction(v["exact"]["y"])
    if bits is None:
        return x
    scale = 2 ** bits
    return tuple(Fraction(round(c * scale), scale) for c in x)


def bresenham(a, b, last):
    """The pixels of a line from a to b (snapped, exact), as a GPU's
    Bresenham lines draw them: along the major axis, every column (row)
    whose centre lies in [a, b) (half-open: the end's is the next line's),
    with the pixel nearest the segment there (the one holding it); the
    end's column too when `last`."""
    (x0, y0), (x1, y1) = a, b
    major = 0 if abs(x1 - x0) >= abs(y1 - y0) else 1
    u0, u1 = (a[major], b[major])
    v0, v1 = (a[1 - major], b[1 - major])
    half = Fraction(1, 2)
    if u1 > u0:
        first, stop, step = ceil(u0 - half), ceil(u1 - half), 1
        if last:
            stop += 1
    else:
        first, stop, step = floor(u0 - half), floor(u1 - half), -1
        if last:
            stop -= 1
    out = []
    for c in range(first, stop, step):
        v = v0 + (c + half - u0) * (v1 - v0) / (u1 - u0)
        # The nearest pixel: the one holding v (its centre within 1/2).
        k = floor(v)
        out.append((c, k) if major == 0 else (k, c))
    return out


def answer(req):
    width, height = req["canvas"]["width"], req["canvas"]["height"]
    bits = req["rules"]["subpixel_bits"]
    if "antialias" in req["plan"]:
        return {"unsupported": "single-sample lines only"}
    out = []
    for prim in req["primitives"]:
        line = prim.get("line")
        if line is None or prim.get("rule") != "diamond-exit":
            return {"unsupported": "diamond-exit lines only"}
        a, b = (snapped(v, bits) for v in line)
        if a == b:
            out.append({"fragments": []})
            continue
        last = prim.get("last_pixel") == "include"
        frags = []
        for x, y in bresenham(a, b, last):
            y += SHIFT
            if 0 <= x < width and 0 <= y < height:
                frags.append([x, y])
        out.append({"fragments": frags})
    return {"primitives": out}


def main():
    caps = {"primitives": ["lines"], "line_rules": ["diamond-exit"],
            "antialias": False, "coverage_only": True}
    hello = {"protocol": 2, "name": "bresenham", "version": "1", "capabilities": caps}
    if "--latitude" in ARGS:
        hello["conventions"] = {"diamond_exit": "latitude"}
    serve(hello, answer)


if __name__ == "__main__":
    main()
