//! Which points a driver draws exactly as SPEC.md §17's square, and why it
//! does not draw the others (the `vulkan` and `gl` adapters'; measured on
//! Mesa's llvmpipe and lavapipe, SPEC.md §17.4):
//!
//! - the size must be one the driver draws: in its range, on its
//!   granularity from the range's low end (a granularity of 0 is no step:
//!   SwiftShader reports 0 and draws any size of its range, its point
//!   set-up taking the size unrounded), an f32, and 1 without large
//!   points;
//! - at least one pixel: Mesa draws a smaller point one pixel wide (its
//!   rasterizer takes the size as at least 1), where the rule's square
//!   may cover no sample;
//! - half the size on the driver's subpixel grid, so that the corners
//!   X ± size/2 of a snapped centre are on it and nothing is rounded;
//! - in clip space, a square reaching outside the viewport rectangle
//!   only across edges not just past a pixel centre: lavapipe and
//!   llvmpipe limit a point's square to the viewport rectangle (judged
//!   under `point_bounds: viewport`, their `fixed_point_bounds`) rounded
//!   to whole pixels as `(int)(x + 0.499)`, which keeps the columns the
//!   rule keeps unless an edge lies less than 0.001 px past a centre;
//! - in screen space, on a driver that pops (GL), the centre at least half
//!   a pixel inside the canvas: the target's viewport covers the canvas,
//!   and a shifted pass moves the centre by less than half a pixel, so no
//!   centre the driver is handed leaves the viewport, where the rule
//!   (clipped by the canvas only) would still draw the square's part on
//!   the canvas.

use dashu_ratio::RBig;

use super::super::float_input::{f32_of, snapped};
use crate::scene::{Number, Point, Scene};

/// What a driver offers for points.
pub(crate) struct PointOffers {
    /// Sizes other than 1 (Vulkan's `largePoints`; GL always).
    pub large: bool,
    /// The sizes it draws, and their step from the low end.
    pub range: [f32; 2],
    pub granularity: f32,
    /// The subpixel grid its rasterizer snaps to.
    pub subpixel_bits: u32,
    /// Whether it discards a point whose centre is outside the viewport
    /// (GL's llvmpipe, measured), rather than drawing its square.
    pub pops: bool,
}

/// Why the driver cannot draw `point` of `scene` as the rule's square,
/// if it cannot.
pub(crate) fn refusal(scene: &Scene, point: &Point, offers: &PointOffers) -> Option<String> {
    let size = &point.size;
    let shown = size.to_exact_string();
    let s = f32_of(size);
    let exact = RBig::try_from(s).is_ok_and(|back| &back == size.as_rbig());
    let [lo, hi] = offers.range;
    let on_step = offers.granularity == 0.0 || ((s - lo) / offers.granularity).fract() == 0.0;
    if !exact || s < lo || s > hi || !on_step || (s != 1.0 && !offers.large) {
        let steps = if offers.granularity == 0.0 {
            ", any size between (pointSizeGranularity 0)".to_owned()
        } else {
            format!(" in steps of {}", offers.granularity)
        };
        return Some(format!(
            "point size {shown}: the driver draws sizes {lo} to {hi}{steps}{}",
            if offers.large {
                ""
            } else {
                " (no largePoints: 1 only)"
            }
        ));
    }
    if s < 1.0 {
        return Some(format!(
            "point size {shown}: Mesa draws a point under one pixel one pixel wide, where \
             the square may cover no sample"
        ));
    }
    let half = size.as_rbig() / RBig::from(2);
    let grid = RBig::from(1u64 << offers.subpixel_bits);
    if !(&half * &grid).is_int() {
        return Some(format!(
            "point size {shown}: its half is off the driver's grid of 2^-{} px, so the \
             square's corners would be rounded",
            offers.subpixel_bits
        ));
    }
    if offers.pops && scene.viewport.is_none() {
        if let Some(why) = near_the_edge(scene, point) {
            return Some(why);
        }
    }
    outside_viewport(scene, point, &half)
}

/// Why a screen-space point's centre is less than half a pixel inside
/// the canvas, on a driver that pops, if it is.
fn near_the_edge(scene: &Scene, point: &Point) -> Option<String> {
    let v = &point.vertices[0];
    let bits = scene.rules.subpixel_bits;
    let half = RBig::ONE / RBig::from(2);
    let inside = |c: &Number, extent: u32| {
        let c = snapped(c, bits);
        c >= half && c <= RBig::from(extent) - &half
    };
    (!(inside(&v.x, scene.canvas.width) && inside(&v.y, scene.canvas.height))).then(|| {
        format!(
            "a point centred at ({}, {}), less than half a pixel inside the canvas: the \
             driver discards a point whose centre leaves its viewport (measured on \
             llvmpipe's GL), where the rule draws the square's part on the canvas",
            v.x.to_exact_string(),
            v.y.to_exact_string()
        )
    })
}

