#!/usr/bin/env python3
"""Writes the catalogue of hard cases: cases/hard/*.json.

Python 3 standard library only. Every coordinate is an exact rational
(fractions.Fraction) written as in tools/gen_cases.py (integers, terminating
decimals, or "p/q" strings), and every vertex that two triangles share is
computed once and written identically in both.

Each case's description says why it is hard. The numbers in
`expect.samples_covered` come only from the small exact checker at the
bottom of this file, written from SPEC.md alone (it shares no code with
rastercheck): snapping with ties to even (section 2), edge ownership in
D3D11's words (where does the third vertex lie? section 3), the midpoint
line rule (section 4.1), and the mesh interior of section 6.2. With
`--check` it also proves each case's claims: that the mesh is watertight
under its own rule, that the stated samples are the crack, that the flipped
fill rule or snapping ties half away from zero changes the picture, that
the degenerate triangles have zero area, how many bits the edge products
need, and so on.

Families (the case names start with the family):

  edge_halfint_*    vertices at half-integers: samples exactly on shared edges
  fan_*             64+ triangles around one sample point
  flipped_*         shared edges drawn with vertex order and winding flipped
  far_b8_*          vertices near +-32768 px at 8 subpixel bits
  sliver_*          near-collinear and collinear triangles
  tjunction_*       a genuine crack (and its overdraw twin) at a T-junction
  miss_*            triangles that cover no sample
  snaptie_*         vertices exactly half a subpixel off the grid
  persp_*           w from 0.001 to 1000, attributes up to +-1e6
  line_*            midpoint ties and 1000+ px lines
  overlap_*         self-overlapping fans (coverage 2 and more)
  far_b16_*         a 16-subpixel-bit mesh at +-32768 (i128 in production)
  unsnapped_*       subpixel_bits null, dyadic coordinates with ties
  degenerate_*      zero-area triangles inside a mesh
  rules_far_*       every fill rule on one tie-heavy mesh at large coordinates

Polygons and antialiasing (SPEC.md section 14; expectations from the exact
checker of tools/gen_aa_cases.py, imported, with each case's claims asserted
here: exact total areas from the shoelace formula, full pixels, no sample
covered twice, the same samples as a simpler scene):

  aa_abut_*         fans of 64 and 128 triangles, a 200-triangle grid tiling a
                    square, a far square with a far hole, at standard 16x:
                    coverages that must sum to exactly 1
  poly_*            self-overlapping polygons (winding twice, overlapping
                    contours, doubled edges, repeated and collinear vertices,
                    zero-area contours), with and without 16x, both fills;
                    poly_far_*: vertices near +-32768 px at 8 bits
  aa_sliver_*       antialiased slivers and near-collinear triangles
  aa_tie_*          samples on shared edges and vertices under 16x

Usage: python3 tools/gen_hard_cases.py [--check]   (run from anywhere)
"""

import json
import math
import os
import sys
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exactjson import exact, js  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT_DIR = os.path.join(ROOT, "cases", "hard")

HALF = F(1, 2)
COORD_LIMIT = 32768


def P(x, y):
    return (exact(x), exact(y))


def add(p, q, k=1):
    return (p[0] + k * q[0], p[1] + k * q[1])


class V:
    """A vertex with depth, w and attributes (the object form)."""

    def __init__(self, x, y, z=None, w=None, attributes=None):
        self.x, self.y = exact(x), exact(y)
        self.z, self.w, self.attributes = z, w, attributes

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


class Line:
    def __init__(self, a, b, last_pixel=None):
        self.v = [a, b]
        self.last_pixel = last_pixel

    def json(self):
        d = {"line": [vjson(v) for v in self.v]}
        if self.last_pixel is not None:
            d["last_pixel"] = self.last_pixel
        return d


CASES = []


def case(name, description, width, height, prims, bits=8, fill_rule="top-left", cull="none",
         watertight=False, checks=(), long_line=False):
    """Registers a case. `checks` are claims the checker must prove (see
    check_claims)."""
    if not long_line:
        assert 1 <= width <= 128 and 1 <= height <= 128, name
    for p in prims:
        for v in p.v:
            for q in pos_of(v):
                assert abs(q) <= COORD_LIMIT, (name, q)
    CASES.append(dict(name=name, description=description, width=width, height=height,
                      prims=prims, bits=bits, fill_rule=fill_rule, cull=cull,
                      watertight=watertight, checks=list(checks)))


def render(c, expect):
    lines = ["{"]
    lines.append('  "name": %s,' % js(c["name"]))
    lines.append('  "description": %s,' % js(c["description"]))
    lines.append('  "canvas": %s,' % js({"width": c["width"], "height": c["height"]}))
    lines.append('  "rules": %s,' % js({"subpixel_bits": c["bits"], "fill_rule": c["fill_rule"],
                                          "cull": c["cull"]}))
    lines.append('  "primitives": [')
    lines.append(",\n".join("    " + js(p.json()) for p in c["prims"]))
    lines.append("  ],")
    lines.append('  "expect": %s' % js(expect))
    lines.append("}")
    text = "\n".join(lines) + "\n"
    json.loads(text)
    return text


def grid_mesh(xs, ys, diag=lambda i, j: (i + j) % 2, orders=None):
    """Triangles of the grid xs x ys, each cell split along one diagonal.
    orders(i, j, k) may permute a triangle's vertices (flipping its winding)."""
    tris = []
    for j in range(len(ys) - 1):
        for i in range(len(xs) - 1):
            p00, p10 = P(xs[i], ys[j]), P(xs[i + 1], ys[j])
            p01, p11 = P(xs[i], ys[j + 1]), P(xs[i + 1], ys[j + 1])
            if diag(i, j):
                pair = [[p00, p10, p11], [p00, p11, p01]]
            else:
                pair = [[p00, p10, p01], [p10, p11, p01]]
            for k, t in enumerate(pair):
                if orders:
                    t = orders(i, j, k, t)
                tris.append(Tri(*t))
    return tris


# ---------------------------------------------------------------------------
# 1. Samples exactly on shared edges: vertices at half-integers.

XS = [0.5, 3.5, 5.5, 9.5, 10.5, 14.5, 17.5, 21.5, 23.5]
YS = [0.5, 2.5, 6.5, 7.5, 11.5, 14.5, 18.5, 20.5, 23.5]
case("edge_halfint_grid",
     "An 8x8 grid of uneven cells (widths 1 to 4 px) whose every vertex is a sample point "
     "(half-integer coordinates), each cell split along alternating diagonals: 128 triangles. Every "
     "horizontal and vertical edge runs along a row or column of samples, every diagonal of a square "
     "cell passes through samples, and every interior vertex is a sample shared by 4 to 8 triangles. "
     "Each sample on a shared edge or vertex must be covered exactly once (top-left). A rasterizer with "
     "closed edges overdraws ~200 samples, one with open edges leaves them as holes.",
     24, 24, grid_mesh(XS, YS), watertight=True, checks=[("ties", 150), ("flip_changes",)])


def sheared(i, j):
    return P(F(1, 2) + 4 * i + 2 * j - 8, F(1, 2) + 4 * j - i + 4)


SH = [[sheared(i, j) for i in range(9)] for j in range(9)]
SH_TRIS = []
for j in range(8):
    for i in range(8):
        a, b, c, d = SH[j][i], SH[j][i + 1], SH[j + 1][i + 1], SH[j + 1][i]
        if (i * 3 + j) % 2:
            SH_TRIS += [Tri(a, b, c), Tri(a, c, d)]
        else:
            SH_TRIS += [Tri(a, b, d), Tri(b, c, d)]
case("edge_halfint_sheared",
     "A sheared 8x8 lattice mesh (cell vectors (4,-1) and (2,4)) with every vertex on a sample "
     "point, 128 triangles. Edges have slopes -1/4, 2, and the diagonals (6,3) and (2,5)/(-2,5): "
     "the first two and (6,3) pass through further samples between their ends, so the tie rule "
     "decides samples on edges of every direction class (left edges going up, right edges going down, "
     "shallow and steep). Watertight: no hole and no sample covered twice.",
     32, 32, SH_TRIS, watertight=True, checks=[("ties", 100), ("flip_changes",)])

# ---------------------------------------------------------------------------
# 2. Fans of 64+ triangles around one sample point.


def square_ring(centre, half, step=1):
    """Points on the square of half-size `half` around centre, clockwise on
    screen from the top-left corner, every `step` px."""
    cx, cy = centre
    pts = []
    for k in range(-half, half, step):
        pts.append((cx + k, cy - half))
    for k in range(-half, half, step):
        pts.append((cx + half, cy + k))
    for k in range(half, -half, -step):
        pts.append((cx + k, cy + half))
    for k in range(half, -half, -step):
        pts.append((cx - half, cy + k))
    return pts


def fan(centre, rim, close=True):
    n = len(rim)
    return [Tri(centre, rim[k], rim[(k + 1) % n]) for k in range(n if close else n - 1)]


C16 = P(16.5, 16.5)
case("fan_128_square_sample",
     "128 triangles around the sample (16.5, 16.5), their rim the square of half-size 16 with a "
     "vertex on every sample of its border. Each spoke (k, -16) runs from the centre to a sample and "
     "passes through gcd(k, 16) - 1 further samples; the centre sample itself lies on all 128 "
     "triangles' vertex and must be covered by exactly one. The fan is closed: every sample strictly "
     "inside the square is covered once. Watertight.",
     33, 33, fan(C16, square_ring(C16, 16)), watertight=True, checks=[("ties", 100)])

RIM72 = []
for k in range(72):
    t = 2 * math.pi * k / 72
    p = (int(round(19 * math.cos(t))), int(round(19 * math.sin(t))))
    if not RIM72 or p != RIM72[-1]:
        RIM72.append(p)
C20 = P(20.5, 20.5)
case("fan_72_circle_b4",
     "A fan of %d triangles around the sample (20.5, 20.5) at 4 subpixel bits, its rim points on a "
     "circle of radius 19 rounded to whole pixels, so every spoke ends on a sample and those with a "
     "common factor in their direction (the axes, the diagonals, (2,-4) ...) pass through samples "
     "on the way. Neighbouring spokes are between 1 and 5 degrees apart: thin triangles meeting at one "
     "sample, which exactly one of them must own. Watertight." % len(RIM72),
     41, 41, fan(C20, [add(C20, p) for p in RIM72]), bits=4, watertight=True,
     checks=[("ties", 40)])

# ---------------------------------------------------------------------------
# 3. Shared edges with the vertex order and winding flipped between the two
# triangles.


def flip_order(i, j, k, t):
    """Rotates the vertex list by (i + 2j + k) mod 3 and reverses it for
    every other triangle: the two triangles of a shared edge list it in the
    same direction as often as not."""
    r = (i + 2 * j + k) % 3
    t = t[r:] + t[:r]
    if (i * 5 + j * 3 + k) % 2:
        t = [t[0], t[2], t[1]]
    return t


case("flipped_order_grid",
     "The mesh of edge_halfint_grid with each triangle's vertex list rotated and, for half of them, "
     "reversed: neighbours list their shared edge in the same direction as often as in opposite "
     "directions, and clockwise and counter-clockwise triangles alternate. Ownership must follow the "
     "side the triangle lies on, never the order its vertices are given in: a rasterizer that "
     "classifies edges by their direction before orienting the triangle gives shared-edge samples to "
     "both triangles or to neither.",
     24, 24, grid_mesh(XS, YS, orders=flip_order), watertight=True,
     checks=[("ties", 150), ("windings_mixed",)])

