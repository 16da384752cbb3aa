"""The clip-space case model: vertices given in clip coordinates (or placed by
their screen position, depth and w), triangles, the case registry, the model
scene a case becomes (homogeneous.Scene), and the writer of its file.
"""

import json
from fractions import Fraction as F

from casegen.clip.homogeneous import Scene
from casegen.exactjson import exact, js

CASES = []

# Every rule is written out, so a file says which convention it pins.
DEFAULT_RULES = {"subpixel_bits": 8, "fill_rule": "top-left", "cull": "none",
                 "clip_xy": "guard-band", "clip_z": "clip-then-snap", "depth": "clip",
                 "provoking_vertex": "first"}

# The four combinations of clip_xy and clip_z with depth clip, and depth clamp
# under each clip_xy (clip_z is not given then).
CONVENTIONS = {
    "gb_ps": {"clip_xy": "guard-band", "clip_z": "per-sample"},
    "gb_cts": {"clip_xy": "guard-band", "clip_z": "clip-then-snap"},
    "cts_cts": {"clip_xy": "clip-then-snap", "clip_z": "clip-then-snap"},
    "cts_ps": {"clip_xy": "clip-then-snap", "clip_z": "per-sample"},
    "gb_clamp": {"clip_xy": "guard-band", "depth": "clamp"},
    "cts_clamp": {"clip_xy": "clip-then-snap", "depth": "clamp"},
}


class CV:
    """A clip-space vertex (x, y, z, w) with attributes."""

    def __init__(self, x, y, z, w, attributes=()):
        self.c = tuple(exact(v) for v in (x, y, z, w))
        self.attributes = tuple(exact(a) for a in attributes)

    def model(self):
        return self.c + self.attributes

    def json(self):
        d = {"clip": list(self.c)}
        if self.attributes:
            d["attributes"] = list(self.attributes)
        return d


def at(xf, yf, z_ndc, w, attributes=(), viewport=None, size=16):
    """The clip-space vertex with weight w that lands at (xf, yf) with depth
    z_ndc, through `viewport` (default: a size x size canvas)."""
    vp = viewport or {"x": 0, "y": 0, "width": size, "height": size}
    w = exact(w)
    nx = 2 * (exact(xf) - exact(vp["x"])) / exact(vp["width"]) - 1
    ny = 2 * (exact(yf) - exact(vp["y"])) / exact(vp["height"]) - 1
    return CV(w * nx, w * ny, w * exact(z_ndc), w, attributes)


class Tri:
    def __init__(self, a, b, c, interpolation=None):
        self.v = [a, b, c]
        self.interpolation = interpolation

    def json(self):
        d = {"triangle": [v.json() for v in self.v]}
        if self.interpolation is not None:
            d["interpolation"] = self.interpolation
        return d


def case(name, description, prims, width=16, height=16, viewport=None, conv="gb_cts",
         watertight=False, checks=(), **rules):
    """Registers a case. description may name {N} (its own samples_covered) and
    {other_case_name} (another case's). conv: a key of CONVENTIONS; rules: any
    other rule (subpixel_bits, fill_rule, cull, provoking_vertex). checks:
    functions of (this case's frame, every case's count) that must hold."""
    assert 8 <= width <= 32 and 8 <= height <= 32, name
    r = dict(DEFAULT_RULES)
    r.update(CONVENTIONS[conv])
    r.update(rules)
    if r["depth"] == "clamp":
        del r["clip_z"]
    CASES.append(dict(name=name, description=description, prims=prims, width=width,
                      height=height, viewport=viewport, rules=r, watertight=watertight,
                      checks=list(checks)))


def viewport_of(c):
    vp = {"x": F(0), "y": F(0), "width": F(c["width"]), "height": F(c["height"]),
          "min_depth": F(0), "max_depth": F(1)}
    for k, v in (c["viewport"] or {}).items():
        vp[k] = exact(v)
    return vp


def model_scene(c, **override):
    """The model's scene of a case, with rules overridden if asked (the
    self-checks draw one case under other conventions)."""
    rules = dict(c["rules"])
    rules.update(override)
    if rules["depth"] == "clamp":
        rules.pop("clip_z", None)
    tris = [(tuple(v.model() for v in p.v), p.interpolation or "perspective") for p in c["prims"]]
    return Scene(c["width"], c["height"], viewport_of(c), rules, tris)


def render(c, expect, description):
    lines = ["{"]
    lines.append('  "name": %s,' % js(c["name"]))
    lines.append('  "description": %s,' % js(description))
    lines.append('  "canvas": %s,' % js({"width": c["width"], "height": c["height"]}))
    if c["viewport"]:
        lines.append('  "viewport": %s,' % js(c["viewport"]))
    lines.append('  "rules": %s,' % js(c["rules"]))
    lines.append('  "primitives": [')
    lines.append(",\n".join("    " + js(p.json()) for p in c["prims"]))
    lines.append("  ],")
    lines.append('  "expect": %s' % js(expect))
    lines.append("}")
    text = "\n".join(lines) + "\n"
    json.loads(text)
    return text
