"""The clip-space cases (cases/clip/), registered in the order they are
written. Vertices are placed with build.at (screen position, z_ndc, w) where
the screen position is the point of the case, and with CV (clip
coordinates) where the clip coordinates are: a vertex behind the eye has no
screen position. A description may name {N}, the case's own
samples_covered, and any other case by name; every number is the model's.
"""

from casegen.clip.build import CV, Tri, at, case


def count(name):
    return lambda frame, n: n[name]


def differ(a, b):
    return lambda frame, n: n[a] != n[b]


def equal(a, b):
    return lambda frame, n: n[a] == n[b]


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
