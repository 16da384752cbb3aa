//! What the case reader checks beyond each value's kind: the documented
//! range of a number (`within`, called by the walk where it reads the
//! value, so the error names that value's path), and the checks across
//! fields on the whole scene once it is read: every vertex carries the same
//! attributes, rules, primitives, effects and expectations that are valid
//! alone but not together, motion's conditions, and the sample limit.
//!
//! Not here: how a field is read (`schema.rs`), or the JSON access layer
//! (`json.rs`).

use crate::scene::model::Scene;
use crate::scene::number::Number;
use crate::scene::primitive::Primitive;
use crate::scene::rules::{FillRule, LineRule};

use super::json::{fail, Fields, Path, Result};
use super::reader::Reader;

pub(super) fn within(
    n: &Number,
    path: &Path,
    low: &Number,
    high: &Number,
    what: &str,
) -> Result<()> {
    if n < low || n > high {
        return fail(
            path,
            format!(
                "{what} {} is outside the documented range [{low}, {high}]",
                crate::scene::number::echo_number(n)
            ),
        );
    }
    Ok(())
}

/// A length that must be positive and at most `high` pixels: a line's
/// width, a point's size. `what` names it in the error ("a line width"),
/// `short` in the range error ("width").
pub(super) fn positive_length(
    n: &Number,
    path: &Path,
    high: i64,
    what: &str,
    short: &str,
) -> Result<()> {
    if !n.is_positive() {
        return fail(path, format!("{what} must be positive, found {n}"));
    }
    within(n, path, &Number::ZERO, &Number::from_int(high), short)
}

