"""Primitives as the antialiasing checker sees them: closed contours of
snapped vertices and a fill rule (a triangle or a parallelogram line is a
one-contour nonzero polygon, SPEC.md section 14.1), and their JSON form.
"""

from fractions import Fraction as F

from casegen.exactjson import exact


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

