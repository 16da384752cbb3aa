//! `effects.conservative` (SPEC.md §19): its fields read onto the model.
//! What this version does not judge with it (`Scene::conservative_unjudged`)
//! is a verdict of `unsupported`, not an error of the file.

use serde_json::Value;

use crate::scene::conservative::{
    Conservative, ConservativeMode, ConservativePromise, MAX_UNCERTAINTY,
};
use crate::scene::model::Scene;
use crate::scene::number::Number;

use super::json::{array, boolean, count, fail, named, number, Fields, Path, Result};
use super::reader::Reader;
use super::validate::within;

impl Reader<'_> {
    pub(super) fn conservative(&self, value: &Value, path: &Path) -> Result<Conservative> {
        let fields = Fields::new(
            value,
            path,
            &[
                "mode",
                "uncertainty",
                "fully_covered",
                "degenerate_triangles",
                "degenerate_lines",
                "points_and_lines",
            ],
        )?;
        let (mode, mode_path) = fields.require("mode")?;
        let mode = named(
            mode,
            &mode_path,
            ConservativeMode::from_name,
            &ConservativeMode::NAMES,
        )?;
        let uncertainty = match fields.get("uncertainty") {
            Some((v, p)) => {
                let u = number(v, &p)?;
                within(
                    &u,
                    &p,
                    &Number::ZERO,
                    &Number::from_int(MAX_UNCERTAINTY),
                    "uncertainty",
                )?;
                u
            }
            None => Number::ZERO,
        };
        let flag = |key: &str| -> Result<bool> {
            match fields.get(key) {
                Some((v, p)) => boolean(v, &p),
                None => Ok(false),
            }
        };
        Ok(Conservative {
            mode,
            uncertainty,
            fully_covered: flag("fully_covered")?,
            degenerate_triangles: flag("degenerate_triangles")?,
            degenerate_lines: flag("degenerate_lines")?,
            points_and_lines: flag("points_and_lines")?,
        })
    }

    pub(super) fn conservative_promise(
        &self,
        value: &Value,
        path: &Path,
    ) -> Result<ConservativePromise> {
        let fields = Fields::new(
            value,
            path,
            &[
                "required",
                "allowed",
                "fully_covered",
                "required_pixels",
                "allowed_pixels",
            ],
        )?;
        let counted = |key: &str| -> Result<Option<u64>> {
            match fields.get(key) {
                Some((v, p)) => Ok(Some(count(v, &p, u64::MAX >> 1)?)),
                None => Ok(None),
            }
        };
        let pixels = |key: &str| -> Result<Option<Vec<[u32; 2]>>> {
            let Some((v, p)) = fields.get(key) else {
                return Ok(None);
            };
            let mut out = Vec::new();
            for (i, item) in array(v, &p)?.iter().enumerate() {
                let at = p.index(i);
                let xy = array(item, &at)?;
                if xy.len() != 2 {
                    return fail(&at, format!("a pixel is [x, y], found {} values", xy.len()));
                }
                let x = count(&xy[0], &at.index(0), u64::from(u32::MAX))? as u32;
                let y = count(&xy[1], &at.index(1), u64::from(u32::MAX))? as u32;
                out.push([x, y]);
            }
            Ok(Some(out))
        };
        Ok(ConservativePromise {
            required: counted("required")?,
            allowed: counted("allowed")?,
            fully_covered: counted("fully_covered")?,
            required_pixels: pixels("required_pixels")?,
            allowed_pixels: pixels("allowed_pixels")?,
        })
    }

    /// `expect.conservative` needs `effects.conservative`.
    pub(super) fn check_conservative(&self, scene: &Scene) -> Result<()> {
        if scene.expect.conservative.is_some() && scene.effects.conservative.is_none() {
            return fail(
                &Path::root().key("expect").key("conservative"),
                "expect.conservative pins a conservative scene's classes; the case needs effects.conservative",
            );
        }
        Ok(())
    }
}
