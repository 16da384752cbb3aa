//! The probe scenes, built here from JSON values (no case files): the
//! fill-rule meshes, the subpixel-precision cells and the interpolation
//! meshes, and the pieces (`tri`, `mesh_scene`) the sample-position probe
//! lays its grid out with. What each probe makes of the frames is
//! `infer.rs`'s.

use serde_json::{json, Value};

use crate::scene::{parse_case, Limits, Scene};

use super::evidence::PROBE_BITS;

fn scene(value: Value) -> Scene {
    parse_case(&value.to_string(), "probe", &Limits::default())
        .unwrap_or_else(|e| panic!("a probe scene is invalid: {e}"))
}

pub(super) fn tri(points: [(f64, f64); 3]) -> Value {
    json!({ "triangle": points.iter().map(|&(x, y)| json!([x, y])).collect::<Vec<_>>() })
}

pub(super) fn mesh_scene(name: &str, w: u32, h: u32, bits: u32, triangles: Vec<Value>) -> Scene {
    scene(json!({
        "name": name,
        "canvas": {"width": w, "height": h},
        "rules": {"subpixel_bits": bits, "fill_rule": "top-left", "cull": "none"},
        "primitives": triangles,
    }))
}

/// The fill-rule meshes: two-triangle meshes over a shared horizontal,
/// vertical, diagonal and anti-diagonal edge (each as written, with both
/// windings reversed, and drawn in the other order), and two fans whose
/// centre is a sample.
pub(super) fn fill_rule_meshes() -> Vec<(String, Scene)> {
    type Pair = [[(f64, f64); 3]; 2];
    let pairs: [(&str, Pair); 4] = [
        (
            "horizontal shared edge",
            [
                [(1.0, 8.5), (15.0, 8.5), (8.0, 1.5)],
                [(1.0, 8.5), (8.0, 15.5), (15.0, 8.5)],
            ],
        ),
        (
            "vertical shared edge",
            [
                [(8.5, 1.0), (8.5, 15.0), (1.5, 8.0)],
                [(8.5, 1.0), (15.5, 8.0), (8.5, 15.0)],
            ],
        ),
        (
            "diagonal shared edge",
            [
                [(1.0, 1.0), (15.0, 1.0), (15.0, 15.0)],
                [(1.0, 1.0), (15.0, 15.0), (1.0, 15.0)],
            ],
        ),
        (
            "anti-diagonal shared edge",
            [
                [(1.0, 1.0), (15.0, 1.0), (1.0, 15.0)],
                [(15.0, 1.0), (15.0, 15.0), (1.0, 15.0)],
            ],
        ),
    ];
    let mut out = Vec::new();
    for (label, [a, b]) in pairs {
        let rev = |t: [(f64, f64); 3]| [t[2], t[1], t[0]];
        out.push((label.to_owned(), vec![tri(a), tri(b)]));
        out.push((
            format!("{label}, windings reversed"),
            vec![tri(rev(a)), tri(rev(b))],
        ));
        out.push((
            format!("{label}, drawn in the other order"),
            vec![tri(b), tri(a)],
        ));
    }
    let fan = |label: &str, spokes: &[(f64, f64)]| {
        let c = (8.5, 8.5);
        let triangles = (0..spokes.len())
            .map(|i| {
                let (p, q) = (spokes[i], spokes[(i + 1) % spokes.len()]);
                tri([c, (c.0 + p.0, c.1 + p.1), (c.0 + q.0, c.1 + q.1)])
            })
            .collect();
        (label.to_owned(), triangles)
    };
    out.push(fan(
        "fan of 8 around a sample (axis and diagonal spokes)",
        &[
            (6.0, 0.0),
            (6.0, 6.0),
            (0.0, 6.0),
            (-6.0, 6.0),
            (-6.0, 0.0),
            (-6.0, -6.0),
            (0.0, -6.0),
            (6.0, -6.0),
        ],
    ));
    out.push(fan(
        "fan of 8 around a sample (spokes of slope 1/2 and 2)",
        &[
            (4.0, 2.0),
            (2.0, 4.0),
            (-2.0, 4.0),
            (-4.0, 2.0),
            (-4.0, -2.0),
            (-2.0, -4.0),
            (2.0, -4.0),
            (4.0, -2.0),
        ],
    ));
    out.into_iter()
        .map(|(label, triangles)| {
            let s = mesh_scene("probe_fill_rule", 16, 16, 8, triangles);
            (label, s)
        })
        .collect()
}

