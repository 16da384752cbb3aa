"""Cross-checks of the section 16 model (`--self-test`), each against
something written apart from it:

- ray cast: a Moeller-Trumbore intersection in (x, y, w) space of the ray
  from the eye through the sample with the triangle, kept where it meets the
  triangle at w > 0 (SPEC 16.4's third bullet), must agree with the
  homogeneous edge test at every sample on no edge, on random unsnapped
  triangles with vertices in front of, at and behind the eye;
- clip against per-sample: unsnapped, a triangle clipped (near and far,
  then the sides) covers what it covers unclipped under per-sample depth and
  the guard band, with the same depth and attributes, except at samples
  whose z_ndc is exactly 0 or 1;
- conventions agree (16.7): a triangle inside the clip volume is drawn alike
  under the six conventions, and as its screen-space triangle by
  casegen/clip/screen.py;
- values the cases' descriptions state (the provoking vertex's values in
  every piece, clamped depth ranges).
"""

import random
from fractions import Fraction as F

from casegen.clip import screen
from casegen.clip.build import CASES, CONVENTIONS, model_scene
from casegen.clip.homogeneous import Piece, Scene, rasterize, screen_xy

SEED = 16


def rational(rng, lo, hi, den=97):
    return F(rng.randint(int(lo * den), int(hi * den)), den)


def random_vertex(rng, attributes=1, den=97):
    """(x, y, z, w, attributes...): w behind, at or in front of the eye."""
    w = rng.choice([rational(rng, -2, -F(1, 10), den), F(0), rational(rng, F(1, 10), 3, den),
                    rational(rng, F(1, 10), 3, den), rational(rng, F(1, 10), 3, den)])
    scale = max(abs(w), F(1, 2))
    v = (rational(rng, -2 * scale, 2 * scale, den), rational(rng, -2 * scale, 2 * scale, den),
         rational(rng, -scale, 2 * scale, den), w)
    return v + tuple(F(rng.randint(-9, 9)) for _ in range(attributes))


