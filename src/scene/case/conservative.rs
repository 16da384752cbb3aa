//! `effects.conservative` (SPEC.md §19): its fields read onto the model.
//! What this version does not judge with it (`Scene::conservative_unjudged`)
//! is a verdict of `unsupported`, not an error of the file.

use serde_json::Value;

use crate::scene::conservative::{Conservative, ConservativeMode, MAX_UNCERTAINTY};
use crate::scene::number::Number;

use super::json::{boolean, named, number, Fields, Path, Result};
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
}
