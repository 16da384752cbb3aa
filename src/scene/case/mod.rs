//! Reading a case file into a [`Scene`], with errors that name the file and
//! the JSON path of the offending value.
//!
//! The file is parsed into a `serde_json::Value` (with `arbitrary_precision`,
//! so every number keeps the text it was written as) and then walked by hand.
//! Walking by hand, rather than deriving `Deserialize`, is what lets every
//! error carry its JSON path, suggest the field that was meant, and read
//! numbers exactly.

//!
//! The reader is in these rooms:
//!
//! - `json.rs`: the JSON access layer (paths, fields with "did you mean",
//!   typed getters), which knows nothing of the format;
//! - `schema.rs`: the walk that maps each field of the format onto the
//!   scene model;
//! - `validate.rs`: documented ranges, and the checks across fields on the
//!   whole scene;
//! - `clip.rs`, `point.rs` and `depth.rs`: the clip-space (§16), point
//!   (§17) and depth (§18) fields and their checks.
//!
//! This file holds the entry point, [`parse_case`], the run's [`Limits`]
//! and the error it returns, [`CaseError`].

use std::fmt;

use serde_json::Value;

use super::rules::limits;
use super::Scene;

mod clip;
mod depth;
mod json;
mod point;
mod schema;
mod validate;

pub use json::closest;
use schema::Reader;

/// Resource limits that a run may tighten or relax (SPEC.md, "Limits").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    pub max_canvas_pixels: u64,
    pub max_primitives: usize,
    /// Sample points per case: pixels × spatial samples × time samples
    /// (the last only when something moves). It bounds the frames'
    /// memory and the work of each primitive.
    pub max_samples: u64,
    /// Bytes of one case file, checked before it is read (`--max-case-bytes`).
    pub max_case_bytes: u64,
    /// Bytes one case's frames may take, estimated before they are
    /// allocated (`--max-case-memory`); enforced by the runner, not the
    /// reader.
    pub max_case_memory: u64,
    /// Wall time each rasterizer (the reference, then each candidate) may
    /// spend on one case; `None` for no limit. Not a property of the file:
    /// the reader ignores it, the runner enforces it ([`crate::deadline`]).
    pub case_timeout: Option<std::time::Duration>,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_canvas_pixels: limits::DEFAULT_MAX_CANVAS_PIXELS,
            max_primitives: limits::DEFAULT_MAX_PRIMITIVES,
            max_samples: limits::DEFAULT_MAX_SAMPLES,
            max_case_bytes: limits::DEFAULT_MAX_CASE_BYTES,
            max_case_memory: limits::DEFAULT_MAX_CASE_MEMORY,
            case_timeout: Some(limits::DEFAULT_CASE_TIMEOUT),
        }
    }
}

/// A case that cannot be read: where, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CaseError {
    /// The case file, as given to the loader.
    pub file: String,
    /// JSON path of the offending value (`$.primitives[2].triangle[0]`), or
    /// `line L column C` for a syntax error.
    pub location: String,
    pub message: String,
}

impl fmt::Display for CaseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}: {}", self.file, self.location, self.message)
    }
}

impl std::error::Error for CaseError {}

/// Reads the text of one case file. `file` names it in errors.
pub fn parse_case(text: &str, file: &str, limits: &Limits) -> Result<Scene, CaseError> {
    let value: Value = serde_json::from_str(text).map_err(|e| CaseError {
        file: file.to_owned(),
        location: format!("line {} column {}", e.line(), e.column()),
        message: format!("invalid JSON: {}", strip_position(&e.to_string())),
    })?;
    if let Some(path) = json::duplicate_key(text) {
        return Err(CaseError {
            file: file.to_owned(),
            location: path.to_string(),
            message: "a key repeated in one object; each key may appear once (SPEC §1)".to_owned(),
        });
    }
    let reader = Reader { limits };
    reader.scene(&value).map_err(|(path, message)| CaseError {
        file: file.to_owned(),
        location: path.to_string(),
        message,
    })
}

fn strip_position(message: &str) -> &str {
    message.find(" at line ").map_or(message, |i| &message[..i])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::number::Number;
    use crate::scene::rules::Rules;

    fn parse(text: &str) -> std::result::Result<Scene, CaseError> {
        parse_case(text, "test.json", &Limits::default())
    }

    const MINIMAL: &str = r#"{"name": "t", "canvas": {"width": 4, "height": 4},
        "primitives": [{"triangle": [[0, 0], [4, 0], [0, "4/3"]]}]}"#;

    #[test]
    fn minimal_case_reads_with_defaults() {
        let scene = parse(MINIMAL).unwrap();
        assert_eq!(scene.rules, Rules::default());
        assert_eq!(scene.attribute_count, 0);
        assert!(!scene.has_depth);
        let (_, t) = scene.triangles().next().unwrap();
        assert_eq!(t.vertices[2].y, Number::ratio(4, 3));
    }

    #[test]
    fn errors_name_the_json_path() {
        let e = parse(
            r#"{"name": "t", "canvas": {"width": 4, "height": 4},
            "primitives": [{"triangle": [[0, 0], [4, 0], [0, 40000]]}]}"#,
        )
        .unwrap_err();
        assert_eq!(e.location, "$.primitives[0].triangle[2][1]");
        assert!(e.message.contains("outside the documented range"), "{e}");
    }

    #[test]
    fn unknown_fields_suggest_the_right_one() {
        let e = parse(r#"{"name": "t", "canvas": {"width": 4, "hieght": 4}, "primitives": []}"#)
            .unwrap_err();
        assert_eq!(e.location, "$.canvas.hieght");
        assert!(e.message.contains("did you mean \"height\""), "{e}");
    }

    #[test]
    fn syntax_errors_give_line_and_column() {
        let e = parse("{\"name\": \"t\",\n \"canvas\": }").unwrap_err();
        assert_eq!(e.location, "line 2 column 12");
    }

    #[test]
    fn repeated_keys_are_refused_with_their_path() {
        let e = parse(
            r#"{"name": "t", "canvas": {"width": 4, "height": 4},
            "primitives": [{"triangle": [[0, 0], [4, 0], [0, 4]]},
                           {"triangle": [[0, 0], [4, 0], [0, 4]], "triangle": [[0, 0], [1, 0], [0, 1]]}]}"#,
        )
        .unwrap_err();
        assert_eq!(e.location, "$.primitives[1].triangle");
        assert!(e.message.contains("repeated"), "{e}");
        // Numbers (maps under arbitrary_precision) and keys repeated in
        // different objects are fine.
        parse(&MINIMAL.replace("\"4/3\"", "1.25e0")).unwrap();
    }

    #[test]
    fn numbers_are_read_exactly() {
        let text = MINIMAL.replace("\"4/3\"", "0.1");
        let scene = parse(&text).unwrap();
        let (_, t) = scene.triangles().next().unwrap();
        assert_eq!(t.vertices[2].y, Number::ratio(1, 10));
    }
}
