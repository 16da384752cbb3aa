#!/usr/bin/env python3
"""A small rasterizer in plain Python, judged by rastercheck.

It speaks the external-process protocol of SPEC.md §12:

    rastercheck run cases -r 'external:python3 examples/python_rasterizer.py'
    rastercheck run cases -r 'external-persistent:python3 examples/python_rasterizer.py --persistent'
    rastercheck run cases -r 'py=external-persistent:python3 examples/python_rasterizer.py --persistent --v1'

In persistent mode it speaks version 2 of the protocol (SPEC.md §12.7): a
hello declaring what it draws, then answers that echo each request's id;
with --v1, version 1 (no hello, no ids).

It is written the way a first course assignment usually is, and it is meant
to be caught:

- triangles: float edge functions with an inside test of `>= 0`, so a pixel
  centre exactly on an edge shared by two triangles is drawn by both
  (overdraw), whatever fill rule the case asks for;
- lines: the textbook float DDA (`y += slope`, row = floor(y)), which picks
  the wrong row at exact ties and can drift on long lines;
- interpolation: barycentric weights in floats, linear or perspective;
- polygons: the classic PNPOLY crossing test, which is even-odd whatever
  fill the case asks for (so nonzero stars lose their centre);
- antialiasing: supersampling at the sample offsets the request gives, with
  the same inside tests, one fragment per covered sample.

Anything else (other line rules, lines in antialiased scenes) is answered
with {"unsupported": "..."}, which rastercheck reports as such.
Standard library only.
"""

import json
import math
import sys


def snap(v, bits):
    """Rounds a coordinate to the subpixel grid (Python's round is ties-to-even)."""
    if bits is None:
        return v
    scale = 2.0 ** bits
    return round(v * scale) / scale


def interpolate(weights, vertices, mode, plan):
    """Depth then attributes at a point with barycentric `weights` (sum 1)."""
    values = []
    if plan["depth"]:
        values.append(sum(b * v["z"] for b, v in zip(weights, vertices)))
    for k in range(plan["attributes"]):
        if mode == "flat":
            values.append(vertices[0]["attributes"][k])
        elif mode == "linear":
            values.append(sum(b * v["attributes"][k] for b, v in zip(weights, vertices)))
        else:  # perspective: interpolate a/w and 1/w linearly, then divide
            num = sum(b * v["attributes"][k] / v["w"] for b, v in zip(weights, vertices))
            den = sum(b / v["w"] for b, v in zip(weights, vertices))
            values.append(num / den)
    return values


def sample_points(plan):
    """(slot, dx, dy): where the samples lie in a pixel, and the slot index a
    fragment names when the scene is antialiased."""
    aa = plan.get("antialias")
    if aa is None:
        return [(None, 0.5, 0.5)]
    return [(s, dx, dy) for s, (dx, dy) in enumerate(aa["offsets"])]


def fragment(x, y, slot, values):
    return [x, y] + ([] if slot is None else [slot]) + values


def triangle(prim, request):
    rules, plan = request["rules"], request["plan"]
    width, height = request["canvas"]["width"], request["canvas"]["height"]
    vs = prim["triangle"]
    (x0, y0), (x1, y1), (x2, y2) = [
        (snap(v["x"], rules["subpixel_bits"]), snap(v["y"], rules["subpixel_bits"])) for v in vs
    ]
    # Twice the signed area; positive means clockwise on screen (y down).
    area = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)
    if area == 0 or (rules["cull"] == "cw" and area > 0) or (rules["cull"] == "ccw" and area < 0):
        return []

    def edge(ax, ay, bx, by, px, py):
        return (bx - ax) * (py - ay) - (by - ay) * (px - ax)

    fragments = []
    # Only the pixels of the bounding box that lie on the canvas.
    left, right = max(0, math.floor(min(x0, x1, x2))), min(width, math.ceil(max(x0, x1, x2)))
    top, bottom = max(0, math.floor(min(y0, y1, y2))), min(height, math.ceil(max(y0, y1, y2)))
    for y in range(top, bottom):
        for x in range(left, right):
            for slot, dx, dy in sample_points(plan):
                px, py = x + dx, y + dy
                # Each weight is the edge function opposite a vertex, over the area.
                w0 = edge(x1, y1, x2, y2, px, py) / area
                w1 = edge(x2, y2, x0, y0, px, py) / area
                w2 = edge(x0, y0, x1, y1, px, py) / area
                if w0 >= 0 and w1 >= 0 and w2 >= 0:  # on an edge counts as inside
                    values = interpolate((w0, w1, w2), vs, prim["interpolation"], plan)
                    fragments.append(fragment(x, y, slot, values))
    return fragments


