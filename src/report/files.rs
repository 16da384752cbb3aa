//! The report folder's files on disk: each written whole or not at all, what
//! a run owns there (and removes before writing again), paths relative to
//! the folder.

use std::path::{Path, PathBuf};

/// What the temporary name of a file being written ends with: a file so
/// named is one rastercheck did not finish writing.
pub const TEMPORARY_SUFFIX: &str = ".rastercheck-partial";

/// The files and folders a report folder holds that rastercheck wrote;
/// nothing else in it is ever removed.
pub const OWNED_FILES: [&str; 4] = ["report.json", "junit.xml", "summary.md", "index.html"];
pub const OWNED_FOLDERS: [&str; 4] = ["images", "exr", "pages", "plots"];

/// Writes `content` to `path` whole or not at all (every report file goes
/// through here): into a temporary file in the same folder, then renamed
/// over `path`, so a run killed mid-write leaves the old file or the new
/// one, never a truncated one. Creates the folder.
pub fn write_file(path: &Path, content: &[u8]) -> Result<PathBuf, String> {
    write_file_with(path, &mut |out| {
        out.write_all(content)
            .map_err(|e| format!("{}: {e}", path.display()))
    })
}

/// Writes the file at `path` as `write` writes it, a piece at a time,
/// whole or not at all as [`write_file`] (which writes through here) does:
/// a report file too large to hold in memory is written from what streams
/// into it.
pub fn write_file_with(
    path: &Path,
    write: &mut dyn FnMut(&mut dyn std::io::Write) -> Result<(), String>,
) -> Result<PathBuf, String> {
    let parent = path.parent().unwrap_or(Path::new("."));
    if !parent.as_os_str().is_empty() {
        std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
    }
    let name = path
        .file_name()
        .ok_or_else(|| format!("{}: not a file name", path.display()))?;
    let temporary = path.with_file_name(format!(
        ".{}.{}{TEMPORARY_SUFFIX}",
        name.to_string_lossy(),
        std::process::id()
    ));
    let written = std::fs::File::create(&temporary)
        .map_err(|e| format!("{}: {e}", path.display()))
        .and_then(|file| {
            let mut out = std::io::BufWriter::new(file);
            write(&mut out)?;
            out.into_inner()
                .map(drop)
                .map_err(|e| format!("{}: {}", path.display(), e.error()))
        })
        .and_then(|()| {
            std::fs::rename(&temporary, path).map_err(|e| format!("{}: {e}", path.display()))
        });
    if written.is_err() {
        let _ = std::fs::remove_file(&temporary);
    }
    written.map(|()| path.to_owned())
}

/// Removes what an earlier run wrote into the report folder `dir`
/// ([`OWNED_FILES`], [`OWNED_FOLDERS`], and temporary files a killed run
/// left), and nothing else: a user's own files there stay. A missing folder
/// is fine.
pub fn remove_owned(dir: &Path) -> Result<(), String> {
    let entries = match std::fs::read_dir(dir) {
        Ok(entries) => entries,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
        Err(e) => return Err(format!("{}: {e}", dir.display())),
    };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let path = entry.path();
        // Not followed: a link named `images` is removed, not its target.
        let Ok(kind) = entry.file_type() else {
            continue;
        };
        let removed = if OWNED_FOLDERS.contains(&name.as_str()) && kind.is_dir() {
            std::fs::remove_dir_all(&path)
        } else if !kind.is_dir()
            && (OWNED_FILES.contains(&name.as_str())
                || OWNED_FOLDERS.contains(&name.as_str())
                || name.ends_with(TEMPORARY_SUFFIX))
        {
            std::fs::remove_file(&path)
        } else {
            continue;
        };
        removed.map_err(|e| {
            format!(
                "{}: removing what an earlier run wrote: {e}",
                path.display()
            )
        })?;
    }
    Ok(())
}

/// `path` relative to `dir`, with forward slashes.
pub fn relative(dir: &Path, path: &Path) -> String {
    let rel = path.strip_prefix(dir).unwrap_or(path);
    rel.components()
        .map(|c| c.as_os_str().to_string_lossy())
        .collect::<Vec<_>>()
        .join("/")
}
