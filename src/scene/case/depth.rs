//! Reading the depth rules of SPEC.md §18: `rules.depth_format` and
//! `rules.depth_bias`, and the checks that keep them where they are
//! defined (a case with depth; polygon offset under a format, in a case
//! without §14 polygons, and in clip space only with every w > 0).

use serde_json::Value;

use crate::scene::depth::{DepthBias, DepthFormat};
use crate::scene::model::Scene;
use crate::scene::number::Number;
use crate::scene::primitive::Primitive;
use crate::scene::rules::{limits, Rules};

use super::json::{fail, named, number, Fields, Path, Result};
use super::reader::Reader;
use super::validate::within;

impl Reader<'_> {
    /// `rules.depth_format` and `rules.depth_bias`.
    pub(super) fn depth_rules(&self, fields: &Fields, rules: &mut Rules) -> Result<()> {
        if let Some((v, p)) = fields.get("depth_format") {
            rules.depth_format = named(v, &p, DepthFormat::from_name, &DepthFormat::NAMES)?;
        }
        if let Some((v, p)) = fields.get("depth_bias") {
            rules.depth_bias = Some(self.depth_bias(v, &p)?);
        }
        Ok(())
    }

    fn depth_bias(&self, value: &Value, path: &Path) -> Result<DepthBias> {
        let fields = Fields::new(value, path, &["constant", "slope", "clamp"])?;
        let limit = Number::from_int(limits::VALUE_LIMIT);
        let read = |key: &str| -> Result<Number> {
            let Some((v, p)) = fields.get(key) else {
                return Ok(Number::ZERO);
            };
            let n = number(v, &p)?;
            within(
                &n,
                &p,
                &-limit.clone(),
                &limit,
                &format!("depth_bias {key}"),
            )?;
            Ok(n)
        };
        Ok(DepthBias {
            constant: read("constant")?,
            slope: read("slope")?,
            clamp: read("clamp")?,
        })
    }

    /// The depth rules where §18 defines them: a format or an offset
    /// needs depth (a vertex `z`, or clip space); an offset needs a format
    /// (its r is the format's), triangles to apply to (a §14 polygon has
    /// no depth of its own), and in clip space every w > 0 (the offset's
    /// slope and r are read off the piece's vertices' depths).
    pub(super) fn check_depth_rules(&self, scene: &Scene) -> Result<()> {
        let rules = Path::root().key("rules");
        let stated = |key: &str| rules.key(key);
        if scene.rules.depth_format != DepthFormat::Exact && !scene.has_depth {
            return fail(
                &stated("depth_format"),
                "a depth format stores depth; this case has none (give a vertex z, or clip-space vertices)",
            );
        }
        if scene.rules.depth_bias.is_none() {
            return Ok(());
        }
        let bias = stated("depth_bias");
        if !scene.has_depth {
            return fail(
                &bias,
                "polygon offset moves depth; this case has none (give a vertex z, or clip-space vertices)",
            );
        }
        if scene.rules.depth_format == DepthFormat::Exact {
            return fail(
                &bias,
                format!(
                    "polygon offset's constant is a multiple of the depth format's minimum resolvable difference r: give rules.depth_format ({}) (SPEC.md §18.2)",
                    DepthFormat::NAMES[1..].join(", ")
                ),
            );
        }
        let primitives = Path::root().key("primitives");
        if let Some(i) = scene
            .primitives
            .iter()
            .position(|p| matches!(p, Primitive::Polygon(_)))
        {
            return fail(
                &primitives.index(i),
                "polygon offset is defined for triangles (SPEC.md §18.2); a polygon (§14) carries no depth",
            );
        }
        if scene.in_clip_space() {
            for (i, p) in scene.primitives.iter().enumerate() {
                if let Some(j) = p.vertices().iter().position(|v| !v.w.is_positive()) {
                    return fail(
                        &primitives.index(i).key("triangle").index(j),
                        "polygon offset in clip space needs every w > 0 (SPEC.md §18.2): a piece with a vertex behind the eye has no depth at that vertex to read r from",
                    );
                }
            }
        }
        Ok(())
    }
}
