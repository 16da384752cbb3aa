//! Polygons in production (SPEC.md §14.1): scanline fill with an edge table
//! and an active edge table (`scanline.rs`), and the other polygon methods
//! measured beside it: convex span fill (`convex.rs`), ear-clipping into
//! production's triangles (`tessellate.rs`), and the outline-and-flood-fill
//! foil (`flood.rs`).
//!
//! What this does not do: interpolate (polygons carry positions only), or
//! fill under `all-edges`, which SPEC.md leaves undefined for polygons.

pub mod convex;
pub mod flood;
pub mod scanline;
pub mod tessellate;

use scanline::{Nudge, Point, Samples};

use super::fixed::{self, EdgeInt, Format};
use super::method::Method;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{Number, Polygon, Primitive, Scene};

/// Draws polygon `index` of the scene into `frame`: one scanline fill per
/// sample of the pixel, each into its slot.
///
/// `E` is the caller's edge-function width; the scanline carries its one
/// product per edge in i128 and steps in i64 whatever it is (see
/// [`scanline::Walk`]).
pub fn draw<E: EdgeInt>(
    scene: &Scene,
    plan: &Plan,
    format: Format,
    index: usize,
    polygon: &Polygon,
    frame: &mut Frame,
) -> Result<(), RasterError> {
    let nudge = nudge(scene)?;
    let contours = snapped(scene, format, polygon)?;
    let one = format.one();
    match &plan.antialias {
        None => {
            let half = format.centre(0).0;
            let samples = Samples {
                one,
                offset: [half, half],
                slot: 0,
                nudge,
            };
            scanline::fill(
                &contours,
                polygon.fill,
                &samples,
                scene.canvas,
                frame,
                index,
            );
        }
        Some(sample_plan) => {
            // Sample s of pixel p lies at p + offsets[s]·2^-position_bits:
            // an integer in the format only when it is at least as fine.
            let Some(shift) = format.frac_bits.checked_sub(sample_plan.position_bits) else {
                return Err(RasterError::Failed(format!(
                    "the fixed-point format has {} fraction bits, fewer than the {} of the sample positions",
                    format.frac_bits, sample_plan.position_bits
                )));
            };
            if frame.samples as usize != sample_plan.offsets.len() {
                return Err(RasterError::Failed(format!(
                    "the frame holds {} samples per pixel, the plan {}",
                    frame.samples,
                    sample_plan.offsets.len()
                )));
            }
            // Adaptive sampling (only pixels an edge touches) is not worth
            // it here: a span already costs one write per sample, so every
            // slot is filled by its own scanline pass, adaptive or not, and
            // the result is the same.
            for (slot, offset) in sample_plan.offsets.iter().enumerate() {
                let samples = Samples {
                    one,
                    offset: offset.map(|o| i64::from(o) << shift),
                    slot,
                    nudge,
                };
                scanline::fill(
                    &contours,
                    polygon.fill,
                    &samples,
                    scene.canvas,
                    frame,
                    index,
                );
            }
        }
    }
    Ok(())
}

/// The nudge of the scene's fill rule.
fn nudge(scene: &Scene) -> Result<Nudge, RasterError> {
    Nudge::of(scene.rules.fill_rule).ok_or_else(|| {
        RasterError::Unsupported("all-edges is not defined for polygons (SPEC.md §14.1)".to_owned())
    })
}

/// A coordinate in `format`, snapped as the scene says, or held exactly
/// when the scene keeps exact coordinates (as production does for
/// triangles).
fn place(scene: &Scene, format: Format, n: &Number) -> Result<i64, RasterError> {
    match scene.rules.subpixel_bits {
        Some(bits) => Ok(format.snap(n, bits).0),
        None => format.exact(n).map(|f| f.0).ok_or_else(|| {
            RasterError::Unsupported(format!(
                "the coordinate {} is not a multiple of 2^-{}",
                n.to_exact_string(),
                format.frac_bits
            ))
        }),
    }
}

/// Every contour's vertices, snapped, in `format`.
fn snapped(
    scene: &Scene,
    format: Format,
    polygon: &Polygon,
) -> Result<Vec<Vec<Point>>, RasterError> {
    polygon
        .contours()
        .map(|contour| {
            contour
                .iter()
                .map(|v| Ok([place(scene, format, &v.x)?, place(scene, format, &v.y)?]))
                .collect()
        })
        .collect()
}

