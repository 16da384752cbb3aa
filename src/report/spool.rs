//! A run's case entries kept on disk, not in memory: each entry written as
//! one JSON line as its case is handed over (in the run's order), into a
//! temporary file in the report folder, and read back one at a time by
//! the writers of the summary files (`report/write.rs`). The file goes when
//! the run is done with it; one a killed run left is removed by the next
//! run into the folder, as every temporary file is (`files::remove_owned`).

use std::fs::File;
use std::io::{BufRead, BufReader, BufWriter, Write};
use std::path::{Path, PathBuf};

use serde::Deserialize;

use super::files::TEMPORARY_SUFFIX;
use super::json::CaseEntry;
use super::merge::lenient::Lenient;

/// The case entries of a run, on disk.
pub struct Spool {
    path: PathBuf,
    out: Option<BufWriter<File>>,
    count: usize,
    /// The first write that failed.
    error: Option<String>,
}

impl Spool {
    /// A new, empty spool in the folder `dir`.
    pub fn create(dir: &Path) -> Result<Spool, String> {
        let path = dir.join(format!(
            ".cases.jsonl.{}{TEMPORARY_SUFFIX}",
            std::process::id()
        ));
        let file = File::create(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        Ok(Spool {
            path,
            out: Some(BufWriter::new(file)),
            count: 0,
            error: None,
        })
    }

    /// Adds the next case's entry. A write that fails is kept, and said by
    /// [`Spool::each`].
    pub fn push(&mut self, entry: &CaseEntry) {
        let Some(out) = &mut self.out else {
            return;
        };
        let written = serde_json::to_writer(&mut *out, entry)
            .map_err(|e| e.to_string())
            .and_then(|()| out.write_all(b"\n").map_err(|e| e.to_string()));
        match written {
            Ok(()) => self.count += 1,
            Err(e) => {
                self.error
                    .get_or_insert(format!("{}: {e}", self.path.display()));
                self.out = None;
            }
        }
    }

    /// How many entries it holds.
    pub fn len(&self) -> usize {
        self.count
    }

    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// Calls `f` with each entry, in the order they were pushed, each read
    /// back as it was written (a number that was not finite, written as
    /// `null`, reads as NaN, and is written as `null` again).
    pub fn each(&mut self, f: &mut dyn FnMut(&CaseEntry)) -> Result<(), String> {
        if let Some(out) = &mut self.out {
            if let Err(e) = out.flush() {
                self.error
                    .get_or_insert(format!("{}: {e}", self.path.display()));
            }
        }
        if let Some(e) = &self.error {
            return Err(e.clone());
        }
        let shown = self.path.display();
        let file = File::open(&self.path).map_err(|e| format!("{shown}: {e}"))?;
        let mut read = 0;
        for line in BufReader::new(file).lines() {
            let line = line.map_err(|e| format!("{shown}: {e}"))?;
            let value: serde_json::Value = serde_json::from_str(&line)
                .map_err(|e| format!("{shown}: line {}: {e}", read + 1))?;
            let entry = CaseEntry::deserialize(Lenient(&value))
                .map_err(|e| format!("{shown}: line {}: {e}", read + 1))?;
            f(&entry);
            read += 1;
        }
        if read != self.count {
            return Err(format!(
                "{shown}: {read} case entries read back where {} were written",
                self.count
            ));
        }
        Ok(())
    }
}

impl Drop for Spool {
    fn drop(&mut self) {
        self.out = None;
        let _ = std::fs::remove_file(&self.path);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::harness::discover::CaseFile;
    use crate::report::json::{Report, ResultEntry};
    use crate::report::write::write_json_streamed;

    fn report() -> Report {
        let mut report = Report::of_production_run();
        for (k, id) in ["lines/a", "lines/b \"quoted\"\nline", "points/c"]
            .iter()
            .enumerate()
        {
            let mut case = CaseEntry::not_run(&CaseFile {
                id: (*id).into(),
                path: PathBuf::from(format!("cases/{id}.json")),
            });
            case.status = "ran";
            // Not finite: written as null, read back as NaN.
            case.reference_ms = if k == 1 { f64::NAN } else { 0.1 + k as f64 };
            case.results.push(ResultEntry {
                reasons: vec![format!("reason {k}\nover two lines")],
                time_ms: 1.0 / 3.0,
                files: vec!["images/x.png".into()],
                ..ResultEntry::bare("production", "fail")
            });
            report.cases.push(case);
        }
        report.tally();
        report
    }

    #[test]
    fn report_json_from_the_spool_is_the_bytes_of_the_report_in_memory() {
        let dir = std::env::temp_dir().join(format!("rastercheck-spool-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let whole = report();
        let mut spool = Spool::create(&dir).unwrap();
        for case in &whole.cases {
            spool.push(case);
        }
        assert_eq!(spool.len(), 3);
        let mut head = whole.clone();
        head.cases.clear();
        write_json_streamed(&dir, &head, &mut |f| spool.each(f)).unwrap();
        let streamed = std::fs::read_to_string(dir.join("report.json")).unwrap();
        assert_eq!(streamed, whole.to_json());
        // No case at all: `[]`, as serde writes it.
        let mut none = head.clone();
        none.tally();
        write_json_streamed(&dir, &none, &mut |_| Ok(())).unwrap();
        let streamed = std::fs::read_to_string(dir.join("report.json")).unwrap();
        assert_eq!(streamed, none.to_json());
        drop(spool);
        // The spool goes with the run; nothing temporary is left.
        let left: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .flatten()
            .map(|e| e.file_name())
            .filter(|n| n.to_string_lossy().ends_with(TEMPORARY_SUFFIX))
            .collect();
        assert!(left.is_empty(), "{left:?}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
