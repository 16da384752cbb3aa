"""The clip-space cases (cases/clip/), registered in the order they are
written. Vertices are placed with build.at (screen position, z_ndc, w) where
the screen position is the point of the case, and with CV (clip
coordinates) where the clip coordinates are: a vertex behind the eye has no
screen position. A description may name {N}, the case's own
samples_covered, and any other case by name; every number is the model's.
"""

from fractions import Fraction as F

from casegen.clip.build import CV, Tri, at, case


def count(name):
    return lambda frame, n: n[name]


def differ(a, b):
    return lambda frame, n: n[a] != n[b]


def equal(a, b):
    return lambda frame, n: n[a] == n[b]


def count_is(k):
    return lambda frame, n: len(frame) == k


def empty(frame, n):
    return not frame


def drawn(frame, n):
    return bool(frame)


def no_overdraw(frame, n):
    return all(cell[0] == 1 for cell in frame.values())


# ---------------------------------------------------------------------------
# The worked examples of SPEC 16.2: one triangle crossing the near plane.

NEAR = [at(2, 2, "-0.3525", 1, [1, 0]), at(14, 2, "0.8475", 1, [0, 1]),
        at(2, 14, "-0.3525", 1, [0, 0])]

case("spec_near_clip_then_snap",
     "SPEC 16.2, clip_z clip-then-snap: the near plane z = 0 crosses this triangle (w = 1, z = "
     "(x - 5.525)/10) on the vertical line x = 5.525. Clipping makes new vertices (5.525, 2) and "
     "(5.525, 10.475), and snapping to 4 subpixel bits moves them to (5.5, 2) and (5.5, 10.5): the "
     "new left edge x = 5.5 runs through the column of sample centres x = 5.5 and owns its 8 "
     "samples (top-left). {N} samples; spec_near_per_sample, whose exact depth there is z_ndc = "
     "-0.0025 < 0, covers {spec_near_per_sample}.",
     [Tri(*NEAR)], conv="gb_cts", subpixel_bits=4,
     checks=[lambda f, n: n["spec_near_clip_then_snap"] - n["spec_near_per_sample"] == 8])

case("spec_near_per_sample",
     "SPEC 16.2, clip_z per-sample: the triangle of spec_near_clip_then_snap is not clipped; a "
     "sample is covered only where its exact z_ndc = (x - 5.525)/10 lies in [0, 1], so the column "
     "x = 5.5 (z_ndc = -0.0025) is not: {N} samples against {spec_near_clip_then_snap} when the "
     "new vertices are snapped. A rasterizer that clips and snaps under this rule, or tests depth "
     "with a tolerance, covers 8 too many.",
     [Tri(*NEAR)], conv="gb_ps", subpixel_bits=4)

case("spec_depth_clamp",
     "SPEC 16.2, depth clamp: the triangle of spec_near_clip_then_snap with nothing clipped by "
     "depth: all {N} samples of the whole triangle are covered, and each depth is clamped to the "
     "viewport's range [0.25, 0.75], so the samples in front of the near plane (x < 5.525, z_ndc "
     "< 0) all get 0.25. Clipping or discarding them (depth clip) covers {spec_near_per_sample}.",
     [Tri(*NEAR)], conv="gb_clamp", subpixel_bits=4,
     viewport={"x": 0, "y": 0, "width": 16, "height": 16, "min_depth": 0.25, "max_depth": 0.75})

# z_ndc = (x - 5.5)/7 is exactly 0 on the sample column x = 5.5 and exactly 1 on x = 12.5.
CLOSED = [at(2, 1, "-0.5", 1, [0]), at(15, 1, "19/14", 2, [1]), at(15, 15, "19/14", "0.5", [2])]
for conv in ("gb_ps", "gb_cts"):
    case("depth_range_closed_" + conv,
         "The near and far planes run exactly through sample centres: z_ndc = (x - 5.5)/7 is 0 "
         "on the column x = 5.5 and 1 on x = 12.5. Per sample, both columns are kept (the "
         "range [0, 1] is closed, as the clip volume's planes are); clipped then snapped, they "
         "are edges of the clipped polygon and bottom-right owns only the right one (x = "
         "12.5). {N} samples (per-sample {depth_range_closed_gb_ps}, clipped "
         "{depth_range_closed_gb_cts}).",
         [Tri(*CLOSED)], conv=conv, fill_rule="bottom-right",
         checks=[differ("depth_range_closed_gb_ps", "depth_range_closed_gb_cts")])

# ---------------------------------------------------------------------------
# The worked examples of SPEC 16.3: the viewport's right side at x = 12.52.

SIDE_VP = {"x": 1.25, "y": 0.5, "width": "11.27", "height": 14}
SIDE = [at(2, 1, "0.25", 2, [1], SIDE_VP), at(20, 6, "0.5", "0.5", [2], SIDE_VP),
        at(4, 13, "0.75", 1, [3], SIDE_VP)]

case("spec_guard_band",
     "SPEC 16.3, clip_xy guard-band: the viewport [1.25, 12.52) x [0.5, 14.5) cuts this triangle "
     "(one vertex at x_f = 20, w = 0.5) on its right side. Nothing is clipped: the triangle is "
     "rasterized whole and the samples outside the viewport rectangle are dropped, so the column "
     "x = 12.5 < 12.52 is covered where the triangle reaches it: {N} samples. spec_clip_then_snap "
     "clips the same triangle and covers {spec_clip_then_snap}.",
     [Tri(*SIDE)], viewport=SIDE_VP, conv="gb_cts", subpixel_bits=4,
     checks=[differ("spec_guard_band", "spec_clip_then_snap")])

