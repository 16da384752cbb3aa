//! External rasterizers (SPEC.md §12): the example Python rasterizer judged
//! through the binary, both modes agreeing, and programs that crash, hang,
//! print garbage or do not exist, each an ERROR for its case only, with no
//! process left behind.

mod common;

use std::path::PathBuf;
use std::time::{Duration, Instant};

use common::cli::{rastercheck_env as rastercheck, text};
use rastercheck::adapters::external::{self, External};
use rastercheck::{parse_case, Limits, Plan, RasterError, Rasterizer};
use serde_json::json;

const EXAMPLE: &str = "examples/python_rasterizer.py";

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The output line of one case and rasterizer.
fn line_of<'a>(t: &'a str, case: &str, rasterizer: &str) -> &'a str {
    t.lines()
        .find(|l| {
            l.split_whitespace().nth(1) == Some(case) && l.contains(&format!("  {rasterizer}  "))
        })
        .unwrap_or_else(|| panic!("no line for {case} / {rasterizer} in:\n{t}"))
}

/// The number just before `word` in a line ("3 overdraw" → 3).
fn count_before(line: &str, word: &str) -> u64 {
    let words: Vec<&str> = line.split_whitespace().collect();
    let at = words
        .iter()
        .position(|w| w.trim_end_matches(',') == word)
        .unwrap_or_else(|| panic!("no {word:?} in {line}"));
    words[at - 1].parse().unwrap()
}

/// A fresh folder for one test.
fn scratch(name: &str) -> PathBuf {
    common::cli::scratch(&format!("external-{name}"))
}

/// A case no sample of which lies on an edge: every rasterizer that gets
/// triangles right at all passes it.
const EASY: &str = r#"{"name": "easy", "canvas": {"width": 8, "height": 8},
  "primitives": [{"triangle": [[0.3, 0.2], [7.7, 1.1], [1.4, 7.3]]}]}"#;

/// The case the misbehaving programs misbehave on.
const VICTIM: &str = r#"{"name": "victim", "canvas": {"width": 8, "height": 8},
  "primitives": [{"triangle": [[0.3, 0.2], [7.7, 1.1], [1.4, 7.6]]}]}"#;

/// A program that answers like the example, except on the case named
/// `victim`, where it does what its first argument says. It writes its pid
/// to `<pids>/<pid>` first, so that tests can look for it afterwards.
const MISBEHAVING: &str = r#"
import importlib.util, json, os, sys, time
mode, example, pids = sys.argv[1], sys.argv[2], sys.argv[3]
spec = importlib.util.spec_from_file_location("example", example)
example = importlib.util.module_from_spec(spec)
spec.loader.exec_module(example)
open(os.path.join(pids, str(os.getpid())), "w").close()

def answer(request):
    if request["case"] != "victim":
        return json.dumps(example.rasterize(request))
    sys.stderr.write("driver: about to %s\n" % mode)
    sys.stderr.flush()
    if mode == "crash":
        sys.exit(3)
    if mode == "hang":
        time.sleep(120)
    if mode == "garbage":
        return "Segmentation fault (core dumped) -- not JSON"
    if mode == "missing":
        return json.dumps({"primitives": [{"pixels": []}]})
    if mode == "outside":
        return json.dumps({"primitives": [{"fragments": [[8, 0]]}]})

if "--persistent" in sys.argv:
    for text in sys.stdin:
        request = json.loads(text)
        if request.get("bye"):
            break
        print(answer(request), flush=True)
else:
    print(answer(json.load(sys.stdin)))
"#;

struct Misbehaving {
    dir: PathBuf,
    pids: PathBuf,
}

impl Misbehaving {
    fn new(name: &str) -> Misbehaving {
        let dir = scratch(name);
        let pids = dir.join("pids");
        std::fs::create_dir_all(&pids).unwrap();
        std::fs::write(dir.join("misbehave.py"), MISBEHAVING).unwrap();
        std::fs::create_dir_all(dir.join("cases")).unwrap();
        std::fs::write(dir.join("cases/easy.json"), EASY).unwrap();
        std::fs::write(dir.join("cases/victim.json"), VICTIM).unwrap();
        Misbehaving { dir, pids }
    }

