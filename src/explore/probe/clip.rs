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

use super::convention::{conclude, differing, Convention, ConventionProbe};
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

/// What the clipping probe found: `clip_xy` and `clip_z` in the profile.
pub type ClipProbe = ConventionProbe<ClipRules>;

impl Convention for ClipRules {
    const FIELDS: [&'static str; 2] = ["clip_xy", "clip_z"];
    const SCENES: &'static str = "clipping";
    fn names(self) -> [&'static str; 2] {
        [self.xy.name(), self.z.name()]
    }
}

impl ClipProbe {
    /// Its own `clip_xy`, when fixed.
    pub fn clip_xy(&self) -> Option<&'static str> {
        self.own.map(|[xy, _]| xy)
    }

    /// Its own `clip_z`, when fixed.
    pub fn clip_z(&self) -> Option<&'static str> {
        self.own.map(|[_, z]| z)
    }
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
    Some(conclude(&all, mismatches, drawn > 0, scenes.len()))
}
