//! The viewport a screen-space scene is drawn through: a rectangle of the
//! target's pixels, of power-of-two sides, that encloses the target and
//! every vertex of the scene, so that the driver clips nothing at its
//! side planes that the case does not clip (SPEC.md §2: a screen-space
//! triangle is rasterized whole from its snapped vertices).
//!
//! Vulkan and GL allow a viewport larger than the framebuffer
//! (`maxViewportDimensions`, `viewportBoundsRange`; `GL_MAX_VIEWPORT_DIMS`,
//! `GL_VIEWPORT_BOUNDS_RANGE`): the scissor, at the canvas, bounds what is
//! drawn. A viewport the size of the target (what the adapters drew
//! through before) makes SwiftShader and Mesa, which have no guard band at
//! the side planes, clip a triangle reaching past the target and snap the
//! new vertices, which moves its edges.
//!
//! Exactness. A position x (on the grid of `2^-fine` pixel, `fine` the
//! larger of the case's and the driver's subpixel bits) is sent as
//! `ndc = 2(x − x0)/V − 1`, and the driver computes
//! `x_w = (ndc + 1)·V/2 + x0 = ndc·V/2 + (x0 + V/2)`. With V a power of two
//! and x0 an integer, x − x0 ∈ [0, V] needs `fine + log2 V` bits and ndc
//! one more below 1, `ndc·V/2` is a power-of-two scaling, and the sum is
//! x, exact when x, x0 and x0 + V/2 fit in f32's 24 bits at `2^-fine`. A
//! shifted pass (`stream.rs`) moves the viewport's corner by its shift s,
//! under half a pixel on the driver's grid, and the driver computes
//! `ndc·V/2 + (x0 + s + V/2) = x + s`: so the budget keeps a pixel to
//! spare (every coordinate below `2^(24 − fine)` by one), and so do the
//! device's bounds (the corner moved by s stays within them). A scene
//! whose rectangle breaks that budget, or the device's largest viewport
//! or its bounds, is drawn through the target as before (the driver may
//! then clip it, at the target moved by each pass's shift: in the case's
//! coordinates, at the target).

use dashu_int::IBig;

use super::super::float_input::{f32_of, snapped};
use crate::rasterizer::ScreenViewport;
use crate::scene::{Primitive, Scene};

/// f32's significand: 24 bits.
const F32_BITS: u32 = 24;

/// Pixels added around the vertices' box: a polygon's cover reaches one
/// pixel past its snapped vertices (rounded out to integers), and a
/// shifted pass moves the scene by less than one pixel.
const MARGIN: i64 = 2;

/// A rectangle of the target's pixels (x right, y down, as the canvas):
/// the viewport's corner and its power-of-two sides.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct View {
    pub origin: [i64; 2],
    pub size: (u32, u32),
}

impl View {
    /// The whole target, from its corner: the viewport of a scene whose
    /// vertices all lie in it, and of one no larger viewport can hold.
    pub(crate) fn target(target: (u32, u32)) -> View {
        View {
            origin: [0, 0],
            size: target,
        }
    }
}

/// What the device allows of a viewport, in the target's pixels (x right,
/// y down): its largest sides, and the ranges its left and right edges
/// (`x`) and its top and bottom edges (`y`) must lie in.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ViewLimits {
    pub max: [u32; 2],
    pub x: [i64; 2],
    pub y: [i64; 2],
}

impl ViewLimits {
    /// Vulkan's: `maxViewportDimensions` and `viewportBoundsRange`, which
    /// bound x, x + width, y and y + height alike.
    pub(crate) fn vulkan(max: [u32; 2], bounds: [f32; 2]) -> ViewLimits {
        let range = [bounds[0].ceil() as i64, bounds[1].floor() as i64];
        ViewLimits {
            max,
            x: range,
            y: range,
        }
    }
}

