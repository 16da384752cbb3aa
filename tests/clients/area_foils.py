#!/usr/bin/env python3
"""Two wrong area-coverage answers speaking protocol v2 coverage only
(SPEC.md §12.9), for tests/area_answers.rs. Neither declares coverage_bits,
so each primitive is held to its exact area within the default step, 2^-8
(SPEC.md §14.4).

  --empty      answers {"coverage": []} for every antialiased primitive:
               it draws nothing
  --constant V answers V for every pixel a primitive touches (its exact
               area there is not 0), whatever that area is

Without antialiasing it draws as tests/clients/area8.py does (exact point
sampling), so only its antialiased answers are wrong.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import area8  # noqa: E402

ARGS = sys.argv[1:]
CONSTANT = float(ARGS[ARGS.index("--constant") + 1]) if "--constant" in ARGS else None


def answer(req):
    if "antialias" not in req["plan"]:
        return area8.answer(req)
    width, height = req["canvas"]["width"], req["canvas"]["height"]
    bits = req["rules"]["subpixel_bits"]
    cull = req["rules"]["cull"]
    out = []
    for prim in req["primitives"]:
        if "triangle" in prim:
            pts = area8.vertices(prim["triangle"], bits)
            contours = [] if area8.culled(pts, cull) else [pts]
        elif "contours" in prim:
            contours = [area8.vertices(c, bits) for c in prim["contours"]]
        else:
            return {"unsupported": "triangles and polygons only"}
        touched = []
        if CONSTANT is not None and contours:
            xs, ys = area8.box([p for c in contours for p in c], width, height)
            touched = [(x, y) for y in ys for x in xs
                       if any(area8.pixel_area(c, x, y) > 0 for c in contours)]
        out.append({"coverage": [[x, y, CONSTANT] for (x, y) in touched]})
    return {"primitives": out}


def main():
    caps = {"primitives": ["triangles", "polygons"], "antialias": True,
            "fill_rules": ["top-left"], "polygon_fills": ["nonzero", "even-odd"],
            "coverage_only": True}
    hello = {"protocol": 2, "name": "area_foils", "version": "1", "capabilities": caps}
    area8.serve(hello, answer)


if __name__ == "__main__":
    main()
