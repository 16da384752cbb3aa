"""Exact arithmetic in tau: quadratic surds u + v*sqrt(s) (compared and
ordered exactly, by intervals from integer square roots refined until they
separate), and polynomials of degree <= 2 with their roots in an interval.
Knows nothing of primitives.
"""

import math
from fractions import Fraction as F

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

