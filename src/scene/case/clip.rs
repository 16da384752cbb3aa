//! Reading clip space (SPEC.md §16): a vertex's `clip` coordinates, the
//! `viewport`, the clip-space rules, and the checks that keep a case in
//! one space: every vertex in clip space or none, and only what this
//! version defines for clip space (triangles and points; no antialiasing,
//! motion or `linear` interpolation).

use serde_json::Value;

use crate::scene::clip::{
    ClipRules, ClipXy, ClipZ, DepthMode, InterpolateFrom, PointBounds, PointClip, Viewport,
};
use crate::scene::model::{Canvas, Scene};
use crate::scene::number::Number;
use crate::scene::primitive::{Primitive, Vertex};
use crate::scene::rules::{limits, Interpolation};

use super::json::{array, fail, named, number, Fields, Path, Result};
use super::reader::Reader;
use super::validate::within;

/// The rules that only a clip-space case may give.
const CLIP_RULES: [&str; 6] = [
    "clip_xy",
    "clip_z",
    "depth",
    "interpolate_from",
    "clip_points",
    "point_bounds",
];

impl Reader<'_> {
    /// `rules.clip_xy`, `rules.clip_z`, `rules.depth`,
    /// `rules.interpolate_from`, `rules.clip_points` and
    /// `rules.point_bounds`.
    pub(super) fn clip_rules(&self, fields: &Fields, clip: &mut ClipRules) -> Result<()> {
        if let Some((v, p)) = fields.get("clip_xy") {
            clip.xy = named(v, &p, ClipXy::from_name, &ClipXy::NAMES)?;
        }
        if let Some((v, p)) = fields.get("clip_z") {
            clip.z = named(v, &p, ClipZ::from_name, &ClipZ::NAMES)?;
        }
        if let Some((v, p)) = fields.get("depth") {
            clip.depth = named(v, &p, DepthMode::from_name, &DepthMode::NAMES)?;
        }
        if let Some((v, p)) = fields.get("interpolate_from") {
            clip.values = named(v, &p, InterpolateFrom::from_name, &InterpolateFrom::NAMES)?;
        }
        if let Some((v, p)) = fields.get("clip_points") {
            clip.points = named(v, &p, PointClip::from_name, &PointClip::NAMES)?;
        }
        if let Some((v, p)) = fields.get("point_bounds") {
            clip.bounds = named(v, &p, PointBounds::from_name, &PointBounds::NAMES)?;
        }
        if let (DepthMode::Clamp, Some((_, p))) = (clip.depth, fields.get("clip_z")) {
            return fail(
                &p,
                "clip_z says how the near and far planes clip; under depth: clamp nothing is clipped by depth",
            );
        }
        Ok(())
    }

    /// A vertex given as `{"clip": [x, y, z, w], "attributes": [...]}`.
    pub(super) fn clip_vertex(
        &self,
        value: &Value,
        path: &Path,
        fields: &Fields,
    ) -> Result<Vertex> {
        for key in ["position", "from", "to", "z", "w"] {
            if let Some((_, p)) = fields.get(key) {
                return fail(
                    &p,
                    format!("a clip-space vertex gives clip: [x, y, z, w] and no {key}"),
                );
            }
        }
        let items = array(value, path)?;
        if items.len() != 4 {
            return fail(
                path,
                format!(
                    "clip coordinates are [x, y, z, w], found {} values",
                    items.len()
                ),
            );
        }
        let limit = Number::from_int(limits::CLIP_LIMIT);
        let mut c = Vec::with_capacity(4);
        for (i, (item, name)) in items.iter().zip(["x", "y", "z", "w"]).enumerate() {
            let n = number(item, &path.index(i))?;
            within(
                &n,
                &path.index(i),
                &-limit.clone(),
                &limit,
                &format!("clip {name}"),
            )?;
            c.push(n);
        }
        let [x, y, z, w]: [Number; 4] = c.try_into().expect("four values");
        Ok(Vertex {
            z,
            w,
            ..Vertex::at(x, y)
        })
    }

    /// The scene's viewport when its vertices are in clip space (the
    /// canvas, depth [0, 1], unless `viewport` says otherwise); `None` for
    /// a screen-space scene, which may not give one.
    pub(super) fn clip_space(&self, root: &Fields, canvas: &Canvas) -> Result<Option<Viewport>> {
        let in_clip = first_vertex(root, true).is_some();
        match (root.get("viewport"), in_clip) {
            (None, false) => Ok(None),
            (Some((_, p)), false) => fail(
                &p,
                "a viewport maps clip-space vertices ({\"clip\": [x, y, z, w]}); this case's vertices are in screen space",
            ),
            (None, true) => Ok(Some(Viewport::canvas(canvas.width, canvas.height))),
            (Some((v, p)), true) => self.viewport(v, &p, canvas).map(Some),
        }
    }

    fn viewport(&self, value: &Value, path: &Path, canvas: &Canvas) -> Result<Viewport> {
        let fields = Fields::new(
            value,
            path,
            &["x", "y", "width", "height", "min_depth", "max_depth"],
        )?;
        let mut viewport = Viewport::canvas(canvas.width, canvas.height);
        let coord = Number::from_int(limits::COORD_LIMIT);
        let side = Number::from_int(i64::from(limits::MAX_CANVAS_SIDE));
        let targets: [(&str, &mut Number, Number, Number); 6] = [
            ("x", &mut viewport.x, -coord.clone(), coord.clone()),
            ("y", &mut viewport.y, -coord.clone(), coord.clone()),
            ("width", &mut viewport.width, Number::ZERO, side.clone()),
            ("height", &mut viewport.height, Number::ZERO, side),
            (
                "min_depth",
                &mut viewport.min_depth,
                Number::ZERO,
                Number::ONE,
            ),
            (
                "max_depth",
                &mut viewport.max_depth,
                Number::ZERO,
                Number::ONE,
            ),
        ];
        for (key, target, low, high) in targets {
            if let Some((v, p)) = fields.get(key) {
                let n = number(v, &p)?;
                within(&n, &p, &low, &high, &format!("viewport {key}"))?;
                if matches!(key, "width" | "height") && !n.is_positive() {
                    return fail(&p, format!("the viewport {key} must be positive"));
                }
                *target = n;
            }
        }
        Ok(viewport)
    }

    /// Every vertex in one space; clip-space rules only in clip space; and
    /// what this version does not define for clip space refused by name.
    pub(super) fn check_clip_space(&self, scene: &Scene, root: &Fields) -> Result<()> {
        if !scene.in_clip_space() {
            if let Some((value, rules)) = root.get("rules") {
                for key in CLIP_RULES {
                    if value.get(key).is_some() {
                        return fail(
                            &rules.key(key),
                            format!("{key} is a clip-space rule; this case's vertices are in screen space (give them as {{\"clip\": [x, y, z, w]}})"),
                        );
                    }
                }
            }
            return Ok(());
        }
        if let Some(path) = first_vertex(root, false) {
            return fail(
                &path,
                "every vertex of a clip-space case is given as {\"clip\": [x, y, z, w]}; this one is in screen space",
            );
        }
        let primitives = Path::root().key("primitives");
        for (i, primitive) in scene.primitives.iter().enumerate() {
            match primitive {
                Primitive::Triangle(t) if t.interpolation == Interpolation::Linear => {
                    return fail(
                        &primitives.index(i).key("interpolation"),
                        "linear (screen-space) interpolation is not defined for clip-space triangles in this version (SPEC.md §16.6); use perspective or flat",
                    )
                }
                Primitive::Triangle(_) | Primitive::Point(_) => {}
                other => {
                    return fail(
                        &primitives.index(i),
                        format!(
                            "a clip-space case draws triangles and points; clip-space {}s are not defined in this version (SPEC.md §16)",
                            other.kind()
                        ),
                    )
                }
            }
        }
        let effects = Path::root().key("effects");
        if scene.effects.antialias.is_some() {
            return fail(
                &effects.key("antialias"),
                "antialiasing is not defined for clip-space cases in this version (SPEC.md §16)",
            );
        }
        if scene.effects.motion_blur.is_some() {
            return fail(
                &effects.key("motion_blur"),
                "motion blur is not defined for clip-space cases in this version (SPEC.md §16)",
            );
        }
        Ok(())
    }
}

/// The path of the first triangle, line or point vertex given in clip
/// space (`clip == true`) or in screen space (`clip == false`); a
/// polygon's vertices are screen-space positions.
fn first_vertex(root: &Fields, clip: bool) -> Option<Path> {
    let primitives = root.map.get("primitives")?.as_array()?;
    let base = Path::root().key("primitives");
    for (i, primitive) in primitives.iter().enumerate() {
        if let Some(vertex) = primitive.get("point") {
            if vertex.get("clip").is_some() == clip {
                return Some(base.index(i).key("point"));
            }
            continue;
        }
        for kind in ["triangle", "line", "polygon", "contours"] {
            let Some(vertices) = primitive.get(kind).and_then(Value::as_array) else {
                continue;
            };
            for (j, vertex) in vertices.iter().enumerate() {
                let is_clip = vertex.get("clip").is_some();
                if is_clip == clip {
                    return Some(base.index(i).key(kind).index(j));
                }
            }
        }
    }
    None
}
