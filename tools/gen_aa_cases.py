#!/usr/bin/env python3
"""Writes the antialiasing and polygon cases: cases/antialias/*.json and
cases/polygons/*.json (SPEC.md section 14).

Python 3 standard library only. Every expectation is computed here, by an
exact checker written from SPEC.md alone (fractions.Fraction, no call into
rastercheck):

- the sample offsets of the five patterns, SplitMix64 included (section 14.2);
- each sample's coverage: the winding number of the sample nudged as the fill
  rule says (section 14.1; a triangle or a parallelogram line is a one-contour
  nonzero polygon, which section 14.1 states is the same as section 3's rule);
- each pixel's exact area: the filled region of every primitive cut into
  slabs at every vertex, every crossing of two edges, every pixel row and
  every crossing of an edge with a pixel column, so that in each slab the
  filled part of each pixel is a trapezoid (its area is exact by the
  trapezoid rule); the canvas total is checked against a second computation
  (slabs clipped to the canvas only, and for convex primitives
  Sutherland-Hodgman clipping and the shoelace formula).

Written expectations:

- `samples_covered`: sample slots covered at least once;
- `area`: the exact total area of the primitives inside the canvas, a
  fraction string;
- `max_coverage_rms` (antialiased cases): piglit's MSAA bound
  0.333 * 0.62^log2(N) over edge pixels; cases whose pattern is known to miss
  it (few independent random samples) use the Monte Carlo bound 1/sqrt(N),
  twice the largest expected RMS sqrt(a(1-a)/N) <= 0.5/sqrt(N) of N
  independent uniform samples, and say so;
- `max_coverage_error`: min(P, 2E/sqrt(N)), where E is the largest number of
  primitive edges that touch one pixel and P the largest number of
  primitives that touch one pixel (a primitive's coverage error is at most
  1). The reasoning: for a k x k grid or stratified pattern only the cells
  a straight edge touches can be wrong, at most 3k - 2 of them, so one edge
  costs at most (3k - 2)/N < 3/sqrt(N); 2/sqrt(N) per edge is the
  tighter quality requirement a good N-sample pattern meets (its worst
  single-edge error is about 1/sqrt(N): a row or column of sqrt(N) samples
  flipping at once). Cases whose pattern is bad at this say so and use a
  looser bound.

The generator asserts that the exact N-sample method (the reference's own
mask, box-resolved) meets every bound it writes: a bound the exact method
fails is a bug here, not in rastercheck.

Usage: python3 tools/gen_aa_cases.py [-v] [--report]   (run from anywhere)
  -v         one line per case: samples covered, area, the exact method's
             largest error and RMS against the written bounds
  --report   print the cases whose exact method breaks a bound instead of
             stopping at the first (for working on the bounds)
"""

import json
import math
import os
import sys
from bisect import bisect_left, bisect_right
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exactjson import exact, js  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
AA_DIR = os.path.join(ROOT, "cases", "antialias")
POLY_DIR = os.path.join(ROOT, "cases", "polygons")

# ---------------------------------------------------------------------------
# Sample patterns (SPEC.md section 14.2), written from the text.

MASK64 = (1 << 64) - 1


class SplitMix64:
    def __init__(self, seed):
        self.state = seed & MASK64

    def next(self):
        self.state = (self.state + 0x9E3779B97F4A7C15) & MASK64
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK64
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK64
        return z ^ (z >> 31)

    def draw(self, bits):
        return self.next() >> (64 - bits)


# Vulkan standardSampleLocations, in 1/16 pixel (y down), in Vulkan's order.
STANDARD = {
    1: [(F(1, 2), F(1, 2))],
    2: [(F(3, 4), F(3, 4)), (F(1, 4), F(1, 4))],
    4: [(F(3, 8), F(1, 8)), (F(7, 8), F(3, 8)), (F(1, 8), F(5, 8)), (F(5, 8), F(7, 8))],
    8: [(F(9, 16), F(5, 16)), (F(7, 16), F(11, 16)), (F(13, 16), F(9, 16)), (F(5, 16), F(3, 16)),
        (F(3, 16), F(13, 16)), (F(1, 16), F(7, 16)), (F(11, 16), F(15, 16)), (F(15, 16), F(1, 16))],
    16: [(F(9, 16), F(9, 16)), (F(7, 16), F(5, 16)), (F(5, 16), F(10, 16)), (F(12, 16), F(7, 16)),
         (F(3, 16), F(6, 16)), (F(10, 16), F(13, 16)), (F(13, 16), F(11, 16)), (F(11, 16), F(3, 16)),
         (F(6, 16), F(14, 16)), (F(8, 16), F(1, 16)), (F(4, 16), F(2, 16)), (F(2, 16), F(12, 16)),
         (F(0, 16), F(8, 16)), (F(15, 16), F(4, 16)), (F(14, 16), F(15, 16)), (F(1, 16), F(0, 16))],
}


def isqrt_exact(n):
    k = math.isqrt(n)
    assert k * k == n, n
    return k