def polygon(prim, request):
    """PNPOLY: a point is inside when a ray to +x crosses an odd number of edges."""
    bits = request["rules"]["subpixel_bits"]
    width, height = request["canvas"]["width"], request["canvas"]["height"]
    contours = [[(snap(v["x"], bits), snap(v["y"], bits)) for v in c] for c in prim["contours"]]
    points = [p for c in contours for p in c]
    left, right = max(0, math.floor(min(p[0] for p in points))), min(width, math.ceil(max(p[0] for p in points)))
    top, bottom = max(0, math.floor(min(p[1] for p in points))), min(height, math.ceil(max(p[1] for p in points)))
    fragments = []
    for y in range(top, bottom):
        for x in range(left, right):
            for slot, dx, dy in sample_points(request["plan"]):
                px, py = x + dx, y + dy
                inside = False
                for c in contours:
                    for (xi, yi), (xj, yj) in zip(c, c[1:] + c[:1]):
                        if (yi > py) != (yj > py) and px < (xj - xi) * (py - yi) / (yj - yi) + xi:
                            inside = not inside
                if inside:
                    fragments.append(fragment(x, y, slot, []))
    return fragments


def line(prim, request):
    rules, plan = request["rules"], request["plan"]
    width, height = request["canvas"]["width"], request["canvas"]["height"]
    a, b = prim["line"]
    x0, y0, x1, y1 = [snap(a["x"], rules["subpixel_bits"]), snap(a["y"], rules["subpixel_bits"]),
                      snap(b["x"], rules["subpixel_bits"]), snap(b["y"], rules["subpixel_bits"])]
    dx, dy = x1 - x0, y1 - y0
    if dx == 0 and dy == 0:
        return []
    steep = abs(dy) > abs(dx)
    if steep:  # walk rows instead of columns: swap the axes, and back at the end
        x0, y0, x1, y1, dx, dy = y0, x0, y1, x1, dy, dx
    step = 1 if dx > 0 else -1
    slope = dy / dx
    # Pixel centres c = i + 0.5 between x0 and x1 (the last one only if included).
    first = math.ceil(x0 - 0.5) if step > 0 else math.floor(x0 - 0.5)
    fragments = []
    c = first + 0.5
    y = y0 + (c - x0) * slope
    while (c <= x1 if step > 0 else c >= x1):
        if c == x1 and prim["last_pixel"] == "exclude":
            break
        column, row = first, math.floor(y)  # the naive DDA's row choice
        px, py = (row, column) if steep else (column, row)
        if 0 <= px < width and 0 <= py < height:
            if prim["parameter"] == "major":
                t = (c - x0) / dx
            else:  # projection of the pixel centre onto the segment
                t = ((c - x0) * dx + (row + 0.5 - y0) * dy) / (dx * dx + dy * dy)
            t = min(1.0, max(0.0, t))
            fragments.append([px, py] + interpolate((1 - t, t), prim["line"], prim["interpolation"], plan))
        first += step
        c += step
        y += slope * step  # accumulates float error, as the textbook DDA does
    return fragments


def rasterize(request):
    """One request in, one response out (both as Python dicts)."""
    antialiased = "antialias" in request["plan"]
    out = []
    for prim in request["primitives"]:
        if "triangle" in prim:
            out.append({"fragments": triangle(prim, request)})
        elif "contours" in prim:
            out.append({"fragments": polygon(prim, request)})
        elif antialiased:
            return {"unsupported": "lines are not antialiased here"}
        elif prim["rule"] == "midpoint":
            out.append({"fragments": line(prim, request)})
        else:
            return {"unsupported": "%s lines are not implemented" % prim["rule"]}
    return {"primitives": out}


# What this program declares in its hello (protocol v2, SPEC.md §12.7): what
# it draws, and the conventions it follows. Cases outside the capabilities
# are never sent to it; they are reported unsupported, with this as reason.
# The fill rule is not declared: the program ignores the case's rule, and a
# case whose rule it breaks is a finding, not something to refuse.
HELLO = {
    "hello": {
        "protocol": 2,
        "name": "python-example",
        "version": "2",
        "capabilities": {
            "primitives": ["triangles", "lines", "polygons"],
            "line_rules": ["midpoint"],
            "interpolation": ["flat", "linear", "perspective"],
            "antialias": True,
            "depth": True,
            "attributes": True,
            "motion": False,
        },
        "conventions": {
            "fill_rule": "inclusive: a centre on any edge is inside",
            "polygon_fill": "even-odd",
            "line_walk": "float DDA",
        },
    }
}


def main():
    args = sys.argv[1:]
    if "--persistent" in args:
        # JSON Lines: one request per line, one response per line, until bye.
        # v2 (the default): a hello first, and every answer echoes the
        # request's id; --v1 speaks version 1 (no hello, no ids).
        v2 = "--v1" not in args
        if v2:
            print(json.dumps(HELLO), flush=True)
        for text in sys.stdin:
            request = json.loads(text)
            if request.get("bye"):
                break
            response = rasterize(request)
            if v2 and "id" in request:
                response["id"] = request["id"]
            print(json.dumps(response), flush=True)
    else:
        print(json.dumps(rasterize(json.load(sys.stdin))))


if __name__ == "__main__":
    main()
