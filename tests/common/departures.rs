//! Named departures (issue 35): every failure a bundled run leaves on a
//! driver is a departure from a rule the driver states, written once in
//! `docs/drivers/departures/<implementation>/<name>.md`:
//!
//! ```text
//! # what it does differently
//!
//! Rule: the rule it departs from, quoted or cited
//! Flaky: yes            (optional: its cases may pass on some runs)
//!
//! what was measured, and why it is the driver's own
//!
//! ## Cases
//!
//! - `family/case_id`: the failure's short numbers
//! ```
//!
//! [`assert_every_failure_is_named`] holds a run's failures to the union of
//! an implementation's `## Cases` lists, both ways: a failure no departure
//! names fails the test, and so does a named case that passed (the list
//! stays true, as Mesa CI's expected-failure lists do).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// One departure file, read.
#[derive(Debug)]
pub struct Departure {
    pub file: PathBuf,
    pub title: String,
    pub rule: String,
    pub flaky: bool,
    pub cases: Vec<String>,
}

/// The departures folder of the repository.
pub fn folder() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/drivers/departures")
}

/// Every departure written for `implementation` (`swiftshader`,
/// `lavapipe`, `llvmpipe`), each checked for its form; panics naming the
/// file and line of a malformed one.
pub fn read(implementation: &str) -> Vec<Departure> {
    let dir = folder().join(implementation);
    let Ok(entries) = std::fs::read_dir(&dir) else {
        return Vec::new();
    };
    let mut files: Vec<PathBuf> = entries
        .map(|e| e.expect("a readable folder").path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    files.sort();
    files.iter().map(|file| parse(file)).collect()
}

/// Reads one departure file.
pub fn parse(file: &Path) -> Departure {
    let text = std::fs::read_to_string(file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
    let at = |n: usize, why: &str| -> String { format!("{}:{}: {why}", file.display(), n + 1) };
    let mut lines = text.lines().enumerate();
    let title = match lines.next() {
        Some((_, l)) if l.starts_with("# ") && l.len() > 2 => l[2..].trim().to_string(),
        _ => panic!("{}", at(0, "a departure opens with a `# title` line")),
    };
    let mut rule = None;
    let mut flaky = false;
    let mut in_cases = false;
    let mut cases = Vec::new();
    for (n, line) in lines {
        if let Some(r) = line.strip_prefix("Rule: ") {
            rule = Some(r.trim().to_string());
        } else if let Some(f) = line.strip_prefix("Flaky: ") {
            assert!(f.trim() == "yes", "{}", at(n, "`Flaky:` takes only `yes`"));
            flaky = true;
        } else if line.starts_with("## ") {
            in_cases = line.trim() == "## Cases";
        } else if in_cases && line.starts_with("- ") {
            let id = line
                .strip_prefix("- `")
                .and_then(|rest| rest.split_once('`'))
                .map(|(id, _)| id.to_string())
                .unwrap_or_else(|| panic!("{}", at(n, "a case bullet is \"- `family/id`: ...\"")));
            let case = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("cases/{id}.json"));
            assert!(case.exists(), "{}", at(n, &format!("no bundled case {id}")));
            cases.push(id);
        }
    }
    let rule = rule
        .unwrap_or_else(|| panic!("{}", at(0, "no `Rule:` line: which rule is departed from?")));
    assert!(!rule.is_empty(), "{}", at(0, "an empty `Rule:`"));
    assert!(!cases.is_empty(), "{}", at(0, "no `## Cases` list"));
    Departure {
        file: file.to_path_buf(),
        title,
        rule,
        flaky,
        cases,
    }
}

/// Holds `verdicts` (case id → verdict, from one bundled run on
/// `implementation`) to its departures: every `fail` or `flaky` case is
/// named by one, and every named case failed (or, for a flaky departure,
/// may have passed). Also checks that the departures index links each
/// file. Panics with every mismatch listed.
pub fn assert_every_failure_is_named(implementation: &str, verdicts: &BTreeMap<String, String>) {
    let departures = read(implementation);
    let mut named: BTreeMap<&str, &Departure> = BTreeMap::new();
    for d in &departures {
        for id in &d.cases {
            named.insert(id, d);
        }
    }
    let failed: BTreeSet<&str> = verdicts
        .iter()
        .filter(|(_, v)| matches!(v.as_str(), "fail" | "flaky"))
        .map(|(id, _)| id.as_str())
        .collect();
    let mut unnamed = Vec::new();
    for id in &failed {
        match named.get(id) {
            Some(d) => eprintln!("{implementation}: {id} fails: {}", d.title),
            None => unnamed.push(format!("{id} ({})", verdicts[*id])),
        }
    }
    let mut stale = Vec::new();
    for (id, d) in &named {
        let verdict = verdicts.get(*id).map_or("not run", String::as_str);
        if failed.contains(id) || (d.flaky && verdict == "pass") {
            continue;
        }
        stale.push(format!("{id} ({verdict}), named in {}", d.file.display()));
    }
    let index = std::fs::read_to_string(folder().join("README.md")).unwrap_or_default();
    let unlisted: Vec<String> = departures
        .iter()
        .map(|d| {
            let name = d.file.file_name().unwrap().to_string_lossy();
            format!("{implementation}/{name}")
        })
        .filter(|link| !index.contains(&format!("({link})")))
        .collect();
    assert!(
        unnamed.is_empty() && stale.is_empty() && unlisted.is_empty(),
        "{implementation}: {} failures no departure in {} names:\n  {}\n\
         {} named cases that did not fail:\n  {}\n\
         {} departure files docs/drivers/departures/README.md does not link:\n  {}",
        unnamed.len(),
        folder().join(implementation).display(),
        unnamed.join("\n  "),
        stale.len(),
        stale.join("\n  "),
        unlisted.len(),
        unlisted.join("\n  "),
    );
    eprintln!(
        "{implementation}: {} failures, each one of {} named departures",
        failed.len(),
        departures.len()
    );
}

/// Whether `id` is named by a flaky departure of `implementation`, and
/// which: the only cases a repeated run may find FLAKY.
pub fn flaky(implementation: &str, id: &str) -> Option<String> {
    read(implementation)
        .into_iter()
        .find(|d| d.flaky && d.cases.iter().any(|c| c == id))
        .map(|d| format!("{} ({})", d.title, d.file.display()))
}
