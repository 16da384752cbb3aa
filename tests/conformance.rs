//! The conformance harness: one trial per case file, named by its path below
//! `cases/` (`triangles/fan_center`, `invalid/nan_string`).
//!
//! - A valid case passes when the production rasterizer matches the exact
//!   reference under the case's expectations, and the reference reproduces
//!   its golden file `reference/<id>.exr` bit for bit.
//! - A case under `cases/invalid/` passes when reading it fails with the
//!   error its `.error` file states: the first line is the JSON path (or
//!   `line L column C`), the second a phrase the message must contain.
//!
//! Listing only walks the folder, so it stays cheap when nextest runs each
//! trial in its own process. Filter as usual:
//! `cargo test --test conformance -- triangles/`.

use std::path::{Path, PathBuf};

use libtest_mimic::{Arguments, Failed, Trial};
use rastercheck::harness::discover::CaseFile;
use rastercheck::harness::golden::GoldenStatus;
use rastercheck::harness::judge::Verdict;
use rastercheck::harness::{discover, golden, judge, load, oracle};
use rastercheck::production::Production;
use rastercheck::scene::Limits;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn main() {
    let args = Arguments::from_args();
    let cases = root().join("cases");
    let found = discover::discover(std::slice::from_ref(&cases));
    let mut trials: Vec<Trial> = found
        .cases
        .into_iter()
        .map(|file| Trial::test(file.id.clone(), move || valid_case(&file)))
        .collect();
    for dir in found.skipped {
        let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
            .expect("readable invalid folder")
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|e| e == "json"))
            .collect();
        files.sort();
        for path in files {
            let file = discover::case_file(&path);
            trials.push(Trial::test(file.id.clone(), move || invalid_case(&file)));
        }
    }
    libtest_mimic::run(&args, trials).exit();
}

fn valid_case(file: &CaseFile) -> Result<(), Failed> {
    let scene = load::load(file, &Limits::default()).map_err(|e| e.to_string())?;
    let reference = oracle::run_reference(&scene);
    let mut problems = Vec::new();
    match golden::check_golden(&root(), &file.id, &reference.frame) {
        GoldenStatus::Matches => {}
        GoldenStatus::Missing(path) => problems.push(format!(
            "no golden file {}; run `cargo run --release -- bless {}` and review it",
            path.display(),
            file.path.display()
        )),
        GoldenStatus::Differs(why) => problems.push(format!(
            "the reference no longer reproduces its golden file: {why}"
        )),
    }
    let run = judge::run_candidate(&scene, &reference, &Production);
    match &run.verdict {
        Verdict::Pass => {}
        Verdict::Fail(reasons) => {
            problems.extend(reasons.iter().map(|r| format!("production: {r}")))
        }
        other => problems.push(format!(
            "production: {}: {}",
            other.label(),
            judge::describe(&run)
        )),
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(problems.join("\n").into())
    }
}

fn invalid_case(file: &CaseFile) -> Result<(), Failed> {
    let expected = expected_error(&file.path)?;
    match load::load(file, &Limits::default()) {
        Ok(_) => Err(format!(
            "{} was read without error; expected: {expected:?}",
            file.path.display()
        )
        .into()),
        Err(e) => {
            let (location, phrase) = &expected;
            if &e.location != location || !e.message.contains(phrase.as_str()) {
                return Err(format!(
                    "wrong error.\n expected: {location}: …{phrase}…\n      got: {}: {}",
                    e.location, e.message
                )
                .into());
            }
            Ok(())
        }
    }
}

fn expected_error(case: &Path) -> Result<(String, String), Failed> {
    let path = case.with_extension("error");
    let text = std::fs::read_to_string(&path).map_err(|e| {
        format!(
            "{}: {e} (every invalid case states its error there)",
            path.display()
        )
    })?;
    let mut lines = text.lines();
    match (lines.next(), lines.next()) {
        (Some(location), Some(phrase)) => {
            Ok((location.trim().to_owned(), phrase.trim().to_owned()))
        }
        _ => Err(format!(
            "{}: expected two lines, a JSON path and a phrase",
            path.display()
        )
        .into()),
    }
}
