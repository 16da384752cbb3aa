"""The motion-blur cases, as data: translation, rotation, scaling, long
motion, grazing edges and double roots, pivots and riding samples, winding
flips under each cull, collapse, meshes, antialiased motion, line major-axis
switches; each with the checks of its author's intent.
"""

import math
from fractions import Fraction as F

from casegen.exactjson import exact
from casegen.motion.evaluate import AA, MB, case
from casegen.motion.primitives import Prim, TimeCoverage, V, line, mv, tri
from casegen.motion.quadratic import ZERO, poly_double_root, roots_in

# ---------------------------------------------------------------------------
# The cases.

BOUNDS_NOTE = ("Bounds: max_time_rms is max(1.25 R, 1.5 sigma) and max_time_error "
               "max(1.25 X, 2/sqrt(M*N)), where R and X are the RMS over moving pixels and the "
               "largest error of the sample method with this case's own instants (SPEC 15.3), and "
               "sigma the RMS that independent uniform instants would give, computed from the "
               "exact coverages (1.5 sigma is never above SPEC's default 0.75/sqrt(M*N)); a method "
               "that draws the scene at shutter open fails them (tools/gen_motion_cases.py "
               "explains and checks both).")


def dec6(x):
    return F(round(x * 10 ** 6), 10 ** 6)


def rotated(cx, cy, r, deg):
    a = math.radians(deg)
    return (dec6(cx + r * math.cos(a)), dec6(cy + r * math.sin(a)))


def moved(pts, dx, dy):
    return [(exact(x) + exact(dx), exact(y) + exact(dy)) for x, y in pts]


def pixel_of(stats, x, y):
    return stats["exact"][(x, y)]


def rat(stats, x, y):
    return pixel_of(stats, x, y).rational()


def events_at(stats, x, y, prim=0, sample=0):
    return stats["tcs"][(x, y, sample, prim)].events


def area_poly(prim):
    """The twice-signed area of a triangle as a polynomial in tau (the last
    of its polys, whatever the sample)."""
    assert prim.kind == "triangle"
    return prim.polys((F(0), F(0)))[-1]


# --- 1. Rigid motion: translation, rotation, scaling ---------------------------

TRANS_FROM = [(F(7, 4), F(9, 4)), (F(19, 2), F(9, 8)), (F(27, 8), F(79, 8))]
case("translate_triangle_stratified16",
     "A triangle translating by (5, 3.5) over the shutter, stratified 16 time samples: with a pure "
     "translation every edge function is linear in tau (the tau^2 coefficient, the cross product "
     "of the endpoint velocities, is zero), so every instant where a sample enters or leaves is "
     "rational and the exact time coverage of every pixel is rational. The leading edge sweeps "
     "samples in and the trailing edge out; pixels along the path are covered for part of the "
     "shutter, those inside the overlap of the first and last positions for all of it. "
     + BOUNDS_NOTE,
     16, 16, [tri(*[mv(p, q) for p, q in zip(TRANS_FROM, moved(TRANS_FROM, 5, F(7, 2)))])],
     MB(16), pins=[(4, 4), (10, 8), (12, 5)],
     checks=[lambda s: all(v.rational() is not None for v in s["exact"].values())])

ROT_FROM = [rotated(8, 8, 6.5, a) for a in (-80, 40, 160)]
ROT_TO = [rotated(8, 8, 6.5, a + 90) for a in (-80, 40, 160)]
ROT_DESC = ("a triangle inscribed in a circle of radius 6.5 around (8, 8) turning by 90 degrees: "
            "its vertices are written with 6 decimals (not multiples of 1/256) and snap at each end "
            "(SPEC 15.1), then move along straight chords, so the triangle shrinks to about 0.71 of "
            "its size mid-shutter as it turns. Each edge function at a sample is a true quadratic "
            "in tau, so most entry and exit instants are irrational")
