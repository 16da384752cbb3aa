//! Reading points (SPEC.md §17): `{"point": vertex, "size": n}`, and the
//! checks that keep a point to what this version defines for it (no
//! interpolation mode, no antialiasing, no motion).

use serde_json::Value;

use crate::scene::model::Scene;
use crate::scene::number::Number;
use crate::scene::primitive::{Point, Primitive};
use crate::scene::rules::limits;

use super::json::{fail, number, Fields, Path, Result};
use super::reader::Reader;
use super::validate::positive_length;

impl Reader<'_> {
    /// `{"point": <vertex>, "size": <number, default 1>}`: the vertex in any
    /// form a triangle's takes, the size in (0, MAX_POINT_SIZE].
    pub(super) fn point(&self, value: &Value, path: &Path) -> Result<Primitive> {
        let fields = Fields::new(value, path, &["point", "size", "interpolation"])?;
        if let Some((_, p)) = fields.get("interpolation") {
            return fail(
                &p,
                "a point takes no interpolation: its depth and attributes are the vertex's at every sample (SPEC.md §17.1)",
            );
        }
        let (vertex, vertex_path) = fields.require("point")?;
        let vertex = self.vertex(vertex, &vertex_path)?;
        let size = match fields.get("size") {
            Some((v, p)) => {
                let size = number(v, &p)?;
                positive_length(&size, &p, limits::MAX_POINT_SIZE, "a point size", "size")?;
                size
            }
            None => Number::ONE,
        };
        Ok(Primitive::Point(Point {
            vertices: [vertex],
            size,
        }))
    }

    /// Points are not defined with antialiasing or motion in this version:
    /// the first point of such a scene is refused by its path.
    pub(super) fn check_points(&self, scene: &Scene) -> Result<()> {
        let Some(i) = scene
            .primitives
            .iter()
            .position(|p| matches!(p, Primitive::Point(_)))
        else {
            return Ok(());
        };
        let path = Path::root().key("primitives").index(i);
        if scene.effects.antialias.is_some() {
            return fail(
                &path,
                "points are not defined with effects.antialias in this version (SPEC.md §17); a point is drawn at pixel centres only",
            );
        }
        if let Some(j) = scene.primitives.iter().position(Primitive::moves) {
            if matches!(scene.primitives[j], Primitive::Point(_)) {
                return fail(
                    &Path::root().key("primitives").index(j),
                    "a moving point is not defined in this version (SPEC.md §17); move triangles or parallelogram lines",
                );
            }
        }
        if scene.effects.motion_blur.is_some() {
            return fail(
                &path,
                "points are not defined with effects.motion_blur in this version (SPEC.md §17)",
            );
        }
        Ok(())
    }
}
