"""The antialiasing checker's exact computations, written from SPEC.md alone:
each sample's coverage as the winding number of the sample nudged as the
fill rule says (section 14.1), and each pixel's exact area by slabs and
trapezoids, with the second computations that check the canvas total
(shoelace, Sutherland-Hodgman). No bounds here: evaluate.py sets them.
"""

import math
from bisect import bisect_left, bisect_right
from fractions import Fraction as F


# ---------------------------------------------------------------------------
# Coverage: winding numbers at nudged samples (SPEC.md section 14.1).

def filled(w, fill):
    return (w % 2 == 1) if fill == "even-odd" else (w != 0)


def row_crossings(edges, sy, rule):
    """(x_c, direction) of every edge the nudged horizontal ray at height sy
    crosses. top-* rules nudge down (y + eps^2): half-open [min, max);
    bottom-* rules nudge up: (min, max]."""
    top = rule in ("top-left", "top-right")
    out = []
    for (ax, ay), (bx, by) in edges:
        if ay == by:
            continue
        lo, hi = min(ay, by), max(ay, by)
        if top:
            if not (lo <= sy < hi):
                continue
        else:
            if not (lo < sy <= hi):
                continue
        xc = ax + (sy - ay) * (bx - ax) / (by - ay)
        out.append((xc, 1 if by > ay else -1))
    out.sort()
    return out


def coverage(c):
    """Per sample slot, how many primitives cover it (list, length W*H*N)."""
    W, H, bits, rule = c["width"], c["height"], c["bits"], c["fill_rule"]
    offs = c["offsets"]
    N = len(offs)
    counts = [0] * (W * H * N)
    # Group the slots by their offset's y, so that each sample row is scanned once.
    by_oy = {}
    for s, (ox, oy) in enumerate(offs):
        by_oy.setdefault(oy, []).append((ox, s))
    left = rule in ("top-left", "bottom-left")   # nudged right: x_c > sx counts
    for p in c["prims"]:
        edges = p.edges(bits)
        ys = [pt[1] for e in edges for pt in e]
        xs = [pt[0] for e in edges for pt in e]
        y_min, y_max, x_min, x_max = min(ys), max(ys), min(xs), max(xs)
        for y in range(H):
            for oy, slots in by_oy.items():
                sy = y + oy
                if sy < y_min or sy > y_max:
                    continue
                cr = row_crossings(edges, sy, rule)
                if not cr:
                    continue
                xcs = [x for x, _ in cr]
                # suffix[i] = sum of directions of crossings i..end
                suffix = [0] * (len(cr) + 1)
                for i in range(len(cr) - 1, -1, -1):
                    suffix[i] = suffix[i + 1] + cr[i][1]
                x_lo = max(0, math.floor(x_min) - 1)
                x_hi = min(W - 1, math.ceil(x_max))
                for x in range(x_lo, x_hi + 1):
                    for ox, s in slots:
                        sx = x + ox
                        # crossings with x_c > sx (left rules) or x_c >= sx (right rules)
                        i = bisect_right(xcs, sx) if left else bisect_left(xcs, sx)
                        if filled(suffix[i], p.fill):
                            counts[(y * W + x) * N + s] += 1
    return counts


# ---------------------------------------------------------------------------
# Exact areas.

def seg_intersection_y(e, f):
    """The y of the proper or touching intersection of two segments, if they
    meet in one point."""
    (ax, ay), (bx, by) = e
    (cx, cy), (dx, dy) = f
    rx, ry = bx - ax, by - ay
    sx, sy = dx - cx, dy - cy
    den = rx * sy - ry * sx
    if den == 0:
        return None
    t = ((cx - ax) * sy - (cy - ay) * sx) / den
    u = ((cx - ax) * ry - (cy - ay) * rx) / den
    if 0 <= t <= 1 and 0 <= u <= 1:
        return ay + t * ry
    return None


def x_at(e, y):
    (ax, ay), (bx, by) = e
    return ax + (y - ay) * (bx - ax) / (by - ay)


