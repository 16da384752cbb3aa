//! Finding case files: walking folders (links followed, `invalid/`
//! skipped, each file and id once), a case file's id, and the folder that
//! holds its golden files.

use std::path::{Path, PathBuf};

use crate::harness::case_list::{CaseList, MAX_CASES};

/// A case file and its id: its path under `cases/`, without `.json`
/// (`triangles/fan_center`).
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct CaseFile {
    pub id: String,
    pub path: PathBuf,
}

/// What a walk over the given paths found: its cases as a `Vec` of
/// [`CaseFile`]s ([`discover`]) or as a compact [`CaseList`]
/// ([`discover_list`]).
#[derive(Debug, Default)]
pub struct Discovery<C = Vec<CaseFile>> {
    pub cases: C,
    /// `invalid/` folders passed over (they hold negative tests; name one
    /// explicitly to read it).
    pub skipped: Vec<PathBuf>,
    /// Paths that do not exist or cannot be read.
    pub errors: Vec<String>,
}

/// Finds case files under `paths`, sorted by id. Folders are walked
/// recursively, following symbolic links; folders named `invalid` inside
/// them are skipped. A folder reached again through a link is walked once,
/// and a link back to a folder being walked (a loop) is an error, reported
/// once. One file reached through several paths is one case; two
/// different files with one id are an error naming both (the first, by
/// path, is kept), since an id names a case's images, golden file and
/// baseline entry.
pub fn discover(paths: &[PathBuf]) -> Discovery {
    let found = discover_list(paths);
    Discovery {
        cases: found
            .cases
            .into_vec()
            .into_iter()
            .map(|(id, path)| CaseFile { id, path })
            .collect(),
        skipped: found.skipped,
        errors: found.errors,
    }
}

/// [`discover`] with the cases held compactly: what a run of a million
/// cases deals out from. The walk keeps only the folders of one folder
/// whole; its case files go straight into the list, which is then sorted.
pub fn discover_list(paths: &[PathBuf]) -> Discovery<CaseList> {
    let mut found = Discovery::<CaseList>::default();
    let mut walk_state = Walk::default();
    for path in paths {
        if path.is_dir() {
            walk_state.walk(path, &mut found);
        } else if path.exists() {
            // A regular file, or something the reader refuses by name.
            add(&mut found, path);
        } else {
            found
                .errors
                .push(format!("{}: no such file or folder", path.display()));
        }
    }
    found.cases = std::mem::take(&mut found.cases).sorted();
    keep_each_id_once(&mut found);
    found
}

/// Adds the case file at `path`; past [`MAX_CASES`], says once that the
/// rest are not run.
fn add(found: &mut Discovery<CaseList>, path: &Path) {
    let case = case_file(path);
    if !found.cases.push(&case.id, &case.path) {
        let full = format!(
            "{}: more than {MAX_CASES} case files in one run; this and the rest are not run",
            path.display()
        );
        if !found
            .errors
            .last()
            .is_some_and(|e| e.contains("case files in one run"))
        {
            found.errors.push(full);
        }
    }
}

/// A file's or folder's identity: (device, inode) where there is one.
fn identity(path: &Path) -> Option<(u64, u64)> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        std::fs::metadata(path).ok().map(|m| (m.dev(), m.ino()))
    }
    #[cfg(not(unix))]
    {
        std::fs::canonicalize(path).ok().map(|p| {
            use std::hash::{Hash, Hasher};
            let mut h = std::collections::hash_map::DefaultHasher::new();
            p.hash(&mut h);
            (0, h.finish())
        })
    }
}

