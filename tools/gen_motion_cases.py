#!/usr/bin/env python3
"""Writes the motion-blur cases: cases/motion/*.json (SPEC.md section 15).

Python 3 standard library only. Every expectation is computed here, by an
exact checker written from SPEC.md alone (no call into rastercheck, no code
shared with tools/gen_aa_cases.py):

- Exact time coverage (section 15.2), per spatial sample q and primitive P.
  With vertices v(tau) = snap(from) + tau*(snap(to) - snap(from)), every
  quantity the static rules look at is a polynomial of degree <= 2 in tau:
  the twice-signed area, each edge function at q, each edge's dx and dy (the
  fill rule's ownership of a sample riding on an edge), and for a
  parallelogram line dx - dy and dx + dy (its major axis) and the edge
  functions of both of its possible parallelograms. Their roots in
  (open, close) are the only instants at which "P covers q" can change. A
  rational root is kept as a Fraction; an irrational one as an exact
  quadratic surd u + v*sqrt(s), compared and ordered exactly (by intervals
  from integer square roots, refined until they separate, so the root
  values carry hundreds of correct digits; equal roots are recognised by exact
  surd arithmetic, so two edges that vanish at the same irrational instant
  make one event). Between consecutive events, coverage is decided by the
  exact predicate (section 3 with its epsilon nudge and cull; section 4.4
  for lines) at a rational instant strictly inside, and c_P(q) is the sum of
  the covered lengths: an exact surd. A pixel's value is the mean over its
  spatial samples of the sum over primitives, still exact; pins are written
  exactly when rational and to 15 significant digits otherwise.
- Cross-checks, asserted before anything is written:
  * a second, separately written per-instant predicate (a triangle by the
    crossing-count winding number of the nudged sample, section 14.1; a
    line by the inequalities of section 4.4 with the nudge) must agree with
    the first at every instant tested, and with the exact coverage's
    intervals at every instant that is not an event;
  * a brute-force Riemann sum of the second predicate at K midpoint instants
    (K = 4096, or 1024 with antialiasing, at every spatial sample of the
    pinned pixels; K = 512 at about 150 other samples per case) must lie
    within (events + 1)/K of the exact value (a midpoint sum of an indicator
    errs by at most one cell per event), and agree instant by instant with
    the exact coverage's intervals;
  * per case checks of the author's intent (a root is double, a vertex
    crosses a sample at 3/8, the three cull variants sum to the unculled
    case, a two-triangle mesh's time coverages sum exactly to its union's...).
- The sample method's estimate (section 15.3): the instants of every pixel
  (SplitMix64 seeded per pixel, the four time patterns,
  tau = open + (close - open)*u/2^16) and the spatial offsets (section 14.2),
  each test decided by the second predicate; static primitives drawn once.

Bounds written (section 15.4), per case (bounds(), rounded up to 4 decimals):

- max_time_rms = max(1.25 R, 1.5 sigma). R is the RMS over moving pixels of
  the sample method above with the case's own instants: what a correct sample
  method gets exactly, and 1.25 leaves room for one whose instants differ by
  rounding. sigma is the RMS over the same pixels of the standard deviation
  that N independent uniform instants per spatial sample give, computed from
  the exact coverages: sqrt(sum over samples and primitives of
  c(1 - c)/(M^2 N)) per pixel. As c(1 - c) <= 1/4, 1.5 sigma is at most SPEC's
  default 0.75 (M N)^-1/2 (asserted), and it is tighter where coverages are
  far from 1/2: in long_motion_112px_stratified16 every pixel is covered for
  a few percent of the shutter, and the default would let a method that
  ignores motion pass.
- max_time_error = max(1.25 X, 2 (M N)^-1/2), X that method's largest |error|;
  2 (M N)^-1/2 lets one stratum in sqrt(M N) flip.

The generator asserts that the sample method meets both; that a method that
ignores motion (draws every moving primitive at its shutter-open position)
fails max_time_rms and, unless the case says why not, max_time_error too; and
that one that draws the scene at mid-shutter fails at least one of them when
M N >= 16 (with fewer tests, the estimate is about as noisy as that guess).
--mutants shows that deliberately wrong variants of the checker trip these
checks.

Usage: python3 tools/gen_motion_cases.py [-v] [--map] [--only TEXT]   (run from anywhere)
  -v           one line per case: moving pixels, the sample method's and the
               motion-ignoring method's RMS and max error against the bounds,
               and the pins with 40 digits
  --map        print each moving case's exact time coverage, pixel by pixel
  --only TEXT  evaluate only the cases whose name contains TEXT; writes nothing
  --mutants    run deliberately wrong variants of the checker (MUTANTS) and
               exit non-zero unless each one trips a check; writes nothing
Exits non-zero (an AssertionError) when any check fails; writes nothing then.
"""

import math
import os
import sys
from fractions import Fraction as F
from functools import cmp_to_key

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exactjson import exact, js  # noqa: E402
import gen_aa_cases as aac  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT_DIR = os.path.join(ROOT, "cases", "motion")

# ---------------------------------------------------------------------------
# Spatial offsets (section 14.2) come from gen_aa_cases.py's port of the
# patterns, with its SplitMix64; the instants (section 15.3) are written here.

TIME_BITS = 16
TIME_ONE = 1 << TIME_BITS
PIXEL_MIX = 0xD6E8FEB86659FD93


def spatial_offsets(aa):
    """The M offsets of effects.antialias in slot order, or the pixel centre."""
    if aa is None:
        return [(F(1, 2), F(1, 2))]
    return aac.offsets(aa)