case("spec_clip_then_snap",
     "SPEC 16.3, clip_xy clip-then-snap: the triangle of spec_guard_band, clipped against x = w "
     "before the divide. The new vertices land exactly on the viewport's right side x_f = 12.52 "
     "and snap (4 subpixel bits) to x = 12.5: the clipped polygon's right edge now runs through "
     "the sample column x = 12.5, and a right edge does not own its samples (top-left). {N} "
     "samples against {spec_guard_band} under the guard band, which keeps that column "
     "(12.5 < 12.52).",
     [Tri(*SIDE)], viewport=SIDE_VP, conv="cts_cts", subpixel_bits=4)

# ---------------------------------------------------------------------------
# The worked examples of SPEC 16.2 and 16.3 again at 8 subpixel bits, the
# drivers' grid (they cannot be handed the 4-bit ones): the near plane and
# the viewport's right side sit 1/1024 px right of a sample column, so that
# clipping then snapping moves the new vertices onto the column, as 4 bits
# did above, while a per-sample test or the guard band sees the column on
# the other side of the plane.

X8 = F(11, 2) + F(1, 1024)
NEAR8 = [at(2, 2, (2 - X8) / 16, 1, [1, 0]), at(14, 2, (14 - X8) / 16, 1, [0, 1]),
         at(2, 14, (2 - X8) / 16, 1, [0, 0])]

case("near8_clip_then_snap",
     "spec_near_clip_then_snap at 8 subpixel bits: the near plane z = 0 crosses this triangle "
     "(w = 1, z = (x - 5.5009765625)/16) on x = 5.5 + 1/1024; its new vertices snap (8 bits) to "
     "x = 5.5, so the new left edge runs through the sample column x = 5.5 and owns it "
     "(top-left): {N} samples; near8_per_sample covers {near8_per_sample}.",
     [Tri(*NEAR8)], conv="gb_cts",
     checks=[differ("near8_clip_then_snap", "near8_per_sample")])

case("near8_per_sample",
     "spec_near_per_sample at 8 subpixel bits: the triangle of near8_clip_then_snap, not clipped; "
     "the column x = 5.5 has z_ndc = -1/16384 < 0 and is not covered: {N} samples against "
     "{near8_clip_then_snap} clipped then snapped.",
     [Tri(*NEAR8)], conv="gb_ps")

SIDE8_VP = {"x": 1.25, "y": 0.5, "width": "11.2509765625", "height": 14}
SIDE8 = [CV("-0.75", "-0.875", "0.25", 1, [1]), CV("0.75", "-0.125", "0.25", "0.5", [2]),
         CV(0, "0.75", "0.75", 1, [3])]

case("side8_guard_band",
     "spec_guard_band at 8 subpixel bits: the viewport [1.25, 12.5009765625) x [0.5, 14.5) cuts "
     "this triangle (one vertex at x/w = 1.5) on its right side, 1/1024 px right of the sample "
     "column x = 12.5. Under the guard band nothing is clipped and the column, inside the "
     "rectangle, is covered where the triangle reaches it: {N} samples; side8_clip_then_snap "
     "covers {side8_clip_then_snap}.",
     [Tri(*SIDE8)], viewport=SIDE8_VP, conv="gb_cts",
     checks=[differ("side8_guard_band", "side8_clip_then_snap")])

case("side8_clip_then_snap",
     "spec_clip_then_snap at 8 subpixel bits: the triangle of side8_guard_band clipped against "
     "x = w; the new vertices land on x_f = 12.5009765625 and snap (8 bits) to 12.5, so the "
     "clipped polygon's right edge runs through the sample column x = 12.5, which a right edge "
     "does not own (top-left): {N} samples against {side8_guard_band}.",
     [Tri(*SIDE8)], viewport=SIDE8_VP, conv="cts_cts")

# ---------------------------------------------------------------------------
# SPEC 16.4: a vertex behind the eye.

W_CROSS = [at(4, 4, "0.5", 2, [0]), at(12, 4, "0.5", 1, [1]), CV(0, "-0.5", "-0.5", -1, [2])]

case("spec_w_crossing",
     "SPEC 16.4: C = (0, -0.5, -0.5, -1) lies behind the eye (w = -1). Divided by its w it would "
     "land at (8, 12) and the triangle would cover the samples below the edge A (4, 4) - B "
     "(12, 4); the rays that meet the triangle at w > 0 lie above that edge instead, in a region "
     "that widens without bound toward the top (the edges from A and B run to C's point at "
     "infinity, directions (-1, -2) and (1, -2)). Pure homogeneous rasterization (guard band, "
     "per-sample depth, z_ndc = 0.5 everywhere): {N} samples, all with y < 4.",
     [Tri(*W_CROSS)], conv="gb_ps",
     checks=[lambda f, n: f and all(j < 4 for (_, j) in f)])

# ---------------------------------------------------------------------------
# SPEC 16.6: a flat triangle whose provoking vertex the near plane removes.

FLAT = [at(2, 3, "0.5", 1, [1, 0, 0]), at(14, 5, "0.5", 2, [0, 1, 0]),
        at(7, 14, "-0.5", "1.5", [0, 0, 1])]

