//! The GitHub Actions workflow `.github/workflows/rastercheck-shards.yml`
//! run here, step by step, as Actions would run it: each shard job's `run:`
//! steps once per value of its matrix, the artifacts carried from
//! `actions/upload-artifact` to `actions/download-artifact` as Actions
//! carries them (one folder per artifact under the download path), then the
//! merge job's steps, `$GITHUB_STEP_SUMMARY` a file of our own. The build
//! steps (`cargo build`) are the one thing not run: the binary under test
//! stands at `target/release/rastercheck` in a scratch folder beside the
//! bundled cases. The merged report must then be the unsharded run's.
//!
//! The YAML is read by a few lines of code, not a YAML library: the workflow
//! keeps a plain layout (two-space indents, `run: |` blocks), and this test
//! fails, saying where, if it stops doing so.

mod common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use common::cli::{rastercheck, read_json, scratch, text};

const WORKFLOW: &str = ".github/workflows/rastercheck-shards.yml";

/// One step of a job: its `uses:`, its `run:` script and its `with:` inputs.
#[derive(Debug, Default)]
struct Step {
    name: String,
    uses: String,
    run: String,
    with: BTreeMap<String, String>,
}

#[derive(Debug, Default)]
struct Job {
    /// `strategy.matrix`'s one variable and its values, if any.
    matrix: Option<(String, Vec<String>)>,
    steps: Vec<Step>,
}

fn indent(line: &str) -> usize {
    line.len() - line.trim_start().len()
}

fn key_value(text: &str) -> (String, String) {
    let (k, v) = text.split_once(':').unwrap_or((text, ""));
    (k.trim().to_owned(), v.trim().to_owned())
}

/// The jobs of the workflow text, by name.
fn jobs(yaml: &str) -> BTreeMap<String, Job> {
    let lines: Vec<&str> = yaml.lines().collect();
    let mut jobs: BTreeMap<String, Job> = BTreeMap::new();
    let mut job: Option<String> = None;
    let mut in_jobs = false;
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        let trimmed = line.trim();
        i += 1;
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        match indent(line) {
            0 => in_jobs = trimmed == "jobs:",
            2 if in_jobs => {
                let name = trimmed.trim_end_matches(':').to_owned();
                jobs.insert(name.clone(), Job::default());
                job = Some(name);
            }
            _ if in_jobs => {
                let job = jobs.get_mut(job.as_deref().expect("a job first")).unwrap();
                let (key, value) = key_value(trimmed.trim_start_matches("- "));
                if indent(line) == 8 && value.starts_with('[') && job.steps.is_empty() {
                    let values = value
                        .trim_matches(|c| c == '[' || c == ']')
                        .split(',')
                        .map(|v| v.trim().to_owned())
                        .collect();
                    job.matrix = Some((key, values));
                    continue;
                }
                if indent(line) == 6 && trimmed.starts_with("- ") {
                    job.steps.push(Step::default());
                }
                let Some(step) = job.steps.last_mut() else {
                    continue;
                };
                if indent(line) == 10 && !trimmed.starts_with("- ") {
                    // Inside `with:` (a step's keys are at 8).
                    step.with.insert(key, value);
                    continue;
                }
                match key.as_str() {
                    "name" => step.name = value,
                    "uses" => step.uses = value,
                    "run" if value == "|" => {
                        while i < lines.len()
                            && (lines[i].trim().is_empty() || indent(lines[i]) > 8)
                        {
                            step.run += lines[i].get(10..).unwrap_or("");
                            step.run.push('\n');
                            i += 1;
                        }
                    }
                    "run" => step.run = value + "\n",
                    _ => {}
                }
            }
            _ => {}
        }
    }
    jobs
}

/// `text` with the matrix variable `${{ matrix.NAME }}` set.
fn expand(text: &str, matrix: Option<(&str, &str)>) -> String {
    match matrix {
        Some((name, value)) => text.replace(&format!("${{{{ matrix.{name} }}}}"), value),
        None => text.to_owned(),
    }
}

/// Runs a `run:` script with bash in `dir`: its exit code and output.
fn bash(dir: &Path, script: &str, summary: &Path) -> (i32, String) {
    assert!(!script.contains("${{"), "an expression left in: {script}");
    let out = Command::new("bash")
        .args(["-eo", "pipefail", "-c", script])
        .current_dir(dir)
        .env("GITHUB_STEP_SUMMARY", summary)
        .output()
        .expect("bash runs");
    (out.status.code().unwrap_or(-1), text(&out))
}