def pixel_areas(edges, fill, W, H, per_pixel=True):
    """Exact area of the filled region in each pixel (dict (x, y) -> area),
    or, with per_pixel False, the total area inside [0, W] x [0, H]
    computed by clipping each slab's spans to the canvas only."""
    edges = [e for e in edges if e[0][1] != e[1][1]]
    ys = set()
    for (a, b) in edges:
        ys.add(a[1])
        ys.add(b[1])
    for i in range(len(edges)):
        for j in range(i + 1, len(edges)):
            y = seg_intersection_y(edges[i], edges[j])
            if y is not None:
                ys.add(y)
    ys.update(F(k) for k in range(H + 1))
    # Where edges cross pixel columns (or, for the total, the canvas's sides):
    # within a slab, no edge crosses a column line, so clipped spans are linear.
    for e in edges:
        (ax, ay), (bx, by) = e
        if ax == bx:
            continue
        lo, hi = sorted((ax, bx))
        ks = range(max(0, math.floor(lo) + 1), min(W, math.ceil(hi) - 1) + 1) if per_pixel \
            else (0, W)
        for k in ks:
            if lo < k < hi:
                ys.add(ay + (k - ax) * (by - ay) / (bx - ax))
    ys = sorted(y for y in ys if 0 <= y <= H)
    areas = {}
    total = F(0)
    for y0, y1 in zip(ys, ys[1:]):
        ym = (y0 + y1) / 2
        active = [e for e in edges if min(e[0][1], e[1][1]) <= y0 and max(e[0][1], e[1][1]) >= y1]
        if not active:
            continue
        active.sort(key=lambda e: x_at(e, ym))
        w = 0
        row = math.floor(y0)
        for i in range(len(active) - 1):
            e = active[i]
            w += 1 if e[1][1] > e[0][1] else -1
            if not filled(w, fill):
                continue
            L, R = e, active[i + 1]
            l0, l1, r0, r1 = x_at(L, y0), x_at(L, y1), x_at(R, y0), x_at(R, y1)
            if not per_pixel:
                def span(l, r):
                    return max(F(0), min(r, F(W)) - max(l, F(0)))
                total += (y1 - y0) * (span(l0, r0) + span(l1, r1)) / 2
                continue
            c_lo = max(0, math.floor(min(l0, l1)))
            c_hi = min(W - 1, math.ceil(max(r0, r1)))
            for col in range(c_lo, c_hi + 1):
                def ln(l, r):
                    return max(F(0), min(r, F(col + 1)) - max(l, F(col)))
                a = (y1 - y0) * (ln(l0, r0) + ln(l1, r1)) / 2
                if a:
                    areas[(col, row)] = areas.get((col, row), F(0)) + a
    return areas if per_pixel else total


def shoelace(pts):
    s = F(0)
    for i in range(len(pts)):
        (ax, ay), (bx, by) = pts[i], pts[(i + 1) % len(pts)]
        s += ax * by - ay * bx
    return s / 2


def clip_convex_to_box(pts, W, H):
    """Sutherland-Hodgman clipping of a polygon to [0, W] x [0, H]."""
    def clip(pts, inside, cut):
        out = []
        for i in range(len(pts)):
            cur, prev = pts[i], pts[i - 1]
            if inside(cur):
                if not inside(prev):
                    out.append(cut(prev, cur))
                out.append(cur)
            elif inside(prev):
                out.append(cut(prev, cur))
        return out

    def cut_x(k):
        return lambda p, q: (F(k), p[1] + (k - p[0]) * (q[1] - p[1]) / (q[0] - p[0]))

    def cut_y(k):
        return lambda p, q: (p[0] + (k - p[1]) * (q[0] - p[0]) / (q[1] - p[1]), F(k))

    pts = clip(pts, lambda p: p[0] >= 0, cut_x(0))
    if pts:
        pts = clip(pts, lambda p: p[0] <= W, cut_x(W))
    if pts:
        pts = clip(pts, lambda p: p[1] >= 0, cut_y(0))
    if pts:
        pts = clip(pts, lambda p: p[1] <= H, cut_y(H))
    return pts


def is_convex_simple(pts):
    n = len(pts)
    signs = set()
    for i in range(n):
        (ax, ay), (bx, by), (cx, cy) = pts[i], pts[(i + 1) % n], pts[(i + 2) % n]
        cr = (bx - ax) * (cy - by) - (by - ay) * (cx - bx)
        if cr:
            signs.add(cr > 0)
    # Convex and turning once: the angles sum to one turn.
    if len(signs) > 1:
        return False
    turn = 0.0
    for i in range(n):
        (ax, ay), (bx, by), (cx, cy) = pts[i], pts[(i + 1) % n], pts[(i + 2) % n]
        a1 = math.atan2(float(by - ay), float(bx - ax))
        a2 = math.atan2(float(cy - by), float(cx - bx))
        d = (a2 - a1 + math.pi) % (2 * math.pi) - math.pi
        turn += d
    return abs(abs(turn) - 2 * math.pi) < 1e-6

