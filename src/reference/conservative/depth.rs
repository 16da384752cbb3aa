//! The depth a conservatively drawn pixel may hold (SPEC.md §19.9),
//! exact.
//!
//! A primitive that draws pixel (x, y) conservatively writes there the
//! depth of its plane at the pixel's sample, its centre c, extrapolated
//! when c lies outside it (D3D12: "Depth extrapolation, which is valid").
//! What is allowed is the interval from the least to the greatest of z(c)
//! and the depths of the primitive within the pixel: z over T ∩ S_w, with
//! S_w the pixel's closed square grown by w = u under overestimation (the
//! same growth that lets it draw the pixel) and w = 0 under
//! underestimation. The plane is linear, so its extremes over that convex
//! polygon are at its vertices, found by clipping T to the square in
//! rationals. A degenerate triangle drawn (`degenerate_triangles`) has
//! the depth of its provoking vertex (Vulkan: "take their attribute and
//! depth values from the provoking vertex"). Polygon offset adds its
//! interval (§18.2); the format then clamps to [0, 1] and quantizes
//! (§18.1), or, for `exact` depth, the interval is widened by §6.3's ε.
//!
//! Which primitive's depth stays is the last writer's (the depth test
//! always passes, as in §18.4): the last primitive that must draw the
//! pixel, or any later one that may. A drawn pixel's depth must lie in the
//! allowed set of one of those possible last writers.

use dashu_int::IBig;
use dashu_ratio::RBig;

use super::classes::{ConservativeClasses, PixelClass};
use super::classify::{frame_of, pixel_class, pixel_range};
use super::geometry::{orient, GridPoint};
use super::outline::{common_scale, snapped, Outline};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::reference::depth::{f64_above, f64_below, plane_gradient, DepthRules, Stored};
use crate::reference::exact::to_f64_round_odd;
use crate::scene::depth::DepthFormat;
use crate::scene::rules::ProvokingVertex;
use crate::scene::{Conservative, ConservativeMode, Primitive, Scene};

/// What every pixel's depth may be, for one conservative scene with depth
/// under one conservative state.
#[derive(Clone, Debug, PartialEq)]
pub struct ConservativeDepth {
    pub width: u32,
    pub format: DepthFormat,
    /// Per pixel, row-major, one allowed interval [lo, hi] of readbacks per
    /// possible last writer (SPEC.md §19.9): a drawn pixel's depth must lie
    /// in one of them. Empty where no primitive may draw the pixel. Each
    /// end is an f64 that decides exactly (`reference::depth::Stored`).
    pub allowed: Vec<Vec<[f64; 2]>>,
    /// Per pixel, the depth the reference writes where a primitive must
    /// draw it: the stored midpoint of its last required writer's
    /// interval (the golden file's value); 0 elsewhere.
    pub value: Vec<f64>,
}

/// The allowed depths of `scene` under `case` (a candidate's declared
/// state, or the case's own), or `None` when the scene has no depth. The
/// scene holds triangles only (`Scene::conservative_unjudged`).
pub fn depth_allowed(scene: &Scene, case: &Conservative) -> Option<ConservativeDepth> {
    if !scene.has_depth {
        return None;
    }
    let (width, height) = (scene.canvas.width, scene.canvas.height);
    let n = width as usize * height as usize;
    let mut out = ConservativeDepth {
        width,
        format: scene.rules.depth_format,
        allowed: vec![Vec::new(); n],
        value: vec![0.0; n],
    };
    let rules = DepthRules::new(scene);
    let epsilon = RBig::try_from(scene.depth_tolerance()).expect("a finite tolerance");
    let bits = scene.rules.subpixel_bits;
    // Each triangle's snapped vertices (x, y) and depth z, exact.
    let triangles: Vec<(usize, [[RBig; 3]; 3])> = scene
        .primitives
        .iter()
        .enumerate()
        .filter_map(|(i, p)| match p {
            Primitive::Triangle(t) => Some((
                i,
                t.vertices.each_ref().map(|v| {
                    [
                        snapped(&v.x, bits),
                        snapped(&v.y, bits),
                        v.z.as_rbig().clone(),
                    ]
                }),
            )),
            _ => None,
        })
        .collect();
    let scale = common_scale(
        triangles
            .iter()
            .flat_map(|(_, t)| t.iter().flat_map(|p| &p[..2]))
            .chain([case.uncertainty.as_rbig()])
            .map(RBig::denominator)
            .collect(),
    );
    let on_grid =
        |q: &RBig| -> IBig { q.numerator() * (&scale / IBig::from(q.denominator().clone())) };
    let u = on_grid(case.uncertainty.as_rbig());
    let growth = match case.mode {
        ConservativeMode::Overestimate => case.uncertainty.as_rbig().clone(),
        ConservativeMode::Underestimate => RBig::ZERO,
    };
    for (index, triangle) in &triangles {
        let t: [GridPoint; 3] = triangle
            .each_ref()
            .map(|p| [on_grid(&p[0]), on_grid(&p[1])]);
        let area = orient(&t[0], &t[1], &t[2]);
        let degenerate = area == IBig::ZERO;
        if degenerate && !case.degenerate_triangles {
            continue;
        }
        if !degenerate && scene.rules.cull.discards(area.cmp(&IBig::ZERO)) {
            continue;
        }
        let outline = Outline::Hull(t.to_vec());
        let Some((xs, ys)) = pixel_range(&outline.bounds(), &u, &scale, width, height) else {
            continue;
        };
        let plane = Plane::of(triangle, scene.rules.provoking_vertex);
        let offset = rules.as_ref().and_then(|r| r.offset(*index));
        for y in ys {
            for x in xs.clone() {
                let (drawn, _) = pixel_class(case.mode, &outline, x, y, &scale, &u);
                if drawn == PixelClass::Forbidden {
                    continue;
                }
                let [lo, hi] = plane.interval(triangle, x, y, &growth);
                let [lo, hi] = match offset {
                    Some([o_lo, o_hi]) => [lo + o_lo, hi + o_hi],
                    None => [lo, hi],
                };
                let stored = match &rules {
                    Some(rules) => rules.store([&lo, &hi]),
                    None => exact_store(&lo, &hi, &epsilon),
                };
                let i = y as usize * width as usize + x as usize;
                if drawn == PixelClass::Required {
                    out.allowed[i].clear();
                    out.value[i] = stored.value;
                }
                out.allowed[i].push(stored.allowed);
            }
        }
    }
    Some(out)
}

