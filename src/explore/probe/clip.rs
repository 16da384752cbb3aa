//! Which clipping a rasterizer follows (SPEC.md §16.9): clip-space scenes
//! from the fuzzer's clip family that the conventions draw differently,
//! stated once under the default conventions (guard band, near and far
//! clipped then snapped) and once under the opposite ones, each drawn by
//! the candidate and compared, sample by sample (count and owner), with the
//! reference under each of the four combinations of `clip_xy` and
//! `clip_z`. A rasterizer that follows each case matches what each
//! statement says; one with fixed clipping matches the same combination
//! under both; anything else is named by its nearest combination and
//! reported inconsistent.

use serde::Serialize;

use crate::explore::fuzz::{generate, Family};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::Rasterizer;
use crate::reference;
use crate::scene::{
    ClipRules, ClipXy, ClipZ, DepthMode, FillRule, InterpolateFrom, PointBounds, PointClip, Scene,
};

/// How many separating scenes the probe draws, and how many it looks
/// through to find them.
const SCENES: usize = 24;
const TRIED: u64 = 3000;
const SEED: u64 = 0xC11F_5EED;

/// What the clipping probe found.
#[derive(Clone, Debug, Serialize)]
pub struct ClipProbe {
    /// "follows each case's", "clip_xy guard-band, clip_z per-sample"
    /// (fixed), or the nearest combination and why it is not certain.
    pub finding: String,
    /// Whether it follows each case's clip conventions.
    pub follows_case: bool,
    /// Its own `clip_xy` and `clip_z`, when they are fixed.
    pub clip_xy: Option<&'static str>,
    pub clip_z: Option<&'static str>,
    /// Whether one answer explains every sample of every scene.
    pub consistent: bool,
    /// Samples that differ from the reference under each combination,
    /// per statement: `[stated][combination]`, combinations in the order
    /// of [`combinations`].
    pub mismatches: Vec<Vec<usize>>,
    pub scenes: usize,
}

/// The four combinations of `clip_xy` and `clip_z`, under depth clip.
fn combinations() -> [ClipRules; 4] {
    let c = |xy, z| ClipRules {
        xy,
        z,
        depth: DepthMode::Clip,
        values: InterpolateFrom::Snapped,
        points: PointClip::Pop,
        bounds: PointBounds::Canvas,
    };
    [
        c(ClipXy::GuardBand, ClipZ::ClipThenSnap),
        c(ClipXy::GuardBand, ClipZ::PerSample),
        c(ClipXy::ClipThenSnap, ClipZ::ClipThenSnap),
        c(ClipXy::ClipThenSnap, ClipZ::PerSample),
    ]
}

fn describe(c: &ClipRules) -> String {
    format!("clip_xy {}, clip_z {}", c.xy.name(), c.z.name())
}

/// Samples whose coverage count or owner differ.
fn differing(a: &Frame, b: &Frame) -> usize {
    (0..a.coverage.len())
        .filter(|&i| a.coverage[i] != b.coverage[i] || a.last[i] != b.last[i])
        .count()
}

fn draw_reference(scene: &Scene) -> Frame {
    reference::render(scene, &Plan::coverage_only())
}

/// Clip-space scenes at 8 subpixel bits (a driver's grid) under `rule`
/// that at least two combinations draw differently, with the reference's
/// frame under each combination.
fn separating_scenes(rule: FillRule) -> Vec<(Scene, Vec<Frame>)> {
    let mut found = Vec::new();
    for index in 0..TRIED {
        if found.len() == SCENES {
            break;
        }
        let (_, mut scene) = generate(SEED, index, Some(Family::Clip));
        scene.rules.subpixel_bits = Some(8);
        scene.rules.fill_rule = rule;
        scene.rules.cull = crate::scene::Cull::None;
        scene.rules.clip.depth = DepthMode::Clip;
        scene.expect = Default::default();
        let frames: Vec<Frame> = combinations()
            .iter()
            .map(|&clip| {
                let mut s = scene.clone();
                s.rules.clip = clip;
                draw_reference(&s)
            })
            .collect();
        if frames.iter().any(|f| differing(f, &frames[0]) > 0) {
            found.push((scene, frames));
        }
    }
    found
}

/// Probes a rasterizer that takes clip space; `None` for one that does
/// not.
pub fn probe_clip(candidate: &dyn Rasterizer) -> Option<ClipProbe> {
    if !candidate.capabilities().clip_space {
        return None;
    }
    let rule = candidate.fixed_fill_rule().unwrap_or(FillRule::TopLeft);
    let scenes = separating_scenes(rule);
    let all = combinations();
    // The default conventions, and their opposite (combinations 0 and 3).
    let statements = [all[0], all[3]];
    let mut mismatches = vec![vec![0usize; all.len()]; statements.len()];
    let mut drawn = 0;
    for (scene, frames) in &scenes {
        for (k, stated) in statements.iter().enumerate() {
            let mut s = scene.clone();
            s.rules.clip = *stated;
            let Ok(frame) = candidate.rasterize(&s, &Plan::for_scene(&s)) else {
                continue;
            };
            if frame.coverage.len() != frames[0].coverage.len() {
                continue;
            }
            drawn += 1;
            for (c, reference) in frames.iter().enumerate() {
                mismatches[k][c] += differing(&frame, reference);
            }
        }
    }
    if drawn == 0 {
        return Some(ClipProbe {
            finding: "unknown: it drew none of the clipping scenes".to_owned(),
            follows_case: false,
            clip_xy: None,
            clip_z: None,
            consistent: false,
            mismatches,
            scenes: scenes.len(),
        });
    }
    let super::verdict::Verdict {
        follows,
        fixed,
        best,
        nearest,
    } = super::verdict::verdict(&mismatches, [0, 3]);
    let (finding, own) = if follows {
        ("follows each case's clip_xy and clip_z".to_owned(), None)
    } else if fixed {
        (
            format!("its own: {}", describe(&all[best])),
            Some(all[best]),
        )
    } else {
        (
            format!(
                "nearest {} ({} samples differ over {} scenes stated twice); inconsistent",
                describe(&all[nearest]),
                mismatches[0][nearest] + mismatches[1][nearest],
                scenes.len()
            ),
            Some(all[nearest]),
        )
    };
    Some(ClipProbe {
        finding,
        follows_case: follows,
        clip_xy: own.map(|c| c.xy.name()),
        clip_z: own.map(|c| c.z.name()),
        consistent: follows || fixed,
        mismatches,
        scenes: scenes.len(),
    })
}
