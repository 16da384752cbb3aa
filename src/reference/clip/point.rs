//! A clip-space point (SPEC.md §17.2): through the projection, viewport
//! and snap (`homogeneous::screen_point`), never the clipper; kept or
//! discarded whole by its centre, then drawn as `../point.rs` draws a
//! square. Its square is limited by the canvas, and by the viewport
//! rectangle only under `point_bounds: viewport` (`visit.rs` applies that
//! bound).

use dashu_ratio::RBig;

use super::clipper::ClipVertex;
use super::homogeneous::screen_point;
use crate::reference::point::Square;
use crate::reference::values::Values;
use crate::scene::{ClipRules, DepthMode, Point, PointClip, Viewport};

/// A clip-space point (§17.2): `None` when it is discarded (w ≤ 0; its
/// centre outside 0 ≤ z ≤ w under depth clip; its centre outside the side
/// planes under `clip_points: pop`), else its square, centred on the
/// snapped (x_f, y_f), and its values (depth z_f, clamped to the depth
/// range under depth clamp; the vertex's attributes).
pub fn clip_square(
    point: &Point,
    viewport: &Viewport,
    clip: ClipRules,
    bits: Option<u32>,
) -> Option<(Square, Values)> {
    let v = ClipVertex::of(&point.vertices[0]);
    let [x, y, z, w] = &v.c;
    if *w <= RBig::ZERO {
        return None;
    }
    if clip.depth == DepthMode::Clip && (*z < RBig::ZERO || z > w) {
        return None;
    }
    let outside = |c: &RBig| *c < -w || c > w;
    if clip.points == PointClip::Pop && (outside(x) || outside(y)) {
        return None;
    }
    let ([sx, sy, _], _) = screen_point(&v, viewport, bits);
    let (min_d, max_d) = (viewport.min_depth.as_rbig(), viewport.max_depth.as_rbig());
    let mut depth = min_d + (max_d - min_d) * (z / w);
    if clip.depth == DepthMode::Clamp {
        depth = depth.clamp(min_d.min(max_d).clone(), min_d.max(max_d).clone());
    }
    Some((
        Square::new([sx, sy], &point.size),
        Values {
            depth_interval: [depth.clone(), depth.clone()],
            depth,
            attributes: v.attributes,
        },
    ))
}