/// What `exact` depth allows (SPEC.md §6.3): [lo − ε, hi + ε], its ends
/// the tightest f64s outside it, and the midpoint as the golden value.
fn exact_store(lo: &RBig, hi: &RBig, epsilon: &RBig) -> Stored {
    let mid = (lo + hi) / RBig::from(2);
    Stored {
        value: to_f64_round_odd(&mid),
        allowed: [f64_below(&(lo - epsilon)), f64_above(&(hi + epsilon))],
    }
}

/// A triangle's depth over the screen: its plane through the snapped
/// vertices, or one depth for a triangle of no area (its provoking
/// vertex's).
enum Plane {
    Linear {
        origin: [RBig; 3],
        gradient: [RBig; 2],
    },
    Constant(RBig),
}

impl Plane {
    fn of(v: &[[RBig; 3]; 3], provoking: ProvokingVertex) -> Plane {
        match plane_gradient(v) {
            Some(gradient) => Plane::Linear {
                origin: v[0].clone(),
                gradient,
            },
            None => Plane::Constant(match provoking {
                ProvokingVertex::First => v[0][2].clone(),
                ProvokingVertex::Last => v[2][2].clone(),
            }),
        }
    }

    fn at(&self, p: &[RBig; 2]) -> RBig {
        match self {
            Plane::Linear { origin, gradient } => {
                &origin[2]
                    + &gradient[0] * (&p[0] - &origin[0])
                    + &gradient[1] * (&p[1] - &origin[1])
            }
            Plane::Constant(z) => z.clone(),
        }
    }

    /// The least and greatest of z at pixel (x, y)'s centre and over the
    /// triangle within its square grown by `growth`.
    fn interval(&self, v: &[[RBig; 3]; 3], x: u32, y: u32, growth: &RBig) -> [RBig; 2] {
        let half = RBig::from_parts(IBig::ONE, 2u8.into());
        let centre = [RBig::from(x) + &half, RBig::from(y) + &half];
        let region = clip_to_square(v, x, y, growth);
        let mut lo = self.at(&centre);
        let mut hi = lo.clone();
        for p in &region {
            let z = self.at(p);
            if z < lo {
                lo = z;
            } else if z > hi {
                hi = z;
            }
        }
        [lo, hi]
    }
}

