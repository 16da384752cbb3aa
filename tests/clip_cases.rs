//! The clip-space cases (`cases/clip/`, SPEC.md §16) and their generator,
//! `tools/gen_clip.py`, whose exact Python model of §16 computes every
//! case's `expect.samples_covered`.
//!
//! Whether the reference meets those pins is `tests/conformance.rs`'s job
//! (it runs every case under `cases/`). This test keeps the files and the
//! generator in step, checks that every case is a clip-space case that pins
//! its coverage, and runs the generator's self-test: its cross-checks, and
//! deliberately wrong variants of the model (dividing before clipping,
//! dividing by a negative w, a float clipper, y up, ...) each of which must
//! change at least one pin, so that a rasterizer with that bug fails a case.
//! Last, a differential test: the reference must cover what the model
//! covers on random clip-space cases, and must not on the same cases pinned
//! by a wrong model.

use std::path::{Path, PathBuf};
use std::process::Command;

use rastercheck::harness::{discover, load, oracle};
use rastercheck::scene::{parse_case, Limits};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Runs `python3 tools/gen_clip.py ARGS` and returns its standard output;
/// panics with both streams when it fails.
fn generator(args: &[&str]) -> String {
    let out = Command::new("python3")
        .arg(root().join("tools/gen_clip.py"))
        .args(args)
        .current_dir(root())
        .output()
        .expect("python3 runs");
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "gen_clip.py {args:?} failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    stdout
}

fn clip_cases() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(root().join("cases/clip"))
        .expect("cases/clip exists")
        .map(|e| e.expect("readable entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    files
}

#[test]
fn the_files_are_what_the_generator_writes() {
    let out = generator(&["--check"]);
    assert!(out.contains("files up to date"), "{out}");
}

#[test]
fn every_clip_case_is_in_clip_space_and_pins_its_coverage() {
    let files = clip_cases();
    assert!(files.len() >= 50, "{} clip cases", files.len());
    for file in &files {
        let text = std::fs::read_to_string(file).expect("readable");
        let name = file.display().to_string();
        let scene =
            parse_case(&text, &name, &Limits::default()).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(scene.in_clip_space(), "{name} is not in clip space");
        assert!(
            scene.expect.samples_covered.is_some(),
            "{name} gives no samples_covered"
        );
        assert!(
            scene.description.len() > 80,
            "{name}: a description says what the case tests and why it is hard"
        );
    }
}

#[test]
fn the_worked_examples_spec_section_16_names_exist() {
    let spec = std::fs::read_to_string(root().join("SPEC.md")).expect("SPEC.md");
    let section = &spec[spec.find("## 16. Clip space").expect("SPEC §16")..];
    let mut named = 0;
    for (i, _) in section.match_indices("`cases/") {
        let rest = &section[i + 1..];
        let path = &rest[..rest.find('`').expect("closing backtick")];
        assert!(
            Path::new(&root().join(path)).is_file(),
            "SPEC §16 names {path}, which does not exist"
        );
        named += 1;
    }
    assert!(named >= 10, "SPEC §16 names {named} cases");
}

/// The planted bugs: each wrong variant of the model changes at least one
/// pin (the generator exits non-zero otherwise), and the cross-checks pass.
#[test]
fn wrong_models_change_pins() {
    let out = generator(&["--self-test"]);
    let caught = out.lines().filter(|l| l.starts_with("caught")).count();
    assert!(caught >= 8, "{out}");
    assert!(!out.contains("NOT CAUGHT"), "{out}");
    assert!(out.contains("ray cast agrees"), "{out}");
}

/// Random clip-space cases pinned by the model and the reference's count
/// of covered samples on each: (cases, disagreements, first few).
fn reference_against_model(seed: &str, wrong: bool) -> (usize, usize, Vec<String>) {
    let dir = std::env::temp_dir().join(format!(
        "rastercheck-clip-random-{seed}-{wrong}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    let cases = dir.join("cases");
    let out = cases.display().to_string();
    let mut args = vec!["--random", seed, "150", out.as_str()];
    if wrong {
        args.push("--wrong");
    }
    generator(&args);
    let found = discover::discover(&[cases]);
    assert!(found.errors.is_empty(), "{:?}", found.errors);
    let mut differ = Vec::new();
    for file in &found.cases {
        let scene = load::load(file, &Limits::default()).expect("a valid random case");
        let covered = oracle::run_reference(&scene).frame.covered_samples();
        let pinned = scene.expect.samples_covered.expect("pinned");
        if covered != pinned {
            differ.push(format!("{}: reference {covered}, model {pinned}", file.id));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    (
        found.cases.len(),
        differ.len(),
        differ.into_iter().take(5).collect(),
    )
}

/// A differential test of the reference against the Python model, on
/// random triangles in front of, at and behind the eye under random
/// conventions; the same cases pinned by a wrong model (vertices behind the
/// eye divided by their w) show that it can fail.
#[test]
fn the_reference_covers_what_the_model_covers_on_random_cases() {
    let (n, differ, shown) = reference_against_model("7", false);
    assert_eq!(n, 150);
    assert_eq!(differ, 0, "{shown:#?}");
    let (_, differ, _) = reference_against_model("7", true);
    assert!(differ > 0, "the wrong model's pins all hold");
}
