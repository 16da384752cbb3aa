//! Reading one side of a diff: a `report.json` (SPEC.md §10.1), or a report
//! folder holding one, into what the comparison needs. Every error names
//! the file and, inside it, the JSON path.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde_json::Value;

use crate::harness::load::file_kind;
use crate::report::json::SCHEMA;

/// The verdicts and case statuses a `rastercheck-report/1` holds.
const VERDICTS: [&str; 6] = ["pass", "fail", "foil", "unsupported", "error", "flaky"];
const STATUSES: [&str; 5] = [
    "ran",
    "unreadable",
    "reference-failed",
    "limit-exceeded",
    "not-run",
];
const GOLDEN: [&str; 3] = ["match", "differ", "missing"];

/// One report, as the diff sees it.
#[derive(Clone, Debug)]
pub struct Side {
    /// The `report.json` file read.
    pub file: PathBuf,
    pub complete: bool,
    pub rasterizers: Vec<String>,
    /// By case id.
    pub cases: BTreeMap<String, Case>,
}

#[derive(Clone, Debug)]
pub struct Case {
    /// `ran`, `unreadable`, `reference-failed`, `limit-exceeded` or `not-run`.
    pub status: String,
    pub error: Option<String>,
    /// `match`, `differ` or `missing`; `None` when not checked.
    pub golden: Option<String>,
    pub golden_detail: Option<String>,
    /// By rasterizer name.
    pub results: BTreeMap<String, Outcome>,
}

#[derive(Clone, Debug)]
pub struct Outcome {
    pub verdict: String,
    pub reasons: Vec<String>,
    /// By metric name (the baseline's, SPEC.md §11); NaN (written `null`)
    /// reads as infinity.
    pub metrics: BTreeMap<String, f64>,
}

impl Case {
    /// What a rasterizer's result on this case is: its verdict when the case
    /// ran, else the case's status (`unreadable`, `not-run`...); `absent`
    /// when the case ran without a result for it.
    pub fn state(&self, rasterizer: &str) -> String {
        if self.status != "ran" {
            return self.status.clone();
        }
        match self.results.get(rasterizer) {
            Some(r) => r.verdict.clone(),
            None => "absent".to_owned(),
        }
    }

    /// Why a rasterizer's result is what it is: its reasons, or the case's
    /// error.
    pub fn reasons(&self, rasterizer: &str) -> Vec<String> {
        if self.status != "ran" {
            return self.error.iter().cloned().collect();
        }
        self.results
            .get(rasterizer)
            .map(|r| r.reasons.clone())
            .unwrap_or_default()
    }
}

/// `path` itself, or `path/report.json` when `path` is a folder.
pub fn report_file(path: &Path) -> PathBuf {
    if path.is_dir() {
        path.join("report.json")
    } else {
        path.to_owned()
    }
}

/// Reads a report file or folder; `Err` names the file and the JSON path.
///
/// Only a regular file is opened (a FIFO with no writer would hang), and
/// its schema is checked by a first pass that keeps nothing but the
/// `schema` field, so a large JSON file that is not a report is refused in
/// constant memory instead of being parsed whole first.
pub fn read(path: &Path) -> Result<Side, String> {
    let file = report_file(path);
    let shown = file.display();
    let meta = std::fs::metadata(&file).map_err(|e| format!("{shown}: {e}"))?;
    if !meta.is_file() {
        return Err(format!(
            "{shown}: not a regular file ({}); a report must be a regular file",
            file_kind(&meta)
        ));
    }
    check_schema(&file).map_err(|e| format!("{shown}: {e}"))?;
    let text = std::fs::read_to_string(&file).map_err(|e| format!("{shown}: {e}"))?;
    let value: Value =
        serde_json::from_str(&text).map_err(|e| format!("{shown}: not JSON: {e}"))?;
    parse(&value)
        .map_err(|e| format!("{shown}: {e}"))
        .map(|(complete, rasterizers, cases)| Side {
            file,
            complete,
            rasterizers,
            cases,
        })
}