def offsets(aa):
    """The N offsets of a pattern as Fractions in [0, 1)^2, in slot order."""
    n, pattern, seed, bits = aa["samples"], aa.get("pattern", "standard"), aa.get("seed", 0), \
        aa.get("position_bits", 8)
    L = 1 << bits
    rng = SplitMix64(seed)
    if pattern == "standard":
        pts = STANDARD[n]
        for p in pts:
            assert (p[0] * L).denominator == 1 and (p[1] * L).denominator == 1
        return list(pts)
    if pattern == "grid":
        k = isqrt_exact(n)
        # (2i + 1)/2k on the lattice, ties to even (Fraction rounds half to even).
        c = [F(round(F((2 * i + 1) * L, 2 * k)), L) for i in range(k)]
        return [(c[s % k], c[s // k]) for s in range(n)]
    if pattern == "stratified":
        k = isqrt_exact(n)
        out = []
        for s in range(n):
            i, j = s % k, s // k
            x = (i * L + rng.draw(bits)) // k
            y = (j * L + rng.draw(bits)) // k
            out.append((F(x, L), F(y, L)))
        return out
    if pattern == "random":
        out = []
        for _ in range(n):
            x = rng.draw(bits)
            y = rng.draw(bits)
            out.append((F(x, L), F(y, L)))
        return out
    if pattern == "n-rooks":
        perm = list(range(n))
        for i in range(n - 1, 0, -1):
            j = rng.next() % (i + 1)
            perm[i], perm[j] = perm[j], perm[i]
        out = []
        for i in range(n):
            x = (i * L + rng.draw(bits)) // n
            y = (perm[i] * L + rng.draw(bits)) // n
            out.append((F(x, L), F(y, L)))
        return out
    raise ValueError(pattern)


# ---------------------------------------------------------------------------
# Primitives, as the checker sees them: closed contours and a fill rule.

def snap(q, bits):
    if bits is None:
        return q
    s = 1 << bits
    return F(round(q * s), s)


class Prim:
    """A primitive as written in the case (json) and as the checker fills it
    (contours of snapped points, fill 'nonzero' or 'even-odd')."""

    def __init__(self, json_obj, contours, fill):
        self.json_obj = json_obj
        self.raw = contours
        self.fill = fill

    def json(self):
        return self.json_obj

    def snapped(self, bits):
        return [[(snap(x, bits), snap(y, bits)) for (x, y) in c] for c in self.raw]

    def edges(self, bits):
        out = []
        for c in self.snapped(bits):
            for i in range(len(c)):
                out.append((c[i], c[(i + 1) % len(c)]))
        return out


def P(x, y):
    return (exact(x), exact(y))


def tri(a, b, c):
    a, b, c = P(*a), P(*b), P(*c)
    return Prim({"triangle": [list(a), list(b), list(c)]}, [[a, b, c]], "nonzero")


def poly(points, fill=None):
    pts = [P(*p) for p in points]
    d = {"polygon": [list(p) for p in pts]}
    if fill:
        d["fill"] = fill
    return Prim(d, [pts], fill or "nonzero")


def contours(cs, fill=None):
    cs = [[P(*p) for p in c] for c in cs]
    d = {"contours": [[list(p) for p in c] for c in cs]}
    if fill:
        d["fill"] = fill
    return Prim(d, cs, fill or "nonzero")


class ParallelogramLine(Prim):
    """A parallelogram line (SPEC.md section 4.4): its endpoints snap, then it
    is the quadrilateral with ends along the minor axis."""

    def __init__(self, a, b, width):
        self.a, self.b, self.width = P(*a), P(*b), exact(width)
        Prim.__init__(self, {"line": [list(self.a), list(self.b)], "rule": "parallelogram",
                             "width": self.width}, None, "nonzero")

    def snapped(self, bits):
        (x0, y0), (x1, y1) = [(snap(x, bits), snap(y, bits)) for (x, y) in (self.a, self.b)]
        h = self.width / 2
        if (x0, y0) == (x1, y1):
            return [[(x0, y0), (x0, y0), (x0, y0)]]
        if abs(x1 - x0) >= abs(y1 - y0):
            return [[(x0, y0 - h), (x1, y1 - h), (x1, y1 + h), (x0, y0 + h)]]
        return [[(x0 - h, y0), (x1 - h, y1), (x1 + h, y1), (x0 + h, y0)]]


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


# ---------------------------------------------------------------------------
# Bounds.

def seg_touches_box(e, x0, y0, x1, y1):
    """Whether a segment meets the closed box [x0, x1] x [y0, y1] (Liang-Barsky)."""
    (ax, ay), (bx, by) = e
    t0, t1 = F(0), F(1)
    for p, q in ((-(bx - ax), ax - x0), (bx - ax, x1 - ax), (-(by - ay), ay - y0), (by - ay, y1 - ay)):
        if p == 0:
            if q < 0:
                return False
            continue
        r = F(q) / p
        if p < 0:
            t0 = max(t0, r)
        else:
            t1 = min(t1, r)
        if t0 > t1:
            return False
    return True


def edges_per_pixel(c):
    """(E, P): the most primitive edges, and the most primitives, touching one
    pixel's closed square."""
    W, H = c["width"], c["height"]
    edge_count = {}
    prim_count = {}
    for p in c["prims"]:
        touched = set()
        for e in p.edges(c["bits"]):
            if e[0] == e[1]:
                continue
            xs, ys = (e[0][0], e[1][0]), (e[0][1], e[1][1])
            for y in range(max(0, math.floor(min(ys)) - 1), min(H - 1, math.ceil(max(ys))) + 1):
                for x in range(max(0, math.floor(min(xs)) - 1), min(W - 1, math.ceil(max(xs))) + 1):
                    if seg_touches_box(e, x, y, x + 1, y + 1):
                        edge_count[(x, y)] = edge_count.get((x, y), 0) + 1
                        touched.add((x, y))
        for q in touched:
            prim_count[q] = prim_count.get(q, 0) + 1
    return max(edge_count.values(), default=1), max(prim_count.values(), default=1)


def round_up(q, digits=4):
    """The smallest decimal with `digits` fractional digits that is >= q."""
    s = 10 ** digits
    return F(math.ceil(q * s), s)


def piglit_rms(n):
    return 0.333 * 0.62 ** math.log2(n)


# ---------------------------------------------------------------------------
# Cases.

CASES = []


def case(folder, name, description, width, height, prims, aa=None, bits=8, fill_rule="top-left",
         rms="piglit", max_error="edges", extra_expect=None, checks=None):
    """Registers a case. aa: the effects.antialias object or None.
    rms: 'piglit' or 'monte-carlo' (see the module docstring).
    max_error: 'edges' (min(P, 2E/sqrt N)) or 'primitives' (P: the pattern
    is known to be bad at this case, and the description says why).
    checks: functions of the computed result that must hold (the author's
    intent, asserted)."""
    assert width <= 64 and height <= 64
    if aa and aa["samples"] >= 64:
        assert width <= 32 and height <= 32, name
    CASES.append(dict(folder=folder, name=name, description=description, width=width,
                      height=height, prims=prims, aa=aa, bits=bits, fill_rule=fill_rule, rms=rms,
                      max_error=max_error, extra_expect=extra_expect or {}, checks=checks or []))


def evaluate(c):
    """Computes every expectation of a case; returns (expect dict, stats)."""
    W, H = c["width"], c["height"]
    aa = c["aa"]
    c["offsets"] = offsets(aa) if aa else [(F(1, 2), F(1, 2))]
    N = len(c["offsets"])
    counts = coverage(c)
    covered = sum(1 for k in counts if k > 0)
    expect = {"samples_covered": covered}
    stats = {"covered": covered, "N": N, "counts": counts}
    if not aa:
        return expect, stats
    # Exact areas, two ways.
    area = {}
    total_a = F(0)
    total_b = F(0)
    for p in c["prims"]:
        edges = p.edges(c["bits"])
        per = pixel_areas(edges, p.fill, W, H)
        for k, v in per.items():
            assert 0 < v <= 1, (c["name"], k, v)
            area[k] = area.get(k, F(0)) + v
        t = sum(per.values(), F(0))
        t2 = pixel_areas(edges, p.fill, W, H, per_pixel=False)
        assert t == t2, (c["name"], t, t2)
        snapped = p.snapped(c["bits"])
        if len(snapped) == 1 and is_convex_simple(snapped[0]):
            clipped = clip_convex_to_box(snapped[0], W, H)
            t3 = abs(shoelace(clipped)) if len(clipped) >= 3 else F(0)
            assert t == t3, (c["name"], t, t3)
        total_a += t
        total_b += t2
    assert total_a == total_b
    expect["area"] = str(total_a)
    # Errors of the exact N-sample method.
    errs = []
    max_err = F(0)
    for y in range(H):
        for x in range(W):
            i = (y * W + x) * N
            frac = F(sum(counts[i:i + N]), N)
            a = area.get((x, y), F(0))
            # Full and empty pixels are exact (SPEC.md 14.3): a pixel of area 0
            # covers no sample, and one of area 1 with one primitive covers all.
            err = frac - a
            max_err = max(max_err, abs(err))
            if 0 < a < 1 or frac not in (0, 1):
                errs.append(err)
    rms_exact = math.sqrt(float(sum(e * e for e in errs) / len(errs))) if errs else 0.0
    E, Pn = edges_per_pixel(c)
    # A pixel's error is at most max(resolved, area): 1 unless primitives overlap.
    cap = max(F(1), F(math.ceil(max(area.values(), default=F(0)))), F(max(counts, default=0)))
    cap = min(cap, F(Pn))
    if c["max_error"] == "edges":
        bound = min(cap, round_up(F(2 * E) / F(math.isqrt(N)) if math.isqrt(N) ** 2 == N
                                  else F(2 * E / math.sqrt(N))))
    elif c["max_error"] == "probe":
        bound = round_up(F(1, N))
    else:
        raise ValueError(c["max_error"])
    if c["rms"] == "piglit":
        rms_bound = round_up(F(piglit_rms(N)))
    elif c["rms"] == "piglit-half":
        rms_bound = round_up(F(piglit_rms(N // 2)))
    elif c["rms"] == "monte-carlo":
        rms_bound = round_up(F(1 / math.sqrt(N)))
    elif c["rms"] == "max":
        rms_bound = bound
    elif c["rms"] == "probe":
        rms_bound = round_up(F(1, N))
    else:
        raise ValueError(c["rms"])
    ok_max = max_err <= bound
    ok_rms = rms_exact <= float(rms_bound) * (1 - 1e-9)
    if "--report" in sys.argv:
        if not (ok_max and ok_rms):
            print("FAILS BOUND", c["name"], float(max_err), float(bound), rms_exact, float(rms_bound))
    else:
        assert ok_max, "%s: exact max error %s > bound %s" % (c["name"], float(max_err), float(bound))
        assert ok_rms, "%s: exact RMS %s > bound %s" % (c["name"], rms_exact, float(rms_bound))
    expect["max_coverage_error"] = bound
    expect["max_coverage_rms"] = rms_bound
    stats.update(area=area, max_err=max_err, rms=rms_exact, E=E, P=Pn, edge_pixels=len(errs))
    return expect, stats


def render(c, expect):
    lines = ["{"]
    lines.append('  "name": %s,' % js(c["name"]))
    lines.append('  "description": %s,' % js(c["description"]))
    lines.append('  "canvas": %s,' % js({"width": c["width"], "height": c["height"]}))
    lines.append('  "rules": %s,' % js({"subpixel_bits": c["bits"], "fill_rule": c["fill_rule"],
                                          "cull": "none"}))
    if c["aa"]:
        lines.append('  "effects": %s,' % js({"antialias": c["aa"]}))
    lines.append('  "primitives": [')
    lines.append(",\n".join("    " + js(p.json()) for p in c["prims"]))
    lines.append("  ],")
    lines.append('  "expect": %s' % js(expect))
    lines.append("}")
    return "\n".join(lines) + "\n"


def AA(samples, pattern="standard", **kw):
    d = {"samples": samples, "pattern": pattern}
    d.update(kw)
    return d


def rect_tris(x0, y0, x1, y1):
    """An axis-aligned rectangle as two triangles sharing its diagonal."""
    return [tri((x0, y0), (x1, y0), (x1, y1)), tri((x0, y0), (x1, y1), (x0, y1))]


PROBE_NOTE = ("Bounds: a probe covers at most one sample of a pixel and at most 1/256 px^2 of it, so "
              "every pixel's error is at most 1/N: that is both max_coverage_error and "
              "max_coverage_rms.")
BOUNDS_NOTE = ("Bounds: max_coverage_rms is piglit's 0.333*0.62^log2(N); max_coverage_error is "
               "min(P, 2E/sqrt(N)) with E the most edges touching one pixel and P the most primitives "
               "(tools/gen_aa_cases.py explains both; the exact N-sample method meets them).")
MC_NOTE = ("Bounds: this pattern has too few independent random samples for piglit's MSAA bound, so "
           "max_coverage_rms is the Monte Carlo bound 1/sqrt(N), twice the largest expected RMS "
           "0.5/sqrt(N) of N independent uniform samples; max_coverage_error is min(P, 2E/sqrt(N)) "
           "with E the most edges touching one pixel and P the most primitives.")


def along_edge(n, dx, dy):
    """How the standard n-sample pattern looks to an edge of direction (dx, dy):
    ('piglit-half', note) when its samples' projections onto the edge normal
    collapse to at most n/2 values, or leave a gap at least 3 times the mean
    gap (the samples pair up, and the pattern acts like n/2 samples along this
    edge); ('piglit', '') otherwise. Decided from the pattern alone."""
    proj = sorted(dy * x - dx * y for x, y in STANDARD[n])
    distinct = sorted(set(proj))
    gaps = [b - a for a, b in zip(proj, proj[1:])]
    mean = (proj[-1] - proj[0]) / (n - 1) if n > 1 else 0
    if n > 1 and (len(distinct) <= n // 2 or max(gaps) >= 3 * mean):
        why = ("only %d distinct projections" % len(distinct) if len(distinct) <= n // 2 else
               "a gap of %.1f times the mean gap between projections" % (max(gaps) / mean))
        return "piglit-half", (
            " Along this direction the standard %dx pattern is weak: its samples' projections onto "
            "the edge normal show %s, so the pattern acts like %d samples here, and max_coverage_rms "
            "is piglit's bound for N = %d (the rest as below)." % (n, why, n // 2, n // 2))
    return "piglit", ""


# --- 1. Edges at many angles ------------------------------------------------

# Each case is one large triangle whose long edge crosses a 16x16 canvas at the
# given slope; its other edges lie on the canvas border or outside it. dx, dy:
# the direction of the long edge.
ANGLES = [
    ("slope_1_128", 128, 1, "1/128 (0.45 degrees from horizontal)"),
    ("slope_neg_1_128", 128, -1, "-1/128 (0.45 degrees below horizontal)"),
    ("steep_1_128", 1, 128, "128 (0.45 degrees from vertical)"),
    ("slope_1_64", 64, 1, "1/64 (0.9 degrees)"),
    ("slope_1_16", 16, 1, "1/16 (3.6 degrees)"),
    ("slope_1_3", 3, 1, "1/3 (18.4 degrees)"),
    ("slope_1_2", 2, 1, "1/2 (26.6 degrees)"),
    ("slope_1", 1, 1, "1 (45 degrees, through the pixel corners' diagonals)"),
    ("slope_5_3", 3, 5, "5/3 (59 degrees)"),
    ("steep_neg_1_16", -1, 16, "-16 (3.6 degrees from vertical, leaning left)"),
]

for tag, dx, dy, what in ANGLES:
    for n in (4, 16):
        # The edge passes through (8, 8) + 1/7-ish offset so that it does not
        # run through sample rows; the triangle extends it far beyond the canvas.
        cx, cy = F(8) + F(37, 256), F(8) + F(11, 256)
        t = F(60)
        a = (cx - t * dx / max(abs(dx), abs(dy)), cy - t * dy / max(abs(dx), abs(dy)))
        b = (cx + t * dx / max(abs(dx), abs(dy)), cy + t * dy / max(abs(dx), abs(dy)))
        # The third vertex: far on one side of the edge.
        nx, ny = -dy, dx
        s = F(60) / max(abs(nx), abs(ny))
        third = (cx + s * nx, cy + s * ny)
        rms, weak = along_edge(n, dx, dy)
        case(AA_DIR, "edge_%s_standard%d" % (tag, n),
             "A long triangle edge of slope %s crosses the 16x16 canvas (the triangle's other vertices "
             "lie far outside it, so only this edge is visible), standard %dx pattern. Near-axis edges "
             "are the hard ones: an edge within 0.5 degrees of an axis sweeps whole rows or columns of "
             "samples at once, so a pattern with collinear samples (a grid) jumps by 1/sqrt(N) while the "
             "exact area moves smoothly; a rasterizer that sets up the edge in too few bits also shows "
             "its error here first.%s %s" % (what, n, weak, BOUNDS_NOTE),
             16, 16, [tri(a, b, third)], aa=AA(n), rms=rms)

# --- 2. Tiny triangles, slivers, abutting triangles ------------------------

TINY = [((F(3) + F(1, 8), F(2) + F(1, 4)), "inside one pixel"),
        ((F(3) - F(1, 4), F(2) - F(1, 4)), "straddling the corner of four pixels")]
for i, ((x, y), where) in enumerate(TINY):
    for n, pat in ((4, "standard"), (16, "standard"), (64, "grid")):
        case(AA_DIR, "tiny_%s_%s%d" % (("in_pixel", "on_corner")[i], pat, n),
             "A 0.5 x 0.6 px right triangle (its legs are 0.5 and 0.6 px; 0.6 snaps to 154/256), %s, "
             "%s %dx pattern. It covers a handful of samples or none; its exact area is 77/512 px^2 "
             "(about 0.15) "
             "whatever the pattern, so a sample method's error here is as large as the triangle "
             "itself, and a method that drops primitives smaller than a sample spacing shows it. The "
             "bound on the largest error is min(1, 2E/sqrt(N)) with E = 3 edges in one pixel, and "
             "since one to four pixels hold the whole triangle, the RMS bound is that same bound "
             "(an RMS never exceeds the largest error); piglit's bound is meant for edges that "
             "cross many pixels." % (where, pat, n),
             6, 5, [tri((x, y), (x + F(1, 2), y), (x, y + F(6, 10)))], aa=AA(n, pat), rms="max")

for n in (4, 16):
    case(AA_DIR, "sliver_long_standard%d" % n,
         "A sliver 1/8 px tall at its base and 24 px long, at a slope of about 1/6, standard %dx: "
         "each pixel it crosses holds a thin wedge whose area is far below one sample's share "
         "(1/N), so most pixels resolve to 0 and a few to 1/N. The exact area is 3/2 in all; the "
         "case holds the mask exact sample by sample and the resolve to the bounds. %s"
         % (n, BOUNDS_NOTE),
         26, 8, [tri((1, 2), (25, 6), (1, F(2) + F(1, 8)))], aa=AA(n))

case(AA_DIR, "abutting_square_diagonal_standard16",
     "An 8x8 square made of two triangles that share its diagonal (2,1)-(10,9), standard 16x, on a "
     "12x10 canvas. Each triangle's coverage is partial along the diagonal, but the two together "
     "cover every sample of the square once: every pixel inside the square must resolve to exactly "
     "1 (the sum of two partial coverages), and the total area is exactly 64. A rasterizer that "
     "double-counts or drops samples on the shared diagonal, or blends the two partial coverages "
     "instead of adding them, fails. %s" % BOUNDS_NOTE,
     12, 10, [tri((2, 1), (10, 1), (10, 9)), tri((2, 1), (10, 9), (2, 9))], aa=AA(16),
     checks=[lambda s: all(s["area"].get((x, y), 0) == 1 for x in range(2, 10) for y in range(1, 9))])

# A fan of 8 triangles around a centre that is no sample position.
FAN_C = (F(5) + F(3, 16), F(4) + F(5, 16))
FAN_R = [(F(1), F(1)), (F(5), F(1) - F(1, 2)), (F(9) + F(1, 4), F(1)), (F(9), F(4)),
         (F(9) + F(1, 2), F(7) + F(3, 4)), (F(5) - F(1, 4), F(8)), (F(1), F(7) + F(1, 2)),
         (F(1) - F(1, 2), F(4) + F(1, 8))]
case(AA_DIR, "abutting_fan_8_standard8",
     "Eight triangles fanned around (5+3/16, 4+5/16), standard 8x, on a 10x9 canvas. Every sample "
     "inside the fan's outline is covered by exactly one triangle (each consistent tie rule gives "
     "shared-edge samples to one side), so the partial coverages of the pixels around the centre, "
     "where all eight triangles meet, sum to exactly the union's coverage and the total area is the "
     "area of the octagon. Overlaps or cracks between the triangles show up as resolved values above "
     "1 or below the union. %s" % BOUNDS_NOTE,
     10, 9, [tri(FAN_C, FAN_R[i], FAN_R[(i + 1) % 8]) for i in range(8)], aa=AA(8))

# --- 3. Standard-pattern probes ----------------------------------------------

for n in (1, 2, 4, 8, 16):
    h = F(1, 32)
    prims = []
    for i, (ox, oy) in enumerate(STANDARD[n]):
        cx, cy = F(i) + ox, F(1) + oy
        prims += rect_tris(cx - h, cy - h, cx + h, cy + h)
    case(AA_DIR, "probe_standard%d" % n,
         "Probes of the standard %dx sample positions: pixel i of row 1 holds a 1/16 px square (two "
         "triangles, half-size 1/32) centred on the standard location of sample i, so each square "
         "covers exactly that one sample (its centre lies on the squares' shared diagonal, which "
         "gives it to exactly one triangle) and no other: the %d samples covered prove that the "
         "pattern's positions are Vulkan's, in Vulkan's order, since sample slot i must be the one "
         "covered in pixel i.%s %s"
         % (n, n, " The 16x pattern puts two samples on the pixel border, (0, 0.5) and (0.0625, 0): "
            "their probes reach into the neighbouring pixels, where they cover no sample." if n == 16
            else "", PROBE_NOTE),
         max(n, 1), 3, prims, aa=AA(n), max_error="probe", rms="probe",
         checks=[lambda s, n=n: s["covered"] == n and all(
             s["counts"][(1 * s["W"] + i) * n + i] == 1 for i in range(n))])

# Tie probes at the 16x border samples: squares with a sample exactly on their
# edge or corner.
SIDE = F(1, 16)
prims = []
for i, (ox, oy) in enumerate(STANDARD[16]):
    sx, sy = F(i) + ox, F(1) + oy
    # Sample at the square's top-left corner: owned (top and left edges).
    prims += rect_tris(sx, sy, sx + SIDE, sy + SIDE)
case(AA_DIR, "probe_standard16_top_left_corners",
     "Each pixel i of row 1 holds a 1/16 px square whose top-left corner is exactly standard 16x "
     "sample i, so every sample lies on a top and a left edge at once (and on the diagonal's end): "
     "under top-left each is covered once, 16 in all, including the border samples at (0, 0.5) and "
     "(0.0625, 0). A rasterizer that tests samples at the wrong positions, or breaks ties at sample "
     "positions differently from pixel centres, fails. %s" % PROBE_NOTE,
     16, 3, prims, aa=AA(16), max_error="probe", rms="probe",
     checks=[lambda s: s["covered"] == 16])
prims = []
for i, (ox, oy) in enumerate(STANDARD[16]):
    sx, sy = F(i) + ox, F(1) + oy
    prims += rect_tris(sx - SIDE, sy - SIDE, sx, sy)
case(AA_DIR, "probe_standard16_bottom_right_corners",
     "The mirror of probe_standard16_top_left_corners: each 1/16 px square ends at standard 16x "
     "sample i (its bottom-right corner), so each sample lies on a bottom and a right edge and "
     "top-left covers none of them: 0 samples, though each pixel has a 1/256 px^2 square. A "
     "rasterizer with closed edges, or with the samples half a lattice step off, covers some. "
     + PROBE_NOTE,
     16, 3, prims, aa=AA(16), max_error="probe", rms="probe",
     checks=[lambda s: s["covered"] == 0])

# Edge swept across a pixel in 32 steps: pixel i holds [i, i + (i+1)/32] x [0, 1].
for n in (4, 16):
    prims = []
    for i in range(32):
        prims += rect_tris(i, 0, F(i) + F(i + 1, 32), 1)
    case(AA_DIR, "sweep_vertical_edge_32_standard%d" % n,
         "A vertical edge swept across one pixel in 32 steps of 1/32 px: pixel i holds the rectangle "
         "[i, i + (i+1)/32] x [0, 1], so its exact coverage is (i+1)/32 and the resolved values "
         "trace the pattern's response curve, a staircase with one step per distinct sample column "
         "(%d of them for standard %dx). Edges at a multiple of 1/16 run through sample columns, "
         "where the right edge does not own them. %s" % (n, n, BOUNDS_NOTE),
         32, 1, prims, aa=AA(n))
    prims = []
    for i in range(32):
        x = 2 * i
        x0 = F(x) + F(i, 32)
        # A sheared edge (dx/dy = 1/4, leaning right) from (x0, 0) to (x0 + 1/4, 1).
        prims.append(poly([(x, 0), (x0, 0), (x0 + F(1, 4), 1), (x, 1)]))
    case(AA_DIR, "sweep_slanted_edge_32_standard%d" % n,
         "A slanted edge (dx/dy = 1/4, 14 degrees from vertical) swept across one pixel in 32 steps: "
         "pixel 2i holds the quadrilateral (2i,0) (2i+i/32,0) (2i+i/32+1/4,1) (2i,1), one polygon, "
         "whose area is i/32 + 1/8; from i = 25 on, its corner spills into the empty pixel 2i+1. "
         "The slant moves samples across the edge one at a time, so the staircase is finer than the "
         "vertical sweep's. %s" % BOUNDS_NOTE,
         64, 1, prims, aa=AA(n))

# --- 4. Parallelogram lines under antialiasing ---------------------------------

LINES = [("w1_slope_1_3", (1, 2), (19, 8), 1, "width 1, slope 1/3"),
         ("w2_5_steep", (3, 1), (6, 15), F(5, 2), "width 2.5, y-major, dx/dy = 3/14"),
         ("w0_25_near_horizontal", (1, F(3) + F(1, 16)), (19, F(3) + F(3, 16)), F(1, 4),
          "width 1/4, slope 1/144 (0.4 degrees)")]
for tag, a, b, w, what in LINES:
    rms, weak = along_edge(16, b[0] - a[0], b[1] - a[1])
    case(AA_DIR, "line_parallelogram_%s_standard16" % tag,
         "A parallelogram line (SPEC 4.4), %s, standard 16x: its ends are along the minor axis and "
         "its width is measured along it, so its area is exactly width x major length and every "
         "corner is rational. A rasterizer that draws it as a rectangle (perpendicular ends, width "
         "measured across the line) gets a different area and different samples.%s %s"
         % (what, weak, BOUNDS_NOTE),
         20, 16, [ParallelogramLine(a, b, w)], aa=AA(16), rms=rms)

# --- 5. Sample-count sweeps ----------------------------------------------------

SWEEP_TRI = [(F(1) + F(3, 8), F(2) + F(1, 16)), (F(15) - F(1, 32), F(5) + F(9, 32)),
             (F(5) + F(7, 16), F(15) - F(1, 8))]
SWEEP_PRIMS = [tri(*SWEEP_TRI), tri((F(9) + F(1, 4), F(10)), (F(14) + F(5, 8), F(9) + F(3, 4)),
                                    (F(12), F(15) + F(1, 2)))]
SWEEP_GEOM = ("two triangles on a 16x16 canvas with edges at slopes from 1/5 to 40 (the first "
              "(1.375,2.0625) (14.96875,5.28125) (5.4375,14.875), the second (9.25,10) "
              "(14.625,9.75) (12,15.5))")
for pattern, counts in (("grid", (1, 4, 16, 64, 256)), ("stratified", (1, 4, 16, 64, 256)),
                        ("random", (1, 4, 16, 64, 256)), ("n-rooks", (1, 4, 16, 64, 256)),
                        ("standard", (1, 2, 4, 8, 16))):
    for n in counts:
        aa = AA(n, pattern)
        if pattern in ("stratified", "random", "n-rooks"):
            aa["seed"] = 1
        # Random samples, and n-rooks (stratified along the axes only: along a slanted
        # edge it samples like random, Shirley 1991), meet the Monte Carlo bound, not
        # piglit's; so does one seeded sample, which is one random offset.
        mc = pattern in ("random", "n-rooks") or (pattern == "stratified" and n == 1)
        case(AA_DIR, "count_%s_%d" % (pattern, n),
             "Sample-count sweep, %s pattern, N = %d: %s. The same geometry at every N of every "
             "pattern, so the report shows how each pattern's error falls as N grows (about N^-3/4 "
             "for stratified and grid along straight edges, N^-1/2 for random; n-rooks is "
             "stratified only along the axes, so along slanted edges it behaves like random). %s"
             % (pattern, n, SWEEP_GEOM, MC_NOTE if mc else BOUNDS_NOTE),
             16, 16, SWEEP_PRIMS, aa=aa, rms="monte-carlo" if mc else "piglit")

# --- 6. Polygons ---------------------------------------------------------------

# Pentagram: the 5 points of a regular pentagon rounded to 1/256, joined in
# star order. The centre pentagon has winding number 2.
def pentagon(cx, cy, r, k=5, phase=-math.pi / 2):
    pts = []
    for i in range(k):
        ang = phase + 2 * math.pi * i / k
        pts.append((F(round((cx + r * math.cos(ang)) * 256), 256),
                    F(round((cy + r * math.sin(ang)) * 256), 256)))
    return pts


PENTA = pentagon(8, F(17, 2), 7.5)
STAR = [PENTA[(2 * i) % 5] for i in range(5)]


for fill in ("even-odd", "nonzero"):
    centre = "stays empty (winding number 2 is even)" if fill == "even-odd" else \
        "is filled (winding number 2 is non-zero)"
    pr = poly(STAR, fill)
    case(POLY_DIR, "pentagram_%s" % fill.replace("-", "_"),
         "A pentagram (the regular pentagon of radius 7.5 around (8, 8.5), its corners rounded to "
         "1/256, joined in star order) under %s: the five points have winding number 1 and the "
         "centre pentagon 2, so the centre %s. Pixel-centre samples only. A rasterizer that treats "
         "every polygon as nonzero (or as even-odd) gets the centre wrong." % (fill, centre),
         16, 16, [pr], fill_rule="top-left",
         checks=[lambda s, f=fill: (s["counts"][8 * 16 + 8] > 0) == (f == "nonzero")])
    case(POLY_DIR, "pentagram_%s_aa_standard16" % fill.replace("-", "_"),
         "The pentagram of pentagram_%s (winding 2 in the centre pentagon) under %s, standard 16x: "
         "the exact area is the five points%s, and along the inner pentagon's sides, where the "
         "edges cross, pixels hold pieces of regions of different winding numbers. %s"
         % (fill.replace("-", "_"), fill, " only" if fill == "even-odd" else " plus the pentagon",
            BOUNDS_NOTE),
         16, 16, [pr], aa=AA(16))

# Square with a hole: two contours.
OUT = [(1, 1), (13, 1), (13, 13), (1, 13)]
HOLE_REV = [(F(4) + F(1, 4), F(4) + F(1, 8)), (F(4) + F(1, 4), F(10)), (F(9) + F(3, 4), F(10)),
            (F(9) + F(3, 4), F(4) + F(1, 8))]
HOLE_SAME = list(reversed(HOLE_REV))
for tag, hole, fill, note in (
        ("hole_reversed_nonzero", HOLE_REV, "nonzero",
         "the inner contour runs the other way, so the hole has winding number 0 and stays empty"),
        ("hole_same_nonzero", HOLE_SAME, "nonzero",
         "both contours run the same way, so the 'hole' has winding number 2 and nonzero fills it"),
        ("hole_same_even_odd", HOLE_SAME, "even-odd",
         "both contours run the same way (winding 2 inside), and even-odd leaves the hole empty")):
    pr = contours([OUT, hole], fill)
    case(POLY_DIR, tag,
         "A 12x12 square with a 5.5 x 5.875 inner contour, %s, fill %s: %s. Pixel-centre samples. "
         "A rasterizer that ignores the second contour, or the direction of contours, fails."
         % ("two contours", fill, note),
         14, 14, [pr],
         checks=[lambda s, h=(fill == "nonzero" and hole is HOLE_SAME):
                 (s["counts"][7 * 14 + 7] > 0) == h])
    case(POLY_DIR, tag + "_aa_standard8",
         "The polygon of %s (%s) under standard 8x: the hole's sides sit at quarter and eighth "
         "pixel offsets, so its border pixels are partial, and the exact area is the outer square "
         "minus the hole%s. %s" % (tag, note, " (here the hole is filled: the area is the whole square)"
                                   if (fill == "nonzero" and hole is HOLE_SAME) else "", BOUNDS_NOTE),
         14, 14, [pr], aa=AA(8))

# Concave polygons: an arrow and a comb.
ARROW = [(1, 6), (8, 1), (8, 4), (15, 4), (15, 8), (8, 8), (8, 11)]
ARROW = [(F(x) + F(1, 16), F(y) + F(3, 32)) for x, y in ARROW]
COMB = [(1, 1), (14, 1), (14, 13), (12, 13), (12, 4), (10, 4), (10, 13), (8, 13), (8, 4), (6, 4),
        (6, 13), (4, 13), (4, 4), (2, 4), (2, 13), (1, 13)]
COMB = [(F(x) + F(1, 8) * (i % 3), F(y) + F(1, 5)) for i, (x, y) in enumerate(COMB)]
for tag, pts, what in (("arrow", ARROW, "an arrow (one reflex vertex on each side of the shaft)"),
                       ("comb", COMB, "a comb with four teeth (eight reflex vertices); its vertices "
                                      "sit 0, 1/8 and 1/4 px off the lattice and 1/5 px down "
                                      "(snapped to 51/256)")):
    pr = poly(pts)
    case(POLY_DIR, "concave_%s" % tag,
         "A concave polygon, %s, nonzero, pixel-centre samples. A scanline crosses it four or more "
         "times; a rasterizer that fills between the first and last crossing (a convex-only filler) "
         "fills the notches." % what,
         16, 15, [pr])
    case(POLY_DIR, "concave_%s_aa_standard16" % tag,
         "The polygon of concave_%s under standard 16x: the exact area of a concave polygon is "
         "the shoelace area, and the checker also finds it by slabs. %s" % (tag, BOUNDS_NOTE),
         16, 15, [pr], aa=AA(16))

# Self-intersecting: bow-tie, and a contour that winds twice around a region.
BOW = [(1, 2), (13, 11), (13, 2), (1, 11)]
BOW = [(F(x) + F(1, 8), F(y) + F(1, 4)) for x, y in BOW]
for fill in ("nonzero", "even-odd"):
    case(POLY_DIR, "bowtie_%s" % fill.replace("-", "_"),
         "A bow-tie: the contour (1.125,2.25) (13.125,11.25) (13.125,2.25) (1.125,11.25) crosses "
         "itself at (7.125, 6.75); its two lobes have winding numbers +1 and -1, so %s fills both. "
         "A rasterizer that takes the sign of the winding number as the fill (fills positive "
         "winding only), or that fills between the first and last crossing of each row, fails."
         % fill,
         15, 13, [poly(BOW, fill)])
case(POLY_DIR, "bowtie_aa_standard16",
     "The bow-tie of bowtie_nonzero under standard 16x: two triangular lobes of opposite winding "
     "meeting at (7.125, 6.75), inside pixel (7, 6), which holds four edges at once. %s"
     % BOUNDS_NOTE,
     15, 13, [poly(BOW)], aa=AA(16))

# A figure eight that winds twice: an outer loop, then an inner loop in the
# same direction, joined by a shared bridge edge.
EIGHT = [(2, 2), (14, 2), (14, 14), (2, 14), (2, 5), (11, 5), (11, 11), (5, 11), (5, 2)]
EIGHT = [(F(x) + F(1, 32), F(y) + F(1, 64)) for x, y in EIGHT]
for fill in ("nonzero", "even-odd"):
    case(POLY_DIR, "double_loop_%s" % fill.replace("-", "_"),
         "One contour that runs around the square (2,2)-(14,14) and then, crossing its own path, "
         "around the inner square (5,5)-(11,11) in the same direction: the inner square has "
         "winding number 2 (%s), the bridge pieces 1 or 2. A rasterizer that counts crossings "
         "without their direction gets even-odd right and nonzero wrong." %
         ("filled under nonzero" if fill == "nonzero" else "empty under even-odd"),
         16, 16, [poly(EIGHT, fill)],
         checks=[lambda s, f=fill: (s["counts"][8 * 16 + 8] > 0) == (f == "nonzero")])
case(POLY_DIR, "double_loop_even_odd_aa_grid16",
     "The contour of double_loop_even_odd (inner square winding 2, empty) under a 4x4 grid "
     "pattern: every edge sits 1/32 or 1/64 px off the pixel lattice, so the grid's rows and "
     "columns of samples lie at 1/8, 3/8, ... and the border pixels resolve to a whole number of "
     "sample rows. %s" % BOUNDS_NOTE,
     16, 16, [poly(EIGHT, "even-odd")], aa=AA(16, "grid"))

# Polygon and its triangulation: the same samples.
QUAD = [(F(2) + F(1, 2), F(1) + F(1, 2)), (F(12) + F(1, 2), F(3) + F(1, 2)),
        (F(10) + F(1, 2), F(12) + F(1, 2)), (F(1) + F(1, 2), F(9) + F(1, 2))]
case(POLY_DIR, "quad_vertices_on_centres",
     "A convex quadrilateral with every vertex on a pixel centre and edges that run through "
     "several centres (slopes 1/5, -9/2, 3/9, 8/1): as one polygon it covers the same samples as "
     "its triangulation (SPEC 14.1), which quad_vertices_on_centres_triangulated draws; both give "
     "the same samples_covered.",
     14, 14, [poly(QUAD)])
case(POLY_DIR, "quad_vertices_on_centres_triangulated",
     "quad_vertices_on_centres drawn as two triangles sharing the diagonal (2.5,1.5)-(10.5,12.5): "
     "the same samples as the polygon, each covered once.",
     14, 14, [tri(QUAD[0], QUAD[1], QUAD[2]), tri(QUAD[0], QUAD[2], QUAD[3])])

# Polygon under the other tie rules, with vertices and crossings on centres.
STAR_C = [(F(1) + F(1, 2), F(5) + F(1, 2)), (F(13) + F(1, 2), F(5) + F(1, 2)),
          (F(3) + F(1, 2), F(13) + F(1, 2)), (F(7) + F(1, 2), F(0) + F(1, 2)),
          (F(11) + F(1, 2), F(13) + F(1, 2))]
for rule in ("top-left", "bottom-right", "top-right", "bottom-left"):
    case(POLY_DIR, "star_on_centres_%s" % rule.replace("-", "_"),
         "A five-pointed star, even-odd, whose vertices all lie on pixel centres and whose top "
         "edge runs along sample row 5, fill rule %s: the horizontal edge and the samples on "
         "the slanted edges go to the side the nudge of SPEC 14.1 points into, so the four rules "
         "cover different samples, and a rasterizer that nudges the wrong way, or decides "
         "samples at crossings without the nudge, fails." % rule,
         15, 15, [poly(STAR_C, "even-odd")], fill_rule=rule)

# Two polygons sharing an edge: watertight under antialiasing.
SHARED = [(F(1) + F(1, 4), F(1)), (F(9) + F(1, 8), F(2) + F(1, 2)), (F(8) - F(1, 8), F(12))]
case(POLY_DIR, "shared_edge_polygons_aa_standard4",
     "Two concave polygons share the broken edge (1.25,1) (9.125,2.5) (7.875,12): one lies left of "
     "it, the other right, and their union is the 14x13 canvas's rectangle (1,1)-(13,12) minus "
     "nothing. Every sample of the rectangle is covered once, every pixel wholly inside resolves to "
     "1, and the areas of the two sum to the rectangle's. %s" % BOUNDS_NOTE,
     14, 13, [poly([(1, 1), SHARED[0], SHARED[1], SHARED[2], (1, 12)]),
              poly([SHARED[0], (13, 1), (13, 12), SHARED[2], SHARED[1]])], aa=AA(4))

# Many vertices: a 64-gon circle.
CIRCLE = pentagon(F(16), F(16), 13.3, k=64, phase=0.1)
case(POLY_DIR, "circle_64_aa_grid64",
     "A 64-vertex circle of radius 13.3 around (16, 16), its vertices rounded to 1/256, under an "
     "8x8 grid on a 32x32 canvas: edges at 64 angles, each 1.3 px long, so most border pixels hold "
     "two edges and a vertex. %s" % BOUNDS_NOTE,
     32, 32, [poly(CIRCLE)], aa=AA(64, "grid"))
case(POLY_DIR, "circle_64_aa_stratified256",
     "The circle of circle_64_aa_grid64 under stratified 256 (seed 3). %s" % BOUNDS_NOTE,
     32, 32, [poly(CIRCLE)], aa=AA(256, "stratified", seed=3))


# ---------------------------------------------------------------------------

def main():
    summary = {}
    for d in (AA_DIR, POLY_DIR):
        os.makedirs(d, exist_ok=True)
        for f in os.listdir(d):
            if f.endswith(".json"):
                os.remove(os.path.join(d, f))
    names = set()
    for c in CASES:
        assert c["name"] not in names, c["name"]
        names.add(c["name"])
        expect, stats = evaluate(c)
        stats["W"] = c["width"]
        for check in c["checks"]:
            assert check(stats), "check failed: %s" % c["name"]
        expect.update(c["extra_expect"])
        path = os.path.join(c["folder"], c["name"] + ".json")
        with open(path, "w") as f:
            f.write(render(c, expect))
        folder = os.path.basename(c["folder"])
        summary[folder] = summary.get(folder, 0) + 1
        if "-v" in sys.argv:
            print("%-45s covered %6d area %-14s maxerr %.4f/%.4f rms %.4f/%.4f" % (
                c["name"], stats["covered"], expect.get("area", "-"),
                float(stats.get("max_err", 0)), float(expect.get("max_coverage_error", 0)),
                stats.get("rms", 0), float(expect.get("max_coverage_rms", 0))))
    print("wrote", ", ".join("%d cases in cases/%s" % (n, k) for k, n in sorted(summary.items())))


if __name__ == "__main__":
    main()