for pattern, n, seed in (("stratified", 16, 0), ("random", 4, 5), ("stratified", 64, 0),
                         ("jittered-xy-t", 16, 0)):
    extra = {
        ("stratified", 16): "The exact time coverage has to integrate between irrational roots; "
                            "a reference that samples instead of solving is off by up to 1/N.",
        ("random", 4): "Only 4 independent random instants per pixel: the noisiest estimate in "
                       "the suite, and still far closer than drawing the triangle at shutter open. "
                       "With 4 instants max_time_error is 1 (one pixel may be wrong by a whole), so "
                       "max_time_rms is what tells a method that ignores motion from this one.",
        ("stratified", 64): "64 stratified instants per pixel: the bounds are tight, so an "
                            "estimator whose strata are wrong (or that reuses one pixel's instants "
                            "everywhere) shows up in the RMS.",
        ("jittered-xy-t", 16): "Without antialiasing the three stratified time patterns draw the "
                               "same instants (SPEC 15.3); this case has the same geometry, seed "
                               "and instants as rotate_triangle_stratified16 and must give the "
                               "same frame.",
    }[(pattern, n)]
    case("rotate_triangle_%s%d" % (pattern.replace("-", "_"), n),
         "Rotation, %s %d time samples%s: %s. %s %s"
         % (pattern, n, " (seed %d)" % seed if seed else "", ROT_DESC, extra, BOUNDS_NOTE),
         16, 16, [tri(*[mv(p, q) for p, q in zip(ROT_FROM, ROT_TO)])], MB(n, pattern, seed),
         pins=[(8, 8), (5, 4), (4, 7), (10, 8), (8, 11)], ignore_max_ok=(n == 4),
         checks=[lambda s: any(v.rational() is None for v in s["exact"].values())])

SCALE_C = (F(33, 4), F(31, 4))
SCALE_R = [(-6, -5), (F(13, 2), -2), (-1, F(27, 4))]
case("scale_triangle_random16",
     "A triangle scaling about (8.25, 7.75) from 1/4 to 5/4 of its size, random 16 time samples "
     "(seed 11): the vertices' velocities are not parallel, so each edge function has a tau^2 "
     "term, yet every root is rational (the edge function is s*(cross(e, q - c) - s*cross(e, r)) "
     "in the scale s, linear in tau): a case whose quadratics all factor. Samples near the centre "
     "are covered for the whole shutter, those near the final edges only at the end. "
     + BOUNDS_NOTE,
     16, 16, [tri(*[mv((SCALE_C[0] + F(r[0]) / 4, SCALE_C[1] + F(r[1]) / 4),
                       (SCALE_C[0] + F(r[0]) * 5 / 4, SCALE_C[1] + F(r[1]) * 5 / 4))
                    for r in SCALE_R])],
     MB(16, "random", 11), pins=[(8, 7), (4, 3), (13, 6), (7, 13)],
     checks=[lambda s: all(v.rational() is not None for v in s["exact"].values()),
             lambda s: any(p[2] != 0 for tc in s["tcs"].values() for p in tc.polys)])

LONG = [(F(2), F(3, 2)), (F(17, 2), F(19, 4)), (F(15, 4), F(21, 2))]
case("long_motion_112px_stratified16",
     "Fast motion: a triangle about 6 px wide moves 112 px to the right (and turns slightly: one "
     "vertex moves 2 px less) across a 128x12 canvas, stratified 16 time samples. Each pixel on "
     "its path is covered for well under a tenth of the shutter, so most of its 16 instants miss "
     "and the estimate is sparse (the regime motion blur is hard in); the exact coverage is small "
     "but never zero along the path. A method that draws the triangle at shutter open puts a "
     "solid triangle at the left end and nothing elsewhere. " + BOUNDS_NOTE,
     128, 12, [tri(mv(LONG[0], (LONG[0][0] + 112, LONG[0][1] + 1)),
                   mv(LONG[1], (LONG[1][0] + 112, LONG[1][1] + 1)),
                   mv(LONG[2], (LONG[2][0] + 110, LONG[2][1] + F(3, 2))))],
     MB(16), pins=[(5, 5), (40, 5), (64, 6), (100, 7), (114, 5)])