case("spec_provoking_last",
     "SPEC 16.6: a flat triangle under provoking_vertex: last, whose last vertex C (z_ndc = -0.5, "
     "w = 1.5) lies in front of the near plane. Clipping (clip-then-snap) removes C and draws a "
     "fan of new vertices, yet every one of the {N} samples takes C's values (0, 0, 1): the "
     "pieces keep the original triangle's provoking vertex. A rasterizer that takes the last "
     "vertex of each piece writes a new vertex's interpolated values instead.",
     [Tri(*FLAT, interpolation="flat")], conv="cts_cts", provoking_vertex="last",
     checks=[drawn])

case("flat_provoking_first_clipped",
     "SPEC 16.6, provoking_vertex: first, with the first vertex A (z_ndc = -0.5) in front of the "
     "near plane: clipping removes A, and all {N} samples must still take A's values (0, 0, 1), "
     "not those of the new vertex that starts the clipped polygon.",
     [Tri(FLAT[2], FLAT[0], FLAT[1], interpolation="flat")], conv="gb_cts", checks=[drawn])

# ---------------------------------------------------------------------------
# SPEC 16.7: inside the clip volume every convention agrees.

case("spec_conventions_agree",
     "SPEC 16.7: all three vertices lie inside the clip volume with w > 0 (w = 3, 0.5, 1.25), so "
     "nothing is clipped and every combination of clip_xy, clip_z and depth draws the screen-space "
     "triangle (1.3, 2.7) (14.2, 5.9) (4.4, 13.6) snapped to 8 bits: {N} samples under "
     "each of the six (the generator checks all six and the screen-space test of SPEC 3). A "
     "difference between conventions here is a bug, not a convention.",
     [Tri(at("1.3", "2.7", "0.1", 3, [1, 2]), at("14.2", "5.9", "0.6", "0.5", [3, 4]),
          at("4.4", "13.6", "0.95", "1.25", [5, 6]))], conv="cts_ps")

# ---------------------------------------------------------------------------
# A mesh whose shared edges cross the near plane.

MESH_X = [-3, "7.3", 19]
MESH_Y = [-2, "8.6", 18]
MESH_W = [[1, 2, "0.5"], [3, "1.5", 1], ["0.75", "2.5", 4]]
MESH_Z = [["0.35", "0.4", "-0.2"], ["0.3", "-0.3", "0.25"], ["0.7", "0.45", "0.15"]]
MESH_V = [[at(MESH_X[c], MESH_Y[r], MESH_Z[r][c], MESH_W[r][c], [r, c]) for c in range(3)]
          for r in range(3)]
MESH = []
for r in range(2):
    for c in range(2):
        MESH.append(Tri(MESH_V[r][c], MESH_V[r][c + 1], MESH_V[r + 1][c + 1]))
        MESH.append(Tri(MESH_V[r][c], MESH_V[r + 1][c + 1], MESH_V[r + 1][c]))

MESH_TEXT = ("Eight triangles of a 3 x 3 grid of vertices (w from 0.5 to 4) cover the canvas; "
             "the centre vertex (7.3, 8.6) lies in front of the near plane (z_ndc = -0.3), so "
             "z_ndc changes sign along six of the eight shared edges and the near plane z = 0 "
             "cuts a hole around the centre whose rim runs through them. ")

case("mesh_across_near",
     MESH_TEXT + "Clip-then-snap: both triangles of a shared edge compute its new vertex as the "
     "same exact rational (t = d(P)/(d(P) - d(Q)) whichever end the edge is walked from), so the "
     "snapped pieces meet without a hole or overdraw: {N} samples, watertight (SPEC 16.3). A "
     "clipper that computes t in float, or from the edge's own first vertex, cracks the mesh.",
     MESH, conv="gb_cts", watertight=True, checks=[no_overdraw])

case("mesh_across_near_per_sample",
     MESH_TEXT + "Per-sample depth: nothing is clipped, and a sample is kept where its exact "
     "z_ndc >= 0; the homogeneous edge functions of a shared edge are exact opposites, so the "
     "mesh stays watertight: {N} samples (clip-then-snap: {mesh_across_near}).",
     MESH, conv="gb_ps", watertight=True, checks=[no_overdraw])

case("mesh_across_near_clamp",
     MESH_TEXT + "Depth clamp: nothing is clipped or discarded by depth, the whole canvas is "
     "covered once ({N} samples) and the depth in front of the near plane is clamped to 0.",
     MESH, conv="gb_clamp", watertight=True, checks=[no_overdraw, count_is(256)])

case("mesh_across_near_clip_xy",
     MESH_TEXT + "Clip-then-snap on all six planes: the outer vertices lie outside the viewport, "
     "so every triangle is also cut by the sides, and the new vertices on the sides are shared "
     "too: {N} samples, watertight.",
     MESH, conv="cts_cts", watertight=True, checks=[no_overdraw])

# ---------------------------------------------------------------------------
# Vertices behind the eye (w < 0) and at w = 0, under every convention.

CONV_TEXT = {
    "gb_ps": "pure homogeneous rasterization (guard band, per-sample depth)",
    "gb_cts": "guard band with near and far clipped then snapped",
    "cts_cts": "clip-then-snap on all six planes",
    "cts_ps": "clip-then-snap on the sides, per-sample depth",
    "gb_clamp": "guard band with depth clamp (nothing clipped)",
    "cts_clamp": "clip-then-snap on the sides with depth clamp",
}

