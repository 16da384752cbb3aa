"""An exact model of SPEC.md section 16, written from the text alone: the
clipper (16.3), the viewport and snapping (16.1, 2), the homogeneous sample
test with the fill rule on homogeneous edges, culling, the guard band's
viewport rectangle and the per-sample depth range (16.4), depth and
attributes (16.5) and the provoking vertex (16.6).

Everything is a Fraction; a sample's signs are taken from integer linear
forms (a triangle's edge coefficients times their common denominator, at
twice the sample's coordinates), which is the same sign, only faster.

The pieces are module-level functions looked up by name at each call, so
that casegen/clip/mutants.py can swap one for a deliberately wrong variant.
It shares nothing with rastercheck and, of casegen, only snapping.py.
"""

from fractions import Fraction as F
from math import lcm

from casegen.snapping import snap

HALF = F(1, 2)

# The planes of 16.3 in their order, each a signed distance of a vertex
# (x, y, z, w, attributes...): kept where d >= 0.
PLANES = [
    ("near", lambda v: v[2]),
    ("far", lambda v: v[3] - v[2]),
    ("left", lambda v: v[3] + v[0]),
    ("right", lambda v: v[3] - v[0]),
    ("top", lambda v: v[3] + v[1]),
    ("bottom", lambda v: v[3] - v[1]),
]

OWNED = {
    "top-left": {"top", "left"},
    "bottom-right": {"bottom", "right"},
    "top-right": {"top", "right"},
    "bottom-left": {"bottom", "left"},
    "all-edges": {"top", "left", "bottom", "right"},
}


class Scene:
    """What the model reads from a case: the canvas, the viewport (x, y, width,
    height, min_depth, max_depth as Fractions), the rules, and the triangles,
    each (vertices, interpolation) with a vertex a tuple of Fractions
    (x, y, z, w, a0, a1, ...)."""

    def __init__(self, width, height, viewport, rules, triangles):
        self.width, self.height = width, height
        self.vp = viewport
        self.bits = rules["subpixel_bits"]
        self.fill_rule = rules["fill_rule"]
        self.cull = rules["cull"]
        self.clip_xy = rules["clip_xy"]
        self.clip_z = rules.get("clip_z", "clip-then-snap")
        self.depth = rules["depth"]
        self.provoking = rules["provoking_vertex"]
        self.interpolate_from = rules.get("interpolate_from", "snapped")
        self.triangles = triangles


def clipped_planes(scene):
    """The planes this case clips (16.3)."""
    names = []
    if scene.depth == "clip" and scene.clip_z == "clip-then-snap":
        names += ["near", "far"]
    if scene.clip_xy == "clip-then-snap":
        names += ["left", "right", "top", "bottom"]
    return [(n, d) for n, d in PLANES if n in names]


def intersect(p, q, dp, dq):
    """The new vertex on the edge p -> q where the plane's distance is 0."""
    t = dp / (dp - dq)
    return tuple(a + t * (b - a) for a, b in zip(p, q))


def clip_polygon(poly, planes):
    """Sutherland-Hodgman, as 16.3 states it, one plane after another."""
    for _, d in planes:
        out = []
        n = len(poly)
        for i in range(n):
            p, q = poly[i], poly[(i + 1) % n]
            dp, dq = d(p), d(q)
            if dp >= 0:
                out.append(p)
            if (dp < 0 < dq) or (dq < 0 < dp):
                out.append(intersect(p, q, dp, dq))
        poly = out
    return poly


def fan(poly):
    if len(poly) < 3:
        return []
    return [(poly[0], poly[i], poly[i + 1]) for i in range(1, len(poly) - 1)]


def screen_xy(v, vp, bits):
    """(x_f, y_f) of a vertex with w > 0, snapped (16.1)."""
    x, y, _, w = v[:4]
    xf = vp["x"] + vp["width"] * (x / w + 1) / 2
    yf = vp["y"] + vp["height"] * (y / w + 1) / 2
    return snap(xf, bits), snap(yf, bits)


def homogeneous(v, vp, bits):
    """The homogeneous screen point H and weight k of a vertex (16.4)."""
    x, y, _, w = v[:4]
    if w > 0:
        X, Y = screen_xy(v, vp, bits)
        return (X, Y, F(1)), 1 / w
    return (w * vp["x"] + vp["width"] / 2 * (w + x),
            w * vp["y"] + vp["height"] / 2 * (w + y), w), F(1)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def edge_kind(a, b):
    """The kind of an edge whose sigma*E is a*s_x + b*s_y + c (16.4)."""
    if a > 0:
        return "left"
    if a < 0:
        return "right"
    if b > 0:
        return "top"
    if b < 0:
        return "bottom"
    return None


def owns(a, b, fill_rule):
    return edge_kind(a, b) in OWNED[fill_rule]


def culled(d, cull):
    return (cull == "cw" and d > 0) or (cull == "ccw" and d < 0)


def in_viewport(sx, sy, vp):
    """The guard band's rectangle, half-open (16.3)."""
    return vp["x"] <= sx < vp["x"] + vp["width"] and vp["y"] <= sy < vp["y"] + vp["height"]