RIM64 = square_ring(P(12.5, 12.5), 8, 1)
FLIP_FAN = []
for k in range(64):
    a, b = RIM64[k], RIM64[(k + 1) % 64]
    c = P(12.5, 12.5)
    FLIP_FAN.append(Tri(*[[c, a, b], [b, a, c], [a, c, b], [a, b, c]][k % 4]))
case("flipped_order_fan_64",
     "64 triangles around the sample (12.5, 12.5), rim on the samples of a square of half-size 8; "
     "each spoke is shared by two triangles and each triangle is written in one of four vertex orders "
     "(two clockwise, two counter-clockwise), so a spoke's two triangles often list it in the same "
     "direction. Every spoke passes through samples; each must be covered exactly once. Watertight.",
     25, 25, FLIP_FAN, watertight=True, checks=[("ties", 50), ("windings_mixed",)])

# ---------------------------------------------------------------------------
# 4. Coordinates near +-32768 at 8 subpixel bits; 12. the same at 16 bits.


def far_bands(u, first, count, anchor, offset, reach, jitter, bits):
    """A mesh of long bands across the canvas. Band boundary k is the line
    through anchor + k*offset with direction u (small integers), so it passes
    through a sample every |u| along the canvas; its ends lie `reach` steps of
    u away on either side (plus a few subpixels of jitter along the line, so
    that the vertices use every fraction bit). Each band is split along a
    far diagonal. Returns the triangles and the boundary end points."""
    ends = []
    unit = F(1, 2**bits)
    for k in range(first, first + count + 1):
        p = add(anchor, offset, k)
        m = reach[0] - 7 * (k - first) - (2 * ((k * 37) % 11) + 1) * jitter * unit
        n = reach[1] - 5 * (k - first) - (2 * ((k * 53) % 13) + 1) * jitter * unit
        ends.append((add(p, u, -m), add(p, u, n)))
    tris = []
    for k in range(count):
        (a0, b0), (a1, b1) = ends[k], ends[k + 1]
        tris += [Tri(a0, b0, b1), Tri(a0, b1, a1)]
    return tris, ends


FAR8, FAR8_ENDS = far_bands(P(3, 1), -8, 30, P(0.5, 0.5), P(0, 3), (10900, 10900), 1, 8)
case("far_b8_bands",
     "60 triangles in 30 bands crossing a 64x64 canvas; every vertex is about 32000 px away "
     "(x from -32700 to +32700) with an 8-bit fraction, and every band boundary has direction (3, 1) "
     "and passes through a sample every 3 columns: {ties} samples lie exactly on edges. In 16.9 "
     "fixed point the edge products reach {bits} bits (SPEC 8 bounds them by 2b + 3 = 51 with the sign), far beyond an f32 "
     "mantissa. At a shared-edge sample the two products are the same real number, so a float "
     "computes them equally whenever the coordinate differences are exact: an f32 rasterizer goes "
     "wrong only where a 25-bit difference such as 65400 + k/256 is rounded (far_b8_near_tie_fan is "
     "the case that breaks it for sure). The mesh covers the whole canvas once: watertight.",
     64, 64, FAR8, watertight=True, checks=[("ties", 450), ("product_bits", 47), ("far", 30000)])

FAR8S, _ = far_bands(P(1, -2), -1, 48, P(0.5, 0.5), P(2, 0), (16000, 16000), 3, 8)
case("far_b8_bands_steep",
     "The far_b8_bands construction with steep boundaries of direction (1, -2) through a sample on "
     "every other row, ends near y = +-32000, and vertices 3/256 px apart along the line from the "
     "simple multiples: 96 triangles, left edges going up and right edges going down, {ties} samples "
     "on edges. Exact in i64 in production; f32 rounds the 25-bit differences of the far y "
     "coordinates and gives a few shared-edge samples to the wrong band. "
     "Watertight.",
     64, 64, FAR8S, watertight=True, checks=[("ties", 450), ("product_bits", 47), ("far", 30000)])



def far_strip(bits, count, start, frac):
    """A strip of 2*count triangles between two far rails, built as a
    zig-zag chain of long edges, each through a sample S_i of the canvas
    one third of the way from its right end: L = 3S - 2R, then R' = (3S' -
    L)/2, and so on (the right ends keep bits-1 fraction bits, the left ones
    bits-2, so both stay on the grid). Every long edge passes exactly through
    one sample, its direction is generic (large coprime components), and
    consecutive edges share a far vertex."""
    unit = F(1, 2**(bits - 1))
    samples = [P(F(65, 2) + ((i * 5) % 13) - 6, F(1, 2) + i) for i in range(2 * count + 1)]
    chain = [add(start, (frac[0] * unit, frac[1] * unit))]   # R0
    for i, s in enumerate(samples):
        q = chain[-1]
        if i % 2 == 0:
            chain.append((3 * s[0] - 2 * q[0], 3 * s[1] - 2 * q[1]))
        else:
            chain.append(((3 * s[0] - q[0]) / 2, (3 * s[1] - q[1]) / 2))
    # chain: R0, L0, R1, L1, R2, ...
    R = chain[0::2]
    L = chain[1::2]
    tris = []
    for k in range(count):
        tris += [Tri(L[k], R[k], R[k + 1]), Tri(L[k], R[k + 1], L[k + 1])]
    return tris


STRIP8 = far_strip(8, 31, P(16300.5, 1500.5), (77, 33))
case("far_b8_strip",
     "62 triangles in a strip between two rails ~32000 px to the left and ~16000 px to the right of a "
     "64x64 canvas, at 8 subpixel bits. Its long edges form a zig-zag chain, each passing exactly "
     "through one sample of the canvas a third of the way from its right end, with a generic "
     "direction (about (48000, 4500) with 7- and 6-bit fractions at its ends): the exact edge "
     "function there is 0, but its two products are ~2^31 px^2 with {bits}-bit integers behind them "
     "(16.9 fixed point). At the sample both products are the same real number, so a float "
     "whose coordinate differences are exact still gets 0: the case pins production's exactness, "
     "and far_b8_near_tie_fan is the one that breaks floats. Watertight.",
     64, 64, STRIP8, watertight=True, checks=[("ties", 60), ("product_bits", 45), ("far", 31000)])

STRIP16 = far_strip(16, 31, P(16300.5, 1500.5), (19777, 10133))
case("far_b16_strip",
     "The far_b8_strip construction at 16 subpixel bits: 62 triangles whose far vertices carry "
     "16-bit fractions, every long edge through exactly one sample of the canvas with a generic "
     "direction. The edge products need {bits} bits in 16.17 fixed point (i128 in production) and "
     "exceed f64's 53-bit mantissa; at an exact 0 both products are the same real number, so f64 "
     "survives, while f32, which rounds the 16-bit fractions of the coordinates themselves, "
     "overdraws. Watertight.",
     64, 64, STRIP16, bits=16, watertight=True,
     checks=[("ties", 60), ("product_bits", 60), ("far", 31000)])

USTRIP = far_strip(16, 31, P(16300.5, 1500.5), (12345, 6001))
case("unsnapped_far_strip",
     "subpixel_bits null: the far_b16_strip construction with 16-bit dyadic far vertices used "
     "exactly. No snapping hides anything: the long edges pass exactly through one sample each, with "
     "products of {bits} bits in production's 16.17 fixed point, beyond f64; f32 cannot hold "
     "the coordinates and overdraws. Watertight.",
     64, 64, USTRIP, bits=None, watertight=True,
     checks=[("ties", 60), ("product_bits", 60), ("far", 31000)])


