//! What a rasterizer does with clip-space points at the clip volume's
//! sides (SPEC.md §17.2): whether a point whose centre leaves the side
//! planes is discarded (`clip_points: pop`) or drawn (`guard-band`), and
//! whether a kept square is cut at the viewport rectangle (`point_bounds:
//! viewport`) or only at the canvas. Five points around a 16×16 viewport
//! inside a 24×24 canvas, each with its square crossing a side of the
//! viewport, separate the four combinations; each is stated once under the
//! defaults (pop, canvas) and once under the opposite (guard-band,
//! viewport), drawn by the candidate, and compared sample by sample
//! (count and owner) with the reference under each combination, as the
//! clipping probe does for triangles (`clip.rs`).

use super::convention::{conclude, differing, Convention, ConventionProbe};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::Rasterizer;
use crate::reference;
use crate::scene::{parse_case, FillRule, Limits, PointBounds, PointClip, Scene};

/// What the point probe found: `clip_points` and `point_bounds` in the
/// profile.
pub type PointProbe = ConventionProbe<(PointClip, PointBounds)>;

impl Convention for (PointClip, PointBounds) {
    const FIELDS: [&'static str; 2] = ["clip_points", "point_bounds"];
    const SCENES: &'static str = "point";
    fn names(self) -> [&'static str; 2] {
        [self.0.name(), self.1.name()]
    }
}

impl PointProbe {
    /// Its own `clip_points`, when fixed.
    pub fn clip_points(&self) -> Option<&'static str> {
        self.own.map(|[points, _]| points)
    }

    /// Its own `point_bounds`, when fixed.
    pub fn point_bounds(&self) -> Option<&'static str> {
        self.own.map(|[_, bounds]| bounds)
    }
}

/// The four combinations of `clip_points` and `point_bounds`.
fn combinations() -> [(PointClip, PointBounds); 4] {
    [
        (PointClip::Pop, PointBounds::Canvas),
        (PointClip::Pop, PointBounds::Viewport),
        (PointClip::GuardBand, PointBounds::Canvas),
        (PointClip::GuardBand, PointBounds::Viewport),
    ]
}

/// The probe's points, as clip coordinates (x, y, w) and sizes: with
/// w = 2 the viewport (4, 4) 16×16 puts x/w = ±1 on x_f = 20 and 4. Two
/// centres outside a side plane (the square reaching back across it), two
/// inside near a side (the square reaching out), one outside the bottom.
const POINTS: [(&str, &str, &str, &str); 5] = [
    ("2.25", "0", "2", "4"),
    ("1.75", "0", "2", "6"),
    ("0", "-2.25", "2", "4"),
    ("-1.75", "0.5", "2", "6"),
    ("0", "2.5", "2", "6"),
];

/// One probe scene of point `i` under `rule`, stating `clip`.
fn scene(i: usize, rule: FillRule, (points, bounds): (PointClip, PointBounds)) -> Scene {
    let (x, y, w, size) = POINTS[i];
    let text = format!(
        r#"{{"name": "probe_point_{i}", "canvas": {{"width": 24, "height": 24}},
            "viewport": {{"x": 4, "y": 4, "width": 16, "height": 16}},
            "rules": {{"subpixel_bits": 8, "fill_rule": "{}", "clip_points": "{}",
                       "point_bounds": "{}"}},
            "primitives": [{{"point": {{"clip": ["{x}", "{y}", "1", "{w}"]}}, "size": "{size}"}}]}}"#,
        rule.name(),
        points.name(),
        bounds.name()
    );
    parse_case(&text, "probe_point.json", &Limits::default()).expect("a valid probe scene")
}

/// Probes a rasterizer that draws clip-space points; `None` for one that
/// does not.
pub fn probe_points(candidate: &dyn Rasterizer) -> Option<PointProbe> {
    let capabilities = candidate.capabilities();
    if !capabilities.clip_space || !capabilities.points {
        return None;
    }
    let rule = candidate.fixed_fill_rule().unwrap_or(FillRule::TopLeft);
    let all = combinations();
    // The defaults, and their opposite (combinations 0 and 3).
    let statements = [all[0], all[3]];
    let mut mismatches = vec![vec![0usize; all.len()]; statements.len()];
    let mut scenes = 0;
    for i in 0..POINTS.len() {
        let frames: Vec<Frame> = all
            .iter()
            .map(|&c| reference::render(&scene(i, rule, c), &Plan::coverage_only()))
            .collect();
        let drawn: Vec<Frame> = statements
            .iter()
            .filter_map(|&stated| {
                let s = scene(i, rule, stated);
                candidate
                    .rasterize(&s, &Plan::for_scene(&s))
                    .ok()
                    .filter(|f| f.coverage.len() == frames[0].coverage.len())
            })
            .collect();
        if drawn.len() != statements.len() {
            continue;
        }
        scenes += 1;
        for (k, frame) in drawn.iter().enumerate() {
            for (c, reference) in frames.iter().enumerate() {
                mismatches[k][c] += differing(frame, reference);
            }
        }
    }
    Some(conclude(&all, mismatches, scenes > 0, scenes))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every probe point separates the four combinations from each other
    /// in at least one pair, and together they separate every pair.
    #[test]
    fn the_points_separate_every_combination() {
        let all = combinations();
        let mut separated = [[false; 4]; 4];
        for i in 0..POINTS.len() {
            let frames: Vec<Frame> = all
                .iter()
                .map(|&c| {
                    reference::render(&scene(i, FillRule::TopLeft, c), &Plan::coverage_only())
                })
                .collect();
            for (a, row) in separated.iter_mut().enumerate() {
                for (b, cell) in row.iter_mut().enumerate() {
                    *cell |= differing(&frames[a], &frames[b]) > 0;
                }
            }
        }
        for (a, row) in separated.iter().enumerate() {
            for (b, &cell) in row.iter().enumerate() {
                assert_eq!(cell, a != b, "{a} {b}");
            }
        }
    }
}
