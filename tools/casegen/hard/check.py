"""The hard cases' independent exact checker, written from SPEC.md alone (it
shares no code with rastercheck): snapping with ties to even (section 2),
edge ownership in D3D11's words (section 3), the midpoint line rule
(section 4.1) and the mesh interior of section 6.2. It computes every
`samples_covered` the files carry, and with --check proves each claim.
"""

import math
from fractions import Fraction as F

from casegen.casefile import Tri, pos_of
from casegen.hard.build import HALF, Line


def snap(v, bits, mode="even"):
    """v rounded to a multiple of 2^-bits, ties to even (or away from zero)."""
    if bits is None:
        return F(v)
    s = F(v) * 2**bits
    fl = math.floor(s)
    r = s - fl
    if r > HALF or (r == HALF and (fl % 2 == 1 if mode == "even" else s > 0)):
        fl += 1
    return F(fl, 2**bits)


OWNS = {"top-left": {"top", "left"}, "bottom-right": {"bottom", "right"},
        "top-right": {"top", "right"}, "bottom-left": {"bottom", "left"},
        "all-edges": {"top", "left", "bottom", "right"}}
FLIP = {"top-left": "bottom-right", "bottom-right": "top-left", "top-right": "bottom-left",
        "bottom-left": "top-right"}


def grid_of(c):
    """Units per pixel of one integer grid holding every snapped vertex and
    every sample centre."""
    if c["bits"] is not None:
        return 2**(c["bits"] + 1)
    den = 2
    for p in c["prims"]:
        for v in p.v:
            for q in pos_of(v):
                den = den * q.denominator // math.gcd(den, q.denominator)
    return 2 * den


def placed(c, v, mode="even"):
    g = grid_of(c)
    return tuple(int(snap(q, c["bits"], mode) * g) for q in pos_of(v))