def scene_of(tri, conv, size=12, bits=None, interpolation="perspective", vp=None):
    rules = {"subpixel_bits": bits, "fill_rule": "top-left", "cull": "none", "depth": "clip",
             "clip_z": "clip-then-snap", "provoking_vertex": "first"}
    rules.update(CONVENTIONS[conv])
    vp = vp or {"x": F(0), "y": F(0), "width": F(size), "height": F(size),
                "min_depth": F(0), "max_depth": F(1)}
    return Scene(size, size, vp, rules, [(tri, interpolation)])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross3(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot3(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def ray_cast(tri, s, vp):
    """'in', 'out' or 'edge': does the ray {t (ndc_x(s), ndc_y(s), 1), t > 0}
    from the eye meet the triangle's (x, y, w) points (Moeller-Trumbore)?"""
    d = (2 * (s[0] - vp["x"]) / vp["width"] - 1, 2 * (s[1] - vp["y"]) / vp["height"] - 1, F(1))
    v0, v1, v2 = [(v[0], v[1], v[3]) for v in tri]
    e1, e2 = sub(v1, v0), sub(v2, v0)
    p = cross3(d, e2)
    det = dot3(e1, p)
    if det == 0:
        return "out"
    tv = sub((F(0), F(0), F(0)), v0)
    u = dot3(tv, p) / det
    q = cross3(tv, e1)
    v = dot3(d, q) / det
    t = dot3(e2, q) / det
    if t <= 0 or u < 0 or v < 0 or u + v > 1:
        return "out"
    if u == 0 or v == 0 or u + v == 1:
        return "edge"
    return "in"


def check_ray_cast(rng, trials=150):
    compared = 0
    for _ in range(trials):
        tri = tuple(random_vertex(rng) for _ in range(3))
        scene = scene_of(tri, "gb_clamp")
        frame = rasterize(scene)
        for j in range(scene.height):
            for i in range(scene.width):
                r = ray_cast(tri, (F(2 * i + 1, 2), F(2 * j + 1, 2)), scene.vp)
                if r != "edge":
                    assert (r == "in") == ((i, j) in frame), ("ray cast", tri, i, j, r)
                    compared += 1
    return compared


def exact_z_ndc(tri, s, vp):
    """z_ndc of the unclipped, unsnapped triangle at s (None when D = 0)."""
    piece = Piece(tri, vp, None)
    if piece.D == 0:
        return None
    S = (s[0], s[1], F(1))
    e = [dot3(E, S) for E in piece.E]
    return sum(e[i] * piece.k[i] * tri[i][2] for i in range(3)) / piece.D


def check_clip_against_per_sample(rng, trials=60):
    compared = 0
    for _ in range(trials):
        tri = tuple(random_vertex(rng, 2) for _ in range(3))
        frames = {conv: rasterize(scene_of(tri, conv), values=True)
                  for conv in ("gb_ps", "gb_cts", "cts_cts", "cts_ps")}
        vp = scene_of(tri, "gb_ps").vp
        base = frames["gb_ps"]
        for conv, frame in frames.items():
            for key in set(base) | set(frame):
                if (key in base) != (key in frame):
                    z = exact_z_ndc(tri, (F(2 * key[0] + 1, 2), F(2 * key[1] + 1, 2)), vp)
                    assert z in (0, 1), ("clip against per-sample", conv, tri, key)
                    continue
                assert base[key] == frame[key], ("values", conv, tri, key)
                compared += 1
    return compared


def random_inside(rng):
    w = rational(rng, F(1, 4), 3)
    return (rational(rng, -w, w), rational(rng, -w, w), rational(rng, 0, w), w,
            F(rng.randint(-9, 9)))


def check_conventions_agree(rng, trials=60):
    tris = [tuple(random_inside(rng) for _ in range(3)) for _ in range(trials)]
    c = next(c for c in CASES if c["name"] == "spec_conventions_agree")
    tris.append(model_scene(c).triangles[0][0])
    for tri in tris:
        frames = [rasterize(scene_of(tri, conv, bits=8), values=True) for conv in CONVENTIONS]
        assert all(f == frames[0] for f in frames), ("conventions", tri)
        vp = scene_of(tri, "gb_ps").vp
        pts = [screen_xy(v, vp, None) for v in tri]
        flat = screen.coverage([pts], 12, 12, 8, "top-left")
        assert set(flat) == set(frames[0]), ("screen", tri)
    return len(tris)


def check_case_values():
    """What the descriptions state of values, on the model's full frames."""
    by = {c["name"]: c for c in CASES}

    def frame(name):
        return rasterize(model_scene(by[name]), values=True)
    for name in ("spec_provoking_last", "flat_provoking_first_clipped"):
        assert {cell[3] for cell in frame(name).values()} == {(0, 0, 1)}, name
    depths = {cell[2] for cell in frame("depth_clamp_reversed").values()}
    assert min(depths) == F(3, 10) and max(depths) == F(4, 5)
    assert min(cell[2] for cell in frame("spec_depth_clamp").values()) == F(1, 4)
    assert {cell[2] for cell in frame("spec_w_crossing").values()} == {F(1, 2)}
    # interpolate_from: unsnapped gives the values of the triangle drawn
    # unsnapped, and they part from the snapped positions' beyond 2^-16.
    unsnapped, snapped = frame("spec_interpolate_unsnapped"), frame("spec_interpolate_snapped")
    ideal = rasterize(model_scene(by["spec_interpolate_unsnapped"], subpixel_bits=None),
                      values=True)
    assert unsnapped.keys() == snapped.keys()
    assert all(unsnapped[k][2:] == ideal[k][2:] for k in unsnapped if k in ideal)
    apart = max(max(abs(unsnapped[k][2] - snapped[k][2]), abs(unsnapped[k][3][0] - snapped[k][3][0]))
                for k in unsnapped)
    assert apart > F(1, 2 ** 16), apart
    return 6


def run_all():
    rng = random.Random(SEED)
    n = check_ray_cast(rng)
    print("ray cast agrees with the homogeneous edge test at %d samples" % n)
    n = check_clip_against_per_sample(rng)
    print("clipped pieces agree with per-sample depth (coverage and values) at %d samples" % n)
    n = check_conventions_agree(rng)
    print("six conventions and the screen-space test agree on %d triangles" % n)
    n = check_case_values()
    print("%d statements of values in descriptions hold" % n)
    return True