# --- 2. Exact events: a vertex through a sample, a double root, riding an edge --

case("vertex_crosses_sample_at_3_8",
     "A vertex passes exactly through the sample centre (4.5, 5.5) at tau = 3/8: it moves "
     "from (1.5, 2.5) to (9.5, 10.5) while the other two vertices translate by (1, 0.5), so both "
     "edges that meet at it vanish at that sample at the same rational instant (two quadratics "
     "sharing a root), and the sample, inside until then, is outside after (the triangle turns "
     "over at tau = 1577/1948, about 0.81, and is drawn both ways under cull none). Pixel (4, 5) has "
     "exact time coverage 3/8; a reference that counts the shared root twice, or that loses the "
     "sample at the vertex, gets another value. " + BOUNDS_NOTE,
     12, 12, [tri(mv((F(3, 2), F(5, 2)), (F(19, 2), F(21, 2))),
                  mv((F(41, 4), F(17, 8)), (F(45, 4), F(21, 8))),
                  mv((F(49, 8), F(43, 4)), (F(57, 8), F(45, 4))))],
     MB(16), pins=[(4, 5), (5, 5), (3, 3), (8, 4)],
     checks=[lambda s: rat(s, 4, 5) == F(3, 8),
             lambda s: [r.rational() for r in roots_in(area_poly(s["prims"][0]), F(0), F(1))]
             == [F(1577, 1948)],
             lambda s: any(e.rational() == F(3, 8) for e in events_at(s, 4, 5)),
             lambda s: sum(1 for p in s["tcs"][(4, 5, 0, 0)].polys
                           if p[2] != 0 and any(r.rational() == F(3, 8)
                                                for r in roots_in(p, F(0), F(1)))) >= 2])

# The grazing edge a->b: at tau = 1/4 it is the horizontal segment (4.5, 6.5)-(12.5, 6.5)
# through the sample q = (8.5, 6.5); a moves by (4, 4) and b by (0, -4), so its edge function at
# q is cross(a - q, b - q) = -16 (tau - 1/4)^2: a double root (it touches q and stays on one side).
GRAZE = [mv((F(7, 2), F(11, 2)), (F(15, 2), F(19, 2))),
         mv((F(25, 2), F(15, 2)), (F(25, 2), F(7, 2))),
         mv((F(21, 2), F(1, 2)), (F(13, 2), F(33, 4)))]


def graze_check(s):
    tc = s["tcs"][(8, 6, 0, 0)]
    doubles = [p for p in tc.polys if poly_double_root(p) == F(1, 4)]
    assert doubles and doubles[0] == (F(-1), F(8), F(-16)), doubles
    eps = F(1, 1 << 20)
    return tc.member(F(1, 4) - eps) and tc.member(F(1, 4) + eps) and not tc.member(F(1) - eps)


case("edge_grazes_sample_double_root",
     "An edge that touches a sample without crossing it: the edge from a (3.5, 5.5)->(7.5, 9.5) "
     "to b (12.5, 7.5)->(12.5, 3.5) turns and slides so that its edge function at the sample "
     "(8.5, 6.5) is -(4 tau - 1)^2, a double root at tau = 1/4: the sample lies on the edge at "
     "that one instant and inside the triangle just before and just after. It leaves later, "
     "through the edge to the third vertex (10.5, 0.5)->(6.5, 8.25), at an irrational instant. "
     "A reference that treats every root as a sign change, or that isolates roots by bisecting "
     "on a change of sign (a double root has none), gets pixel (8, 6) wrong by 1/4 or more. "
     + BOUNDS_NOTE,
     16, 12, [tri(*GRAZE)], MB(16), pins=[(8, 6), (6, 5), (11, 6)], checks=[graze_check])

