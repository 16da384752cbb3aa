"""Wrong variants of the section 16 model (`--self-test`): each swaps one
piece of casegen/clip/homogeneous.py for a bug a real implementation has
(dividing before clipping, dividing by a negative w, a float clipper, y up,
ties away from zero, a closed guard band, an open depth range, clamping
that still clips, left and right swapped), and must change at least one
case's pin: the cases are what would catch a rasterizer with that bug.
"""

from fractions import Fraction as F

from casegen.clip import homogeneous as model
from casegen.clip.build import CASES, model_scene
from casegen.snapping import snap


def swap(name, value):
    old = getattr(model, name)
    setattr(model, name, value)
    return lambda: setattr(model, name, old)


def _ndc_intersect(p, q, dp, dq):
    """t from the distances divided by w: clipping after the divide."""
    if p[3] == 0 or q[3] == 0:
        return ORIGINAL["intersect"](p, q, dp, dq)
    a, b = dp / p[3], dq / q[3]
    t = a / (a - b) if a != b else F(1, 2)
    return tuple(u + t * (v - u) for u, v in zip(p, q))


def _float_intersect(p, q, dp, dq):
    """t in f64, from the far end: Q + t'(P - Q), t' = d(Q)/(d(Q) - d(P))."""
    t = float(dq) / (float(dq) - float(dp))
    return tuple(F(float(v) + t * (float(u) - float(v))) for u, v in zip(p, q))


def divided(v, vp, bits):
    """Every vertex divided by its w, whatever its sign."""
    x, y, _, w = v[:4]
    X, Y = model.screen_xy(v, vp, bits)
    return (X, Y, F(1)), 1 / w


def _screen_xy_y_up(v, vp, bits):
    x, y, _, w = v[:4]
    xf = vp["x"] + vp["width"] * (x / w + 1) / 2
    yf = vp["y"] + vp["height"] * (1 - y / w) / 2
    return snap(xf, bits), snap(yf, bits)


def _homogeneous_y_up(v, vp, bits):
    x, y, _, w = v[:4]
    if w > 0:
        X, Y = model.screen_xy(v, vp, bits)
        return (X, Y, F(1)), 1 / w
    return (w * vp["x"] + vp["width"] / 2 * (w + x),
            w * vp["y"] + vp["height"] / 2 * (w - y), w), F(1)


def _clamp_clips(scene):
    names = ["near", "far"] if scene.depth == "clamp" or scene.clip_z == "clip-then-snap" else []
    if scene.clip_xy == "clip-then-snap":
        names += ["left", "right", "top", "bottom"]
    return [(n, d) for n, d in model.PLANES if n in names]


def _mirrored_kind(a, b):
    kind = ORIGINAL["edge_kind"](a, b)
    return {"left": "right", "right": "left"}.get(kind, kind)


ORIGINAL = {name: getattr(model, name) for name in
            ("intersect", "homogeneous", "screen_xy", "snap", "in_viewport", "depth_in_range",
             "clipped_planes", "edge_kind")}

MUTANTS = [
    ("divide before clipping (t from z/w, x/w...)", "intersect", _ndc_intersect),
    ("clip t in f64 from the far end of the edge", "intersect", _float_intersect),
    ("vertices behind the eye divided by their w", "homogeneous", divided),
    ("viewport y up (y_ndc = -1 at the bottom)", "screen_xy", _screen_xy_y_up),
    ("viewport y up for the vertices behind the eye only", "homogeneous", _homogeneous_y_up),
    ("snapping ties away from zero", "snap", lambda v, bits: snap(v, bits, "away")),
    ("guard band rectangle closed [x, x + width]", "in_viewport",
     lambda sx, sy, vp: vp["x"] <= sx <= vp["x"] + vp["width"]
     and vp["y"] <= sy <= vp["y"] + vp["height"]),
    ("per-sample depth range open (0, 1)", "depth_in_range", lambda lo, hi: lo > 0 and hi > 0),
    ("depth clamp still clips near and far", "clipped_planes", _clamp_clips),
    ("left and right edges swapped in the fill rule", "edge_kind", _mirrored_kind),
]


def pins_under_mutant():
    """{case: samples_covered or the exception it raised} with a swap in place."""
    out = {}
    for c in CASES:
        try:
            out[c["name"]] = len(model.rasterize(model_scene(c)))
        except (ZeroDivisionError, OverflowError, ValueError) as e:
            out[c["name"]] = type(e).__name__
    return out


def run_mutants(counts):
    """Each wrong variant must change at least one pin; prints how many."""
    ok = True
    for what, name, bad in MUTANTS:
        undo = swap(name, bad)
        try:
            got = pins_under_mutant()
        finally:
            undo()
        changed = [n for n in counts if got[n] != counts[n]]
        example = ("e.g. %s %s -> %s" % (changed[0], counts[changed[0]], got[changed[0]])
                   if changed else "")
        print("%-12s %-50s %2d pins change  %s" % ("caught" if changed else "NOT CAUGHT", what,
                                                   len(changed), example))
        ok &= bool(changed)
    return ok
