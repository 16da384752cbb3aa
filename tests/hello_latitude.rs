//! The diamond-exit latitude (SPEC.md §4.2.1) declared by an external
//! program in its hello (`conventions.diamond_exit`, §12.7) and by a
//! profile (`conventions.diamond_exit`, §13), checked like the other keys.
//!
//! `tests/clients/bresenham.py` draws diamond-exit lines by Bresenham's
//! algorithm between the pixels of their ends: within the latitude the
//! APIs allow, not the exact rule. Undeclared, it fails the diamond-exit
//! cases where Bresenham departs from the exact set; declaring the
//! latitude, it passes them, judged under the four rules with its moves
//! counted. Moved two rows down (`--shift 2`), it lies outside the
//! latitude and fails whether it declares it or not.

use std::path::PathBuf;

use rastercheck::adapters::external::External;
use rastercheck::harness::judge::{run_candidate, Verdict};
use rastercheck::harness::profile::{load_declared, Profiled};
use rastercheck::harness::{discover, load, oracle};
use rastercheck::rasterizer::Rasterizer;
use rastercheck::scene::{Limits, Scene};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Bundled cases of diamond-exit lines alone, single-sample, on which the
/// client keeps to the latitude.
const CASES: [&str; 6] = [
    "diamond_axis_lines",
    "diamond_endpoints_centres",
    "diamond_endpoints_corners",
    "diamond_exit_worked_example",
    "diamond_far_endpoints",
    "diamond_star_16",
];

/// Bundled cases on which the client leaves the latitude: on a line whose
/// end lies on a diamond's edge, or on a diagonal, it lights a fragment
/// more than one unit from every exact one (its count then off by two).
/// Declared or not, it fails them.
const BEYOND: [&str; 4] = [
    "diamond_diagonals",
    "diamond_endpoints_edges",
    "diamond_strip",
    "diamond_subpixel_8bits",
];

fn scene(id: &str) -> Scene {
    let path = root().join("cases/lines").join(format!("{id}.json"));
    load::load(&discover::case_file(&path), &Limits::default()).unwrap()
}

fn client(flags: &[&str]) -> External {
    let mut args = vec![root()
        .join("tests/clients/bresenham.py")
        .display()
        .to_string()];
    args.extend(flags.iter().map(|f| f.to_string()));
    External::new("bresenham", "python3".to_owned(), args, true)
}

/// (passed, failed with reasons, judged under the latitude) over CASES.
fn tally(candidate: &dyn Rasterizer) -> (Vec<&'static str>, Vec<String>, usize) {
    tally_over(&CASES, candidate)
}

