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
- `parallelogram` lines: the quad of SPEC.md §4.4 as two triangles, with
  the same float `>= 0` test (its ends and sides are all inclusive);
- antialiasing: supersampling at the sample offsets the request gives, with
  the same inside tests, one fragment per covered sample;
- motion blur (protocol v2 only, SPEC.md §12.8): each moving triangle or
  parallelogram line tested at the instants the request lists, its
  vertices placed in floats at each instant, one fragment [x, y, j] per
  covered test; static primitives once, [x, y, sample].

Anything else (other line rules, midpoint lines in antialiased or moving
scenes) is answered with {"unsupported": "..."}, which rastercheck reports
as such.
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


def inside_triangle(points, cull, px, py):
    """The float inside test at one sample: every edge function `>= 0` once
    the winding is made positive, so a sample on any edge is inside."""
    (x0, y0), (x1, y1), (x2, y2) = points
    area = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)
    if area == 0 or (cull == "cw" and area > 0) or (cull == "ccw" and area < 0):
        return False
    w0 = ((x2 - x1) * (py - y1) - (y2 - y1) * (px - x1)) / area
    w1 = ((x0 - x2) * (py - y2) - (y0 - y2) * (px - x2)) / area
    w2 = ((x1 - x0) * (py - y0) - (y1 - y0) * (px - x0)) / area
    return w0 >= 0 and w1 >= 0 and w2 >= 0


def parallelogram_corners(a, b, half):
    """SPEC.md §4.4's quad: the segment swept half the width both ways along
    its minor axis (y for an x-major line); None for a zero-length line."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    if dx == 0 and dy == 0:
        return None
    ox, oy = (0, half) if abs(dx) >= abs(dy) else (half, 0)
    return [(a[0] - ox, a[1] - oy), (b[0] - ox, b[1] - oy),
            (b[0] + ox, b[1] + oy), (a[0] + ox, a[1] + oy)]


def inside_parallelogram(corners, px, py):
    """The quad as two triangles sharing a diagonal, each tested as above."""
    if corners is None:
        return False
    a, b, c, e = corners
    return inside_triangle((a, b, c), "none", px, py) or inside_triangle((a, c, e), "none", px, py)


def parallelogram(prim, request):
    """A static `parallelogram` line; values along its major axis."""
    rules, plan = request["rules"], request["plan"]
    width, height = request["canvas"]["width"], request["canvas"]["height"]
    bits = rules["subpixel_bits"]
    a, b = [(snap(v["x"], bits), snap(v["y"], bits)) for v in prim["line"]]
    corners = parallelogram_corners(a, b, prim["width"] / 2)
    if corners is None:
        return []
    major = 0 if abs(b[0] - a[0]) >= abs(b[1] - a[1]) else 1
    left, top, right, bottom = box(corners, width, height)
    fragments = []
    for y in range(top, bottom):
        for x in range(left, right):
            for slot, dx, dy in sample_points(plan):
                px, py = x + dx, y + dy
                if inside_parallelogram(corners, px, py):
                    t = min(1.0, max(0.0, ((px, py)[major] - a[major]) / (b[major] - a[major])))
                    values = interpolate((1 - t, t), prim["line"], prim["interpolation"], plan)
                    fragments.append(fragment(x, y, slot, values))
    return fragments


def box(points, width, height):
    """The pixels (left, top, right, bottom; right and bottom excluded) of the
    points' bounding box that lie on the canvas."""
    left = max(0, math.floor(min(p[0] for p in points)))
    top = max(0, math.floor(min(p[1] for p in points)))
    right = min(width, math.floor(max(p[0] for p in points)) + 1)
    bottom = min(height, math.floor(max(p[1] for p in points)) + 1)
    return left, top, right, bottom