for rule, covered in (("top-left", "covered while the edge passes over them (top edges own their "
                                   "samples)"),
                      ("bottom-right", "never covered (a top edge does not own its samples under "
                                       "bottom-right)")):
    tag = rule.replace("-", "_")
    case("ride_top_edge_%s" % tag,
         "A triangle with a horizontal top edge on sample row 2 (y = 2.5) slides 6 px to the right "
         "and 1.5 px down at its lowest vertex only, fill rule %s: the samples of row 2 lie on the "
         "top edge for the whole time it is over them, so their edge function is identically "
         "zero and the fill rule decides them at every instant: they are %s. Row 3 is covered "
         "normally. A reference that finds roots only, or treats an identically zero edge function "
         "as outside (or inside) whatever the rule, fails row 2. %s" % (rule, covered, BOUNDS_NOTE),
         16, 8, [tri(mv((F(5, 4), F(5, 2)), (F(29, 4), F(5, 2))),
                     mv((F(31, 4), F(5, 2)), (F(55, 4), F(5, 2))),
                     mv((F(7, 2), F(29, 4)), (F(19, 2), F(35, 4))))],
         MB(16), fill_rule=rule, pins=[(4, 2), (8, 2), (11, 2), (8, 3)],
         checks=[lambda s, r=rule: (rat(s, 8, 2) > 0) == (r == "top-left"),
                 lambda s: float(pixel_of(s, 8, 3)) > 0])

# An edge turning about the sample (6.5, 5.5): its ends are opposite each other through the
# sample at every instant, so the sample rides on it (edge function identically zero), and the
# edge is horizontal at tau = 3/8, where its ownership changes.
case("edge_pivots_on_sample",
     "An edge turns about the sample centre (6.5, 5.5): its ends (2.5, 4)->(2.5, 8) and "
     "(10.5, 7)->(10.5, 3) stay opposite each other through the sample, so the sample lies on the "
     "edge at every instant (an identically zero edge function) and the fill rule decides it "
     "throughout. The edge is horizontal at tau = 3/8: before, it is a right edge (not owned under "
     "top-left), after, a left edge (owned), so pixel (6, 5) has exact time coverage 5/8. The "
     "instant where ownership changes is a root of the edge's dy, not of any edge function. "
     + BOUNDS_NOTE,
     12, 12, [tri(mv((F(5, 2), 4), (F(5, 2), 8)), mv((F(21, 2), 7), (F(21, 2), 3)),
                  (F(27, 4), F(21, 2)))],
     MB(16), pins=[(6, 5), (4, 6), (8, 4)],
     checks=[lambda s: rat(s, 6, 5) == F(5, 8),
             lambda s: any(p == (ZERO, ZERO, ZERO) for p in s["tcs"][(6, 5, 0, 0)].polys)])

# --- 3. Winding flips and collapse ---------------------------------------------------

FLIP = [(F(9, 4), F(25, 8)), mv((F(27, 2), F(5, 2)), (F(57, 4), F(23, 4))),
        mv((F(51, 8), F(55, 4)), (F(73, 8), F(-5, 2)))]
FLIP_TRI = tri(*FLIP)
FLIP_RESULTS = {}


def flip_check(cull):
    def check(s):
        FLIP_RESULTS[cull] = s["exact"]
        if len(FLIP_RESULTS) == 3:
            for k, v in FLIP_RESULTS["none"].items():
                d = v - FLIP_RESULTS["cw"][k] - FLIP_RESULTS["ccw"][k]
                assert d.rational() == 0, ("cull none != cw + ccw", k)
        return True
    return check