/// The vertices of T ∩ [x − g, x + 1 + g] × [y − g, y + 1 + g], T the
/// closed triangle on `v`'s (x, y): Sutherland–Hodgman against the four
/// closed half-planes, exact. Empty when they do not meet; a point or a
/// segment's ends where they only touch.
fn clip_to_square(v: &[[RBig; 3]; 3], x: u32, y: u32, g: &RBig) -> Vec<[RBig; 2]> {
    let mut polygon: Vec<[RBig; 2]> = v.iter().map(|p| [p[0].clone(), p[1].clone()]).collect();
    let sides = [
        (0, RBig::from(x) - g, 1),
        (0, RBig::from(x + 1) + g, -1),
        (1, RBig::from(y) - g, 1),
        (1, RBig::from(y + 1) + g, -1),
    ];
    for (axis, bound, sign) in sides {
        if polygon.is_empty() {
            break;
        }
        // d ≥ 0 inside the half-plane.
        let d = |p: &[RBig; 2]| {
            let e = &p[axis] - &bound;
            if sign > 0 {
                e
            } else {
                -e
            }
        };
        let mut kept = Vec::with_capacity(polygon.len() + 1);
        for k in 0..polygon.len() {
            let (p, q) = (&polygon[k], &polygon[(k + 1) % polygon.len()]);
            let (dp, dq) = (d(p), d(q));
            if dp >= RBig::ZERO {
                kept.push(p.clone());
            }
            if (dp > RBig::ZERO && dq < RBig::ZERO) || (dp < RBig::ZERO && dq > RBig::ZERO) {
                let t = &dp / (&dp - &dq);
                kept.push([0, 1].map(|c| &p[c] + &t * (&q[c] - &p[c])));
            }
        }
        polygon = kept;
    }
    polygon
}

/// The reference's frame of a conservative scene with its depth: its
/// required pixels drawn (`frame_of`), each with the depth it writes.
pub fn frame_with_depth(scene: &Scene, plan: &Plan, classes: &ConservativeClasses) -> Frame {
    let mut frame = frame_of(scene, plan, classes);
    write_depth(scene, &mut frame);
    frame
}

/// The reference's own frame of a conservative scene, with depth.
pub fn render(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    let mut frame = super::classify::render(scene, plan)?;
    write_depth(scene, &mut frame);
    Ok(frame)
}

/// Writes the reference's depth at every pixel it draws, under the case's
/// own conservative state.
fn write_depth(scene: &Scene, frame: &mut Frame) {
    let Some(case) = &scene.effects.conservative else {
        return;
    };
    let (Some(depth), Some(allowed)) = (frame.depth.as_mut(), depth_allowed(scene, case)) else {
        return;
    };
    for (i, z) in depth.iter_mut().enumerate() {
        if frame.last[i] > 0 {
            *z = allowed.value[i];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: u64) -> RBig {
        RBig::from_parts(n.into(), d.into())
    }

    fn triangle(p: [[i64; 3]; 3]) -> [[RBig; 3]; 3] {
        p.map(|v| v.map(RBig::from))
    }

    #[test]
    fn a_corner_touch_clips_to_one_point() {
        // x ≥ 1, y ≥ 1, x + y ≤ 4: pixel (0, 0)'s square touches it at (1, 1).
        let t = triangle([[1, 1, 0], [3, 1, 0], [1, 3, 0]]);
        let region = clip_to_square(&t, 0, 0, &RBig::ZERO);
        assert!(!region.is_empty());
        assert!(region.iter().all(|p| p == &[RBig::ONE, RBig::ONE]));
        assert!(clip_to_square(&t, 3, 3, &RBig::ZERO).is_empty());
    }

    #[test]
    fn the_interval_holds_the_centre_and_the_part_inside() {
        // z = x / 4 over (0,0) (4,0) (0,4); pixel (3, 0) holds only the
        // corner x + y ≤ 4 of its square: x from 3 to 4, z from 3/4 to 1;
        // the centre (3.5, 0.5) is on the hypotenuse's far side? 3.5 + 0.5
        // = 4: on it, z = 7/8.
        let t = triangle([[0, 0, 0], [4, 0, 1], [0, 4, 0]]);
        let plane = Plane::of(&t, ProvokingVertex::First);
        assert_eq!(plane.interval(&t, 3, 0, &RBig::ZERO), [q(3, 4), RBig::ONE]);
        // Pixel (3, 1) touches T only at (3, 1): z = 3/4; its centre
        // (3.5, 1.5) is outside, extrapolated to 7/8.
        assert_eq!(plane.interval(&t, 3, 1, &RBig::ZERO), [q(3, 4), q(7, 8)]);
        // Grown by 1/4, pixel (4, 0)'s square reaches x = 15/4.
        assert_eq!(plane.interval(&t, 4, 0, &q(1, 4)), [q(15, 16), q(9, 8)]);
    }

    #[test]
    fn a_degenerate_triangle_has_its_provoking_vertex_depth() {
        let t = triangle([[1, 1, 1], [3, 1, 0], [2, 1, 0]]);
        let first = Plane::of(&t, ProvokingVertex::First);
        assert_eq!(
            first.interval(&t, 1, 1, &RBig::ZERO),
            [RBig::ONE, RBig::ONE]
        );
        let last = Plane::of(&t, ProvokingVertex::Last);
        assert_eq!(
            last.interval(&t, 1, 1, &RBig::ZERO),
            [RBig::ZERO, RBig::ZERO]
        );
    }
}
