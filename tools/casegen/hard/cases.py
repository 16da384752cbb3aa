"""The hard triangle and line cases, as data (each family named in
tools/gen_hard_cases.py's docstring): half-integer edges, fans, flipped
windings, far meshes at 8 and 16 bits, slivers, T-junctions, misses, snap
ties, extreme perspective, midpoint ties and long lines, overlaps, unsnapped
and degenerate triangles, every fill rule at large coordinates. Their
`samples_covered` and claims are computed and proved by check.py.
"""

import math
from fractions import Fraction as F

from casegen.casefile import P, V, Tri
from casegen.hard.build import Line, add, case


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

