//! Claiming a report folder for a run: only a new or empty folder, or one a
//! run of ours marked as its own, and locked while the run writes it.
//!
//! The marker [`MARKER`] is what tells a report folder from a user's folder
//! that happens to hold an `index.html` or an `images/`: without it, nothing
//! in the folder is removed or overwritten, and the run is refused. The same
//! file is locked (`flock`, exclusive, never waited on) for as long as the
//! [`ClaimedFolder`] lives, so a second run into a folder a live run is
//! writing is refused before it removes anything, instead of deleting files
//! the first run's report names.

use std::fs::File;
use std::path::{Path, PathBuf};

use super::files::remove_owned;

/// The marker file a run writes into its report folder.
pub const MARKER: &str = ".rastercheck-report";

/// What the marker says to a person who opens it.
const MARKER_TEXT: &str =
    "This folder is a rastercheck report folder: a run wrote it, and a later \
run into it replaces report.json, junit.xml, summary.md, index.html, images/, exr/, pages/ and \
plots/ (nothing else). Delete this file to make rastercheck refuse the folder.\n";

/// A report folder claimed for one run: ours, locked, emptied of what an
/// earlier run wrote. The lock is released when it is dropped (or the
/// process ends).
#[derive(Debug)]
pub struct ClaimedFolder {
    pub dir: PathBuf,
    _lock: File,
}

/// Claims `dir` for a run (SPEC.md §10): creates it when it is missing;
/// refuses a folder that holds anything and no [`MARKER`], and a folder
/// another run holds locked; then removes what an earlier run wrote there.
/// `Err` is the message for the user, naming the folder.
pub fn claim(dir: &Path) -> Result<ClaimedFolder, String> {
    let shown = dir.display();
    let marker = dir.join(MARKER);
    let marked = std::fs::symlink_metadata(&marker).is_ok_and(|m| m.is_file());
    if !marked {
        let foreign = foreign_entries(dir)?;
        if !foreign.is_empty() {
            return Err(format!(
                "--report {shown}: the folder holds files no rastercheck run wrote ({}), and no \
                 {MARKER} marker; a report goes only into a new or empty folder, or one an \
                 earlier run wrote. Choose another folder (nothing was changed here)",
                foreign.join(", ")
            ));
        }
        std::fs::create_dir_all(dir).map_err(|e| format!("--report {shown}: {e}"))?;
    }
    let lock = File::options()
        .create(true)
        .append(true)
        .open(&marker)
        .map_err(|e| format!("--report {shown}: {}: {e}", marker.display()))?;
    lock_exclusive(&lock).map_err(|busy| {
        format!(
            "--report {shown}: another rastercheck run is writing this folder ({busy}); \
             wait for it, or choose another folder (nothing was changed here)"
        )
    })?;
    if !marked {
        std::fs::write(&marker, MARKER_TEXT)
            .map_err(|e| format!("--report {shown}: {}: {e}", marker.display()))?;
    }
    remove_owned(dir)?;
    Ok(ClaimedFolder {
        dir: dir.to_owned(),
        _lock: lock,
    })
}

/// The names in `dir` (at most 5 shown, then a count); empty for a missing
/// or empty folder.
fn foreign_entries(dir: &Path) -> Result<Vec<String>, String> {
    let entries = match std::fs::read_dir(dir) {
        Ok(entries) => entries,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => return Err(format!("--report {}: {e}", dir.display())),
    };
    let mut names: Vec<String> = entries
        .flatten()
        .map(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            match e.file_type() {
                Ok(kind) if kind.is_dir() => format!("{name}/"),
                _ => name,
            }
        })
        .collect();
    names.sort();
    if names.len() > 5 {
        let more = names.len() - 5;
        names.truncate(5);
        names.push(format!("{more} more"));
    }
    Ok(names)
}

/// An exclusive lock on `file`, or why not (another process holds it).
#[cfg(unix)]
fn lock_exclusive(file: &File) -> Result<(), String> {
    use std::os::fd::AsRawFd;
    // SAFETY: flock on a file descriptor this File owns for its lifetime.
    let locked = unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) };
    if locked == 0 {
        Ok(())
    } else {
        let e = std::io::Error::last_os_error();
        if e.raw_os_error() == Some(libc::EWOULDBLOCK) {
            Err("its lock is held".to_owned())
        } else {
            Err(format!("cannot lock {MARKER}: {e}"))
        }
    }
}

/// Elsewhere no lock is taken: the marker alone guards the user's files.
#[cfg(not(unix))]
fn lock_exclusive(_file: &File) -> Result<(), String> {
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("rastercheck-folder-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    #[test]
    fn a_new_folder_is_claimed_and_marked() {
        let dir = scratch("new");
        let claimed = claim(&dir).unwrap();
        assert!(dir.join(MARKER).is_file());
        drop(claimed);
        // Claimed again: it is ours now.
        std::fs::write(dir.join("index.html"), "an earlier run's").unwrap();
        claim(&dir).unwrap();
        assert!(!dir.join("index.html").exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_users_folder_is_refused_and_left_as_it_was() {
        let dir = scratch("users");
        std::fs::create_dir_all(dir.join("images")).unwrap();
        std::fs::write(dir.join("index.html"), "mine").unwrap();
        let e = claim(&dir).unwrap_err();
        assert!(e.contains("images/, index.html"), "{e}");
        assert_eq!(
            std::fs::read_to_string(dir.join("index.html")).unwrap(),
            "mine"
        );
        assert!(dir.join("images").is_dir());
        assert!(!dir.join(MARKER).exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_folder_another_claim_holds_is_refused() {
        let dir = scratch("locked");
        let first = claim(&dir).unwrap();
        std::fs::write(dir.join("summary.md"), "the live run's").unwrap();
        let e = claim(&dir).unwrap_err();
        assert!(e.contains("another rastercheck run"), "{e}");
        assert!(dir.join("summary.md").exists());
        drop(first);
        claim(&dir).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
