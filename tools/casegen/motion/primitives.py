"""Moving primitives (vertices with from and to, snapped at each end) and the
exact time coverage of one primitive at one spatial sample: the events
(roots in tau of every quantity the static rules look at) and the covered
length between them, decided by the predicates at rational instants.
"""

from fractions import Fraction as F
from functools import cmp_to_key

from casegen.exactjson import exact
from casegen.motion.predicates import convex_main, line_alt, line_main, quad_alt, tri_alt, tri_main
from casegen.motion.quadratic import (ZERO, Surd, between, const, padd, pcross, psub, roots_in,
                                      surd_cmp)

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

