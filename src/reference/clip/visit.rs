//! Visiting a clip-space scene (SPEC.md §16): each point kept or discarded
//! by its centre (`point.rs`) and drawn by `../point.rs`; each triangle culled, clipped
//! (`clipper.rs`), fanned, and each piece's samples decided by homogeneous
//! edge functions (`homogeneous.rs`), with the viewport's pixel ranges.

use dashu_int::IBig;
use dashu_ratio::RBig;

use super::clipper::{self, ClipVertex};
use super::homogeneous::{self, Homogeneous};
use super::point::clip_square;
use crate::reference::point;
use crate::reference::values::Values;
use crate::scene::{
    ClipXy, ClipZ, DepthMode, FillRule, InterpolateFrom, Interpolation, PointBounds, Primitive,
    Scene,
};

/// Visits every covered pixel centre of every triangle of a clip-space
/// scene under `rule`, in scene order: `visit(primitive, pixel, values)`,
/// the values only when `with_values`.
pub fn visit<F>(scene: &Scene, rule: FillRule, with_values: bool, mut visit: F)
where
    F: FnMut(usize, usize, Option<Values>),
{
    let viewport = scene.viewport.as_ref().expect("a clip-space scene");
    let clip = scene.rules.clip;
    let bits = scene.rules.subpixel_bits;
    let canvas = scene.canvas;
    let (min_d, max_d) = (viewport.min_depth.as_rbig(), viewport.max_depth.as_rbig());
    let depth_low = min_d.min(max_d).clone();
    let depth_high = min_d.max(max_d).clone();
    let per_sample_z = clip.depth == DepthMode::Clip && clip.z == ClipZ::PerSample;
    let needs_depth = with_values || per_sample_z;
    // The canvas's pixels, and those whose centre lies in the viewport
    // rectangle: x + ½ in [vx, vx + vw). The guard band lets the latter
    // through, as `point_bounds: viewport` does a kept point's square.
    let whole = [0..i64::from(canvas.width), 0..i64::from(canvas.height)];
    let in_viewport = [
        within(&whole[0], viewport.x.as_rbig(), viewport.width.as_rbig()),
        within(&whole[1], viewport.y.as_rbig(), viewport.height.as_rbig()),
    ];
    let [columns, rows] = match clip.xy {
        ClipXy::GuardBand => in_viewport.clone(),
        ClipXy::ClipThenSnap => whole.clone(),
    };
    let point_pixels = match clip.bounds {
        PointBounds::Canvas => whole,
        PointBounds::Viewport => in_viewport,
    };
    let width = i64::from(canvas.width);
    for (index, primitive) in scene.primitives.iter().enumerate() {
        crate::deadline::check();
        if let Primitive::Point(point) = primitive {
            // Kept or discarded whole by its centre (SPEC.md §17.2); its
            // square is limited by the canvas, and by the viewport
            // rectangle under `point_bounds: viewport`.
            if let Some((square, values)) = clip_square(point, viewport, clip, bits) {
                point::visit(&square, rule, canvas, |pixel| {
                    let (px, py) = (pixel as i64 % width, pixel as i64 / width);
                    if point_pixels[0].contains(&px) && point_pixels[1].contains(&py) {
                        visit(index, pixel, with_values.then(|| values.clone()))
                    }
                });
            }
            continue;
        }
        let Primitive::Triangle(triangle) = primitive else {
            unreachable!("the reader refuses other primitives in clip space")
        };
        let original = triangle.vertices.each_ref().map(ClipVertex::of);
        let winding = homogeneous::winding(&original, viewport, bits);
        // A triangle of no winding is never culled: its pieces, snapped
        // apart, may have an area of their own (SPEC.md §16.4).
        if scene.rules.cull.discards(winding.cmp(&0)) {
            continue;
        }
        let provoking = scene.rules.provoking_vertex.index(3);
        let flat = original[provoking].attributes.clone();
        let polygon = clipper::clip(original.to_vec(), clip.clipped_planes());
        for i in 1..polygon.len().saturating_sub(1) {
            let piece = [&polygon[0], &polygon[i], &polygon[i + 1]].map(Clone::clone);
            let Some(h) = Homogeneous::new(&piece, viewport, bits, rule) else {
                continue;
            };
            // The triangle values are interpolated over (SPEC.md §16.5):
            // the snapped one, or the exact one before snapping, unless
            // that one has no area; built only where a value is read
            // (coverage alone is the snapped piece's).
            let unsnapped =
                (needs_depth && clip.values == InterpolateFrom::Unsnapped && bits.is_some())
                    .then(|| Homogeneous::new(&piece, viewport, None, rule))
                    .flatten();
            // The piece's offset (SPEC.md §18.2), its slope read from the
            // plane its depth is interpolated over: the reader keeps every
            // w > 0 under depth_bias, so the piece is a screen triangle
            // whose depth z_f is a plane and whose vertices have a depth.
            let offset = scene
                .rules
                .depth_bias
                .as_ref()
                .filter(|_| with_values)
                .map(|bias| {
                    let range = max_d - min_d;
                    let gradient = unsnapped
                        .as_ref()
                        .unwrap_or(&h)
                        .depth_gradient()
                        .map(|g| &range * g);
                    let largest = piece
                        .iter()
                        .map(|v| {
                            let z_f = min_d + &range * (&v.c[2] / &v.c[3]);
                            if z_f < RBig::ZERO {
                                -z_f
                            } else {
                                z_f
                            }
                        })
                        .max()
                        .expect("three");
                    crate::reference::depth::offset_interval(
                        bias,
                        scene.rules.depth_format,
                        &gradient,
                        &largest,
                    )
                });
            let (mut xs, mut ys) = (columns.clone(), rows.clone());
            if let Some([x0, x1, y0, y1]) = &h.bounded {
                xs = centres_between(&xs, x0, x1);
                ys = centres_between(&ys, y0, y1);
            }
            for py in ys {
                crate::deadline::check();
                for px in xs.clone() {
                    let Some(e) = h.covers(px, py) else {
                        continue;
                    };
                    // A sample the unsnapped triangle's plane does not
                    // reach in front of the eye takes the snapped one's.
                    let (v, e) = match &unsnapped {
                        Some(u) => {
                            let eu = u.edge_values(px, py);
                            if u.weight(&eu) > RBig::ZERO {
                                (u, eu)
                            } else {
                                (&h, e)
                            }
                        }
                        None => (&h, e),
                    };
                    let z_ndc = needs_depth.then(|| v.depth(&e));
                    if per_sample_z {
                        let z = z_ndc.as_ref().expect("computed");
                        if *z < RBig::ZERO || *z > RBig::ONE {
                            continue;
                        }
                    }
                    let pixel = (py * i64::from(canvas.width) + px) as usize;
                    let values = with_values.then(|| {
                        let z_ndc = z_ndc.expect("computed");
                        let unclamped = min_d + (max_d - min_d) * z_ndc;
                        // Values from the unsnapped positions may reach a
                        // hair beyond a plane the snapped piece was cut
                        // by: the range holds them (SPEC.md §16.5).
                        let hold = clip.depth == DepthMode::Clamp
                            || clip.values == InterpolateFrom::Unsnapped;
                        let clamped = |depth: RBig| {
                            if hold {
                                depth.clamp(depth_low.clone(), depth_high.clone())
                            } else {
                                depth
                            }
                        };
                        let depth_interval = match &offset {
                            Some([lo, hi]) => [&unclamped + lo, &unclamped + hi].map(clamped),
                            None => [0, 1].map(|_| clamped(unclamped.clone())),
                        };
                        let depth = clamped(unclamped);
                        let attributes = (0..flat.len())
                            .map(|k| match triangle.interpolation {
                                Interpolation::Flat => flat[k].clone(),
                                _ => v.perspective(&e, k),
                            })
                            .collect();
                        Values {
                            depth,
                            depth_interval,
                            attributes,
                        }
                    });
                    visit(index, pixel, values);
                }
            }
        }
    }
}