/// Drops a second path to the same file under one id, and turns two
/// different files with one id into an error naming both.
fn keep_each_id_once(found: &mut Discovery<CaseList>) {
    let cases = std::mem::take(&mut found.cases);
    // The case last kept, and its file's identity.
    let mut last: Option<(usize, Option<(u64, u64)>)> = None;
    let mut errors = Vec::new();
    found.cases = cases.retain(|list, k| {
        let this = identity(&list.path(k));
        if let Some((first, kept_identity)) = last.filter(|(f, _)| list.id(*f) == list.id(k)) {
            if this.is_none() || this != kept_identity {
                errors.push(format!(
                    "two different files have the case id {:?}: {} and {} (ids name images, golden files and baseline entries; only the first is run)",
                    list.id(k),
                    list.path(first).display(),
                    list.path(k).display()
                ));
            }
            return false;
        }
        last = Some((k, this));
        true
    });
    found.errors.extend(errors);
}

/// The folders a walk has entered, by identity, and those it is inside.
#[derive(Default)]
struct Walk {
    visited: std::collections::HashSet<(u64, u64)>,
    inside: Vec<(u64, u64)>,
}

impl Walk {
    fn walk(&mut self, dir: &Path, found: &mut Discovery<CaseList>) {
        let Some(id) = identity(dir) else {
            return found
                .errors
                .push(format!("{}: cannot read the folder", dir.display()));
        };
        if self.inside.contains(&id) {
            return found.errors.push(format!(
                "{}: a symbolic link loop (it leads back to a folder that contains it); not followed",
                dir.display()
            ));
        }
        if !self.visited.insert(id) {
            return; // walked already through another path
        }
        let entries = match std::fs::read_dir(dir) {
            Ok(entries) => entries,
            Err(e) => return found.errors.push(format!("{}: {e}", dir.display())),
        };
        // Case files go straight into the list (sorted once the walk is
        // over); folders are walked in order, after this one is read.
        let mut folders: Vec<PathBuf> = Vec::new();
        for path in entries.filter_map(|e| e.ok().map(|e| e.path())) {
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|e| e == "json") {
                add(found, &path);
            }
        }
        folders.sort();
        self.inside.push(id);
        for path in folders {
            if path.file_name().is_some_and(|n| n == "invalid") {
                found.skipped.push(path);
            } else {
                self.walk(&path, found);
            }
        }
        self.inside.pop();
    }
}

/// The id of a case file: its path below the nearest folder named `cases`,
/// without the extension; the path as given when there is none. The path
/// as given is searched first, then its absolute form, so that
/// `rastercheck run triangles` inside `cases/` names the same case as
/// `rastercheck run cases/triangles` beside it.
pub fn case_file(path: &Path) -> CaseFile {
    let (base, start) = cases_ancestor(path).unwrap_or((path.to_owned(), 0));
    let without_ext = base.with_extension("");
    let components: Vec<_> = without_ext.components().collect();
    let id = components[start..]
        .iter()
        .filter(|c| matches!(c, std::path::Component::Normal(_)))
        .map(|c| c.as_os_str().to_string_lossy())
        .collect::<Vec<_>>()
        .join("/");
    CaseFile {
        id,
        path: path.to_owned(),
    }
}

/// The folder that holds a case's golden files (`reference/` inside it,
/// SPEC.md §7): the parent of the nearest folder named `cases` above the
/// case file, so that golden files are found wherever the run starts;
/// `fallback` (the working directory) when no folder above it is named
/// `cases`.
pub fn golden_root(path: &Path, fallback: &Path) -> PathBuf {
    match cases_ancestor(path) {
        Some((base, start)) => {
            let cases: PathBuf = base.components().take(start - 1).collect();
            if cases.as_os_str().is_empty() {
                PathBuf::from(".")
            } else {
                cases
            }
        }
        None => fallback.to_owned(),
    }
}

/// The path (as given, else absolute) in which a folder above the file is
/// named `cases`, and the index of the component after the nearest one.
fn cases_ancestor(path: &Path) -> Option<(PathBuf, usize)> {
    let find = |p: &Path| {
        let components: Vec<_> = p.components().collect();
        // The file itself is no folder: only the components above it count.
        components[..components.len().saturating_sub(1)]
            .iter()
            .rposition(|c| c.as_os_str() == "cases")
            .map(|i| (p.to_owned(), i + 1))
    };
    find(path).or_else(|| std::path::absolute(path).ok().as_deref().and_then(find))
}
