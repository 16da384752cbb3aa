//! `foil-coarse-edges`: a scanline rasterizer that keeps vertices at 8
//! subpixel bits (1/256 px) but walks slanted edges coarsely: each edge's
//! x is found exactly on its first sample row, then stepped row by row by
//! its slope truncated to 1/16 px per row (a DDA whose increment keeps 4
//! fraction bits). **A foil**, wrong in that one way: a real 2D library
//! that walks edges in coarse fixed point while storing fine vertices
//! (issue 40) was said by probe to "snap vertices to 6 subpixel bits".
//!
//! Axis-aligned edges step by 0 and so lie exactly where their vertices
//! do: they show the 8-bit vertex grid; slanted edges drift from their
//! line by up to (rows walked) × 1/16 px and resolve fewer bits. Ties go
//! top-left (a sample row from a triangle's top included, its bottom not;
//! a span's left end included, its right end not). Triangles,
//! single-sample, coverage only, under `top-left`.

use dashu_int::IBig;
use dashu_ratio::RBig;

use super::declare::coverage_foil;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{FillRule, Number, Primitive, Scene};

coverage_foil!(
    /// The coarse edge walker.
    CoarseEdges,
    "foil-coarse-edges",
    walk_coarsely
);

/// The vertex grid: 8 subpixel bits, or the case's when it states fewer.
pub const VERTEX_BITS: u32 = 8;

/// Fraction bits of an edge's per-row increment.
pub const STEP_BITS: u32 = 4;

/// Each triangle walked row by row, its edges stepped coarsely.
fn walk_coarsely(scene: &Scene, _plan: &Plan) -> Result<Frame, RasterError> {
    let unsupported = |why: &str| Err(RasterError::Unsupported(why.to_owned()));
    if scene.rules.fill_rule != FillRule::TopLeft {
        return unsupported("foil-coarse-edges draws the top-left rule only");
    }
    let bits = scene
        .rules
        .subpixel_bits
        .map_or(VERTEX_BITS, |b| b.min(VERTEX_BITS));
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let mut frame = Frame::new(w, h, false, 0);
    for (index, primitive) in scene.primitives.iter().enumerate() {
        let Primitive::Triangle(t) = primitive else {
            return unsupported("foil-coarse-edges draws triangles only");
        };
        let snap = |n: &Number| n.snapped(bits).as_rbig().clone();
        let p: Vec<[RBig; 2]> = t
            .vertices
            .iter()
            .map(|v| [snap(&v.x), snap(&v.y)])
            .collect();
        let cross = (&p[1][0] - &p[0][0]) * (&p[2][1] - &p[0][1])
            - (&p[1][1] - &p[0][1]) * (&p[2][0] - &p[0][0]);
        if cross == RBig::ZERO || scene.rules.cull.discards(cross.cmp(&RBig::ZERO)) {
            continue;
        }
        let edges: Vec<Walk> = (0..3)
            .filter_map(|k| Walk::new(&p[k], &p[(k + 1) % 3]))
            .collect();
        let rows = |e: &Walk| e.first..e.end;
        let top = edges.iter().map(|e| e.first).min().unwrap_or(0).max(0);
        let bottom = edges
            .iter()
            .map(|e| e.end)
            .max()
            .unwrap_or(0)
            .min(i64::from(h));
        for r in top..bottom {
            let xs: Vec<RBig> = edges
                .iter()
                .filter(|e| rows(e).contains(&r))
                .map(|e| e.x_at(r))
                .collect();
            let [a, b] = xs.as_slice() else { continue };
            let (left, right) = if a <= b { (a, b) } else { (b, a) };
            // Sample x = c + ½ with left ≤ x < right.
            let first = centre_index(left).max(0);
            let end = centre_index(right).min(i64::from(w));
            for c in first..end {
                let i = frame.index(c as u32, r as u32);
                frame.coverage[i] = frame.coverage[i].saturating_add(1);
                frame.last[i] = index as u32 + 1;
            }
        }
    }
    Ok(frame)
}

/// The first pixel index c whose centre c + ½ is at or right of `x`
/// (⌈x − ½⌉), clamped to what a canvas can hold.
fn centre_index(x: &RBig) -> i64 {
    let c: IBig = (x - RBig::from(1) / RBig::from(2)).ceil();
    i64::try_from(c.clamp(IBig::from(-(1i64 << 40)), IBig::from(1i64 << 40))).expect("clamped")
}

/// A slanted or vertical edge walked down its sample rows.
struct Walk {
    /// Its sample rows, `first..end` (centres y + ½ in [top, bottom)).
    first: i64,
    end: i64,
    /// Its x on row `first`, exactly.
    x0: RBig,
    /// Its slope (px per row) truncated to 2^-STEP_BITS.
    step: RBig,
}

impl Walk {
    /// `None` for a horizontal edge (its rows are its neighbours').
    fn new(a: &[RBig; 2], b: &[RBig; 2]) -> Option<Walk> {
        let (top, bottom) = match a[1].cmp(&b[1]) {
            std::cmp::Ordering::Equal => return None,
            std::cmp::Ordering::Less => (a, b),
            std::cmp::Ordering::Greater => (b, a),
        };
        let first = centre_index(&top[1]);
        let end = centre_index(&bottom[1]);
        let slope = (&bottom[0] - &top[0]) / (&bottom[1] - &top[1]);
        let y0 = RBig::from(first) + RBig::from(1) / RBig::from(2);
        let x0 = &top[0] + (&y0 - &top[1]) * &slope;
        let scale = RBig::from(1i64 << STEP_BITS);
        let step = RBig::from((&slope * &scale).floor()) / scale;
        Some(Walk {
            first,
            end,
            x0,
            step,
        })
    }

    fn x_at(&self, r: i64) -> RBig {
        &self.x0 + RBig::from(r - self.first) * &self.step
    }
}