ONE_BEHIND = [at(3, 12, "0.6", "1.5", [0, 1]), at(13, 11, "0.4", "0.8", [1, 0]),
              CV("0.2", "-1.5", "-1.2", "-0.5", [2, 2])]
for conv in ("gb_ps", "gb_cts", "cts_cts", "gb_clamp"):
    case("w_one_behind_" + conv,
         "One vertex behind the eye (w = -0.5) and two in front (w = 1.5 and 0.8), under "
         + CONV_TEXT[conv] + ". The triangle's visible part runs off toward the top of the "
         "canvas, toward w = 0 (depth clip cuts it at the near plane first); a rasterizer "
         "that divides by the negative w draws the mirrored external triangle instead. {N} "
         "samples (per-sample "
         "{w_one_behind_gb_ps}, near clipped {w_one_behind_gb_cts}, all planes clipped "
         "{w_one_behind_cts_cts}, depth clamp {w_one_behind_gb_clamp}).",
         [Tri(*ONE_BEHIND)], conv=conv, checks=[drawn])

TWO_BEHIND = [at(8, 12, "0.95", 1, [1]), CV("-0.5", -1, "-1.2", -1, [2]),
              CV("0.6", "-0.8", "-0.65", "-0.5", [3])]
for conv in ("gb_ps", "gb_cts", "cts_cts", "gb_clamp"):
    case("w_two_behind_" + conv,
         "Two vertices behind the eye (w = -1 and -0.5), one in front at (8, 12) (w = 1), under "
         + CONV_TEXT[conv] + ". Only a wedge from the front vertex is visible, bounded by the two "
         "edges that reach w = 0; dividing either negative w flips it. {N} samples (per-sample "
         "{w_two_behind_gb_ps}, near clipped {w_two_behind_gb_cts}, all planes clipped "
         "{w_two_behind_cts_cts}, depth clamp {w_two_behind_gb_clamp}).",
         [Tri(*TWO_BEHIND)], conv=conv, checks=[drawn])

W_ZERO = [at(3, 13, "0.5", 1, [0]), at(13, 12, "0.5", 2, [1]), CV("0.25", -1, 0, 0, [2])]
for conv in ("gb_ps", "gb_cts", "cts_cts"):
    case("w_zero_vertex_" + conv,
         "A vertex at w = 0 exactly, (0.25, -1, 0, 0): a point at infinity in the direction "
         "(2, -8) on the screen, with no projection of its own; a divide by its w is a division "
         "by zero. Under " + CONV_TEXT[conv] + "; it lies on both the near and the far plane "
         "(d = 0, kept), so only the sides clip it. {N} samples.",
         [Tri(*W_ZERO)], conv=conv, checks=[drawn])

BEHIND = [CV("-0.5", "-0.5", "-0.5", -1, [0]), CV("0.5", "-0.3", "-0.2", -2, [1]),
          CV("0.1", "0.6", "-0.3", "-0.75", [2])]
for conv in ("gb_ps", "gb_clamp", "cts_cts"):
    case("behind_eye_" + conv,
         "All three vertices behind the eye (w = -1, -2, -0.75): no ray from the eye meets the "
         "triangle at w > 0, so it draws nothing under " + CONV_TEXT[conv] + ". Divided by their "
         "w the vertices land at (12, 12), (6, 9.2) and (6.93, 1.6) and would cover a large "
         "triangle: the homogeneous test gives every sample sigma*E < 0 on some edge.",
         [Tri(*BEHIND)], conv=conv, checks=[empty])

# (x, y, w) of C is A - 3B: the plane of the triangle passes through the eye.
EYE = [CV("0.25", "0.125", "0.5", 1, [0]), CV("-0.25", "0.5", "0.25", "0.5", [1]),
       CV(1, "-1.375", "-0.25", "-0.5", [2])]
for conv, bits in (("gb_ps", 8), ("gb_clamp", 8), ("cts_cts", None)):
    case("plane_through_eye_" + conv,
         "The plane of this triangle passes through the eye: C's (x, y, w) is A's minus three "
         "times B's, so D = det[H0, H1, H2] = 0 and it covers nothing (SPEC 16.4), although C is "
         "behind the eye (w = -0.5) and A and B project to the grid points (10, 9) and (4, 16). "
         "Under " + CONV_TEXT[conv] + (", unsnapped so that the clipped pieces stay on the "
                                       "line" if bits is None else "") + ".",
         [Tri(*EYE)], conv=conv, subpixel_bits=bits, checks=[empty])

# ---------------------------------------------------------------------------
# Near-plane slivers: the kept part is 1/300 px thick.