def egcd(a, b):
    """(g, x, y) with a*x + b*y = g = gcd(a, b)."""
    if b == 0:
        return (a, 1, 0)
    g, x, y = egcd(b, a % b)
    return (g, y, x - (a // b) * y)


def near_tie_fan(bits, apex, samples):
    """A fan from a far apex O whose every spoke misses a sample S_k by the
    least amount the grid allows: with S_k - O = (U, V) and the spoke
    O -> R_k = (X, Y) in units of 2^-bits, X*V - Y*U = +-1, so the exact edge
    function at S_k is +-2^-2bits px^2 while its two products are ~2^31 px^2.
    R_k is the solution nearest 2 S_k - O."""
    unit = 2**bits
    O = apex
    rim, signs = [], []
    for k, S in enumerate(samples):
        U, V = int((S[0] - O[0]) * unit), int((S[1] - O[1]) * unit)
        g, x, y = egcd(V, U)          # V*x + U*y = g
        if g != 1:
            continue
        sign = 1 if k % 2 else -1
        X0, Y0 = sign * x, -sign * y  # X0*V - Y0*U = sign
        t = (2 * U - X0) // U
        X, Y = X0 + t * U, Y0 + t * V
        assert X * V - Y * U == sign
        rim.append((O[0] + F(X, unit), O[1] + F(Y, unit)))
        signs.append(sign)
    return fan(O, rim, close=False), len(rim)


def generic_slivers(bits, offsets, base_y):
    """Long triangles through one sample S with a generic direction v: A = S
    - 3v, B = S + 4v, third vertex S + v + offset (offset 0: collinear)."""
    unit = F(1, 2**bits)
    tris = []
    for k, off in enumerate(offsets):
        s = P(F(5, 2) + 7 * k, base_y + 3 * k)
        v = (6500 + 13 * k + (2 * k + 37) * unit, 650 - 31 * k + (4 * k + 11) * unit)
        a, b = add(s, v, -3), add(s, v, 4)
        c = add(add(s, v), (off[0] * unit, off[1] * unit))
        tris.append(Tri(a, b, c) if k % 2 else Tri(c, a, b))
    return tris


NT_SAMPLES = [P(F(1, 2) + 4 * k, F(127, 2) - 4 * k) for k in range(16)]
NT8, n8 = near_tie_fan(8, P(F(-8179183, 256), F(-8179201, 256)), NT_SAMPLES)
case("far_b8_near_tie_fan",
     "A fan of %d triangles from a far apex O = (-31949.93..., -31950.00...) whose spokes end ~32000 "
     "px beyond the canvas; each spoke misses a sample of the canvas (on the anti-diagonal, every 4 "
     "px) by the least amount the 8-bit grid allows: the exact edge function there is +-2^-16 px^2, "
     "alternately inside the triangle before and after the spoke, while the two products it is the "
     "difference of are ~2^31 px^2 ({bits}-bit integers in 16.9 fixed point). No sample lies on an "
     "edge, so the fill rule decides nothing; an f32 edge function (ulp 2^8 px^2 there) rounds "
     "the difference to 0 or to a few hundred px^2 of either sign, and the sample goes to the "
     "tie rule's choice or to both or neither neighbour." % (n8 - 1),
     64, 64, NT8, checks=[("product_bits", 45), ("far", 31000)])

NT16, n16 = near_tie_fan(16, P(F(-2093871111, 65536), F(-2093875207, 65536)), NT_SAMPLES)
case("far_b16_near_tie_fan",
     "The far_b8_near_tie_fan construction at 16 subpixel bits: %d triangles from an apex near "
     "(-31950, -31950), each spoke missing a canvas sample by an exact edge value of +-2^-32 px^2 "
     "(16.17 fixed point: products of {bits} bits, i128 in production). Every difference of vertex "
     "coordinates is exact in f64 (33 bits), but each product needs ~64 bits: f64 rounds both to "
     "the same value (ulp 2^-21 px^2) or to neighbours, the sign of the edge function is lost, and "
     "the sample goes to the wrong side of the spoke." % (n16 - 1),
     64, 64, NT16, bits=16, checks=[("product_bits", 60), ("far", 31000)])

# ---------------------------------------------------------------------------
# 5. Slivers: collinear and near-collinear triangles.

SL_U = P(3, 1)
SL_P = P(2.5, 10.5)
SLIVERS0 = []
for k, (m, n, t) in enumerate([(10000, 10000, 37), (10800, 9000, -5123), (7000, 10900, 11),
                               (10917, 10917, 10000)]):
    m = m + F(2 * k + 1, 256)
    n = n - F(2 * k + 3, 256)
    a, b, c = add(SL_P, SL_U, -m), add(SL_P, SL_U, n), add(SL_P, SL_U, F(t) + F(5, 256))
    SLIVERS0.append(Tri(a, b, c) if k % 2 else Tri(c, b, a))
SLIVERS0 += generic_slivers(8, [(0, 0)] * 8, F(3, 2))
case("sliver_far_collinear_b8",
     "Twelve triangles whose three vertices are exactly collinear on the 8-bit grid: four on the line "
     "through (2.5, 10.5) with direction (3, 1) (through about 20 samples of the canvas), eight on "
     "lines through one sample each with generic directions near (6500, 650) and 8-bit fractions; "
     "ends ~30000 px away, the third vertex inside or beyond the segment. Zero area, so nothing is "
     "drawn. The exact area is 0 but its two products are ~2^31 px^2, far beyond "
     "f32's 24-bit mantissa: the degeneracy must be decided exactly (a float gets 0 here only "
     "because each pair of products is the same real number from exact differences).",
     64, 32, SLIVERS0, checks=[("zero_covered",), ("degenerate", 12)])

SLIVERS1 = []
for k, (m, n, t, off) in enumerate([(10000, 10000, 17, (0, F(1, 256))),
                                    (10900, 9000, -3000, (0, F(-1, 256))),
                                    (9500, 10900, 4001, (F(1, 256), 0)),
                                    (10917, 10000, 20, (F(-3, 256), F(1, 256)))]):
    p = add(P(0.5, 4.5 + 6 * k), P(0, 0))
    a, b = add(p, SL_U, -(m + F(2 * k + 1, 256))), add(p, SL_U, n - F(2 * k + 1, 256))
    c = add(add(p, SL_U, t), off)
    SLIVERS1.append(Tri(a, b, c))
SLIVERS1 += generic_slivers(8, [(0, 1), (0, -1), (1, 0), (-1, 0), (0, 2), (0, -2), (3, 1), (-3, -1)],
                            F(5, 2))
case("sliver_far_offset_b8",
     "Twelve long slivers, ~65000 px long, whose third vertex lies one or a few subpixels (1/256 px) "
     "off the line through the other two; four long edges pass through a sample every 3 columns of "
     "the canvas, eight (generic directions near (6500, 650)) through exactly one sample each. Exactly, the twice-area is a few hundred px^2 against products of ~2^31 px^2, so in "
     "f32 the orientation is within rounding of 0. A sliver covers exactly the samples on its long "
     "edge when the fill rule owns that edge: those above a left edge (third vertex above or to the "
     "right) are drawn, the others not.",
     64, 32, SLIVERS1, checks=[("ties", 40), ("flip_changes",), ("far", 29000)])

SLIVERS16 = []
for k, (m, n, t, off) in enumerate([(10000, 10000, 17, (0, F(1, 65536))),
                                    (10900, 9000, -3000, (0, F(-1, 65536))),
                                    (9500, 10900, 4001, (F(1, 65536), 0)),
                                    (10917, 10000, 20, (F(-3, 65536), F(1, 65536)))]):
    p = P(0.5, 4.5 + 6 * k)
    a = add(p, SL_U, -(m + F(2 * k + 1, 65536)))
    b = add(p, SL_U, n - F(2 * k + 5, 65536))
    c = add(add(p, SL_U, F(t) + F(7, 65536)), off)
    SLIVERS16.append(Tri(a, b, c))
a = add(P(0.5, 28.5), SL_U, -F(655360001, 65536))
b = add(P(0.5, 28.5), SL_U, F(655360003, 65536))
c = add(P(0.5, 28.5), SL_U, F(123456789, 65536))
SLIVERS16.append(Tri(a, b, c))
SLIVERS16 += generic_slivers(16, [(0, 1), (0, -1), (0, 0), (1, 0), (-1, 0), (0, 0), (3, 1), (-3, -1)],
                             F(3, 2))
case("sliver_far_b16",
     "The slivers of sliver_far_offset_b8 at 16 subpixel bits: the third vertex 1/65536 px off the "
     "long edge, every vertex with a 16-bit fraction ~30000 px from the canvas, eight more through "
     "one sample each with generic directions (two of them exactly collinear), plus one exactly "
     "collinear triangle along the line through (0.5, 28.5); the collinear ones draw nothing. Edge products "
     "need ~64 bits, more than f64's 53, and production needs i128. f32 cannot hold the 16-bit fractions and "
     "loses the slivers; f64 holds them and keeps the exact zeros of the on-edge samples.",
     64, 32, SLIVERS16, bits=16, checks=[("ties", 40), ("degenerate", 3), ("product_bits", 60)])

SMALL = [
    # Not collinear as written, collinear after snapping: 3.5 + 1/1000 snaps to 3.5.
    Tri(P(0.5, 2.5), P(6.5, 4.5), P(3.5, F(7, 2) + F(1, 1000))),
    # Snaps to an exactly collinear triple on the diagonal through samples.
    Tri(P(0.5, 6.5), P(12.5, 18.5), P(F(13, 2) + F(1, 600), F(25, 2) - F(1, 700))),
    # Nonzero after snapping: one subpixel off the diagonal through samples.
    Tri(P(14.5, 0.5), P(30.5, 16.5), P(22.5, F(17, 2) - F(1, 256))),
    Tri(P(14.5, 6.5), P(30.5, 22.5), P(22.5, F(29, 2) + F(1, 256))),
]
case("sliver_snap_collinear",
     "Near-collinear triangles near the origin. The first two are not collinear as written but "
     "snapping (ties to even) makes them exactly collinear: zero area, nothing drawn, although their "
     "lines pass through samples. The last two have their middle vertex one subpixel (1/256 px) off a "
     "diagonal through 16 samples: twice-area 1/16 px^2, nonzero. The one whose middle vertex is above "
     "the diagonal (a left long edge) covers the 15 samples on it between its ends; the other (a right "
     "long edge) covers none of them, under top-left: 15 samples in all.",
     32, 24, SMALL, checks=[("degenerate", 2), ("ties", 25), ("flip_changes",), ("covered", 15)])

# ---------------------------------------------------------------------------
# 6. T-junctions.

TJ_A, TJ_B = P(0.5, 0.5), P(96.5, 32.5)
TJ_E, TJ_D = P(96.5, 0.5), P(0.5, 32.5)
TJ_M = P(49.5, F(1, 2) + F(49, 3))         # on the long edge, y = 16.8333...
CRACK = [(3 * k, k) for k in range(1, 32)]
case("tjunction_crack",
     "A genuine crack that no fill rule fixes. The rectangle [0.5, 96.5] x [0.5, 32.5] is split by "
     "its diagonal A = (0.5, 0.5) to B = (96.5, 32.5) into a lower triangle A, B, (0.5, 32.5) and, "
     "above it, two triangles meeting at M = (49.5, 16.8333...), which lies on AB exactly as written "
     "(a T-junction). Snapping moves M to y = 16.83203125, 1/768 px above AB, so the polyline A-M-B "
     "leaves a sliver open above AB. The diagonal passes through the 31 samples (3k + 0.5, k + 0.5) "
     "for k = 1..31 (pixels (3,1) (6,2) ... (93,31)); it is a right edge of the lower triangle, which "
     "does not own them under top-left, and the upper triangles no longer reach them: these 31 "
     "samples are the expected crack, left uncovered by the reference. Not watertight by design.",
     97, 33, [Tri(TJ_A, TJ_B, TJ_D), Tri(TJ_A, TJ_M, TJ_E), Tri(TJ_M, TJ_B, TJ_E)],
     checks=[("crack", (0, 0, 96, 32), CRACK), ("snap_moves", TJ_M)])

TJ_M2 = P(50.5, F(1, 2) + F(50, 3))        # y = 17.1666..., snaps 1/768 px below AB
case("tjunction_overlap_bottom_right",
     "The T-junction of tjunction_crack with its middle vertex at M = (50.5, 17.1666...), which "
     "snapping moves 1/768 px below the diagonal AB: the upper triangles now overlap the lower one "
     "in a sliver that contains the 31 samples (3k + 0.5, k + 0.5), k = 1..31. Under bottom-right the "
     "lower triangle owns its right edge AB, and the upper triangles contain those samples strictly, "
     "so each of them is covered twice: 31 overdrawn samples, expected, and no hole. Not watertight by "
     "design.",
     97, 33, [Tri(TJ_A, TJ_B, TJ_D), Tri(TJ_A, TJ_M2, TJ_E), Tri(TJ_M2, TJ_B, TJ_E)],
     fill_rule="bottom-right",
     checks=[("overdraw_exactly", (1, 1, 97, 33), CRACK), ("snap_moves", TJ_M2)])

# ---------------------------------------------------------------------------
# 7. Triangles that miss every sample.

MISS = [
    # Long thin: along x - 2y = 0, which lies halfway between the sample
    # lines x - 2y = -1/2 and +1/2; the sliver is +-1/4 wide in x - 2y.
    Tri(P(0, 0), P(120, 60), P(60.25, 30)),
    Tri(P(0, 0), P(59.75, 30), P(120, 60)),
    # Long horizontal needle between two sample rows.
    Tri(P(0.25, 40.75), P(127.75, 40.75), P(64, 40.99609375)),
    # Sub-pixel triangles inside one pixel, around (not on) its centre.
    Tri(P("10.1", "50.1"), P("10.45", "50.1"), P("10.1", "50.45")),
    Tri(P("12.6", "50.6"), P("12.9", "50.9"), P("12.6", "50.9")),
    # Sub-pixel triangles reaching a sample only with an unowned edge or vertex.
    Tri(P(20.5, 50.5), P(20.5, 50.25), P(20.25, 50.5)),   # corner at the sample: right/bottom edges
    Tri(P(22, 50), P(22.5, 50), P(22.5, 51)),             # the sample on its right edge
    Tri(P(24, 51.5), P(25, 50.5), P(25, 51.5)),           # the sample (24.5, 51.5) on its bottom edge
    Tri(P(26.25, 50.5), P(26.75, 50.5), P(26.5, 50.25)),  # the sample (26.5, 50.5) on its bottom edge
]
case("miss_thin_and_subpixel",
     "Triangles that cover no sample (samples_covered 0): two long slivers along x - 2y = 0 that fit "
     "between the sample lines x - 2y = -1/2 and +1/2 for 120 px; a horizontal needle between two "
     "sample rows across the canvas; sub-pixel triangles beside a pixel centre; and tiny triangles that "
     "touch a sample only with an edge or vertex that top-left does not own (a right edge, a bottom "
     "edge, the meeting point of a right and a bottom edge). A rasterizer that tests with <= on every "
     "edge, or whose bounding box or float edge test is one ulp generous, draws something.",
     128, 64, MISS, checks=[("zero_covered",), ("ties", 2)])

# ---------------------------------------------------------------------------
# 8. Vertices exactly half a subpixel off the grid.


def snaptie_mesh(bits, negative):
    h = F(1, 2**(bits + 1))
    if not negative:
        # A vertical shared edge at x = 8.5 + h (snaps to 8.5 under ties to
        # even: 8.5 * 2^b is even) and a horizontal one at y = 4.5 + h.
        x, y = F(17, 2) + h, F(9, 2) + h
        tl, tr, bl, br = P(-1, -1), P(17, -1), P(-1, 17), P(17, 17)
        top, bot, left, right = P(x, -1), P(x, 17), P(-1, y), P(17, y)
        mid = P(x, y)
        return [Tri(tl, top, mid), Tri(tl, mid, left), Tri(top, tr, right), Tri(top, right, mid),
                Tri(left, mid, bot), Tri(left, bot, bl), Tri(mid, right, br), Tri(mid, br, bot)]
    # A diagonal from A = (-7.5, -7.5 - h) to B = (23.5, 23.5): ties to even
    # snap A to (-7.5, -7.5) and the diagonal runs through the samples
    # (k + 1/2, k + 1/2); half away from zero tilts it above them.
    A, B = P(F(-15, 2), F(-15, 2) - h), P(F(47, 2), F(47, 2))
    C, D = P(40, -8), P(-8, 40)
    return [Tri(A, C, B), Tri(A, B, D)]


for bits in (8, 4):
    for negative in (False, True):
        name = "snaptie_b%d_%s" % (bits, "negative" if negative else "positive")
        h = "2^-%d" % (bits + 1)
        if negative:
            desc = ("Two triangles share the diagonal from A = (-7.5, -7.5 - %s) to (23.5, 23.5). A's y is "
                    "exactly half a subpixel off the %d-bit grid at a negative coordinate; ties to even "
                    "(SPEC 2) snap it to -7.5, so the diagonal runs through the 16 samples (k + 0.5, "
                    "k + 0.5) and the upper triangle (whose left edge it is) owns them. Rounding half "
                    "away from zero, as f32/f64 round() and many snapping routines do, moves A up to "
                    "y = -7.5 - 2*%s: the diagonal tilts above those samples, into the lower "
                    "triangle, and they change owner. "
                    "Watertight either way." % (h, bits, h))
        else:
            desc = ("Eight triangles tile the canvas around the point (8.5 + %s, 4.5 + %s), each "
                    "coordinate exactly half a subpixel off the %d-bit grid above an even grid value. "
                    "Ties to even (SPEC 2) snap the point to (8.5, 4.5): the shared vertical edge runs "
                    "through the samples of column 8 and the horizontal one through row 4, and the "
                    "right and lower triangles own them under top-left. Rounding half away from zero "
                    "puts the edges one subpixel right of and below those samples, and column 8 and "
                    "row 4 change owner. Watertight either way." % (h, h, bits))
        case(name, desc, 16, 16, snaptie_mesh(bits, negative), bits=bits, watertight=True,
             checks=[("snap_tie_sensitive",), ("ties", 15)])

# ---------------------------------------------------------------------------
# 9. Extreme perspective.

PW = [V(0.5, 0.5, z=0, w="0.001", attributes=[1000000, -1000000, 1]),
      V(31.5, 0.5, z=1, w=1000, attributes=[-1000000, 1000000, 0]),
      V(31.5, 31.5, z=0.5, w=1, attributes=[1000000, 1000000, -1]),
      V(0.5, 31.5, z="1/3", w="0.01", attributes=[-1000000, 500000, "1/7"]),
      V(16.25, 15.75, z=0.75, w=100, attributes=[0, -1000000, 2])]
case("persp_w_extreme_mesh",
     "Four perspective triangles around (16.25, 15.75) covering the 32x32 canvas, with w from 0.001 "
     "to 1000 (a ratio of 10^6 between neighbouring vertices) and attributes of +-10^6: 1/w spans "
     "six orders of magnitude, so the perspective weights of most samples are dominated by one vertex "
     "and the a/w terms reach 10^9 with opposite signs. The default bound is 2^-16 * 10^6 (about 15) "
     "in absolute terms; a rasterizer that interpolates a/w and 1/w as separate f32 planes, or "
     "divides before blending, exceeds it. Watertight.",
     32, 32, [Tri(PW[4], PW[0], PW[1], "perspective"), Tri(PW[4], PW[1], PW[2], "perspective"),
              Tri(PW[4], PW[2], PW[3], "perspective"), Tri(PW[4], PW[3], PW[0], "perspective")],
     watertight=True, checks=[("ties", 1)])

PL = [V(2.5, 1.5, z=-1000000, w="0.001", attributes=[1000000, 0.5]),
      V(60.5, 3.5, z=1000000, w=1000, attributes=[-999999, 0]),
      V(8.5, 29.5, z=0, w=0.5, attributes=[1, 1000000])]
case("persp_long_sliver_w_range",
     "One long perspective triangle across a 64x32 canvas with w = 0.001, 1000 and 0.5 and depth "
     "and attributes up to +-10^6: across the triangle the perspective-correct value swings from one "
     "vertex's value to another's within a few pixels of the w = 0.001 vertex, and the screen-linear "
     "depth crosses zero. Linear interpolation in place of perspective is off by about 10^6; an f32 "
     "plane setup anchored far from the samples loses the low bits.",
     64, 32, [Tri(PL[0], PL[1], PL[2], "perspective"), Tri(PL[0], PL[2], PL[1], "linear")],
     checks=[("ties", 1)])

# ---------------------------------------------------------------------------
# 10. Lines: midpoint ties and 1000+ px lines.

case("line_midpoint_ties_1024",
     "Three x-major midpoint lines 1024 columns long on a 1030x8 canvas. The first, (0.5, 2) to "
     "(1024.5, 6), has slope 1/256 and its height at column centre i + 0.5 is 2 + i/256: an exact tie "
     "between two rows at columns 0, 256, 512, 768 and 1024, where the upper row wins (SPEC 4.1). The "
     "second is its mirror image drawn right to left (the same ties, the same pixels as drawn left to "
     "right), the third, (1029.5, 7) to (5.5, 3), excludes its last pixel. A DDA that accumulates the "
     "slope 1/256 is exact; one whose tie goes down the screen is wrong at the ties, and an f32 "
     "accumulator of a non-dyadic slope drifts over 1000 steps.",
     1030, 8,
     [Line(P(0.5, 2), P(1024.5, 6)), Line(P(1024.5, 3), P(0.5, 7)),
      Line(P(1029.5, 7), P(5.5, 3), last_pixel="exclude")],
     long_line=True, checks=[("line_ties", 10)])

case("line_midpoint_steep_1100_thirds",
     "Two y-major midpoint lines 1100 rows long on an 8x1104 canvas: (1, 0.5) to (4.6666..., 1100.5) "
     "snaps its end to x = 4.66796875 (slope 3.66796875/1100: no ties, but an accumulator drifts), "
     "and (6, 2.5) to (3, 1052.5) moves x by -1/350 per row: x(r) is an integer, a tie between two "
     "columns won by the left one, every 350 rows.",
     8, 1104,
     [Line(P(1, 0.5), P(F(14, 3), 1100.5)), Line(P(6, 2.5), P(3, 1052.5))],
     long_line=True, checks=[("line_ties", 3)])

case("line_midpoint_far_ends",
     "Two midpoint lines whose endpoints are ~32600 px off a 128x128 canvas: an x-major one with "
     "direction (65280, 2040) (slope 1/32) passing through height 4 at column 0, so that in the "
     "canvas its height is 4 + i/32 and ties at columns 0, 32, 64 and 96; and a y-major one with slope "
     "32 through the same kind of ties in rows 0, 32, 64, 96. Only the part on the canvas is drawn; "
     "the line parameter at the first sample is ~0.5, so an implementation that walks from the far "
     "end, or computes the start in f32 (ulp 2^-8 at 32768), lands on the wrong row.",
     128, 128,
     [Line(P(-32639.5, -1016), P(32640.5, 1024)), Line(P(-1016 + 60, -32639.5), P(1024 + 60, 32640.5))],
     checks=[("line_ties", 6), ("far", 32000)])

# ---------------------------------------------------------------------------
# 11. Self-overlapping geometry.

C_OV = P(16.5, 16.5)
RING = square_ring(C_OV, 14, 1)
OV = [Tri(C_OV, RING[k], RING[(k + 2) % len(RING)]) for k in range(0, len(RING), 2)]
OV += [Tri(C_OV, RING[k], RING[(k + 2) % len(RING)]) for k in range(1, len(RING), 2)]
case("overlap_fan_twice_around",
     "A fan that winds twice around the sample (16.5, 16.5): 112 triangles whose rim vertices step "
     "two samples at a time along a square of half-size 14, once starting at the even points and once "
     "at the odd ones. Every sample strictly inside the square is covered exactly twice (coverage "
     "count 2 expected, the last triangle is the owner), samples on spokes go to exactly one triangle "
     "of each loop. Not a mesh (not watertight): the check is that counts, not just a covered mask, "
     "match.",
     33, 33, OV, checks=[("count_at_least", 2, [(16, 16), (3, 3), (29, 29)]), ("ties", 50)])

BOW = [Tri(P(2.5, 2.5), P(28.5, 2.5), P(15.5, 28.5)),
       Tri(P(2.5, 28.5), P(15.5, 2.5), P(28.5, 28.5)),
       Tri(P(15.5, 15.5), P(2.5, 15.5), P(28.5, 8.5)),
       Tri(P(15.5, 15.5), P(28.5, 22.5), P(2.5, 15.5))]
case("overlap_stacked_windings",
     "Four triangles with both windings stacked on one another, sharing edges through samples and "
     "crossing each other: parts of the canvas are covered 1, 2 and 3 times, and samples on their "
     "shared edge y = 15.5 from (2.5,15.5) to (15.5,15.5) are tie-broken independently per triangle. "
     "The count and the last owner of every sample must match exactly. Not watertight.",
     31, 31, BOW, checks=[("count_at_least", 3, []), ("ties", 20)])

# ---------------------------------------------------------------------------
# 12. A 16-subpixel-bit mesh at +-32768.

FAR16, _ = far_bands(P(2, 1), -16, 36, P(0.5, 0.5), P(0, 2), (16000, 16200), 5, 16)
case("far_b16_bands",
     "72 triangles in 36 bands across a 64x64 canvas at 16 subpixel bits; every vertex is ~32000 px "
     "away with a 16-bit fraction, every band boundary has direction (2, 1) and passes through a "
     "sample every other column ({ties} samples on edges). In 16.17 fixed point the edge "
     "products need {bits} bits: production switches to i128. An f64 edge function survives "
     "only because at an exact 0 both products are the same real number computed from exact "
     "differences (far_b16_near_tie_fan is where f64 fails). Watertight.",
     64, 64, FAR16, bits=16, watertight=True,
     checks=[("ties", 500), ("product_bits", 64), ("far", 31000)])

# ---------------------------------------------------------------------------
# 13. Unsnapped dyadic meshes with ties.

UC = P(16.5, 16.5)
URIM = []
for k, (dx, dy) in enumerate([(1, 0), (3, 1), (2, 1), (1, 1), (1, 2), (1, 3), (0, 1), (-1, 3),
                              (-1, 2), (-1, 1), (-2, 1), (-3, 1), (-1, 0), (-3, -1), (-2, -1),
                              (-1, -1), (-1, -2), (-1, -3), (0, -1), (1, -3), (1, -2), (1, -1),
                              (2, -1), (3, -1)]):
    t = F(15, max(abs(dx), abs(dy))) - F(2 * k + 1, 2**(6 + k % 11))
    URIM.append(add(UC, (F(dx), F(dy)), t))
case("unsnapped_dyadic_fan",
     "subpixel_bits null: a fan of 24 triangles around the sample (16.5, 16.5) whose rim vertices lie "
     "on the spokes of directions (1,0), (3,1), (2,1), (1,1) ... at dyadic distances with 6 to 16 "
     "fraction bits (15 - (2k+1)/2^(6 + k mod 11) steps), used exactly as written. Every spoke passes "
     "through samples (every 1 to 3 px) and is shared by two triangles, so the tie rule decides them "
     "without any snapping to hide behind; production holds these coordinates exactly in 16.17 fixed "
     "point. Watertight.",
     33, 33, fan(UC, URIM), bits=None, watertight=True, checks=[("ties", 60)])

UFAR, _ = far_bands(P(1, 1), -20, 40, P(0.5, 0.5), P(0, 2), (32000, 32000), 1, 16)
case("unsnapped_far_dyadic_bands",
     "subpixel_bits null with coordinates near +-32000 carrying 16-bit dyadic fractions: 80 "
     "triangles in 40 diagonal bands across a 64x64 canvas, the band boundaries (direction (1,1)) "
     "passing through a sample in every column. Exactly representable in production's fixed point "
     "(i128 edge functions); the products exceed 53 bits, and f32 cannot even hold the "
     "coordinates (31 significant bits) and cracks and overdraws the mesh. Watertight.",
     64, 64, UFAR, bits=None, watertight=True,
     checks=[("ties", 1000), ("product_bits", 60), ("far", 31000)])

# ---------------------------------------------------------------------------
# 14. Degenerate triangles inside a mesh.

DG = grid_mesh(XS, YS)
DEG = [
    Tri(P(3.5, 2.5), P(3.5, 2.5), P(9.5, 7.5)),                 # repeated vertex
    Tri(P(0.5, 6.5), P(23.5, 6.5), P(9.5, 6.5)),                # along a shared row of samples
    Tri(P(5.5, 2.5), P(9.5, 6.5), P(7.5, 4.5)),                 # along a shared diagonal
    Tri(P(14.5, 14.5), P(14.5, 14.5), P(14.5, 14.5)),           # a point on a shared vertex
    Tri(P(10.5, 11.5), P(14.5, F(29, 2) + F(1, 1024)), P(18.5, 17.5)),  # collinear after snapping
    Tri(P(0.5, 0.5), P(23.5, 23.5), P(F(23, 2) + F(1, 600), F(23, 2) - F(1, 600))),  # ditto, across cells
]
DG_ALL = DG[:40] + DEG[:3] + DG[40:90] + DEG[3:] + DG[90:]
case("degenerate_in_grid",
     "The mesh of edge_halfint_grid with six zero-area triangles mixed into its drawing order: one "
     "with a repeated vertex, one lying along a shared row of samples, one along a shared diagonal, "
     "one collapsed to a shared vertex, and two whose vertices are distinct as written but collinear "
     "after snapping (a vertex 1/1024 and 1/600 px off a line of samples). A zero-area triangle covers "
     "nothing (SPEC 2): drawn with <= tests or with its edges classified anyway, it adds coverage "
     "exactly on the mesh's shared edges, which shows as overdraw.",
     24, 24, DG_ALL, watertight=True, checks=[("degenerate", 6), ("ties", 150)])

DEGF = list(FAR8[:30])
for k, (a, b) in enumerate(FAR8_ENDS[3:28:4]):
    mid = add(a, P(3, 1), 2000 * (k + 1))
    DEGF.append(Tri(a, mid, b) if k % 2 else Tri(b, a, mid))
DEGF += FAR8[30:]
case("degenerate_in_far_bands",
     "The mesh of far_b8_bands with seven zero-area triangles: each spans a band boundary "
     "(~65000 px long, through ~20 samples of the canvas) with its third vertex exactly on that "
     "boundary, 2000k steps of (3, 1) from its far end (so on the 8-bit grid). Exactly collinear, so nothing is added; in f32 the area is a difference of two "
     "~2^31 px^2 products and rarely exactly 0. Watertight.",
     64, 64, DEGF, watertight=True, checks=[("degenerate", 7), ("ties", 450)])

# ---------------------------------------------------------------------------
# 15. Every fill rule on one tie-heavy mesh at large coordinates.

RULES_MESH, _ = far_bands(P(1, 1), -12, 24, P(0.5, 0.5), P(3, 0), (32000, 32200), 1, 8)
for rule in ("top-left", "bottom-right", "top-right", "bottom-left", "all-edges"):
    closed = rule == "all-edges"
    case("rules_far_%s" % rule,
         "A mesh of 48 triangles in 24 diagonal bands (boundaries of direction (1, 1), each through a "
         "sample in every column of the 48x48 canvas it crosses) with vertices near +-32000 px, drawn "
         "under %s. %s" % (
             rule,
             "Every edge owns its samples, so each sample on a shared boundary is covered twice and the "
             "mesh is deliberately not watertight; the counts must match exactly." if closed else
             "The four consistent rules split the {ties} samples on edges differently (each goes to "
             "the band above or below the boundary), and each must be watertight; a rasterizer that "
             "ignores the rule, or evaluates the huge edge products in f32, gives the wrong owner."),
         48, 48, RULES_MESH, fill_rule=rule, watertight=not closed,
         checks=[("ties", 700), ("flip_changes",) if not closed else ("count_at_least", 2, [])])


# ---------------------------------------------------------------------------
# An independent exact checker, written from SPEC.md. It computes every
# `samples_covered` the files carry, and with --check proves each claim.


def snap(v, bits, mode="even"):
    """v rounded to a multiple of 2^-bits, ties to even (or away from zero)."""
    if bits is None:
        return F(v)
    s = F(v) * 2**bits
    fl = math.floor(s)
    r = s - fl
    if r > HALF or (r == HALF and (fl % 2 == 1 if mode == "even" else s > 0)):
        fl += 1
    return F(fl, 2**bits)


OWNS = {"top-left": {"top", "left"}, "bottom-right": {"bottom", "right"},
        "top-right": {"top", "right"}, "bottom-left": {"bottom", "left"},
        "all-edges": {"top", "left", "bottom", "right"}}
FLIP = {"top-left": "bottom-right", "bottom-right": "top-left", "top-right": "bottom-left",
        "bottom-left": "top-right"}


def grid_of(c):
    """Units per pixel of one integer grid holding every snapped vertex and
    every sample centre."""
    if c["bits"] is not None:
        return 2**(c["bits"] + 1)
    den = 2
    for p in c["prims"]:
        for v in p.v:
            for q in pos_of(v):
                den = den * q.denominator // math.gcd(den, q.denominator)
    return 2 * den


def placed(c, v, mode="even"):
    g = grid_of(c)
    return tuple(int(snap(q, c["bits"], mode) * g) for q in pos_of(v))


def cross(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def edge_kind(a, b, third):
    """D3D11's words: a top edge is horizontal with the triangle below it; a
    left edge is not horizontal with the triangle to its right."""
    if a[1] == b[1]:
        return "top" if third[1] > a[1] else "bottom"
    # The x of the edge at third's height, compared with third's x:
    # third.x > a.x + (third.y - a.y)(b.x - a.x)/(b.y - a.y).
    lhs = (third[0] - a[0]) * (b[1] - a[1])
    rhs = (third[1] - a[1]) * (b[0] - a[0])
    right_of_edge = lhs > rhs if b[1] > a[1] else lhs < rhs
    return "left" if right_of_edge else "right"


def triangle_samples(c, pts, rule):
    """The set of (x, y) samples covered by one snapped triangle."""
    g = grid_of(c)
    area = cross(*pts)
    if area == 0:
        return set(), [], 0
    if c["cull"] == "cw" and area > 0 or c["cull"] == "ccw" and area < 0:
        return set(), [], area
    edges = []
    for i in range(3):
        a, b, third = pts[i], pts[(i + 1) % 3], pts[(i + 2) % 3]
        side = 1 if cross(a, b, third) > 0 else -1
        edges.append((a, b, side, edge_kind(a, b, third) in OWNS[rule]))
    W, H = c["width"], c["height"]
    h = g // 2
    x_lo = max(0, -(-(min(p[0] for p in pts) - h) // g))
    x_hi = min(W - 1, (max(p[0] for p in pts) - h) // g)
    y_lo = max(0, -(-(min(p[1] for p in pts) - h) // g))
    y_hi = min(H - 1, (max(p[1] for p in pts) - h) // g)
    out, on_edge = set(), []
    for yy in range(y_lo, y_hi + 1):
        sy = yy * g + h
        for xx in range(x_lo, x_hi + 1):
            s = (xx * g + h, sy)
            ok, touched = True, False
            for a, b, side, owned in edges:
                e = cross(a, b, s) * side
                if e < 0 or (e == 0 and not owned):
                    ok = False
                    if e < 0:
                        break
                if e == 0:
                    touched = True
            if touched:
                on_edge.append((xx, yy))
            if ok:
                out.add((xx, yy))
    return out, on_edge, area


def ceil_f(q):
    return -((-q.numerator) // q.denominator)


def midpoint_pixels(c, line):
    """SPEC 4.1: the nearest row in each column (x-major), ties to the upper
    row; y-major the same with the axes swapped, ties to the left."""
    (x0, y0), (x1, y1) = [tuple(snap(q, c["bits"]) for q in pos_of(v)) for v in line.v]
    dx, dy = x1 - x0, y1 - y0
    if dx == 0 and dy == 0:
        return set(), 0
    swap = abs(dx) < abs(dy)
    if swap:
        x0, y0, x1, y1, dx, dy = y0, x0, y1, x1, dy, dx
    W, H = (c["height"], c["width"]) if swap else (c["width"], c["height"])
    lo, hi = min(x0, x1), max(x0, x1)
    out, ties = set(), 0
    for i in range(max(0, ceil_f(lo - HALF)), min(W - 1, math.floor(hi - HALF)) + 1):
        cc = i + HALF
        if line.last_pixel == "exclude" and cc == x1:
            continue
        y = y0 + (cc - x0) * dy / dx
        if y.denominator == 1:
            ties += 1
        j = ceil_f(y) - 1
        if 0 <= j < H:
            out.add((j, i) if swap else (i, j))
    return out, ties


def render_frame(c, rule=None, mode="even"):
    """Per sample: the list of primitives covering it, in order. Also the
    samples lying on some triangle edge, and each triangle's twice-area."""
    rule = rule or c["fill_rule"]
    cov = {}
    on_edges, areas, line_ties = set(), [], 0
    for idx, p in enumerate(c["prims"]):
        if isinstance(p, Line):
            px, ties = midpoint_pixels(c, p)
            line_ties += ties
            areas.append(None)
        else:
            pts = [placed(c, v, mode) for v in p.v]
            px, on, area = triangle_samples(c, pts, rule)
            on_edges.update(on)
            areas.append(area)
        for s in px:
            cov.setdefault(s, []).append(idx)
    return cov, on_edges, areas, line_ties


def interior(c):
    frames = [render_frame(c, rule)[0] for rule in FLIP]
    return {s for s in frames[0] if all(s in f for f in frames[1:])}


def product_bits(c):
    """Bits of the largest |(bx - ax)(py - ay)| over triangle edges and the
    canvas corner samples, in production's units (2^-(bits+1) px)."""
    g = grid_of(c)
    corners = [(h * g + g // 2, v * g + g // 2) for h in (0, c["width"] - 1)
               for v in (0, c["height"] - 1)]
    best = 0
    for p in c["prims"]:
        pts = [placed(c, v) for v in p.v]
        for i in range(len(pts)):
            a, b = pts[i], pts[(i + 1) % len(pts)]
            for s in corners:
                best = max(best, abs((b[0] - a[0]) * (s[1] - a[1])), abs((b[1] - a[1]) * (s[0] - a[0])))
    return best.bit_length()


def check_claims(c, cov, on_edges, areas, line_ties):
    notes, ok = [], True

    def fail(msg):
        nonlocal ok
        ok = False
        notes.append("FAILED: " + msg)

    if c["watertight"]:
        inner = interior(c)
        holes = sum(1 for s in inner if s not in cov)
        over = sum(1 for s in cov if len(cov[s]) > 1)
        notes.append("interior %d" % len(inner))
        if holes or over:
            fail("not watertight: %d holes, %d overdraw" % (holes, over))
    for claim in c["checks"]:
        kind = claim[0]
        if kind == "ties":
            n = len(on_edges) if c["prims"] and isinstance(c["prims"][0], Tri) else 0
            notes.append("%d samples on edges" % n)
            if n < claim[1]:
                fail("only %d samples on edges, claimed %d" % (n, claim[1]))
        elif kind == "flip_changes":
            other = render_frame(c, FLIP[c["fill_rule"]])[0]
            d = sum(1 for s in set(cov) | set(other) if cov.get(s, [])[-1:] != other.get(s, [])[-1:]
                    or len(cov.get(s, [])) != len(other.get(s, [])))
            notes.append("flipped rule: %d differ" % d)
            if not d:
                fail("the flipped rule changes nothing")
        elif kind == "snap_tie_sensitive":
            other = render_frame(c, mode="away")[0]
            d = sum(1 for s in set(cov) | set(other) if cov.get(s, [])[-1:] != other.get(s, [])[-1:]
                    or len(cov.get(s, [])) != len(other.get(s, [])))
            notes.append("half-away snapping: %d differ" % d)
            if not d:
                fail("snapping ties away from zero changes nothing")
        elif kind == "zero_covered":
            if cov:
                fail("covers %d samples" % len(cov))
        elif kind == "degenerate":
            n = sum(1 for a in areas if a == 0)
            notes.append("%d zero-area" % n)
            if n != claim[1]:
                fail("%d zero-area triangles, claimed %d" % (n, claim[1]))
        elif kind == "product_bits":
            b = product_bits(c)
            notes.append("products %d bits" % b)
            if b < claim[1]:
                fail("products need only %d bits" % b)
        elif kind == "far":
            far = max(abs(q) for p in c["prims"] for v in p.v for q in pos_of(v))
            if far < claim[1]:
                fail("farthest coordinate only %s" % far)
        elif kind == "crack":
            x0, y0, x1, y1 = claim[1]
            holes = sorted((x, y) for y in range(y0, y1) for x in range(x0, x1) if (x, y) not in cov)
            if holes != sorted(claim[2]):
                fail("uncovered samples %s, claimed %s" % (holes, sorted(claim[2])))
            notes.append("crack of %d samples" % len(holes))
            over = [s for s in cov if len(cov[s]) > 1]
            if over:
                fail("overdraw at %s" % over)
        elif kind == "count_at_least":
            k, samples = claim[1], claim[2]
            top = max((len(v) for v in cov.values()), default=0)
            notes.append("max count %d" % top)
            if top < k or any(len(cov.get(s, [])) < k for s in samples):
                fail("some sample of %s covered fewer than %d times" % (samples, k))
        elif kind == "covered":
            if len(cov) != claim[1]:
                fail("covers %d samples, claimed %d" % (len(cov), claim[1]))
        elif kind == "overdraw_exactly":
            x0, y0, x1, y1 = claim[1]
            over = sorted(s for s in cov if len(cov[s]) > 1)
            if over != sorted(claim[2]):
                fail("overdrawn %s, claimed %s" % (over, sorted(claim[2])))
            holes = [(x, y) for y in range(y0, y1) for x in range(x0, x1) if (x, y) not in cov]
            if holes:
                fail("holes at %s" % holes)
            notes.append("%d overdrawn" % len(over))
        elif kind == "snap_moves":
            v = claim[1]
            if all(snap(q, c["bits"]) == q for q in v):
                fail("the vertex is on the grid")
        elif kind == "windings_mixed":
            signs = {a > 0 for a in areas if a}
            if len(signs) != 2:
                fail("one winding only")
        elif kind == "line_ties":
            notes.append("%d line ties" % line_ties)
            if line_ties < claim[1]:
                fail("only %d ties on lines" % line_ties)
        else:
            raise ValueError(kind)
    return ok, notes


# ---------------------------------------------------------------------------
# Polygons and antialiasing (SPEC.md section 14). Their expectations come
# from the exact checker of tools/gen_aa_cases.py (winding numbers at nudged
# samples, per-pixel areas by exact slabs, checked a second way), imported
# rather than copied; the claims below (no sample covered twice, full pixels
# whose areas sum to exactly 1, the exact total area from a formula of its
# own, the same samples as a simpler scene) are asserted here.

import gen_aa_cases as aac  # noqa: E402

AA_CASES = []
A16 = {"samples": 16, "pattern": "standard"}


def aa_case(name, description, width, height, prims, aa=A16, bits=8, fill_rule="top-left",
            area=None, full_pixels=None, single=False, same_as=None, checks=()):
    """Registers a polygon or antialiasing hard case (prims are
    gen_aa_cases primitives). Claims, asserted by main(): `area` the exact
    total area (a Fraction, computed independently of the checker's slabs),
    `full_pixels` how many pixels have area exactly 1, `single` that no
    sample is covered twice, `same_as` a list of primitives that must cover
    exactly the same samples."""
    for pr in prims:
        for c in pr.snapped(bits):
            for q in c:
                assert abs(q[0]) <= COORD_LIMIT and abs(q[1]) <= COORD_LIMIT, name
    assert 1 <= width <= 64 and 1 <= height <= 64, name
    AA_CASES.append(dict(folder=OUT_DIR, name=name, description=description, width=width,
                         height=height, prims=prims, aa=aa, bits=bits, fill_rule=fill_rule,
                         rms="piglit", max_error="edges", extra_expect={}, checks=[],
                         claim_area=area, claim_full=full_pixels, claim_single=single,
                         claim_same=same_as, claim_checks=list(checks)))


def ring(cx, cy, r, k, phase, denom=256):
    """k points on a circle, rounded to multiples of 1/denom (exact Fractions)."""
    out = []
    for i in range(k):
        t = phase + 2 * math.pi * i / k
        out.append((F(round((cx + r * math.cos(t)) * denom), denom),
                    F(round((cy + r * math.sin(t)) * denom), denom)))
    return out


def shoelace(pts):
    s2 = 0
    for i in range(len(pts)):
        (ax, ay), (bx, by) = pts[i], pts[(i + 1) % len(pts)]
        s2 += ax * by - ay * bx
    return abs(F(s2) / 2)


# (a) Abutting antialiased shapes whose coverages sum exactly.

FAN_NOTE = ("Every sample inside the outline is covered exactly once, so each pixel's "
            "coverage is a sum of partial coverages of up to {p} triangles that must add up to "
            "the union's, and pixels wholly inside resolve to exactly 1 (piglit's rule) although "
            "no single triangle covers them; expect.area is the shoelace area of the rim, which "
            "the reference's per-pixel areas must sum to exactly. An overlap or a crack between "
            "neighbours shows as a sample counted twice or none.")
C64 = (F(16) + F(9, 16), F(16) + F(9, 16))
RIM64 = ring(16.5, 16.5, 14.3, 64, 0.05)
aa_case("aa_abut_fan_64_standard16",
        "64 triangles fanned around (16+9/16, 16+9/16), which is exactly sample 0 of the standard "
        "16x pattern in pixel (16, 16): all 64 share that vertex and one of them must own the "
        "sample. The rim is a 64-gon of radius 14.3 rounded to 1/256. " + FAN_NOTE.format(p=64),
        33, 33, [aac.tri(C64, RIM64[k], RIM64[(k + 1) % 64]) for k in range(64)],
        area=shoelace(RIM64), single=True)
C128 = (F(16), F(16))
RIM128 = ring(16, 16, 15.2, 128, 0.3)
aa_case("aa_abut_fan_128_corner_standard16",
        "128 triangles fanned around the pixel corner (16, 16), where four pixels meet: each of "
        "those four full pixels is cut into 32 slivers of area under 1/20 px^2 each. The rim is "
        "a 128-gon of radius 15.2 rounded to 1/256. " + FAN_NOTE.format(p=128),
        32, 32, [aac.tri(C128, RIM128[k], RIM128[(k + 1) % 128]) for k in range(128)],
        area=shoelace(RIM128), single=True,
        checks=[lambda st: all(st["area"].get(q) == 1 for q in ((15, 15), (16, 15), (15, 16), (16, 16)))])

GX = [F(3), F(5) + F(3, 16), F(7) + F(1, 256), F(10) + F(1, 2), F(12) + F(7, 256), F(15) + F(9, 16),
      F(17), F(19) + F(255, 256), F(22) + F(1, 3), F(25) + F(5, 16), F(29)]


def jittered(i, j):
    """Vertex (i, j) of the jittered grid over the square [3, 29]^2: interior
    vertices move by up to 3/4 px (multiples of 1/256), border vertices stay
    on the square's sides."""
    x, y = GX[i], GX[j]
    if 0 < i < len(GX) - 1:
        x += F(((i * 7 + j * 13) % 11) - 5, 16) * F(1, 2) + F((i * j) % 5, 256)
    if 0 < j < len(GX) - 1:
        y += F(((i * 5 + j * 3) % 9) - 4, 16) * F(3, 4) + F((i + j) % 3, 256)
    return (x, y)


SQ_TRIS = []
for j in range(len(GX) - 1):
    for i in range(len(GX) - 1):
        a, b, c, d = jittered(i, j), jittered(i + 1, j), jittered(i + 1, j + 1), jittered(i, j + 1)
        if (i + j) % 2:
            SQ_TRIS += [aac.tri(a, b, c), aac.tri(a, c, d)]
        else:
            SQ_TRIS += [aac.tri(a, b, d), aac.tri(b, c, d)]
aa_case("aa_abut_grid_square_standard16",
        "200 triangles of a jittered 10x10 grid (diagonals alternating, one snapped (1/3 px) "
        "column) that tile the square [3, 29]^2 exactly. Interior vertices sit at multiples of "
        "1/256 px, so the shared edges cross pixels at every angle and the triangles' partial "
        "coverages must add up: the 26x26 = 676 pixels of the square resolve to exactly 1 and "
        "its outside to exactly 0, and expect.area is 676 exactly. A rasterizer whose shared "
        "edges overlap or crack (an edge function rounded differently for the two triangles of "
        "an edge) fails.",
        32, 32, SQ_TRIS, area=F(676), full_pixels=676, single=True)

HOLE_FAR = [(F(-32760), F(-32760)), (F(32760), F(-32760)), (F(32760), F(32760)), (F(-32760), F(32760))]
HOLE_TRI = [(F(-32767) + F(3, 256), F(13) + F(1, 256)), (F(4) + F(131, 256), F(32766) + F(5, 256)),
            (F(32767) - F(7, 256), F(-32000) + F(99, 256))]
aa_case("aa_abut_far_square_with_far_hole_standard16",
        "A contour of 65520 px a side around the whole 24x24 canvas, with a triangular hole (the "
        "second contour, the same orientation, even-odd) whose vertices are within 1 px of "
        "+-32768: three edges of 65000+ px cross the canvas. Every pixel away from them must "
        "resolve to exactly 1 (full) and their exact areas sum to expect.area; edge functions "
        "there are products of 24-bit coordinate differences.",
        24, 24, [aac.contours([HOLE_FAR, HOLE_TRI], "even-odd")])

# (b) Self-overlapping polygons.

HEPT = ring(12.2, 11.7, 9.6, 7, 0.4)
for fill in ("nonzero", "even-odd"):
    tag = fill.replace("-", "_")
    aa_case("poly_wind_twice_%s_standard16" % tag,
            "One contour that runs twice around the same heptagon (14 vertices, each written "
            "twice, every edge doubled and coincident with itself): the interior has winding "
            "number 2, so nonzero fills the heptagon and even-odd fills nothing (area 0, no "
            "sample). A rasterizer that counts crossings modulo 2 gets nonzero wrong; one that "
            "dedupes edges or treats the doubled edges as an open sliver gets even-odd wrong. "
            "Fill %s." % fill,
            24, 24, [aac.poly(HEPT + HEPT, fill)],
            area=shoelace(HEPT) if fill == "nonzero" else F(0), single=True)

SQ_A = [(F(3) + F(1, 8), F(3) + F(1, 4)), (F(17) + F(1, 2), F(3) + F(1, 4)),
        (F(17) + F(1, 2), F(16) + F(9, 16)), (F(3) + F(1, 8), F(16) + F(9, 16))]
SQ_B = [(F(9) + F(7, 16), F(8)), (F(22) + F(5, 8), F(8)), (F(22) + F(5, 8), F(21)),
        (F(9) + F(7, 16), F(21))]
TRI_R = [(F(6), F(12) + F(1, 2)), (F(14) + F(1, 2), F(23) + F(1, 2)), (F(20) + F(1, 3), F(5))]
for fill in ("nonzero", "even-odd"):
    tag = fill.replace("-", "_")
    aa_case("poly_overlap_contours_%s_standard16" % tag,
            "Three contours: two overlapping rectangles in the same direction (their overlap has "
            "winding 2) and a triangle in the opposite direction crossing both (windings -1, 0 and "
            "1 where it overlaps them). Under %s the filled region is %s; pixels where four "
            "edges and two crossings meet hold partial areas of several winding regions." %
            (fill, "every point of non-zero winding (the overlap of the rectangles stays filled, "
             "the triangle's part over one rectangle is empty)" if fill == "nonzero" else
             "the odd-winding points (the rectangles' overlap is empty)"),
            26, 26, [aac.contours([SQ_A, SQ_B, TRI_R], fill)], single=True,
            checks=[lambda st, f=fill: (st["counts"][(9 * 26 + 10) * 16] > 0) == (f == "nonzero")])

SLIT = [(F(2) + F(1, 2), F(2) + F(1, 2)), (F(14) + F(9, 16), F(2) + F(1, 2)),
        (F(14) + F(9, 16), F(7) + F(9, 16)), (F(21) + F(9, 16), F(14) + F(9, 16)),
        (F(14) + F(9, 16), F(7) + F(9, 16)), (F(14) + F(9, 16), F(14) + F(1, 2)),
        (F(2) + F(1, 2), F(14) + F(1, 2))]
SLIT_CLEAN = [SLIT[0], SLIT[1], SLIT[5], SLIT[6]]
RIGHT = [(F(14) + F(9, 16), F(2) + F(1, 2)), (F(14) + F(9, 16), F(14) + F(1, 2)),
         (F(20) + F(1, 4), F(14) + F(1, 2)), (F(20) + F(1, 4), F(2) + F(1, 2))]
for fill in ("nonzero", "even-odd"):
    tag = fill.replace("-", "_")
    aa_case("poly_doubled_edges_%s_standard16" % tag,
            "Coincident edges: a rectangle whose right side runs out along a spike to "
            "(21+9/16, 14+9/16) and straight back (a zero-width slit through 7 sample points of "
            "the 16x pattern, sample 0 of each pixel it crosses: it covers nothing), plus a "
            "second contour whose left edge is the first's right edge traversed the other way "
            "(the two share it, x = 14+9/16, through the samples at offset 9/16): the union is "
            "one rectangle, each sample on the shared edge covered once. Fill %s; the same "
            "samples as the rectangles without the spike." % fill,
            24, 18, [aac.contours([SLIT, [RIGHT[0], RIGHT[3], RIGHT[2], RIGHT[1]]], fill)],
            same_as=[aac.contours([SLIT_CLEAN, [RIGHT[0], RIGHT[3], RIGHT[2], RIGHT[1]]], fill)],
            area=shoelace(SLIT_CLEAN) + shoelace(RIGHT), single=True)

PENT = ring(11, 10.5, 8.7, 5, -1.2, denom=16)
REP = []
for i, v in enumerate(PENT):
    w = PENT[(i + 1) % 5]
    REP += [v, v, v] if i % 2 == 0 else [v]
    for t in (F(1, 4), F(1, 2), F(3, 4)):
        REP.append((v[0] + t * (w[0] - v[0]), v[1] + t * (w[1] - v[1])))
    if i == 2:   # back along the edge and forth again: a doubled collinear piece
        REP += [(v[0] + F(1, 4) * (w[0] - v[0]), v[1] + F(1, 4) * (w[1] - v[1]))]
        REP += [(v[0] + F(3, 4) * (w[0] - v[0]), v[1] + F(3, 4) * (w[1] - v[1]))]
aa_case("poly_collinear_repeated_vertices_standard16",
        "A pentagon (vertices on multiples of 1/16 px, so sample points lie on its edges) written "
        "with %d vertices: three of its corners repeated three times, three collinear points on "
        "every edge, and one edge that goes back and forth along itself. Zero-length and "
        "collinear edges must change nothing: the same samples and the same area as the plain "
        "pentagon. A rasterizer that divides by an edge's length, or counts a vertex crossing "
        "once per repeated vertex, fails." % len(REP),
        22, 21, [aac.poly(REP)], same_as=[aac.poly(PENT)], area=shoelace(PENT), single=True)
assert len(REP) >= 25

REAL = [(F(2) + F(3, 16), F(3) + F(1, 2)), (F(19) + F(1, 2), F(2) + F(5, 8)),
        (F(17) + F(7, 16), F(17) + F(9, 16)), (F(4) + F(1, 2), F(15) + F(1, 4))]
FLAT = [(F(1) + F(9, 16), F(1) + F(9, 16)), (F(10) + F(9, 16), F(10) + F(9, 16)),
        (F(19) + F(9, 16), F(19) + F(9, 16))]
POINT = [(F(9) + F(9, 16), F(7) + F(9, 16))] * 3
for fill in ("nonzero", "even-odd"):
    tag = fill.replace("-", "_")
    aa_case("poly_zero_area_contour_%s_standard16" % tag,
            "A quadrilateral plus two contours of zero area: three collinear vertices on the "
            "diagonal y = x, through sample 0 (9/16, 9/16) of every pixel on it, and one point "
            "written three times on a sample inside the quadrilateral. They add winding 0 "
            "everywhere off their lines, and the nudged samples on them are off them too: the "
            "samples and area are the quadrilateral's alone (fill %s)." % fill,
            21, 21, [aac.contours([REAL, FLAT, POINT], fill)], same_as=[aac.contours([REAL], fill)],
            area=shoelace(REAL), single=True)

# Each self-overlapping polygon also without antialiasing (one sample at the
# pixel centre), so that the polygon methods that do not antialias
# (polygon-convex, polygon-tessellate, flood-fill) meet them too.
for c in [c for c in AA_CASES if c["name"].startswith("poly_")]:
    AA_CASES.append(dict(c, name=c["name"].replace("_standard16", ""), aa=None,
                         claim_full=None, claim_checks=[],
                         description="Without antialiasing: " + c["description"]))

# (c) Polygons with vertices near +-32768 px at 8 subpixel bits.


def far_line(c, slope_num, reach):
    """Endpoints at x = c.x -+ reach of the line through c with slope
    slope_num/65536, rounded to 1/256."""
    def at(x):
        return (F(x), F(round((c[1] + F(slope_num, 65536) * (x - c[0])) * 256), 256))
    return at(c[0] - reach), at(c[0] + reach)


FAR_ZIG = []
for k, (sn, cy) in enumerate([(37, 7), (-113, 9), (411, 13), (-1023, 15), (2999, 11),
                              (-7, 18), (5001, 20), (-222, 4)]):
    a, b = far_line((F(12) + F(k, 3), F(cy) + F(1, 7)), sn, 32750 - k)
    FAR_ZIG += [a, b] if k % 2 == 0 else [b, a]
for fill in ("nonzero", "even-odd"):
    tag = fill.replace("-", "_")
    aa_case("poly_far_zigzag_b8_%s" % tag,
            "One 16-vertex contour whose vertices alternate between x = -32743 and +32762 (within "
            "30 px of +-32768): its 8 long edges, slopes from 7/65536 to 5001/65536, cross the 24x24 "
            "canvas and each other inside it, so winding numbers from -2 to 2 meet there. At 8 "
            "bits the edge functions multiply 24-bit coordinate differences; the orientation of "
            "a sample against an edge is near zero for the slope-7 edge. Fill %s, no "
            "antialiasing." % fill,
            24, 24, [aac.poly(FAR_ZIG, fill)], aa=None)
    aa_case("poly_far_zigzag_b8_%s_standard16" % tag,
            "The contour of poly_far_zigzag_b8_%s under standard 16x: the exact areas of pixels "
            "cut by 65000 px edges and their crossings (rationals with 40-bit denominators) must "
            "sum to expect.area." % tag,
            24, 24, [aac.poly(FAR_ZIG, fill)])

NT_C = (F(9) + F(1, 2), F(10) + F(1, 2))
NT_D = (F(32750), F(3) + F(1, 256))
NT = [(NT_C[0] - NT_D[0], NT_C[1] - NT_D[1]), (F(-32700), F(32760)),
      (NT_C[0] + NT_D[0], NT_C[1] + NT_D[1]), (F(9) + F(1, 2) + F(1, 256), F(-32760))]
aa_case("poly_far_near_tie_b8",
        "A quadrilateral with all four vertices 32700+ px away; its first diagonal-like edge runs "
        "from (-32740.5, 7.49609375) to (32759.5, 13.50390625) and passes exactly through the "
        "pixel centre (9.5, 10.5) (the midpoint of its ends), and the last edge is vertical "
        "1/256 px right of the centres of column 9. The sample on the edge is decided by the "
        "nudge alone; the centres next to it miss the edge by 6/65500 px.",
        20, 20, [aac.poly(NT)], aa=None)

# (d) Antialiased slivers and near-collinear triangles.

DIR = (F(1000003, 256), F(7, 256))      # a primitive direction on the 1/256 lattice
SL_C = (F(11) + F(1, 2), F(9) + F(5, 16))


def on_line(k):
    return (SL_C[0] + k * DIR[0], SL_C[1] + k * DIR[1])


SL_A, SL_B = on_line(-8), on_line(8)
SLIVERS = [aac.tri(SL_A, SL_B, (SL_C[0] + F(j, 1), SL_C[1] + F(j, 1) * F(7, 1000003) + F(d, 256)))
           for j, d in ((-9, 1), (-3, -1), (2, 2), (7, -3))]
SLIVERS = [aac.tri(SL_A, SL_B, (p[0], F(round(p[1] * 256), 256))) for p in
           [(SL_C[0] + j, SL_C[1] + j * F(7, 1000003) + F(d, 256))
            for j, d in ((-9, 1), (-3, -1), (2, 2), (7, -3))]]
SLIVERS.append(aac.tri(SL_A, SL_B, SL_C))
aa_case("aa_sliver_near_collinear_far_standard16",
        "Five triangles sharing the edge from (%s, %s) to (%s, %s) (31250 px each side of the "
        "canvas, direction (1000003, 7)/256): four with a third vertex in the canvas within "
        "3/256 px of that edge's line, after rounding to 1/256 (orientations of a few 2^-16 px^2 "
        "against coordinates of 2^15 px), and one with its third vertex exactly on the line (zero "
        "area, no sample). Each sliver is under 1/64 px thick where it crosses the canvas: its "
        "exact per-pixel areas are tiny rationals and the samples it covers lie within 3/256 px "
        "of the edge." % (float(SL_A[0]), float(SL_A[1]), float(SL_B[0]), float(SL_B[1])),
        24, 20, SLIVERS)

THIN = []
for k, (a, b) in enumerate([((1, 2), (23, 5)), ((2, 18), (22, 3)), ((3, 1), (7, 19)),
                            ((20, 1), (17, 19))]):
    a = (F(a[0]) + F(k, 16), F(a[1]) + F(1, 2))
    b = (F(b[0]) + F(9, 16), F(b[1]) + F(9, 16))
    # a parallelogram 1/256 px wide split along its long diagonal: two slivers
    w = (F(0), F(1, 256)) if abs(b[0] - a[0]) >= abs(b[1] - a[1]) else (F(1, 256), F(0))
    a2, b2 = (a[0] + w[0], a[1] + w[1]), (b[0] + w[0], b[1] + w[1])
    THIN += [aac.tri(a, b, b2), aac.tri(a, b2, a2)]
aa_case("aa_sliver_thin_pairs_standard16",
        "Four parallelograms 1/256 px thick across a 24x20 canvas, each split along its long "
        "diagonal into two slivers of zero width at one end: most pixels they cross hold "
        "under 1/100 px^2 of them and no sample, some hold one sample on the shared diagonal, "
        "which one of the pair must own. Coverage errors are at most 1/16 per sample, the "
        "exact areas sum to 4 x the parallelograms' 1/256 x length.",
        24, 20, THIN, single=False)

SNAPC = [aac.tri((F(1) + F(1, 2), F(2) + F(1, 2)), (F(20) + F(1, 2), F(11) + F(1, 2)),
                 (F(11) - F(1, 1024), F(7) + F(3, 2048))),
         aac.tri((F(2), F(17)), (F(22), F(3)), (F(12) + F(1, 1024), F(10) - F(1, 2048))),
         aac.tri((F(3) + F(1, 4), F(18)), (F(19) + F(1, 4), F(18) + F(1, 512)),
                 (F(11) + F(1, 4), F(18) + F(1, 1024) - F(1, 8192)))]
aa_case("aa_sliver_snaps_collinear_standard16",
        "Three triangles with a vertex 1/2048 to 1/512 px off the line of the other two "
        "before snapping (a snapping tie, rounded to even, in the third) and exactly on it after "
        "snapping to 8 bits: all three have zero area, "
        "cover no sample and add nothing to expect.area (0). A rasterizer that uses the "
        "unsnapped coordinates draws slivers through sample points of the 16x pattern.",
        24, 20, SNAPC, area=F(0))

# (e) Samples exactly on shared edges and vertices under antialiasing.

UNIT = []
for y in range(2, 14):
    for x in range(2, 14):
        UNIT += [aac.tri((x, y), (x + 1, y), (x + 1, y + 1)), aac.tri((x, y), (x + 1, y + 1), (x, y + 1))]
for rule in ("top-left", "top-right", "bottom-left", "bottom-right"):
    aa_case("aa_tie_unit_grid_%s_standard16" % rule.replace("-", "_"),
            "288 triangles: every pixel of the square [2, 14]^2 split along its main diagonal. "
            "The standard 16x pattern puts sample 12 at (0, 1/2) on every vertical edge, sample 15 "
            "at (1/16, 0) on every horizontal edge, and sample 0 at (9/16, 9/16) on every "
            "diagonal: 3 of each pixel's 16 samples lie on shared edges, which the %s rule hands "
            "to exactly one triangle. Inside, every pixel resolves to exactly 1 (full); on the "
            "square's border the rule decides which border samples belong to the square." % rule,
            16, 16, UNIT, fill_rule=rule, area=F(144), full_pixels=144, single=True)

S16 = aac.STANDARD[16]


def smp(px, py, s):
    return (F(px) + S16[s][0], F(py) + S16[s][1])


VC = smp(10, 10, 0)
VRIM = [smp(3, 3, 9), smp(10, 2, 15), smp(17, 3, 12), smp(18, 10, 3), smp(17, 17, 6),
        smp(10, 18, 14), smp(3, 17, 11), smp(2, 10, 4)]
aa_case("aa_tie_vertices_on_samples_standard16",
        "A fan of 8 triangles whose every vertex is a sample point of the standard 16x pattern "
        "(centre: sample 0 of pixel (10, 10); rim: samples 9, 15, 12, 3, 6, 14, 11, 4 of pixels "
        "around it): the samples at the vertices are decided by the tie rule at a vertex shared "
        "by 2 or 8 triangles, and one triangle must own each. Every inner sample is covered once.",
        21, 21, [aac.tri(VC, VRIM[k], VRIM[(k + 1) % 8]) for k in range(8)],
        area=shoelace(VRIM), single=True)

STAIR = [(2, 2), (14, 2), (14, 6), (10, 6), (10, 10), (6, 10), (6, 14), (2, 14)]
HOLE = [(4, 4), (4, 8), (8, 8), (8, 4)]
for fill in ("nonzero", "even-odd"):
    tag = fill.replace("-", "_")
    aa_case("aa_tie_border_samples_polygon_%s_standard16" % tag,
            "A staircase polygon with a square hole (the hole's contour reversed), every edge on "
            "pixel borders: under the standard 16x pattern samples 12 (0, 1/2) and 15 (1/16, 0) "
            "lie on its vertical and horizontal edges, and at the concave corners a sample sits "
            "on two edges. The nudge of SPEC 14.1 decides them; every pixel resolves to exactly "
            "0 or 1 (fill %s)." % fill,
            16, 16, [aac.contours([STAIR, HOLE], fill)], area=F(96 - 16), full_pixels=80, single=True)


def aa_evaluate(c):
    """Expectations of a polygon/antialiasing hard case from gen_aa_cases'
    checker, with the claims of aa_case asserted."""
    try:
        expect, stats = aac.evaluate(c)
    except AssertionError as e:
        if "RMS" not in str(e):
            raise
        c["rms"] = "max"
        c["description"] += (" Bounds: the exact 16-sample method breaks piglit's RMS bound here "
                             "(its edges line up with the pattern), so max_coverage_rms is the "
                             "max_coverage_error bound.")
        expect, stats = aac.evaluate(c)
    name = c["name"]
    if c["aa"] is not None and "Bounds:" not in c["description"] and "max_coverage_rms" in expect:
        c["description"] += " " + aac.BOUNDS_NOTE
    if c["claim_single"]:
        assert max(stats["counts"]) <= 1, name
        assert c["claim_area"] == 0 or any(stats["counts"]), name
    if c["claim_area"] is not None and c["aa"] is not None:
        assert F(expect["area"]) == c["claim_area"], (name, expect["area"], c["claim_area"])
    if c["claim_full"] is not None:
        full = sum(1 for a in stats["area"].values() if a == 1)
        assert full == c["claim_full"], (name, full)
        N = stats["N"]
        for (x, y), a in stats["area"].items():
            # Full pixels away from the outline (the rule may give a sample
            # on the outline away): every sample covered once.
            if all(stats["area"].get((x + i, y + j)) == 1 for i in (-1, 0, 1) for j in (-1, 0, 1)):
                i = (y * c["width"] + x) * N
                assert stats["counts"][i:i + N] == [1] * N, (name, x, y)
    if c["claim_same"] is not None:
        other = dict(c, prims=c["claim_same"])
        assert aac.coverage(other) == stats["counts"], name
    for check in c["claim_checks"]:
        assert check(stats), name
    return expect, stats



def main():
    names = [c["name"] for c in CASES]
    names += [c["name"] for c in AA_CASES]
    assert len(names) == len(set(names)), "duplicate case names"
    checking = "--check" in sys.argv[1:]
    os.makedirs(OUT_DIR, exist_ok=True)
    all_ok = True
    for c in CASES:
        cov, on_edges, areas, line_ties = render_frame(c)
        if "{bits}" in c["description"] or "{ties}" in c["description"]:
            c["description"] = c["description"].replace("{bits}", str(product_bits(c))).replace(
                "{ties}", str(len(on_edges)))
        expect = {"samples_covered": len(cov)}
        if c["watertight"]:
            expect = {"watertight": True, "samples_covered": len(cov)}
        with open(os.path.join(OUT_DIR, c["name"] + ".json"), "w") as f:
            f.write(render(c, expect))
        if checking:
            ok, notes = check_claims(c, cov, on_edges, areas, line_ties)
            all_ok &= ok
            print("%-36s %5d covered  %s" % (c["name"], len(cov), "; ".join(notes)), flush=True)
    for c in AA_CASES:
        expect, stats = aa_evaluate(c)
        with open(os.path.join(OUT_DIR, c["name"] + ".json"), "w") as f:
            f.write(aac.render(c, expect))
        if checking:
            print("%-36s %5d covered  area %s" % (c["name"], stats["covered"],
                                                  expect.get("area", "-")), flush=True)
    print("wrote %d cases to %s" % (len(CASES) + len(AA_CASES), OUT_DIR))
    if checking:
        sys.exit(0 if all_ok else 1)


if __name__ == "__main__":
    main()
