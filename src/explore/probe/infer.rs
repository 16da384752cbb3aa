//! What each probe decides from the frames it draws: the fill rule that
//! explains the tie samples, the y direction, the subpixel bits resolved
//! along an axis, the sample position, and the interpolation error. The
//! scenes are `scenes.rs`'s; sentences about the result are `describe.rs`'s.

use super::diagnosis::{Eighths, CENTRE};
use crate::frame::Frame;
use crate::harness::judge::Verdict;
use crate::harness::{judge, oracle, panics};
use crate::plan::Plan;
use crate::rasterizer::{RasterError, Rasterizer};
use crate::reference;
use crate::scene::{FillRule, Number, Scene};

use super::evidence::{
    ChannelProbe, InterpolationProbe, MeshEvidence, RuleCount, SlopeRule, PROBE_BITS, RULE_NAMES,
};
use super::scenes::{
    fill_rule_meshes, interpolation_scene, mesh_scene, precision_scenes, slope_words,
    tie_slope_meshes, tri, vertex_scenes, TIE_CENTRE,
};

/// Draws a scene, catching panics.
pub(super) fn draw(candidate: &dyn Rasterizer, scene: &Scene) -> Result<Frame, RasterError> {
    let plan = Plan::for_scene(scene);
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        candidate.rasterize(scene, &plan)
    }))
    .unwrap_or_else(|panic| {
        Err(RasterError::Failed(format!(
            "panicked: {}",
            panics::panic_message(&*panic)
        )))
    })
}

/// `scene` moved by (o − centre): a point sampler whose sample is at `o`
/// then draws pixel Q exactly where a centre sampler draws it in `scene`
/// (Q + o ∈ T + o − ½ ⇔ Q + ½ ∈ T), so the fill-rule and precision probes
/// read its frames against the reference's centre samples. The move is a
/// multiple of 1/8 px, on the grid of every rasterizer that keeps 3 bits
/// or more, so it does not change how vertices snap.
fn moved(scene: &Scene, o: Eighths) -> Scene {
    let t = [o.0 - CENTRE.0, o.1 - CENTRE.1].map(|e| Number::ratio(e, 8));
    let mut s = scene.clone();
    if t.iter().all(Number::is_zero) {
        return s;
    }
    for v in s.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
        v.x = Number::from_rbig(v.x.as_rbig() + t[0].as_rbig());
        v.y = Number::from_rbig(v.y.as_rbig() + t[1].as_rbig());
    }
    s
}

/// Draws `scene` moved for a sample at `o` ([`moved`]).
pub(super) fn draw_for(
    candidate: &dyn Rasterizer,
    scene: &Scene,
    o: Eighths,
) -> Result<Frame, RasterError> {
    draw(candidate, &moved(scene, o))
}

/// Runs the fill-rule meshes, then the tie meshes of every slope
/// (`scenes::tie_slope_meshes`), moved for a sample at `o`; returns the
/// evidence per mesh.
pub(super) fn probe_fill_rule(candidate: &dyn Rasterizer, o: Eighths) -> Vec<MeshEvidence> {
    let general = fill_rule_meshes()
        .into_iter()
        .map(|(label, s)| (label, None, s));
    let sloped = tie_slope_meshes()
        .into_iter()
        .map(|(label, slope, s)| (label, Some(slope), s));
    general
        .chain(sloped)
        .map(|(label, slope, s)| mesh_evidence(candidate, o, label, slope, &s))
        .collect()
}

/// Whether pixel `i`'s centre lies strictly inside the shared edge of the
/// tie mesh of `slope` (exactly: twice every coordinate is an integer).
fn on_shared_edge(i: usize, width: usize, (dy, dx): (i64, i64)) -> bool {
    let (x, y) = ((i % width) as i64, (i / width) as i64);
    let (cx, cy) = (x - TIE_CENTRE.0, y - TIE_CENTRE.1);
    let reach = 9 / dy.abs().max(dx.abs());
    let t = if dx != 0 { cx / dx } else { cy / dy };
    cx * dy == cy * dx && t.abs() < reach && (t * dx, t * dy) == (cx, cy)
}