for cull, what in (("none", "both windings are drawn, so the sample coverage is that of the "
                            "triangle before and of its mirror image after"),
                   ("cw", "the triangle is drawn only while it is counter-clockwise: before the "
                          "flip it is clockwise and culled, so only the second part counts"),
                   ("ccw", "the triangle is drawn only while it is clockwise, before the flip")):
    case("winding_flip_cull_%s" % cull,
         "A winding flip mid-shutter, cull %s: vertex c moves from (6.375, 13.75) to "
         "(9.125, -2.5) straight through the opposite edge while b also moves, so the twice-signed "
         "area is a quadratic in tau with an irrational root near tau = 0.612, where the triangle "
         "is flat and changes winding. Culling applies at each instant to the winding at that "
         "instant (SPEC 15.2): %s. The three cull variants of this case sum to the unculled one "
         "pixel by pixel (checked by the generator). A rasterizer that culls by the winding at "
         "shutter open (or mid-shutter) culls the whole shutter or none of it.%s %s"
         % (cull, what, " Drawing the scene at shutter open draws nothing here (the triangle "
            "is culled then): that errs by at most 0.39 in a pixel, within max_time_error, and "
            "fails max_time_rms." if cull == "cw" else "", BOUNDS_NOTE),
         16, 16, [FLIP_TRI], MB(16), cull=cull, pins=[(5, 3), (9, 4), (11, 4), (7, 1), (6, 10)],
         ignore_max_ok=(cull == "cw"),
         checks=[flip_check(cull),
                 lambda s: [float(r) for r in roots_in(area_poly(FLIP_TRI), F(0), F(1))
                            if r.rational() is None] == [0.6121883684734365],
                 lambda s: any(0 < float(e) < 1 and e.rational() is None
                               for e in events_at(s, 5, 3))])

COL_P = (F(33, 4), F(63, 8))
COL_R = [(F(-11, 2), F(-13, 4)), (6, F(-9, 2)), (F(3, 4), F(25, 4))]
COLLAPSE_TRI = tri(*[mv((COL_P[0] + r[0], COL_P[1] + r[1]), (COL_P[0] - r[0], COL_P[1] - r[1]))
                     for r in COL_R])
case("collapse_to_point_at_half_cull_ccw",
     "A triangle collapsing to zero area at tau = 1/2: every vertex moves from p + r to p - r "
     "with p = (8.25, 7.875), so the triangle shrinks to the point p at tau = 1/2 and grows "
     "back turned by 180 degrees. Its twice-signed area is (1 - 2 tau)^2 times its initial "
     "(clockwise) area: a double root, no change of winding, so with cull ccw it is drawn for the "
     "whole shutter except the one instant. A reference that takes every root of the area as a "
     "winding flip culls the second half; one that samples coverage by the area's sign at the ends "
     "is right by luck. Samples near p are covered except around tau = 1/2, samples far out only "
     "near the ends. " + BOUNDS_NOTE,
     16, 16, [COLLAPSE_TRI],
     MB(16), cull="ccw", pins=[(8, 7), (8, 8), (4, 5), (7, 3), (12, 4)],
     checks=[lambda s: poly_double_root(area_poly(COLLAPSE_TRI)) == F(1, 2),
             lambda s: rat(s, 8, 7) is not None and 0 < rat(s, 8, 7) < 1,
             lambda s: rat(s, 12, 4) > 0])

# --- 4. Shutter, static primitives and meshes ----------------------------------------