/// How far past a pixel centre (in pixels) a viewport edge may lie where
/// Mesa's whole-pixel rectangle departs from SPEC.md §17.2's: llvmpipe
/// (`lp_setup.c`) rounds the viewport rectangle to whole pixels as
/// `(int)(x + 0.499)` and `(int)(x + width − 0.501)` (inclusive), which
/// keeps exactly the columns whose centre the rule's [x, x + width) holds
/// unless an edge lies less than 0.001 px past a centre (measured on the
/// bundled case with an edge through centres); twice that, for the f32
/// sums.
const MESA_ROUNDING: (i64, i64) = (1, 500);

/// Why a clip-space point's square cannot be judged where it reaches
/// outside the viewport rectangle, which Mesa limits it to: an edge of the
/// rectangle just past a pixel centre, where Mesa's rounding of the
/// rectangle to whole pixels departs from the rule ([`MESA_ROUNDING`]; a
/// point with w ≤ 0 is discarded by both and never refused).
fn outside_viewport(scene: &Scene, point: &Point, half: &RBig) -> Option<String> {
    let view = scene.viewport.as_ref()?;
    let v = &point.vertices[0];
    if !v.w.is_positive() {
        return None;
    }
    let bits = scene.rules.subpixel_bits;
    // x_f = v.x + v.width · (x/w + 1)/2, snapped (SPEC.md §16.1).
    let place = |c: &Number, origin: &Number, extent: &Number| {
        let ratio = c.as_rbig() / v.w.as_rbig();
        let f = origin.as_rbig() + extent.as_rbig() * (ratio + RBig::ONE) / RBig::from(2);
        snapped(&Number::from_rbig(f), bits)
    };
    let x = place(&v.x, &view.x, &view.width);
    let y = place(&v.y, &view.y, &view.height);
    let inside = |c: &RBig, origin: &Number, extent: &Number| {
        c - half >= *origin.as_rbig() && c + half <= origin.as_rbig() + extent.as_rbig()
    };
    let reaches = !(inside(&x, &view.x, &view.width) && inside(&y, &view.y, &view.height));
    let (num, den) = MESA_ROUNDING;
    let latitude = RBig::from(num) / RBig::from(den);
    // The fraction of an edge past the pixel centre before it: in (0, ε).
    let just_past = |edge: RBig| {
        let past = &edge - RBig::from(1) / RBig::from(2);
        let fraction = &past - RBig::from(past.floor());
        fraction > RBig::ZERO && fraction < latitude
    };
    let edges = [
        view.x.as_rbig().clone(),
        view.y.as_rbig().clone(),
        view.x.as_rbig() + view.width.as_rbig(),
        view.y.as_rbig() + view.height.as_rbig(),
    ];
    let off = edges.into_iter().any(just_past);
    (reaches && off).then(|| {
        format!(
            "a point of size {} whose square reaches outside a viewport rectangle with an \
             edge less than 1/{den} px past a pixel centre: Mesa limits the square to the \
             rectangle rounded to whole pixels as (int)(x + 0.499) and (int)(x + width - 0.501) \
             (lp_setup.c), which departs from SPEC.md §17.2's centre rule there (SPEC.md §17.4)",
            point.size.to_exact_string()
        )
    })
}

