//! A clip-space scene drawn: each point kept or discarded by its centre
//! (`../point.rs`), each triangle culled by its own winding, then clipped,
//! projected, rasterized and shaded piece by piece; the depths stored.

use dashu_ratio::RBig;

use super::clipper::{self, ClipVertex, NewVertex};
use super::homogeneous::{self, Piece};
use super::point;
use super::project::{Mapping, Projected};
use super::shade::Values;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::{ClipXy, ClipZ, Cull, DepthMode, InterpolateFrom, Primitive, Scene, Triangle};

/// Draws a clip-space scene.
pub fn rasterize(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    rasterize_with(scene, plan, clipper::new_vertex)
}

/// [`rasterize`] with the clipper's new vertices computed by `new`: tests
/// pass wrong ones to show that their checks catch them.
pub fn rasterize_with(scene: &Scene, plan: &Plan, new: NewVertex) -> Result<Frame, RasterError> {
    let viewport = scene.viewport.as_ref().ok_or_else(|| {
        RasterError::Unsupported("the clip-space path draws clip-space scenes only".to_owned())
    })?;
    if plan.antialias.is_some() || plan.motion.is_some() {
        return Err(RasterError::Unsupported(
            "a clip-space case neither antialiases nor moves (SPEC.md §16.1)".to_owned(),
        ));
    }
    // `interpolate_from: unsnapped`: values come from the exact projected
    // positions, and the depth written is held to the depth range
    // (SPEC.md §16.5).
    let from_unsnapped = scene.rules.clip.values == InterpolateFrom::Unsnapped;
    let clamp = scene.rules.clip.depth == DepthMode::Clamp || from_unsnapped;
    let mapping = Mapping::new(viewport, scene.rules.subpixel_bits, clamp);
    // Only where something reads a value: coverage alone is the snapped
    // piece's.
    let reads_values = plan.interpolates()
        || (scene.rules.clip.depth == DepthMode::Clip && scene.rules.clip.z == ClipZ::PerSample);
    let unsnapped = (from_unsnapped && reads_values && scene.rules.subpixel_bits.is_some())
        .then(|| Mapping::new(viewport, None, clamp));
    let canvas = [
        [0, i64::from(scene.canvas.width)],
        [0, i64::from(scene.canvas.height)],
    ];
    // Under the guard band a sample outside the viewport rectangle is not
    // covered: the rectangle bounds every piece's samples.
    let limit = match scene.rules.clip.xy {
        ClipXy::GuardBand => {
            let rect = mapping.pixel_rectangle();
            [0, 1].map(|k| [canvas[k][0].max(rect[k][0]), canvas[k][1].min(rect[k][1])])
        }
        ClipXy::ClipThenSnap => canvas,
    };
    let mut frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, plan);
    for (index, primitive) in scene.primitives.iter().enumerate() {
        if index % 16 == 0 {
            // The per-case time limit, polled every few primitives.
            crate::deadline::check();
        }
        let triangle = match primitive {
            Primitive::Triangle(triangle) => triangle,
            Primitive::Point(point) => {
                point::draw_clip(point, scene, &mapping, plan, index, &mut frame);
                continue;
            }
            _ => {
                return Err(RasterError::Unsupported(format!(
                    "a clip-space case draws triangles and points only (SPEC.md §16.1), primitive {index} is a {}",
                    primitive.kind()
                )))
            }
        };
        let draw = Draw {
            scene,
            plan,
            mapping: &mapping,
            unsnapped: unsnapped.as_ref(),
            limit,
            index,
        };
        draw.triangle(triangle, new, &mut frame);
    }
    crate::production::depth::store_all(scene.rules.depth_format, &mut frame);
    Ok(frame)
}

/// One primitive's drawing context.
struct Draw<'a> {
    scene: &'a Scene,
    plan: &'a Plan,
    mapping: &'a Mapping,
    /// The mapping without snapping, when values are interpolated from
    /// the unsnapped positions.
    unsnapped: Option<&'a Mapping>,
    /// The pixels any sample may lie in, half-open [[x0, x1], [y0, y1]].
    limit: [[i64; 2]; 2],
    index: usize,
}