    fn command(&self, mode: &str) -> String {
        format!(
            "python3 {} {mode} {} {}",
            self.dir.join("misbehave.py").display(),
            root().join(EXAMPLE).display(),
            self.pids.display()
        )
    }

    /// Every process of this program that was started.
    fn started(&self) -> Vec<u32> {
        std::fs::read_dir(&self.pids)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().parse().unwrap())
            .collect()
    }
}

/// The state letter of a process (R, S, Z...), or `None` when it is gone.
fn process_state(pid: u32) -> Option<char> {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    // The state follows the command name, which is in parentheses.
    stat[stat.rfind(')')? + 1..].trim_start().chars().next()
}

/// The tests that start programs in this process take turns, so that the
/// children each sees are its own.
static CHILDREN: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// Children of this test process whose command line mentions `needle`,
/// with their states, and any zombie `python3` child (a zombie has no
/// command line left).
fn children_mentioning(needle: &str) -> Vec<(u32, char)> {
    let me = std::process::id();
    let mut found = Vec::new();
    for entry in std::fs::read_dir("/proc").unwrap().flatten() {
        let Ok(pid) = entry.file_name().to_string_lossy().parse::<u32>() else {
            continue;
        };
        let Ok(stat) = std::fs::read_to_string(format!("/proc/{pid}/stat")) else {
            continue;
        };
        let Some(after) = stat.rfind(')').map(|i| &stat[i + 1..]) else {
            continue;
        };
        let fields: Vec<&str> = after.split_whitespace().collect();
        if fields.get(1).and_then(|p| p.parse::<u32>().ok()) != Some(me) {
            continue;
        }
        let cmdline = std::fs::read(format!("/proc/{pid}/cmdline")).unwrap_or_default();
        let zombie_python = fields[0] == "Z" && stat.contains("(python3)");
        if zombie_python || String::from_utf8_lossy(&cmdline).contains(needle) {
            found.push((pid, fields[0].chars().next().unwrap_or('?')));
        }
    }
    found
}

#[test]
fn the_python_rasterizer_passes_a_plain_triangle_and_overdraws_shared_edges() {
    let started = Instant::now();
    let out = rastercheck(
        &root(),
        &[
            "run",
            "cases/triangles/interp_linear.json",
            "cases/triangles/shared_edge_diagonal.json",
            "cases/lines/midpoint_tie_slope_half.json",
            "cases/lines/rectangle_worked_example.json",
            "-r",
            &format!("external:python3 {EXAMPLE}"),
        ],
        &[],
    );
    let t = text(&out);
    let name = format!("external:python3 {EXAMPLE}");
    assert_eq!(out.status.code(), Some(1), "{t}");
    // One triangle, interpolated in floats: right, and within the bound.
    let plain = line_of(&t, "triangles/interp_linear", &name);
    assert!(plain.starts_with("PASS"), "{t}");
    assert!(plain.contains("interp max"), "{t}");
    // `>= 0` puts the diagonal's 8 samples in both triangles.
    let shared = line_of(&t, "triangles/shared_edge_diagonal", &name);
    assert!(shared.starts_with("FAIL"), "{t}");
    assert_eq!(count_before(shared, "overdraw"), 8, "{t}");
    assert_eq!(count_before(shared, "holes"), 0, "{t}");
    // floor(y) takes the lower row at exact ties.
    let tie = line_of(&t, "lines/midpoint_tie_slope_half", &name);
    assert!(tie.starts_with("FAIL"), "{t}");
    // What it does not do, it says so.
    let rect = line_of(&t, "lines/rectangle_worked_example", &name);
    assert!(rect.starts_with("UNSUPPORTED"), "{t}");
    assert!(rect.contains("rectangle lines are not implemented"), "{t}");
    assert!(
        t.contains(&format!(
            "{name}: 1 passed, 2 failed, 1 unsupported, 0 errors"
        )),
        "{t}"
    );
    eprintln!("one-shot on 4 cases: {:?}", started.elapsed());
}

