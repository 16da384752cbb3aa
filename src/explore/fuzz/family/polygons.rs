//! The `polygons` family (SPEC.md §14): polygons of one to three contours
//! with repeated, collinear and doubled vertices, under both fills and the
//! consistent fill rules, sometimes with a triangle or two. The antialias and
//! motion families draw their polygons from here too.

use dashu_ratio::RBig;

use super::common::{any_bits, canvas, plain_triangle, position, scene_of, Values};
use crate::explore::fuzz::geometry::num;
use crate::explore::fuzz::rng::Rng;
use crate::scene::{
    Canvas, Cull, FillRule, Number, Polygon, PolygonFill, Primitive, Rules, Scene, Vertex,
};

/// One contour of 3 to 8 vertices; sometimes with a vertex repeated, a
/// vertex inserted halfway along an edge (collinear), or the whole contour
/// run twice (winding twice, every edge doubled).
fn contour(rng: &mut Rng, canvas: Canvas) -> Vec<Vertex> {
    let n = rng.range(3, 9) as usize;
    let mut vs: Vec<Vertex> = (0..n).map(|_| position(rng, canvas)).collect();
    if rng.chance(1, 5) {
        let k = rng.below(vs.len() as u64) as usize;
        let copy = vs[k].clone();
        vs.insert(k, copy);
    }
    if rng.chance(1, 5) {
        let k = rng.below(vs.len() as u64) as usize;
        let (a, b) = (&vs[k], &vs[(k + 1) % vs.len()]);
        let half = |p: &Number, q: &Number| num(&((p.as_rbig() + q.as_rbig()) / RBig::from(2u8)));
        let mid = Vertex::at(half(&a.x, &b.x), half(&a.y, &b.y));
        vs.insert(k + 1, mid);
    }
    if rng.chance(1, 10) {
        vs.extend(vs.clone());
    }
    vs
}

pub(super) fn polygon(rng: &mut Rng, canvas: Canvas) -> Polygon {
    let mut vertices = Vec::new();
    let mut contour_ends = Vec::new();
    for _ in 0..*rng.pick(&[1, 1, 1, 2, 2, 3]) {
        vertices.extend(contour(rng, canvas));
        contour_ends.push(vertices.len());
    }
    let fill = *rng.pick(&[PolygonFill::NonZero, PolygonFill::EvenOdd]);
    Polygon {
        vertices,
        contour_ends,
        fill,
    }
}

/// Rules for polygons: every consistent fill rule (`all-edges` is an input
/// error there), no culling (it does not apply to polygons).
pub(super) fn polygon_rules(rng: &mut Rng) -> Rules {
    Rules {
        subpixel_bits: any_bits(rng),
        fill_rule: *rng.pick(&FillRule::CONSISTENT),
        cull: Cull::None,
        ..Rules::default()
    }
}

pub(super) fn polygon_scene(rng: &mut Rng) -> Scene {
    let canvas = canvas(rng);
    let mut primitives = Vec::new();
    for _ in 0..rng.range(1, 3) {
        primitives.push(Primitive::Polygon(polygon(rng, canvas)));
    }
    for _ in 0..*rng.pick(&[0, 0, 1, 2]) {
        let at = rng.below(primitives.len() as u64 + 1) as usize;
        let t = plain_triangle(rng, canvas);
        primitives.insert(at, t);
    }
    let none = Values {
        attributes: 0,
        depth: false,
        w: false,
    };
    scene_of(canvas, polygon_rules(rng), primitives, &none)
}