SLIVER = [at(1, "8.5", "0.0004", 1), at(15, "8.5", "0.0004", 1), at(8, 1, "-0.8996", 1)]
for name, conv, bits in (("near_sliver_b4", "gb_cts", 4), ("near_sliver_b8", "gb_cts", 8),
                         ("near_sliver_per_sample", "gb_ps", 8)):
    case(name,
         "The near plane leaves a sliver 1/300 px thick along the edge y = 8.5 (z_ndc = 0.0004 "
         "there, -0.8996 at the apex (8, 1)); bottom-left owns that bottom edge's samples. "
         + {"near_sliver_b4": "Clip-then-snap at 4 subpixel bits snaps the new vertices "
            "(y = 8.5 - 1/300) onto y = 8.5: every piece has zero area and nothing is drawn.",
            "near_sliver_b8": "Clip-then-snap at 8 subpixel bits snaps the new vertices to "
            "y = 8.5 - 1/256: the sliver survives and covers the samples on its bottom edge.",
            "near_sliver_per_sample": "Per-sample: the samples on y = 8.5 have z_ndc = 0.0004 "
            ">= 0 and are covered; those above are in front of the near plane."}[name]
         + " {N} samples (4 bits {near_sliver_b4}, 8 bits {near_sliver_b8}, per-sample "
         "{near_sliver_per_sample}).",
         [Tri(*SLIVER)], conv=conv, subpixel_bits=bits, fill_rule="bottom-left")

# ---------------------------------------------------------------------------
# The far plane.

FAR = [at(2, 3, "0.2", 2, [0]), at(14, 6, "1.6", "0.5", [1]), at(5, 14, "1.1", "1.25", [2])]
for conv in ("gb_cts", "gb_ps"):
    case("far_clip_" + conv,
         "Two vertices lie beyond the far plane z = w (z_ndc = 1.6 and 1.1, w = 0.5 and 1.25): "
         "the far plane cuts the triangle where the screen-linear z_ndc reaches 1, which is not "
         "where clip z and w interpolated apart on the screen put it. Under " + CONV_TEXT[conv]
         + " at 4 subpixel bits: {N} samples (clipped {far_clip_gb_cts}, per-sample "
         "{far_clip_gb_ps}).",
         [Tri(*FAR)], conv=conv, subpixel_bits=4, checks=[drawn])

# ---------------------------------------------------------------------------
# Extreme ratios of w.

EXTREME = [at(2, "2.5", "0.5", "0.000001", [0, 1]), at(14, 4, "0.25", 1000000, [1, 0]),
           at(6, 14, "0.75", 1, [1, 1])]
for conv in ("gb_ps", "cts_cts"):
    case("extreme_w_" + conv,
         "w spans twelve orders of magnitude: 10^-6, 10^6 and 1 (clip x up to 750000). The "
         "perspective weights 1/w of the vertices differ by 10^12, so f32 barycentrics lose the "
         "small ones entirely. Under " + CONV_TEXT[conv] + ": {N} samples.",
         [Tri(*EXTREME)], conv=conv, checks=[drawn])

EXTREME_NEAR = [CV("-0.00000075", "-0.000000625", "-0.0000005", "0.000001", [0]),
                at(14, 4, "0.5", 1000000, [1]), at(6, 14, "0.75", 1, [2])]
for conv in ("gb_cts", "gb_ps"):
    case("extreme_w_near_" + conv,
         "The near plane cuts the edges from a vertex at w = 10^-6 (z = -5*10^-7) to vertices at "
         "w = 10^6 and 1: on the first edge t = 5*10^-7/(5*10^-7 + 5*10^5), about 10^-12, and "
         "the new vertex is 10^-12 of the way along in clip space but lands far from the "
         "first vertex's projection on the screen. Under " + CONV_TEXT[conv] + ": {N} samples "
         "(clipped {extreme_w_near_gb_cts}, per-sample {extreme_w_near_gb_ps}).",
         [Tri(*EXTREME_NEAR)], conv=conv, checks=[drawn])

# ---------------------------------------------------------------------------
# Depth clamp at the near and the far plane, with viewport depth ranges.


def depth_range(low, high):
    return {"x": 0, "y": 0, "width": 16, "height": 16, "min_depth": low, "max_depth": high}


CLAMP_NEAR = [at(2, 2, "-0.4", "0.5", [0]), at(14, 3, "0.6", 2, [1]), at(4, 14, "0.3", 1, [2])]
case("depth_clamp_near",
     "Depth clamp with the viewport's depth range [0.2, 0.9]: one vertex lies in front of the "
     "near plane (z_ndc = -0.4, w = 0.5). Nothing is clipped; the depth there, 0.2 + 0.7 z_ndc, "
     "falls below 0.2 and is clamped to 0.2, not to 0. {N} samples, against "
     "{depth_clip_near} when depth clips.",
     [Tri(*CLAMP_NEAR)], conv="gb_clamp", viewport=depth_range("0.2", "0.9"),
     checks=[differ("depth_clamp_near", "depth_clip_near")])
case("depth_clip_near",
     "The triangle of depth_clamp_near under depth clip (clip-then-snap): the part in front of "
     "the near plane (z_ndc < 0) is clipped away, and the viewport's depth range [0.2, 0.9] "
     "maps z_ndc = 0 on the new edge to 0.2. {N} samples.",
     [Tri(*CLAMP_NEAR)], conv="gb_cts", viewport=depth_range("0.2", "0.9"))

CLAMP_FAR = [at(2, 2, "1.5", 2, [0]), at(14, 3, "0.4", 1, [1]), at(4, 14, "0.9", "0.5", [2])]
case("depth_clamp_far",
     "Depth clamp with the depth range [0.1, 0.6]: one vertex lies beyond the far plane "
     "(z_ndc = 1.5, w = 2). Nothing is clipped; depths beyond 0.6 are clamped to 0.6, the "
     "viewport's max_depth, not to 1. {N} samples, against {depth_clip_far} when depth clips.",
     [Tri(*CLAMP_FAR)], conv="gb_clamp", viewport=depth_range("0.1", "0.6"),
     checks=[differ("depth_clamp_far", "depth_clip_far")])