/// The viewport `scene` is drawn through on a `target`: the target itself
/// for a clip-space scene (whose own viewport the adapter sets) and for a
/// scene whose vertices all lie in the target (less `MARGIN`), else the
/// smallest power-of-two rectangle holding the target and every vertex
/// (snapped to `bits`; both ends of a moving vertex, so every instant
/// between), centred on them, when the device allows it and the mapping
/// stays exact at `fine` bits (the module's notes); else the target.
pub(crate) fn screen_view(
    scene: &Scene,
    bits: u32,
    fine: u32,
    target: (u32, u32),
    limits: &ViewLimits,
) -> View {
    let whole = View::target(target);
    if scene.viewport.is_some() {
        return whole;
    }
    let Some([lo, hi]) = vertex_box(scene, bits) else {
        return whole;
    };
    let sides = [target.0, target.1];
    let mut origin = [0i64; 2];
    let mut size = [0u32; 2];
    for axis in 0..2 {
        let low = lo[axis].saturating_sub(MARGIN).min(0);
        let high = hi[axis].saturating_add(MARGIN).max(i64::from(sides[axis]));
        let span = (i128::from(high) - i128::from(low)) as u128;
        let Ok(span) = u64::try_from(span) else {
            return whole;
        };
        if span > u64::from(limits.max[axis]) {
            return whole;
        }
        let side = span.next_power_of_two();
        if side > u64::from(limits.max[axis]) || side > u64::from(u32::MAX) {
            return whole;
        }
        // Centred: the slack split, the integer half to the low side.
        let x0 = low - ((side - span) / 2) as i64;
        // A pixel to spare on each side for a shifted pass's viewport.
        let range = if axis == 0 { limits.x } else { limits.y };
        if x0 - 1 < range[0] || x0 + side as i64 + 1 > range[1] {
            return whole;
        }
        origin[axis] = x0;
        size[axis] = side as u32;
    }
    let view = View {
        origin,
        size: (size[0], size[1]),
    };
    if view == whole || exact(&view, fine) {
        view
    } else {
        whole
    }
}

/// The viewport a screen-space `scene` drawn through `view` (what
/// [`screen_view`] chose) is clipped at by a driver without a guard band,
/// when `view` does not hold every vertex (snapped to `bits`, widened by a
/// line's width or a point's size): where the device's largest viewport
/// cannot hold them (`Rasterizer::screen_viewport`). `None` for a
/// clip-space scene (its own viewport) and for one `view` holds whole.
pub(crate) fn clipped_at(scene: &Scene, bits: u32, view: &View) -> Option<ScreenViewport> {
    if scene.viewport.is_some() {
        return None;
    }
    let [lo, hi] = vertex_box(scene, bits)?;
    let ends = [view.size.0, view.size.1];
    let holds = (0..2).all(|axis| {
        lo[axis] >= view.origin[axis]
            && hi[axis] <= view.origin[axis].saturating_add(i64::from(ends[axis]))
    });
    (!holds).then_some(ScreenViewport {
        origin: view.origin,
        size: ends,
    })
}

/// Whether every position of `view` at `2^-fine` pixel, and the
/// viewport's centre, are f32s, also moved by a shifted pass's shift (under
/// a pixel), as the module's notes need: every coordinate in it, and its
/// sides, are below `2^24` steps of `2^-fine` by a pixel.
fn exact(view: &View, fine: u32) -> bool {
    let sides = [view.size.0, view.size.1];
    (0..2).all(|axis| {
        let x0 = view.origin[axis].unsigned_abs();
        let x1 = (view.origin[axis] + i64::from(sides[axis])).unsigned_abs();
        let largest = x0.max(x1).max(u64::from(sides[axis]));
        fine < F32_BITS && largest < 1 << (F32_BITS - fine)
    })
}

