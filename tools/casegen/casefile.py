"""A static case file as the triangle, line and hard generators write it:
points, vertices in the object form, triangles, and the writer of the whole
file (name, description, canvas, rules, primitives, expect).

Lines are not here: the line generator's lines carry a rule, width and
interpolation, the hard cases' only a last pixel; each keeps its own class.
The antialiasing checker has its own primitives (contours and a fill rule),
written by render() with their effects; the motion generator has its own
writer (moving vertices, time expectations).
"""

import json

from casegen.exactjson import exact, js


def P(x, y):
    return (exact(x), exact(y))


class V:
    """A vertex with depth, w and attributes (the object form). z, w and the
    attributes are written as given: a string stays a JSON string."""

    def __init__(self, x, y, z=None, w=None, attributes=None):
        self.x, self.y = exact(x), exact(y)
        self.z = z
        self.w = w
        self.attributes = attributes

    def pos(self):
        return (self.x, self.y)

    def json(self):
        d = {"position": [self.x, self.y]}
        if self.z is not None:
            d["z"] = self.z
        if self.w is not None:
            d["w"] = self.w
        if self.attributes is not None:
            d["attributes"] = list(self.attributes)
        return d


def pos_of(v):
    return v.pos() if isinstance(v, V) else (exact(v[0]), exact(v[1]))


def vjson(v):
    return v.json() if isinstance(v, V) else [exact(v[0]), exact(v[1])]


class Tri:
    def __init__(self, a, b, c, interpolation=None):
        self.v = [a, b, c]
        self.interpolation = interpolation

    def json(self):
        d = {"triangle": [vjson(v) for v in self.v]}
        if self.interpolation is not None:
            d["interpolation"] = self.interpolation
        return d


def render(c, expect, effects=None):
    """The case file's text: one line per top-level field and per primitive,
    checked to be valid JSON. `expect` is left out when empty; a case without
    a "cull" is written with cull "none"; `effects` (the antialiasing cases'
    {"antialias": ...}) is written before the primitives when given."""
    lines = ["{"]
    lines.append('  "name": %s,' % js(c["name"]))
    lines.append('  "description": %s,' % js(c["description"]))
    lines.append('  "canvas": %s,' % js({"width": c["width"], "height": c["height"]}))
    lines.append('  "rules": %s,' % js({"subpixel_bits": c["bits"], "fill_rule": c["fill_rule"],
                                          "cull": c.get("cull", "none")}))
    if effects:
        lines.append('  "effects": %s,' % js(effects))
    lines.append('  "primitives": [')
    lines.append(",\n".join("    " + js(p.json()) for p in c["prims"]))
    if expect:
        lines.append("  ],")
        lines.append('  "expect": %s' % js(expect))
    else:
        lines.append("  ]")
    lines.append("}")
    text = "\n".join(lines) + "\n"
    json.loads(text)
    return text