case("depth_clip_far",
     "The triangle of depth_clamp_far under depth clip, per sample: samples with exact "
     "z_ndc > 1 are dropped. {N} samples.",
     [Tri(*CLAMP_FAR)], conv="gb_ps", viewport=depth_range("0.1", "0.6"))

CLAMP_BOTH = [at(1, 2, "-0.5", 1, [0]), at(15, 4, "1.5", "1.5", [1]),
              at(3, 15, "0.5", "0.75", [2])]
case("depth_clamp_reversed",
     "Depth clamp with a reversed depth range, min_depth 0.8 > max_depth 0.3 (z_ndc = 0 maps to "
     "0.8, 1 to 0.3): the triangle crosses both the near and the far plane. Each depth is "
     "clamped to [min, max] = [0.3, 0.8] of the two, so the near side gets 0.8 and the far side "
     "0.3; clamping to [min_depth, max_depth] as written is an empty range. {N} samples.",
     [Tri(*CLAMP_BOTH)], conv="gb_clamp", viewport=depth_range("0.8", "0.3"))
case("depth_clip_reversed",
     "The triangle of depth_clamp_reversed under depth clip, clipped then snapped at both the "
     "near and the far plane with the reversed range [0.8, 0.3]: {N} samples, against "
     "{depth_clamp_reversed} clamped.",
     [Tri(*CLAMP_BOTH)], conv="gb_cts", viewport=depth_range("0.8", "0.3"),
     checks=[differ("depth_clamp_reversed", "depth_clip_reversed")])

case("depth_clamp_clip_xy",
     "Depth clamp with clip-then-snap on the sides: one vertex beyond the right side "
     "(x_f = 20), one in front of the near plane, and one behind the eye (w = -0.3). The "
     "sides clip away everything with w <= 0 (each needs w >= |x|); depth is not clipped but "
     "clamped to [0, 1]. {N} samples.",
     [Tri(at(3, 3, "-0.5", 1, [0]), at(20, 8, "0.5", 2, [1]),
          CV("-0.2", "0.9", "-0.4", "-0.3", [2]))],
     conv="cts_clamp", checks=[drawn])

# ---------------------------------------------------------------------------
# The viewport's sides: guard band against clip then snap.

HALF_VP = {"x": "2.5", "y": "1.5", "width": 10, "height": 12}
WEDGE = [at(-20, 7, "0.5", 2, [0], HALF_VP), at(30, -2, "0.5", "0.5", [1], HALF_VP),
         at(30, 18, "0.5", 1, [2], HALF_VP)]
for name, conv, rule in (("viewport_sides_gb_bottom_right", "gb_cts", "bottom-right"),
                         ("viewport_sides_cts_top_left", "cts_cts", "top-left"),
                         ("viewport_sides_cts_bottom_right", "cts_cts", "bottom-right")):
    case(name,
         "The viewport [2.5, 12.5) x [1.5, 13.5) has its sides on sample centres, and a wedge "
         "widening to the right crosses its left and right sides. The guard band keeps x = 2.5 "
         "and drops x = 12.5 whatever the fill rule (the rectangle is half-open); clip-then-snap "
         "makes the sides edges of the clipped polygon, owned by the fill rule: under "
         "bottom-right it keeps the right column x = 12.5, where the wedge is taller, and drops "
         "the left. {N} samples (guard band {viewport_sides_gb_bottom_right}, clip-then-snap "
         "top-left {viewport_sides_cts_top_left}, bottom-right "
         "{viewport_sides_cts_bottom_right}).",
         [Tri(*WEDGE)], viewport=HALF_VP, conv=conv, fill_rule=rule,
         checks=[equal("viewport_sides_gb_bottom_right", "viewport_sides_cts_top_left"),
                 differ("viewport_sides_cts_top_left", "viewport_sides_cts_bottom_right")])

FRAC_VP = {"x": "1.3", "y": "2.7", "width": "12.9", "height": "10.1"}
FRAC = [at(-7, -9, "0.25", "1.5", [0], FRAC_VP), at(27, 1, "0.5", "0.25", [1], FRAC_VP),
        at(4, 31, "0.75", 3, [2], FRAC_VP)]
for conv in ("gb_cts", "cts_cts"):
    case("viewport_fractional_" + conv,
         "A fractional viewport [1.3, 14.2) x [2.7, 12.8) inside a large triangle whose vertices "
         "all lie outside it (w = 1.5, 0.25, 3). Clip-then-snap at 4 subpixel bits moves the "
         "new vertices on the sides to 1.3125, 14.1875, 2.6875 and 12.8125; the guard band cuts "
         "at the exact sides. Under " + CONV_TEXT[conv] + ": {N} samples (guard band "
         "{viewport_fractional_gb_cts}, clip-then-snap {viewport_fractional_cts_cts}).",
         [Tri(*FRAC)], viewport=FRAC_VP, conv=conv, subpixel_bits=4)

OFF_VP = {"x": "3.5", "y": "4.5", "width": "8.75", "height": "6.25"}
OFFSET = [at(-20, -20, "0.5", 2, [0], OFF_VP), at(60, 0, "0.5", "0.5", [1], OFF_VP),
          at(0, 60, "0.5", 1, [2], OFF_VP)]
