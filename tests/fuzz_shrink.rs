//! `rastercheck fuzz`: counterexample search and shrinking, through the real
//! binary. A closed-edge rasterizer (the mutant, and euc) is found to
//! overdraw a mesh, the failure is shrunk to a case of at most three
//! triangles that `rastercheck run` reproduces (and production passes);
//! likewise a wrong resolve, flipped ties on polygons, and the two motion
//! mutants on moving scenes (a `time:` failure on a case of one or two
//! primitives); the production rasterizer survives the search, moving
//! scenes included; a seed always writes the same file; and the command a
//! finding's case file gives (its seed, family and case) writes it again.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use rastercheck::scene::{parse_case, Limits, Primitive};

fn rastercheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rastercheck"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn text(out: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rastercheck-fuzz-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// The one case file a run wrote into `dir`.
fn written(dir: &Path) -> PathBuf {
    let files: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("the output folder exists")
        .map(|e| e.unwrap().path())
        .collect();
    assert_eq!(files.len(), 1, "{files:?}");
    files.into_iter().next().unwrap()
}

/// Runs `rastercheck fuzz -r rasterizer` with `args`, writing into a fresh
/// folder named after `name`: the folder and what the run printed.
fn fuzz(rasterizer: &str, args: &[&str], name: &str) -> (PathBuf, Output) {
    let dir = scratch(name);
    let mut all = vec!["fuzz", "-r", rasterizer];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--out", dir.to_str().unwrap()]);
    let out = rastercheck(&all);
    (dir, out)
}

/// [`fuzz`], which must fail (exit 1) and write one case file. Returns the
/// folder, the log and the file.
fn fuzz_writes_one(rasterizer: &str, args: &[&str], name: &str) -> (PathBuf, String, PathBuf) {
    let (dir, out) = fuzz(rasterizer, args, name);
    let log = text(&out);
    assert_eq!(out.status.code(), Some(1), "{log}");
    let path = written(&dir);
    (dir, log, path)
}

/// [`fuzz`] on production with `args`: all `cases` pass, nothing is
/// written.
fn production_survives(args: &[&str], cases: &str, name: &str) {
    let mut all = vec!["--cases", cases];
    all.extend_from_slice(args);
    let (dir, out) = fuzz("production", &all, name);
    let log = text(&out);
    assert_eq!(out.status.code(), Some(0), "{log}");
    assert!(log.contains(&format!("{cases} cases, ")), "{log}");
    assert!(log.contains(" 0 failed and shrunk"), "{log}");
    assert!(!dir.exists(), "nothing is written when nothing fails");
}

/// `run` fails the shrunk `case` at `path` for `rasterizer` (its log is
/// returned) and passes it for production.
fn reproduced(path: &Path, rasterizer: &str, case: &str) -> String {
    let again = rastercheck(&["run", path.to_str().unwrap(), "-r", rasterizer]);
    let again_log = text(&again);
    assert_eq!(again.status.code(), Some(1), "{again_log}\n{case}");
    let production = rastercheck(&["run", path.to_str().unwrap(), "-r", "production"]);
    assert_eq!(
        production.status.code(),
        Some(0),
        "{}\n{case}",
        text(&production)
    );
    again_log
}

