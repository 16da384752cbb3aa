"""The bundled triangle cases, as data: windings and culls, ties on shared
edges, meshes, snapping, interpolation, degenerate and sliver triangles,
every fill rule. Registering a case computes nothing; tools/gen_cases.py
writes them and check.py verifies the counts they state.
"""

import math
from fractions import Fraction as F

from casegen.casefile import P, V, Tri


def dec6(x):
    """An irrational value rounded once to 6 fractional digits."""
    return F(round(x * 10**6), 10**6)



def tri(a, b, c, interpolation=None):
    return Tri(a, b, c, interpolation)


CASES = []


def case(name, description, width, height, prims, bits=8, fill_rule="top-left", cull="none",
         expect=None, ties=False, snap_sensitive=False, rule_note=None):
    """Registers a case. `ties`: the checker must find that the flipped fill
    rule changes coverage. `snap_sensitive`: the checker must find that some
    wrong tie-breaking of the snapping changes coverage."""
    assert 1 <= width <= 256 and 1 <= height <= 256, name
    CASES.append(dict(name=name, description=description, width=width, height=height,
                      prims=prims, bits=bits, fill_rule=fill_rule, cull=cull,
                      expect=expect or {}, ties=ties, snap_sensitive=snap_sensitive))



# ---------------------------------------------------------------------------
# 1. Windings and cull modes.

HALF = F(1, 2)

RT_CW = [P(0.5, 0.5), P(7.5, 0.5), P(0.5, 7.5)]       # twice-area +49: clockwise on screen
RT_CCW = [RT_CW[0], RT_CW[2], RT_CW[1]]               # the same triangle, counter-clockwise

RT_NOTE = ("The triangle (0.5,0.5) (7.5,0.5) (0.5,7.5) has its top edge on sample row 0, its left "
           "edge on sample column 0 and its hypotenuse through the 8 samples with x+y=7, so the tie "
           "rule decides 21 samples. Under top-left the top and left edges own their samples and the "
           "hypotenuse (a right edge) does not: the samples with x+y<=6, 28 of them. Edge ownership "
           "depends on where the triangle lies, never on the order of its vertices.")

for winding, verts in (("cw", RT_CW), ("ccw", RT_CCW)):
    for cull in ("none", "cw", "ccw"):
        culled = cull == winding
        what = ("culled: it is %s on screen (y down) and cull is %s, so nothing is drawn"
                % ("clockwise" if winding == "cw" else "counter-clockwise", cull)) if culled else \
               ("drawn: it is %s on screen and cull is %s" %
                ("clockwise" if winding == "cw" else "counter-clockwise", cull))
        case("winding_%s_cull_%s" % (winding, cull),
             "A %s triangle with cull %s is %s. %s" % (winding, cull, what, RT_NOTE),
             8, 8, [tri(*verts)], cull=cull,
             expect={"samples_covered": 0 if culled else 28}, ties=not culled)

# Both windings in one case: a square split along its main diagonal, one half
# clockwise and the other counter-clockwise.
SQ = [P(0, 0), P(8, 0), P(8, 8), P(0, 8)]
for cull, count, note in (
        ("none", 64, "Both halves are drawn; the diagonal runs through the 8 samples (k+0.5, k+0.5), and "
                     "each goes to exactly one half, whatever the winding of either half."),
        ("cw", 28, "The upper-right half is clockwise and culled; the lower-left half keeps the samples "
                   "below the diagonal (28) but not those on it, since the diagonal is its right edge."),
        ("ccw", 36, "The lower-left half is counter-clockwise and culled; the upper-right half keeps the "
                    "28 samples above the diagonal and the 8 on it (its left edge owns them): 36.")):
    case("cull_%s_mixed_windings" % cull,
         "Two halves of the full 8x8 canvas with opposite windings (the upper-right one (0,0) (8,0) (8,8) "
         "clockwise, the lower-left one (0,0) (0,8) (8,8) counter-clockwise), cull %s. %s A rasterizer "
         "that derives edge ownership from the winding, or culls the wrong winding, fails." % (cull, note),
         8, 8, [tri(SQ[0], SQ[1], SQ[2]), tri(SQ[0], SQ[3], SQ[2])], cull=cull,
         expect=dict({"samples_covered": count}, **({"watertight": True} if cull == "none" else {})),
         ties=True)

# ---------------------------------------------------------------------------
# 2. Shared edges.

case("shared_edge_horizontal",
     "Two triangles share the horizontal edge y=4.5, which runs through the 8 samples of row 4 from end "
     "to end. The lower triangle's top edge owns them under top-left; a flipped tie rule, an overdraw "
     "(closed edges) or a crack shows up on that row.",
     8, 8, [tri(P(4, 0), P(8, 4.5), P(0, 4.5)), tri(P(0, 4.5), P(8, 4.5), P(4, 8))],
     expect={"watertight": True}, ties=True)

case("shared_edge_vertical",
     "Two triangles share the vertical edge x=4.5, which runs through the 8 samples of column 4 from "
     "top to bottom. The right triangle's left edge owns them under top-left.",
     8, 8, [tri(P(0, 4), P(4.5, 0), P(4.5, 8)), tri(P(4.5, 0), P(8, 4), P(4.5, 8))],
     expect={"watertight": True}, ties=True)

case("shared_edge_diagonal",
     "The full 8x8 canvas split along its main diagonal (0,0)-(8,8), which passes exactly through the "
     "8 samples (k+0.5, k+0.5). Each belongs to exactly one triangle; the union is the canvas, so all "
     "64 samples are covered once.",
     8, 8, [tri(SQ[0], SQ[1], SQ[2]), tri(SQ[0], SQ[2], SQ[3])],
     expect={"watertight": True, "samples_covered": 64}, ties=True)

case("shared_edge_antidiagonal",
     "The full 8x8 canvas split along its anti-diagonal (8,0)-(0,8), through the 8 samples with x+y=7. "
     "The anti-diagonal is a right edge of the upper-left triangle and a left edge of the lower-right "
     "one; each of its samples is drawn once, all 64 samples in all.",
     8, 8, [tri(SQ[0], SQ[1], SQ[3]), tri(SQ[1], SQ[2], SQ[3])],
     expect={"watertight": True, "samples_covered": 64}, ties=True)

