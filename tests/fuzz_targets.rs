//! The coverage-guided fuzz targets' side of the binary (`fuzz/`):
//! `rastercheck fuzz --corpus` writes every target's seeds, and
//! `--from-crash` turns a crash input of the scene target into a shrunk
//! case file that `run` reproduces. A wrong rasterizer (a mutant) fails the
//! scene a seed tape draws, and production passes it. The targets
//! themselves run clean on every seed (a unit test in
//! src/explore/fuzz/targets/); that libFuzzer finds a bug planted in
//! production is fuzz/smoke.sh's check, which CI runs.

mod common;

use std::path::{Path, PathBuf};
use std::process::Output;

use common::cli::{rastercheck as rastercheck_in, scratch, text};
use rastercheck::scene::{parse_case, Limits};

/// Runs the binary in the repository root (for `cases/`).
fn rastercheck(args: &[&str]) -> Output {
    rastercheck_in(Path::new(env!("CARGO_MANIFEST_DIR")), args)
}

fn files(dir: &Path) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|d| d.map(|e| e.unwrap().path()).collect())
        .unwrap_or_default();
    files.sort();
    files
}

/// The seed corpus of every target, with the bundled cases as the case
/// reader's seeds, byte for byte.
#[test]
fn corpus_holds_every_targets_seeds() {
    let dir = scratch("fuzz-targets-corpus");
    let out = rastercheck(&["fuzz", "--corpus", dir.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    for (target, at_least) in [
        ("case_json", 300),
        ("scene_reference_vs_production", 48),
        ("protocol_response", 15),
        ("exact_arithmetic", 16),
    ] {
        let n = files(&dir.join(target)).len();
        assert!(n >= at_least, "{target}: {n} seeds");
    }
    let seed = std::fs::read(dir.join("case_json/triangles_shared_edge_vertical.json")).unwrap();
    assert_eq!(
        seed,
        std::fs::read(
            Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/triangles/shared_edge_vertical.json")
        )
        .unwrap()
    );
    let missing = rastercheck(&[
        "fuzz",
        "--corpus",
        dir.to_str().unwrap(),
        "--corpus-cases",
        "no/such",
    ]);
    assert_eq!(missing.status.code(), Some(2), "{}", text(&missing));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A mesh seed of the scene target, as a crash input: a closed-edge mutant
/// fails it and `--from-crash` writes the shrunk case, which `run`
/// reproduces and production passes; production passes the input itself.
#[test]
fn from_crash_shrinks_the_scene_a_tape_draws() {
    let dir = scratch("fuzz-targets-crash");
    let out = rastercheck(&["fuzz", "--corpus", dir.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let tapes: Vec<PathBuf> = files(&dir.join("scene_reference_vs_production"))
        .into_iter()
        .filter(|p| {
            p.file_name()
                .unwrap()
                .to_string_lossy()
                .starts_with("meshes_")
        })
        .collect();
    assert_eq!(tapes.len(), 8);

    let mut found = None;
    for tape in &tapes {
        let production = rastercheck(&[
            "fuzz",
            "-r",
            "production",
            "--from-crash",
            tape.to_str().unwrap(),
        ]);
        let log = text(&production);
        assert_eq!(production.status.code(), Some(0), "{log}");
        assert!(log.contains("production passes the scene"), "{log}");

        let cases = dir.join(format!(
            "out-{}",
            tape.file_name().unwrap().to_string_lossy()
        ));
        let mutant = rastercheck(&[
            "fuzz",
            "-r",
            "mutant:closed-edges",
            "--from-crash",
            tape.to_str().unwrap(),
            "--out",
            cases.to_str().unwrap(),
        ]);
        if mutant.status.code() == Some(1) {
            found = Some((text(&mutant), cases));
            break;
        }
        assert_eq!(mutant.status.code(), Some(0), "{}", text(&mutant));
    }
    let (log, cases) = found.expect("the closed-edge mutant fails one of 8 generated meshes");
    assert!(log.contains("FAIL  meshes_"), "{log}");
    let written = files(&cases);
    assert_eq!(written.len(), 1, "{written:?}");
    let name = written[0]
        .file_name()
        .unwrap()
        .to_string_lossy()
        .into_owned();
    assert!(
        name.starts_with("fuzz_mutant_closed_edges_") && name.contains("_crash_"),
        "{name}"
    );
    let case = std::fs::read_to_string(&written[0]).unwrap();
    let scene = parse_case(&case, "shrunk", &Limits::default()).expect("a valid case");
    assert!(
        scene.description.contains("the libFuzzer input meshes_"),
        "{case}"
    );
    assert!(scene.primitives.len() <= 3, "{case}");
    let again = rastercheck(&[
        "run",
        written[0].to_str().unwrap(),
        "-r",
        "mutant:closed-edges",
    ]);
    assert_eq!(again.status.code(), Some(1), "{}", text(&again));
    let production = rastercheck(&["run", written[0].to_str().unwrap(), "-r", "production"]);
    assert_eq!(production.status.code(), Some(0), "{}", text(&production));

    let none = rastercheck(&["fuzz", "-r", "production", "--from-crash", "no/such/crash"]);
    assert_eq!(none.status.code(), Some(2), "{}", text(&none));
    assert!(text(&none).contains("no/such/crash"), "{}", text(&none));
    std::fs::remove_dir_all(&dir).unwrap();
}