fn tally_over(
    cases: &[&'static str],
    candidate: &dyn Rasterizer,
) -> (Vec<&'static str>, Vec<String>, usize) {
    let (mut pass, mut fail, mut latitude) = (Vec::new(), Vec::new(), 0);
    for &id in cases {
        let scene = scene(id);
        let reference = oracle::run_reference(&scene);
        let run = run_candidate(&scene, &reference, candidate);
        latitude += usize::from(run.judged.line_latitude);
        match &run.verdict {
            Verdict::Pass => pass.push(id),
            Verdict::Fail(why) => fail.push(format!("{id}: {}", why.join("; "))),
            other => panic!("{id}: {other:?}"),
        }
    }
    eprintln!(
        "{}: {} pass, {} fail, {latitude} under the latitude",
        candidate.name(),
        pass.len(),
        fail.len()
    );
    (pass, fail, latitude)
}

#[test]
fn bresenham_lines_pass_under_a_declared_latitude_and_fail_without_it() {
    let (_, undeclared, latitude) = tally(&client(&[]));
    assert_eq!(latitude, 0);
    // Judged exactly, every one of them differs from the diamond-exit set.
    assert_eq!(undeclared.len(), CASES.len(), "{undeclared:#?}");
    let (pass, declared, latitude) = tally(&client(&["--latitude"]));
    assert!(declared.is_empty(), "{declared:#?}");
    assert_eq!(pass.len(), CASES.len());
    assert_eq!(latitude, CASES.len());
}

#[test]
fn lines_outside_the_latitude_fail_declared_or_not() {
    for flags in [&[][..], &["--latitude"]] {
        let (pass, fail, _) = tally_over(&BEYOND, &client(flags));
        assert!(pass.is_empty(), "{flags:?}: {pass:?}");
        let declared = !flags.is_empty();
        for why in fail.iter().filter(|_| declared) {
            assert!(
                why.contains("more than one unit from every diamond-exit fragment"),
                "{why}"
            );
        }
    }
    for flags in [&["--shift", "2"][..], &["--shift", "2", "--latitude"]] {
        let (pass, fail, _) = tally(&client(flags));
        assert!(pass.is_empty(), "{flags:?}: {pass:?}");
        assert_eq!(fail.len(), CASES.len(), "{flags:?}");
    }
}

/// A profile declares the latitude for a program that cannot say it in a
/// hello (or a built-in rasterizer): judged as the declaring hello is.
#[test]
fn a_profile_declares_the_latitude() {
    let dir = std::env::temp_dir().join(format!("rastercheck-latitude-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("bresenham.json");
    std::fs::write(
        &file,
        r#"{"schema": "rastercheck-profile/1", "rasterizer": "bresenham",
            "fill_rule": "top-left", "conventions": {"diamond_exit": "latitude"}}"#,
    )
    .unwrap();
    let d = load_declared(&file).unwrap();
    assert_eq!(d.conventions.diamond_exit_latitude, Some(true));
    assert!(
        d.note().contains("latitude for diamond-exit lines"),
        "{}",
        d.note()
    );
    let profiled = Profiled {
        inner: Box::new(client(&[])),
        rule: d.fill_rule,
        conventions: d.conventions,
        coverage: d.coverage,
    };
    let (pass, fail, latitude) = tally(&profiled);
    assert!(fail.is_empty(), "{fail:#?}");
    assert_eq!((pass.len(), latitude), (CASES.len(), CASES.len()));
    // Checked like the hello: a wrong word names its path, a wrong key
    // the one meant.
    std::fs::write(
        &file,
        r#"{"schema": "rastercheck-profile/1", "rasterizer": "bresenham",
            "fill_rule": "top-left", "conventions": {"diamond_exit": "latitud"}}"#,
    )
    .unwrap();
    let e = load_declared(&file).unwrap_err();
    assert!(e.contains("$.conventions.diamond_exit"), "{e}");
    assert!(e.contains("known: exact-rule, latitude"), "{e}");
    std::fs::write(
        &file,
        r#"{"schema": "rastercheck-profile/1", "rasterizer": "bresenham",
            "fill_rule": "top-left", "conventions": {"diamond_exits": "latitude"}}"#,
    )
    .unwrap();
    let e = load_declared(&file).unwrap_err();
    assert!(e.contains("did you mean \"diamond_exit\""), "{e}");
    std::fs::remove_dir_all(&dir).ok();
}

/// The hello's key is checked like every other: a wrong word or a key one
/// typo away is an error naming its JSON path, with the word or key meant.
#[test]
fn the_hello_checks_the_latitude_key() {
    use rastercheck::adapters::external::read_hello;
    let s = scene("diamond_exit_worked_example");
    let plan = rastercheck::plan::Plan::for_scene(&s);
    let hello = |conventions: &str| {
        format!(r#"{{"hello": {{"protocol": 2, "conventions": {conventions}}}}}"#)
    };
    let ok = read_hello(
        hello(r#"{"diamond_exit": "latitude"}"#).as_bytes(),
        &s,
        &plan,
    );
    assert!(ok.is_ok(), "{ok:?}");
    let word = read_hello(
        hello(r#"{"diamond_exit": "latitud"}"#).as_bytes(),
        &s,
        &plan,
    )
    .unwrap_err();
    assert!(
        word.contains(
            "$.hello.conventions.diamond_exit is \"latitud\"; did you mean \"latitude\"?"
        ),
        "{word}"
    );
    let key = read_hello(
        hello(r#"{"diamond_exits": "latitude"}"#).as_bytes(),
        &s,
        &plan,
    )
    .unwrap_err();
    assert!(
        key.contains("$.hello.conventions.diamond_exits: unknown key"),
        "{key}"
    );
    assert!(key.contains("did you mean \"diamond_exit\""), "{key}");
}
