//! Convention probing: what a rasterizer does, found from its rendered
//! frames alone, and the profile (`rastercheck-profile/1`) that `run
//! --profile` judges it by.
//!
//! Every probe draws small scenes built here (no case files) and reads the
//! frames back; nothing about the rasterizer is assumed or asked:
//!
//! - **Fill rule.** Meshes whose samples lie exactly on shared horizontal,
//!   vertical and diagonal edges and on fan centres, in several windings
//!   and draw orders. The reference draws each under all five rules; the
//!   samples where the rules disagree are the tie samples, and the
//!   candidate's count and owner there are compared with each rule and with
//!   "none" (open edges: holes). The rule that explains every tie sample is
//!   the answer; when none does, the nearest is named and the rule is
//!   reported inconsistent, with the meshes where it departs.
//! - **y direction.** A triangle in the top half of the canvas: does it
//!   appear in the top rows?
//! - **Subpixel precision.** For k = 1..16, a vertex B of a thin triangle
//!   is drawn at three consecutive steps p_j → p_j + 2^-k of the 2^-k
//!   grid (j = 0, 1, 2), each in its own cell whose geometry puts one
//!   sample exactly on the edge when B is at τ_j = p_j + ⅓·2^-k or
//!   p_j + ⅔·2^-k: never a dyadic number, so never a rounding boundary or
//!   a tie, and strictly inside the step. The other vertices lie on the
//!   2^-k grid and do not move within a step. A rasterizer that keeps
//!   k bits (and is exact once it has snapped) draws each sample in one
//!   render of its step and not in the other. One that keeps b < k bits
//!   moves B to a point of its 2^-b grid less than 2^-b away (truncation,
//!   rounding with any ties): the four points p_0 … p_3 span 3·2^-k, and
//!   four distinct grid points 2^-b ≥ 2·2^-k apart cannot lie within 2^-b
//!   of them, so at least one step is drawn twice the same and its sample
//!   does not change. The finest k at which every step changes, for every
//!   k up to it, is therefore exactly the bits kept. The sweep is made
//!   along x and along y; one that rounds edge positions between vertices
//!   (tiny-skia rounds each edge's x on its first scanline to 1/64)
//!   resolves fewer bits along that axis, never more than its grid, so the
//!   grid is the finer of the two (both are reported). Scenes state 16
//!   subpixel bits, the most a case can: "exact" means the rasterizer
//!   keeps all of them.
//! - **Sample position.** 64 tiny triangles (3/32 px) around the offsets
//!   (i/8, j/8) of separate pixels: the ones drawn say where the sample is.
//! - **Interpolation.** A linear and a perspective mesh (w from 0.1 to 10)
//!   with depth and two attributes, measured as in `run` (SPEC §6.3).
//!
//! `run --profile FILE` overrides each case's `rules.fill_rule` with the
//! profile's rule for the rasterizer the profile names (and drops the
//! case's `expect.samples_covered`, which pins the reference to the case's
//! own rule); snapping, sample position and interpolation are still judged
//! against the case as written.

use std::path::Path;

use rayon::prelude::*;
use serde::Serialize;
use serde_json::{json, Value};

use crate::frame::Frame;
use crate::harness::runner::{self, CaseOutcome};
use crate::harness::suite::{self, CaseFile, Verdict};
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::reference;
use crate::scene::{parse_case, FillRule, Limits, Scene};

pub const SCHEMA: &str = "rastercheck-profile/1";

/// The subpixel bits the probe scenes state: the most a case can.
pub const PROBE_BITS: u32 = 16;