/// The one contour of a polygon, snapped and without repeats, for the
/// methods that fill a single contour; `method` names the one that refuses
/// several.
fn single_contour(
    scene: &Scene,
    format: Format,
    polygon: &Polygon,
    method: &str,
) -> Result<Vec<Point>, RasterError> {
    let contours = snapped(scene, format, polygon)?;
    match contours.as_slice() {
        [contour] => Ok(without_repeats(contour)),
        _ => Err(RasterError::Unsupported(format!(
            "{method} fills one contour, not {}",
            contours.len()
        ))),
    }
}

/// The vertices of a closed contour without consecutive repeats (the
/// last vertex counts as followed by the first): a repeated vertex adds a
/// zero-length edge, which changes no winding number.
fn without_repeats(contour: &[Point]) -> Vec<Point> {
    let mut points: Vec<Point> = Vec::with_capacity(contour.len());
    for &p in contour {
        if points.last() != Some(&p) {
            points.push(p);
        }
    }
    while points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
    points
}

/// (b − a) × (c − b): positive when a, b, c turn clockwise on screen (y
/// down). Differences are below 2^(16 + f) ≤ 2^33, so products fit i128.
fn turn(a: Point, b: Point, c: Point) -> i128 {
    let d = |u: i64, v: i64| i128::from(u) - i128::from(v);
    d(b[0], a[0]) * d(c[1], b[1]) - d(b[1], a[1]) * d(c[0], b[0])
}

/// The format production uses for a scene: one bit finer than the snapping
/// grid, or the finest dyadic format exact coordinates need.
fn format_for(scene: &Scene) -> Result<Format, RasterError> {
    match scene.rules.subpixel_bits {
        Some(bits) => Ok(Format::snapped(bits)),
        None => Format::for_exact(scene.vertices().flat_map(|v| [&v.x, &v.y])).ok_or_else(|| {
            RasterError::Unsupported(format!(
                "unsnapped coordinates must be multiples of 2^-{} to be held in fixed point",
                fixed::MAX_FRAC_BITS - 1
            ))
        }),
    }
}

/// Draws one polygon of a scene, already checked to hold only polygons.
type DrawPolygon = fn(&Scene, Format, usize, &Polygon, &mut Frame) -> Result<(), RasterError>;

/// A polygon method that is a rasterizer of its own: polygons only, one
/// sample per pixel.
struct PolygonMethod {
    name: &'static str,
    foil: bool,
    draw: DrawPolygon,
}

impl Rasterizer for PolygonMethod {
    fn name(&self) -> &str {
        self.name
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            triangles: false,
            polygons: true,
            antialias: false,
            motion_blur: false,
            clip_space: false,
            points: false,
            ..Capabilities::everything()
        }
    }

    fn is_foil(&self) -> bool {
        self.foil
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        if plan.antialias.is_some() {
            return Err(RasterError::Unsupported(format!(
                "{} does not antialias",
                self.name
            )));
        }
        if let Some(other) = scene
            .primitives
            .iter()
            .find(|p| !matches!(p, Primitive::Polygon(_)))
        {
            return Err(RasterError::Unsupported(format!(
                "{} draws polygons only, not a {}",
                self.name,
                other.kind()
            )));
        }
        nudge(scene)?;
        let format = format_for(scene)?;
        let mut frame = Frame::new(
            scene.canvas.width,
            scene.canvas.height,
            plan.depth,
            plan.attributes,
        );
        for (index, primitive) in scene.primitives.iter().enumerate() {
            if let Primitive::Polygon(polygon) = primitive {
                (self.draw)(scene, format, index, polygon, &mut frame)?;
            }
        }
        Ok(frame)
    }
}

/// The polygon methods that are rasterizers of their own.
pub fn methods() -> Vec<Method> {
    vec![
        Method {
            name: "polygon-convex",
            make: || {
                Box::new(PolygonMethod {
                    name: "polygon-convex",
                    foil: false,
                    draw: convex::draw,
                })
            },
        },
        Method {
            name: "polygon-tessellate",
            make: || {
                Box::new(PolygonMethod {
                    name: "polygon-tessellate",
                    foil: false,
                    draw: tessellate::draw,
                })
            },
        },
        Method {
            name: "flood-fill",
            make: || {
                Box::new(PolygonMethod {
                    name: "flood-fill",
                    foil: true,
                    draw: flood::draw,
                })
            },
        },
    ]
}