def moving(request):
    """A moving scene (SPEC.md §12.8), answered with time-sample masks: a
    moving primitive's fragment [x, y, j] says it covers spatial sample
    j // N of pixel (x, y) at the instant of slot j of that pixel's times;
    a static primitive's [x, y, s], sample s at every instant."""
    rules, plan = request["rules"], request["plan"]
    motion = plan["motion"]
    width, height = request["canvas"]["width"], request["canvas"]["height"]
    bits, cull = rules["subpixel_bits"], rules["cull"]
    n, times = motion["samples"], motion["times"]
    shutter_open, shutter_close = motion["shutter"]
    samples = [(slot or 0, dx, dy) for slot, dx, dy in sample_points(plan)]
    out = []
    for prim in request["primitives"]:
        # Each vertex snapped at its two ends, then placed in floats at τ.
        ends = []
        for v in prim.get("triangle") or prim.get("line") or []:
            to = v.get("to", v)
            ends.append(((snap(v["x"], bits), snap(v["y"], bits)),
                         (snap(to["x"], bits), snap(to["y"], bits))))
        if "triangle" in prim:
            def covers(points, px, py):
                return inside_triangle(points, cull, px, py)
        elif "line" in prim and prim["rule"] == "parallelogram":
            half = prim["width"] / 2

            def covers(points, px, py, half=half):
                return inside_parallelogram(parallelogram_corners(points[0], points[1], half), px, py)
        elif "line" in prim:
            return {"unsupported": "%s lines are not drawn in moving scenes here" % prim["rule"]}
        else:
            return {"unsupported": "polygons are not drawn in moving scenes here"}
        reach = prim["width"] / 2 if "line" in prim else 0
        swept = [(p[0] + sx * reach, p[1] + sy * reach)
                 for a, b in ends for p in (a, b) for sx in (-1, 1) for sy in (-1, 1)]
        left, top, right, bottom = box(swept, width, height)
        fragments = []
        for y in range(top, bottom):
            for x in range(left, right):
                if not prim["moves"]:
                    at_open = [a for a, _ in ends]
                    fragments.extend([x, y, s] for s, dx, dy in samples if covers(at_open, x + dx, y + dy))
                    continue
                pixel_times = times[y * width + x]
                for s, dx, dy in samples:
                    for k in range(n):
                        j = s * n + k
                        tau = shutter_open + (shutter_close - shutter_open) * pixel_times[j] / 65536
                        points = [((1 - tau) * a[0] + tau * b[0], (1 - tau) * a[1] + tau * b[1])
                                  for a, b in ends]
                        if covers(points, x + dx, y + dy):
                            fragments.append([x, y, j])
        out.append({"fragments": fragments})
    return {"primitives": out}


def rasterize(request):
    """One request in, one response out (both as Python dicts)."""
    if "motion" in request["plan"]:
        return moving(request)
    antialiased = "antialias" in request["plan"]
    out = []
    for prim in request["primitives"]:
        if "triangle" in prim:
            out.append({"fragments": triangle(prim, request)})
        elif "contours" in prim:
            out.append({"fragments": polygon(prim, request)})
        elif prim["rule"] == "parallelogram":
            out.append({"fragments": parallelogram(prim, request)})
        elif antialiased:
            return {"unsupported": "%s lines are not antialiased here" % prim["rule"]}
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
        "version": "3",
        "capabilities": {
            "primitives": ["triangles", "lines", "polygons"],
            "line_rules": ["midpoint", "parallelogram"],
            "interpolation": ["flat", "linear", "perspective"],
            "antialias": True,
            "depth": True,
            "attributes": True,
            "motion": True,
        },
        # Descriptions only: a `fill_rule` here would be judged (SPEC.md
        # §3.1), and this example is meant to be caught on its ties.
        "conventions": {
            "ties": "inclusive: a centre on any edge is inside",
            "polygon_fill": "even-odd",
            "line_walk": "float DDA",
        },
    }
}


def serve(hello, answer):
    """Persistent mode: `hello` first (None: version 1, no hello), then one
    line of `answer(request)` per request line until bye, echoing each
    request's id (version 2)."""
    if hello is not None:
        print(json.dumps(hello), flush=True)
    for text in sys.stdin:
        request = json.loads(text)
        if request.get("bye"):
            break
        response = answer(request)
        if hello is not None and "id" in request:
            response["id"] = request["id"]
        print(json.dumps(response), flush=True)


def main():
    args = sys.argv[1:]
    if "--persistent" in args:
        # JSON Lines: one request per line, one response per line, until bye.
        # v2 (the default): a hello first, and every answer echoes the
        # request's id; --v1 speaks version 1 (no hello, no ids).
        serve(None if "--v1" in args else HELLO, rasterize)
    else:
        print(json.dumps(rasterize(json.load(sys.stdin))))


if __name__ == "__main__":
    main()