/// Every point of the scene.
pub(crate) fn points(scene: &Scene) -> impl Iterator<Item = &Point> {
    scene.primitives.iter().filter_map(|p| match p {
        crate::scene::Primitive::Point(point) => Some(point),
        _ => None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{parse_case, Limits, Primitive, Vertex};

    /// A 16×16 scene (a 16×16 viewport at (4, 4) of a 24×24 canvas when
    /// `clip`) of one point at `at` (x, y, w) of side `size`.
    fn scene(clip: bool, at: [i64; 3], size: Number) -> Scene {
        let (canvas, view, v) = if clip {
            (
                24,
                r#""viewport": {"x": 4, "y": 4, "width": 16, "height": 16},"#,
                r#"{"clip": [0, 0, 0, 1]}"#,
            )
        } else {
            (16, "", "[0, 0]")
        };
        let text = format!(
            r#"{{"name": "p", "canvas": {{"width": {canvas}, "height": {canvas}}}, {view}
                "primitives": [{{"triangle": [{v}, {v}, {v}]}}]}}"#
        );
        let mut scene = parse_case(&text, "p.json", &Limits::default()).unwrap();
        let mut vertex = Vertex::at(Number::from_int(at[0]), Number::from_int(at[1]));
        vertex.w = Number::from_int(at[2]);
        scene.primitives = vec![Primitive::Point(Point {
            vertices: [vertex],
            size,
        })];
        scene
    }

    fn why(scene: &Scene, pops: bool) -> Option<String> {
        let offers = PointOffers {
            large: true,
            range: [1.0, 255.0],
            granularity: 0.125,
            subpixel_bits: 8,
            pops,
        };
        let Primitive::Point(p) = &scene.primitives[0] else {
            unreachable!()
        };
        refusal(scene, p, &offers)
    }

    #[test]
    fn sizes_the_driver_draws_exactly_pass_and_others_are_refused() {
        for (num, den, refused) in [
            (5, 2, None),
            (1, 1, None),
            (1, 2, Some("the driver draws sizes")),
            (257, 256, Some("steps of 0.125")),
            (1000, 1, Some("the driver draws sizes")),
            (1, 10, Some("the driver draws sizes")),
        ] {
            let scene = scene(false, [8, 8, 1], Number::ratio(num, den));
            let got = why(&scene, false);
            match refused {
                None => assert_eq!(got, None, "{num}/{den}"),
                Some(words) => assert!(got.unwrap().contains(words), "{num}/{den}"),
            }
        }
        // On a finer granularity, a half off the 8-bit grid is refused.
        let scene = scene(false, [8, 8, 1], Number::ratio(257, 256));
        let offers = PointOffers {
            large: true,
            range: [1.0, 255.0],
            granularity: 1.0 / 1024.0,
            subpixel_bits: 8,
            pops: false,
        };
        let Primitive::Point(p) = &scene.primitives[0] else {
            unreachable!()
        };
        assert!(refusal(&scene, p, &offers)
            .unwrap()
            .contains("off the driver's grid"));
        // A granularity of 0 is no step: any size in range on the grid.
        let continuous = PointOffers {
            large: true,
            range: [1.0, 1024.0],
            granularity: 0.0,
            subpixel_bits: 4,
            pops: false,
        };
        for (num, den, refused) in [(5, 2, false), (7, 1, false), (1, 2, true)] {
            let at = self::scene(false, [8, 8, 1], Number::ratio(num, den));
            let Primitive::Point(p) = &at.primitives[0] else {
                unreachable!()
            };
            let got = refusal(&at, p, &continuous);
            assert_eq!(got.is_some(), refused, "{num}/{den}: {got:?}");
        }
    }

    #[test]
    fn clip_squares_across_fractional_viewport_edges_and_popped_edges_are_refused() {
        // x = 0 is the viewport's centre, X = 12: a size-16 square fills it
        // exactly; size 17 reaches out.
        assert_eq!(
            why(&scene(true, [0, 0, 1], Number::from_int(16)), false),
            None
        );
        // Reaching out across whole-pixel edges is judged (under
        // `point_bounds: viewport`), and across an edge through pixel
        // centres; across one just past a centre, refused.
        assert_eq!(
            why(&scene(true, [0, 0, 1], Number::from_int(17)), false),
            None
        );
        let mut fractional = scene(true, [0, 0, 1], Number::from_int(17));
        fractional.viewport.as_mut().unwrap().x = Number::ratio(9, 2);
        assert_eq!(why(&fractional, false), None);
        fractional.viewport.as_mut().unwrap().x = Number::ratio(4609, 1024);
        let out = why(&fractional, false);
        assert!(out.unwrap().contains("past a pixel centre"));
        // w ≤ 0 is discarded by driver and rule alike.
        assert_eq!(
            why(&scene(true, [0, 0, -1], Number::from_int(17)), false),
            None
        );
        // Screen space: the edge matters only to a driver that pops.
        let edge = scene(false, [0, 8, 1], Number::from_int(4));
        assert_eq!(why(&edge, false), None);
        assert!(why(&edge, true).unwrap().contains("half a pixel inside"));
        assert_eq!(
            why(&scene(false, [8, 8, 1], Number::from_int(4)), true),
            None
        );
    }
}