case("shared_edge_shallow",
     "Two triangles share a shallow edge of slope 1/3 from (-1,1) to (17,7), which passes exactly "
     "through the samples (0.5,1.5), (3.5,2.5), (6.5,3.5), (9.5,4.5), (12.5,5.5), (15.5,6.5). Near-"
     "horizontal edges are where an incremental edge walker accumulates error. The union contains the "
     "whole 16x8 canvas, so all 128 samples are covered once.",
     16, 8, [tri(P(-1, 1), P(17, 7), P(17, -30)), tri(P(-1, 1), P(-1, 30), P(17, 7))],
     expect={"watertight": True, "samples_covered": 128}, ties=True)

case("shared_edge_steep",
     "Two triangles share a steep edge of slope 3 from (4,-1) to (8.5,12.5), through the samples "
     "(4.5,0.5), (5.5,3.5), (6.5,6.5), (7.5,9.5). The union contains the 12x12 canvas: 144 samples, "
     "each covered once.",
     12, 12, [tri(P(4, -1), P(8.5, 12.5), P(-20, 12.5)), tri(P(4, -1), P(-20, 12.5), P(-20, -1)),
              tri(P(4, -1), P(30, -1), P(8.5, 12.5)), tri(P(30, -1), P(30, 12.5), P(8.5, 12.5))],
     expect={"watertight": True, "samples_covered": 144}, ties=True)

case("shared_edge_long_shallow",
     "A 64x8 canvas cut by one edge of slope 1/16 from (-0.5, 2.4375) to (64.5, 6.5) that grazes the "
     "samples (0.5,2.5), (16.5,3.5), (32.5,4.5), (48.5,5.5): long, nearly horizontal edges whose "
     "error grows along the span. Covered by two triangles on each side of it, all vertices shared "
     "exactly; 512 samples, each once.",
     64, 8, [tri(P(-0.5, F(39, 16)), P(64.5, 6.5), P(64.5, -1)),
             tri(P(-0.5, F(39, 16)), P(64.5, -1), P(-0.5, -1)),
             tri(P(-0.5, F(39, 16)), P(-0.5, 9), P(64.5, 6.5)),
             tri(P(64.5, 6.5), P(-0.5, 9), P(64.5, 9))],
     expect={"watertight": True, "samples_covered": 512}, ties=True)

case("shared_edge_fractions_offgrid",
     "Two triangles share an edge whose ends are written as fractions (-1/3, 7/3) and (49/3, 17/3); "
     "they snap to 8-bit subpixels (-85/256, 597/256) and (4181/256, 1451/256). The snapped edge misses "
     "every sample by a few subpixels: an exact test and a careless fixed-point test can disagree. "
     "Both triangles give the same fraction strings, so they snap to the same vertices and stay "
     "watertight.",
     16, 8, [tri(P(F(-1, 3), F(7, 3)), P(F(49, 3), F(17, 3)), P(8, -5)),
             tri(P(F(-1, 3), F(7, 3)), P(2, 12), P(F(49, 3), F(17, 3)))],
     expect={"watertight": True})

case("shared_edge_mixed_windings",
     "A steep shared edge (slope -3/2 through the samples (6.5,1.5), (4.5,4.5), (2.5,7.5)) between two "
     "triangles listed with the same winding direction along it (one clockwise, one counter-clockwise). "
     "Ownership must follow the geometry, not the vertex order.",
     10, 10, [tri(P(7.5, 0), P(1.5, 9), P(10, 10)), tri(P(7.5, 0), P(1.5, 9), P(0, 0))],
     expect={"watertight": True}, ties=True)

# ---------------------------------------------------------------------------
# 3. A 4x4 quad grid, rotated.