impl Reader<'_> {
    /// Every vertex of a case carries the same number of attributes, so that
    /// every pixel of the frame has the same channels.
    pub(super) fn check_attribute_counts(&self, scene: &Scene, path: &Path) -> Result<()> {
        for (i, primitive) in scene.primitives.iter().enumerate() {
            let kind = primitive.kind();
            for (j, v) in primitive.vertices().iter().enumerate() {
                if v.attributes.len() != scene.attribute_count {
                    return fail(
                        &path.index(i).key(kind).index(j).key("attributes"),
                        format!(
                            "this vertex has {} attributes but the first vertex of the case has {}; every vertex carries the same number",
                            v.attributes.len(),
                            scene.attribute_count
                        ),
                    );
                }
            }
        }
        Ok(())
    }

    /// Pixels × spatial samples × time samples within `max_samples`; time
    /// samples count only when something moves (otherwise no time loop
    /// runs, SPEC.md §15.1).
    pub(super) fn check_samples(&self, scene: &Scene) -> Result<()> {
        let pixels = u64::from(scene.canvas.width) * u64::from(scene.canvas.height);
        let spatial = scene.effects.antialias.as_ref().map_or(1, |a| a.samples);
        let time = match &scene.effects.motion_blur {
            Some(blur) if scene.moves() => blur.samples,
            _ => 1,
        };
        // At most 2^28 · 2^8 · 2^10: no overflow.
        let total = pixels * u64::from(spatial) * u64::from(time);
        if total <= self.limits.max_samples {
            return Ok(());
        }
        let effects = Path::root().key("effects");
        let (path, factors) = match (spatial, time) {
            (1, 1) => (Path::root().key("canvas"), String::new()),
            (s, 1) => (
                effects.key("antialias").key("samples"),
                format!(" × {s} samples"),
            ),
            (1, t) => (
                effects.key("motion_blur").key("samples"),
                format!(" × {t} time samples"),
            ),
            (s, t) => (
                effects.key("motion_blur").key("samples"),
                format!(" × {s} samples × {t} time samples"),
            ),
        };
        self.over(
            &path,
            format!(
                "{pixels} pixels{factors} = {total} sample points exceed the limit of {} (raise it with --max-samples)",
                self.limits.max_samples
            ),
        )
    }

    /// Rules, primitives, effects and expectations that are each valid
    /// alone but not together.
    pub(super) fn check_combinations(&self, scene: &Scene, fields: &Fields) -> Result<()> {
        let primitives_path = Path::root().key("primitives");
        if scene.rules.fill_rule == FillRule::AllEdges {
            if let Some(i) = scene
                .primitives
                .iter()
                .position(|p| matches!(p, Primitive::Polygon(_)))
            {
                return fail(
                    &primitives_path.index(i),
                    "a polygon needs one of the four consistent tie rules (top-left, top-right, bottom-left, bottom-right), not all-edges",
                );
            }
        }
        let antialias = scene.effects.antialias.is_some();
        if antialias {
            for (i, primitive) in scene.primitives.iter().enumerate() {
                let Primitive::Line(line) = primitive else {
                    continue;
                };
                let why = match line.rule {
                    LineRule::Midpoint | LineRule::DiamondExit => format!(
                        "a {} line chooses whole pixels and has no samples; antialiasing samples triangles, polygons and parallelogram lines",
                        line.rule.name()
                    ),
                    LineRule::Rectangle => "a rectangle line has irrational corners, so its exact area coverage is not a rational number; antialias parallelogram lines".to_owned(),
                    LineRule::Parallelogram => continue,
                };
                return fail(&primitives_path.index(i), why);
            }
        }
        self.check_motion(scene, fields)?;
        if !antialias {
            let e = &scene.expect;
            let given = [
                ("max_coverage_error", e.max_coverage_error.is_some()),
                ("max_coverage_rms", e.max_coverage_rms.is_some()),
                ("area", e.area.is_some()),
            ];
            if let (Some((key, _)), Some((_, expect_path))) =
                (given.iter().find(|(_, g)| *g), fields.get("expect"))
            {
                return fail(
                    &expect_path.key(key),
                    format!(
                        "{key} measures antialiased coverage; the case needs effects.antialias"
                    ),
                );
            }
        }
        Ok(())
    }

    /// Moving primitives need `effects.motion_blur`, move only as triangles
    /// and parallelogram lines, and carry positions only; time expectations
    /// need something that moves (SPEC.md §15).
    pub(super) fn check_motion(&self, scene: &Scene, fields: &Fields) -> Result<()> {
        let primitives_path = Path::root().key("primitives");
        let moving = scene.primitives.iter().position(Primitive::moves);
        if let Some(i) = moving {
            let path = primitives_path.index(i);
            let primitive = &scene.primitives[i];
            if scene.effects.motion_blur.is_none() {
                return fail(
                    &path,
                    "this primitive moves (a vertex gives from and to), so the case needs effects.motion_blur",
                );
            }
            for (i, primitive) in scene.primitives.iter().enumerate() {
                if !primitive.moves() {
                    continue;
                }
                let why = match primitive {
                    Primitive::Point(_) => "a moving point is not defined in this version (SPEC.md §17); move triangles or parallelogram lines",
                    Primitive::Polygon(_) => "a polygon cannot move in this version of rastercheck; move triangles or parallelogram lines",
                    Primitive::Line(line) if line.rule != LineRule::Parallelogram => "only parallelogram lines can move in this version of rastercheck (a midpoint or diamond-exit line chooses whole pixels at each instant, and a rectangle's corners are irrational)",
                    _ => continue,
                };
                return fail(&primitives_path.index(i), why);
            }
            let valued = scene.has_depth
                || scene.attribute_count > 0
                || scene.vertices().any(|v| v.w != Number::ONE);
            if valued {
                return fail(
                    &path.key(primitive.kind()),
                    "a scene in which something moves is judged on time coverage only: z, w and attributes are not supported with motion in this version of rastercheck",
                );
            }
            if let (Some(key), Some((_, expect_path))) = (
                scene.expect.sample_expectations().first(),
                fields.get("expect"),
            ) {
                return fail(
                    &expect_path.key(key),
                    format!("expect.{key} measures samples; a scene in which something moves is judged on time coverage only (max_time_error, max_time_rms, time_coverage)"),
                );
            }
            if scene.rules.subpixel_bits.is_none() {
                return fail(
                    &Path::root().key("rules").key("subpixel_bits"),
                    "moving vertices snap at shutter open and close: a moving scene needs subpixel_bits",
                );
            }
        }
        let e = &scene.expect;
        let given = [
            ("max_time_error", e.max_time_error.is_some()),
            ("max_time_rms", e.max_time_rms.is_some()),
            ("time_coverage", !e.time_coverage.is_empty()),
        ];
        if let (Some((key, _)), Some((_, expect_path))) =
            (given.iter().find(|(_, g)| *g), fields.get("expect"))
        {
            if moving.is_none() {
                return fail(
                    &expect_path.key(key),
                    format!("{key} measures time coverage; the case needs a primitive that moves and effects.motion_blur"),
                );
            }
        }
        for (i, pin) in e.time_coverage.iter().enumerate() {
            let [x, y] = pin.pixel;
            if x >= scene.canvas.width || y >= scene.canvas.height {
                let path = fields.get("expect").map_or(Path::root(), |(_, p)| p);
                return fail(
                    &path.key("time_coverage").index(i).key("pixel"),
                    format!(
                        "pixel ({x}, {y}) is outside the {}×{} canvas",
                        scene.canvas.width, scene.canvas.height
                    ),
                );
            }
        }
        Ok(())
    }
}
