//! One report read back for a merge: a `report.json`, or the report folder
//! holding it, into the report model (`report/json.rs`) every writer
//! takes. Errors name the file.

use std::path::{Path, PathBuf};

use serde::Deserialize;
use serde_json::Value;

use super::lenient::Lenient;
use crate::harness::load::file_kind;
use crate::report::json::{Report, SCHEMA};

/// The largest `report.json` read: a million cases of about 4.4 KiB each.
pub const MAX_REPORT_BYTES: u64 = 8 << 30;

/// A report to merge, and where it was read from.
#[derive(Clone, Debug)]
pub struct Input {
    /// The `report.json` read, as named on the command line.
    pub file: PathBuf,
    /// The folder its pages and pictures are relative to.
    pub dir: PathBuf,
    pub report: Report,
}

/// Reads `path` (a `report.json`, or a folder holding one).
pub fn read_input(path: &Path) -> Result<Input, String> {
    let file = if path.is_dir() {
        path.join("report.json")
    } else {
        path.to_owned()
    };
    let shown = file.display();
    let meta = std::fs::metadata(&file).map_err(|e| format!("{shown}: cannot read it: {e}"))?;
    if !meta.is_file() {
        return Err(format!(
            "{shown}: not a regular file ({}); give a report.json or the folder holding one",
            file_kind(&meta)
        ));
    }
    if meta.len() > MAX_REPORT_BYTES {
        return Err(format!(
            "{shown}: {} bytes, over the {MAX_REPORT_BYTES} bytes a report is read up to",
            meta.len()
        ));
    }
    let text =
        std::fs::read_to_string(&file).map_err(|e| format!("{shown}: cannot read it: {e}"))?;
    let value: Value =
        serde_json::from_str(&text).map_err(|e| format!("{shown}: not JSON: {e}"))?;
    drop(text);
    match value.get("schema").and_then(Value::as_str) {
        Some(SCHEMA) => {}
        Some(other) => {
            return Err(format!(
                "{shown}: $.schema is {other:?}, not {SCHEMA:?}: not a report this version reads"
            ))
        }
        None => {
            return Err(format!(
                "{shown}: $.schema is missing: not a rastercheck report"
            ))
        }
    }
    let report = Report::deserialize(Lenient(&value))
        .map_err(|e| format!("{shown}: not a {SCHEMA} report: {e}"))?;
    let dir = file
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_owned);
    Ok(Input {
        file: path.to_owned(),
        dir: if dir.as_os_str().is_empty() {
            PathBuf::from(".")
        } else {
            dir
        },
        report,
    })
}
