"""The hard polygon and antialiasing cases (SPEC.md section 14): abutting
fans and grids, self-overlapping polygons, antialiased slivers and ties at
the standard 16x samples. Their expectations come from the exact checker of
the antialiasing cases (casegen/antialias/), imported rather than copied;
the claims below (no sample covered twice, full pixels whose areas sum to
exactly 1, the exact total area from a formula of its own, the same samples
as a simpler scene) are asserted here.
"""

import math
from fractions import Fraction as F

from casegen.antialias.check import coverage
from casegen.antialias.evaluate import BOUNDS_NOTE, evaluate
from casegen.antialias.primitives import contours, poly, tri
from casegen.hard.build import COORD_LIMIT, OUT_DIR
from casegen.samples import STANDARD


AA_CASES = []
A16 = {"samples": 16, "pattern": "standard"}


def aa_case(name, description, width, height, prims, aa=A16, bits=8, fill_rule="top-left",
            area=None, full_pixels=None, single=False, same_as=None, checks=()):
    """Registers a polygon or antialiasing hard case (prims are
    casegen.antialias primitives). Claims, asserted by aa_evaluate(): `area` the exact
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
        33, 33, [tri(C64, RIM64[k], RIM64[(k + 1) % 64]) for k in range(64)],
        area=shoelace(RIM64), single=True)
C128 = (F(16), F(16))
RIM128 = ring(16, 16, 15.2, 128, 0.3)
aa_case("aa_abut_fan_128_corner_standard16",
        "128 triangles fanned around the pixel corner (16, 16), where four pixels meet: each of "
        "those four full pixels is cut into 32 slivers of area under 1/20 px^2 each. The rim is "
        "a 128-gon of radius 15.2 rounded to 1/256. " + FAN_NOTE.format(p=128),
        32, 32, [tri(C128, RIM128[k], RIM128[(k + 1) % 128]) for k in range(128)],
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
            SQ_TRIS += [tri(a, b, c), tri(a, c, d)]
        else:
            SQ_TRIS += [tri(a, b, d), tri(b, c, d)]
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
        24, 24, [contours([HOLE_FAR, HOLE_TRI], "even-odd")])

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
            24, 24, [poly(HEPT + HEPT, fill)],
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
            26, 26, [contours([SQ_A, SQ_B, TRI_R], fill)], single=True,
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
            24, 18, [contours([SLIT, [RIGHT[0], RIGHT[3], RIGHT[2], RIGHT[1]]], fill)],
            same_as=[contours([SLIT_CLEAN, [RIGHT[0], RIGHT[3], RIGHT[2], RIGHT[1]]], fill)],
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
        22, 21, [poly(REP)], same_as=[poly(PENT)], area=shoelace(PENT), single=True)
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
            21, 21, [contours([REAL, FLAT, POINT], fill)], same_as=[contours([REAL], fill)],
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
            24, 24, [poly(FAR_ZIG, fill)], aa=None)
    aa_case("poly_far_zigzag_b8_%s_standard16" % tag,
            "The contour of poly_far_zigzag_b8_%s under standard 16x: the exact areas of pixels "
            "cut by 65000 px edges and their crossings (rationals with 40-bit denominators) must "
            "sum to expect.area." % tag,
            24, 24, [poly(FAR_ZIG, fill)])

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
        20, 20, [poly(NT)], aa=None)

# (d) Antialiased slivers and near-collinear triangles.

DIR = (F(1000003, 256), F(7, 256))      # a primitive direction on the 1/256 lattice
SL_C = (F(11) + F(1, 2), F(9) + F(5, 16))


def on_line(k):
    return (SL_C[0] + k * DIR[0], SL_C[1] + k * DIR[1])


SL_A, SL_B = on_line(-8), on_line(8)
SLIVERS = [tri(SL_A, SL_B, (SL_C[0] + F(j, 1), SL_C[1] + F(j, 1) * F(7, 1000003) + F(d, 256)))
           for j, d in ((-9, 1), (-3, -1), (2, 2), (7, -3))]
SLIVERS = [tri(SL_A, SL_B, (p[0], F(round(p[1] * 256), 256))) for p in
           [(SL_C[0] + j, SL_C[1] + j * F(7, 1000003) + F(d, 256))
            for j, d in ((-9, 1), (-3, -1), (2, 2), (7, -3))]]
SLIVERS.append(tri(SL_A, SL_B, SL_C))
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
    THIN += [tri(a, b, b2), tri(a, b2, a2)]
aa_case("aa_sliver_thin_pairs_standard16",
        "Four parallelograms 1/256 px thick across a 24x20 canvas, each split along its long "
        "diagonal into two slivers of zero width at one end: most pixels they cross hold "
        "under 1/100 px^2 of them and no sample, some hold one sample on the shared diagonal, "
        "which one of the pair must own. Coverage errors are at most 1/16 per sample, the "
        "exact areas sum to 4 x the parallelograms' 1/256 x length.",
        24, 20, THIN, single=False)

SNAPC = [tri((F(1) + F(1, 2), F(2) + F(1, 2)), (F(20) + F(1, 2), F(11) + F(1, 2)),
                 (F(11) - F(1, 1024), F(7) + F(3, 2048))),
         tri((F(2), F(17)), (F(22), F(3)), (F(12) + F(1, 1024), F(10) - F(1, 2048))),
         tri((F(3) + F(1, 4), F(18)), (F(19) + F(1, 4), F(18) + F(1, 512)),
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
        UNIT += [tri((x, y), (x + 1, y), (x + 1, y + 1)), tri((x, y), (x + 1, y + 1), (x, y + 1))]
for rule in ("top-left", "top-right", "bottom-left", "bottom-right"):
    aa_case("aa_tie_unit_grid_%s_standard16" % rule.replace("-", "_"),
            "288 triangles: every pixel of the square [2, 14]^2 split along its main diagonal. "
            "The standard 16x pattern puts sample 12 at (0, 1/2) on every vertical edge, sample 15 "
            "at (1/16, 0) on every horizontal edge, and sample 0 at (9/16, 9/16) on every "
            "diagonal: 3 of each pixel's 16 samples lie on shared edges, which the %s rule hands "
            "to exactly one triangle. Inside, every pixel resolves to exactly 1 (full); on the "
            "square's border the rule decides which border samples belong to the square." % rule,
            16, 16, UNIT, fill_rule=rule, area=F(144), full_pixels=144, single=True)

S16 = STANDARD[16]


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
        21, 21, [tri(VC, VRIM[k], VRIM[(k + 1) % 8]) for k in range(8)],
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
            16, 16, [contours([STAIR, HOLE], fill)], area=F(96 - 16), full_pixels=80, single=True)


def aa_evaluate(c):
    """Expectations of a polygon/antialiasing hard case from gen_aa_cases'
    checker, with the claims of aa_case asserted."""
    try:
        expect, stats = evaluate(c)
    except AssertionError as e:
        if "RMS" not in str(e):
            raise
        c["rms"] = "max"
        c["description"] += (" Bounds: the exact 16-sample method breaks piglit's RMS bound here "
                             "(its edges line up with the pattern), so max_coverage_rms is the "
                             "max_coverage_error bound.")
        expect, stats = evaluate(c)
    name = c["name"]
    if c["aa"] is not None and "Bounds:" not in c["description"] and "max_coverage_rms" in expect:
        c["description"] += " " + BOUNDS_NOTE
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
        assert coverage(other) == stats["counts"], name
    for check in c["claim_checks"]:
        assert check(stats), name
    return expect, stats


