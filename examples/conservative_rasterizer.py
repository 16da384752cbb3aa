#!/usr/bin/env python3
"""An exact conservative rasterizer speaking protocol v2 (SPEC.md §12.7,
§12.11), in plain Python: triangles only, each drawn by overestimation or
underestimation as the request's `rules.conservative` asks, in exact
rational arithmetic (Python's integers and fractions; no float decides a
pixel).

Overestimation: pixel (x, y) is drawn when its closed square
[x, x + 1] x [y, y + 1] meets the snapped triangle. The test is the
separating-axis one: the square and the triangle meet unless their
projections on one of five axes are apart, the two pixel axes (the
triangle's bounding box against the square) and each edge's normal (the
edge function offset by the square's half extent along the normal,
(|a| + |b|)/2: the classic offset edge function). A degenerate triangle
(zero area after snapping) is drawn as the segment or point it is when the
case's `degenerate_triangles` is true (its edges' normals are the
segment's, and the same test draws every pixel the segment touches), and
culled otherwise. Its `grow` is 0: it draws no pixel the triangle does not touch,
the least a conservative rasterizer may draw, so it passes at any declared
uncertainty.

Underestimation: pixel (x, y) is drawn when its closed square lies inside
the closed triangle (its four corners do): the most it may draw.

The fully-covered flag (`rules.conservative.fully_covered`): a fragment
[x, y, f] with f = 1 when the square lies inside the triangle, else 0.

Multisampled (SPEC.md §19.10): a drawn pixel covers all its samples, one
fragment [x, y, s] (or [x, y, s, f]) for each.

Flags:
  --uncertainty U   declare U (an exact number, "1/256") as its
                    overestimation uncertainty (default "0")
  --grow G          grow each triangle by G px before testing (the
                    square tested is [x - G, x + 1 + G]); with G above the
                    declared uncertainty, it draws pixels it must not
  --too-much        grow by the declared uncertainty plus one 2^-8 step:
                    caught (a forbidden pixel drawn)
  --open            test the open square: a triangle that only touches a
                    pixel at a side or corner does not draw it: caught (a
                    required pixel missing)
  --flag-partial    report fully covered wherever it draws: caught
  --always U        draw every triangle conservatively (overestimation,
                    growing by U), whatever the case asks, and declare
                    nothing of it (for `probe`, which measures U)
"""

import json
import sys
from fractions import Fraction

ARGS = sys.argv[1:]
FLAGS = set(ARGS)


def option(name):
    return ARGS[ARGS.index(name) + 1] if name in ARGS else None


UNCERTAINTY = Fraction(option("--uncertainty") or "0")
ALWAYS = option("--always")
if ALWAYS is not None:
    GROW = Fraction(ALWAYS)
elif "--too-much" in FLAGS:
    GROW = UNCERTAINTY + Fraction(1, 256)
else:
    GROW = Fraction(option("--grow") or "0")
OPEN = "--open" in FLAGS


def snap(v, bits):
    if bits is None:
        return v
    scale = 2**bits
    return Fraction(round(v * scale), scale)  # round() on a Fraction: half-even


def vertices(tri, bits):
    return [(snap(Fraction(v["exact"]["x"]), bits), snap(Fraction(v["exact"]["y"]), bits)) for v in tri]


def twice_area(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def axes(pts):
    """The separating axes: the pixel axes and each edge's normal (a zero
    edge has none)."""
    out = [(1, 0), (0, 1)]
    for i in range(3):
        (x0, y0), (x1, y1) = pts[i], pts[(i + 1) % 3]
        n = (y0 - y1, x1 - x0)
        if n != (0, 0):
            out.append(n)
    return out


def meets(pts, normals, x, y, grow):
    """Whether the square [x - grow, x + 1 + grow] x [y - grow, y + 1 + grow]
    meets the triangle (closed; open with --open)."""
    cx, cy, half = Fraction(2 * x + 1, 2), Fraction(2 * y + 1, 2), Fraction(1, 2) + grow
    for a, b in normals:
        proj = [a * px + b * py for px, py in pts]
        centre = a * cx + b * cy
        reach = (abs(a) + abs(b)) * half
        if OPEN:
            if min(proj) >= centre + reach or max(proj) <= centre - reach:
                return False
        elif min(proj) > centre + reach or max(proj) < centre - reach:
            return False
    return True


def inside(pts, x, y):
    """Whether the closed square of pixel (x, y) lies inside the closed
    triangle (not degenerate)."""
    area = twice_area(*pts)
    if area == 0:
        return False
    sign = 1 if area > 0 else -1
    for cx, cy in [(x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)]:
        for i in range(3):
            a, b = pts[i], pts[(i + 1) % 3]
            if sign * twice_area(a, b, (cx, cy)) < 0:
                return False
    return True


def culled(pts, cull):
    area = twice_area(*pts)
    return (cull == "cw" and area > 0) or (cull == "ccw" and area < 0)


def draw(pts, width, height, mode, flagged, samples):
    """The fragments of one triangle: [x, y] (or [x, y, f]); multisampled
    (`samples` a count, SPEC.md §19.10), [x, y, s] (or [x, y, s, f]) for
    every sample s of a drawn pixel: its samples are all covered."""
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    reach = GROW + 1
    x0, x1 = max(0, int(min(xs) - reach)), min(width - 1, int(max(xs) + reach))
    y0, y1 = max(0, int(min(ys) - reach)), min(height - 1, int(max(ys) + reach))
    normals = axes(pts)
    out = []
    for y in range(y0, y1 + 1):
        for x in range(x0, x1 + 1):
            full = inside(pts, x, y)
            if mode == "underestimate":
                hit = full
            else:
                hit = meets(pts, normals, x, y, GROW)
            if not hit:
                continue
            flag = [1 if full or "--flag-partial" in FLAGS else 0] if flagged else []
            slots = [[]] if samples is None else [[s] for s in range(samples)]
            out.extend([x, y] + slot + flag for slot in slots)
    return out


def answer(req):
    rules = req["rules"]
    conservative = rules.get("conservative")
    if ALWAYS is not None:
        mode = "overestimate"
    elif conservative is None:
        return {"unsupported": "this example draws conservative cases only"}
    else:
        mode = conservative["mode"]
    flagged = bool(conservative and conservative.get("fully_covered"))
    width, height = req["canvas"]["width"], req["canvas"]["height"]
    aa = req.get("plan", {}).get("antialias")
    samples = None if aa is None else len(aa["offsets"])
    prims = []
    for p in req["primitives"]:
        if "triangle" not in p:
            return {"unsupported": "this example draws triangles only"}
        pts = vertices(p["triangle"], rules["subpixel_bits"])
        degenerate = twice_area(*pts) == 0
        if degenerate and ALWAYS is None and not conservative.get("degenerate_triangles"):
            prims.append({"fragments": []})  # culled, as the case states
            continue
        if culled(pts, rules.get("cull", "none")):
            prims.append({"fragments": []})
            continue
        prims.append({"fragments": draw(pts, width, height, mode, flagged, samples)})
    return {"primitives": prims}


def main():
    hello = {"protocol": 2, "name": "conservative-example", "version": "1"}
    caps = {"primitives": ["triangles"], "coverage_only": True}
    if ALWAYS is None:
        caps["conservative"] = {
            "modes": ["overestimate", "underestimate"],
            "uncertainty": str(UNCERTAINTY),
            "fully_covered": True,
        }
    hello["capabilities"] = caps
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