/// What a probe found.
#[derive(Clone, Debug, Serialize)]
pub struct Profile {
    pub schema: &'static str,
    pub tool: crate::report::json::Tool,
    pub rasterizer: String,
    /// The rule that explains the most tie samples (`top-left`, ...,
    /// `all-edges`, or `none` for open edges); `null` when nothing was drawn.
    pub fill_rule: Option<String>,
    /// Whether that rule explains every tie sample.
    pub fill_rule_consistent: bool,
    /// One entry per probe mesh.
    pub fill_rule_evidence: Vec<MeshEvidence>,
    /// `true` when y points down on screen (a triangle in the top half is
    /// drawn in the top rows), `false` when up, `null` when unclear.
    pub y_down: Option<bool>,
    /// Subpixel bits the rasterizer keeps; `null` when it keeps all the
    /// case states (`exact`) or when it could not be measured.
    pub subpixel_bits: Option<u32>,
    /// "8 bits", "exact", or why it is unknown.
    pub subpixel: String,
    /// Bits resolved along x and along y.
    pub subpixel_resolved: Resolved,
    /// "centre", "(x, y)", "several: ..." or "none found".
    pub sample_position: String,
    /// The sample's offset in its pixel, when there is exactly one.
    pub sample_offset: Option<[f64; 2]>,
    pub interpolation: Vec<InterpolationProbe>,
    /// Departures from D3D11 and Vulkan, as sentences.
    pub departures: Vec<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct Resolved {
    pub x: Option<u32>,
    pub y: Option<u32>,
}

#[derive(Clone, Debug, Serialize)]
pub struct MeshEvidence {
    pub mesh: String,
    pub tie_samples: usize,
    /// Tie samples each rule explains, in the order top-left, bottom-right,
    /// top-right, bottom-left, all-edges, none.
    pub explained: Vec<RuleCount>,
    /// Samples away from every edge that differ from the reference.
    pub off_edge_differences: usize,
    /// Why the rasterizer drew nothing, when it did not.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct RuleCount {
    pub rule: String,
    pub samples: usize,
}

#[derive(Clone, Debug, Serialize)]
pub struct InterpolationProbe {
    pub case: String,
    /// `measured`, `unsupported` or `error`.
    pub status: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub why: Option<String>,
    pub channels: Vec<ChannelProbe>,
}

#[derive(Clone, Debug, Serialize)]
pub struct ChannelProbe {
    pub channel: String,
    pub max_abs: f64,
    pub max_ulp: f64,
    pub allowed_abs: f64,
    pub within_bound: bool,
}

/// The candidate rules: the five fill rules, then "none" (open edges).
const RULE_NAMES: [&str; 6] = [
    "top-left",
    "bottom-right",
    "top-right",
    "bottom-left",
    "all-edges",
    "none",
];

fn scene(value: Value) -> Scene {
    parse_case(&value.to_string(), "probe", &Limits::default())
        .unwrap_or_else(|e| panic!("a probe scene is invalid: {e}"))
}

fn tri(points: [(f64, f64); 3]) -> Value {
    json!({ "triangle": points.iter().map(|&(x, y)| json!([x, y])).collect::<Vec<_>>() })
}

fn mesh_scene(name: &str, w: u32, h: u32, bits: u32, triangles: Vec<Value>) -> Scene {
    scene(json!({
        "name": name,
        "canvas": {"width": w, "height": h},
        "rules": {"subpixel_bits": bits, "fill_rule": "top-left", "cull": "none"},
        "primitives": triangles,
    }))
}

/// Draws a scene, catching panics.
fn draw(candidate: &dyn Rasterizer, scene: &Scene) -> Result<Frame, RasterError> {
    let plan = Plan::for_scene(scene);
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        candidate.rasterize(scene, &plan)
    }))
    .unwrap_or_else(|panic| {
        Err(RasterError::Failed(format!(
            "panicked: {}",
            suite::panic_message(&*panic)
        )))
    })
}