#[test]
fn persistent_mode_gives_the_results_of_one_shot_mode() {
    let one_shot = format!("external:python3 {EXAMPLE}");
    let persistent = format!("external-persistent:python3 {EXAMPLE} --persistent");
    // Passes, failures (overdraw, ties, interpolation) and unsupported
    // lines; one-shot mode starts a process per case, so not every case.
    let mut args: Vec<String> = vec!["run".into()];
    for family in ["triangles", "lines"] {
        for entry in std::fs::read_dir(root().join("cases").join(family)).unwrap() {
            let name = entry.unwrap().file_name().to_string_lossy().into_owned();
            if [
                "shared_edge",
                "interp",
                "midpoint_",
                "rectangle_w",
                "winding_",
            ]
            .iter()
            .any(|p| name.starts_with(p))
            {
                args.push(format!("cases/{family}/{name}"));
            }
        }
    }
    args.extend([
        "-r".into(),
        one_shot.clone(),
        "-r".into(),
        persistent.clone(),
    ]);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let started = Instant::now();
    let out = rastercheck(&root(), &args, &[]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(1), "{t}");
    // An unsupported case's reason differs: the persistent example speaks
    // protocol v2, and its hello refuses the case unsent (SPEC.md §12.7).
    let results = |name: &str| -> Vec<String> {
        t.lines()
            .filter(|l| l.contains(&format!("  {name}  ")))
            .map(|l| l.replacen(name, "", 1))
            .map(|l| match l.strip_prefix("UNSUPPORTED") {
                Some(rest) => format!("UNSUPPORTED {}", rest.split_whitespace().next().unwrap()),
                None => l,
            })
            .collect()
    };
    let (a, b) = (results(&one_shot), results(&persistent));
    assert!(a.len() > 30, "{t}");
    assert_eq!(a, b);
    let tally = |name: &str| {
        t.lines()
            .find(|l| l.starts_with(&format!("{name}: ")))
            .map(|l| l[name.len()..].to_owned())
            .unwrap()
    };
    assert_eq!(tally(&one_shot), tally(&persistent), "{t}");
    assert!(tally(&one_shot).contains(" 0 errors"), "{t}");
    assert!(a.iter().any(|l| l.starts_with("PASS")), "{t}");
    assert!(a.iter().any(|l| l.starts_with("FAIL")), "{t}");
    assert!(a.iter().any(|l| l.starts_with("UNSUPPORTED")), "{t}");
    assert!(t.contains("declares no rectangle lines"), "{t}");
    eprintln!("{} cases in both modes: {:?}", a.len(), started.elapsed());
}

/// Runs `easy` and `victim` through a program that misbehaves on `victim`,
/// in both modes, and checks that only `victim` is an error, that the error
/// says `expected`, and that no process of the program outlives the run.
fn misbehaving_run(mode: &str, expected: &str, env: &[(&str, &str)]) {
    let program = Misbehaving::new(mode);
    let one_shot = format!("external:{}", program.command(mode));
    let persistent = format!("external-persistent:{} --persistent", program.command(mode));
    let started = Instant::now();
    let out = rastercheck(
        &program.dir,
        &["run", "cases", "-r", &one_shot, "-r", &persistent],
        env,
    );
    let elapsed = started.elapsed();
    let t = text(&out);
    assert_eq!(out.status.code(), Some(1), "{t}");
    for name in [&one_shot, &persistent] {
        let victim = line_of(&t, "victim", name);
        assert!(victim.starts_with("ERROR"), "{t}");
        assert!(victim.contains(expected), "{expected:?} in {t}");
        let easy = line_of(&t, "easy", name);
        assert!(easy.starts_with("PASS"), "the run goes on: {t}");
        assert!(
            t.contains(&format!(
                "{name}: 1 passed, 0 failed, 0 unsupported, 1 errors"
            )),
            "{t}"
        );
    }
    let pids = program.started();
    // One-shot: a process per case; persistent: one, plus a fresh one when
    // the first was discarded (two threads may also each start one).
    assert!(pids.len() >= 3, "{pids:?}");
    for pid in pids {
        assert_eq!(process_state(pid), None, "process {pid} outlived the run");
    }
    eprintln!("{mode}: {elapsed:?}");
}

