"""Random clip-space cases (`--random`), for a differential test of the
reference against the model (tests/clip_cases.rs): one to three random
triangles with vertices in front of, at and behind the eye, under random
conventions, viewports, depth ranges, fill rules, culls, subpixel bits and
provoking vertices, each pinned with the model's samples_covered.

Left out: a triangle whose original D is 0 (its snapped screen area is
zero, or its plane passes through the eye). Section 16.4 applies "D = 0
covers nothing" to each triangle that reaches rasterization, and culling
reads the original's D without discarding D = 0; so when clipping makes
pieces whose snapped D is not 0, the model draws them, while the reference
discards the whole triangle. Which one SPEC means is the lead's to say.
"""

import os
import random
from fractions import Fraction as F

from casegen.clip import mutants
from casegen.clip.check import random_vertex
from casegen.clip.build import CASES, CONVENTIONS, CV, Tri, case, model_scene, render
from casegen.clip.homogeneous import Piece, rasterize

FILL_RULES = ["top-left", "bottom-right", "top-right", "bottom-left", "all-edges"]


def _r(rng, lo, hi, den):
    return F(rng.randint(int(lo * den), int(hi * den)), den)


def _vertex(rng, den):
    v = random_vertex(rng, 1, den)
    return CV(*v[:4], attributes=v[4:])


def _one(rng, name):
    """Registers one random case (and returns it)."""
    den = rng.choice([4, 10, 97, 1000])
    vp = None
    if rng.random() < 0.5:
        vp = {"x": _r(rng, -2, 6, 4), "y": _r(rng, -2, 6, 4), "width": _r(rng, 4, 14, 4),
              "height": _r(rng, 4, 14, 4), "min_depth": _r(rng, 0, 1, 10),
              "max_depth": _r(rng, 0, 1, 10)}
    rules = dict(conv=rng.choice(list(CONVENTIONS)), subpixel_bits=rng.choice([0, 2, 4, 8, None]),
                 fill_rule=rng.choice(FILL_RULES), cull=rng.choice(["none", "cw", "ccw"]),
                 provoking_vertex=rng.choice(["first", "last"]))
    tris, count = [], rng.randint(1, 3)
    while len(tris) < count:
        t = Tri(*[_vertex(rng, den) for _ in range(3)],
                interpolation=rng.choice([None, "flat"]))
        case(name, "random", [t], width=12, height=12, viewport=vp, **rules)
        c = CASES.pop()
        if Piece([v.model() for v in t.v], model_scene(c).vp, c["rules"]["subpixel_bits"]).D != 0:
            tris.append(t)
    case(name, "A random clip-space case (tools/gen_clip.py --random).", tris, width=12,
         height=12, viewport=vp, **rules)
    return CASES.pop()


def write_random(seed, count, out_dir, wrong=False):
    """Writes `count` random cases into out_dir; with wrong, pins them with a
    wrong model (vertices behind the eye divided by their w)."""
    rng = random.Random(seed)
    os.makedirs(out_dir, exist_ok=True)
    for k in range(count):
        c = _one(rng, "random_%d_%d" % (seed, k))
        undo = mutants.swap("homogeneous", mutants.divided) if wrong else (lambda: None)
        try:
            n = len(rasterize(model_scene(c)))
        except ZeroDivisionError:
            n = 0
        finally:
            undo()
        with open(os.path.join(out_dir, c["name"] + ".json"), "w") as f:
            f.write(render(c, {"samples_covered": n}, c["description"]))