/// One mesh drawn by the reference under every rule and by the candidate:
/// which rule explains its tie samples.
fn mesh_evidence(
    candidate: &dyn Rasterizer,
    o: Eighths,
    label: String,
    slope: Option<(i64, i64)>,
    s: &Scene,
) -> MeshEvidence {
    let plan = Plan::for_scene(s);
    let refs: Vec<Frame> = FillRule::ALL
        .iter()
        .map(|&r| reference::render(&s.with_fill_rule(r), &plan))
        .collect();
    let n = refs[0].sample_count();
    let width = refs[0].width as usize;
    let key = |f: &Frame, i: usize| (f.coverage[i], f.last[i]);
    let differ: Vec<usize> = (0..n)
        .filter(|&i| refs.iter().any(|f| key(f, i) != key(&refs[0], i)))
        .collect();
    // A tie mesh of one slope keeps only the samples on its shared edge.
    let ties: Vec<usize> = differ
        .iter()
        .copied()
        .filter(|&i| slope.is_none_or(|slope| on_shared_edge(i, width, slope)))
        .collect();
    let mut evidence = MeshEvidence {
        mesh: label,
        slope: slope.map(slope_words),
        tie_samples: ties.len(),
        explained: Vec::new(),
        off_edge_differences: 0,
        error: None,
    };
    let frame = match draw_for(candidate, s, o) {
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
        .filter(|i| !differ.contains(i) && key(&refs[0], *i) != key(&frame, *i))
        .count();
    evidence
}

/// The rule that explains the most tie samples over all meshes, and
/// whether it explains all of them. `None` when no mesh was drawn.
pub(super) fn nearest_rule(evidence: &[MeshEvidence]) -> Option<(String, bool)> {
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

/// What the tie probe found beyond the nearest rule: the slopes whose tie
/// samples `nearest` does not explain, each with the consistent rules
/// that explain all of them, when every slope follows one (then its ties
/// are inconsistent: a rule by slope, not one rule); and what that was
/// measured on, "N tie samples over M slopes (K meshes)".
pub(super) fn slope_findings(
    evidence: &[MeshEvidence],
    nearest: &str,
) -> (Option<Vec<SlopeRule>>, String) {
    let drawn: Vec<&MeshEvidence> = evidence.iter().filter(|e| e.error.is_none()).collect();
    let samples: usize = drawn.iter().map(|e| e.tie_samples).sum();
    let mut slopes: Vec<&str> = Vec::new();
    for e in &drawn {
        if let Some(s) = e.slope.as_deref().filter(|s| !slopes.contains(s)) {
            slopes.push(s);
        }
    }
    let measured_on = format!(
        "{samples} tie samples over {} slopes ({} meshes)",
        slopes.len(),
        drawn.len()
    );
    let k_nearest = RULE_NAMES.iter().position(|r| *r == nearest).unwrap_or(0);
    let mut disagree = Vec::new();
    for slope in &slopes {
        let meshes: Vec<&&MeshEvidence> = drawn
            .iter()
            .filter(|e| e.slope.as_deref() == Some(slope))
            .collect();
        let explains = |k: usize| {
            meshes
                .iter()
                .all(|e| e.explained[k].samples == e.tie_samples)
        };
        if explains(k_nearest) {
            continue;
        }
        // The four consistent rules only: a slope whose ties go to both
        // sides or neither follows no rule, and is no slope-dependent rule.
        let follows: Vec<String> = (0..FillRule::CONSISTENT.len())
            .filter(|&k| explains(k))
            .map(|k| RULE_NAMES[k].to_owned())
            .collect();
        if follows.is_empty() {
            return (None, measured_on);
        }
        disagree.push(SlopeRule {
            slope: (*slope).to_owned(),
            follows,
        });
    }
    (Some(disagree).filter(|d| !d.is_empty()), measured_on)
}

/// y direction: a triangle over the top half.
pub(super) fn probe_y(candidate: &dyn Rasterizer) -> Option<bool> {
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

/// Where a precision probe puts its sample along an edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Along {
    /// On the first sample row below the moving vertex: its grid
    /// (`scenes::vertex_scenes`).
    Vertex,
    /// Three rows down the edge from the fixed vertex: its grid and how
    /// the edge is stepped (`scenes::precision_scenes`).
    Edge,
}

/// Bits resolved along one axis, the scenes moved for a sample at `o`:
/// the largest k such that all three steps of every k' ≤ k change their
/// sample. `Err` when it could not draw.
pub(super) fn probe_axis(
    candidate: &dyn Rasterizer,
    along: Along,
    transpose: bool,
    o: Eighths,
) -> Result<u32, String> {
    let (before, after, steps) = match along {
        Along::Vertex => vertex_scenes(transpose),
        Along::Edge => precision_scenes(transpose),
    };
    let f0 = draw_for(candidate, &before, o).map_err(|e| e.to_string())?;
    let f1 = draw_for(candidate, &after, o).map_err(|e| e.to_string())?;
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

/// The sample position: what `probe_sample_position` found.
pub(super) struct Position {
    /// "centre", "(x, y) in the pixel", "(1, 1) of the pixel, outside it",
    /// "several: ..." or "none found ...".
    pub(super) words: String,
    /// The one offset found, in eighths of a pixel.
    pub(super) offset: Option<Eighths>,
}

/// Pixels between the canvas border and the grid of tiny triangles: a
/// sample up to this far outside its pixel (offsets from −2 to 3 px) still
/// lands on the canvas.
const POSITION_MARGIN: u32 = 2;

/// Sample position: tiny triangles (3/32 px) around (i/8, j/8) of pixel
/// (2i + 3, 2j + 3), i, j in 0..8. A point sampler draws the one whose
/// anchor A lies by its sample, in the pixel Q with Q + o ≈ A: the offset
/// o = A − Q is read to 1/8 whether or not it lies inside the pixel, since
/// the anchors' fractions cover every eighth and the margin keeps Q on the
/// canvas for o from −2 to 3 px (a sample at the bottom-right corner
/// (1, 1), or at (1.5, 0.5), draws the whole raster shifted).
pub(super) fn probe_sample_position(candidate: &dyn Rasterizer) -> Position {
    let d = 1.0 / 32.0;
    let mut triangles = Vec::new();
    let mut anchors = Vec::new();
    for j in 0..8u32 {
        for i in 0..8u32 {
            let (px, py) = (2 * i + 1 + POSITION_MARGIN, 2 * j + 1 + POSITION_MARGIN);
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
    let side = 16 + 2 * POSITION_MARGIN;
    let s = mesh_scene("probe_sample_position", side, side, 8, triangles);
    let frame = match draw(candidate, &s) {
        Ok(f) if f.samples == 1 && f.sample_count() == s.canvas.pixel_count() => f,
        Ok(_) => {
            return Position {
                words: "unknown: returned a frame of the wrong size".to_owned(),
                offset: None,
            }
        }
        Err(e) => {
            return Position {
                words: format!("unknown: {e}"),
                offset: None,
            }
        }
    };
    let mut offsets: Vec<Eighths> = Vec::new();
    for qy in 0..frame.height {
        for qx in 0..frame.width {
            let i = frame.index(qx, qy);
            let Some(&(x, y)) = anchors.get((frame.last[i] as usize).wrapping_sub(1)) else {
                continue;
            };
            if frame.coverage[i] == 0 {
                continue;
            }
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
    let eighths = |(x, y): Eighths| format!("({}, {})", x as f64 / 8.0, y as f64 / 8.0);
    let inside = |v: i64| (0..8).contains(&v);
    let words = match offsets.as_slice() {
        [] => {
            "none found (no triangle of 3/32 px around an offset (i/8, j/8) was drawn)".to_owned()
        }
        [CENTRE] => "centre".to_owned(),
        [o] if inside(o.0) && inside(o.1) => format!("{} in the pixel", eighths(*o)),
        [o] => format!(
            "{} of the pixel, outside it (the raster is shifted by {} px)",
            eighths(*o),
            eighths((o.0 - CENTRE.0, o.1 - CENTRE.1))
        ),
        many => format!(
            "several: {}",
            many.iter()
                .map(|o| eighths(*o))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    Position {
        words,
        offset: (offsets.len() == 1).then(|| offsets[0]),
    }
}

pub(super) fn probe_interpolation(candidate: &dyn Rasterizer) -> Vec<InterpolationProbe> {
    [
        interpolation_scene("linear", "linear", ["1", "1", "1"]),
        interpolation_scene("perspective", "perspective", ["0.1", "1", "10"]),
    ]
    .iter()
    .map(|s| {
        let reference = oracle::run_reference(s);
        let run = judge::run_candidate(s, &reference, candidate);
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