#[test]
fn a_program_that_crashes_is_an_error_with_its_stderr() {
    misbehaving_run(
        "crash",
        "exited with status 3; stderr: driver: about to crash",
        &[],
    );
}

#[test]
fn a_program_that_hangs_is_killed_at_the_time_limit() {
    misbehaving_run(
        "hang",
        // 3 s, not 1: the limit counts from the program's start, and a
        // Python start-up on a loaded 2-core machine can take over 1 s.
        "timed out after 3 s; stderr: driver: about to hang",
        &[(external::TIMEOUT_ENV, "3")],
    );
}

#[test]
fn a_program_that_prints_garbage_is_an_error() {
    misbehaving_run(
        "garbage",
        "printed something that is not a JSON response",
        &[],
    );
}

#[test]
fn a_response_without_the_required_fields_is_an_error() {
    misbehaving_run(
        "missing",
        "bad response: $.primitives[0] must be an object with a fragments array",
        &[],
    );
}

#[test]
fn a_fragment_outside_the_canvas_is_an_error() {
    misbehaving_run(
        "outside",
        "bad response: $.primitives[0].fragments[0]: (8, 0) is not a pixel of the 8×8 canvas",
        &[],
    );
}

#[test]
fn a_missing_program_cannot_start_and_says_so_once() {
    let dir = scratch("missing-program");
    std::fs::create_dir_all(dir.join("cases")).unwrap();
    std::fs::write(dir.join("cases/easy.json"), EASY).unwrap();
    std::fs::write(
        dir.join("cases/easy_too.json"),
        EASY.replace("\"easy\"", "\"easy_too\""),
    )
    .unwrap();
    for name in [
        "external:/no/such/rasterizer --fast",
        "external-persistent:/no/such/rasterizer",
        "mine=external:/no/such/rasterizer",
    ] {
        let out = rastercheck(&dir, &["run", "cases", "-r", name, "--report", "rep"], &[]);
        let t = text(&out);
        // Bad usage, said once before any case runs, with no report.
        assert_eq!(out.status.code(), Some(2), "{t}");
        assert_eq!(
            t.trim(),
            format!(
                "error: -r {name}: cannot start /no/such/rasterizer: No such file or directory"
            ),
        );
        assert!(!dir.join("rep").exists(), "{t}");
    }
    // A bare name is looked for on PATH.
    let out = rastercheck(
        &dir,
        &["run", "cases", "-r", "external:no-such-rasterizer-here"],
        &[],
    );
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(
        text(&out).contains(
            "cannot start no-such-rasterizer-here: No such file or directory (not found on PATH)"
        ),
        "{}",
        text(&out)
    );
    // No program at all is not a rasterizer name.
    let out = rastercheck(&dir, &["run", "cases", "-r", "external:  "], &[]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(text(&out).contains("unknown rasterizer"), "{}", text(&out));
}

#[test]
fn a_file_that_is_not_executable_cannot_start_and_says_so_once() {
    let dir = scratch("not-executable");
    std::fs::create_dir_all(dir.join("cases")).unwrap();
    std::fs::write(dir.join("cases/easy.json"), EASY).unwrap();
    std::fs::write(dir.join("raster.sh"), "#!/bin/sh\nexit 0\n").unwrap();
    for name in ["external:./raster.sh", "external-persistent:./raster.sh"] {
        for command in [&["run", "cases", "-r", name][..], &["probe", "-r", name]] {
            let out = rastercheck(&dir, command, &[]);
            let t = text(&out);
            assert_eq!(out.status.code(), Some(2), "{command:?}: {t}");
            assert_eq!(
                t.trim(),
                format!(
                    "error: -r {name}: cannot start ./raster.sh: Permission denied (the file \
                     is not executable)"
                ),
                "{command:?}"
            );
        }
    }
    let out = rastercheck(&dir, &["run", "cases", "-r", "external:./cases"], &[]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(
        text(&out).contains("cannot start ./cases: Is a directory"),
        "{}",
        text(&out)
    );
}

#[test]
fn a_bad_time_limit_is_an_error_naming_the_variable() {
    let dir = scratch("bad-timeout");
    std::fs::create_dir_all(dir.join("cases")).unwrap();
    std::fs::write(dir.join("cases/easy.json"), EASY).unwrap();
    let name = format!("external:python3 {}", root().join(EXAMPLE).display());
    let out = rastercheck(
        &dir,
        &["run", "cases", "-r", &name],
        &[(external::TIMEOUT_ENV, "soon")],
    );
    let t = text(&out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(
        t.contains("RASTERCHECK_EXTERNAL_TIMEOUT=\"soon\" is not a positive number of seconds"),
        "{t}"
    );
}

// ---------------------------------------------------------------------------
// In process: the adapter's own children, seen from /proc.

fn scene(text: &str) -> rastercheck::Scene {
    parse_case(text, "test.json", &Limits::default()).unwrap()
}

fn adapter(command: &str, persistent: bool) -> External {
    let words: Vec<String> = command.split_whitespace().map(str::to_owned).collect();
    let prefix = if persistent {
        "external-persistent:"
    } else {
        "external:"
    };
    External::new(
        &format!("{prefix}{command}"),
        words[0].clone(),
        words[1..].to_vec(),
        persistent,
    )
}

#[test]
fn no_process_is_left_behind_in_either_mode() {
    let _turn = CHILDREN.lock().unwrap_or_else(|e| e.into_inner());
    let program = Misbehaving::new("children");
    let script = program.dir.join("misbehave.py").display().to_string();
    let (easy, victim) = (scene(EASY), scene(VICTIM));
    let plan = Plan::for_scene(&easy);
    for mode in ["crash", "hang", "garbage"] {
        for persistent in [false, true] {
            let extra = if persistent { " --persistent" } else { "" };
            let r = adapter(&format!("{}{extra}", program.command(mode)), persistent)
                .with_timeout(Duration::from_secs(2));
            let before = r.rasterize(&easy, &plan);
            assert!(before.is_ok(), "{mode}: {before:?}");
            let broken = r.rasterize(&victim, &plan);
            assert!(matches!(broken, Err(RasterError::Failed(_))), "{broken:?}");
            let after = r.rasterize(&easy, &plan);
            assert!(after.is_ok(), "{mode}: {after:?}");
            let alive = children_mentioning(&script);
            if persistent {
                // The broken process is gone; its replacement waits for work.
                assert_eq!(alive.len(), 1, "{mode}: {alive:?}");
                assert_ne!(alive[0].1, 'Z', "{mode}: {alive:?}");
            } else {
                assert_eq!(alive, vec![], "{mode}");
            }
            drop(r);
            assert_eq!(children_mentioning(&script), vec![], "{mode}");
        }
    }
}

#[test]
fn a_persistent_process_is_started_once_and_reused() {
    let _turn = CHILDREN.lock().unwrap_or_else(|e| e.into_inner());
    let program = Misbehaving::new("reuse");
    let script = program.dir.join("misbehave.py").display().to_string();
    let easy = scene(EASY);
    let plan = Plan::for_scene(&easy);
    let r = adapter(&format!("{} --persistent", program.command("crash")), true);
    let first = r.rasterize(&easy, &plan).unwrap();
    let pids = || -> Vec<u32> { children_mentioning(&script).iter().map(|c| c.0).collect() };
    let alive = pids();
    assert_eq!(alive.len(), 1);
    for _ in 0..5 {
        assert_eq!(r.rasterize(&easy, &plan).unwrap(), first);
    }
    assert_eq!(pids(), alive);
    assert_eq!(program.started().len(), 1);
    drop(r);
    assert_eq!(children_mentioning(&script), vec![]);
}

// ---------------------------------------------------------------------------
// The protocol's documents.

#[test]
fn the_request_carries_exact_and_float_values() {
    let scene = scene(
        r#"{"name": "both", "canvas": {"width": 4, "height": 2},
        "rules": {"subpixel_bits": null, "fill_rule": "bottom-right", "cull": "cw"},
        "primitives": [
          {"triangle": [{"position": ["1/3", 0.1], "z": 0.5, "w": 2, "attributes": ["2/3"]},
                        {"position": [4, 0], "attributes": [1]},
                        {"position": [0, 2], "attributes": [0]}],
           "interpolation": "linear"},
          {"line": [{"position": [0, 0], "attributes": [0]},
                    {"position": [4, 2], "attributes": [0]}],
           "rule": "rectangle", "width": "3/2"}
        ]}"#,
    );
    let plan = Plan::for_scene(&scene);
    let request = external::request(&scene, &plan);
    assert_eq!(request["protocol"], json!(external::PROTOCOL));
    assert_eq!(request["case"], json!("both"));
    assert_eq!(request["canvas"], json!({"width": 4, "height": 2}));
    assert_eq!(
        request["rules"],
        json!({"subpixel_bits": null, "fill_rule": "bottom-right", "cull": "cw",
               "provoking_vertex": "first"})
    );
    assert_eq!(
        request["plan"],
        json!({"samples_per_pixel": 1, "depth": true, "attributes": 1})
    );
    let v = &request["primitives"][0]["triangle"][0];
    assert_eq!(v["x"].as_f64(), Some(1.0 / 3.0));
    assert_eq!(v["y"].as_f64(), Some(0.1));
    assert_eq!(
        v["exact"],
        json!({"x": "1/3", "y": "0.1", "z": "0.5", "w": "2", "attributes": ["2/3"]})
    );
    assert_eq!(request["primitives"][0]["interpolation"], json!("linear"));
    let line = &request["primitives"][1];
    assert_eq!(line["rule"], json!("rectangle"));
    assert_eq!(line["width"].as_f64(), Some(1.5));
    assert_eq!(line["exact"], json!({"width": "1.5"}));
    assert_eq!(line["last_pixel"], json!("include"));
    assert_eq!(line["parameter"], json!("major"));
}

#[test]
fn fragments_compose_in_primitive_order() {
    let scene = scene(
        r#"{"name": "two", "canvas": {"width": 2, "height": 1},
        "primitives": [
          {"triangle": [{"position": [0, 0], "z": 1, "attributes": [5]},
                        {"position": [2, 0], "attributes": [5]},
                        {"position": [0, 1], "attributes": [5]}]},
          {"triangle": [{"position": [0, 0], "attributes": [6]},
                        {"position": [2, 0], "attributes": [6]},
                        {"position": [0, 1], "attributes": [6]}]}
        ]}"#,
    );
    let plan = Plan::for_scene(&scene);
    let response = json!({"primitives": [
        {"fragments": [[0, 0, 0.25, 7.0], [1, 0, 0.5, 8.0]]},
        {"fragments": [[1, 0, 0.75, 9.0]]}
    ]});
    let frame = external::frame_from_response(&response, &scene, &plan).unwrap();
    assert_eq!(frame.coverage, vec![1, 2]);
    assert_eq!(frame.last, vec![1, 2]);
    assert_eq!(frame.depth, Some(vec![0.25, 0.75]));
    assert_eq!(frame.attributes, vec![vec![7.0, 9.0]]);

    let unsupported = json!({"unsupported": "no triangles on Tuesdays"});
    assert_eq!(
        external::frame_from_response(&unsupported, &scene, &plan),
        Err(RasterError::Unsupported("no triangles on Tuesdays".into()))
    );
    for (bad, says) in [
        (json!({"primitives": [{"fragments": []}]}), "has 1 entries"),
        (
            json!({"primitives": [{"fragments": [[0, 0]]}, {"fragments": []}]}),
            "array of 4 numbers: x, y, depth, 1 attributes",
        ),
        (
            json!({"primitives": [{"fragments": [[0.5, 0, 0, 0]]}, {"fragments": []}]}),
            "is not a pixel",
        ),
        (json!({"protocol": "rastercheck-external/9"}), "$.protocol"),
        (
            json!({"error": "GPU lost"}),
            "the program reported an error: GPU lost",
        ),
        (json!([]), "not a JSON object"),
    ] {
        match external::frame_from_response(&bad, &scene, &plan) {
            Err(RasterError::Failed(why)) => assert!(why.contains(says), "{why}"),
            other => panic!("{bad}: {other:?}"),
        }
    }
}

#[test]
fn antialiased_fragments_name_their_sample_and_area_methods_answer_coverage() {
    let scene = scene(
        r#"{"name": "aa", "canvas": {"width": 2, "height": 1},
        "effects": {"antialias": {"samples": 2}},
        "primitives": [{"polygon": [[0, 0], [2, 0], [0, 1]], "fill": "even-odd"},
                       {"triangle": [[0, 0], [2, 0], [0, 1]]}]}"#,
    );
    let plan = Plan::for_scene(&scene);
    let request = external::request(&scene, &plan);
    assert_eq!(request["plan"]["antialias"]["samples"], 2);
    assert_eq!(
        request["plan"]["antialias"]["offsets"][0],
        json!([0.75, 0.75])
    );
    assert_eq!(
        request["plan"]["antialias"]["exact"]["offsets"][1],
        json!(["0.25", "0.25"])
    );
    assert_eq!(request["primitives"][0]["fill"], "even-odd");
    assert_eq!(
        request["primitives"][0]["contours"][0][2]["exact"]["y"],
        "1"
    );

    let response = json!({"primitives": [
        {"fragments": [[0, 0, 1], [1, 0, 1]]},
        {"fragments": [[0, 0, 0], [0, 0, 1]]}
    ]});
    let frame = external::frame_from_response(&response, &scene, &plan).unwrap();
    assert_eq!(frame.samples, 2);
    assert_eq!(frame.coverage, vec![1, 2, 0, 1]);
    assert_eq!(frame.last, vec![2, 2, 0, 1]);
    assert_eq!(frame.resolved, Some(vec![1.5, 0.5]));

    let area = json!({"primitives": [
        {"coverage": [[0, 0, 0.75], [1, 0, 0.25]]},
        {"coverage": [[0, 0, 0.75]]}
    ]});
    let frame = external::frame_from_response(&area, &scene, &plan).unwrap();
    assert_eq!(frame.samples, 0, "an area method has no samples");
    assert_eq!(frame.resolved, Some(vec![1.5, 0.25]));

    for (bad, says) in [
        (
            json!({"primitives": [{"fragments": [[0, 0, 2]]}, {"fragments": []}]}),
            "$.primitives[0].fragments[0][2]: 2 is not a sample index in [0, 2)",
        ),
        (
            json!({"primitives": [{"fragments": [[0, 0]]}, {"fragments": []}]}),
            "array of 3 numbers: x, y, sample",
        ),
        (
            json!({"primitives": [{"coverage": []}, {"fragments": []}]}),
            "coverage for every primitive or fragments for every one",
        ),
        (
            json!({"primitives": [{"coverage": [[0, 0, 1.5]]}, {"coverage": []}]}),
            "$.primitives[0].coverage[0][2]: 1.5 is not a fraction in [0, 1]",
        ),
        (json!({"exr": "frame.exr"}), "one sample per pixel"),
    ] {
        match external::frame_from_response(&bad, &scene, &plan) {
            Err(RasterError::Failed(why)) => assert!(why.contains(says), "{why}"),
            other => panic!("{bad}: {other:?}"),
        }
    }
}

#[test]
fn a_response_may_name_an_exr_file_with_golden_channels() {
    let scene =
        scene(&std::fs::read_to_string(root().join("cases/triangles/interp_linear.json")).unwrap());
    let plan = Plan::for_scene(&scene);
    let reference = rastercheck::reference::render(&scene, &plan);
    let dir = scratch("exr");
    let path = dir.join("frame.exr");
    rastercheck::harness::golden::write(&reference, &path).unwrap();
    let response = json!({"exr": path.display().to_string()});
    let frame = external::frame_from_response(&response, &scene, &plan).unwrap();
    assert_eq!(frame.coverage, reference.coverage);
    assert_eq!(frame.last, reference.last);
    // Values travel as f32, as in the golden files.
    let narrowed: Vec<f64> = reference.attributes[2]
        .iter()
        .map(|&v| f64::from(v as f32))
        .collect();
    assert_eq!(frame.attributes[2], narrowed);

    let missing = json!({"exr": dir.join("nothing.exr").display().to_string()});
    assert!(matches!(
        external::frame_from_response(&missing, &scene, &plan),
        Err(RasterError::Failed(_))
    ));
}
