#!/usr/bin/env python3
"""An exact conservative rasterizer speaking protocol v2 (SPEC.md §12.7,
§12.11), in plain Python: triangles, points and `rectangle` and
`parallelogram` lines (SPEC.md §19.8), each drawn by overestimation or
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

Points and lines (SPEC.md §19.8) are their closed shapes: a point's
square and a parallelogram line's quad are convex polygons, tested as a
triangle is; a rectangle line's corners are irrational, so its tests
compare squares (the reach h·|d| of its half width h along its normal,
h·|d_y|/|d| past its ends on x). A line of zero length after snapping is
culled, or drawn as its point when the case's `degenerate_lines` is true.

The fully-covered flag (`rules.conservative.fully_covered`): a fragment
[x, y, f] with f = 1 when the square lies inside the triangle, else 0.

Multisampled (SPEC.md §19.10): a drawn pixel covers all its samples, one
fragment [x, y, s] (or [x, y, s, f]) for each.

Depth (SPEC.md §19.9; declared as `conservative.depth`, SPEC.md §12.11):
a triangle's plane through its snapped vertices at the pixel centre,
extrapolated where the centre is outside the triangle (Vulkan's and
D3D12's "extrapolated" value, always in the interval §19.9 allows), plus
the polygon offset (SPEC.md §18.2, m = max(|dz/dx|, |dz/dy|) and r the
least the format allows), clamped to [0, 1] and stored in the case's
format (a unorm integer rounded to nearest); a degenerate triangle drawn
writes its provoking vertex's z. All in fractions: a fragment
[x, y, depth] (or [x, y, depth, f]).

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
  --depth-unclamped store the depth without the format's clamp to [0, 1]:
                    caught (a float32 depth below 0 outside the allowed
                    depths; a unorm integer past its range an error)
  --depth-first-vertex
                    write the first vertex's z at every pixel (a far
                    vertex's depth, not the plane's there): caught
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
    for i in range(len(pts)):
        (x0, y0), (x1, y1) = pts[i], pts[(i + 1) % len(pts)]
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


def polygon_area(pts):
    return sum(twice_area(pts[0], pts[i], pts[i + 1]) for i in range(1, len(pts) - 1))


def inside(pts, x, y):
    """Whether the closed square of pixel (x, y) lies inside the closed
    convex polygon (a triangle, a point's square, a parallelogram)."""
    area = polygon_area(pts) if len(pts) >= 3 else 0
    if area == 0:
        return False
    sign = 1 if area > 0 else -1
    for cx, cy in [(x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)]:
        for i in range(len(pts)):
            a, b = pts[i], pts[(i + 1) % len(pts)]
            if sign * twice_area(a, b, (cx, cy)) < 0:
                return False
    return True


def exponent(z):
    """The e with 2^e <= |z| < 2^(e+1), at least -126 (SPEC.md §18.2)."""
    z = abs(z)
    if z == 0:
        return -126
    e = z.numerator.bit_length() - z.denominator.bit_length()
    if Fraction(2) ** e > z:
        e -= 1
    return max(e, -126)


class Depth:
    """The depth a triangle writes at pixel (x, y) (SPEC.md §19.9): the
    plane at the centre plus the offset, or the provoking vertex's z of a
    degenerate one, then the format's clamp and storage."""

    def __init__(self, pts, zs, rules):
        self.format = rules.get("depth_format", "exact")
        first = 0 if rules.get("provoking_vertex", "first") == "first" else 2
        area = twice_area(*pts)
        if "--depth-first-vertex" in FLAGS:
            area = 0
            first = 0
        self.flat = zs[first] if area == 0 else None
        if self.flat is not None:
            return
        (x0, y0), (x1, y1), (x2, y2) = pts
        dx1, dy1, dz1 = x1 - x0, y1 - y0, zs[1] - zs[0]
        dx2, dy2, dz2 = x2 - x0, y2 - y0, zs[2] - zs[0]
        self.a = (dz1 * dy2 - dz2 * dy1) / area  # dz/dx
        self.b = (dx1 * dz2 - dx2 * dz1) / area  # dz/dy
        self.origin = (x0, y0, zs[0])
        self.offset = Fraction(0)
        bias = rules.get("depth_bias")
        if bias is not None:
            exact = bias["exact"]
            s, c, k = (Fraction(exact.get(key, "0")) for key in ("slope", "constant", "clamp"))
            m = max(abs(self.a), abs(self.b))
            if self.format in ("unorm16", "unorm24"):
                r = Fraction(1, 2 ** int(self.format[5:]))
            else:
                r = Fraction(2) ** (exponent(max(abs(z) for z in zs)) - 23)
            o = m * s + r * c
            self.offset = min(o, k) if k > 0 else max(o, k) if k < 0 else o

    def at(self, x, y):
        if self.flat is not None:
            z = self.flat
        else:
            x0, y0, z0 = self.origin
            cx, cy = Fraction(2 * x + 1, 2), Fraction(2 * y + 1, 2)
            z = z0 + self.a * (cx - x0) + self.b * (cy - y0) + self.offset
        if self.format == "exact":
            return float(z)
        if "--depth-unclamped" not in FLAGS:
            z = min(max(z, Fraction(0)), Fraction(1))
        if self.format in ("unorm16", "unorm24"):
            top = 2 ** int(self.format[5:]) - 1
            return int((z * top + Fraction(1, 2)) // 1)
        return float(z)


def culled(pts, cull):
    area = twice_area(*pts)
    return (cull == "cw" and area > 0) or (cull == "ccw" and area < 0)


class Rectangle:
    """A rectangle line from a to b (a != b), half width h: the points p
    with 0 <= (p - a).d <= |d|^2 and |(p - a) x d| <= h |d|."""

    def __init__(self, a, b, h):
        self.a, self.b, self.h = a, b, h
        self.d = (b[0] - a[0], b[1] - a[1])
        self.l2 = self.d[0] ** 2 + self.d[1] ** 2

    def box(self):
        xs, ys = [self.a[0], self.b[0]], [self.a[1], self.b[1]]
        return min(xs) - self.h, min(ys) - self.h, max(xs) + self.h, max(ys) + self.h

    def meets(self, x, y, grow):
        (a, d, h, l2) = (self.a, self.d, self.h, self.l2)
        lo = (x - grow, y - grow)
        hi = (x + 1 + grow, y + 1 + grow)
        corners = [(lo[0], lo[1]), (hi[0], lo[1]), (lo[0], hi[1]), (hi[0], hi[1])]

        def apart(gap, reach2, scale2):
            # gap * sqrt(scale2) > sqrt(reach2), or >= with --open
            if gap < 0 or (gap == 0 and not OPEN):
                return False
            if gap == 0:
                return reach2 == 0
            return gap * gap * scale2 >= reach2 if OPEN else gap * gap * scale2 > reach2

        along = [(c[0] - a[0]) * d[0] + (c[1] - a[1]) * d[1] for c in corners]
        if apart(-max(along), 0, 1) or apart(min(along) - l2, 0, 1):
            return False
        across = [(c[1] - a[1]) * d[0] - (c[0] - a[0]) * d[1] for c in corners]
        if apart(min(across), h * h * l2, 1) or apart(-max(across), h * h * l2, 1):
            return False
        for k in range(2):
            ends = sorted([self.a[k], self.b[k]])
            reach2 = h * h * d[1 - k] ** 2
            if apart(lo[k] - ends[1], reach2, l2) or apart(ends[0] - hi[k], reach2, l2):
                return False
        return True

    def inside(self, x, y):
        (a, d, h, l2) = (self.a, self.d, self.h, self.l2)
        for cx, cy in [(x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)]:
            along = (cx - a[0]) * d[0] + (cy - a[1]) * d[1]
            across = (cy - a[1]) * d[0] - (cx - a[0]) * d[1]
            if along < 0 or along > l2 or across * across > h * h * l2:
                return False
        return True


class Polygon:
    """A closed convex polygon: a triangle (or the segment or point a
    degenerate one is), a point's square, a parallelogram line."""

    def __init__(self, pts):
        self.pts = pts
        self.normals = axes(pts)

    def box(self):
        xs, ys = [p[0] for p in self.pts], [p[1] for p in self.pts]
        return min(xs), min(ys), max(xs), max(ys)

    def meets(self, x, y, grow):
        return meets(self.pts, self.normals, x, y, grow)

    def inside(self, x, y):
        return inside(self.pts, x, y)


def draw(shape, width, height, mode, flagged, samples, depth=None):
    """The fragments of one shape: [x, y] (or [x, y, f]); multisampled
    (`samples` a count, SPEC.md §19.10), [x, y, s] (or [x, y, s, f]) for
    every sample s of a drawn pixel: its samples are all covered. With
    `depth` (a `Depth`), its value follows x, y (and s)."""
    bx0, by0, bx1, by1 = shape.box()
    reach = GROW + 1
    x0, x1 = max(0, int(bx0 - reach)), min(width - 1, int(bx1 + reach))
    y0, y1 = max(0, int(by0 - reach)), min(height - 1, int(by1 + reach))
    out = []
    for y in range(y0, y1 + 1):
        for x in range(x0, x1 + 1):
            full = shape.inside(x, y)
            if mode == "underestimate":
                hit = full
            else:
                hit = shape.meets(x, y, GROW)
            if not hit:
                continue
            flag = [1 if full or "--flag-partial" in FLAGS else 0] if flagged else []
            slots = [[]] if samples is None else [[s] for s in range(samples)]
            z = [] if depth is None else [depth.at(x, y)]
            out.extend([x, y] + slot + z + flag for slot in slots)
    return out


def point_or_line(p, bits, conservative):
    """A point's square or a line's shape; None for a line culled."""
    if "point" in p:
        (x, y), = vertices([p["point"]], bits)
        h = Fraction(p["exact"]["size"]) / 2
        return Polygon([(x - h, y - h), (x + h, y - h), (x + h, y + h), (x - h, y + h)])
    a, b = vertices(p["line"], bits)
    if a == b:
        return Polygon([a]) if conservative.get("degenerate_lines") else None
    h = Fraction(p["exact"]["width"]) / 2
    if p["rule"] == "rectangle":
        return Rectangle(a, b, h)
    minor = 1 if abs(b[0] - a[0]) >= abs(b[1] - a[1]) else 0

    def shift(q, by):
        q = list(q)
        q[minor] += by
        return tuple(q)

    return Polygon([shift(a, -h), shift(b, -h), shift(b, h), shift(a, h)])


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
    deep = bool(req.get("plan", {}).get("depth"))
    prims = []
    for p in req["primitives"]:
        if ("point" in p or "line" in p) and deep:
            return {"unsupported": "this example gives no depth of points and lines"}
        if ("point" in p or "line" in p) and conservative is not None:
            if p.get("rule", "rectangle") not in ("rectangle", "parallelogram"):
                return {"unsupported": "this example draws rectangle and parallelogram lines only"}
            shape = point_or_line(p, rules["subpixel_bits"], conservative)
            prims.append({"fragments": [] if shape is None else draw(shape, width, height, mode, flagged, samples)})
            continue
        if "triangle" not in p:
            return {"unsupported": "this example draws triangles, points and lines only"}
        pts = vertices(p["triangle"], rules["subpixel_bits"])
        degenerate = twice_area(*pts) == 0
        if degenerate and ALWAYS is None and not conservative.get("degenerate_triangles"):
            prims.append({"fragments": []})  # culled, as the case states
            continue
        if culled(pts, rules.get("cull", "none")):
            prims.append({"fragments": []})
            continue
        depth = None
        if deep:
            zs = [Fraction(v["exact"]["z"]) for v in p["triangle"]]
            depth = Depth(pts, zs, rules)
        prims.append({"fragments": draw(Polygon(pts), width, height, mode, flagged, samples, depth)})
    return {"primitives": prims}


def main():
    hello = {"protocol": 2, "name": "conservative-example", "version": "1"}
    caps = {"primitives": ["triangles"], "coverage_only": True}
    if ALWAYS is None:
        caps["primitives"] = ["triangles", "lines", "points"]
        caps["line_rules"] = ["rectangle", "parallelogram"]
        del caps["coverage_only"]  # it gives depth (SPEC.md §19.9)
        caps["depth_formats"] = ["unorm16", "unorm24", "float32"]
        caps["polygon_offset"] = True
        caps["conservative"] = {
            "modes": ["overestimate", "underestimate"],
            "uncertainty": str(UNCERTAINTY),
            "fully_covered": True,
            "points_and_lines": True,
            "depth": True,
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