type Parsed = (bool, Vec<String>, BTreeMap<String, Case>);

/// The first pass: the file is JSON, an object, and its `schema` is a
/// report's. Every other value is skipped as it is read
/// ([`serde::de::IgnoredAny`]), so memory stays constant.
fn check_schema(file: &Path) -> Result<(), String> {
    #[derive(serde::Deserialize)]
    struct Head {
        schema: Option<String>,
    }
    use std::io::BufRead;
    let opened = std::fs::File::open(file).map_err(|e| e.to_string())?;
    let mut reader = std::io::BufReader::new(opened);
    // An object, not an array (serde would read an array as the struct's
    // fields in order).
    loop {
        let buf = reader.fill_buf().map_err(|e| e.to_string())?;
        if buf.is_empty() {
            return Err("not JSON: the file is empty".to_owned());
        }
        let blank = buf.iter().take_while(|b| b.is_ascii_whitespace()).count();
        if blank == buf.len() {
            reader.consume(blank);
            continue;
        }
        if buf[blank] != b'{' {
            return Err("expected a JSON object (a report.json)".to_owned());
        }
        break;
    }
    let head: Head = serde_json::from_reader(reader).map_err(|e| {
        if e.is_data() {
            format!("schema: expected the string {SCHEMA:?}: {e}")
        } else {
            format!("not JSON: {e}")
        }
    })?;
    check_schema_name(head.schema.as_deref())
}

fn check_schema_name(schema: Option<&str>) -> Result<(), String> {
    match schema {
        Some(SCHEMA) => Ok(()),
        Some(other) => Err(format!(
            "schema: expected {SCHEMA:?}, got {other:?} (not a rastercheck report, or another version)"
        )),
        None => Err(format!(
            "schema: missing; expected {SCHEMA:?} (not a rastercheck report.json)"
        )),
    }
}

fn parse(root: &Value) -> Result<Parsed, String> {
    let root_obj = root
        .as_object()
        .ok_or("expected a JSON object (a report.json)")?;
    check_schema_name(root_obj.get("schema").and_then(Value::as_str))?;
    let complete = root_obj
        .get("complete")
        .and_then(Value::as_bool)
        .ok_or("complete: expected true or false")?;
    let mut rasterizers = Vec::new();
    for (i, r) in array(root, "rasterizers")?.iter().enumerate() {
        let name = string(r, "name", &format!("rasterizers[{i}]"))?;
        if rasterizers.contains(&name) {
            return Err(format!("rasterizers[{i}].name: {name:?} appears twice"));
        }
        rasterizers.push(name);
    }
    let mut cases = BTreeMap::new();
    for (i, c) in array(root, "cases")?.iter().enumerate() {
        let at = format!("cases[{i}]");
        let id = string(c, "id", &at)?;
        let status = one_of(c, "status", &at, &STATUSES)?;
        let golden = match c.get("golden") {
            None | Some(Value::Null) => None,
            Some(_) => Some(one_of(c, "golden", &at, &GOLDEN)?),
        };
        let mut results = BTreeMap::new();
        let list = c
            .get("results")
            .and_then(Value::as_array)
            .ok_or_else(|| format!("{at}.results: expected an array"))?;
        for (k, r) in list.iter().enumerate() {
            let at = format!("{at}.results[{k}]");
            let rasterizer = string(r, "rasterizer", &at)?;
            let verdict = one_of(r, "verdict", &at, &VERDICTS)?;
            let reasons = match r.get("reasons").and_then(Value::as_array) {
                Some(list) => list
                    .iter()
                    .filter_map(|s| s.as_str().map(str::to_owned))
                    .collect(),
                None => Vec::new(),
            };
            let metrics = match r.get("metrics") {
                None | Some(Value::Null) => BTreeMap::new(),
                Some(m) => metrics(m, &format!("{at}.metrics"))?,
            };
            let outcome = Outcome {
                verdict,
                reasons,
                metrics,
            };
            if results.insert(rasterizer.clone(), outcome).is_some() {
                return Err(format!(
                    "{at}.rasterizer: {rasterizer:?} has two results in case {id:?}"
                ));
            }
        }
        let case = Case {
            status,
            error: c.get("error").and_then(Value::as_str).map(str::to_owned),
            golden,
            golden_detail: c
                .get("golden_detail")
                .and_then(Value::as_str)
                .map(str::to_owned),
            results,
        };
        if cases.insert(id.clone(), case).is_some() {
            return Err(format!("{at}.id: case {id:?} appears twice"));
        }
    }
    Ok((complete, rasterizers, cases))
}

