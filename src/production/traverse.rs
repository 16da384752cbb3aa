//! Traversal: bounding box in 8×8 blocks, whole blocks accepted or rejected
//! from their corners, partial blocks walked pixel by pixel with
//! incremental edge functions (Pineda, "A Parallel Algorithm for Polygon
//! Rasterization", SIGGRAPH 1988).

use super::fixed::EdgeInt;
use super::setup::TriangleSetup;

/// Receives covered pixels as horizontal runs, like tiny-skia's `Blitter`.
pub trait Sink {
    /// Pixels `x0..x1` of row `y` are covered.
    fn span(&mut self, y: i64, x0: i64, x1: i64);
}

/// Side of a square block, in pixels.
pub const BLOCK: i64 = 8;

pub fn traverse<E: EdgeInt, S: Sink>(setup: &TriangleSetup<E>, sink: &mut S) {
    let bounds = setup.bounds;
    let zero = E::default();
    let mut by = bounds.y0;
    while by < bounds.y1 {
        let bh = BLOCK.min(bounds.y1 - by);
        let mut bx = bounds.x0;
        while bx < bounds.x1 {
            let bw = BLOCK.min(bounds.x1 - bx);
            // Edge functions are linear, so over a block they are extreme at
            // its corners.
            let mut all_inside = true;
            let mut all_outside = false;
            for e in &setup.edges {
                let corner = e.at(bx, by);
                let across = e.step_x * E::from(bw - 1);
                let down = e.step_y * E::from(bh - 1);
                let high = corner + across.max(zero) + down.max(zero);
                let low = corner + across.min(zero) + down.min(zero);
                if high < zero {
                    all_outside = true;
                    break;
                }
                all_inside &= low >= zero;
            }
            if all_inside && !all_outside {
                for y in by..by + bh {
                    sink.span(y, bx, bx + bw);
                }
            } else if !all_outside {
                walk_block(setup, bx, by, bw, bh, sink);
            }
            bx += BLOCK;
        }
        by += BLOCK;
    }
}

fn walk_block<E: EdgeInt, S: Sink>(
    setup: &TriangleSetup<E>,
    bx: i64,
    by: i64,
    bw: i64,
    bh: i64,
    sink: &mut S,
) {
    let [e0, e1, e2] = &setup.edges;
    let mut row = [e0.at(bx, by), e1.at(bx, by), e2.at(bx, by)];
    let zero = E::default();
    for y in by..by + bh {
        let mut v = row;
        let mut run: Option<i64> = None;
        for x in bx..bx + bw {
            // Inside every edge exactly when no value has its sign bit set.
            if (v[0] | v[1] | v[2]) >= zero {
                run.get_or_insert(x);
            } else if let Some(start) = run.take() {
                sink.span(y, start, x);
            }
            v = [v[0] + e0.step_x, v[1] + e1.step_x, v[2] + e2.step_x];
        }
        if let Some(start) = run {
            sink.span(y, start, bx + bw);
        }
        row = [row[0] + e0.step_y, row[1] + e1.step_y, row[2] + e2.step_y];
    }
}
