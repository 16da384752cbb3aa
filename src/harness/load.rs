//! Reading one case file into a scene: only a regular file, no larger than
//! `--max-case-bytes`, parsed and validated.

use std::path::Path;

use super::case_hash::case_hash;
use super::discover::CaseFile;
use crate::scene::{parse_case, CaseError, Limits, Scene};

/// Reads and validates one case file.
pub fn load(file: &CaseFile, limits: &Limits) -> Result<Scene, CaseError> {
    load_checked(file, limits).map_err(|e| match e {
        LoadError::Unreadable(e) | LoadError::OverLimit(e) => e,
    })
}

/// Why a case file did not become a scene: bad input, or a case over a
/// configurable limit of the run (`--max-case-bytes`, `--max-canvas-pixels`,
/// `--max-primitives`, `--max-samples`: not a fault of the case).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LoadError {
    Unreadable(CaseError),
    OverLimit(CaseError),
}

/// [`load`], telling a file over the size limit from bad input. Only a
/// regular file (symbolic links followed) is opened, so a FIFO or a device
/// cannot hang the run, and its size is checked before a byte is read.
pub fn load_checked(file: &CaseFile, limits: &Limits) -> Result<Scene, LoadError> {
    load_hashed(file, limits).1
}

/// [`load_checked`], and the hash of the file's bytes when they could be
/// read ([`case_hash`]), whether or not they parse.
pub fn load_hashed(file: &CaseFile, limits: &Limits) -> (Option<String>, Result<Scene, LoadError>) {
    let text = match read_case_text(&file.path, limits.max_case_bytes) {
        Ok(text) => text,
        Err(e) => return (None, Err(e)),
    };
    (
        Some(case_hash(text.as_bytes())),
        parse_text(file, &text, limits),
    )
}

fn parse_text(file: &CaseFile, text: &str, limits: &Limits) -> Result<Scene, LoadError> {
    parse_case(text, &file.path.display().to_string(), limits).map_err(|e| {
        if e.over_limit {
            LoadError::OverLimit(e)
        } else {
            LoadError::Unreadable(e)
        }
    })
}

/// The text of a case file of at most `max_bytes` bytes.
fn read_case_text(path: &Path, max_bytes: u64) -> Result<String, LoadError> {
    use std::io::Read;
    let shown = path.display().to_string();
    let error = |message: String| CaseError {
        file: shown.clone(),
        location: "$".to_owned(),
        message,
        over_limit: false,
    };
    let bad = |message: String| LoadError::Unreadable(error(message));
    let regular = |meta: &std::fs::Metadata| -> Result<(), LoadError> {
        if !meta.is_file() {
            return Err(bad(format!(
                "not a regular file ({}); a case must be a regular file",
                file_kind(meta)
            )));
        }
        if meta.len() > max_bytes {
            return Err(LoadError::OverLimit(error(format!(
                "the file has {} bytes, over the limit of {max_bytes} bytes per case file (raise it with --max-case-bytes)",
                meta.len()
            ))));
        }
        Ok(())
    };
    let cannot = |e: std::io::Error| bad(format!("cannot read the file: {e}"));
    // Checked before opening: opening a FIFO blocks until a writer comes.
    regular(&std::fs::metadata(path).map_err(cannot)?)?;
    let opened = std::fs::File::open(path).map_err(cannot)?;
    // And again on what was opened, in case the path changed in between.
    regular(&opened.metadata().map_err(cannot)?)?;
    let mut bytes = Vec::new();
    opened
        .take(max_bytes.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    if bytes.len() as u64 > max_bytes {
        return Err(LoadError::OverLimit(error(format!(
            "the file grew past the limit of {max_bytes} bytes per case file while it was read (raise it with --max-case-bytes)"
        ))));
    }
    String::from_utf8(bytes).map_err(|e| bad(format!("cannot read the file: not UTF-8 text ({e})")))
}

/// What kind of file `meta` describes, in words.
pub fn file_kind(meta: &std::fs::Metadata) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        let t = meta.file_type();
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_socket() {
            return "a socket";
        }
        if t.is_block_device() || t.is_char_device() {
            return "a device";
        }
    }
    if meta.is_dir() {
        "a folder"
    } else {
        "of an unknown kind"
    }
}
