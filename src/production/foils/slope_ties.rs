//! `foil-slope-ties`: production with a tie rule that depends on each
//! edge's slope, as a real 2D library's does (issue 40): a sample exactly
//! on an edge goes bottom-right on most slopes, and top-left on edges of
//! slope 3, 3/2, −3, −1/3 and −2/3 (dy/dx, y down). **A foil**, wrong in
//! that one way: off the ties it is production, and at each tie it is
//! production under one consistent rule or the other. So it has no tie
//! rule a case can state: declared `none` (SPEC.md §3.1.1) it passes every
//! case it draws, with its ties counted apart; declared `bottom-right` it
//! fails where an edge of those slopes holds a sample; and `probe` must
//! call it inconsistent and name the slopes.
//!
//! It draws the scene twice with production, under `bottom-right` and
//! `top-left`; where the two disagree the sample lies on an edge, and it
//! takes the top-left answer when an edge through the sample has one of
//! those slopes. The edges are the snapped vertices' own, tested in exact
//! rationals (a foil may; production's fast path does not).

use dashu_ratio::RBig;

use super::declare::foil;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::dispatch::Production;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{FillRule, Number, Primitive, Scene};

foil!(
    /// Ties by slope: bottom-right, but top-left on five slopes.
    SlopeTies,
    "foil-slope-ties",
    rasterize
);

/// The slopes dy/dx (y down) whose ties go top-left, as (dy, dx); every
/// other edge's go bottom-right, horizontal and vertical ones included.
pub const TOP_LEFT_SLOPES: [(i64, i64); 5] = [(3, 1), (3, 2), (-3, 1), (-1, 3), (-2, 3)];

/// An edge of a snapped triangle: its two ends, exactly.
struct Edge {
    a: [RBig; 2],
    b: [RBig; 2],
}

impl Edge {
    /// Whether the point lies on the segment, exactly.
    fn holds(&self, p: &[RBig; 2]) -> bool {
        let d = [&self.b[0] - &self.a[0], &self.b[1] - &self.a[1]];
        let q = [&p[0] - &self.a[0], &p[1] - &self.a[1]];
        let cross = &d[0] * &q[1] - &d[1] * &q[0];
        let within = |k: usize| {
            let (lo, hi) = match self.a[k] <= self.b[k] {
                true => (&self.a[k], &self.b[k]),
                false => (&self.b[k], &self.a[k]),
            };
            lo <= &p[k] && &p[k] <= hi
        };
        cross == RBig::ZERO && within(0) && within(1)
    }

    /// Whether its ties go top-left.
    fn top_left(&self) -> bool {
        let dx = &self.b[0] - &self.a[0];
        if dx == RBig::ZERO {
            return false;
        }
        let slope = (&self.b[1] - &self.a[1]) / dx;
        TOP_LEFT_SLOPES
            .iter()
            .any(|&(dy, dx)| slope == RBig::from(dy) / RBig::from(dx))
    }
}

/// The edges of the scene's triangles, their vertices snapped as the case
/// states.
fn edges(scene: &Scene) -> Vec<Edge> {
    let bits = scene.rules.subpixel_bits;
    let exact = |n: &Number| {
        bits.map_or_else(|| n.clone(), |b| n.snapped(b))
            .as_rbig()
            .clone()
    };
    let mut out = Vec::new();
    for p in &scene.primitives {
        let Primitive::Triangle(t) = p else { continue };
        let v: Vec<[RBig; 2]> = t
            .vertices
            .iter()
            .map(|v| [exact(&v.x), exact(&v.y)])
            .collect();
        for k in 0..3 {
            out.push(Edge {
                a: v[k].clone(),
                b: v[(k + 1) % 3].clone(),
            });
        }
    }
    out
}

fn rasterize(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    let mut frame = Production.rasterize(&scene.with_fill_rule(FillRule::BottomRight), plan)?;
    let top_left = Production.rasterize(&scene.with_fill_rule(FillRule::TopLeft), plan)?;
    let edges = edges(scene);
    let half = RBig::from(1) / RBig::from(2);
    // One sample per pixel, at its centre: the foil takes no antialiasing.
    for i in 0..frame.sample_count().min(top_left.sample_count()) {
        if (frame.coverage[i], frame.last[i]) == (top_left.coverage[i], top_left.last[i]) {
            continue;
        }
        let (x, y) = (i % frame.width as usize, i / frame.width as usize);
        let centre = [RBig::from(x) + &half, RBig::from(y) + &half];
        if !edges.iter().any(|e| e.top_left() && e.holds(&centre)) {
            continue;
        }
        frame.coverage[i] = top_left.coverage[i];
        frame.last[i] = top_left.last[i];
        if let (Some(d), Some(t)) = (frame.depth.as_mut(), top_left.depth.as_ref()) {
            d[i] = t[i];
        }
        for (a, t) in frame.attributes.iter_mut().zip(&top_left.attributes) {
            a[i] = t[i];
        }
    }
    Ok(frame)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn edge(a: (i64, i64), b: (i64, i64)) -> Edge {
        Edge {
            a: [RBig::from(a.0), RBig::from(a.1)],
            b: [RBig::from(b.0), RBig::from(b.1)],
        }
    }

    #[test]
    fn five_slopes_go_top_left_and_the_rest_bottom_right() {
        for ((ax, ay), (bx, by), top_left) in [
            ((0, 0), (1, 3), true),
            ((0, 0), (2, 3), true),
            ((1, 0), (0, 3), true),
            ((0, 0), (-3, 1), true),
            ((0, 0), (3, -2), true),
            ((0, 0), (3, 1), false),
            ((0, 0), (1, 1), false),
            ((0, 0), (0, 4), false),
            ((0, 0), (4, 0), false),
            ((0, 0), (1, 2), false),
        ] {
            assert_eq!(edge((ax, ay), (bx, by)).top_left(), top_left, "{bx} {by}");
        }
        let e = edge((0, 0), (2, 6));
        let on = [RBig::from(1), RBig::from(3)];
        let past = [RBig::from(3), RBig::from(9)];
        assert!(e.holds(&on) && !e.holds(&past));
    }
}