case("shutter_quarter_to_three_quarters",
     "The shutter is [0.25, 0.75]: a triangle that turns and slides from (1.5, 9.25) (6.75, 1.5) "
     "(13.25, 12.5) at tau = 0 to (5, 13.5) (3.5, 3.75) (14.5, 5.25) at tau = 1 is seen only in "
     "the middle half of its motion, and the time coverage is normalised by the shutter's length "
     "(SPEC 15.2). Instants are open + (close - open) u/2^16. Fill rule top-right. A rasterizer "
     "that integrates over [0, 1], or maps its instants onto [0, 1], gets other values, near "
     "the ends of the motion most. " + BOUNDS_NOTE,
     16, 16, [tri(mv((F(3, 2), F(37, 4)), (5, F(27, 2))),
                  mv((F(27, 4), F(3, 2)), (F(7, 2), F(15, 4))),
                  mv((F(53, 4), F(25, 2)), (F(29, 2), F(21, 4))))],
     MB(16, shutter=(F(1, 4), F(3, 4))), fill_rule="top-right",
     pins=[(4, 5), (5, 3), (10, 6), (12, 8), (4, 10)])

case("static_and_moving_overlap",
     "A static triangle (2, 2) (13, 3) (4, 13) and a moving one that slides 8 px right across "
     "it, stratified 16 time samples: the pixel value is the sum over primitives (SPEC 15.2), so "
     "where the moving triangle passes over the static one it lies between 1 and 2. Static "
     "primitives need no instants and are drawn once (SPEC 15.3), but they cover their samples "
     "for the whole shutter: a method that counts a static sample as one test out of M*N, or "
     "that clamps a pixel's value to 1, fails here. " + BOUNDS_NOTE,
     16, 16, [tri((2, 2), (13, 3), (4, 13)),
              tri(mv((1, F(21, 4)), (9, F(23, 4))), mv((6, F(31, 8)), (14, F(25, 8))),
                  mv((F(11, 4), F(45, 4)), (F(43, 4), F(49, 4))))],
     MB(16), pins=[(5, 6), (9, 8), (11, 4), (4, 10), (12, 3)],
     checks=[lambda s: 1 < float(pixel_of(s, 5, 6)) < 2])

MESH = [(F(5, 2), F(9, 4)), mv((F(51, 4), F(3, 2)), (F(27, 2), 3)), (F(53, 4), F(27, 2)),
        mv((F(7, 4), F(49, 4)), (F(7, 2), F(23, 2)))]
MESH_TRIS = [tri(MESH[0], MESH[1], MESH[3]), tri(MESH[1], MESH[2], MESH[3])]


def mesh_check(s):
    """The two triangles of the mesh share the moving edge MESH[1]-MESH[3]: at each sample their
    time coverages must sum exactly to the time coverage of their union (a convex quad that moves
    with them), and a sample the diagonal sweeps over gets exactly 1."""
    quad = Prim("quad", [MESH[0], MESH[1], MESH[2], MESH[3]])
    quad.setup(8)
    for tau in (F(0), F(1, 2), F(1)):
        pts = quad.at(tau)
        n = len(pts)
        for i in range(n):
            (ax, ay), (bx, by), (cx, cy) = pts[i], pts[(i + 1) % n], pts[(i + 2) % n]
            assert (bx - ax) * (cy - by) - (by - ay) * (cx - bx) > 0, "mesh quad not convex"
    checked = 0
    for (x, y, si, pi), tc in s["tcs"].items():
        if pi != 0:
            continue
        other = s["tcs"][(x, y, si, 1)]
        union = TimeCoverage(quad, tc.q, (F(0), F(1)), "top-left", "none")
        d = tc.length + other.length - union.length
        assert d.rational() == 0, ("mesh is not watertight in time", x, y)
        if tc.length.rational() is None and union.length.rational() == 1:
            checked += 1
    assert checked >= 3, "no sample swept by the shared edge at irrational instants"
    return True