impl Draw<'_> {
    /// Culls the triangle by its own winding, clips it, and draws its fan.
    fn triangle(&self, triangle: &Triangle, new: NewVertex, frame: &mut Frame) {
        let rules = &self.scene.rules;
        let original = triangle.vertices.each_ref().map(ClipVertex::of);
        let h = original.each_ref().map(|v| self.mapping.project(v));
        let d = det(&h);
        let culled = match rules.cull {
            Cull::None => false,
            Cull::Clockwise => d > RBig::ZERO,
            Cull::CounterClockwise => d < RBig::ZERO,
        };
        if culled {
            return;
        }
        let flat = original[rules.provoking_vertex.index(3)].attributes.clone();
        let polygon = clipper::clip(original.into(), rules.clip.clipped_planes(), new);
        let projected: Vec<Projected> = polygon.iter().map(|v| self.mapping.project(v)).collect();
        let exact: Option<Vec<Projected>> = self
            .unsnapped
            .map(|m| polygon.iter().map(|v| m.project(v)).collect());
        for [a, b, c] in clipper::fan(polygon.len()) {
            let pick = |p: &[Projected]| [&p[a], &p[b], &p[c]].map(Clone::clone);
            let h = pick(&projected);
            let vertices = [&polygon[a], &polygon[b], &polygon[c]];
            let exact = exact.as_deref().map(pick);
            self.piece(&h, exact.as_ref(), vertices, triangle, &flat, frame);
        }
    }

    /// Tests and writes every sample of one piece's region; its values
    /// from `exact`, the piece unsnapped, when given and of some area.
    fn piece(
        &self,
        h: &[Projected; 3],
        exact: Option<&[Projected; 3]>,
        vertices: [&ClipVertex; 3],
        triangle: &Triangle,
        flat: &[RBig],
        frame: &mut Frame,
    ) {
        let rules = &self.scene.rules;
        let Some(piece) = Piece::new(h, rules.fill_rule) else {
            return;
        };
        let values_of = |piece: &Piece, h: &[Projected; 3], mapping: &Mapping, extrapolated| {
            let values = Values::new(
                piece,
                h,
                vertices,
                triangle.interpolation,
                flat,
                self.plan,
                mapping,
                extrapolated,
            );
            match &rules.depth_bias {
                Some(bias) if self.plan.depth => {
                    values.with_offset(bias, rules.depth_format, piece, vertices, mapping)
                }
                _ => values,
            }
        };
        let values = values_of(&piece, h, self.mapping, false);
        let unsnapped = exact.and_then(|h| {
            let mapping = self
                .unsnapped
                .expect("exact positions come with their mapping");
            Piece::new(h, rules.fill_rule).map(|p| (values_of(&p, h, mapping, true), p))
        });
        let depth_test = rules.clip.depth == DepthMode::Clip && rules.clip.z == ClipZ::PerSample;
        let [[x0, x1], [y0, y1]] = homogeneous::region(h, self.limit);
        let width = frame.width as usize;
        for py in y0..y1 {
            // A piece with a vertex behind the eye visits the whole canvas:
            // the time limit is polled every row.
            crate::deadline::check();
            for px in x0..x1 {
                let e = piece.at(px, py);
                if !piece.covers(&e) {
                    continue;
                }
                // Where the unsnapped piece's plane does not reach in
                // front of the eye, the snapped piece's values stand.
                let (values, e) = match &unsnapped {
                    Some((v, p)) => {
                        let eu = p.at(px, py);
                        if v.in_front(&eu) {
                            (v, eu)
                        } else {
                            (&values, e)
                        }
                    }
                    None => (&values, e),
                };
                if depth_test && !values.depth_inside(&e) {
                    continue;
                }
                let i = py as usize * width + px as usize;
                frame.hit(i, self.index);
                values.write(frame, i, &e, self.mapping);
            }
        }
    }
}

/// D = det[H_0, H_1, H_2], exact: positive when the triangle runs
/// clockwise on the screen (y down).
fn det(h: &[Projected; 3]) -> RBig {
    let [a, b, c] = h.each_ref().map(|p| &p.h);
    &a[0] * (&b[1] * &c[2] - &b[2] * &c[1]) - &a[1] * (&b[0] * &c[2] - &b[2] * &c[0])
        + &a[2] * (&b[0] * &c[1] - &b[1] * &c[0])
}