/// The pixels of `range` whose centre p + ½ lies in [origin, origin + size).
fn within(range: &std::ops::Range<i64>, origin: &RBig, size: &RBig) -> std::ops::Range<i64> {
    let half = RBig::from_parts(IBig::ONE, 2u8.into());
    let first = ceil(&(origin - &half));
    let end = ceil(&(origin + size - &half));
    first.max(range.start)..end.min(range.end).max(first.max(range.start))
}

/// The pixels of `range` whose centre p + ½ lies in [low, high].
fn centres_between(range: &std::ops::Range<i64>, low: &RBig, high: &RBig) -> std::ops::Range<i64> {
    let half = RBig::from_parts(IBig::ONE, 2u8.into());
    let first = ceil(&(low - &half)).max(range.start);
    let last = floor(&(high - &half)).min(range.end - 1);
    first..(last + 1).max(first)
}

fn floor(q: &RBig) -> i64 {
    let f = q.floor();
    i64::try_from(f.clamp(IBig::from(i64::MIN / 2), IBig::from(i64::MAX / 2))).expect("clamped")
}

fn ceil(q: &RBig) -> i64 {
    let c = q.ceil();
    i64::try_from(c.clamp(IBig::from(i64::MIN / 2), IBig::from(i64::MAX / 2))).expect("clamped")
}