def depth_in_range(above_near, below_far):
    """Per-sample depth clip: z_ndc in [0, 1], both ends included, given the
    signs of z_ndc and of 1 - z_ndc (each times a positive number)."""
    return above_near >= 0 and below_far >= 0


def integer_form(coeffs):
    """Integers (A, B, C) with the signs of a*s_x + b*s_y + c at every sample,
    evaluated at twice the sample's coordinates: A*(2i+1) + B*(2j+1) + 2C."""
    m = lcm(*[F(c).denominator for c in coeffs])
    return tuple(int(F(c) * m) for c in coeffs)


class Piece:
    """One triangle that reaches rasterization: its H, k, D and edges."""

    def __init__(self, verts, vp, bits):
        self.verts = verts
        hk = [homogeneous(v, vp, bits) for v in verts]
        self.H = [h for h, _ in hk]
        self.k = [k for _, k in hk]
        self.D = dot(self.H[0], cross(self.H[1], self.H[2]))
        # E_i = det[H_(i+1), H_(i+2), S] = (H_(i+1) x H_(i+2)) . S
        self.E = [cross(self.H[(i + 1) % 3], self.H[(i + 2) % 3]) for i in range(3)]


def rasterize(scene, values=False):
    """The frame: {(i, j): [count, last primitive, depth, attributes]} for
    every covered pixel centre (depth and attributes only with values)."""
    frame = {}
    vp = scene.vp
    planes = clipped_planes(scene)
    for index, (verts, interpolation) in enumerate(scene.triangles):
        original = Piece(verts, vp, scene.bits)
        if culled(original.D, scene.cull):
            continue
        for piece_verts in fan(clip_polygon(list(verts), planes)):
            piece = Piece(piece_verts, vp, scene.bits)
            draw_piece(scene, index, verts, interpolation, piece, frame, values)
    return frame


def draw_piece(scene, index, original, interpolation, piece, frame, values):
    D = piece.D
    if D == 0:
        return
    sigma = 1 if D > 0 else -1
    forms = []
    for a, b, c in piece.E:
        a, b, c = sigma * a, sigma * b, sigma * c
        forms.append((integer_form((a, b, c)), owns(a, b, scene.fill_rule)))
    per_sample = scene.depth == "clip" and scene.clip_z == "per-sample"
    # interpolate_from: unsnapped (16.5): values, and the per-sample depth
    # test, come from the piece's exact positions, unless it has no area.
    exact = None
    if scene.interpolate_from == "unsnapped" and scene.bits is not None:
        exact = Piece(piece.verts, scene.vp, None)
        if exact.D == 0:
            exact = None
    guard = scene.clip_xy == "guard-band"
    for j in range(scene.height):
        sy2 = 2 * j + 1
        for i in range(scene.width):
            sx2 = 2 * i + 1
            inside = True
            for (A, B, C), owned in forms:
                e = A * sx2 + B * sy2 + 2 * C
                if e < 0 or (e == 0 and not owned):
                    inside = False
                    break
            if not inside:
                continue
            s = (F(sx2, 2), F(sy2, 2))
            if guard and not in_viewport(s[0], s[1], scene.vp):
                continue
            by = piece
            if exact is not None and in_front(exact, s):
                by = exact
            if per_sample:
                z = z_ndc(by, s)
                if not depth_in_range(z, 1 - z):
                    continue
            cell = frame.setdefault((i, j), [0, None, None, None])
            cell[0] += 1
            cell[1] = index
            if values:
                cell[2], cell[3] = sample_values(scene, original, interpolation, by, s)
    return frame


def weights(piece, s):
    """E_i(s)*k_i, divided by D (the signs cancel)."""
    S = (s[0], s[1], F(1))
    return [dot(piece.E[i], S) * piece.k[i] / piece.D for i in range(3)]


def in_front(piece, s):
    """Whether the piece's plane lies in front of the eye at s."""
    return sum(weights(piece, s)) > 0


def z_ndc(piece, s):
    return sum(w * v[2] for w, v in zip(weights(piece, s), piece.verts))


def sample_values(scene, original, interpolation, piece, s):
    """Depth written and attributes at a covered sample (16.5)."""
    S = (s[0], s[1], F(1))
    e = [dot(E, S) for E in piece.E]
    ek = [e[i] * piece.k[i] for i in range(3)]
    z_ndc = sum(ek[i] * piece.verts[i][2] for i in range(3)) / piece.D
    vp = scene.vp
    depth = vp["min_depth"] + (vp["max_depth"] - vp["min_depth"]) * z_ndc
    if scene.depth == "clamp" or scene.interpolate_from == "unsnapped":
        lo, hi = sorted((vp["min_depth"], vp["max_depth"]))
        depth = min(max(depth, lo), hi)
    if interpolation == "flat":
        attrs = tuple(original[0 if scene.provoking == "first" else 2][4:])
    else:
        total = sum(ek)
        attrs = tuple(sum(ek[i] * piece.verts[i][4 + a] for i in range(3)) / total
                      for a in range(len(original[0]) - 4))
    return depth, attrs


def samples_covered(scene):
    return len(rasterize(scene))