/// The slopes dy/dx (y down) of the tie meshes, as (dy, dx): horizontal,
/// vertical, and ±1/3, ±1/2, ±2/3, ±1, ±3/2, ±2, ±3, so that every octant
/// holds steep and shallow edges and each slope's reciprocal.
pub(super) const TIE_SLOPES: [(i64, i64); 16] = [
    (0, 1),
    (1, 0),
    (1, 3),
    (1, 2),
    (2, 3),
    (1, 1),
    (3, 2),
    (2, 1),
    (3, 1),
    (-1, 3),
    (-1, 2),
    (-2, 3),
    (-1, 1),
    (-3, 2),
    (-2, 1),
    (-3, 1),
];

/// The centre of the tie meshes' shared edge: a pixel centre.
pub(super) const TIE_CENTRE: (i64, i64) = (12, 12);

/// A slope in words: "3", "-1/3", "0 (horizontal)", "vertical".
pub(super) fn slope_words((dy, dx): (i64, i64)) -> String {
    match (dy, dx) {
        (0, _) => "0 (horizontal)".to_owned(),
        (_, 0) => "vertical".to_owned(),
        (dy, 1) => dy.to_string(),
        (dy, dx) => format!("{dy}/{dx}"),
    }
}

/// The tie meshes: for each of [`TIE_SLOPES`], two triangles sharing an
/// edge of that slope through the centres of pixel [`TIE_CENTRE`] and of
/// the pixels a whole step (dx, dy) along it, each pair drawn as written,
/// with windings reversed, and in the other order. Their other vertices
/// sit off the pixel-centre lattice by (5/16, 3/16), so that the tie
/// samples `infer.rs` reads are those on the shared edge (it keeps only
/// those, by an exact test).
pub(super) fn tie_slope_meshes() -> Vec<(String, (i64, i64), Scene)> {
    let mut out = Vec::new();
    for slope in TIE_SLOPES {
        let (dy, dx) = slope;
        let reach = 9 / dy.abs().max(dx.abs());
        let c = (TIE_CENTRE.0 as f64 + 0.5, TIE_CENTRE.1 as f64 + 0.5);
        let along = |t: i64| (c.0 + (t * dx) as f64, c.1 + (t * dy) as f64);
        let (a, b) = (along(-reach), along(reach));
        // Apexes on either side, along the normal (−dy, dx), off-lattice.
        let side = |k: f64| {
            let n = (-dy as f64, dx as f64);
            let scale = 6.0 / dy.abs().max(dx.abs()) as f64;
            (
                c.0 + k * n.0 * scale + 0.3125,
                c.1 + k * n.1 * scale + 0.1875,
            )
        };
        let (p, q) = ([a, b, side(1.0)], [b, a, side(-1.0)]);
        let rev = |t: [(f64, f64); 3]| [t[2], t[1], t[0]];
        let words = slope_words(slope);
        for (how, triangles) in [
            ("", vec![tri(p), tri(q)]),
            (", windings reversed", vec![tri(rev(p)), tri(rev(q))]),
            (", drawn in the other order", vec![tri(q), tri(p)]),
        ] {
            let s = mesh_scene("probe_tie_slopes", 25, 25, 8, triangles);
            out.push((format!("shared edge of slope {words}{how}"), slope, s));
        }
    }
    out
}

/// One precision cell: its sample, and the two positions of B.
pub(super) struct Step {
    pub(super) k: u32,
    pub(super) sample: (u32, u32),
}

