"""The line case model: a line with its rule, width, last pixel, parameter
and interpolation; the short constructors (mid, rect, para, dia); the case
registry with its size limits (written by casefile.render). Holds no case
and no checker.
"""

from casegen import casefile
from casegen.casefile import P, vjson
from casegen.exactjson import exact


class V(casefile.V):
    """A vertex with depth, w and attributes (the object form), each an exact
    number: unlike the triangle cases, a string value here is a number
    ("1/3"), written as a JSON number when it terminates."""

    def __init__(self, x, y, z=None, w=None, attributes=None):
        super().__init__(x, y, None if z is None else exact(z), None if w is None else exact(w),
                         None if attributes is None else [exact(a) for a in attributes])


class Line:
    def __init__(self, a, b, rule="midpoint", width=None, last_pixel=None, parameter=None,
                 interpolation=None):
        assert rule in ("midpoint", "rectangle", "parallelogram", "diamond-exit")
        assert width is None or rule not in ("midpoint", "diamond-exit")
        assert last_pixel is None or rule == "midpoint"
        self.v = [a, b]
        self.rule = rule
        self.width = None if width is None else exact(width)
        self.last_pixel = last_pixel
        self.parameter = parameter
        self.interpolation = interpolation

    def reversed(self):
        return Line(self.v[1], self.v[0], self.rule, self.width, self.last_pixel, self.parameter,
                    self.interpolation)

    def with_(self, **kw):
        d = dict(rule=self.rule, width=self.width, last_pixel=self.last_pixel,
                 parameter=self.parameter, interpolation=self.interpolation)
        d.update(kw)
        return Line(self.v[0], self.v[1], **d)

    def json(self):
        d = {"line": [vjson(v) for v in self.v], "rule": self.rule}
        if self.width is not None:
            d["width"] = self.width
        if self.last_pixel is not None:
            d["last_pixel"] = self.last_pixel
        if self.parameter is not None:
            d["parameter"] = self.parameter
        if self.interpolation is not None:
            d["interpolation"] = self.interpolation
        return d


def mid(a, b, **kw):
    return Line(P(*a) if not isinstance(a, V) else a, P(*b) if not isinstance(b, V) else b,
                "midpoint", **kw)


def rect(a, b, width=None, **kw):
    return Line(P(*a) if not isinstance(a, V) else a, P(*b) if not isinstance(b, V) else b,
                "rectangle", width=width, **kw)


def para(a, b, width=None, **kw):
    return Line(P(*a) if not isinstance(a, V) else a, P(*b) if not isinstance(b, V) else b,
                "parallelogram", width=width, **kw)


def dia(a, b, **kw):
    return Line(P(*a) if not isinstance(a, V) else a, P(*b) if not isinstance(b, V) else b,
                "diamond-exit", **kw)


CASES = []
LONG_CASES = {"midpoint_long_shallow_2048", "midpoint_long_steep_2048", "rectangle_width_64",
              "diamond_long_shallow_1200", "diamond_long_steep_1200"}


def case(name, description, width, height, prims, bits=8, fill_rule="top-left", covered=True,
         checks=(), pixels=None):
    """Registers a case.

    covered: write expect.samples_covered, as counted by the checker.
    checks: extra claims the checker must prove, each a tuple:
      ("ties",)                 a flipped midpoint tie rule changes coverage
      ("fill_rule",)            the flipped fill rule changes coverage
      ("snap",)                 some other rounding of the snapping changes coverage
      ("xmajor_at_one",)        treating |slope| = 1 as y-major changes coverage
      ("same_as", other_name)   same coverage counts and same covered set as another case
      ("max_coverage", k)       no sample is covered more than k times
      ("uncovered", x, y)       pixel (x, y) is not covered
      ("min_coverage_max", k)   some sample is covered at least k times
      ("parameter",)            major vs projected parameter changes some value
      ("perspective",)          linear vs perspective changes some value
      ("clamp",)                some sample's parameter is clamped
      ("diamond", variant)      a wrong diamond (see diamond_shape) changes coverage
      ("differs_from", name)    the covered set differs from another case's
      ("lit", i, x, y)          primitive i lights pixel (x, y); ("unlit", i, x, y) it does not
    pixels: {primitive index: [(x, y), ...]} the exact pixel list the
      description states, verified by the checker.
    """
    if name not in LONG_CASES:
        assert 1 <= width <= 64 and 1 <= height <= 64, name
    assert width * height <= 2**20, name
    CASES.append(dict(name=name, description=description, width=width, height=height,
                      prims=prims, bits=bits, fill_rule=fill_rule, covered=covered,
                      checks=list(checks), pixels=pixels or {}))



def fmt_px(px):
    return " ".join("(%d,%d)" % p for p in px)