def quad_grid(angle_deg, centre, cell, n=4):
    """(n+1)^2 vertices computed once; 2 n^2 triangles, alternating diagonals."""
    if angle_deg % 90 == 0:
        k = (angle_deg // 90) % 4
        c, s = [(1, 0), (0, 1), (-1, 0), (0, -1)][k]
        exact = True
    else:
        a = math.radians(angle_deg)
        c, s = math.cos(a), math.sin(a)
        exact = False
    verts = {}
    for j in range(n + 1):
        for i in range(n + 1):
            u = (F(i) - F(n, 2)) * cell
            v = (F(j) - F(n, 2)) * cell
            if exact:
                x = centre[0] + c * u - s * v
                y = centre[1] + s * u + c * v
            else:
                x = dec6(float(centre[0]) + c * float(u) - s * float(v))
                y = dec6(float(centre[1]) + s * float(u) + c * float(v))
            verts[(i, j)] = (F(x), F(y))
    tris = []
    for j in range(n):
        for i in range(n):
            a, b, cc, d = verts[(i, j)], verts[(i + 1, j)], verts[(i + 1, j + 1)], verts[(i, j + 1)]
            if (i + j) % 2 == 0:
                tris += [tri(a, b, cc), tri(a, cc, d)]
            else:
                tris += [tri(a, b, d), tri(b, cc, d)]
    return tris


for angle in (0, 15, 30, 45, 60, 75, 90):
    exp = {"watertight": True}
    extra = ""
    if angle in (0, 90):
        exp["samples_covered"] = 1024
        extra = (" At %d degrees the grid is the square [8.5, 40.5]^2 with every vertex on a sample and "
                 "every edge on a sample row, column or diagonal: a tie at every vertex and along "
                 "every edge. Its left and top sides own their samples, its right and bottom sides do "
                 "not, so it covers 32x32 = 1024 samples, each once." % angle)
    else:
        extra = (" The rotated vertices are irrational; each is rounded once to 6 decimals and written "
                 "identically in every triangle that uses it, then snapped to 1/256.")
    case("quad_grid_rot%d" % angle,
         "A 4x4 grid of 8-px quads (32 triangles, diagonals alternating) centred on the sample "
         "(24.5, 24.5) and rotated by %d degrees. Every interior vertex is shared by 4 or 8 triangles "
         "and every interior edge by 2: any crack or double hit is a watertightness failure.%s"
         % (angle, extra),
         48, 48, quad_grid(angle, (F(24.5), F(24.5)), 8), expect=exp, ties=angle in (0, 45, 90))

# ---------------------------------------------------------------------------
# 4. Fans around a sample centre.


def circle_fan(centre, radius, n, phase=0.0, reverse=False):
    ring = [(dec6(float(centre[0]) + radius * math.cos(phase + 2 * math.pi * k / n)),
             dec6(float(centre[1]) + radius * math.sin(phase + 2 * math.pi * k / n))) for k in range(n)]
    tris = []
    for k in range(n):
        a, b = ring[k], ring[(k + 1) % n]
        tris.append(tri(centre, b, a) if reverse else tri(centre, a, b))
    return tris


case("fan_16_center",
     "16 triangles fan around the sample (8.5, 8.5): all 16 edges meet exactly at a sample centre, "
     "which exactly one triangle may cover. The ring vertices (radius 8, rounded to 6 decimals) are "
     "shared exactly between neighbours. The spokes at 0, 90, 180 and 270 degrees run along a sample "
     "row or column, the diagonal ones through the samples (8.5+-k, 8.5+-k) after snapping.",
     17, 17, circle_fan((F(8.5), F(8.5)), 8, 16), expect={"watertight": True}, ties=True)

case("fan_16_center_ccw",
     "The fan of fan_16_center with every triangle's vertices listed in the other order "
     "(counter-clockwise on screen): coverage must be identical, since ownership is geometric.",
     17, 17, circle_fan((F(8.5), F(8.5)), 8, 16, reverse=True), expect={"watertight": True}, ties=True)

case("fan_64_center",
     "64 thin triangles fan around the sample (16.5, 16.5) with a ring of radius 16 (6 decimals, "
     "shared by neighbours). Near the centre the wedges are narrower than a subpixel: the centre "
     "sample and the samples along each of the 64 spokes must each go to exactly one triangle.",
     33, 33, circle_fan((F(16.5), F(16.5)), 16, 64), expect={"watertight": True}, ties=True)

case("fan_24_offset_phase_b4",
     "24 triangles fan around the sample (12.5, 12.5) at 4 subpixel bits, the ring rotated by a third "
     "of a wedge (5 degrees) so that no spoke is axis-aligned: 24 irrational ring vertices, rounded "
     "to 6 decimals and then snapped to a coarse 1/16 px, where neighbouring spokes come close.",
     25, 25, circle_fan((F(12.5), F(12.5)), 12, 24, phase=2 * math.pi / 72), bits=4,
     expect={"watertight": True})


def square_fan(centre, half, step):
    cx, cy = centre
    ring = []
    # clockwise on screen along the square's boundary, starting at the top-left corner
    for t in range(0, 2 * half, step):
        ring.append((cx - half + t, cy - half))
    for t in range(0, 2 * half, step):
        ring.append((cx + half, cy - half + t))
    for t in range(0, 2 * half, step):
        ring.append((cx + half - t, cy + half))
    for t in range(0, 2 * half, step):
        ring.append((cx - half, cy + half - t))
    return [tri(centre, ring[k], ring[(k + 1) % len(ring)]) for k in range(len(ring))]


case("fan_16_square_ring",
     "16 triangles fan from the sample (8.5, 8.5) to 16 vertices on the square [0.5, 16.5]^2, every one "
     "a sample centre. Every spoke passes through several samples (directions (1,0), (1,2), (1,1), "
     "(2,1), ...), and the square's sides run along sample rows and columns: nearly every tie there "
     "is. The square's left and top sides own their samples, the right and bottom do not, so "
     "16x16 = 256 samples are covered, each once.",
     17, 17, square_fan((F(8.5), F(8.5)), 8, 4), expect={"watertight": True, "samples_covered": 256},
     ties=True)

case("fan_16_center_snap_tie",
     "The fan of fan_16_square_ring with its centre written as (8.5 + 1/512, 8.5 - 1/512): both "
     "coordinates lie exactly half a subpixel off the 1/256 grid and round to even, which is back to "
     "the sample (8.5, 8.5). Rounding halves up or away from zero moves the centre off the sample and "
     "changes which wedge owns it. The centre is computed once and shared by all 16 triangles.",
     17, 17, [tri(P(8.5 + 1 / 512, 8.5 - 1 / 512), t.v[1], t.v[2])
              for t in square_fan((F(8.5), F(8.5)), 8, 4)],
     expect={"watertight": True, "samples_covered": 256}, ties=True, snap_sensitive=True)

# ---------------------------------------------------------------------------
# 5. Pinwheels of tiny triangles around pixel centres.

SPOKES8 = [(3, 0), (3, 3), (0, 3), (-3, 3), (-3, 0), (-3, -3), (0, -3), (3, -3)]


def pinwheel(centre, spokes, unit):
    cx, cy = centre
    ring = [(cx + sx * unit, cy + sy * unit) for sx, sy in spokes]
    return [tri(centre, ring[k], ring[(k + 1) % len(ring)]) for k in range(len(ring))]


def pinwheel_grid(spokes, unit, shifts, spacing=2):
    tris = []
    for idx, (dx, dy) in enumerate(shifts):
        i, j = idx % 3, idx // 3
        c = (F(spacing * i) + F(1.5) + dx * unit, F(spacing * j) + F(1.5) + dy * unit)
        tris += pinwheel(c, spokes, unit)
    return tris


SHIFTS9 = [(dx, dy) for dy in (-1, 0, 1) for dx in (-1, 0, 1)]

case("pinwheel_axis_shift1_b8",
     "Nine pinwheels of 8 tiny triangles (spokes 3 subpixels long, along the axes and diagonals) "
     "around the pixel centres (1.5+2i, 1.5+2j), each shifted by (dx, dy) in {-1,0,1}^2 subpixels. "
     "Every shift puts the sample exactly on a spoke or on the hub, so the tie rule alone decides "
     "which triangle of each pinwheel covers it; exactly one does, 9 samples in all.",
     8, 8, pinwheel_grid(SPOKES8, F(1, 256), SHIFTS9), expect={"watertight": True, "samples_covered": 9},
     ties=True)

case("pinwheel_axis_shift1_b4",
     "pinwheel_axis_shift1_b8 at 4 subpixel bits: spokes of 3/16 px, shifts of +-1/16 px. The sample "
     "lies on a spoke or at the hub of every pinwheel; 9 samples, each covered once.",
     8, 8, pinwheel_grid(SPOKES8, F(1, 16), SHIFTS9), bits=4,
     expect={"watertight": True, "samples_covered": 9}, ties=True)

SPOKES_SKEW = [(3, 1), (-1, 3), (-3, -1), (1, -3)]
case("pinwheel_skew_shift1_b8",
     "Nine pinwheels of 4 triangles whose spokes (3,1), (-1,3), (-3,-1), (1,-3) subpixels are skewed, "
     "shifted by {-1,0,1}^2 subpixels: the sample now falls strictly inside one wedge (or on the hub), "
     "a few subpixels from three edges at once. Each pinwheel covers its sample exactly once: 9.",
     8, 8, pinwheel_grid(SPOKES_SKEW, F(1, 256), SHIFTS9), expect={"watertight": True, "samples_covered": 9})

SHIFTS_RIM = [(dx, dy) for dy in (-3, 0, 3) for dx in (-3, 0, 3)]
case("pinwheel_rim_shift3_b8",
     "The 8-spoke pinwheels of pinwheel_axis_shift1_b8 shifted by {-3,0,3}^2 subpixels, so the sample "
     "lands on the pinwheel's rim, the square [-3,3]^2 subpixels (at a corner or the middle of a side) "
     "or at its hub. Under top-left the square owns its left and top sides: the sample is covered "
     "when the shift is 0 or +3 in both x and y, 4 pinwheels of 9.",
     8, 8, pinwheel_grid(SPOKES8, F(1, 256), SHIFTS_RIM), expect={"samples_covered": 4}, ties=True)

# ---------------------------------------------------------------------------
# 6. Sub-pixel triangles that hit no sample.


def no_sample_tris(s):
    """Tiny triangles near the sample s = (sx, sy), none covering it under top-left."""
    sx, sy = s
    q = F(1, 4)
    return [
        # strictly between samples
        tri((sx + F(1, 8), sy + F(1, 8)), (sx + F(7, 8), sy + F(1, 8)), (sx + F(1, 8), sy + F(7, 8))),
        # the sample on a vertical right edge
        tri((sx - q, sy - q), (sx, sy - q), (sx, sy + q)),
        # the sample on a horizontal bottom edge
        tri((sx - q, sy), (sx, sy - q), (sx + q, sy)),
        # the sample at a vertex where two right edges meet
        tri((sx, sy), (sx - q, sy + F(1, 10)), (sx - q, sy - F(1, 10))),
        # the sample at the bottom vertex of a thin upright sliver
        tri((sx, sy), (sx - F(1, 256), sy - q), (sx + F(1, 256), sy - q)),
    ]


prims = []
for k, s in enumerate([(F(1.5), F(1.5)), (F(4.5), F(1.5)), (F(1.5), F(4.5)), (F(4.5), F(4.5))]):
    t = no_sample_tris(s)
    prims += [t[0], t[1 + k]]
case("subpixel_no_sample",
     "Sub-pixel triangles that hit no sample: one between sample centres, one with its right edge "
     "through a sample, one with its bottom edge through a sample, one with the sample at a vertex "
     "where two right edges meet, one with the sample at the lowest vertex of a thin upright sliver. "
     "Under top-left none owns its sample; a flipped or closed tie rule draws them.",
     7, 7, prims, expect={"samples_covered": 0}, ties=True)

case("subpixel_no_sample_snapped_away",
     "Tiny triangles that contain a sample before snapping, but whose vertices (within 1/512 of the "
     "sample, i.e. within half a subpixel) all snap onto it: after snapping they have zero area and "
     "cover nothing. Rasterizing before snapping, or with more fraction bits than the rules allow, "
     "draws them.",
     6, 6, [tri(P(1.5 - 1 / 1024, 1.5 - 1 / 1024), P(1.5 + 1 / 1024, 1.5 - 1 / 1024), P(1.5, 1.5 + 1 / 1024)),
            tri(P(4.5 - 1 / 512, 1.5), P(4.5 + 1 / 512, 1.5 - 1 / 1024), P(4.5 + 1 / 512, 1.5 + 1 / 1024)),
            tri(P(1.5, 4.5 - 1 / 512), P(1.5 + 1 / 1024, 4.5 + 1 / 512), P(1.5 - 1 / 1024, 4.5 + 1 / 512))],
     expect={"samples_covered": 0}, snap_sensitive=True)

case("subpixel_no_sample_b4",
     "At 4 subpixel bits (1/16 px) tiny triangles 1-3 subpixels across sit between sample centres, "
     "or have the sample on a right or bottom edge, or collapse when snapped. None may be drawn.",
     4, 4, [tri(P(0.5625, 0.5625), P(0.75, 0.5625), P(0.5625, 0.75)),
            tri(P(2.4375, 0.4375), P(2.5, 0.4375), P(2.5, 0.5625)),
            tri(P(0.4375, 2.5), P(0.5, 2.4375), P(0.5625, 2.5)),
            tri(P(2.5 + 1 / 64, 2.5), P(2.5 + 1 / 32, 2.5 + 1 / 64), P(2.5 - 1 / 64, 2.5 + 1 / 32))],
     bits=4, expect={"samples_covered": 0}, ties=True)

# ---------------------------------------------------------------------------
# 7. The guard band: coordinates up to +-32768.

case("guard_band_huge",
     "One triangle (-32768,-32768) (32768,0) (0,32768) whose vertices lie at the coordinate limit, "
     "4096 canvases away; the 32x32 canvas lies strictly inside it, so all 1024 samples are covered. "
     "In 16.9 fixed point the edge-function products reach about 2^50: an i32 setup overflows, an "
     "f32 setup loses the sample offsets.",
     32, 32, [tri(P(-32768, -32768), P(32768, 0), P(0, 32768))], expect={"samples_covered": 1024})

case("guard_band_vertex_32768",
     "A triangle with two vertices at x = -32768 and x = 32768 exactly on the sample row y = 4.5, and a "
     "third at (0, 32768): its top edge runs through 16 samples of the canvas 32768 px from its ends. "
     "Under top-left the top edge owns them: rows 4..15 are covered, 12x16 = 192 samples.",
     16, 16, [tri(P(-32768, 4.5), P(32768, 4.5), P(0, 32768))], expect={"samples_covered": 192}, ties=True)

case("guard_band_diagonal_pair",
     "Two huge triangles share the diagonal from (-32767.5,-32767.5) to (32767.5,32767.5), which "
     "passes exactly through the 16 samples (k+0.5, k+0.5) of the canvas; their other vertices are "
     "the corners (32768,-32768) and (-32768,32768). Each diagonal sample belongs to exactly one; "
     "the canvas lies inside the union, 256 samples.",
     16, 16, [tri(P(-32767.5, -32767.5), P(32768, -32768), P(32767.5, 32767.5)),
              tri(P(-32767.5, -32767.5), P(32767.5, 32767.5), P(-32768, 32768))],
     expect={"watertight": True, "samples_covered": 256}, ties=True)

H16 = F(1, 131072)  # half a subpixel at 16 bits
case("guard_band_b16",
     "At 16 subpixel bits, two triangles spanning the whole coordinate range share an edge of slope "
     "1/16 from (-32768, -2047.53125) to (32768, 2048.46875) through the samples (0.5,0.5) and "
     "(16.5,1.5); the apexes are written as (-1/131072, -32768 + 1/131072) and "
     "(1/131072, 32768 - 1/131072), exactly half a subpixel off the grid, and round to even: "
     "(0, -32768) and (0, 32768). Edge functions need more than 64 bits here. The canvas lies inside "
     "the union: 256 samples, each once.",
     32, 8, [tri(P(-32768, F(-65521, 32)), P(H16 * -1, -32768 + H16), P(32768, F(65551, 32))),
             tri(P(-32768, F(-65521, 32)), P(32768, F(65551, 32)), P(H16, 32768 - H16))],
     bits=16, expect={"watertight": True, "samples_covered": 256}, ties=True)

# ---------------------------------------------------------------------------
# 8. Snapping ties: half a subpixel off the grid.


def band_v(x0, x1, y0, y1):
    """A vertical band [x0,x1] x [y0,y1] as two triangles."""
    return [tri(P(x0, y0), P(x1, y0), P(x1, y1)), tri(P(x0, y0), P(x1, y1), P(x0, y1))]


def snap_columns(bits):
    h = F(1, 2 ** (bits + 1))  # half a subpixel
    tris = []
    # column c = 0, 2, 4, 6 (rows 0..7) and rows r = 8, 10, 12, 14 (columns 0..7)
    offsets = [(h, h), (3 * h, 3 * h), (-h, -h), (-3 * h, -3 * h)]
    for k, (dl, dr) in enumerate(offsets):
        c = 2 * k
        tris += band_v(F(c) + HALF + dl, F(c) + F(1.5) + dr, F(0), F(8))
    for k, (dt, db) in enumerate(offsets):
        r = 8 + 2 * k
        x0, x1, y0, y1 = F(0), F(8), F(r) + HALF + dt, F(r) + F(1.5) + db
        tris += [tri(P(x0, y0), P(x1, y0), P(x1, y1)), tri(P(x0, y0), P(x1, y1), P(x0, y1))]
    return tris


case("snap_tie_half_subpixel_b8",
     "Bands whose sides lie exactly half a subpixel (1/512) or three halves (3/512) off the 1/256 grid, "
     "next to sample rows and columns. Ties round to even: c+0.5+1/512 -> c+0.5 (a sample column), "
     "c+0.5+3/512 -> c+0.5+4/512, c+0.5-1/512 -> c+0.5, c+0.5-3/512 -> c+0.5-4/512. Whether a side "
     "lands on the samples, and so whether the tie rule or the interior decides them, depends on "
     "rounding ties to even; rounding halves up (or away from zero) moves a whole column or row. The "
     "bottom-right variant of this case catches rounding halves down.",
     8, 16, snap_columns(8), ties=True, snap_sensitive=True)

case("snap_tie_half_subpixel_b4",
     "snap_tie_half_subpixel_b8 at 4 subpixel bits: sides at c+0.5 +- 1/32 and +- 3/32, half a 1/16 "
     "subpixel off the grid; ties go to even multiples of 1/16.",
     8, 16, snap_columns(4), bits=4, ties=True, snap_sensitive=True)

case("snap_tie_half_subpixel_b8_bottom_right",
     "snap_tie_half_subpixel_b8 under the bottom-right rule, which owns right and bottom sides: a side "
     "at c+0.5-1/512 must snap up to the sample column c+0.5 (1/512 is half a subpixel and 128 is "
     "even) and then owns it; rounding halves down leaves it off the samples. Together with the "
     "top-left case this catches both directions of wrong tie rounding.",
     8, 16, snap_columns(8), fill_rule="bottom-right", ties=True, snap_sensitive=True)

case("snap_tie_examples_b8",
     "The textbook ties at 8 bits, made to decide coverage. (4+1/512, 0) rounds to (4, 0) (1024 is "
     "even), and its edge to (8, 4) then runs through the samples (4.5,0.5)..(7.5,3.5) as a right edge, "
     "which does not own them; rounding the half up moves the vertex right and pulls those samples "
     "inside. (3, 4+3/512) rounds to (3, 4+4/512) (1026 is even), and its edge to (4, 5-1/128) then "
     "passes exactly through the sample (3.5, 4.5), again as a right edge; rounding the half down "
     "moves the vertex up and pulls the sample inside.",
     8, 8, [tri(P(4 + 1 / 512, 0), P(8, 4), P(4, 4)),
            tri(P(3, 4 + 3 / 512), P(4, 5 - 1 / 128), P(0, 8))],
     ties=True, snap_sensitive=True)

case("snap_tie_negative_b8",
     "Vertices half a subpixel off the grid at negative coordinates, where rounding half away from "
     "zero, half up or half toward zero disagree with ties to even: -1/512 -> 0 (not -1/256), "
     "-1-1/512 -> -1, -3/512 -> -4/512 (not -2/512). From each such vertex an edge runs exactly "
     "through sample centres as a right edge (not owned under top-left); a wrongly rounded vertex "
     "tilts the edge so that those samples fall inside.",
     8, 8, [tri(P(0, F(-1, 512)), P(8, 8), P(0, 8)),
            tri(P(1, -1 - F(1, 512)), P(9, 7), P(1, 7)),
            tri(P(8, F(-3, 512)), P(7, 1 + F(1, 128)), P(0, 0))],
     ties=True, snap_sensitive=True)

case("snap_tie_b0",
     "subpixel_bits 0: vertices snap to whole pixels, ties to even, so 0.5 -> 0, 8.5 -> 8, 1.5 -> 2, "
     "2.5 -> 2, 5.5 -> 6. The square written as (0.5,0.5)-(8.5,8.5) snaps to the full canvas [0,8]^2 "
     "(64 samples) and is split along its diagonal through the samples (k+0.5, k+0.5); rounding "
     "halves up would give [1,9]^2 and leave row 0 and column 0 empty. A small triangle whose "
     "vertices 1.5 and 2.5 both snap to 2 collapses to zero area.",
     8, 8, [tri(P(0.5, 0.5), P(8.5, 0.5), P(8.5, 8.5)), tri(P(0.5, 0.5), P(8.5, 8.5), P(0.5, 8.5)),
            tri(P(1.5, 5.5), P(2.5, 5.5), P(2.5, 7.5))],
     bits=0, expect={"watertight": True, "samples_covered": 64}, ties=True, snap_sensitive=True)

case("snap_b0_diagonals",
     "subpixel_bits 0: a four-triangle mesh whose vertices are written as 0.4, 2.6, 4.6, 11.6 and "
     "round (not truncate) to whole pixels (0, 3, 5, 12). Between whole-pixel points an odd step "
     "apart in both x and y the midpoint is a sample: the edges of steps (1,3) and (5,9) pass exactly "
     "through (0.5,1.5) and (3.5,7.5), where the tie rule decides.",
     12, 12, [tri(P("0.4", "0.4"), P("4.6", 0), P(1, "2.6")), tri(P(1, "2.6"), P("4.6", 0), P(6, "11.6")),
              tri(P("4.6", 0), P(12, "0.4"), P(6, "11.6")), tri(P(1, "2.6"), P(6, "11.6"), P(0, 12))],
     bits=0, expect={"watertight": True}, ties=True)

# ---------------------------------------------------------------------------
# 9. Interpolation: perspective, linear, flat, depth.

QUAD = [P(1, 1), P(15, 2), P(14, 15), P(2, 13)]


def quad_vertices(ws, attrs, zs):
    return [V(x, y, z=z, w=w, attributes=a) for (x, y), w, a, z in zip(QUAD, ws, attrs, zs)]


qv = quad_vertices([F(1, 10), 4, 1, F(5, 2)],
                   [[1, 0, -10000, F(1, 3)], [0, 1, 10000, F(-2, 7)], [0, 0, F(1, 2), 5000], [1, 1, -1, 0]],
                   [0, F(1, 2), 1, F(1, 4)])
case("interp_perspective_w_range",
     "A quad of two triangles with w = 0.1, 4, 1, 2.5 at its corners (a 40:1 range) and 4 attributes "
     "up to +-1e4, including the fractions 1/3 and -2/7. Perspective-correct values bend strongly "
     "toward the w=0.1 corner; screen-space interpolation misses by far more than the bound. Depth "
     "is screen-space linear whatever w is. The shared diagonal carries identical values in both "
     "triangles.",
     16, 16, [tri(qv[0], qv[1], qv[2]), tri(qv[0], qv[2], qv[3])], expect={"watertight": True})

big = [V(0, 0, z=-1000000, w=F(1, 10), attributes=[10000, -10000, 0, 1, 2, 3]),
       V(32, 4, z=1000000, w=4, attributes=[-10000, 10000, F(1, 3), 4, 5, 6]),
       V(6, 32, z=F(1, 7), w=F(7, 10), attributes=[F(3, 7), -9999.5, 10000, 7, 8, 9])]
case("interp_perspective_extreme",
     "One triangle over a 32x32 canvas with w from 0.1 to 4, six attributes including +-1e4 and "
     "fractions, and depth from -1e6 to 1e6: the f32 rounding of large values must stay within "
     "2^-16 of the largest magnitude; a wrong weight or swapped vertex breaks it by orders of "
     "magnitude.",
     32, 32, [tri(*big)])

lin = [V(v.x, v.y, z=v.z, w=v.w, attributes=v.attributes) for v in big]
case("interp_linear",
     "The triangle of interp_perspective_extreme with linear (screen-space) interpolation: w must be "
     "ignored, values are the plain barycentric blend of the snapped vertices.",
     32, 32, [tri(*lin, interpolation="linear")])

fl = [V(2, 1, z=F(1, 3), w=F(1, 10), attributes=[7, -10000, F(1, 3)]),
      V(15, 3, z=2, w=4, attributes=[-1, 2, 3]),
      V(3, 15, z=-5, w=2, attributes=[10000, 0, F(-5, 7)]),
      V(14, 14, z=0, w=1, attributes=[0, 1, 2])]
case("interp_flat",
     "Flat interpolation: each triangle takes every attribute from its first (provoking) vertex, "
     "exactly as written, whatever w is. The two triangles share an edge but start from different "
     "vertices, so each half of the quad is uniform with its own values. Depth is still "
     "interpolated linearly.",
     16, 16, [tri(fl[0], fl[1], fl[2], interpolation="flat"), tri(fl[3], fl[2], fl[1], interpolation="flat")],
     expect={"watertight": True})

dz = [V(0.5, 0.5, z=0), V(15.5, 0.5, z=1), V(0.5, 15.5, z=-1), V(15.5, 15.5, z=F(1, 3))]
case("interp_depth_z",
     "Depth only: a quad whose corners are sample centres with z = 0, 1, -1 and 1/3. z is linear in "
     "screen space, and at a covered corner sample it equals the vertex value exactly; the diagonal "
     "passes through samples shared by both triangles.",
     16, 16, [tri(dz[0], dz[1], dz[3]), tri(dz[0], dz[3], dz[2])], expect={"watertight": True}, ties=True)

zw = [V(1, 1, z=F(1, 2), w=F(1, 10), attributes=[0]), V(15, 1, z=F(1, 2), w=4, attributes=[1]),
      V(8, 15, z=F(-3, 2), w=1, attributes=[2])]
case("interp_depth_perspective_w",
     "Depth with strongly varying w: z must still be interpolated linearly in screen space (z is "
     "already divided by w), while the attribute is perspective-correct. A rasterizer that divides z "
     "by w again, or interpolates it with the perspective weights, fails the depth bound.",
     16, 16, [tri(*zw)])

mixed = [V(0, 0, z=1, w=F(1, 5), attributes=[100, -100]), V(16, 0, z=2, w=3, attributes=[-100, 100]),
         V(0, 16, z=3, w=1, attributes=[F(1, 3), 50]), V(16, 16, z=4, w=F(1, 2), attributes=[0, 0])]
case("interp_mixed_modes",
     "Three overlapping triangles with perspective, linear and flat interpolation, drawn in that "
     "order: each sample keeps the values of the last triangle covering it, computed with that "
     "triangle's mode.",
     16, 16, [tri(mixed[0], mixed[1], mixed[2]), tri(mixed[1], mixed[3], mixed[2], interpolation="linear"),
              tri(mixed[3], mixed[0], V(8, -4, z=0, w=2, attributes=[-7, 7]), interpolation="flat")])


def fan_with_w():
    c = V(8.5, 8.5, z=F(1, 2), w=1, attributes=[0, 0, 0])
    ring = []
    for k in range(16):
        a = 2 * math.pi * k / 16
        w = [F(1, 10), F(1, 2), 2, 4][k % 4]
        ring.append(V(dec6(8.5 + 8 * math.cos(a)), dec6(8.5 + 8 * math.sin(a)), z=F(k, 16), w=w,
                      attributes=[dec6(10000 * math.cos(a)), dec6(10000 * math.sin(a)), k]))
    return [tri(c, ring[k], ring[(k + 1) % 16]) for k in range(16)]


case("interp_perspective_fan",
     "The 16-triangle fan around the sample (8.5, 8.5) with per-vertex w cycling through 0.1, 0.5, 2, 4 "
     "and attributes up to +-1e4 (cos, sin, index): every triangle is perspective-interpolated with "
     "different w at its ring vertices, and the hub sample must take the exact hub values.",
     17, 17, fan_with_w(), expect={"watertight": True}, ties=True)

# ---------------------------------------------------------------------------
# 10. Degenerate triangles and slivers, under every cull mode.

DEGENERATE = [
    tri(P(0.5, 0.5), P(4.5, 4.5), P(7.5, 7.5)),          # collinear through samples
    tri(P(7.5, 0.5), P(0.5, 7.5), P(3.5, 4.5)),          # collinear, the other diagonal
    tri(P(3.5, 3.5), P(3.5, 3.5), P(3.5, 3.5)),          # a point on a sample
    tri(P(0.5, 2.5), P(7.5, 2.5), P(0.5, 2.5)),          # two equal vertices, along a sample row
    tri(P(5.5, 0), P(5.5, 8), P(5.5, 3)),                # vertical, along a sample column
    tri(P(0.5, 5.5), P(4.5, 5.5 + 1 / 1024), P(7.5, 5.5)),  # collinear only after snapping
    tri(P(1, F(1, 3)), P(7, F(7, 3)), P(4, F(4, 3))),    # collinear with fractions
]

for cull in ("none", "cw", "ccw"):
    case("degenerate_collinear_cull_%s" % cull,
         "Zero-area triangles under cull %s: collinear vertices along sample diagonals, a row and a "
         "column; a triangle that is one point on a sample; two equal vertices; a triangle that is "
         "collinear only after snapping ((4.5, 5.5+1/1024) snaps onto the row 5.5); collinear "
         "fractions. Their winding is neither clockwise nor counter-clockwise: nothing may be drawn, "
         "even on the samples they pass through." % cull,
         8, 8, DEGENERATE, cull=cull, expect={"samples_covered": 0})

SLIVERS = [
    # long thin slivers whose long edge passes through samples (one subpixel wide)
    tri(P(0.5, 0.5), P(15.5, 5.5), P(15.5, 5.5 + 1 / 256)),          # cw
    tri(P(0.5, 2.5), P(15.5, 7.5 + 1 / 256), P(15.5, 7.5)),          # ccw
    # a sliver pair: the parallelogram split along its long diagonal
    tri(P(0.5, 9.5), P(15.5, 14.5), P(0.5, 9.5 + 1 / 128)),          # ccw
    tri(P(0.5, 9.5), P(15.5, 14.5 - 1 / 128), P(15.5, 14.5)),        # cw
    # almost vertical slivers through sample columns
    tri(P(2.5, 10), P(2.5 + 1 / 256, 10), P(2.5, 16)),
    tri(P(13.5, 0), P(13.5, 8), P(13.5 - 1 / 256, 8)),
]
for cull in ("none", "cw", "ccw"):
    case("sliver_cull_%s" % cull,
         "Slivers one or two subpixels wide, of both windings, under cull %s. Their long edges pass "
         "exactly through sample centres (slopes 1/3, vertical), so every covered sample is a tie on "
         "an edge a subpixel from the opposite one; area is tiny but not zero, so the culling sign "
         "must be exact." % cull,
         16, 16, SLIVERS, cull=cull, ties=True)

case("sliver_fan_needles",
     "Twelve needle triangles from a common vertex (0.5, 0.5) to points one subpixel apart near "
     "(24.5, 6.5), forming a fan of shared edges with slopes just around 1/4; the middle spoke passes "
     "through the samples (4.5,1.5), (8.5,2.5), ..., (24.5,6.5), each of which must go to exactly "
     "one of the two needles beside it. Needles are far thinner than a pixel near the hub.",
     32, 8, [tri(P(0.5, 0.5), P(24.5, F(6.5) + F(k - 6, 256)), P(24.5, F(6.5) + F(k - 5, 256)))
             for k in range(12)], expect={"watertight": True}, ties=True)

# ---------------------------------------------------------------------------
# 11. Every fill rule on one tie-heavy mesh.


def rect_fan():
    """A fan from the sample (6.5, 4.5) to points every 2 px on the border of [0.5,12.5]x[0.5,8.5]."""
    ring = []
    for x in range(0, 12, 2):
        ring.append((F(x) + HALF, F(0.5)))
    for y in range(0, 8, 2):
        ring.append((F(12.5), F(y) + HALF))
    for x in range(12, 0, -2):
        ring.append((F(x) + HALF, F(8.5)))
    for y in range(8, 0, -2):
        ring.append((F(0.5), F(y) + HALF))
    c = (F(6.5), F(4.5))
    return [tri(c, ring[k], ring[(k + 1) % len(ring)]) for k in range(len(ring))]


RULE_WHY = {
    "top-left": "top and left edges own their samples (D3D11)",
    "bottom-right": "bottom and right edges own their samples",
    "top-right": "top and right edges own their samples",
    "bottom-left": "bottom and left edges own their samples",
    "all-edges": "every edge owns its samples, so samples on shared edges are drawn twice (not watertight)",
}
for rule in ("top-left", "bottom-right", "top-right", "bottom-left", "all-edges"):
    if rule == "all-edges":
        exp = {"samples_covered": 117}
        count = ("the closed rectangle holds 13x9 = 117 samples, and every one of them is covered, the "
                 "ones on interior edges more than once")
    else:
        exp = {"watertight": True, "samples_covered": 96}
        count = ("the rectangle owns two of its sides, so 12x8 = 96 samples are covered, each exactly "
                 "once")
    case("fill_rule_%s" % rule.replace("-", "_"),
         "Fill rule %s: %s. The mesh is a fan of 20 triangles from the sample (6.5, 4.5) to sample "
         "centres every 2 px along the border of the rectangle [0.5,12.5]x[0.5,8.5]; spokes of "
         "directions (3,2), (1,2), (0,1), (1,1)... run through many samples, and the border runs "
         "along sample rows and columns: ties almost everywhere. %s."
         % (rule, RULE_WHY[rule], count[0].upper() + count[1:]),
         14, 10, rect_fan(), fill_rule=rule, expect=exp, ties=rule != "all-edges")

# ---------------------------------------------------------------------------
# 12. Unsnapped dyadic geometry.

case("unsnapped_sliver_dyadic",
     "subpixel_bits null: a sliver (0.5, 4.5) (4.5, 4.5+1/1024) (8.5, 4.5) only 1/1024 px tall. "
     "Unsnapped it is a real triangle whose top edge runs along sample row 4 and owns the samples "
     "x = 0.5 .. 7.5 (8 samples; the sample at (8.5, 4.5) is a vertex on its right edge). Snapping "
     "to 8 bits would make it collinear and draw nothing.",
     10, 10, [tri(P(0.5, 4.5), P(8.5, 4.5), P(4.5, 4.5 + 1 / 1024))], bits=None,
     expect={"samples_covered": 8}, ties=True, snap_sensitive=True)

case("unsnapped_tiny_covers",
     "subpixel_bits null: triangles a couple of 1/1024 px across around sample centres, each "
     "containing its sample strictly inside (3 samples), and one 1/1024 px to the side of a sample "
     "that must stay empty. With 8-bit snapping all four would collapse.",
     6, 6, [tri(P(1.5 - 1 / 1024, 1.5 - 1 / 1024), P(1.5 + 1 / 1024, 1.5 - 1 / 1024), P(1.5, 1.5 + 1 / 1024)),
            tri(P(4.5 - 1 / 512, 1.5), P(4.5 + 1 / 512, 1.5 - 1 / 1024), P(4.5 + 1 / 512, 1.5 + 1 / 1024)),
            tri(P(1.5, 4.5 - 1 / 512), P(1.5 + 1 / 1024, 4.5 + 1 / 512), P(1.5 - 1 / 1024, 4.5 + 1 / 512)),
            tri(P(4.5 + 1 / 1024, 4.5 - 1 / 512), P(4.5 + 3 / 1024, 4.5), P(4.5 + 1 / 1024, 4.5 + 1 / 512))],
     bits=None, expect={"samples_covered": 3}, snap_sensitive=True)

UA = P(F(7, 1024), F(2, 1024))
UB = P(F(9977, 512), F(3455, 256))   # 3 * (6.5, 4.5) - 2 * UA: the edge UA-UB passes the sample (6.5, 4.5)
case("unsnapped_dyadic_edges",
     "subpixel_bits null: a fan of four triangles around (7/1024, 2/1024), a vertex on multiples of "
     "1/1024 but not of 1/256. Its edge to (9977/512, 3455/256) passes exactly through the sample "
     "(6.5, 4.5), two thirds of the way along, so the tie rule decides it; snapped to 8 bits the edge "
     "would miss that sample. The fan's union holds the whole 12x10 canvas: 120 samples, each once.",
     12, 10, [tri(UA, UB, P(30, 0)), tri(UA, P(0, 30), UB),
              tri(UA, P(30, 0), P(0, 0)), tri(UA, P(0, 0), P(0, 30))],
     bits=None, expect={"watertight": True, "samples_covered": 120}, ties=True, snap_sensitive=True)

# ---------------------------------------------------------------------------
# 13. Meshes covering the whole canvas.


def full_canvas_mesh(w, h, nx, ny, jitter):
    """A triangulated rectangle [0,w]x[0,h]; interior vertices jittered by `jitter(i, j)`,
    boundary vertices kept on the border (computed once, shared by every triangle)."""
    verts = {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            x = F(w * i, nx)
            y = F(h * j, ny)
            if 0 < i < nx and 0 < j < ny:
                dx, dy = jitter(i, j)
                x += dx
                y += dy
            elif 0 < i < nx:
                x += jitter(i, j)[0]
            elif 0 < j < ny:
                y += jitter(i, j)[1]
            verts[(i, j)] = (x, y)
    tris = []
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = verts[(i, j)], verts[(i + 1, j)], verts[(i + 1, j + 1)], verts[(i, j + 1)]
            if (i * 7 + j * 3) % 3 == 0:
                tris += [tri(a, b, c), tri(a, c, d)]
            else:
                tris += [tri(a, b, d), tri(b, c, d)]
    return tris


case("mesh_full_canvas_64",
     "A 64x64 canvas triangulated as an 8x8 grid of quads (128 triangles) whose interior vertices are "
     "jittered by fractions such as 1/3 and -4/7 px (snapped to 1/256), and whose border vertices "
     "slide along the border. The mesh's union is exactly the canvas, so all 4096 samples are "
     "covered, each exactly once.",
     64, 64, full_canvas_mesh(64, 64, 8, 8, lambda i, j: (F((i * 5 + j * 3) % 7 - 3, 3), F((i * 2 + j * 5) % 9 - 4, 7))),
     expect={"watertight": True, "samples_covered": 4096})

case("mesh_full_canvas_odd",
     "A 37x23 canvas triangulated by a 5x3 grid of quads (30 triangles) with vertices at fractions of "
     "the odd sides (37/5, 23/3, ...), interior ones jittered by fractions such as 1/10, 3/5 and "
     "-1/6 px, border ones sliding along the border. The union is the canvas: 851 samples, each once.",
     37, 23, full_canvas_mesh(37, 23, 5, 3, lambda i, j: (F((i + j) % 2, 2) + F(1, 10), F(i % 2, 2) - F(1, 6))),
     expect={"watertight": True, "samples_covered": 851})

case("mesh_full_canvas_b0",
     "subpixel_bits 0: a 24x16 canvas as a 4x4 grid of quads whose interior vertices, written at "
     "fractional positions, snap to whole pixels (some with ties to even). The union is the canvas: "
     "384 samples, each once.",
     24, 16, full_canvas_mesh(24, 16, 4, 4, lambda i, j: (F((i * 3 + j) % 5 - 2, 2), F((i + j * 2) % 3 - 1, 2))),
     bits=0, expect={"watertight": True, "samples_covered": 384})