/// The two scenes (B at p, B at p + 2^-k for every k and both parities)
/// and the cells' samples. `transpose` swaps x and y (the y sweep).
pub(super) fn precision_scenes(transpose: bool) -> (Scene, Scene, Vec<Step>) {
    let (cols, cell_w, cell_h) = (8u32, 12u32, 8u32);
    let mut before = Vec::new();
    let mut after = Vec::new();
    let mut steps = Vec::new();
    let mut cell = 0u32;
    let fraction = |num: i64, k: u32| format!("{num}/{}", 1i64 << k);
    for k in 1..=PROBE_BITS {
        // Three consecutive steps p_j → p_j + 2^-k, p_j = p_0 + j·2^-k.
        // With A = (n − 3j·2^-k, s_y − 3), B = (x, s_y + 1) and the sample
        // at (n + ½, s_y), the edge AB meets the sample when
        // x = τ_j = n + 2/3 + j·2^-k: strictly inside step j.
        for j in 0..3i64 {
            let (cx, cy) = ((cell % cols * cell_w) as i64, (cell / cols * cell_h) as i64);
            cell += 1;
            let n = cx + 4;
            let ax = fraction((n << k) - 3 * j, k);
            let p0 = (((3 * n + 2) << k) / 3) + j;
            let point = |x: String, y: String| {
                if transpose {
                    json!([y, x])
                } else {
                    json!([x, y])
                }
            };
            let a = point(ax, format!("{}.5", cy));
            let c = point((cx + 9).to_string(), format!("{}.5", cy + 3));
            let by = format!("{}.5", cy + 4);
            let t0 =
                json!({"triangle": [a.clone(), point(fraction(p0, k), by.clone()), c.clone()]});
            let t1 = json!({"triangle": [a, point(fraction(p0 + 1, k), by), c]});
            before.push(t0);
            after.push(t1);
            let sample = (n as u32, (cy + 3) as u32);
            steps.push(Step {
                k,
                sample: if transpose {
                    (sample.1, sample.0)
                } else {
                    sample
                },
            });
        }
    }
    let rows = cell.div_ceil(cols);
    let (w, h) = (cols * cell_w, rows * cell_h);
    let (w, h) = if transpose { (h, w) } else { (w, h) };
    (
        mesh_scene("probe_precision", w, h, PROBE_BITS, before),
        mesh_scene("probe_precision", w, h, PROBE_BITS, after),
        steps,
    )
}