case("mesh_shared_moving_edge",
     "Two triangles sharing the edge (12.75, 1.5)->(13.5, 3) to (1.75, 12.25)->(3.5, 11.5), "
     "both of whose ends move, form a moving convex quad; a third, static triangle overlaps its "
     "top-left corner. A sample the shared edge sweeps over is covered by one triangle before "
     "and by the other after an irrational instant, and the two time coverages sum to exactly "
     "what their union gives (watertight in time, checked by the generator at every sample): "
     "pixels inside the quad for the whole shutter have exact value 1 even where each triangle's "
     "share is irrational. A rasterizer whose shared-edge test is not consistent between the two "
     "triangles at every instant leaves gaps or double coverage in time. " + BOUNDS_NOTE,
     16, 16, MESH_TRIS + [tri((0, 0), (F(11, 2), F(1, 4)), (F(1, 2), F(23, 4)))],
     MB(16), pins=[(7, 7), (10, 4), (2, 7), (9, 2), (6, 12), (2, 3)],
     checks=[mesh_check, lambda s: rat(s, 7, 7) == 1 and rat(s, 10, 4) == 1,
             lambda s: 1 < float(pixel_of(s, 2, 3)) < 2])

case("coverage_starts_at_shutter_open",
     "The shutter is [0.25, 1] and a triangle with a vertical right edge moves 8 px to the right "
     "over [0, 1], so at shutter open its right edge is exactly at x = 4.5, on the samples of "
     "column 4: their coverage starts exactly at tau = open (a right edge does not own them under "
     "top-left, so at that instant they are not covered) and ends when the slanted left edge "
     "passes. The samples the right edge reaches exactly at shutter close (x = 10.5) get "
     "coverage 0. A test at u = 0 lands exactly on the edge, and a reference that clips its "
     "intervals to the shutter with an off-by-one end gains or loses a point, not an interval; "
     "what it must get right is the normalisation by 0.75. " + BOUNDS_NOTE,
     12, 6, [tri(mv((F(5, 2), F(1, 4)), (F(21, 2), F(1, 4))),
                 mv((F(5, 2), F(23, 4)), (F(21, 2), F(23, 4))),
                 mv((F(-3, 2), 3), (F(13, 2), 3)))],
     MB(16, shutter=(F(1, 4), 1)), pins=[(4, 2), (4, 4), (10, 2), (7, 1)],
     checks=[lambda s: rat(s, 10, 2) == 0,
             lambda s: all(tc.member(F(1, 4)) is None for k, tc in s["tcs"].items()
                           if k[:2] == (4, 2))])

case("static_scene_with_motion_blur",
     "effects.motion_blur is declared but nothing moves: one vertex is even written in the moving "
     "form with from equal to to, which is a static vertex (SPEC 15.1). The scene is drawn as a "
     "static scene (no time loop) and judged as in SPEC 6: it carries samples_covered and no "
     "time expectations. A rasterizer that enters its time loop anyway must still give each "
     "sample a whole coverage.",
     12, 12, [tri((F(3, 2), F(1, 2)), V((F(21, 2), F(5, 2)), (F(21, 2), F(5, 2))),
                  (F(7, 2), F(21, 2))),
              tri((F(21, 2), F(5, 2)), (F(23, 2), F(23, 2)), (F(7, 2), F(21, 2)))],
     MB(8))

# --- 5. Motion and antialiasing ---------------------------------------------------------

AA_TRI = [mv((F(9, 4), F(7, 2)), (F(11, 2), F(17, 8))),
          mv((F(47, 4), F(5, 4)), (F(27, 2), F(33, 4))),
          mv((F(13, 2), F(103, 8)), (F(23, 8), F(53, 4)))]