fn copy_tree(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let target = to.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            copy_tree(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), target).unwrap();
        }
    }
}

/// Runs one job's steps (once per matrix value) in `dir`; uploads go into
/// `artifacts` by name, downloads come from it.
fn run_job(dir: &Path, job: &Job, artifacts: &Path, summary: &Path) -> Vec<i32> {
    let values: Vec<Option<(&str, &str)>> = match &job.matrix {
        Some((name, values)) => values
            .iter()
            .map(|v| Some((name.as_str(), v.as_str())))
            .collect(),
        None => vec![None],
    };
    let mut codes = Vec::new();
    for matrix in values {
        for step in &job.steps {
            if step.run.contains("cargo build") || step.uses.starts_with("actions/checkout") {
                continue;
            }
            if step.uses.starts_with("actions/upload-artifact") {
                let name = expand(&step.with["name"], matrix);
                let path = dir.join(expand(&step.with["path"], matrix));
                if path.is_dir() {
                    copy_tree(&path, &artifacts.join(name));
                }
            } else if step.uses.starts_with("actions/download-artifact") {
                let prefix = step.with["pattern"].trim_end_matches('*').to_owned();
                let into = dir.join(&step.with["path"]);
                for entry in std::fs::read_dir(artifacts).unwrap() {
                    let name = entry.unwrap().file_name().into_string().unwrap();
                    if name.starts_with(&prefix) {
                        copy_tree(&artifacts.join(&name), &into.join(&name));
                    }
                }
            } else if !step.run.is_empty() {
                let (code, output) = bash(dir, &expand(&step.run, matrix), summary);
                assert!(!output.contains("panicked"), "{output}");
                assert!(
                    code == 0 || code == 1,
                    "step {:?} exited {code}:\n{output}",
                    step.name
                );
                codes.push(code);
            }
        }
    }
    codes
}

#[test]
fn the_workflow_steps_shard_and_merge_the_bundled_cases() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let yaml = std::fs::read_to_string(root.join(WORKFLOW)).unwrap();
    let jobs = jobs(&yaml);
    let (shard, merge) = (&jobs["shard"], &jobs["merge"]);
    assert_eq!(
        shard.matrix.as_ref().map(|(_, v)| v.len()),
        Some(4),
        "the shard job's matrix: {shard:?}"
    );
    assert!(merge
        .steps
        .iter()
        .any(|s| s.run.contains("rastercheck merge")));

    // The repository as the workflow's checkout sees it: the cases and
    // their golden files, and the binary where `cargo build --release` puts it.
    let dir = scratch("ci-workflow");
    for tree in ["cases", "reference"] {
        std::os::unix::fs::symlink(root.join(tree), dir.join(tree)).unwrap();
    }
    std::fs::create_dir_all(dir.join("target/release")).unwrap();
    std::os::unix::fs::symlink(
        env!("CARGO_BIN_EXE_rastercheck"),
        dir.join("target/release/rastercheck"),
    )
    .unwrap();
    let artifacts = dir.join("artifacts");
    std::fs::create_dir_all(&artifacts).unwrap();
    let summary = dir.join("step-summary.md");

    let shard_codes = run_job(&dir, shard, &artifacts, &summary);
    assert_eq!(shard_codes, [0, 0, 0, 0], "production passes every shard");
    let merge_codes = run_job(&dir, merge, &artifacts, &summary);
    assert_eq!(merge_codes, [0]);

    // The job summary is the merged summary.md; the merged JUnit is there.
    let merged = dir.join("out/merged");
    let shown = std::fs::read_to_string(&summary).unwrap();
    assert_eq!(
        shown,
        std::fs::read_to_string(merged.join("summary.md")).unwrap()
    );
    assert!(merged.join("junit.xml").is_file());
    assert!(artifacts.join("rastercheck-merged/report.json").is_file());

    // And it is the unsharded run's verdicts.
    let whole = dir.join("whole");
    let out = rastercheck(
        &dir,
        &[
            "run",
            "cases",
            "-r",
            "production",
            "-q",
            "--report",
            whole.to_str().unwrap(),
        ],
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let verdicts = |report: &Path| {
        let report = read_json(&report.join("report.json"));
        (report["totals"].clone(), common::cli::verdicts(&report))
    };
    assert_eq!(verdicts(&whole), verdicts(&merged));
}