/// The vertex cells: as [`precision_scenes`], but with the sample on the
/// first sample row below the edge's top vertex, so that no edge is
/// stepped before the sample. For k = 1..16 and j = 0, 1, 2:
///
/// - **along x**: the moving vertex B = (x, s − ½) is the top of an edge
///   to A = (n − 7j·2^-k, s + 7/2), and the sample is (n + ½, s): the edge
///   meets it, ⅛ of the way down, when x = τ_j = n + 4/7 + j·2^-k, never a
///   dyadic number and strictly inside step j of the 2^-k grid
///   (τ_j·2^k = n·2^k + 4·2^k/7 + j). The third vertex C = (cx + 15, s)
///   meets the sample's row far to the right.
/// - **along y** (`along_y`): B = (m, y) moves down, the edge runs to
///   A = (m + 3, n + 5 − 5j·2^-k), and the sample is (m + ½, n + 3/2): the
///   edge meets it, ⅙ of the way along, when y = τ_j = n + 4/5 + j·2^-k
///   (⅚·τ_j + ⅙·(n + 5 − 5j·2^-k) = n + 3/2), never dyadic and strictly
///   inside step j. C = (m + 12, n + 1), or (m + 12, n + 2) where A lies
///   above the sample's row (k = 1, j = 2), so that the sample lies on A's
///   side of CB whatever B's position. For k ≥ 2 every position of B
///   lies in (n + ½, n + 3/2]: B is the edge's top and the sample's row the
///   first at or below it, so a row walker finds the edge's x there from
///   B's y with no row stepped, and B's y grid decides. (For k = 1, B at
///   n + ½ and, for j = 2, A at n put one row before the sample's.) The
///   crossing moves about 0.6 times as far in x as B in y, so a walker that
///   rounds that x (to 1/64, say) resolves fewer bits of y than its grid
///   holds: a lower bound there.
///
/// A rasterizer that finds an edge's x on its first row from its snapped
/// vertices exactly reads its vertex grid here, however coarsely it steps
/// the edge down the rows after.
pub(super) fn vertex_scenes(along_y: bool) -> (Scene, Scene, Vec<Step>) {
    let (cols, cell_w, cell_h) = (8u32, 16u32, 8u32);
    let mut before = Vec::new();
    let mut after = Vec::new();
    let mut steps = Vec::new();
    let mut cell = 0u32;
    let fraction = |num: i64, k: u32| format!("{num}/{}", 1i64 << k);
    let point = |x: String, y: String| json!([x, y]);
    for k in 1..=PROBE_BITS {
        for j in 0..3i64 {
            let (cx, cy) = ((cell % cols * cell_w) as i64, (cell / cols * cell_h) as i64);
            cell += 1;
            // B's coordinate that moves, before and after: p_0 + j and
            // p_0 + j + 1 steps, p_0 = ⌊τ_0·2^k⌋, τ_0 = n + 4/7 along x and
            // n + 4/5 along y (n its whole part).
            let (a, c, fixed, sample, n) = if along_y {
                let (m, n) = (cx + 2, cy);
                let a = point((m + 3).to_string(), fraction(((n + 5) << k) - 5 * j, k));
                // C above the sample's row, or below it where A is above
                // it (k = 1, j = 2): the sample lies on A's side of CB.
                let c_y = if ((n + 5) << k) - 5 * j < ((2 * n + 3) << k) / 2 {
                    n + 2
                } else {
                    n + 1
                };
                let c = point((m + 12).to_string(), c_y.to_string());
                (a, c, m.to_string(), (m as u32, (n + 1) as u32), n)
            } else {
                let n = cx + 8;
                // The sample's row centre s = cy + 5/2.
                let a = point(fraction((n << k) - 7 * j, k), format!("{}", cy + 6));
                let c = point((cx + 15).to_string(), format!("{}.5", cy + 2));
                (a, c, (cy + 2).to_string(), (n as u32, (cy + 2) as u32), n)
            };
            // B at its coordinate that moves.
            let b = |moving: String| {
                if along_y {
                    point(fixed.clone(), moving)
                } else {
                    point(moving, fixed.clone())
                }
            };
            let below = if along_y {
                (4i64 << k) / 5
            } else {
                (4i64 << k) / 7
            };
            let p0 = (n << k) + below + j;
            let t0 = json!({"triangle": [b(fraction(p0, k)), a.clone(), c.clone()]});
            let t1 = json!({"triangle": [b(fraction(p0 + 1, k)), a, c]});
            before.push(t0);
            after.push(t1);
            steps.push(Step { k, sample });
        }
    }
    let (w, h) = (cols * cell_w, cell.div_ceil(cols) * cell_h);
    (
        mesh_scene("probe_vertex_precision", w, h, PROBE_BITS, before),
        mesh_scene("probe_vertex_precision", w, h, PROBE_BITS, after),
        steps,
    )
}

pub(super) fn interpolation_scene(name: &str, mode: &str, w: [&str; 3]) -> Scene {
    let v = |x: i32, y: i32, z: &str, w: &str, a: [&str; 2]| json!({"position": [x, y], "z": z, "w": w, "attributes": a});
    let (v0, v1, v2, v3) = (
        v(0, 0, "0.25", w[0], ["0", "1000"]),
        v(16, 0, "0.75", w[1], ["100", "-3"]),
        v(0, 16, "0.5", w[2], ["-50", "7"]),
        v(16, 16, "0.125", w[0], ["33", "0.5"]),
    );
    scene(json!({
        "name": name,
        "canvas": {"width": 16, "height": 16},
        "rules": {"subpixel_bits": 8},
        "primitives": [
            {"triangle": [v0, v1.clone(), v2.clone()], "interpolation": mode},
            {"triangle": [v1, v3, v2], "interpolation": mode},
        ],
    }))
}