fn array<'a>(v: &'a Value, key: &str) -> Result<&'a Vec<Value>, String> {
    v.get(key)
        .and_then(Value::as_array)
        .ok_or_else(|| format!("{key}: expected an array"))
}

fn string(v: &Value, key: &str, at: &str) -> Result<String, String> {
    v.get(key)
        .and_then(Value::as_str)
        .map(str::to_owned)
        .ok_or_else(|| format!("{at}.{key}: expected a string"))
}

fn one_of(v: &Value, key: &str, at: &str, known: &[&str]) -> Result<String, String> {
    let s = string(v, key, at)?;
    if known.contains(&s.as_str()) {
        Ok(s)
    } else {
        Err(format!(
            "{at}.{key}: unknown value {s:?}; expected one of {}",
            known.join(", ")
        ))
    }
}

/// A metric's value: a number, or `null` (NaN as serde writes it) read as
/// infinity; `Err` for anything else.
fn number(v: &Value, at: &str) -> Result<f64, String> {
    match v {
        Value::Null => Ok(f64::INFINITY),
        Value::Number(n) => n.as_f64().ok_or_else(|| format!("{at}: not a number")),
        _ => Err(format!("{at}: expected a number")),
    }
}

/// The metrics of one result, by name. A section or field that is absent is
/// skipped (it was not measured); one of the wrong type is an error.
fn metrics(m: &Value, at: &str) -> Result<BTreeMap<String, f64>, String> {
    let mut out = BTreeMap::new();
    let mut take = |section: &str, fields: &[&str], name: &str| -> Result<(), String> {
        let Some(s) = m.get(section).filter(|s| !s.is_null()) else {
            return Ok(());
        };
        for &field in fields {
            if let Some(v) = s.get(field) {
                let value = number(v, &format!("{at}.{section}.{field}"))?;
                out.insert(format!("{name}.{field}"), value);
            }
        }
        Ok(())
    };
    take(
        "coverage",
        &["mismatched", "missing", "extra", "wrong_owner"],
        "coverage",
    )?;
    take("watertight", &["holes", "overdraw"], "watertight")?;
    take("lines", &["crowded_steps"], "lines")?;
    take(
        "antialias",
        &[
            "max_error",
            "rms_edge",
            "rms_all",
            "piglit_violations",
            "resolve_mismatches",
            "invalid_values",
        ],
        "antialias",
    )?;
    take(
        "time",
        &["max_error", "rms_moving", "rms_all", "invalid_values"],
        "time",
    )?;
    if let Some(bias) = m.get("time").and_then(|t| t.get("bias_moving")) {
        let value = number(bias, &format!("{at}.time.bias_moving"))?;
        out.insert("time.abs_bias".to_owned(), value.abs());
    }
    if let Some(channels) = m.get("channels").filter(|c| !c.is_null()) {
        let list = channels
            .as_array()
            .ok_or_else(|| format!("{at}.channels: expected an array"))?;
        for (i, ch) in list.iter().enumerate() {
            let at = format!("{at}.channels[{i}]");
            let name = string(ch, "channel", &at)?;
            // Not max_ulp: it is max_abs in units of the value's ulp, and
            // moves with it.
            for field in ["max_abs", "rms"] {
                if let Some(v) = ch.get(field) {
                    out.insert(
                        format!("{name}.{field}"),
                        number(v, &format!("{at}.{field}"))?,
                    );
                }
            }
        }
    }
    Ok(out)
}