/// Fuzzes meshes on `rasterizer`, and checks the shrunk case: a watertight
/// mesh of at most three triangles that `run` fails for `rasterizer` on
/// watertightness and passes for production.
fn finds_and_shrinks_overdraw(rasterizer: &str, name: &str) {
    let args = ["--family", "meshes", "--seed", "1", "--cases", "200"];
    let (dir, log, path) = fuzz_writes_one(rasterizer, &args, name);
    assert!(log.contains("seed 1"), "{log}");
    assert!(log.contains(&path.display().to_string()), "{log}");

    let case = std::fs::read_to_string(&path).unwrap();
    let scene = parse_case(&case, "shrunk", &Limits::default()).expect("a valid case");
    assert!(scene.expect.watertight, "{case}");
    assert!(
        (1..=3).contains(&scene.primitives.len()),
        "not shrunk to 3 triangles or fewer:\n{case}"
    );
    assert!(scene
        .primitives
        .iter()
        .all(|p| matches!(p, Primitive::Triangle(_))));
    assert!(scene.description.contains("seed 1"), "{case}");
    assert!(scene.description.contains("originally"), "{case}");

    let again_log = reproduced(&path, rasterizer, &case);
    assert!(again_log.contains("watertight: "), "{again_log}");
    assert!(
        again_log.contains("overdrawn samples") || again_log.contains(" holes and "),
        "{again_log}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn closed_edges_mutant_overdraw_shrinks_to_three_triangles_or_fewer() {
    finds_and_shrinks_overdraw("mutant:closed-edges", "closed-edges");
}

#[test]
fn euc_overdraw_shrinks_to_three_triangles_or_fewer() {
    finds_and_shrinks_overdraw("euc", "euc");
}

#[test]
fn production_survives_the_search() {
    production_survives(&["--seed", "7"], "200", "production");
}

#[test]
fn the_same_seed_writes_the_same_file() {
    let runs: Vec<(String, Vec<u8>)> = ["a", "b"]
        .iter()
        .map(|run| {
            let args = ["--seed", "12345", "--cases", "100"];
            let name = format!("determinism-{run}");
            let (dir, _, path) = fuzz_writes_one("mutant:flipped-ties", &args, &name);
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            let bytes = std::fs::read(&path).unwrap();
            let _ = std::fs::remove_dir_all(&dir);
            (name, bytes)
        })
        .collect();
    assert_eq!(runs[0], runs[1]);
}

#[test]
fn bad_input_exits_2() {
    for args in [
        &["fuzz", "-r", "no-such-rasterizer"][..],
        &["fuzz", "-r", "production", "--family", "quads"],
        &["fuzz", "-r", "production", "--check", "speed"],
        &["fuzz", "-r", "production", "--cases", "0"],
    ] {
        let out = rastercheck(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", text(&out));
    }
}

#[test]
fn check_selects_the_kind_to_shrink() {
    // euc fails single triangles on coverage first; asking for
    // watertightness skips those until a mesh overdraws.
    let args = ["--check", "watertight", "--seed", "2", "--cases", "300"];
    let (dir, _, path) = fuzz_writes_one("euc", &args, "check");
    let name = path.file_name().unwrap().to_string_lossy().into_owned();
    assert!(
        name.contains("overdraw") || name.contains("holes"),
        "{path:?}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// Fuzzes `family` on `rasterizer` and checks the shrunk case: it reads
/// back (effects and polygons included), has at most `most` primitives,
/// `run` fails it for `rasterizer` with a reason starting `reason` and
/// production passes it. Returns the case text.
fn finds_and_shrinks(
    rasterizer: &str,
    family: &str,
    seed: &str,
    most: usize,
    reason: &str,
) -> String {
    let args = ["--family", family, "--seed", seed, "--cases", "100"];
    let name = format!("{family}-{}", rasterizer.replace(':', "-"));
    let (dir, _, path) = fuzz_writes_one(rasterizer, &args, &name);
    let case = std::fs::read_to_string(&path).unwrap();
    let scene = parse_case(&case, "shrunk", &Limits::default()).expect("a valid case");
    assert!(
        (1..=most).contains(&scene.primitives.len()),
        "not shrunk to {most} primitives or fewer:\n{case}"
    );
    let again_log = reproduced(&path, rasterizer, &case);
    assert!(again_log.contains(reason), "{again_log}\n{case}");
    let _ = std::fs::remove_dir_all(&dir);
    case
}

#[test]
fn a_wrong_resolve_on_antialiased_scenes_shrinks_to_a_small_antialiased_case() {
    // leaky-full resolves full pixels a hair under 1: only antialiased
    // scenes show it, so the shrunk case keeps its effects.antialias.
    let case = finds_and_shrinks("mutant:leaky-full", "antialias", "1", 2, "antialias: ");
    let scene = parse_case(&case, "shrunk", &Limits::default()).unwrap();
    let aa = scene
        .effects
        .antialias
        .expect("the effect is written and kept");
    assert!(aa.samples <= 16, "{case}");
    assert!(scene.expect.area.is_some(), "{case}");
}

#[test]
fn flipped_ties_on_polygons_shrink_to_a_small_polygon_case() {
    let case = finds_and_shrinks("mutant:flipped-ties", "polygons", "1", 2, "coverage: ");
    let scene = parse_case(&case, "shrunk", &Limits::default()).unwrap();
    let vertices: usize = scene.primitives.iter().map(|p| p.vertices().len()).sum();
    assert!(vertices <= 8, "{case}");
}

/// Fuzzes moving scenes on a motion mutant and checks the shrunk case
/// beyond what [`finds_and_shrinks`] does: it still moves, keeps its
/// `effects.motion_blur`, sits on a canvas of at most 4×4 pixels (the
/// search starts from canvases up to 16×16; today every shrink ends on
/// 1×1 with one primitive) and pins the reference's time coverage of the
/// pixel it fails at.
fn motion_mutant_shrinks(mutant: &str) {
    let case = finds_and_shrinks(mutant, "motion", "1", 2, "time: ");
    let scene = parse_case(&case, "shrunk", &Limits::default()).unwrap();
    assert!(scene.moves(), "{case}");
    let blur = scene
        .effects
        .motion_blur
        .as_ref()
        .expect("motion blur kept");
    assert!(blur.samples <= 16, "{case}");
    assert!(
        scene.canvas.width <= 4 && scene.canvas.height <= 4,
        "not cropped to 4×4 or less:\n{case}"
    );
    assert_eq!(scene.expect.time_coverage.len(), 1, "{case}");
}

#[test]
fn drawing_at_shutter_open_shrinks_to_a_small_moving_case() {
    motion_mutant_shrinks("mutant:motion-at-open");
}

#[test]
fn half_a_shutter_shrinks_to_a_small_moving_case() {
    motion_mutant_shrinks("mutant:motion-half-shutter");
}

#[test]
fn production_survives_the_motion_search() {
    production_survives(
        &["--family", "motion", "--seed", "3"],
        "60",
        "production-motion",
    );
}

/// The command a written case's description says found it: between
/// "Found by `" and the next "`".
fn found_by(case: &str) -> String {
    let scene = parse_case(case, "found", &Limits::default()).expect("a valid case");
    let (_, rest) = scene
        .description
        .split_once("Found by `")
        .unwrap_or_else(|| panic!("no command in {:?}", scene.description));
    rest.split_once('`').expect("a closing quote").0.to_owned()
}

#[test]
fn a_findings_printed_command_draws_it_again() {
    // A search naming no family finds a failure past its first cases; the
    // command its case file and its log give names the family and the case
    // (so that it stays valid when a version adds families, which changes
    // the family an unnamed search gives each case), and running it
    // writes the same file.
    let args = ["--seed", "12345", "--cases", "100"];
    let (dir, log, path) = fuzz_writes_one("mutant:flipped-ties", &args, "reproduce");
    let case = std::fs::read_to_string(&path).unwrap();
    let command = found_by(&case);
    assert!(log.contains(&format!("found again by: {command}")), "{log}");
    let words: Vec<String> = command
        .split_whitespace()
        .map(|w| w.trim_matches('\'').to_owned())
        .collect();
    let at = |flag: &str| {
        let k = words.iter().position(|w| w == flag);
        k.map(|k| words[k + 1].clone())
            .unwrap_or_else(|| panic!("{command} has no {flag}"))
    };
    assert_eq!(words[..2], ["rastercheck", "fuzz"], "{command}");
    assert_eq!(at("-r"), "mutant:flipped-ties");
    assert_eq!(at("--seed"), "12345");
    assert_eq!(at("--cases"), "1");
    let family = at("--family");
    let first: u64 = at("--first-case").parse().unwrap();
    assert!(
        first > 0,
        "the seed's first case fails: --first-case is not tried"
    );
    assert!(
        log.contains(&format!("FAIL  case {first} ({family},")),
        "{log}"
    );
    let again: Vec<&str> = words[2..].iter().map(String::as_str).collect();
    let (dir_again, log_again, path_again) =
        fuzz_writes_one(again[1], &again[2..], "reproduce-again");
    assert_eq!(path.file_name(), path_again.file_name(), "{log_again}");
    assert_eq!(
        std::fs::read(&path).unwrap(),
        std::fs::read(&path_again).unwrap(),
        "{log_again}"
    );
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&dir_again);
}