for name, conv, bits in (("viewport_offset_gb", "gb_cts", 8),
                         ("viewport_offset_cts_b8", "cts_cts", 8),
                         ("viewport_offset_cts_b0", "cts_cts", 0)):
    case(name,
         "The viewport [3.5, 12.25) x [4.5, 10.75) is smaller than the 16 x 16 canvas and offset "
         "into it; a triangle far larger covers it. Nothing outside the viewport may be drawn: "
         "the guard band drops those samples, clip-then-snap cuts the triangle to the viewport. "
         "At 0 subpixel bits the clipped corners snap to (4, 4) and (12, 11) (3.5 and 4.5 are "
         "ties, to even). {N} samples (guard band {viewport_offset_gb}, clip-then-snap 8 bits "
         "{viewport_offset_cts_b8}, 0 bits {viewport_offset_cts_b0}).",
         [Tri(*OFFSET)], viewport=OFF_VP, conv=conv, subpixel_bits=bits,
         checks=[count("viewport_offset_gb"),
                 lambda f, n: all(3 <= i <= 11 and 4 <= j <= 10 for i, j in f)])

# ---------------------------------------------------------------------------
# Culling with a vertex behind the eye.

CULL = [at(3, 12, "0.5", 1, [0]), at(13, 12, "0.5", 1, [1]), CV(0, "-0.5", "-0.25", "-0.5", [2])]
for cull in ("none", "cw", "ccw"):
    case("cull_%s_behind_eye" % cull,
         "cull: %s on a triangle with one vertex behind the eye (w = -0.5). Its winding is the "
         "sign of D = det[H0, H1, H2] with the vertex behind the eye kept homogeneous: "
         "D < 0, counter-clockwise, although the screen triangle of the three divided vertices "
         "(3, 12) (13, 12) (8, 24) is clockwise. {N} samples (none {cull_none_behind_eye}, "
         "cw {cull_cw_behind_eye}, ccw {cull_ccw_behind_eye})." % cull,
         [Tri(*CULL)], conv="gb_ps", cull=cull,
         checks=[lambda f, n: n["cull_none_behind_eye"] == n["cull_cw_behind_eye"] > 0
                 and n["cull_ccw_behind_eye"] == 0])

# ---------------------------------------------------------------------------
# Perspective attributes across a clipped triangle.

PERSP = [at(1, 1, "-0.5", "0.5", [0, 10]), at(15, 3, "0.5", 4, [1, 20]),
         at(3, 15, "0.8", 1, [2, -5])]
for conv in ("gb_cts", "gb_ps"):
    case("interp_perspective_clipped_" + conv,
         "Perspective-correct attributes across a triangle cut by the near plane (w = 0.5, 4, "
         "1): clipping makes new vertices whose attributes are interpolated linearly in clip "
         "space, which is perspective-correct at their position, so the pieces of the clipped "
         "triangle carry the same values as the unclipped triangle tested per sample (up to "
         "the snapping of the new vertices). Interpolating the new vertices' attributes on the "
         "screen, or dividing before clipping, is wrong by up to the attribute range. Under "
         + CONV_TEXT[conv] + ": {N} samples.",
         [Tri(*PERSP)], conv=conv, checks=[drawn])

# ---------------------------------------------------------------------------
# All five fill rules on homogeneous edges through sample centres.

# C divided would land at (8.5, 20.5); its edges from A (4.5, 12.5) and B (12.5, 12.5) run
# up and outward with slopes -2 and 2 through sample centres.
FILL = [at("4.5", "12.5", "0.5", 1, [0]), at("12.5", "12.5", "0.5", 2, [1]),
        CV("-0.0625", "-1.5625", "-0.5", -1, [2])]
for rule in ("top-left", "bottom-right", "top-right", "bottom-left", "all-edges"):
    name = "fill_" + rule.replace("-", "_")
    case(name,
         "Fill rule %s on a triangle with a vertex behind the eye (w = -1): the visible region "
         "lies above the bottom edge A (4.5, 12.5) - B (12.5, 12.5), between a left edge from A "
         "and a right edge from B that run toward the top with slopes -2 and 2, all three "
         "through sample centres. Ownership is read from sigma*E's coefficients (SPEC 16.4), "
         "not from the divided vertices, whose triangle lies below AB. {N} samples "
         "(top-left {fill_top_left}, bottom-right {fill_bottom_right}, top-right "
         "{fill_top_right}, bottom-left {fill_bottom_left}, all-edges {fill_all_edges})." % rule,
         [Tri(*FILL)], conv="gb_ps", fill_rule=rule,
         checks=[lambda f, n: len({n["fill_top_left"], n["fill_bottom_right"],
                                  n["fill_bottom_left"], n["fill_all_edges"]}) == 4])

# ---------------------------------------------------------------------------
# Subpixel bits on the new vertices.

# Four bands, each cut by the near plane on the vertical line x = c (z_ndc = (x - c)/20 is
# linear on the screen whatever the w); each new vertex x = c snaps to the case's grid, and the
# column of sample centres beside c is inside the kept part or not.
BITS_CUTS = ["5.501", "9.500005", "11.5", "13.51"]
BITS = []
for band, c in enumerate(BITS_CUTS):
    left, y0 = int(F(c)) - 3, 1 + 4 * band
    z = [(F(x) - F(c)) / 20 for x in (left, left + 6, left + 6)]
    BITS.append(Tri(at(left, y0, z[0], 1, [band]), at(left + 6, y0, z[1], 2, [band]),
                    at(left + 6, y0 + 3, z[2], "0.5", [band])))