for aa, n, adesc in ((AA(4), 16, "standard 4x"), (AA(16, "stratified", 0), 16, "stratified 16x")):
    for pattern, pdesc in (
            ("random", "independent random instants for each of the M*N tests"),
            ("stratified", "each spatial sample's N instants stratified over the shutter "
                           "(time-only stratification: the M spatial samples repeat the same "
                           "strata)"),
            ("jittered-xy-t", "the pixel's M*N instants stratified over the shutter and taken "
                              "in the order of the spatial samples (x, y and t correlated)"),
            ("stratified-shuffled", "the pixel's M*N strata dealt to the spatial samples by a "
                                    "seeded shuffle (t stratified independently of x and y)")):
        tag = "%s%d" % (aa["pattern"], aa["samples"])
        case("aa_%s_time_%s" % (tag, pattern.replace("-", "_")),
             "Motion with antialiasing: %s spatial samples x %d time samples, time pattern %s: "
             "%s. A triangle turning and sliding across a 16x16 canvas (the same geometry in all "
             "eight aa_*_time_* cases, so the report compares the patterns); the pixel's time "
             "coverage is the mean over its %d spatial samples of each one's exact time coverage "
             "(SPEC 15.2), and the instants come from SplitMix64 seeded per pixel (SPEC 15.3). "
             "%s" % (adesc, n, pattern, pdesc, aa["samples"], BOUNDS_NOTE),
             16, 16, [tri(*AA_TRI)], MB(n, pattern), aa=aa,
             pins=[(4, 3), (3, 4), (9, 6), (12, 8), (5, 12)])

# --- 6. Moving parallelogram lines ---------------------------------------------------------

case("line_parallelogram_moving_w1_5",
     "A parallelogram line of width 1.5 (SPEC 4.4) moving and turning: its ends go from "
     "(2.5, 3.25) to (6.25, 9.75) and from (12.75, 5.5) to (14.5, 12.25), so it stays x-major "
     "while its slope changes; its ends are vertical and its width is measured vertically at "
     "every instant. Its edge functions are quadratics in tau, and the samples on its path are "
     "covered for irrational fractions of the shutter. A rasterizer that moves a rectangle "
     "(perpendicular ends) instead gets other values near the ends. " + BOUNDS_NOTE,
     16, 16, [line(mv((F(5, 2), F(13, 4)), (F(25, 4), F(39, 4))),
                   mv((F(51, 4), F(11, 2)), (F(29, 2), F(49, 4))), F(3, 2))],
     MB(16), pins=[(7, 6), (3, 4), (13, 9), (10, 8)])

def switch_check(s):
    """Some samples are covered on one side of tau = 4/7 and not on the other, and
    there no edge of either parallelogram passes through them: the jump is the
    switch of major axis alone."""
    eps = F(1, 1 << 20)
    jumps = 0
    for tc in s["tcs"].values():
        if tc.member(F(4, 7) - eps) != tc.member(F(4, 7) + eps):
            assert tc.event_at(F(4, 7))
            others = [p for i, p in enumerate(tc.polys) if i >= 4 and
                      any(r.rational() == F(4, 7) for r in roots_in(p, F(0), F(1)))]
            jumps += not others
    return jumps >= 2


case("line_parallelogram_major_axis_flip",
     "A parallelogram line of width 2 whose major axis changes mid-shutter: its ends move from "
     "(2.125, 5.8125) to (5.625, 2.3125) and from (14.125, 9.8125) to (10.625, 13.3125), so its "
     "direction goes from "
     "(12, 4) (x-major: vertical ends, width measured vertically) to (5, 11) (y-major: horizontal "
     "ends, width measured horizontally), and |dx| = |dy| at tau = 4/7, a rational instant that "
     "is not a multiple of any power of 2. There the parallelogram jumps from one shape to the "
     "other (SPEC 15.2: the major axis is that of the direction at tau): the samples of pixels "
     "(4, 3) and (12, 11) lie in one parallelogram's end and not in the other's, so their "
     "coverage jumps at 4/7 with no edge passing through them. A rasterizer that "
     "keeps the major axis of shutter open gets them wrong for 3/7 of the shutter. " + BOUNDS_NOTE,
     16, 16, [line(mv((F(17, 8), F(93, 16)), (F(45, 8), F(37, 16))),
                   mv((F(113, 8), F(157, 16)), (F(85, 8), F(213, 16))), 2)],
     MB(16), pins=[(4, 3), (12, 11), (3, 5), (6, 7), (10, 10)],
     checks=[switch_check])

