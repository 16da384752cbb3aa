//! The polygon methods that are rasterizers of their own (polygons only,
//! one sample per pixel): `polygon-convex`, `polygon-tessellate` and the
//! `flood-fill` foil.

use super::contour::nudge;
use super::{convex, flood, tessellate};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::fixed::Format;
use crate::production::method::Method;
use crate::production::scene_format::format_for;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::Polygon;
use crate::scene::{Primitive, Scene};

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
        let format = format_for(scene, None)?;
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