for bits in (0, 4, 8, 16, None):
    case("bits_%s" % ("null" if bits is None else bits),
         "subpixel_bits %s on four bands cut by the near plane (clip-then-snap) on the vertical "
         "lines x = 5.501, 9.500005, 11.5 and 13.51. The new vertices snap (ties to even) and "
         "decide whether the column of sample centres at x = 5.5, 9.5, 11.5, 13.5 in each band "
         "lies on the kept side (a left edge through it owns it): 0 bits moves them to 6, 10, "
         "12, 14 (11.5 is a tie), 4 bits to 5.5, 9.5, 11.5, 13.5, 8 bits keeps 13.51 off 13.5 "
         "(3459/256), 16 bits keeps 5.501 too, and null keeps all but 11.5. {N} samples "
         "(0 bits {bits_0}, 4 {bits_4}, 8 {bits_8}, 16 {bits_16}, null {bits_null})."
         % ("null" if bits is None else bits),
         BITS, conv="gb_cts", subpixel_bits=bits,
         checks=[lambda f, n: len({n["bits_0"], n["bits_4"], n["bits_8"], n["bits_16"],
                                  n["bits_null"]}) == 5])

# ---------------------------------------------------------------------------
# Values from the unsnapped positions (16.5).

UNSNAPPED = [at("1.0013", "1.0027", "0.05", 1, [0]), at("15.0031", "2.0009", "0.95", 2, [1]),
             at("3.0021", "14.9989", "0.5", "0.5", ["0.5"])]
case("spec_interpolate_unsnapped",
     "interpolate_from: unsnapped. A triangle inside the clip volume whose vertices land off "
     "the 8-bit grid (x_f, y_f = (1.0013, 1.0027), (15.0031, 2.0009), (3.0021, 14.9989)): "
     "coverage comes from the snapped vertices, depth and the perspective attribute from the "
     "exact ones, as a driver that sets its planes up in floating point does. The values differ "
     "from the snapped positions' by up to 1.2e-4 in depth and 1.1e-4 in the attribute, beyond the 2^-16 bound of 6.3, and equal "
     "those of the same triangle drawn unsnapped. {N} samples, as under snapped "
     "({spec_interpolate_snapped}).",
     [Tri(*UNSNAPPED)], conv="gb_cts", interpolate_from="unsnapped",
     checks=[lambda f, n: n["spec_interpolate_unsnapped"] == n["spec_interpolate_snapped"]])
case("spec_interpolate_snapped",
     "The triangle of spec_interpolate_unsnapped under interpolate_from: snapped (the "
     "default, written out): depth and attributes from the snapped vertices. {N} samples.",
     [Tri(*UNSNAPPED)], conv="gb_cts", interpolate_from="snapped", checks=[drawn])
for conv in ("gb_cts", "gb_ps"):
    case("interp_unsnapped_clipped_" + conv,
         "The triangle of interp_perspective_clipped_%s (cut by the near plane) under "
         "interpolate_from: unsnapped: each piece's values come from its exact projected "
         "vertices, the new ones included. {N} samples, as under snapped." % conv,
         [Tri(*PERSP)], conv=conv, interpolate_from="unsnapped",
         checks=[lambda f, n, conv=conv: n["interp_unsnapped_clipped_" + conv]
                 == n["interp_perspective_clipped_" + conv]])

# ---------------------------------------------------------------------------
# Polygon offset on steep slopes in clip space (SPEC 18.2): the offset is
# read off each piece's plane of z_f on the screen; coverage, pinned here,
# is the offset-free triangle's (an offset moves depth, never coverage).

STEEP = [at(2, 2, 0, 1, [0]), at(6, 2, "0.75", 1, [1]), at(2, 14, 0, 1, [2])]
case("offset_steep_slope",
     "Polygon offset on a steep depth plane in clip space: z_ndc = 3(x - 2)/16 rises by 3/16 a "
     "pixel (|dz/dx| = 3/16, dz/dy = 0, so the maximum slope m is 3/16 whichever way it is "
     "measured), float32 with slope factor 1/2 and constant 16: every sample is pushed back by "
     "m/2 = 3/32 plus 16 r (r from the largest depth 3/4's exponent, 2^-24 or 2^-23), the "
     "largest depth 3/4 + 3/32 staying inside [0, 1]. {N} samples, as without the offset.",
     [Tri(*STEEP)], conv="gb_cts", depth_format="float32",
     depth_bias={"constant": 16, "slope": "1/2"}, checks=[drawn])

STEEP_W = [at(2, 2, "0.1", 1, [0]), at(8, 2, "0.9", 4, [1]), at(2, 12, "0.1", 2, [2])]
case("offset_steep_perspective",
     "Polygon offset on a steep plane under perspective, unorm16: w from 1 to 4, z_ndc from 0.1 "
     "to 0.9 over 6 pixels (dz/dx = 2/15 on the screen, z_ndc being linear there whatever w "
     "is), slope factor 1 and constant 2: near the far vertex the offset depth 0.9 + 2/15 + 2r "
     "passes 1 and the format clamps it to 1 (k = 65535). {N} samples, as without the offset.",
     [Tri(*STEEP_W)], conv="gb_cts", depth_format="unorm16",
     depth_bias={"constant": 2, "slope": 1}, checks=[drawn])