def cross(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def edge_kind(a, b, third):
    """D3D11's words: a top edge is horizontal with the triangle below it; a
    left edge is not horizontal with the triangle to its right."""
    if a[1] == b[1]:
        return "top" if third[1] > a[1] else "bottom"
    # The x of the edge at third's height, compared with third's x:
    # third.x > a.x + (third.y - a.y)(b.x - a.x)/(b.y - a.y).
    lhs = (third[0] - a[0]) * (b[1] - a[1])
    rhs = (third[1] - a[1]) * (b[0] - a[0])
    right_of_edge = lhs > rhs if b[1] > a[1] else lhs < rhs
    return "left" if right_of_edge else "right"


def triangle_samples(c, pts, rule):
    """The set of (x, y) samples covered by one snapped triangle."""
    g = grid_of(c)
    area = cross(*pts)
    if area == 0:
        return set(), [], 0
    if c["cull"] == "cw" and area > 0 or c["cull"] == "ccw" and area < 0:
        return set(), [], area
    edges = []
    for i in range(3):
        a, b, third = pts[i], pts[(i + 1) % 3], pts[(i + 2) % 3]
        side = 1 if cross(a, b, third) > 0 else -1
        edges.append((a, b, side, edge_kind(a, b, third) in OWNS[rule]))
    W, H = c["width"], c["height"]
    h = g // 2
    x_lo = max(0, -(-(min(p[0] for p in pts) - h) // g))
    x_hi = min(W - 1, (max(p[0] for p in pts) - h) // g)
    y_lo = max(0, -(-(min(p[1] for p in pts) - h) // g))
    y_hi = min(H - 1, (max(p[1] for p in pts) - h) // g)
    out, on_edge = set(), []
    for yy in range(y_lo, y_hi + 1):
        sy = yy * g + h
        for xx in range(x_lo, x_hi + 1):
            s = (xx * g + h, sy)
            ok, touched = True, False
            for a, b, side, owned in edges:
                e = cross(a, b, s) * side
                if e < 0 or (e == 0 and not owned):
                    ok = False
                    if e < 0:
                        break
                if e == 0:
                    touched = True
            if touched:
                on_edge.append((xx, yy))
            if ok:
                out.add((xx, yy))
    return out, on_edge, area


def ceil_f(q):
    return -((-q.numerator) // q.denominator)


def midpoint_pixels(c, line):
    """SPEC 4.1: the nearest row in each column (x-major), ties to the upper
    row; y-major the same with the axes swapped, ties to the left."""
    (x0, y0), (x1, y1) = [tuple(snap(q, c["bits"]) for q in pos_of(v)) for v in line.v]
    dx, dy = x1 - x0, y1 - y0
    if dx == 0 and dy == 0:
        return set(), 0
    swap = abs(dx) < abs(dy)
    if swap:
        x0, y0, x1, y1, dx, dy = y0, x0, y1, x1, dy, dx
    W, H = (c["height"], c["width"]) if swap else (c["width"], c["height"])
    lo, hi = min(x0, x1), max(x0, x1)
    out, ties = set(), 0
    for i in range(max(0, ceil_f(lo - HALF)), min(W - 1, math.floor(hi - HALF)) + 1):
        cc = i + HALF
        if line.last_pixel == "exclude" and cc == x1:
            continue
        y = y0 + (cc - x0) * dy / dx
        if y.denominator == 1:
            ties += 1
        j = ceil_f(y) - 1
        if 0 <= j < H:
            out.add((j, i) if swap else (i, j))
    return out, ties


def render_frame(c, rule=None, mode="even"):
    """Per sample: the list of primitives covering it, in order. Also the
    samples lying on some triangle edge, and each triangle's twice-area."""
    rule = rule or c["fill_rule"]
    cov = {}
    on_edges, areas, line_ties = set(), [], 0
    for idx, p in enumerate(c["prims"]):
        if isinstance(p, Line):
            px, ties = midpoint_pixels(c, p)
            line_ties += ties
            areas.append(None)
        else:
            pts = [placed(c, v, mode) for v in p.v]
            px, on, area = triangle_samples(c, pts, rule)
            on_edges.update(on)
            areas.append(area)
        for s in px:
            cov.setdefault(s, []).append(idx)
    return cov, on_edges, areas, line_ties


def interior(c):
    frames = [render_frame(c, rule)[0] for rule in FLIP]
    return {s for s in frames[0] if all(s in f for f in frames[1:])}


def product_bits(c):
    """Bits of the largest |(bx - ax)(py - ay)| over triangle edges and the
    canvas corner samples, in production's units (2^-(bits+1) px)."""
    g = grid_of(c)
    corners = [(h * g + g // 2, v * g + g // 2) for h in (0, c["width"] - 1)
               for v in (0, c["height"] - 1)]
    best = 0
    for p in c["prims"]:
        pts = [placed(c, v) for v in p.v]
        for i in range(len(pts)):
            a, b = pts[i], pts[(i + 1) % len(pts)]
            for s in corners:
                best = max(best, abs((b[0] - a[0]) * (s[1] - a[1])), abs((b[1] - a[1]) * (s[0] - a[0])))
    return best.bit_length()


def check_claims(c, cov, on_edges, areas, line_ties):
    notes, ok = [], True

    def fail(msg):
        nonlocal ok
        ok = False
        notes.append("FAILED: " + msg)

    if c["watertight"]:
        inner = interior(c)
        holes = sum(1 for s in inner if s not in cov)
        over = sum(1 for s in cov if len(cov[s]) > 1)
        notes.append("interior %d" % len(inner))
        if holes or over:
            fail("not watertight: %d holes, %d overdraw" % (holes, over))
    for claim in c["checks"]:
        kind = claim[0]
        if kind == "ties":
            n = len(on_edges) if c["prims"] and isinstance(c["prims"][0], Tri) else 0
            notes.append("%d samples on edges" % n)
            if n < claim[1]:
                fail("only %d samples on edges, claimed %d" % (n, claim[1]))
        elif kind == "flip_changes":
            other = render_frame(c, FLIP[c["fill_rule"]])[0]
            d = sum(1 for s in set(cov) | set(other) if cov.get(s, [])[-1:] != other.get(s, [])[-1:]
                    or len(cov.get(s, [])) != len(other.get(s, [])))
            notes.append("flipped rule: %d differ" % d)
            if not d:
                fail("the flipped rule changes nothing")
        elif kind == "snap_tie_sensitive":
            other = render_frame(c, mode="away")[0]
            d = sum(1 for s in set(cov) | set(other) if cov.get(s, [])[-1:] != other.get(s, [])[-1:]
                    or len(cov.get(s, [])) != len(other.get(s, [])))
            notes.append("half-away snapping: %d differ" % d)
            if not d:
                fail("snapping ties away from zero changes nothing")
        elif kind == "zero_covered":
            if cov:
                fail("covers %d samples" % len(cov))
        elif kind == "degenerate":
            n = sum(1 for a in areas if a == 0)
            notes.append("%d zero-area" % n)
            if n != claim[1]:
                fail("%d zero-area triangles, claimed %d" % (n, claim[1]))
        elif kind == "product_bits":
            b = product_bits(c)
            notes.append("products %d bits" % b)
            if b < claim[1]:
                fail("products need only %d bits" % b)
        elif kind == "far":
            far = max(abs(q) for p in c["prims"] for v in p.v for q in pos_of(v))
            if far < claim[1]:
                fail("farthest coordinate only %s" % far)
        elif kind == "crack":
            x0, y0, x1, y1 = claim[1]
            holes = sorted((x, y) for y in range(y0, y1) for x in range(x0, x1) if (x, y) not in cov)
            if holes != sorted(claim[2]):
                fail("uncovered samples %s, claimed %s" % (holes, sorted(claim[2])))
            notes.append("crack of %d samples" % len(holes))
            over = [s for s in cov if len(cov[s]) > 1]
            if over:
                fail("overdraw at %s" % over)
        elif kind == "count_at_least":
            k, samples = claim[1], claim[2]
            top = max((len(v) for v in cov.values()), default=0)
            notes.append("max count %d" % top)
            if top < k or any(len(cov.get(s, [])) < k for s in samples):
                fail("some sample of %s covered fewer than %d times" % (samples, k))
        elif kind == "covered":
            if len(cov) != claim[1]:
                fail("covers %d samples, claimed %d" % (len(cov), claim[1]))
        elif kind == "overdraw_exactly":
            x0, y0, x1, y1 = claim[1]
            over = sorted(s for s in cov if len(cov[s]) > 1)
            if over != sorted(claim[2]):
                fail("overdrawn %s, claimed %s" % (over, sorted(claim[2])))
            holes = [(x, y) for y in range(y0, y1) for x in range(x0, x1) if (x, y) not in cov]
            if holes:
                fail("holes at %s" % holes)
            notes.append("%d overdrawn" % len(over))
        elif kind == "snap_moves":
            v = claim[1]
            if all(snap(q, c["bits"]) == q for q in v):
                fail("the vertex is on the grid")
        elif kind == "windings_mixed":
            signs = {a > 0 for a in areas if a}
            if len(signs) != 2:
                fail("one winding only")
        elif kind == "line_ties":
            notes.append("%d line ties" % line_ties)
            if line_ties < claim[1]:
                fail("only %d ties on lines" % line_ties)
        else:
            raise ValueError(kind)
    return ok, notes
