//! A clip-space point (SPEC.md §17.2): kept or discarded by its centre,
//! then drawn as production's points are (`../point.rs`), its centre and
//! spans exact from the clip path's projection.

use dashu_ratio::RBig;

use super::clipper::ClipVertex;
use super::project::Mapping;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::point::{attributes, exact_span, fill, Ends, Values};
use crate::scene::{DepthMode, Number, Point, PointBounds, PointClip, Scene};

/// Draws a clip-space point (SPEC.md §17.2): discarded whole when w ≤ 0,
/// when depth clips and its centre's z is outside [0, w], or under
/// `clip_points: pop` when its centre is outside −w ≤ x, y ≤ w; otherwise
/// its whole square within the canvas, and within the viewport rectangle
/// under `point_bounds: viewport`.
pub(crate) fn draw_clip(
    point: &Point,
    scene: &Scene,
    mapping: &Mapping,
    plan: &Plan,
    index: usize,
    frame: &mut Frame,
) {
    let (clip, rule, canvas) = (scene.rules.clip, scene.rules.fill_rule, scene.canvas);
    let vertex = &point.vertices[0];
    let [x, y, z, w] = [&vertex.x, &vertex.y, &vertex.z, &vertex.w].map(Number::as_rbig);
    if *w <= RBig::ZERO {
        return;
    }
    if clip.depth == DepthMode::Clip && (*z < RBig::ZERO || z > w) {
        return;
    }
    let inside = |c: &RBig| -w <= *c && c <= w;
    if clip.points == PointClip::Pop && !(inside(x) && inside(y)) {
        return;
    }
    let projected = mapping.project(&ClipVertex::of(vertex));
    let half = point.size.as_rbig() / RBig::from(2u8);
    let mut columns = exact_span(&projected.h[0], &half, Ends::of(rule, 0), canvas.width);
    let mut rows = exact_span(&projected.h[1], &half, Ends::of(rule, 1), canvas.height);
    if clip.bounds == PointBounds::Viewport {
        // The viewport rectangle (the mapping's) as a span of its own:
        // centre o + e/2, half e/2, left and top closed, right and bottom
        // open.
        let two = RBig::from(2u8);
        let bound = |origin: &RBig, extent: &RBig, side| {
            let half = extent / &two;
            let ends = Ends {
                low: true,
                high: false,
            };
            exact_span(&(origin + &half), &half, ends, side)
        };
        let x = bound(&mapping.x, &mapping.width, canvas.width);
        let y = bound(&mapping.y, &mapping.height, canvas.height);
        columns = columns.start.max(x.start)..columns.end.min(x.end);
        rows = rows.start.max(y.start)..rows.end.min(y.end);
    }
    if columns.is_empty() || rows.is_empty() {
        return;
    }
    let depth = plan.depth.then(|| {
        let mut z_f = mapping.depth(&(z / w));
        if mapping.clamp {
            let [lo, hi] = mapping.depth_range();
            z_f = z_f.clamp(lo, hi);
        }
        z_f.to_f64().value() as f32
    });
    let values = Values {
        depth,
        attributes: attributes(vertex, plan),
    };
    fill(frame, canvas, columns, rows, index, &values);
}
