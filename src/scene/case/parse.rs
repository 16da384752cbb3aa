//! The reader's entry point: a case file's text into a [`Scene`], the
//! syntax and repeated keys checked first, then the walk of `schema.rs`.

use serde_json::Value;

use super::error::CaseError;
use super::json;
use super::limits::Limits;
use super::reader::Reader;
use crate::scene::model::Scene;

/// Reads the text of one case file. `file` names it in errors.
pub fn parse_case(text: &str, file: &str, limits: &Limits) -> Result<Scene, CaseError> {
    let value: Value = serde_json::from_str(text).map_err(|e| CaseError {
        file: file.to_owned(),
        location: format!("line {} column {}", e.line(), e.column()),
        message: format!("invalid JSON: {}", strip_position(&e.to_string())),
        over_limit: false,
    })?;
    if let Some(path) = json::duplicate_key(text) {
        return Err(CaseError {
            file: file.to_owned(),
            location: path.to_string(),
            message: "a key repeated in one object; each key may appear once (SPEC §1)".to_owned(),
            over_limit: false,
        });
    }
    let reader = Reader::new(limits);
    reader.scene(&value).map_err(|(path, message)| CaseError {
        file: file.to_owned(),
        location: path.to_string(),
        message,
        over_limit: reader.over_limit.get(),
    })
}

fn strip_position(message: &str) -> &str {
    message.find(" at line ").map_or(message, |i| &message[..i])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::model::Scene;
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
