//! The `protocol_response` target: arbitrary bytes as an external
//! rasterizer's answer, read as `-r external:…` reads it.

use std::path::PathBuf;
use std::sync::OnceLock;

use crate::adapters::external::{read_answer, read_hello};
use crate::plan::Plan;
use crate::scene::{parse_case, Limits, Scene};

/// The requests the answers answer: values (depth and a perspective
/// attribute), shared edges, and antialiasing (sample indices and
/// per-primitive coverage).
const REQUESTS: [&str; 3] = [
    r#"{"name": "values", "description": "",
        "canvas": {"width": 6, "height": 5},
        "primitives": [{"triangle": [
            {"position": [0.5, 0.5], "z": 0.5, "w": 0.25, "attributes": [0, 1]},
            {"position": [5.5, 1], "z": 0.25, "w": 2, "attributes": [1, 0]},
            {"position": [2, 4.5], "z": -0.5, "w": 1, "attributes": [2, 2]}]}]}"#,
    r#"{"name": "shared", "description": "",
        "canvas": {"width": 8, "height": 8},
        "primitives": [{"triangle": [[0, 4], [4.5, 0], [4.5, 8]]},
                       {"triangle": [[4.5, 0], [8, 4], [4.5, 8]]}]}"#,
    r#"{"name": "antialiased", "description": "",
        "canvas": {"width": 4, "height": 4},
        "effects": {"antialias": {"pattern": "standard", "samples": 4}},
        "primitives": [{"triangle": [[0.2, 0.1], [3.9, 1.3], [1.1, 3.7]]},
                       {"triangle": [[3.9, 1.3], [4, 4], [1.1, 3.7]]}]}"#,
];

/// The requests, read once.
pub(super) fn requests() -> &'static [(Scene, Plan)] {
    static REQUESTS_READ: OnceLock<Vec<(Scene, Plan)>> = OnceLock::new();
    REQUESTS_READ.get_or_init(|| {
        REQUESTS
            .iter()
            .map(|text| {
                let scene = parse_case(text, "request", &Limits::default())
                    .unwrap_or_else(|e| panic!("{e}"));
                let plan = Plan::for_scene(&scene);
                (scene, plan)
            })
            .collect()
    })
}

/// What the first byte asks the rest to be read as.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum Form {
    /// A response line (JSON).
    Json,
    /// The EXR file a `{"exr": path}` response names.
    Exr,
    /// The hello line, then whether it refuses the request.
    Hello,
}

pub(super) const FORMS: [Form; 3] = [Form::Json, Form::Exr, Form::Hello];

/// The first byte of an input: the form and the request.
pub(super) fn selector(form: Form, request: usize) -> u8 {
    let at = FORMS.iter().position(|&f| f == form).unwrap_or(0);
    (request * FORMS.len() + at) as u8
}

/// Reads `data` (after a selector byte: the form and the request) as an
/// answer. Any answer is read or refused with a reason; none panics.
pub fn protocol_response(data: &[u8]) {
    let Some((&select, body)) = data.split_first() else {
        return;
    };
    let form = FORMS[usize::from(select) % FORMS.len()];
    let (scene, plan) = &requests()[usize::from(select) / FORMS.len() % REQUESTS.len()];
    match form {
        Form::Json => drop(read_answer(body, scene, plan)),
        Form::Hello => drop(read_hello(body, scene, plan)),
        Form::Exr => {
            let path = exr_file();
            if std::fs::write(&path, body).is_ok() {
                let answer = serde_json::json!({ "exr": path }).to_string();
                drop(read_answer(answer.as_bytes(), scene, plan));
            }
        }
    }
}

/// This process's scratch file for EXR answers.
fn exr_file() -> PathBuf {
    static PATH: OnceLock<PathBuf> = OnceLock::new();
    PATH.get_or_init(|| {
        std::env::temp_dir().join(format!("rastercheck-fuzz-{}.exr", std::process::id()))
    })
    .clone()
}
