//! `foil-empty-antialias`: an area method that answers every antialiased
//! scene with nothing: each primitive's coverage an empty list, no step
//! declared (as a program answering `{"coverage": []}` does, issue 40).
//! **A foil**, wrong everywhere something is drawn: held to the exact
//! area within the default step (SPEC.md §14.4), it fails every case in
//! which some primitive covers more than one step of some pixel, and
//! passes only those where none does. It draws no single-sample scene.

use crate::frame::{Frame, Parts};
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::Scene;

/// The empty area method.
#[derive(Clone, Copy, Debug, Default)]
pub struct EmptyAntialias;

impl Rasterizer for EmptyAntialias {
    fn name(&self) -> &str {
        "foil-empty-antialias"
    }

    fn is_foil(&self) -> bool {
        true
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            triangles: true,
            polygons: true,
            antialias: true,
            ideal_geometry: true,
            ..Capabilities::none()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        if plan.antialias.is_none() {
            return Err(RasterError::Unsupported(
                "foil-empty-antialias answers antialiased scenes only".to_owned(),
            ));
        }
        let (w, h) = (scene.canvas.width, scene.canvas.height);
        let zero = vec![0.0; scene.canvas.pixel_count()];
        let mut frame = Frame::resolved_only(w, h, zero);
        frame.parts = Some(Parts {
            coverage: vec![Vec::new(); scene.primitives.len()],
            step: 0.0,
            saturates: false,
        });
        frame.coverage_only = true;
        Ok(frame)
    }
}
