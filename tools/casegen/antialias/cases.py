"""The antialiasing and polygon cases, as data: edges at many angles, tiny
triangles, fans and meshes, tie probes at the standard samples, swept
edges, parallelogram lines, and polygons (stars, holes, concave,
self-intersecting, many vertices) under every pattern. Their expectations
come from evaluate.py.
"""

import math
from fractions import Fraction as F

from casegen.antialias.evaluate import (AA, AA_DIR, BOUNDS_NOTE, MC_NOTE, POLY_DIR, PROBE_NOTE,
                                        case)
from casegen.antialias.primitives import ParallelogramLine, contours, poly, tri
from casegen.samples import STANDARD


def rect_tris(x0, y0, x1, y1):
    """An axis-aligned rectangle as two triangles sharing its diagonal."""
    return [tri((x0, y0), (x1, y0), (x1, y1)), tri((x0, y0), (x1, y1), (x0, y1))]



def along_edge(n, dx, dy):
    """How the standard n-sample pattern looks to an edge of direction (dx, dy):
    ('piglit-half', note) when its samples' projections onto the edge normal
    collapse to at most n/2 values, or leave a gap at least 3 times the mean
    gap (the samples pair up, and the pattern acts like n/2 samples along this
    edge); ('piglit', '') otherwise. Decided from the pattern alone."""
    proj = sorted(dy * x - dx * y for x, y in STANDARD[n])
    distinct = sorted(set(proj))
    gaps = [b - a for a, b in zip(proj, proj[1:])]
    mean = (proj[-1] - proj[0]) / (n - 1) if n > 1 else 0
    if n > 1 and (len(distinct) <= n // 2 or max(gaps) >= 3 * mean):
        why = ("only %d distinct projections" % len(distinct) if len(distinct) <= n // 2 else
               "a gap of %.1f times the mean gap between projections" % (max(gaps) / mean))
        return "piglit-half", (
            " Along this direction the standard %dx pattern is weak: its samples' projections onto "
            "the edge normal show %s, so the pattern acts like %d samples here, and max_coverage_rms "
            "is piglit's bound for N = %d (the rest as below)." % (n, why, n // 2, n // 2))
    return "piglit", ""


# --- 1. Edges at many angles ------------------------------------------------

# Each case is one large triangle whose long edge crosses a 16x16 canvas at the
# given slope; its other edges lie on the canvas border or outside it. dx, dy:
# the direction of the long edge.
ANGLES = [
    ("slope_1_128", 128, 1, "1/128 (0.45 degrees from horizontal)"),
    ("slope_neg_1_128", 128, -1, "-1/128 (0.45 degrees below horizontal)"),
    ("steep_1_128", 1, 128, "128 (0.45 degrees from vertical)"),
    ("slope_1_64", 64, 1, "1/64 (0.9 degrees)"),
    ("slope_1_16", 16, 1, "1/16 (3.6 degrees)"),
    ("slope_1_3", 3, 1, "1/3 (18.4 degrees)"),
    ("slope_1_2", 2, 1, "1/2 (26.6 degrees)"),
    ("slope_1", 1, 1, "1 (45 degrees, through the pixel corners' diagonals)"),
    ("slope_5_3", 3, 5, "5/3 (59 degrees)"),
    ("steep_neg_1_16", -1, 16, "-16 (3.6 degrees from vertical, leaning left)"),
]

for tag, dx, dy, what in ANGLES:
    for n in (4, 16):
        # The edge passes through (8, 8) + 1/7-ish offset so that it does not
        # run through sample rows; the triangle extends it far beyond the canvas.
        cx, cy = F(8) + F(37, 256), F(8) + F(11, 256)
        t = F(60)
        a = (cx - t * dx / max(abs(dx), abs(dy)), cy - t * dy / max(abs(dx), abs(dy)))
        b = (cx + t * dx / max(abs(dx), abs(dy)), cy + t * dy / max(abs(dx), abs(dy)))
        # The third vertex: far on one side of the edge.
        nx, ny = -dy, dx
        s = F(60) / max(abs(nx), abs(ny))
        third = (cx + s * nx, cy + s * ny)
        rms, weak = along_edge(n, dx, dy)
        case(AA_DIR, "edge_%s_standard%d" % (tag, n),
             "A long triangle edge of slope %s crosses the 16x16 canvas (the triangle's other vertices "
             "lie far outside it, so only this edge is visible), standard %dx pattern. Near-axis edges "
             "are the hard ones: an edge within 0.5 degrees of an axis sweeps whole rows or columns of "
             "samples at once, so a pattern with collinear samples (a grid) jumps by 1/sqrt(N) while the "
             "exact area moves smoothly; a rasterizer that sets up the edge in too few bits also shows "
             "its error here first.%s %s" % (what, n, weak, BOUNDS_NOTE),
             16, 16, [tri(a, b, third)], aa=AA(n), rms=rms)

# --- 2. Tiny triangles, slivers, abutting triangles ------------------------

TINY = [((F(3) + F(1, 8), F(2) + F(1, 4)), "inside one pixel"),
        ((F(3) - F(1, 4), F(2) - F(1, 4)), "straddling the corner of four pixels")]
for i, ((x, y), where) in enumerate(TINY):
    for n, pat in ((4, "standard"), (16, "standard"), (64, "grid")):
        case(AA_DIR, "tiny_%s_%s%d" % (("in_pixel", "on_corner")[i], pat, n),
             "A 0.5 x 0.6 px right triangle (its legs are 0.5 and 0.6 px; 0.6 snaps to 154/256), %s, "
             "%s %dx pattern. It covers a handful of samples or none; its exact area is 77/512 px^2 "
             "(about 0.15) "
             "whatever the pattern, so a sample method's error here is as large as the triangle "
             "itself, and a method that drops primitives smaller than a sample spacing shows it. The "
             "bound on the largest error is min(1, 2E/sqrt(N)) with E = 3 edges in one pixel, and "
             "since one to four pixels hold the whole triangle, the RMS bound is that same bound "
             "(an RMS never exceeds the largest error); piglit's bound is meant for edges that "
             "cross many pixels." % (where, pat, n),
             6, 5, [tri((x, y), (x + F(1, 2), y), (x, y + F(6, 10)))], aa=AA(n, pat), rms="max")

for n in (4, 16):
    case(AA_DIR, "sliver_long_standard%d" % n,
         "A sliver 1/8 px tall at its base and 24 px long, at a slope of about 1/6, standard %dx: "
         "each pixel it crosses holds a thin wedge whose area is far below one sample's share "
         "(1/N), so most pixels resolve to 0 and a few to 1/N. The exact area is 3/2 in all; the "
         "case holds the mask exact sample by sample and the resolve to the bounds. %s"
         % (n, BOUNDS_NOTE),
         26, 8, [tri((1, 2), (25, 6), (1, F(2) + F(1, 8)))], aa=AA(n))

case(AA_DIR, "abutting_square_diagonal_standard16",
     "An 8x8 square made of two triangles that share its diagonal (2,1)-(10,9), standard 16x, on a "
     "12x10 canvas. Each triangle's coverage is partial along the diagonal, but the two together "
     "cover every sample of the square once: every pixel inside the square must resolve to exactly "
     "1 (the sum of two partial coverages), and the total area is exactly 64. A rasterizer that "
     "double-counts or drops samples on the shared diagonal, or blends the two partial coverages "
     "instead of adding them, fails. %s" % BOUNDS_NOTE,
     12, 10, [tri((2, 1), (10, 1), (10, 9)), tri((2, 1), (10, 9), (2, 9))], aa=AA(16),
     checks=[lambda s: all(s["area"].get((x, y), 0) == 1 for x in range(2, 10) for y in range(1, 9))])

# A fan of 8 triangles around a centre that is no sample position.
FAN_C = (F(5) + F(3, 16), F(4) + F(5, 16))
FAN_R = [(F(1), F(1)), (F(5), F(1) - F(1, 2)), (F(9) + F(1, 4), F(1)), (F(9), F(4)),
         (F(9) + F(1, 2), F(7) + F(3, 4)), (F(5) - F(1, 4), F(8)), (F(1), F(7) + F(1, 2)),
         (F(1) - F(1, 2), F(4) + F(1, 8))]
case(AA_DIR, "abutting_fan_8_standard8",
     "Eight triangles fanned around (5+3/16, 4+5/16), standard 8x, on a 10x9 canvas. Every sample "
     "inside the fan's outline is covered by exactly one triangle (each consistent tie rule gives "
     "shared-edge samples to one side), so the partial coverages of the pixels around the centre, "
     "where all eight triangles meet, sum to exactly the union's coverage and the total area is the "
     "area of the octagon. Overlaps or cracks between the triangles show up as resolved values above "
     "1 or below the union. %s" % BOUNDS_NOTE,
     10, 9, [tri(FAN_C, FAN_R[i], FAN_R[(i + 1) % 8]) for i in range(8)], aa=AA(8))

# --- 3. Standard-pattern probes ----------------------------------------------

for n in (1, 2, 4, 8, 16):
    h = F(1, 32)
    prims = []
    for i, (ox, oy) in enumerate(STANDARD[n]):
        cx, cy = F(i) + ox, F(1) + oy
        prims += rect_tris(cx - h, cy - h, cx + h, cy + h)
    case(AA_DIR, "probe_standard%d" % n,
         "Probes of the standard %dx sample positions: pixel i of row 1 holds a 1/16 px square (two "
         "triangles, half-size 1/32) centred on the standard location of sample i, so each square "
         "covers exactly that one sample (its centre lies on the squares' shared diagonal, which "
         "gives it to exactly one triangle) and no other: %s covered prove%s that the "
         "pattern's positions are Vulkan's, in Vulkan's order, since sample slot i must be the one "
         "covered in pixel i.%s %s"
         % (n, "the one sample" if n == 1 else "the %d samples" % n, "s" if n == 1 else "",
            " The 16x pattern puts two samples on the pixel border, (0, 0.5) and (0.0625, 0): "
            "their probes reach into the neighbouring pixels, where they cover no sample." if n == 16
            else "", PROBE_NOTE),
         max(n, 1), 3, prims, aa=AA(n), max_error="probe", rms="probe",
         checks=[lambda s, n=n: s["covered"] == n and all(
             s["counts"][(1 * s["W"] + i) * n + i] == 1 for i in range(n))])

# Tie probes at the 16x border samples: squares with a sample exactly on their
# edge or corner.
SIDE = F(1, 16)
prims = []
for i, (ox, oy) in enumerate(STANDARD[16]):
    sx, sy = F(i) + ox, F(1) + oy
    # Sample at the square's top-left corner: owned (top and left edges).
    prims += rect_tris(sx, sy, sx + SIDE, sy + SIDE)
case(AA_DIR, "probe_standard16_top_left_corners",
     "Each pixel i of row 1 holds a 1/16 px square whose top-left corner is exactly standard 16x "
     "sample i, so every sample lies on a top and a left edge at once (and on the diagonal's end): "
     "under top-left each is covered once, 16 in all, including the border samples at (0, 0.5) and "
     "(0.0625, 0). A rasterizer that tests samples at the wrong positions, or breaks ties at sample "
     "positions differently from pixel centres, fails. %s" % PROBE_NOTE,
     16, 3, prims, aa=AA(16), max_error="probe", rms="probe",
     checks=[lambda s: s["covered"] == 16])
prims = []
for i, (ox, oy) in enumerate(STANDARD[16]):
    sx, sy = F(i) + ox, F(1) + oy
    prims += rect_tris(sx - SIDE, sy - SIDE, sx, sy)
case(AA_DIR, "probe_standard16_bottom_right_corners",
     "The mirror of probe_standard16_top_left_corners: each 1/16 px square ends at standard 16x "
     "sample i (its bottom-right corner), so each sample lies on a bottom and a right edge and "
     "top-left covers none of them: 0 samples, though each pixel has a 1/256 px^2 square. A "
     "rasterizer with closed edges, or with the samples half a lattice step off, covers some. "
     + PROBE_NOTE,
     16, 3, prims, aa=AA(16), max_error="probe", rms="probe",
     checks=[lambda s: s["covered"] == 0])

# Edge swept across a pixel in 32 steps: pixel i holds [i, i + (i+1)/32] x [0, 1].
for n in (4, 16):
    prims = []
    for i in range(32):
        prims += rect_tris(i, 0, F(i) + F(i + 1, 32), 1)
    case(AA_DIR, "sweep_vertical_edge_32_standard%d" % n,
         "A vertical edge swept across one pixel in 32 steps of 1/32 px: pixel i holds the rectangle "
         "[i, i + (i+1)/32] x [0, 1], so its exact coverage is (i+1)/32 and the resolved values "
         "trace the pattern's response curve, a staircase with one step per distinct sample column "
         "(%d of them for standard %dx). Edges at a multiple of 1/16 run through sample columns, "
         "where the right edge does not own them. %s" % (n, n, BOUNDS_NOTE),
         32, 1, prims, aa=AA(n))
    prims = []
    for i in range(32):
        x = 2 * i
        x0 = F(x) + F(i, 32)
        # A sheared edge (dx/dy = 1/4, leaning right) from (x0, 0) to (x0 + 1/4, 1).
        prims.append(poly([(x, 0), (x0, 0), (x0 + F(1, 4), 1), (x, 1)]))
    case(AA_DIR, "sweep_slanted_edge_32_standard%d" % n,
         "A slanted edge (dx/dy = 1/4, 14 degrees from vertical) swept across one pixel in 32 steps: "
         "pixel 2i holds the quadrilateral (2i,0) (2i+i/32,0) (2i+i/32+1/4,1) (2i,1), one polygon, "
         "whose area is i/32 + 1/8; from i = 25 on, its corner spills into the empty pixel 2i+1. "
         "The slant moves samples across the edge one at a time, so the staircase is finer than the "
         "vertical sweep's. %s" % BOUNDS_NOTE,
         64, 1, prims, aa=AA(n))

# --- 4. Parallelogram lines under antialiasing ---------------------------------

LINES = [("w1_slope_1_3", (1, 2), (19, 8), 1, "width 1, slope 1/3"),
         ("w2_5_steep", (3, 1), (6, 15), F(5, 2), "width 2.5, y-major, dx/dy = 3/14"),
         ("w0_25_near_horizontal", (1, F(3) + F(1, 16)), (19, F(3) + F(3, 16)), F(1, 4),
          "width 1/4, slope 1/144 (0.4 degrees)")]
for tag, a, b, w, what in LINES:
    rms, weak = along_edge(16, b[0] - a[0], b[1] - a[1])
    case(AA_DIR, "line_parallelogram_%s_standard16" % tag,
         "A parallelogram line (SPEC 4.4), %s, standard 16x: its ends are along the minor axis and "
         "its width is measured along it, so its area is exactly width x major length and every "
         "corner is rational. A rasterizer that draws it as a rectangle (perpendicular ends, width "
         "measured across the line) gets a different area and different samples.%s %s"
         % (what, weak, BOUNDS_NOTE),
         20, 16, [ParallelogramLine(a, b, w)], aa=AA(16), rms=rms)

# --- 5. Sample-count sweeps ----------------------------------------------------

SWEEP_TRI = [(F(1) + F(3, 8), F(2) + F(1, 16)), (F(15) - F(1, 32), F(5) + F(9, 32)),
             (F(5) + F(7, 16), F(15) - F(1, 8))]
SWEEP_PRIMS = [tri(*SWEEP_TRI), tri((F(9) + F(1, 4), F(10)), (F(14) + F(5, 8), F(9) + F(3, 4)),
                                    (F(12), F(15) + F(1, 2)))]
SWEEP_GEOM = ("two triangles on a 16x16 canvas with edges at slopes from 1/5 to 40 (the first "
              "(1.375,2.0625) (14.96875,5.28125) (5.4375,14.875), the second (9.25,10) "
              "(14.625,9.75) (12,15.5))")
for pattern, counts in (("grid", (1, 4, 16, 64, 256)), ("stratified", (1, 4, 16, 64, 256)),
                        ("random", (1, 4, 16, 64, 256)), ("n-rooks", (1, 4, 16, 64, 256)),
                        ("standard", (1, 2, 4, 8, 16))):
    for n in counts:
        aa = AA(n, pattern)
        if pattern in ("stratified", "random", "n-rooks"):
            aa["seed"] = 1
        # Random samples, and n-rooks (stratified along the axes only: along a slanted
        # edge it samples like random, Shirley 1991), meet the Monte Carlo bound, not
        # piglit's; so does one seeded sample, which is one random offset.
        mc = pattern in ("random", "n-rooks") or (pattern == "stratified" and n == 1)
        case(AA_DIR, "count_%s_%d" % (pattern, n),
             "Sample-count sweep, %s pattern, N = %d: %s. The same geometry at every N of every "
             "pattern, so the report shows how each pattern's error falls as N grows (about N^-3/4 "
             "for stratified and grid along straight edges, N^-1/2 for random; n-rooks is "
             "stratified only along the axes, so along slanted edges it behaves like random). %s"
             % (pattern, n, SWEEP_GEOM, MC_NOTE if mc else BOUNDS_NOTE),
             16, 16, SWEEP_PRIMS, aa=aa, rms="monte-carlo" if mc else "piglit")

# --- 6. Polygons ---------------------------------------------------------------

# Pentagram: the 5 points of a regular pentagon rounded to 1/256, joined in
# star order. The centre pentagon has winding number 2.
def pentagon(cx, cy, r, k=5, phase=-math.pi / 2):
    pts = []
    for i in range(k):
        ang = phase + 2 * math.pi * i / k
        pts.append((F(round((cx + r * math.cos(ang)) * 256), 256),
                    F(round((cy + r * math.sin(ang)) * 256), 256)))
    return pts


PENTA = pentagon(8, F(17, 2), 7.5)
STAR = [PENTA[(2 * i) % 5] for i in range(5)]


for fill in ("even-odd", "nonzero"):
    centre = "stays empty (winding number 2 is even)" if fill == "even-odd" else \
        "is filled (winding number 2 is non-zero)"
    pr = poly(STAR, fill)
    case(POLY_DIR, "pentagram_%s" % fill.replace("-", "_"),
         "A pentagram (the regular pentagon of radius 7.5 around (8, 8.5), its corners rounded to "
         "1/256, joined in star order) under %s: the five points have winding number 1 and the "
         "centre pentagon 2, so the centre %s. Pixel-centre samples only. A rasterizer that treats "
         "every polygon as nonzero (or as even-odd) gets the centre wrong." % (fill, centre),
         16, 16, [pr], fill_rule="top-left",
         checks=[lambda s, f=fill: (s["counts"][8 * 16 + 8] > 0) == (f == "nonzero")])
    case(POLY_DIR, "pentagram_%s_aa_standard16" % fill.replace("-", "_"),
         "The pentagram of pentagram_%s (winding 2 in the centre pentagon) under %s, standard 16x: "
         "the exact area is the five points%s, and along the inner pentagon's sides, where the "
         "edges cross, pixels hold pieces of regions of different winding numbers. %s"
         % (fill.replace("-", "_"), fill, " only" if fill == "even-odd" else " plus the pentagon",
            BOUNDS_NOTE),
         16, 16, [pr], aa=AA(16))

# Square with a hole: two contours.
OUT = [(1, 1), (13, 1), (13, 13), (1, 13)]
HOLE_REV = [(F(4) + F(1, 4), F(4) + F(1, 8)), (F(4) + F(1, 4), F(10)), (F(9) + F(3, 4), F(10)),
            (F(9) + F(3, 4), F(4) + F(1, 8))]
HOLE_SAME = list(reversed(HOLE_REV))
for tag, hole, fill, note in (
        ("hole_reversed_nonzero", HOLE_REV, "nonzero",
         "the inner contour runs the other way, so the hole has winding number 0 and stays empty"),
        ("hole_same_nonzero", HOLE_SAME, "nonzero",
         "both contours run the same way, so the 'hole' has winding number 2 and nonzero fills it"),
        ("hole_same_even_odd", HOLE_SAME, "even-odd",
         "both contours run the same way (winding 2 inside), and even-odd leaves the hole empty")):
    pr = contours([OUT, hole], fill)
    case(POLY_DIR, tag,
         "A 12x12 square with a 5.5 x 5.875 inner contour, %s, fill %s: %s. Pixel-centre samples. "
         "A rasterizer that ignores the second contour, or the direction of contours, fails."
         % ("two contours", fill, note),
         14, 14, [pr],
         checks=[lambda s, h=(fill == "nonzero" and hole is HOLE_SAME):
                 (s["counts"][7 * 14 + 7] > 0) == h])
    case(POLY_DIR, tag + "_aa_standard8",
         "The polygon of %s (%s) under standard 8x: the hole's sides sit at quarter and eighth "
         "pixel offsets, so its border pixels are partial, and the exact area is the outer square "
         "minus the hole%s. %s" % (tag, note, " (here the hole is filled: the area is the whole square)"
                                   if (fill == "nonzero" and hole is HOLE_SAME) else "", BOUNDS_NOTE),
         14, 14, [pr], aa=AA(8))

# Concave polygons: an arrow and a comb.
ARROW = [(1, 6), (8, 1), (8, 4), (15, 4), (15, 8), (8, 8), (8, 11)]
ARROW = [(F(x) + F(1, 16), F(y) + F(3, 32)) for x, y in ARROW]
COMB = [(1, 1), (14, 1), (14, 13), (12, 13), (12, 4), (10, 4), (10, 13), (8, 13), (8, 4), (6, 4),
        (6, 13), (4, 13), (4, 4), (2, 4), (2, 13), (1, 13)]
COMB = [(F(x) + F(1, 8) * (i % 3), F(y) + F(1, 5)) for i, (x, y) in enumerate(COMB)]
for tag, pts, what in (("arrow", ARROW, "an arrow (one reflex vertex on each side of the shaft)"),
                       ("comb", COMB, "a comb with four teeth (eight reflex vertices); its vertices "
                                      "sit 0, 1/8 and 1/4 px off the lattice and 1/5 px down "
                                      "(snapped to 51/256)")):
    pr = poly(pts)
    case(POLY_DIR, "concave_%s" % tag,
         "A concave polygon, %s, nonzero, pixel-centre samples. A scanline crosses it four or more "
         "times; a rasterizer that fills between the first and last crossing (a convex-only filler) "
         "fills the notches." % what,
         16, 15, [pr])
    case(POLY_DIR, "concave_%s_aa_standard16" % tag,
         "The polygon of concave_%s under standard 16x: the exact area of a concave polygon is "
         "the shoelace area, and the checker also finds it by slabs. %s" % (tag, BOUNDS_NOTE),
         16, 15, [pr], aa=AA(16))

# Self-intersecting: bow-tie, and a contour that winds twice around a region.
BOW = [(1, 2), (13, 11), (13, 2), (1, 11)]
BOW = [(F(x) + F(1, 8), F(y) + F(1, 4)) for x, y in BOW]
for fill in ("nonzero", "even-odd"):
    case(POLY_DIR, "bowtie_%s" % fill.replace("-", "_"),
         "A bow-tie: the contour (1.125,2.25) (13.125,11.25) (13.125,2.25) (1.125,11.25) crosses "
         "itself at (7.125, 6.75); its two lobes have winding numbers +1 and -1, so %s fills both. "
         "A rasterizer that takes the sign of the winding number as the fill (fills positive "
         "winding only), or that fills between the first and last crossing of each row, fails."
         % fill,
         15, 13, [poly(BOW, fill)])
case(POLY_DIR, "bowtie_aa_standard16",
     "The bow-tie of bowtie_nonzero under standard 16x: two triangular lobes of opposite winding "
     "meeting at (7.125, 6.75), inside pixel (7, 6), which holds four edges at once. %s"
     % BOUNDS_NOTE,
     15, 13, [poly(BOW)], aa=AA(16))

# A figure eight that winds twice: an outer loop, then an inner loop in the
# same direction, joined by a shared bridge edge.
EIGHT = [(2, 2), (14, 2), (14, 14), (2, 14), (2, 5), (11, 5), (11, 11), (5, 11), (5, 2)]
EIGHT = [(F(x) + F(1, 32), F(y) + F(1, 64)) for x, y in EIGHT]
for fill in ("nonzero", "even-odd"):
    case(POLY_DIR, "double_loop_%s" % fill.replace("-", "_"),
         "One contour that runs around the square (2,2)-(14,14) and then, crossing its own path, "
         "around the inner square (5,5)-(11,11) in the same direction: the inner square has "
         "winding number 2 (%s), the bridge pieces 1 or 2. A rasterizer that counts crossings "
         "without their direction gets even-odd right and nonzero wrong." %
         ("filled under nonzero" if fill == "nonzero" else "empty under even-odd"),
         16, 16, [poly(EIGHT, fill)],
         checks=[lambda s, f=fill: (s["counts"][8 * 16 + 8] > 0) == (f == "nonzero")])
case(POLY_DIR, "double_loop_even_odd_aa_grid16",
     "The contour of double_loop_even_odd (inner square winding 2, empty) under a 4x4 grid "
     "pattern: every edge sits 1/32 or 1/64 px off the pixel lattice, so the grid's rows and "
     "columns of samples lie at 1/8, 3/8, ... and the border pixels resolve to a whole number of "
     "sample rows. %s" % BOUNDS_NOTE,
     16, 16, [poly(EIGHT, "even-odd")], aa=AA(16, "grid"))

# Polygon and its triangulation: the same samples.
QUAD = [(F(2) + F(1, 2), F(1) + F(1, 2)), (F(12) + F(1, 2), F(3) + F(1, 2)),
        (F(10) + F(1, 2), F(12) + F(1, 2)), (F(1) + F(1, 2), F(9) + F(1, 2))]
case(POLY_DIR, "quad_vertices_on_centres",
     "A convex quadrilateral with every vertex on a pixel centre and edges that run through "
     "several centres (slopes 1/5, -9/2, 3/9, 8/1): as one polygon it covers the same samples as "
     "its triangulation (SPEC 14.1), which quad_vertices_on_centres_triangulated draws; both give "
     "the same samples_covered.",
     14, 14, [poly(QUAD)])
case(POLY_DIR, "quad_vertices_on_centres_triangulated",
     "quad_vertices_on_centres drawn as two triangles sharing the diagonal (2.5,1.5)-(10.5,12.5): "
     "the same samples as the polygon, each covered once.",
     14, 14, [tri(QUAD[0], QUAD[1], QUAD[2]), tri(QUAD[0], QUAD[2], QUAD[3])])

# Polygon under the other tie rules, with vertices and crossings on centres.
STAR_C = [(F(1) + F(1, 2), F(5) + F(1, 2)), (F(13) + F(1, 2), F(5) + F(1, 2)),
          (F(3) + F(1, 2), F(13) + F(1, 2)), (F(7) + F(1, 2), F(0) + F(1, 2)),
          (F(11) + F(1, 2), F(13) + F(1, 2))]
for rule in ("top-left", "bottom-right", "top-right", "bottom-left"):
    case(POLY_DIR, "star_on_centres_%s" % rule.replace("-", "_"),
         "A five-pointed star, even-odd, whose vertices all lie on pixel centres and whose top "
         "edge runs along sample row 5, fill rule %s: the horizontal edge and the samples on "
         "the slanted edges go to the side the nudge of SPEC 14.1 points into, so the four rules "
         "cover different samples, and a rasterizer that nudges the wrong way, or decides "
         "samples at crossings without the nudge, fails." % rule,
         15, 15, [poly(STAR_C, "even-odd")], fill_rule=rule)

# Two polygons sharing an edge: watertight under antialiasing.
SHARED = [(F(1) + F(1, 4), F(1)), (F(9) + F(1, 8), F(2) + F(1, 2)), (F(8) - F(1, 8), F(12))]
case(POLY_DIR, "shared_edge_polygons_aa_standard4",
     "Two concave polygons share the broken edge (1.25,1) (9.125,2.5) (7.875,12): one lies left of "
     "it, the other right, and their union is the 14x13 canvas's rectangle (1,1)-(13,12) minus "
     "nothing. Every sample of the rectangle is covered once, every pixel wholly inside resolves to "
     "1, and the areas of the two sum to the rectangle's. %s" % BOUNDS_NOTE,
     14, 13, [poly([(1, 1), SHARED[0], SHARED[1], SHARED[2], (1, 12)]),
              poly([SHARED[0], (13, 1), (13, 12), SHARED[2], SHARED[1]])], aa=AA(4))

# Many vertices: a 64-gon circle.
CIRCLE = pentagon(F(16), F(16), 13.3, k=64, phase=0.1)
case(POLY_DIR, "circle_64_aa_grid64",
     "A 64-vertex circle of radius 13.3 around (16, 16), its vertices rounded to 1/256, under an "
     "8x8 grid on a 32x32 canvas: edges at 64 angles, each 1.3 px long, so most border pixels hold "
     "two edges and a vertex. %s" % BOUNDS_NOTE,
     32, 32, [poly(CIRCLE)], aa=AA(64, "grid"))
case(POLY_DIR, "circle_64_aa_stratified256",
     "The circle of circle_64_aa_grid64 under stratified 256 (seed 3). %s" % BOUNDS_NOTE,
     32, 32, [poly(CIRCLE)], aa=AA(256, "stratified", seed=3))