def pixel_us(mb, pixel, M):
    """The u (in 2^-16 of the shutter) of the M*N tests of pixel y*W + x;
    slot s*N + k is instant k of spatial sample s."""
    N = mb["samples"]
    T = M * N
    rng = aac.SplitMix64(mb.get("seed", 0) ^ (((pixel + 1) * PIXEL_MIX) & aac.MASK64))

    def draw():
        return rng.draw(TIME_BITS)

    pattern = mb.get("pattern", "stratified")
    if pattern == "random":
        return [draw() for _ in range(T)]
    if pattern == "stratified":
        return [((j % N) * TIME_ONE + draw()) // N for j in range(T)]
    v = [(i * TIME_ONE + draw()) // T for i in range(T)]
    if pattern == "jittered-xy-t":
        return v
    if pattern == "stratified-shuffled":
        perm = list(range(T))
        for i in range(T - 1, 0, -1):
            j = rng.next() % (i + 1)
            perm[i], perm[j] = perm[j], perm[i]
        return [v[perm[j]] for j in range(T)]
    raise ValueError(pattern)


# ---------------------------------------------------------------------------
# Exact quadratic surds: sums of rational multiples of square roots.

SMALL_PRIMES = [p for p in range(2, 1000) if all(p % d for d in range(2, math.isqrt(p) + 1))]


def is_square(n):
    return n >= 0 and math.isqrt(n) ** 2 == n


def square_split(n):
    """(k, s) with n = k^2 * s, small square factors moved into k."""
    k = 1
    for p in SMALL_PRIMES:
        pp = p * p
        if pp > n:
            break
        while n % pp == 0:
            n //= pp
            k *= p
    return k, n


class Surd:
    """sum of c_s * sqrt(s) over keys s (s = 1: the rational part). Two keys
    never have a rational ratio of roots (s*s' is never a square), so the
    square roots are linearly independent over Q (Besicovitch) and a surd is
    zero exactly when every coefficient is."""

    __slots__ = ("t",)

    def __init__(self, t=None):
        self.t = {k: v for k, v in (t or {}).items() if v != 0}

    @staticmethod
    def rat(q):
        return Surd({1: F(q)})

    def __add__(self, o):
        if not isinstance(o, Surd):
            o = Surd.rat(o)
        t = dict(self.t)
        for s, c in o.t.items():
            for k in t:
                if k == s:
                    t[k] += c
                    break
                if k != 1 and s != 1 and is_square(k * s):
                    # c*sqrt(s) = c*sqrt(k*s)/k * sqrt(k)
                    t[k] += c * F(math.isqrt(k * s), k)
                    break
            else:
                t[s] = c
        return Surd(t)

    def __neg__(self):
        return Surd({k: -v for k, v in self.t.items()})

    def __sub__(self, o):
        return self + (-(o if isinstance(o, Surd) else Surd.rat(o)))

    def scale(self, q):
        return Surd({k: v * q for k, v in self.t.items()})

    def rational(self):
        """The value if rational, else None."""
        if any(k != 1 for k in self.t):
            return None
        return self.t.get(1, F(0))

    def interval(self, bits):
        """[lo, hi] Fractions around the value, each root within 2^-bits."""
        lo = hi = F(0)
        for s, c in self.t.items():
            if s == 1:
                lo += c
                hi += c
                continue
            r = math.isqrt(s << (2 * bits))
            a, b = F(r, 1 << bits), F(r + 1, 1 << bits)
            if c > 0:
                lo, hi = lo + c * a, hi + c * b
            else:
                lo, hi = lo + c * b, hi + c * a
        return lo, hi

    def sign(self):
        q = self.rational()
        if q is not None:
            return (q > 0) - (q < 0)
        bits = 64
        while True:
            lo, hi = self.interval(bits)
            if lo > 0:
                return 1
            if hi < 0:
                return -1
            bits *= 2
            assert bits <= 1 << 14, "a non-zero surd did not separate from 0"

    def approx(self, bits=200):
        lo, hi = self.interval(bits)
        return (lo + hi) / 2

    def __float__(self):
        return float(self.approx(80))


def surd_cmp(x, y):
    return (x - y).sign()


def between(x, y):
    """A rational strictly between surds x < y."""
    a, b = x.rational(), y.rational()
    if a is not None and b is not None:
        return (a + b) / 2
    bits = 64
    while True:
        hx = a if a is not None else x.interval(bits)[1]
        ly = b if b is not None else y.interval(bits)[0]
        if hx < ly:
            return (hx + ly) / 2
        bits *= 2
        assert bits <= 1 << 14


# ---------------------------------------------------------------------------
# Polynomials in tau of degree <= 2, as (c0, c1, c2) of Fractions.

ZERO = F(0)


def const(a):
    return (F(a), ZERO, ZERO)


def padd(p, q):
    return (p[0] + q[0], p[1] + q[1], p[2] + q[2])


def psub(p, q):
    return (p[0] - q[0], p[1] - q[1], p[2] - q[2])


def pmul(p, q):
    assert p[2] == 0 and q[2] == 0, "only linear times linear"
    return (p[0] * q[0], p[0] * q[1] + p[1] * q[0], p[1] * q[1])


def pcross(ax, ay, bx, by):
    return psub(pmul(ax, by), pmul(ay, bx))


def roots_in(poly, lo, hi):
    """Roots of poly strictly inside (lo, hi), as surds; a double root once.
    An identically zero polynomial has none (its sign never changes)."""
    den = 1
    for c in poly:
        den = den * c.denominator // math.gcd(den, c.denominator)
    c0, c1, c2 = (int(c * den) for c in poly)
    if c2 == 0:
        if c1 == 0:
            return []
        cands = [Surd.rat(F(-c0, c1))]
    else:
        disc = c1 * c1 - 4 * c2 * c0
        if disc < 0:
            return []
        k = math.isqrt(disc)
        if k == 0:
            cands = [Surd.rat(F(-c1, 2 * c2))]
        elif k * k == disc:
            cands = [Surd.rat(F(-c1 - k, 2 * c2)), Surd.rat(F(-c1 + k, 2 * c2))]
        else:
            kk, s = square_split(disc)
            assert not is_square(s)
            cands = [Surd({1: F(-c1, 2 * c2), s: F(sg * kk, 2 * c2)}) for sg in (-1, 1)]
    lo_s, hi_s = Surd.rat(lo), Surd.rat(hi)
    return [r for r in cands if surd_cmp(lo_s, r) < 0 and surd_cmp(r, hi_s) < 0]


def poly_double_root(poly):
    """The double root of a quadratic with zero discriminant, else None."""
    c0, c1, c2 = poly
    if c2 != 0 and c1 * c1 - 4 * c2 * c0 == 0:
        return -c1 / (2 * c2)
    return None


# ---------------------------------------------------------------------------
# The per-instant predicates. Two independent formulations of the same rule;
# each works on Fractions or on integers (all coordinates scaled by one
# positive power of two: every test below is homogeneous, so its sign is
# unchanged).

NUDGE = {"top-left": (1, 1), "bottom-right": (-1, -1), "top-right": (-1, 1), "bottom-left": (1, -1)}


def nudged_positive(f, gx, gy, rule):
    """Whether the linear function with value f and gradient (gx, gy) at the
    sample is positive at the sample nudged as the fill rule says
    (x + nx*eps, y + ny*eps^2), eps infinitesimal."""
    if f != 0:
        return f > 0
    nx, ny = NUDGE[rule]
    v = gx * nx
    if v != 0:
        return v > 0
    return gy * ny > 0


def area2(pts):
    """Twice the signed area, positive for clockwise on screen (y down)."""
    n = len(pts)
    return sum(pts[i][0] * pts[(i + 1) % n][1] - pts[(i + 1) % n][0] * pts[i][1] for i in range(n))


def convex_main(pts, q, rule):
    """Section 3 by edge functions: the sample is inside every edge, and an
    edge it lies on owns it (the nudge)."""
    A = area2(pts)
    if A == 0:
        return False
    sg = 1 if A > 0 else -1
    qx, qy = q
    n = len(pts)
    for i in range(n):
        (ax, ay), (bx, by) = pts[i], pts[(i + 1) % n]
        e = ((bx - ax) * (qy - ay) - (by - ay) * (qx - ax)) * sg
        if e == 0:
            assert (ax, ay) != (bx, by)
        if not nudged_positive(e, -(by - ay) * sg, (bx - ax) * sg, rule):
            return False
    return True


def culled(A, cull):
    return (cull == "cw" and A > 0) or (cull == "ccw" and A < 0)


def tri_main(pts, q, rule, cull):
    A = area2(pts)
    if A == 0 or culled(A, cull):
        return False
    return convex_main(pts, q, rule)


def line_quads(p0, p1, h):
    """The parallelogram of section 4.4 as a quadrilateral, for the major
    axis of p1 - p0, or None for a zero-length line."""
    (x0, y0), (x1, y1) = p0, p1
    dx, dy = x1 - x0, y1 - y0
    if dx == 0 and dy == 0:
        return None
    if abs(dx) >= abs(dy):
        return [(x0, y0 - h), (x1, y1 - h), (x1, y1 + h), (x0, y0 + h)]
    return [(x0 - h, y0), (x1 - h, y1), (x1 + h, y1), (x0 + h, y0)]


def line_main(p0, p1, h, q, rule):
    quad = line_quads(p0, p1, h)
    return quad is not None and convex_main(quad, q, rule)


def winding_nudged(pts, q, rule):
    """Section 14.1: the winding number of the nudged sample, by counting
    directed crossings of the nudged horizontal ray to +x."""
    top = rule in ("top-left", "top-right")
    left = rule in ("top-left", "bottom-left")
    qx, qy = q
    w = 0
    n = len(pts)
    for i in range(n):
        (ax, ay), (bx, by) = pts[i], pts[(i + 1) % n]
        if ay == by:
            continue
        lo, hi = min(ay, by), max(ay, by)
        if not ((lo <= qy < hi) if top else (lo < qy <= hi)):
            continue
        # sign(x_c - qx), x_c the crossing's x at height qy, without dividing.
        num = (ax - qx) * (by - ay) + (qy - ay) * (bx - ax)
        s = num if by > ay else -num
        if (s > 0) if left else (s >= 0):
            w += 1 if by > ay else -1
    return w


def tri_alt(pts, q, rule, cull):
    (x0, y0), (x1, y1), (x2, y2) = pts
    A = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)
    if A == 0 or culled(A, cull):
        return False
    return winding_nudged(pts, q, rule) != 0


def line_alt(p0, p1, h, q, rule):
    """Section 4.4 as written: between the ends along the major axis, and
    within width/2 of the line along the minor axis (scaled by |d_major| to
    stay polynomial); a border sample by the nudge."""
    (x0, y0), (x1, y1) = p0, p1
    qx, qy = q
    dx, dy = x1 - x0, y1 - y0
    if dx == 0 and dy == 0:
        return False
    if abs(dx) >= abs(dy):
        s, m = (1 if dx > 0 else -1), abs(dx)
        g = (qy - y0) * m - (qx - x0) * dy * s
        fs = [((qx - x0) * s, s, 0), ((x1 - qx) * s, -s, 0),
              (h * m - g, dy * s, -m), (h * m + g, -dy * s, m)]
    else:
        s, m = (1 if dy > 0 else -1), abs(dy)
        g = (qx - x0) * m - (qy - y0) * dx * s
        fs = [((qy - y0) * s, 0, s), ((y1 - qy) * s, 0, -s),
              (h * m - g, -m, dx * s), (h * m + g, m, -dx * s)]
    return all(nudged_positive(f, gx, gy, rule) for f, gx, gy in fs)


def quad_alt(pts, q, rule):
    return area2(pts) != 0 and winding_nudged(pts, q, rule) != 0


# ---------------------------------------------------------------------------
# Primitives.

def snap(q, bits):
    s = 1 << bits
    return F(round(q * s), s)   # Fraction rounds half to even


def pow2_exp(q):
    d = F(q).denominator
    assert d & (d - 1) == 0, "not dyadic: %s" % q
    return d.bit_length() - 1


class V:
    """A vertex as written: its position at open, and at close when it
    moves (to None: the short static form)."""

    def __init__(self, frm, to=None):
        self.frm = (exact(frm[0]), exact(frm[1]))
        self.to = None if to is None else (exact(to[0]), exact(to[1]))

    def json(self):
        if self.to is None:
            return list(self.frm)
        return {"from": list(self.frm), "to": list(self.to)}

    def moves(self):
        return self.to is not None and self.to != self.frm


def as_v(v):
    return v if isinstance(v, V) else V(v)


def mv(a, b):
    return V(a, b)


class Prim:
    """A triangle, a parallelogram line, or (checks only) a convex quad."""

    def __init__(self, kind, verts, width=None):
        self.kind = kind
        self.verts = [as_v(v) for v in verts]
        self.h = None if width is None else exact(width) / 2
        self.width = width

    def json(self):
        if self.kind == "triangle":
            return {"triangle": [v.json() for v in self.verts]}
        assert self.kind == "line"
        return {"line": [v.json() for v in self.verts], "rule": "parallelogram",
                "width": exact(self.width)}

    def moves(self):
        return any(v.moves() for v in self.verts)

    def setup(self, bits):
        self.a = []
        self.d = []
        for v in self.verts:
            a = (snap(v.frm[0], bits), snap(v.frm[1], bits))
            b = a if v.to is None else (snap(v.to[0], bits), snap(v.to[1], bits))
            self.a.append(a)
            self.d.append((b[0] - a[0], b[1] - a[1]))
        pts = self.a + [(a[0] + d[0], a[1] + d[1]) for a, d in zip(self.a, self.d)]
        m = self.h or 0
        self.bbox = (min(p[0] for p in pts) - m, min(p[1] for p in pts) - m,
                     max(p[0] for p in pts) + m, max(p[1] for p in pts) + m)
        self.exp = max([pow2_exp(c) for p in self.a + self.d for c in p] +
                       [pow2_exp(self.h or 0)])

    def touches(self, q):
        x0, y0, x1, y1 = self.bbox
        return x0 <= q[0] <= x1 and y0 <= q[1] <= y1

    def at(self, tau):
        return [(a[0] + tau * d[0], a[1] + tau * d[1]) for a, d in zip(self.a, self.d)]

    def scale_to(self, E):
        """Keeps the snapped ends times 2^E as integers, for at_int."""
        def whole(v):
            v = F(v) * 2 ** E
            assert v.denominator == 1
            return v.numerator

        self.ints = [(whole(a[0]), whole(d[0]), whole(a[1]), whole(d[1]))
                     for a, d in zip(self.a, self.d)]
        self.h_int = None if self.h is None else whole(self.h)

    def at_int(self, n, t):
        """Positions at tau = n/2^t, times 2^(E + t), as integers."""
        return [((ax << t) + dx * n, (ay << t) + dy * n) for ax, dx, ay, dy in self.ints]

    def pred(self, which, pts, q, h, rule, cull):
        if self.kind == "triangle":
            return (tri_main if which == "main" else tri_alt)(pts, q, rule, cull)
        if self.kind == "line":
            return (line_main if which == "main" else line_alt)(pts[0], pts[1], h, q, rule)
        assert self.kind == "quad"
        return (convex_main if which == "main" else quad_alt)(pts, q, rule)

    def polys(self, q):
        """Every polynomial whose sign can change whether this covers q."""
        P = [((a[0], d[0], ZERO), (a[1], d[1], ZERO)) for a, d in zip(self.a, self.d)]
        Q = (const(q[0]), const(q[1]))
        extra = []
        if self.kind == "line":
            h = const(self.h)
            (x0, y0), (x1, y1) = P
            dx, dy = psub(x1, x0), psub(y1, y0)
            extra = [dx, dy, psub(dx, dy), padd(dx, dy)]
            polygons = [
                [(x0, psub(y0, h)), (x1, psub(y1, h)), (x1, padd(y1, h)), (x0, padd(y0, h))],
                [(psub(x0, h), y0), (psub(x1, h), y1), (padd(x1, h), y1), (padd(x0, h), y0)]]
        else:
            polygons = [P]
        out = list(extra)
        for pts in polygons:
            n = len(pts)
            area = const(0)
            for i in range(n):
                (ax, ay), (bx, by) = pts[i], pts[(i + 1) % n]
                area = padd(area, pcross(ax, ay, bx, by))
                ex, ey = psub(bx, ax), psub(by, ay)
                out += [pcross(ex, ey, psub(Q[0], ax), psub(Q[1], ay)), ex, ey]
            out.append(area)
        return out


def tri(*v):
    return Prim("triangle", v)


def line(v0, v1, width):
    return Prim("line", [v0, v1], width)


# ---------------------------------------------------------------------------
# Exact time coverage of one primitive at one spatial sample.

class TimeCoverage:
    """c_P(q) before normalisation: the covered length (a surd), the events
    and, per piece between events, whether it is covered."""

    def __init__(self, prim, q, shutter, rule, cull):
        lo, hi = shutter
        self.prim, self.q = prim, q
        roots = []
        self.polys = prim.polys(q)
        for p in self.polys:
            roots += roots_in(p, lo, hi)
        roots.sort(key=cmp_to_key(surd_cmp))
        events = []
        for r in roots:
            if not events or surd_cmp(events[-1], r) != 0:
                events.append(r)
        self.events = events
        self.bounds = [Surd.rat(lo)] + events + [Surd.rat(hi)]
        self.floats = [float(b) for b in self.bounds]
        self.covered = []
        self.length = Surd()
        for x, y in zip(self.bounds, self.bounds[1:]):
            m = between(x, y)
            c = prim.pred("main", prim.at(m), q, prim.h, rule, cull)
            self.covered.append(c)
            if c:
                self.length = self.length + (y - x)

    def member(self, tau):
        """Whether tau (rational, in the shutter) lies in a covered piece;
        None when tau is an event or a shutter end (measure zero)."""
        tf = float(tau)
        ts = Surd.rat(tau)
        i = 0
        for k, (b, bf) in enumerate(zip(self.bounds, self.floats)):
            if abs(tf - bf) < 1e-9:
                c = surd_cmp(ts, b)
            else:
                c = 1 if tf > bf else -1
            if c == 0:
                return None
            if c > 0:
                i = k
        return self.covered[min(i, len(self.covered) - 1)]

    def event_at(self, tau):
        return any(surd_cmp(e, Surd.rat(tau)) == 0 for e in self.events)


# ---------------------------------------------------------------------------
# Cases.

CASES = []


def case(name, description, width, height, prims, mb, aa=None, fill_rule="top-left",
         cull="none", bits=8, pins=(), checks=(), ignore_max_ok=False):
    """Registers a case. mb: effects.motion_blur. pins: pixels whose exact
    time coverage is written (more are chosen automatically). checks:
    functions of the evaluated case that must hold (the author's intent).
    ignore_max_ok: the motion-ignoring method may meet the max-error bound
    here (the description says why); it must still fail the RMS bound."""
    assert (width <= 64 and height <= 64) or name.startswith("long_"), name
    assert mb["samples"] <= 64 and mb["samples"] * (aa["samples"] if aa else 1) <= 256, name
    CASES.append(dict(name=name, description=description, W=width, H=height, prims=prims,
                      mb=mb, aa=aa, rule=fill_rule, cull=cull, bits=bits, pins=list(pins),
                      checks=list(checks), ignore_max_ok=ignore_max_ok))


def MB(samples, pattern="stratified", seed=0, shutter=None):
    d = {}
    if shutter is not None:
        d["shutter"] = [exact(shutter[0]), exact(shutter[1])]
    d["samples"] = samples
    d["pattern"] = pattern
    if seed:
        d["seed"] = seed
    return d


def AA(samples, pattern="standard", seed=None):
    d = {"samples": samples, "pattern": pattern}
    if seed is not None:
        d["seed"] = seed
    return d


def round_up(q, digits=4):
    s = 10 ** digits
    return F(math.ceil(F(q) * s), s)


def sig15(q):
    """A positive rational rounded to 15 significant digits, as a Fraction."""
    q = F(q)
    if q == 0:
        return q
    e = math.floor(math.log10(float(q)))
    k = 14 - e
    return F(round(q * F(10) ** k)) / F(10) ** k


def shutter_of(mb):
    s = mb.get("shutter", [0, 1])
    return F(s[0]), F(s[1])


def bounds(rms, mx, sigma, T):
    """(max_time_rms, max_time_error) from the sample method's RMS and largest
    error, the RMS sigma of independent uniform instants, and M*N (see the
    module docstring)."""
    return round_up(max(1.25 * rms, 1.5 * sigma)), round_up(max(1.25 * mx, 2 / math.sqrt(T)))


def time_fraction(length, shutter):
    """c_P(q): the covered length over the shutter's length (SPEC 15.2)."""
    return length.scale(1 / (shutter[1] - shutter[0]))


def evaluate(c):
    """Every expectation of a case, after every cross-check; returns
    (expect dict, stats)."""
    W, H, rule, cull, mb = c["W"], c["H"], c["rule"], c["cull"], c["mb"]
    prims = c["prims"]
    for p in prims:
        p.setup(c["bits"])
    offs = spatial_offsets(c["aa"])
    M = len(offs)
    moving = [p for p in prims if p.moves()]
    shutter = shutter_of(mb)
    o16, c16 = int(shutter[0] * TIME_ONE), int(shutter[1] * TIME_ONE)
    assert shutter[0] * TIME_ONE == o16 and shutter[1] * TIME_ONE == c16
    E = max([p.exp for p in prims] + [pow2_exp(v) for o in offs for v in o] + [1])

    for p in prims:
        p.scale_to(E)
    q_ints = {}

    def test(p, n, t, q, which="alt"):
        """The predicate at tau = n/2^t, on integers (everything times 2^(E + t))."""
        qi = q_ints.get(q)
        if qi is None:
            qi = q_ints[q] = (int(q[0] * 2 ** E), int(q[1] * 2 ** E))
        h = None if p.h_int is None else p.h_int << t
        return p.pred(which, p.at_int(n, t), (qi[0] << t, qi[1] << t), h, rule, cull)

    def static_cov(p, q):
        a = p.pred("main", p.at(0), q, p.h, rule, cull)
        b = p.pred("alt", p.at(0), q, p.h, rule, cull)
        assert a == b, (c["name"], "predicates disagree on a static primitive", q)
        return a

    if not moving:
        # A static scene with effects.motion_blur: samples_covered as in section 6.
        covered = 0
        for y in range(H):
            for x in range(W):
                for ox, oy in offs:
                    q = (x + ox, y + oy)
                    if any(static_cov(p, q) for p in prims):
                        covered += 1
        return {"samples_covered": covered}, {"covered": covered, "moving_pixels": 0}

    span = shutter[1] - shutter[0]
    # --- exact values -------------------------------------------------------
    exact_px = {}
    tcs = {}
    for y in range(H):
        for x in range(W):
            total = Surd()
            for si, (ox, oy) in enumerate(offs):
                q = (x + ox, y + oy)
                for pi, p in enumerate(prims):
                    if not p.moves():
                        if static_cov(p, q):
                            total = total + F(1)
                        continue
                    if not p.touches(q):
                        continue
                    tc = TimeCoverage(p, q, shutter, rule, cull)
                    tcs[(x, y, si, pi)] = tc
                    total = total + time_fraction(tc.length, shutter)
            exact_px[(x, y)] = total.scale(F(1, M))

    # --- the sample method, the motion-ignoring method and the mid-shutter one
    N = mb["samples"]
    est, ign, mid = {}, {}, {}
    agree = 0
    for y in range(H):
        for x in range(W):
            us = pixel_us(mb, y * W + x, M)
            assert len(us) == M * N
            hits = F(0)
            ig = F(0)
            md = F(0)
            for si, (ox, oy) in enumerate(offs):
                q = (x + ox, y + oy)
                for pi, p in enumerate(prims):
                    if not p.moves():
                        if static_cov(p, q):
                            hits += N
                            ig += N
                            md += N
                        continue
                    if not p.touches(q):
                        continue
                    tc = tcs[(x, y, si, pi)]
                    ig += N * test(p, o16 << TIME_BITS, 32, q)
                    md += N * test(p, (o16 + c16) << (TIME_BITS - 1), 32, q)
                    for k in range(N):
                        u = us[si * N + k]
                        n = (o16 << TIME_BITS) + (c16 - o16) * u   # tau * 2^32
                        a = test(p, n, 32, q)
                        b = test(p, n, 32, q, "main")
                        assert a == b, (c["name"], "predicates disagree", x, y, si, pi, n)
                        mem = tc.member(F(n, 1 << 32))
                        assert mem is None or mem == a, (c["name"], "exact coverage disagrees with "
                                                         "the predicate", x, y, si, pi, n)
                        agree += mem is not None
                        hits += a
            est[(x, y)] = hits / (M * N)
            ign[(x, y)] = ig / (M * N)
            mid[(x, y)] = md / (M * N)

    def errors(cand):
        errs = []
        for key, ex in exact_px.items():
            r = ex.rational()
            whole = r is not None and r.denominator == 1
            err = float(cand[key] - ex.approx(120))
            if not whole or cand[key] != r:
                errs.append(err)
        rms = math.sqrt(sum(e * e for e in errs) / len(errs)) if errs else 0.0
        return rms, max((abs(e) for e in errs), default=0.0), len(errs)

    # The variance of the estimate with independent uniform instants: each of
    # the N tests of a moving primitive at a spatial sample is a Bernoulli
    # draw of mean c_P(q).
    var = {}
    for (x, y, si, pi), tc in tcs.items():
        cp = float(time_fraction(tc.length, shutter))
        var[(x, y)] = var.get((x, y), 0.0) + cp * (1 - cp) / (M * M * N)
    rms, mx, n_moving = errors(est)
    ig_rms, ig_max, _ = errors(ign)
    md_rms, md_max, _ = errors(mid)
    T = M * N
    moving_keys = [k for k, v in exact_px.items() if v.rational() is None or
                   v.rational().denominator != 1 or est[k] != v.rational()]
    sigma = math.sqrt(sum(var.get(k, 0.0) for k in moving_keys) / len(moving_keys))
    assert 1.5 * sigma <= 0.75 / math.sqrt(T) + 1e-12
    rms_bound, max_bound = bounds(rms, mx, sigma, T)
    name = c["name"]
    assert rms <= float(rms_bound) and mx <= float(max_bound), name
    assert ig_rms > float(rms_bound), "%s: ignoring motion passes the RMS bound (%.4f <= %s)" % (
        name, ig_rms, float(rms_bound))
    assert c["ignore_max_ok"] or ig_max > float(max_bound), \
        "%s: ignoring motion passes the max bound (%.4f <= %s)" % (name, ig_max, float(max_bound))
    # Drawing at mid-shutter is a better guess than shutter open; with 16 or more
    # tests per pixel it must still fail (with fewer, the estimate is as noisy).
    assert T < 16 or md_rms > float(rms_bound) or md_max > float(max_bound), \
        "%s: drawing at mid-shutter passes both bounds" % name

    # --- pins -----------------------------------------------------------------
    pins = list(c["pins"])
    movers = sorted(k for k, v in exact_px.items()
                    if v.rational() is None or v.rational().denominator != 1)
    irr = [k for k in movers if exact_px[k].rational() is None]
    auto = []
    for pool in (irr, movers):
        if pool:
            for k in (pool[len(pool) // 3], pool[(2 * len(pool)) // 3]):
                if k not in pins and k not in auto:
                    auto.append(k)
    pins += auto[:max(0, 5 - len(pins))]
    assert len(pins) >= 3, name

    # --- brute force: Riemann sums of the second predicate ----------------------
    def riemann(key, K):
        x, y, si, pi = key
        tc = tcs[key]
        p = prims[pi]
        q = (x + offs[si][0], y + offs[si][1])
        lk = K.bit_length() - 1
        assert 1 << lk == K
        t = TIME_BITS + lk + 1
        count = 0
        for i in range(K):
            n = o16 * (2 * K) + (c16 - o16) * (2 * i + 1)   # tau * 2^t
            a = test(p, n, t, q)
            mem = tc.member(F(n, 1 << t))
            assert mem is None or mem == a, (name, "Riemann instant disagrees", key, i)
            count += a
        exact_c = float(time_fraction(tc.length, shutter))
        assert abs(count / K - exact_c) <= (len(tc.events) + 1) / K + 1e-12, \
            (name, "Riemann sum", key, count / K, exact_c)

    pinned = set(pins)
    rest = sorted(k for k in tcs if (k[0], k[1]) not in pinned)
    for key in tcs:
        if (key[0], key[1]) in pinned:
            riemann(key, 4096 if M == 1 else 1024)
    step = max(1, len(rest) // 150)
    for key in rest[::step]:
        riemann(key, 512)

    expect = {"time_coverage": [], "max_time_error": max_bound, "max_time_rms": rms_bound}
    pin_report = []
    for (x, y) in pins:
        v = exact_px[(x, y)]
        r = v.rational()
        if r is not None:
            written = r
            shown = str(r)
        else:
            written = sig15(v.approx(200))
            shown = "%s (irrational; written %s)" % (format_dec(v.approx(200), 40), js(written))
        expect["time_coverage"].append({"pixel": [x, y], "value": written})
        pin_report.append(((x, y), shown))
    stats = dict(prims=prims, moving_pixels=n_moving, rms=rms, sigma=sigma, max=mx,
                 ig_rms=ig_rms, ig_max=ig_max,
                 md_rms=md_rms, md_max=md_max, rms_bound=rms_bound, max_bound=max_bound,
                 pins=pin_report, exact=exact_px, tcs=tcs, est=est, agree=agree, M=M, N=N)
    return expect, stats


def format_dec(q, digits):
    q = F(q)
    s = "-" if q < 0 else ""
    q = abs(q)
    ip = math.floor(q)
    frac = math.floor((q - ip) * 10 ** digits)
    return "%s%d.%0*d" % (s, ip, digits, frac)


def render(c, expect):
    lines = ["{"]
    lines.append('  "name": %s,' % js(c["name"]))
    lines.append('  "description": %s,' % js(c["description"]))
    lines.append('  "canvas": %s,' % js({"width": c["W"], "height": c["H"]}))
    lines.append('  "rules": %s,' % js({"subpixel_bits": c["bits"], "fill_rule": c["rule"],
                                          "cull": c["cull"]}))
    eff = {}
    if c["aa"]:
        eff["antialias"] = c["aa"]
    eff["motion_blur"] = c["mb"]
    lines.append('  "effects": %s,' % js(eff))
    lines.append('  "primitives": [')
    lines.append(",\n".join("    " + js(p.json()) for p in c["prims"]))
    lines.append("  ],")
    if "time_coverage" in expect:
        lines.append('  "expect": {')
        lines.append('    "time_coverage": [')
        lines.append(",\n".join("      " + js(p) for p in expect["time_coverage"]))
        lines.append("    ],")
        lines.append('    "max_time_error": %s,' % js(expect["max_time_error"]))
        lines.append('    "max_time_rms": %s' % js(expect["max_time_rms"]))
        lines.append("  }")
    else:
        lines.append('  "expect": %s' % js(expect))
    lines.append("}")
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------
# The cases.

BOUNDS_NOTE = ("Bounds: max_time_rms is max(1.25 R, 1.5 sigma) and max_time_error "
               "max(1.25 X, 2/sqrt(M*N)), where R and X are the RMS over moving pixels and the "
               "largest error of the sample method with this case's own instants (SPEC 15.3), and "
               "sigma the RMS that independent uniform instants would give, computed from the "
               "exact coverages (1.5 sigma is never above SPEC's default 0.75/sqrt(M*N)); a method "
               "that draws the scene at shutter open fails them (tools/gen_motion_cases.py "
               "explains and checks both).")


def dec6(x):
    return F(round(x * 10 ** 6), 10 ** 6)


def rotated(cx, cy, r, deg):
    a = math.radians(deg)
    return (dec6(cx + r * math.cos(a)), dec6(cy + r * math.sin(a)))


def moved(pts, dx, dy):
    return [(exact(x) + exact(dx), exact(y) + exact(dy)) for x, y in pts]


def pixel_of(stats, x, y):
    return stats["exact"][(x, y)]


def rat(stats, x, y):
    return pixel_of(stats, x, y).rational()


def events_at(stats, x, y, prim=0, sample=0):
    return stats["tcs"][(x, y, sample, prim)].events


def area_poly(prim):
    """The twice-signed area of a triangle as a polynomial in tau (the last
    of its polys, whatever the sample)."""
    assert prim.kind == "triangle"
    return prim.polys((F(0), F(0)))[-1]


# --- 1. Rigid motion: translation, rotation, scaling ---------------------------

TRANS_FROM = [(F(7, 4), F(9, 4)), (F(19, 2), F(9, 8)), (F(27, 8), F(79, 8))]
case("translate_triangle_stratified16",
     "A triangle translating by (5, 3.5) over the shutter, stratified 16 time samples: with a pure "
     "translation every edge function is linear in tau (the tau^2 coefficient, the cross product "
     "of the endpoint velocities, is zero), so every instant where a sample enters or leaves is "
     "rational and the exact time coverage of every pixel is rational. The leading edge sweeps "
     "samples in and the trailing edge out; pixels along the path are covered for part of the "
     "shutter, those inside the overlap of the first and last positions for all of it. "
     + BOUNDS_NOTE,
     16, 16, [tri(*[mv(p, q) for p, q in zip(TRANS_FROM, moved(TRANS_FROM, 5, F(7, 2)))])],
     MB(16), pins=[(4, 4), (10, 8), (12, 5)],
     checks=[lambda s: all(v.rational() is not None for v in s["exact"].values())])

ROT_FROM = [rotated(8, 8, 6.5, a) for a in (-80, 40, 160)]
ROT_TO = [rotated(8, 8, 6.5, a + 90) for a in (-80, 40, 160)]
ROT_DESC = ("a triangle inscribed in a circle of radius 6.5 around (8, 8) turning by 90 degrees: "
            "its vertices are written with 6 decimals (not multiples of 1/256) and snap at each end "
            "(SPEC 15.1), then move along straight chords, so the triangle shrinks to about 0.71 of "
            "its size mid-shutter as it turns. Each edge function at a sample is a true quadratic "
            "in tau, so most entry and exit instants are irrational")
for pattern, n, seed in (("stratified", 16, 0), ("random", 4, 5), ("stratified", 64, 0),
                         ("jittered-xy-t", 16, 0)):
    extra = {
        ("stratified", 16): "The exact time coverage has to integrate between irrational roots; "
                            "a reference that samples instead of solving is off by up to 1/N.",
        ("random", 4): "Only 4 independent random instants per pixel: the noisiest estimate in "
                       "the suite, and still far closer than drawing the triangle at shutter open. "
                       "With 4 instants max_time_error is 1 (one pixel may be wrong by a whole), so "
                       "max_time_rms is what tells a method that ignores motion from this one.",
        ("stratified", 64): "64 stratified instants per pixel: the bounds are tight, so an "
                            "estimator whose strata are wrong (or that reuses one pixel's instants "
                            "everywhere) shows up in the RMS.",
        ("jittered-xy-t", 16): "Without antialiasing the three stratified time patterns draw the "
                               "same instants (SPEC 15.3); this case has the same geometry, seed "
                               "and instants as rotate_triangle_stratified16 and must give the "
                               "same frame.",
    }[(pattern, n)]
    case("rotate_triangle_%s%d" % (pattern.replace("-", "_"), n),
         "Rotation, %s %d time samples%s: %s. %s %s"
         % (pattern, n, " (seed %d)" % seed if seed else "", ROT_DESC, extra, BOUNDS_NOTE),
         16, 16, [tri(*[mv(p, q) for p, q in zip(ROT_FROM, ROT_TO)])], MB(n, pattern, seed),
         pins=[(8, 8), (5, 4), (4, 7), (10, 8), (8, 11)], ignore_max_ok=(n == 4),
         checks=[lambda s: any(v.rational() is None for v in s["exact"].values())])

SCALE_C = (F(33, 4), F(31, 4))
SCALE_R = [(-6, -5), (F(13, 2), -2), (-1, F(27, 4))]
case("scale_triangle_random16",
     "A triangle scaling about (8.25, 7.75) from 1/4 to 5/4 of its size, random 16 time samples "
     "(seed 11): the vertices' velocities are not parallel, so each edge function has a tau^2 "
     "term, yet every root is rational (the edge function is s*(cross(e, q - c) - s*cross(e, r)) "
     "in the scale s, linear in tau): a case whose quadratics all factor. Samples near the centre "
     "are covered for the whole shutter, those near the final edges only at the end. "
     + BOUNDS_NOTE,
     16, 16, [tri(*[mv((SCALE_C[0] + F(r[0]) / 4, SCALE_C[1] + F(r[1]) / 4),
                       (SCALE_C[0] + F(r[0]) * 5 / 4, SCALE_C[1] + F(r[1]) * 5 / 4))
                    for r in SCALE_R])],
     MB(16, "random", 11), pins=[(8, 7), (4, 3), (13, 6), (7, 13)],
     checks=[lambda s: all(v.rational() is not None for v in s["exact"].values()),
             lambda s: any(p[2] != 0 for tc in s["tcs"].values() for p in tc.polys)])

LONG = [(F(2), F(3, 2)), (F(17, 2), F(19, 4)), (F(15, 4), F(21, 2))]
case("long_motion_112px_stratified16",
     "Fast motion: a triangle about 6 px wide moves 112 px to the right (and turns slightly: one "
     "vertex moves 2 px less) across a 128x12 canvas, stratified 16 time samples. Each pixel on "
     "its path is covered for well under a tenth of the shutter, so most of its 16 instants miss "
     "and the estimate is sparse (the regime motion blur is hard in); the exact coverage is small "
     "but never zero along the path. A method that draws the triangle at shutter open puts a "
     "solid triangle at the left end and nothing elsewhere. " + BOUNDS_NOTE,
     128, 12, [tri(mv(LONG[0], (LONG[0][0] + 112, LONG[0][1] + 1)),
                   mv(LONG[1], (LONG[1][0] + 112, LONG[1][1] + 1)),
                   mv(LONG[2], (LONG[2][0] + 110, LONG[2][1] + F(3, 2))))],
     MB(16), pins=[(5, 5), (40, 5), (64, 6), (100, 7), (114, 5)])

# --- 2. Exact events: a vertex through a sample, a double root, riding an edge --

case("vertex_crosses_sample_at_3_8",
     "A vertex passes exactly through the sample centre (4.5, 5.5) at tau = 3/8: it moves "
     "from (1.5, 2.5) to (9.5, 10.5) while the other two vertices translate by (1, 0.5), so both "
     "edges that meet at it vanish at that sample at the same rational instant (two quadratics "
     "sharing a root), and the sample, inside until then, is outside after (the triangle turns "
     "over at tau = 1577/1948, about 0.81, and is drawn both ways under cull none). Pixel (4, 5) has "
     "exact time coverage 3/8; a reference that counts the shared root twice, or that loses the "
     "sample at the vertex, gets another value. " + BOUNDS_NOTE,
     12, 12, [tri(mv((F(3, 2), F(5, 2)), (F(19, 2), F(21, 2))),
                  mv((F(41, 4), F(17, 8)), (F(45, 4), F(21, 8))),
                  mv((F(49, 8), F(43, 4)), (F(57, 8), F(45, 4))))],
     MB(16), pins=[(4, 5), (5, 5), (3, 3), (8, 4)],
     checks=[lambda s: rat(s, 4, 5) == F(3, 8),
             lambda s: [r.rational() for r in roots_in(area_poly(s["prims"][0]), F(0), F(1))]
             == [F(1577, 1948)],
             lambda s: any(e.rational() == F(3, 8) for e in events_at(s, 4, 5)),
             lambda s: sum(1 for p in s["tcs"][(4, 5, 0, 0)].polys
                           if p[2] != 0 and any(r.rational() == F(3, 8)
                                                for r in roots_in(p, F(0), F(1)))) >= 2])

# The grazing edge a->b: at tau = 1/4 it is the horizontal segment (4.5, 6.5)-(12.5, 6.5)
# through the sample q = (8.5, 6.5); a moves by (4, 4) and b by (0, -4), so its edge function at
# q is cross(a - q, b - q) = -16 (tau - 1/4)^2: a double root (it touches q and stays on one side).
GRAZE = [mv((F(7, 2), F(11, 2)), (F(15, 2), F(19, 2))),
         mv((F(25, 2), F(15, 2)), (F(25, 2), F(7, 2))),
         mv((F(21, 2), F(1, 2)), (F(13, 2), F(33, 4)))]


def graze_check(s):
    tc = s["tcs"][(8, 6, 0, 0)]
    doubles = [p for p in tc.polys if poly_double_root(p) == F(1, 4)]
    assert doubles and doubles[0] == (F(-1), F(8), F(-16)), doubles
    eps = F(1, 1 << 20)
    return tc.member(F(1, 4) - eps) and tc.member(F(1, 4) + eps) and not tc.member(F(1) - eps)


case("edge_grazes_sample_double_root",
     "An edge that touches a sample without crossing it: the edge from a (3.5, 5.5)->(7.5, 9.5) "
     "to b (12.5, 7.5)->(12.5, 3.5) turns and slides so that its edge function at the sample "
     "(8.5, 6.5) is -(4 tau - 1)^2, a double root at tau = 1/4: the sample lies on the edge at "
     "that one instant and inside the triangle just before and just after. It leaves later, "
     "through the edge to the third vertex (10.5, 0.5)->(6.5, 8.25), at an irrational instant. "
     "A reference that treats every root as a sign change, or that isolates roots by bisecting "
     "on a change of sign (a double root has none), gets pixel (8, 6) wrong by 1/4 or more. "
     + BOUNDS_NOTE,
     16, 12, [tri(*GRAZE)], MB(16), pins=[(8, 6), (6, 5), (11, 6)], checks=[graze_check])

for rule, covered in (("top-left", "covered while the edge passes over them (top edges own their "
                                   "samples)"),
                      ("bottom-right", "never covered (a top edge does not own its samples under "
                                       "bottom-right)")):
    tag = rule.replace("-", "_")
    case("ride_top_edge_%s" % tag,
         "A triangle with a horizontal top edge on sample row 2 (y = 2.5) slides 6 px to the right "
         "and 1.5 px down at its lowest vertex only, fill rule %s: the samples of row 2 lie on the "
         "top edge for the whole time it is over them, so their edge function is identically "
         "zero and the fill rule decides them at every instant: they are %s. Row 3 is covered "
         "normally. A reference that finds roots only, or treats an identically zero edge function "
         "as outside (or inside) whatever the rule, fails row 2. %s" % (rule, covered, BOUNDS_NOTE),
         16, 8, [tri(mv((F(5, 4), F(5, 2)), (F(29, 4), F(5, 2))),
                     mv((F(31, 4), F(5, 2)), (F(55, 4), F(5, 2))),
                     mv((F(7, 2), F(29, 4)), (F(19, 2), F(35, 4))))],
         MB(16), fill_rule=rule, pins=[(4, 2), (8, 2), (11, 2), (8, 3)],
         checks=[lambda s, r=rule: (rat(s, 8, 2) > 0) == (r == "top-left"),
                 lambda s: float(pixel_of(s, 8, 3)) > 0])

# An edge turning about the sample (6.5, 5.5): its ends are opposite each other through the
# sample at every instant, so the sample rides on it (edge function identically zero), and the
# edge is horizontal at tau = 3/8, where its ownership changes.
case("edge_pivots_on_sample",
     "An edge turns about the sample centre (6.5, 5.5): its ends (2.5, 4)->(2.5, 8) and "
     "(10.5, 7)->(10.5, 3) stay opposite each other through the sample, so the sample lies on the "
     "edge at every instant (an identically zero edge function) and the fill rule decides it "
     "throughout. The edge is horizontal at tau = 3/8: before, it is a right edge (not owned under "
     "top-left), after, a left edge (owned), so pixel (6, 5) has exact time coverage 5/8. The "
     "instant where ownership changes is a root of the edge's dy, not of any edge function. "
     + BOUNDS_NOTE,
     12, 12, [tri(mv((F(5, 2), 4), (F(5, 2), 8)), mv((F(21, 2), 7), (F(21, 2), 3)),
                  (F(27, 4), F(21, 2)))],
     MB(16), pins=[(6, 5), (4, 6), (8, 4)],
     checks=[lambda s: rat(s, 6, 5) == F(5, 8),
             lambda s: any(p == (ZERO, ZERO, ZERO) for p in s["tcs"][(6, 5, 0, 0)].polys)])

# --- 3. Winding flips and collapse ---------------------------------------------------

FLIP = [(F(9, 4), F(25, 8)), mv((F(27, 2), F(5, 2)), (F(57, 4), F(23, 4))),
        mv((F(51, 8), F(55, 4)), (F(73, 8), F(-5, 2)))]
FLIP_TRI = tri(*FLIP)
FLIP_RESULTS = {}


def flip_check(cull):
    def check(s):
        FLIP_RESULTS[cull] = s["exact"]
        if len(FLIP_RESULTS) == 3:
            for k, v in FLIP_RESULTS["none"].items():
                d = v - FLIP_RESULTS["cw"][k] - FLIP_RESULTS["ccw"][k]
                assert d.rational() == 0, ("cull none != cw + ccw", k)
        return True
    return check


for cull, what in (("none", "both windings are drawn, so the sample coverage is that of the "
                            "triangle before and of its mirror image after"),
                   ("cw", "the triangle is drawn only while it is counter-clockwise: before the "
                          "flip it is clockwise and culled, so only the second part counts"),
                   ("ccw", "the triangle is drawn only while it is clockwise, before the flip")):
    case("winding_flip_cull_%s" % cull,
         "A winding flip mid-shutter, cull %s: vertex c moves from (6.375, 13.75) to "
         "(9.125, -2.5) straight through the opposite edge while b also moves, so the twice-signed "
         "area is a quadratic in tau with an irrational root near tau = 0.612, where the triangle "
         "is flat and changes winding. Culling applies at each instant to the winding at that "
         "instant (SPEC 15.2): %s. The three cull variants of this case sum to the unculled one "
         "pixel by pixel (checked by the generator). A rasterizer that culls by the winding at "
         "shutter open (or mid-shutter) culls the whole shutter or none of it.%s %s"
         % (cull, what, " Drawing the scene at shutter open draws nothing here (the triangle "
            "is culled then): that errs by at most 0.39 in a pixel, within max_time_error, and "
            "fails max_time_rms." if cull == "cw" else "", BOUNDS_NOTE),
         16, 16, [FLIP_TRI], MB(16), cull=cull, pins=[(5, 3), (9, 4), (11, 4), (7, 1), (6, 10)],
         ignore_max_ok=(cull == "cw"),
         checks=[flip_check(cull),
                 lambda s: [float(r) for r in roots_in(area_poly(FLIP_TRI), F(0), F(1))
                            if r.rational() is None] == [0.6121883684734365],
                 lambda s: any(0 < float(e) < 1 and e.rational() is None
                               for e in events_at(s, 5, 3))])

COL_P = (F(33, 4), F(63, 8))
COL_R = [(F(-11, 2), F(-13, 4)), (6, F(-9, 2)), (F(3, 4), F(25, 4))]
COLLAPSE_TRI = tri(*[mv((COL_P[0] + r[0], COL_P[1] + r[1]), (COL_P[0] - r[0], COL_P[1] - r[1]))
                     for r in COL_R])
case("collapse_to_point_at_half_cull_ccw",
     "A triangle collapsing to zero area at tau = 1/2: every vertex moves from p + r to p - r "
     "with p = (8.25, 7.875), so the triangle shrinks to the point p at tau = 1/2 and grows "
     "back turned by 180 degrees. Its twice-signed area is (1 - 2 tau)^2 times its initial "
     "(clockwise) area: a double root, no change of winding, so with cull ccw it is drawn for the "
     "whole shutter except the one instant. A reference that takes every root of the area as a "
     "winding flip culls the second half; one that samples coverage by the area's sign at the ends "
     "is right by luck. Samples near p are covered except around tau = 1/2, samples far out only "
     "near the ends. " + BOUNDS_NOTE,
     16, 16, [COLLAPSE_TRI],
     MB(16), cull="ccw", pins=[(8, 7), (8, 8), (4, 5), (7, 3), (12, 4)],
     checks=[lambda s: poly_double_root(area_poly(COLLAPSE_TRI)) == F(1, 2),
             lambda s: rat(s, 8, 7) is not None and 0 < rat(s, 8, 7) < 1,
             lambda s: rat(s, 12, 4) > 0])

# --- 4. Shutter, static primitives and meshes ----------------------------------------

case("shutter_quarter_to_three_quarters",
     "The shutter is [0.25, 0.75]: a triangle that turns and slides from (1.5, 9.25) (6.75, 1.5) "
     "(13.25, 12.5) at tau = 0 to (5, 13.5) (3.5, 3.75) (14.5, 5.25) at tau = 1 is seen only in "
     "the middle half of its motion, and the time coverage is normalised by the shutter's length "
     "(SPEC 15.2). Instants are open + (close - open) u/2^16. Fill rule top-right. A rasterizer "
     "that integrates over [0, 1], or maps its instants onto [0, 1], gets other values, near "
     "the ends of the motion most. " + BOUNDS_NOTE,
     16, 16, [tri(mv((F(3, 2), F(37, 4)), (5, F(27, 2))),
                  mv((F(27, 4), F(3, 2)), (F(7, 2), F(15, 4))),
                  mv((F(53, 4), F(25, 2)), (F(29, 2), F(21, 4))))],
     MB(16, shutter=(F(1, 4), F(3, 4))), fill_rule="top-right",
     pins=[(4, 5), (5, 3), (10, 6), (12, 8), (4, 10)])

case("static_and_moving_overlap",
     "A static triangle (2, 2) (13, 3) (4, 13) and a moving one that slides 8 px right across "
     "it, stratified 16 time samples: the pixel value is the sum over primitives (SPEC 15.2), so "
     "where the moving triangle passes over the static one it lies between 1 and 2. Static "
     "primitives need no instants and are drawn once (SPEC 15.3), but they cover their samples "
     "for the whole shutter: a method that counts a static sample as one test out of M*N, or "
     "that clamps a pixel's value to 1, fails here. " + BOUNDS_NOTE,
     16, 16, [tri((2, 2), (13, 3), (4, 13)),
              tri(mv((1, F(21, 4)), (9, F(23, 4))), mv((6, F(31, 8)), (14, F(25, 8))),
                  mv((F(11, 4), F(45, 4)), (F(43, 4), F(49, 4))))],
     MB(16), pins=[(5, 6), (9, 8), (11, 4), (4, 10), (12, 3)],
     checks=[lambda s: 1 < float(pixel_of(s, 5, 6)) < 2])

MESH = [(F(5, 2), F(9, 4)), mv((F(51, 4), F(3, 2)), (F(27, 2), 3)), (F(53, 4), F(27, 2)),
        mv((F(7, 4), F(49, 4)), (F(7, 2), F(23, 2)))]
MESH_TRIS = [tri(MESH[0], MESH[1], MESH[3]), tri(MESH[1], MESH[2], MESH[3])]


def mesh_check(s):
    """The two triangles of the mesh share the moving edge MESH[1]-MESH[3]: at each sample their
    time coverages must sum exactly to the time coverage of their union (a convex quad that moves
    with them), and a sample the diagonal sweeps over gets exactly 1."""
    quad = Prim("quad", [MESH[0], MESH[1], MESH[2], MESH[3]])
    quad.setup(8)
    for tau in (F(0), F(1, 2), F(1)):
        pts = quad.at(tau)
        n = len(pts)
        for i in range(n):
            (ax, ay), (bx, by), (cx, cy) = pts[i], pts[(i + 1) % n], pts[(i + 2) % n]
            assert (bx - ax) * (cy - by) - (by - ay) * (cx - bx) > 0, "mesh quad not convex"
    checked = 0
    for (x, y, si, pi), tc in s["tcs"].items():
        if pi != 0:
            continue
        other = s["tcs"][(x, y, si, 1)]
        union = TimeCoverage(quad, tc.q, (F(0), F(1)), "top-left", "none")
        d = tc.length + other.length - union.length
        assert d.rational() == 0, ("mesh is not watertight in time", x, y)
        if tc.length.rational() is None and union.length.rational() == 1:
            checked += 1
    assert checked >= 3, "no sample swept by the shared edge at irrational instants"
    return True


case("mesh_shared_moving_edge",
     "Two triangles sharing the edge (12.75, 1.5)->(13.5, 3) to (1.75, 12.25)->(3.5, 11.5), "
     "both of whose ends move, form a moving convex quad; a third, static triangle overlaps its "
     "top-left corner. A sample the shared edge sweeps over is covered by one triangle before "
     "and by the other after an irrational instant, and the two time coverages sum to exactly "
     "what their union gives (watertight in time, checked by the generator at every sample): "
     "pixels inside the quad for the whole shutter have exact value 1 even where each triangle's "
     "share is irrational. A rasterizer whose shared-edge test is not consistent between the two "
     "triangles at every instant leaves gaps or double coverage in time. " + BOUNDS_NOTE,
     16, 16, MESH_TRIS + [tri((0, 0), (F(11, 2), F(1, 4)), (F(1, 2), F(23, 4)))],
     MB(16), pins=[(7, 7), (10, 4), (2, 7), (9, 2), (6, 12), (2, 3)],
     checks=[mesh_check, lambda s: rat(s, 7, 7) == 1 and rat(s, 10, 4) == 1,
             lambda s: 1 < float(pixel_of(s, 2, 3)) < 2])

case("coverage_starts_at_shutter_open",
     "The shutter is [0.25, 1] and a triangle with a vertical right edge moves 8 px to the right "
     "over [0, 1], so at shutter open its right edge is exactly at x = 4.5, on the samples of "
     "column 4: their coverage starts exactly at tau = open (a right edge does not own them under "
     "top-left, so at that instant they are not covered) and ends when the slanted left edge "
     "passes. The samples the right edge reaches exactly at shutter close (x = 10.5) get "
     "coverage 0. A test at u = 0 lands exactly on the edge, and a reference that clips its "
     "intervals to the shutter with an off-by-one end gains or loses a point, not an interval; "
     "what it must get right is the normalisation by 0.75. " + BOUNDS_NOTE,
     12, 6, [tri(mv((F(5, 2), F(1, 4)), (F(21, 2), F(1, 4))),
                 mv((F(5, 2), F(23, 4)), (F(21, 2), F(23, 4))),
                 mv((F(-3, 2), 3), (F(13, 2), 3)))],
     MB(16, shutter=(F(1, 4), 1)), pins=[(4, 2), (4, 4), (10, 2), (7, 1)],
     checks=[lambda s: rat(s, 10, 2) == 0,
             lambda s: all(tc.member(F(1, 4)) is None for k, tc in s["tcs"].items()
                           if k[:2] == (4, 2))])

case("static_scene_with_motion_blur",
     "effects.motion_blur is declared but nothing moves: one vertex is even written in the moving "
     "form with from equal to to, which is a static vertex (SPEC 15.1). The scene is drawn as a "
     "static scene (no time loop) and judged as in SPEC 6: it carries samples_covered and no "
     "time expectations. A rasterizer that enters its time loop anyway must still give each "
     "sample a whole coverage.",
     12, 12, [tri((F(3, 2), F(1, 2)), V((F(21, 2), F(5, 2)), (F(21, 2), F(5, 2))),
                  (F(7, 2), F(21, 2))),
              tri((F(21, 2), F(5, 2)), (F(23, 2), F(23, 2)), (F(7, 2), F(21, 2)))],
     MB(8))

# --- 5. Motion and antialiasing ---------------------------------------------------------

AA_TRI = [mv((F(9, 4), F(7, 2)), (F(11, 2), F(17, 8))),
          mv((F(47, 4), F(5, 4)), (F(27, 2), F(33, 4))),
          mv((F(13, 2), F(103, 8)), (F(23, 8), F(53, 4)))]
for aa, n, adesc in ((AA(4), 16, "standard 4x"), (AA(16, "stratified", 0), 16, "stratified 16x")):
    for pattern, pdesc in (
            ("random", "independent random instants for each of the M*N tests"),
            ("stratified", "each spatial sample's N instants stratified over the shutter "
                           "(time-only stratification: the M spatial samples repeat the same "
                           "strata)"),
            ("jittered-xy-t", "the pixel's M*N instants stratified over the shutter and taken "
                              "in the order of the spatial samples (x, y and t correlated)"),
            ("stratified-shuffled", "the pixel's M*N strata dealt to the spatial samples by a "
                                    "seeded shuffle (t stratified independently of x and y)")):
        tag = "%s%d" % (aa["pattern"], aa["samples"])
        case("aa_%s_time_%s" % (tag, pattern.replace("-", "_")),
             "Motion with antialiasing: %s spatial samples x %d time samples, time pattern %s: "
             "%s. A triangle turning and sliding across a 16x16 canvas (the same geometry in all "
             "eight aa_*_time_* cases, so the report compares the patterns); the pixel's time "
             "coverage is the mean over its %d spatial samples of each one's exact time coverage "
             "(SPEC 15.2), and the instants come from SplitMix64 seeded per pixel (SPEC 15.3). "
             "%s" % (adesc, n, pattern, pdesc, aa["samples"], BOUNDS_NOTE),
             16, 16, [tri(*AA_TRI)], MB(n, pattern), aa=aa,
             pins=[(4, 3), (3, 4), (9, 6), (12, 8), (5, 12)])

# --- 6. Moving parallelogram lines ---------------------------------------------------------

case("line_parallelogram_moving_w1_5",
     "A parallelogram line of width 1.5 (SPEC 4.4) moving and turning: its ends go from "
     "(2.5, 3.25) to (6.25, 9.75) and from (12.75, 5.5) to (14.5, 12.25), so it stays x-major "
     "while its slope changes; its ends are vertical and its width is measured vertically at "
     "every instant. Its edge functions are quadratics in tau, and the samples on its path are "
     "covered for irrational fractions of the shutter. A rasterizer that moves a rectangle "
     "(perpendicular ends) instead gets other values near the ends. " + BOUNDS_NOTE,
     16, 16, [line(mv((F(5, 2), F(13, 4)), (F(25, 4), F(39, 4))),
                   mv((F(51, 4), F(11, 2)), (F(29, 2), F(49, 4))), F(3, 2))],
     MB(16), pins=[(7, 6), (3, 4), (13, 9), (10, 8)])

def switch_check(s):
    """Some samples are covered on one side of tau = 4/7 and not on the other, and
    there no edge of either parallelogram passes through them: the jump is the
    switch of major axis alone."""
    eps = F(1, 1 << 20)
    jumps = 0
    for tc in s["tcs"].values():
        if tc.member(F(4, 7) - eps) != tc.member(F(4, 7) + eps):
            assert tc.event_at(F(4, 7))
            others = [p for i, p in enumerate(tc.polys) if i >= 4 and
                      any(r.rational() == F(4, 7) for r in roots_in(p, F(0), F(1)))]
            jumps += not others
    return jumps >= 2


case("line_parallelogram_major_axis_flip",
     "A parallelogram line of width 2 whose major axis changes mid-shutter: its ends move from "
     "(2.125, 5.8125) to (5.625, 2.3125) and from (14.125, 9.8125) to (10.625, 13.3125), so its "
     "direction goes from "
     "(12, 4) (x-major: vertical ends, width measured vertically) to (5, 11) (y-major: horizontal "
     "ends, width measured horizontally), and |dx| = |dy| at tau = 4/7, a rational instant that "
     "is not a multiple of any power of 2. There the parallelogram jumps from one shape to the "
     "other (SPEC 15.2: the major axis is that of the direction at tau): the samples of pixels "
     "(4, 3) and (12, 11) lie in one parallelogram's end and not in the other's, so their "
     "coverage jumps at 4/7 with no edge passing through them. A rasterizer that "
     "keeps the major axis of shutter open gets them wrong for 3/7 of the shutter. " + BOUNDS_NOTE,
     16, 16, [line(mv((F(17, 8), F(93, 16)), (F(45, 8), F(37, 16))),
                   mv((F(113, 8), F(157, 16)), (F(85, 8), F(213, 16))), 2)],
     MB(16), pins=[(4, 3), (12, 11), (3, 5), (6, 7), (10, 10)],
     checks=[switch_check])


# ---------------------------------------------------------------------------
# Wrong variants: each must make the generator's own checks fail.

def _swap(name, value):
    old = globals()[name]
    globals()[name] = value
    return lambda: globals().__setitem__(name, old)


def _swap_attr(obj, name, value):
    old = getattr(obj, name)
    setattr(obj, name, value)
    return lambda: setattr(obj, name, old)


def _drop_polys(keep):
    real = Prim.polys

    def polys(self, q):
        return [p for i, p in enumerate(real(self, q)) if keep(self, i, p)]
    return _swap_attr(Prim, "polys", polys)


MUTANTS = [
    ("the second predicate gives ties to the opposite edges", "ride_top_edge_top_left",
     lambda: _swap("tri_alt", lambda pts, q, rule, cull: tri_main(
         pts, q, {"top-left": "bottom-right"}.get(rule, rule), cull))),
    ("the first predicate ignores cull", "winding_flip_cull_cw",
     lambda: _swap("tri_main", lambda pts, q, rule, cull: convex_main(pts, q, rule))),
    ("cull by the winding at shutter open (clockwise here)", "winding_flip_cull_ccw",
     lambda: _swap("tri_main", lambda pts, q, rule, cull: area2(pts) != 0 and not culled(1, cull)
                   and convex_main(pts, q, rule))),
    ("edges' dx and dy are not events (ownership changes are missed)", "edge_pivots_on_sample",
     lambda: _drop_polys(lambda prim, i, p: prim.kind != "triangle" or i % 3 == 0)),
    ("a line's major-axis switch is not an event", "line_parallelogram_major_axis_flip",
     lambda: _drop_polys(lambda prim, i, p: prim.kind != "line" or i >= 4)),
    ("irrational roots are dropped", "rotate_triangle_stratified16",
     lambda: _swap("roots_in", (lambda real: lambda poly, lo, hi: [
         r for r in real(poly, lo, hi) if r.rational() is not None])(roots_in))),
    ("max_time_rms is SPEC's default 0.75/sqrt(M*N)", "long_motion_112px_stratified16",
     lambda: _swap("bounds", (lambda real: lambda rms, mx, sigma, T: (
         round_up(0.75 / math.sqrt(T)), real(rms, mx, sigma, T)[1]))(bounds))),
    ("the covered length is not divided by the shutter's length", "coverage_starts_at_shutter_open",
     lambda: _swap("time_fraction", lambda length, shutter: length)),
]


def run_mutants():
    """Each wrong variant must trip an assertion of evaluate() or of its case's
    checks; exits non-zero otherwise."""
    by_name = {c["name"]: c for c in CASES}
    ok = True
    for what, name, patch in MUTANTS:
        undo = patch()
        try:
            c = by_name[name]
            _, stats = evaluate(c)
            for check in c["checks"]:
                assert check(stats)
            print("NOT CAUGHT  %-62s %s" % (what, name))
            ok = False
        except AssertionError as e:
            print("caught      %-62s %s: %s" % (what, name, str(e)[:70]))
        finally:
            undo()
    sys.exit(0 if ok else 1)


def main():
    if "--mutants" in sys.argv:
        run_mutants()
    names = set()
    results = []
    only = sys.argv[sys.argv.index("--only") + 1] if "--only" in sys.argv else None
    for c in CASES:
        assert c["name"] not in names, c["name"]
        names.add(c["name"])
        if only and only not in c["name"]:
            continue
        expect, stats = evaluate(c)
        for check in c["checks"]:
            assert check(stats), "check failed: %s" % c["name"]
        results.append((c, expect, stats))
        if "-v" in sys.argv:
            if stats["moving_pixels"] == 0:
                print("%-40s static, samples_covered %d" % (c["name"], stats["covered"]))
                continue
            print("%-40s M*N %3d moving %4d  sigma %.4f rms %.4f ignore %.4f mid %.4f / %s   max %.4f "
                  "ignore %.4f mid %.4f / %s  (%d instants checked against the intervals)" % (
                      c["name"], stats["M"] * stats["N"], stats["moving_pixels"], stats["sigma"],
                      stats["rms"],
                      stats["ig_rms"], stats["md_rms"], stats["rms_bound"], stats["max"],
                      stats["ig_max"], stats["md_max"], stats["max_bound"], stats["agree"]))
            for px, shown in stats["pins"]:
                print("    pin %-10s %s" % ("%d,%d" % px, shown))
        if "--map" in sys.argv and stats["moving_pixels"]:
            for y in range(c["H"]):
                print(" ".join("%4.2f" % float(stats["exact"][(x, y)]) for x in range(c["W"])))
    # The three stratified patterns draw the same instants without antialiasing
    # (SPEC 15.3; the shuffled one deals them to the N slots in another order).
    for px in range(64):
        a = [pixel_us(MB(16, p), px, 1) for p in ("stratified", "jittered-xy-t",
                                                   "stratified-shuffled")]
        assert a[0] == a[1] and sorted(a[1]) == sorted(a[2]) and a[1] != a[2]
    assert len(CASES) >= 24
    if only:
        print("evaluated %d cases (--only: nothing written)" % len(results))
        return
    os.makedirs(OUT_DIR, exist_ok=True)
    for f in os.listdir(OUT_DIR):
        if f.endswith(".json"):
            os.remove(os.path.join(OUT_DIR, f))
    for c, expect, _ in results:
        with open(os.path.join(OUT_DIR, c["name"] + ".json"), "w") as f:
            f.write(render(c, expect))
    print("wrote %d cases in cases/motion" % len(results))


if __name__ == "__main__":
    main()
