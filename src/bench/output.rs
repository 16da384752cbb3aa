//! Where `bench` writes BENCH.md and bench.svg beside it: the committed
//! files in the current folder for the full run, a folder under the ignored
//! `out/` for `--quick` (so a quick look never overwrites the committed
//! numbers), or wherever `--out` says; checked before the run.

use std::path::{Path, PathBuf};

/// Where a `--quick` run writes when no `--out` is given: under `out/`,
/// which git ignores.
pub const QUICK_DIR: &str = "out/bench";

/// The report a run writes: `out` when given; otherwise a full run's
/// BENCH.md in the current folder (the committed one), a quick run's in
/// [`QUICK_DIR`].
pub fn report_path(quick: bool, out: Option<PathBuf>) -> PathBuf {
    match out {
        Some(out) => out,
        None if quick => Path::new(QUICK_DIR).join("BENCH.md"),
        None => PathBuf::from("BENCH.md"),
    }
}

/// [`report_path`], with [`QUICK_DIR`] created when a quick run writes
/// there (a folder named by `--out` must exist already). `Err` names the
/// folder that could not be made.
pub fn prepare_report_path(quick: bool, out: Option<PathBuf>) -> Result<PathBuf, String> {
    let default_quick = quick && out.is_none();
    let path = report_path(quick, out);
    if default_quick {
        std::fs::create_dir_all(QUICK_DIR).map_err(|e| format!("{QUICK_DIR}: {e}"))?;
    }
    Ok(path)
}

/// Whether BENCH.md can be written at `out`, and bench.svg beside it,
/// checked before a run rather than after its minutes of measuring: the
/// folder must exist and take a new file (one is created there and removed
/// at once), and either file that exists already must open for writing
/// (opened to append, left as it is). `Err` says why not, naming the path.
pub fn check_out_path(out: &Path) -> Result<(), String> {
    let dir = match out.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    };
    if !dir.is_dir() {
        return Err(format!(
            "{}: no such folder (create it before the run)",
            dir.display()
        ));
    }
    if out.is_dir() {
        return Err(format!(
            "{}: a folder; name the file to write, e.g. {}",
            out.display(),
            out.join("BENCH.md").display()
        ));
    }
    let probe = dir.join(format!(".rastercheck-bench-{}.tmp", std::process::id()));
    std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&probe)
        .map_err(|e| format!("{}: cannot write a file there: {e}", dir.display()))?;
    std::fs::remove_file(&probe).map_err(|e| format!("{}: {e}", probe.display()))?;
    for file in [out.to_path_buf(), out.with_file_name("bench.svg")] {
        if file.exists() {
            std::fs::OpenOptions::new()
                .append(true)
                .open(&file)
                .map_err(|e| format!("{}: cannot write it: {e}", file.display()))?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::{check_out_path, report_path, QUICK_DIR};
    use std::path::Path;

    #[test]
    fn out_path_in_a_missing_folder_is_refused_before_the_run() {
        let out = std::env::temp_dir().join("rastercheck-no-such-folder-7f3a/BENCH.md");
        let why = check_out_path(&out).unwrap_err();
        assert!(why.contains("no such folder"), "{why}");
    }

    #[test]
    fn out_path_in_a_writable_folder_passes_and_leaves_nothing() {
        let dir = std::env::temp_dir().join(format!("rastercheck-out-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        assert_eq!(check_out_path(&dir.join("BENCH.md")), Ok(()));
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
        let why = check_out_path(&dir).unwrap_err();
        assert!(why.contains("a folder"), "{why}");
        std::fs::remove_dir(&dir).unwrap();
    }

    #[test]
    fn a_bare_file_name_is_checked_in_the_current_folder() {
        assert_eq!(check_out_path(Path::new("BENCH.md")), Ok(()));
    }

    #[test]
    fn a_quick_run_writes_under_out_unless_told_where() {
        let told = std::path::PathBuf::from("elsewhere/B.md");
        assert_eq!(report_path(true, Some(told.clone())), told);
        assert_eq!(report_path(false, Some(told.clone())), told);
        assert_eq!(
            report_path(true, None),
            Path::new(QUICK_DIR).join("BENCH.md")
        );
        assert_eq!(report_path(false, None), Path::new("BENCH.md"));
    }
}
