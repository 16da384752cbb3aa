//! Outline over fill, told apart from any-coverage. Both draw the four
//! slivers of `sampler.rs` (a hairline stroked along a sliver's edge lies
//! in its pixel), so the sampler decision asks once more, on one triangle
//! whose edges are long and shallow (slopes about 1/9, −3/4 and −4): which
//! of the pixels the triangle touches (its interior meets the open pixel,
//! found exactly here) but whose centre it does not cover are drawn?
//!
//! - **Any-coverage** (conservative) draws every one of them.
//! - **Outline over fill** draws every pixel the reference's point fill
//!   draws, and some touched pixels beside it, but not all: a one-pixel
//!   hairline lights one pixel per column (or row) along a shallow edge,
//!   and the edge grazes a second pixel in many columns, which stays
//!   undrawn however much of it the triangle covers.
//!
//! Anything else is `unknown`, with the counts.

use super::diagnosis::{Sampler, SamplerKind};
use super::infer::draw;
use super::scenes::{mesh_scene, tri};
use crate::plan::Plan;
use crate::rasterizer::Rasterizer;
use crate::reference;
use crate::scene::Scene;

/// The triangle's vertices: multiples of 1/8 px, on a 32 × 16 canvas.
const TRIANGLE: [(f64, f64); 3] = [(1.25, 2.125), (29.75, 5.375), (4.625, 13.875)];
const SIDE: (u32, u32) = (32, 16);

fn scene() -> Scene {
    mesh_scene("probe_outline", SIDE.0, SIDE.1, 8, vec![tri(TRIANGLE)])
}

/// Twice the signed area of (a, b, c), in units of 1/8 px squared.
fn cross(a: (i64, i64), b: (i64, i64), c: (i64, i64)) -> i64 {
    (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
}

/// The pixels the triangle's interior meets (an area in common with the
/// open square), exactly: convex shapes are disjoint exactly when a box
/// axis or a triangle edge separates them.
fn touched() -> Vec<bool> {
    let mut p = TRIANGLE.map(|(x, y)| ((x * 8.0) as i64, (y * 8.0) as i64));
    if cross(p[0], p[1], p[2]) < 0 {
        p.swap(1, 2);
    }
    let (w, h) = SIDE;
    let mut out = vec![false; (w * h) as usize];
    for y in 0..i64::from(h) {
        for x in 0..i64::from(w) {
            let corners = [(0, 0), (8, 0), (0, 8), (8, 8)].map(|(dx, dy)| (x * 8 + dx, y * 8 + dy));
            let boxes = p.iter().any(|q| q.0 > x * 8) // some vertex right of the left side
                && p.iter().any(|q| q.0 < x * 8 + 8)
                && p.iter().any(|q| q.1 > y * 8)
                && p.iter().any(|q| q.1 < y * 8 + 8);
            let edges = (0..3).all(|e| corners.iter().any(|&c| cross(p[e], p[(e + 1) % 3], c) > 0));
            out[(y * i64::from(w) + x) as usize] = boxes && edges;
        }
    }
    out
}

/// After the slivers said "all four drawn": any-coverage, outline over
/// fill, or unknown. `sliver_words` is what the slivers showed.
pub(super) fn decide(candidate: &dyn Rasterizer, sliver_words: &str) -> Sampler {
    let s = scene();
    let unknown = |why: String| Sampler {
        kind: SamplerKind::Unknown,
        evidence: format!("{sliver_words}; {why}"),
    };
    let frame = match draw(candidate, &s) {
        Ok(f) if f.samples == 1 && f.sample_count() == s.canvas.pixel_count() => f,
        Ok(_) => return unknown("its frame of one triangle has the wrong size".to_owned()),
        Err(e) => return unknown(format!("it could not draw one triangle: {e}")),
    };
    let fill: Vec<bool> = reference::render(&s, &Plan::for_scene(&s))
        .coverage
        .iter()
        .map(|&c| c > 0)
        .collect();
    let touch = touched();
    let drawn: Vec<bool> = frame.coverage.iter().map(|&c| c > 0).collect();
    let count = |f: &dyn Fn(usize) -> bool| (0..drawn.len()).filter(|&i| f(i)).count();
    let edge_only = count(&|i| touch[i] && !fill[i]);
    let edge_drawn = count(&|i| touch[i] && !fill[i] && drawn[i]);
    let fill_missed = count(&|i| fill[i] && !drawn[i]);
    let beyond = count(&|i| drawn[i] && !touch[i]);
    let on = format!(
        "of one triangle with shallow edges (32 × 16), whose interior touches {edge_only} pixels besides the {} whose centre it covers",
        count(&|i| fill[i])
    );
    if edge_drawn == edge_only && beyond == 0 {
        return Sampler {
            kind: SamplerKind::AnyCoverage,
            evidence: format!("{sliver_words}, and {on}, it draws every one"),
        };
    }
    if fill_missed == 0 && beyond == 0 && 0 < edge_drawn && edge_drawn < edge_only {
        return Sampler {
            kind: SamplerKind::OutlineOverFill,
            evidence: format!(
                "{sliver_words}, yet {on}, it draws every pixel whose centre is covered and {edge_drawn} of the touched ones, leaving {} undrawn: a point-sampled fill with its edges stroked over it, not any-coverage",
                edge_only - edge_drawn
            ),
        };
    }
    unknown(format!(
        "{on}, it draws {edge_drawn} of the touched ones, misses {fill_missed} whose centre is covered and draws {beyond} the triangle does not touch"
    ))
}