/// The fill-rule meshes: two-triangle meshes over a shared horizontal,
/// vertical, diagonal and anti-diagonal edge (each as written, with both
/// windings reversed, and drawn in the other order), and two fans whose
/// centre is a sample.
fn fill_rule_meshes() -> Vec<(String, Scene)> {
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

fn with_rule(scene: &Scene, rule: FillRule) -> Scene {
    let mut s = scene.clone();
    s.rules.fill_rule = rule;
    s
}

/// Runs the fill-rule meshes; returns the evidence per mesh.
fn probe_fill_rule(candidate: &dyn Rasterizer) -> Vec<MeshEvidence> {
    fill_rule_meshes()
        .into_iter()
        .map(|(label, s)| {
            let plan = Plan::for_scene(&s);
            let refs: Vec<Frame> = FillRule::ALL
                .iter()
                .map(|&r| reference::render(&with_rule(&s, r), &plan))
                .collect();
            let n = refs[0].sample_count();
            let key = |f: &Frame, i: usize| (f.coverage[i], f.last[i]);
            let ties: Vec<usize> = (0..n)
                .filter(|&i| refs.iter().any(|f| key(f, i) != key(&refs[0], i)))
                .collect();
            let mut evidence = MeshEvidence {
                mesh: label,
                tie_samples: ties.len(),
                explained: Vec::new(),
                off_edge_differences: 0,
                error: None,
            };
            let frame = match draw(candidate, &s) {
                Ok(f) if f.sample_count() == n => f,
                Ok(_) => {
                    evidence.error = Some("returned a frame of the wrong size".to_owned());
                    return evidence;
                }
                Err(e) => {
                    evidence.error = Some(e.to_string());
                    return evidence;
                }
            };
            for (k, name) in RULE_NAMES.iter().enumerate() {
                let samples = ties
                    .iter()
                    .filter(|&&i| match refs.get(k) {
                        Some(r) => key(r, i) == key(&frame, i),
                        None => frame.coverage[i] == 0,
                    })
                    .count();
                evidence.explained.push(RuleCount {
                    rule: (*name).to_owned(),
                    samples,
                });
            }
            evidence.off_edge_differences = (0..n)
                .filter(|i| !ties.contains(i) && key(&refs[0], *i) != key(&frame, *i))
                .count();
            evidence
        })
        .collect()
}

/// The rule that explains the most tie samples over all meshes, and
/// whether it explains all of them. `None` when no mesh was drawn.
fn nearest_rule(evidence: &[MeshEvidence]) -> Option<(String, bool)> {
    let drawn: Vec<&MeshEvidence> = evidence.iter().filter(|e| e.error.is_none()).collect();
    if drawn.is_empty() {
        return None;
    }
    let total: usize = drawn.iter().map(|e| e.tie_samples).sum();
    let score = |k: usize| -> usize { drawn.iter().map(|e| e.explained[k].samples).sum() };
    let best = (0..RULE_NAMES.len())
        .max_by_key(|&k| (score(k), std::cmp::Reverse(k)))
        .unwrap_or(0);
    Some((
        RULE_NAMES[best].to_owned(),
        score(best) == total && drawn.len() == evidence.len(),
    ))
}

/// y direction: a triangle over the top half.
fn probe_y(candidate: &dyn Rasterizer) -> Option<bool> {
    let s = mesh_scene(
        "probe_y",
        16,
        16,
        8,
        vec![tri([(0.0, 0.0), (16.0, 0.0), (0.0, 8.0)])],
    );
    let frame = draw(candidate, &s).ok()?;
    let (mut top, mut bottom) = (0usize, 0usize);
    for y in 0..frame.height {
        for x in 0..frame.width {
            if frame.coverage[frame.index(x, y)] > 0 {
                if y < frame.height / 2 {
                    top += 1;
                } else {
                    bottom += 1;
                }
            }
        }
    }
    match (top > 0, bottom > 0) {
        (true, false) => Some(true),
        (false, true) => Some(false),
        _ => None,
    }
}

/// One precision cell: its sample, and the two positions of B.
struct Step {
    k: u32,
    sample: (u32, u32),
}

/// The two scenes (B at p, B at p + 2^-k for every k and both parities)
/// and the cells' samples. `transpose` swaps x and y (the y sweep).
fn precision_scenes(transpose: bool) -> (Scene, Scene, Vec<Step>) {
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

/// Bits resolved along one axis: the largest k such that all three steps
/// of every k' ≤ k change their sample. `Err` when it could not draw.
fn probe_axis(candidate: &dyn Rasterizer, transpose: bool) -> Result<u32, String> {
    let (before, after, steps) = precision_scenes(transpose);
    let f0 = draw(candidate, &before).map_err(|e| e.to_string())?;
    let f1 = draw(candidate, &after).map_err(|e| e.to_string())?;
    if f0.sample_count() != before.canvas.pixel_count()
        || f1.sample_count() != after.canvas.pixel_count()
    {
        return Err("returned a frame of the wrong size".to_owned());
    }
    let mut bits = 0;
    for k in 1..=PROBE_BITS {
        let changed = steps.iter().filter(|s| s.k == k).all(|s| {
            let i = f0.index(s.sample.0, s.sample.1);
            f0.coverage[i] != f1.coverage[i]
        });
        if !changed {
            break;
        }
        bits = k;
    }
    Ok(bits)
}

/// Sample position: tiny triangles around (i/8, j/8) in pixel (2i+1, 2j+1).
fn probe_sample_position(candidate: &dyn Rasterizer) -> (String, Option<[f64; 2]>) {
    let d = 1.0 / 32.0;
    let mut triangles = Vec::new();
    let mut anchors = Vec::new();
    for j in 0..8u32 {
        for i in 0..8u32 {
            let (px, py) = (2 * i + 1, 2 * j + 1);
            let (x, y) = (
                f64::from(px) + f64::from(i) / 8.0,
                f64::from(py) + f64::from(j) / 8.0,
            );
            triangles.push(tri([
                (x - d, y - d),
                (x + 2.0 * d, y - d),
                (x - d, y + 2.0 * d),
            ]));
            anchors.push((x, y));
        }
    }
    let s = mesh_scene("probe_sample_position", 18, 18, 8, triangles);
    let frame = match draw(candidate, &s) {
        Ok(f) => f,
        Err(e) => return (format!("unknown: {e}"), None),
    };
    let mut offsets: Vec<(i64, i64)> = Vec::new();
    for qy in 0..frame.height {
        for qx in 0..frame.width {
            let i = frame.index(qx, qy);
            if frame.coverage[i] == 0 {
                continue;
            }
            let (x, y) = anchors[frame.last[i] as usize - 1];
            // The sample lies within 3/32 px of the anchor: name it to 1/8.
            let o = (
                ((x - f64::from(qx)) * 8.0).round() as i64,
                ((y - f64::from(qy)) * 8.0).round() as i64,
            );
            if !offsets.contains(&o) {
                offsets.push(o);
            }
        }
    }
    offsets.sort();
    match offsets.as_slice() {
        [] => (
            "none found (no triangle of 3/32 px around an offset (i/8, j/8) was drawn)".to_owned(),
            None,
        ),
        [(4, 4)] => ("centre".to_owned(), Some([0.5, 0.5])),
        [(x, y)] => {
            let o = [*x as f64 / 8.0, *y as f64 / 8.0];
            (format!("({}, {}) in the pixel", o[0], o[1]), Some(o))
        }
        many => (
            format!(
                "several: {}",
                many.iter()
                    .map(|(x, y)| format!("({}, {})", *x as f64 / 8.0, *y as f64 / 8.0))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            None,
        ),
    }
}

fn interpolation_scene(name: &str, mode: &str, w: [&str; 3]) -> Scene {
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

fn probe_interpolation(candidate: &dyn Rasterizer) -> Vec<InterpolationProbe> {
    [
        interpolation_scene("linear", "linear", ["1", "1", "1"]),
        interpolation_scene("perspective", "perspective", ["0.1", "1", "10"]),
    ]
    .iter()
    .map(|s| {
        let reference = suite::run_reference(s);
        let run = suite::run_candidate(s, &reference, candidate);
        let (status, why) = match &run.verdict {
            Verdict::Unsupported(why) => ("unsupported", Some(why.clone())),
            Verdict::Error(why) => ("error", Some(why.clone())),
            _ => ("measured", None),
        };
        let channels = run
            .metrics
            .map(|m| {
                m.channels
                    .iter()
                    .map(|c| ChannelProbe {
                        channel: c.channel.clone(),
                        max_abs: c.max_abs,
                        max_ulp: c.max_ulp,
                        allowed_abs: c.allowed_abs,
                        within_bound: c.within_bounds(),
                    })
                    .collect()
            })
            .unwrap_or_default();
        InterpolationProbe {
            case: s.name.clone(),
            status: status.to_owned(),
            why,
            channels,
        }
    })
    .collect()
}

/// Probes a rasterizer. `Err` when it draws none of the probe scenes.
pub fn probe(candidate: &dyn Rasterizer) -> Result<Profile, String> {
    let evidence = probe_fill_rule(candidate);
    if let Some(e) = evidence.iter().find_map(|e| e.error.clone()) {
        if evidence.iter().all(|e| e.error.is_some()) {
            return Err(format!(
                "{} could not draw the probe meshes: {e}",
                candidate.name()
            ));
        }
    }
    let rule = nearest_rule(&evidence);
    let y_down = probe_y(candidate);
    let x_bits = probe_axis(candidate, false);
    let y_bits = probe_axis(candidate, true);
    let (subpixel_bits, subpixel) = match (&x_bits, &y_bits) {
        (Ok(x), Ok(y)) => {
            // A rasterizer cannot resolve finer than its vertex grid along
            // any axis, but may resolve less along one where it rounds edge
            // positions between vertices: the grid is the finer of the two.
            let b = (*x).max(*y);
            let axes = if x == y {
                String::new()
            } else {
                format!(
                    " (x {x}, y {y}: edges resolve fewer bits along {} than the vertex grid)",
                    if x < y { "x" } else { "y" }
                )
            };
            if b >= PROBE_BITS {
                (None, format!("exact{axes}"))
            } else {
                (Some(b), format!("{b} bits{axes}"))
            }
        }
        (Err(e), _) | (_, Err(e)) => (None, format!("unknown: {e}")),
    };
    let (sample_position, sample_offset) = probe_sample_position(candidate);
    let interpolation = probe_interpolation(candidate);
    let mut profile = Profile {
        schema: SCHEMA,
        tool: crate::report::json::Tool {
            name: "rastercheck",
            version: env!("CARGO_PKG_VERSION"),
        },
        rasterizer: candidate.name().to_owned(),
        fill_rule: rule.as_ref().map(|r| r.0.clone()),
        fill_rule_consistent: rule.as_ref().is_some_and(|r| r.1),
        fill_rule_evidence: evidence,
        y_down,
        subpixel_bits,
        subpixel,
        subpixel_resolved: Resolved {
            x: x_bits.ok(),
            y: y_bits.ok(),
        },
        sample_position,
        sample_offset,
        interpolation,
        departures: Vec::new(),
    };
    profile.departures = departures(&profile);
    Ok(profile)
}

fn rule_index(name: &str) -> usize {
    RULE_NAMES.iter().position(|r| *r == name).unwrap_or(0)
}

/// Where the nearest rule does not explain a mesh, as "mesh (n of m)".
fn inconsistencies(p: &Profile) -> Vec<String> {
    let Some(rule) = &p.fill_rule else {
        return Vec::new();
    };
    let k = rule_index(rule);
    p.fill_rule_evidence
        .iter()
        .filter(|e| e.error.is_none() && e.explained[k].samples < e.tie_samples)
        .map(|e| {
            let others: Vec<&str> = e
                .explained
                .iter()
                .filter(|c| c.samples == e.tie_samples)
                .map(|c| c.rule.as_str())
                .collect();
            format!(
                "{}: {} of {} tie samples differ{}",
                e.mesh,
                e.tie_samples - e.explained[k].samples,
                e.tie_samples,
                if others.is_empty() {
                    String::new()
                } else {
                    format!(" (explained by {})", others.join(", "))
                }
            )
        })
        .collect()
}

/// Departures from D3D11 and Vulkan, as sentences.
fn departures(p: &Profile) -> Vec<String> {
    let mut out = Vec::new();
    match p.fill_rule.as_deref() {
        None => out.push("It drew none of the fill-rule meshes, so its tie rule is unknown.".to_owned()),
        Some("top-left") => {}
        Some("all-edges") => out.push(
            "Samples on an edge belong to every triangle that has the edge (closed edges): samples on shared edges are drawn twice, where D3D11's top-left rule (functional spec §3.4.2.1) and Vulkan give each to exactly one triangle.".to_owned(),
        ),
        Some("none") => out.push(
            "Samples on an edge belong to no triangle (open edges): meshes get holes along every shared edge, where D3D11 and Vulkan give each such sample to exactly one triangle.".to_owned(),
        ),
        Some(rule) => {
            let owned = match rule {
                "bottom-right" => "bottom and right",
                "top-right" => "top and right",
                _ => "bottom and left",
            };
            out.push(format!(
                "Tie samples go to the triangle whose {owned} edges hold them ({rule}); D3D11 (functional spec §3.4.2.1) and Vulkan implementations use top-left. Meshes stay watertight, but every sample on a shared edge goes to the other triangle than on D3D11."
            ));
        }
    }
    if p.fill_rule.is_some() && !p.fill_rule_consistent {
        out.push(format!(
            "Its tie rule is not consistent: no single fill rule explains every tie sample ({}).",
            inconsistencies(p).join("; ")
        ));
    }
    if p.y_down == Some(false) {
        out.push("y points up: a triangle in the top half of the canvas is drawn in the bottom rows; D3D11 and Vulkan framebuffer coordinates point down.".to_owned());
    }
    match p.subpixel_bits {
        Some(b) if b < 4 => out.push(format!(
            "Vertices snap to {b} subpixel bits (a 1/{} px grid): fewer than Vulkan's minimum subPixelPrecisionBits of 4 and D3D11's 8.",
            1u64 << b
        )),
        Some(b) if b < 8 => out.push(format!(
            "Vertices snap to {b} subpixel bits (a 1/{} px grid); D3D11 snaps to 8 (16.8 fixed point). Vulkan allows it (subPixelPrecisionBits ≥ 4).",
            1u64 << b
        )),
        Some(b) if b > 8 => out.push(format!(
            "Vertices keep {b} subpixel bits; D3D11 snaps to exactly 8, so vertices off the 1/256 px grid land elsewhere than on D3D11 (Vulkan allows any subPixelPrecisionBits ≥ 4)."
        )),
        None if p.subpixel.starts_with("exact") => out.push(
            "Vertices keep every subpixel bit the case states (up to 16); D3D11 snaps to exactly 8, so a case stating more than 8 bits is drawn finer than on D3D11 (Vulkan allows any subPixelPrecisionBits ≥ 4).".to_owned(),
        ),
        _ => {}
    }
    if p.sample_offset != Some([0.5, 0.5]) {
        out.push(format!(
            "Sample position: {}; D3D11 and single-sampled Vulkan sample at the pixel centre.",
            p.sample_position
        ));
    }
    for probe in &p.interpolation {
        for c in probe.channels.iter().filter(|c| !c.within_bound) {
            out.push(format!(
                "Interpolation of {} in the {} mesh is off by {:.3e} ({:.1} ulp), beyond rastercheck's bound of {:.3e} (SPEC §6.3).",
                c.channel, probe.case, c.max_abs, c.max_ulp, c.allowed_abs
            ));
        }
    }
    out
}

impl Profile {
    /// A human-readable account of the profile.
    pub fn describe(&self) -> String {
        let mut s = String::new();
        let ties: usize = self
            .fill_rule_evidence
            .iter()
            .filter(|e| e.error.is_none())
            .map(|e| e.tie_samples)
            .sum();
        s += &format!("profile of {}\n", self.rasterizer);
        s += &format!(
            "  fill rule:          {}{}\n",
            self.fill_rule.as_deref().unwrap_or("unknown"),
            match (&self.fill_rule, self.fill_rule_consistent) {
                (None, _) => String::new(),
                (Some(_), true) => format!(
                    " (explains all {ties} tie samples of {} meshes)",
                    self.fill_rule_evidence.len()
                ),
                (Some(_), false) => ", inconsistent".to_owned(),
            }
        );
        for line in inconsistencies(self) {
            s += &format!("                      {line}\n");
        }
        let off: usize = self
            .fill_rule_evidence
            .iter()
            .map(|e| e.off_edge_differences)
            .sum();
        if off > 0 {
            s += &format!("                      and {off} samples away from the edges differ from the reference\n");
        }
        s += &format!(
            "  y direction:        {}\n",
            match self.y_down {
                Some(true) => "down",
                Some(false) => "up",
                None => "unclear",
            }
        );
        s += &format!(
            "  subpixel precision: {}{}\n",
            self.subpixel,
            if self.subpixel.starts_with("exact") {
                format!(" (all {PROBE_BITS} bits a case can state)")
            } else {
                String::new()
            }
        );
        s += &format!("  sample position:    {}\n", self.sample_position);
        for probe in &self.interpolation {
            match probe.status.as_str() {
                "measured" => {
                    let worst = probe
                        .channels
                        .iter()
                        .max_by(|a, b| a.max_abs.total_cmp(&b.max_abs));
                    match worst {
                        Some(c) => {
                            s += &format!(
                                "  interpolation:      {} max {:.3e} ({:.1} ulp, {}){}\n",
                                probe.case,
                                c.max_abs,
                                c.max_ulp,
                                c.channel,
                                if probe.channels.iter().all(|c| c.within_bound) {
                                    ""
                                } else {
                                    " beyond the bound"
                                }
                            )
                        }
                        None => {
                            s += &format!(
                                "  interpolation:      {} nothing to compare\n",
                                probe.case
                            )
                        }
                    }
                }
                other => {
                    s += &format!(
                        "  interpolation:      {} {other}: {}\n",
                        probe.case,
                        probe.why.as_deref().unwrap_or("")
                    )
                }
            }
        }
        if self.departures.is_empty() {
            s += "departures from D3D11/Vulkan: none found\n";
        } else {
            s += "departures from D3D11/Vulkan:\n";
            for d in &self.departures {
                s += &format!("  - {d}\n");
            }
        }
        s
    }

    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default() + "\n"
    }
}

/// What `run --profile` takes from a profile file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Declared {
    pub rasterizer: String,
    pub fill_rule: FillRule,
    pub file: String,
}

/// Reads a profile file for `run --profile`.
pub fn load_declared(path: &Path) -> Result<Declared, String> {
    let shown = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| format!("{shown}: {e}"))?;
    let value: Value =
        serde_json::from_str(&text).map_err(|e| format!("{shown}: not JSON: {e}"))?;
    let schema = value.get("schema").and_then(Value::as_str);
    if schema != Some(SCHEMA) {
        return Err(format!(
            "{shown}: $.schema: expected {SCHEMA:?}, found {}",
            value
                .get("schema")
                .map_or("nothing".to_owned(), |v| v.to_string())
        ));
    }
    let rasterizer = value
        .get("rasterizer")
        .and_then(Value::as_str)
        .ok_or_else(|| format!("{shown}: $.rasterizer: expected a rasterizer name"))?
        .to_owned();
    let rule = value
        .get("fill_rule")
        .and_then(Value::as_str)
        .ok_or_else(|| format!("{shown}: $.fill_rule: the profile declares no fill rule"))?;
    let fill_rule = FillRule::from_name(rule).ok_or_else(|| {
        format!(
            "{shown}: $.fill_rule: {rule:?} is not a fill rule a case can state ({})",
            FillRule::ALL.map(|r| r.name()).join(", ")
        )
    })?;
    Ok(Declared {
        rasterizer,
        fill_rule,
        file: shown,
    })
}

impl Declared {
    /// The line `run` prints about the override.
    pub fn note(&self) -> String {
        format!(
            "profile: {} is judged under its declared fill rule {} (from {}) instead of each case's",
            self.rasterizer, self.fill_rule, self.file
        )
    }
}

/// The profiles of `run --profile`, and the rasterizers to run: `names`,
/// or the profiles' rasterizers when none are named (production when
/// there are no profiles either). Every profiled rasterizer must be run,
/// and have one profile.
pub fn for_run(
    files: &[std::path::PathBuf],
    names: &[String],
) -> Result<(Vec<Declared>, Vec<String>), String> {
    let mut declared: Vec<Declared> = Vec::new();
    for file in files {
        let d = load_declared(file)?;
        if let Some(other) = declared.iter().find(|o| o.rasterizer == d.rasterizer) {
            return Err(format!(
                "{} and {} are both profiles of {}; give one per rasterizer",
                other.file, d.file, d.rasterizer
            ));
        }
        declared.push(d);
    }
    let names = if !names.is_empty() {
        names.to_vec()
    } else if declared.is_empty() {
        vec!["production".to_owned()]
    } else {
        declared.iter().map(|d| d.rasterizer.clone()).collect()
    };
    if let Some(d) = declared.iter().find(|d| !names.contains(&d.rasterizer)) {
        return Err(format!(
            "{} is a profile of {}, which this run does not check (add -r '{}')",
            d.file, d.rasterizer, d.rasterizer
        ));
    }
    Ok((declared, names))
}

/// Stands in for a profiled rasterizer during the ordinary run, so that it
/// is drawn only once, under its declared rule.
struct Deferred {
    name: String,
    foil: bool,
}

impl Rasterizer for Deferred {
    fn name(&self) -> &str {
        &self.name
    }
    fn capabilities(&self) -> Capabilities {
        Capabilities::everything()
    }
    fn is_foil(&self) -> bool {
        self.foil
    }
    fn rasterize(&self, _: &Scene, _: &Plan) -> Result<Frame, RasterError> {
        Err(RasterError::Unsupported(
            "deferred to its profile".to_owned(),
        ))
    }
}

/// A case with its fill rule replaced by a declared one.
pub fn under_rule(scene: &Scene, rule: FillRule) -> Scene {
    let mut s = with_rule(scene, rule);
    // The pin describes the case's own rule, not the declared one.
    s.expect.samples_covered = None;
    s
}

/// [`runner::run_all`], except that every candidate named by a profile is
/// judged against a reference drawn under the profile's fill rule.
pub fn run_all_with_profiles(
    files: &[CaseFile],
    limits: &Limits,
    candidates: &mut [Box<dyn Rasterizer>],
    declared: &[Declared],
    root: &Path,
    threads: Option<usize>,
    done: &(dyn Fn(&CaseOutcome) + Sync),
) -> Vec<CaseOutcome> {
    let mut swapped: Vec<(usize, Box<dyn Rasterizer>, FillRule)> = Vec::new();
    for (index, candidate) in candidates.iter_mut().enumerate() {
        if let Some(d) = declared.iter().find(|d| d.rasterizer == candidate.name()) {
            let stand_in: Box<dyn Rasterizer> = Box::new(Deferred {
                name: candidate.name().to_owned(),
                foil: candidate.is_foil(),
            });
            swapped.push((index, std::mem::replace(candidate, stand_in), d.fill_rule));
        }
    }
    let mut outcomes = runner::run_all(files, limits, candidates, root, threads, done);
    let work = |outcomes: &mut Vec<CaseOutcome>| {
        outcomes.par_iter_mut().for_each(|outcome| {
            let (Some(scene), true) = (&outcome.scene, outcome.reference.is_some()) else {
                return;
            };
            for (index, candidate, rule) in &swapped {
                let s = under_rule(scene, *rule);
                let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                    let reference = suite::run_reference(&s);
                    suite::run_candidate(&s, &reference, candidate.as_ref())
                }));
                let run = run.unwrap_or_else(|panic| suite::CandidateRun {
                    rasterizer: candidate.name().to_owned(),
                    verdict: Verdict::Error(format!(
                        "the reference under the declared {rule} rule panicked: {}",
                        suite::panic_message(&*panic)
                    )),
                    metrics: None,
                    frame: None,
                    elapsed: std::time::Duration::ZERO,
                });
                if let Some(slot) = outcome.candidates.get_mut(*index) {
                    *slot = run;
                }
            }
        })
    };
    match rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()
    {
        Ok(pool) => pool.install(|| work(&mut outcomes)),
        Err(_) => work(&mut outcomes),
    }
    for (index, candidate, _) in swapped {
        candidates[index] = candidate;
    }
    outcomes
}