/// The box of the scene's snapped vertices, rounded out to integers and
/// widened by a line's width or a point's size (the driver's quads and
/// squares reach past their vertices), or `None` for a scene without
/// vertices.
fn vertex_box(scene: &Scene, bits: u32) -> Option<[[i64; 2]; 2]> {
    let mut lo = [i64::MAX; 2];
    let mut hi = [i64::MIN; 2];
    let mut any = false;
    for primitive in &scene.primitives {
        let reach = match primitive {
            Primitive::Line(l) => f32_of(&l.width),
            Primitive::Point(p) => f32_of(&p.size),
            _ => 0.0,
        };
        // Sizes are bounded by the reader; a non-finite one reaches nowhere.
        let reach = if reach.is_finite() {
            reach.ceil().clamp(0.0, 1e9) as i64
        } else {
            0
        };
        for v in primitive.vertices() {
            let mut ends = vec![[&v.x, &v.y]];
            if let Some(to) = v.to.as_deref() {
                ends.push([&to[0], &to[1]]);
            }
            for end in ends {
                for (axis, c) in end.into_iter().enumerate() {
                    let c = snapped(c, Some(bits));
                    // Saturated: a box this far fails the limits anyway.
                    let whole = |n: IBig| {
                        let past = if n < IBig::ZERO { i64::MIN } else { i64::MAX };
                        i64::try_from(n).unwrap_or(past)
                    };
                    lo[axis] = lo[axis].min(whole(c.floor()).saturating_sub(reach));
                    hi[axis] = hi[axis].max(whole(c.ceil()).saturating_add(reach));
                    any = true;
                }
            }
        }
    }
    any.then_some([lo, hi])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{parse_case, Limits};

    fn scene(canvas: (u32, u32), triangles: &str) -> Scene {
        let json = format!(
            r#"{{"name": "view", "canvas": {{"width": {}, "height": {}}},
                "rules": {{"subpixel_bits": 8, "fill_rule": "top-left", "cull": "none"}},
                "primitives": [{triangles}]}}"#,
            canvas.0, canvas.1
        );
        parse_case(&json, "view.json", &Limits::default()).expect("a valid case")
    }

    /// lavapipe's limits.
    const LIMITS: ViewLimits = ViewLimits {
        max: [16384, 16384],
        x: [-32768, 32768],
        y: [-32768, 32768],
    };

    #[test]
    fn a_scene_inside_the_target_is_drawn_through_the_target() {
        let inside = scene((16, 8), r#"{"triangle": [[2, 2], [14, 2], [2, 6]]}"#);
        let view = screen_view(&inside, 8, 8, (16, 8), &LIMITS);
        assert_eq!(view, View::target((16, 8)));
    }

    #[test]
    fn a_scene_past_the_target_gets_an_enclosing_power_of_two_viewport() {
        // shared_edge_shallow: x from −1 to 17, y from −30 to 30.
        let past = scene(
            (16, 8),
            r#"{"triangle": [[-1, 1], [17, 7], [17, -30]]}, {"triangle": [[-1, 1], [-1, 30], [17, 7]]}"#,
        );
        let view = screen_view(&past, 8, 8, (16, 8), &LIMITS);
        // x: [−3, 19] spans 22 → 32, centred from −8; y: [−32, 32] spans 64.
        assert_eq!(
            view,
            View {
                origin: [-8, -32],
                size: (32, 64)
            }
        );
    }

    #[test]
    fn a_scene_past_the_largest_viewport_is_drawn_through_the_target() {
        let far = scene(
            (64, 64),
            r#"{"triangle": [[-20000, 0], [20000, 0], [0, 64]]}"#,
        );
        assert_eq!(
            screen_view(&far, 8, 8, (64, 64), &LIMITS),
            View::target((64, 64))
        );
        // Within the dimensions but past the bounds range.
        let off = scene((64, 64), r#"{"triangle": [[0, 0], [30000, 0], [0, 64]]}"#);
        let narrow = ViewLimits {
            max: [65536, 65536],
            x: [-16384, 16384],
            y: [-16384, 16384],
        };
        assert_eq!(
            screen_view(&off, 8, 8, (64, 64), &narrow),
            View::target((64, 64))
        );
        // And within both: a 32768 px viewport from x = −1384.
        let view = screen_view(
            &off,
            8,
            8,
            (64, 64),
            &ViewLimits {
                max: [65536, 65536],
                ..LIMITS
            },
        );
        assert_eq!(view.origin[0], -1384);
        assert_eq!(view.size.0, 32768);
    }

    #[test]
    fn only_a_viewport_that_cannot_hold_the_vertices_clips() {
        let past = scene((16, 8), r#"{"triangle": [[-1, 1], [17, 7], [17, -30]]}"#);
        let view = screen_view(&past, 8, 8, (16, 8), &LIMITS);
        assert_eq!(clipped_at(&past, 8, &view), None);
        let far = scene(
            (64, 64),
            r#"{"triangle": [[-20000, 0], [20000, 0], [0, 64]]}"#,
        );
        let view = screen_view(&far, 8, 8, (64, 64), &LIMITS);
        assert_eq!(
            clipped_at(&far, 8, &view),
            Some(ScreenViewport {
                origin: [0, 0],
                size: [64, 64]
            })
        );
    }

    #[test]
    fn exactness_counts_the_largest_coordinate_and_the_fine_bits() {
        let view = View {
            origin: [-16, 0],
            size: (64, 32),
        };
        assert!(exact(&view, 8));
        // x − x0 reaches 2^16: at 2^-7 that is 2^23 steps, at 2^-8 2^24,
        // a pixel short of the spare a shift needs.
        let far = View {
            origin: [-65535, 0],
            size: (65536, 32),
        };
        assert!(exact(&far, 7));
        assert!(!exact(&far, 8));
        let lower = View {
            origin: [-65534, 0],
            size: (32768, 32),
        };
        assert!(exact(&lower, 8));
    }
}
