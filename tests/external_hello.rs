//! The hello and ids of protocol v2 (SPEC.md §12.7) through the binary,
//! with a real program (`tests/clients/hello_faults.py`, the example
//! rasterizer behind a hello with issue 40's mistakes): a malformed hello
//! is refused at startup, naming its JSON path, and no case is sent; a
//! program whose answers carry no id, or the wrong ones, is told so once
//! and not waited on for every case; cases a declaration rules out are
//! never sent (counted by the program); results name only the conventions
//! that apply; a long name is quoted short; commands split as a shell
//! splits them.

mod common;

use std::path::PathBuf;

use common::cli::{case_entry, rastercheck, rastercheck_env, read_json, scratch, text, verdicts};
use serde_json::Value;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn client() -> String {
    root()
        .join("tests/clients/hello_faults.py")
        .display()
        .to_string()
}

/// What a run of the client printed, its exit code, its report (when one
/// was written) and the cases it received, in order.
struct Run {
    code: Option<i32>,
    printed: String,
    report: Option<Value>,
    received: Vec<String>,
    /// Its report.json.
    report_file: PathBuf,
}

/// Runs the client with `flags` over `cases` (files or folders of the
/// repository), one thread, under `env`.
fn run(tag: &str, flags: &str, cases: &[&str], env: &[(&str, &str)]) -> Run {
    let dir = scratch(&format!("hello-{tag}"));
    let log = dir.join("received.log");
    let spec = format!(
        "faults=external-persistent:python3 {} {} {flags}",
        client(),
        log.display()
    );
    let report = dir.join("report");
    let report_arg = report.display().to_string();
    let mut args = vec![
        "run",
        "--threads",
        "1",
        "--report",
        &report_arg,
        "-r",
        &spec,
    ];
    args.extend_from_slice(cases);
    let out = rastercheck_env(&root(), &args, env);
    let printed = text(&out);
    assert!(!printed.contains("panicked"), "{printed}");
    let received = std::fs::read_to_string(&log)
        .unwrap_or_default()
        .lines()
        .filter_map(|l| l.strip_prefix("case "))
        .map(str::to_owned)
        .collect();
    let file = report.join("report.json");
    Run {
        code: out.status.code(),
        printed,
        report: file.exists().then(|| read_json(&file)),
        received,
        report_file: file,
    }
}

/// Each mistake of issue 40 stops the run before any case, exit 2, with
/// the path and the key or word meant; the program receives nothing.
#[test]
fn a_malformed_hello_is_refused_at_startup_naming_its_path() {
    let mistakes = [
        (
            "conventions.fillrule=\"top-left\"",
            "$.hello.conventions.fillrule: unknown key \"fillrule\"; did you mean \"fill_rule\"?",
        ),
        (
            "capabilities.primitive=[\"triangles\"]",
            "$.hello.capabilities.primitive: unknown key \"primitive\"; did you mean \"primitives\"?",
        ),
        (
            "capabilities.coverage_bit=8",
            "$.hello.capabilities.coverage_bit: unknown key \"coverage_bit\"; did you mean \"coverage_bits\"?",
        ),
        (
            "primitives=[\"triangles\"]",
            "$.hello.primitives: unknown key \"primitives\"; did you mean \"capabilities.primitives\"?",
        ),
        (
            "capabilities.line_rules=[\"midpiont\"]",
            "$.hello.capabilities.line_rules[0] is \"midpiont\"; did you mean \"midpoint\"?",
        ),
        (
            "capabilities.antialias=\"yes\"",
            "$.hello.capabilities.antialias must be true or false",
        ),
    ];
    for (i, (set, expected)) in mistakes.iter().enumerate() {
        let r = run(
            &format!("bad-{i}"),
            &format!("--set '{set}'"),
            &["cases/triangles"],
            &[],
        );
        assert_eq!(r.code, Some(2), "{set}: {}", r.printed);
        assert!(r.printed.contains(expected), "{set}: {}", r.printed);
        assert!(
            r.printed
                .contains("its hello is not a hello of SPEC.md §12.7"),
            "{}",
            r.printed
        );
        assert!(r.received.is_empty(), "{set}: {:?}", r.received);
        assert!(r.report.is_none(), "{set}: a report was written");
    }
}

/// A program whose answers carry no id is told so on its first answer,
/// once; every later case is an error naming that cause, not sent and not
/// waited for (at the default time limit of 30 s, waiting would take an
/// hour over the antialias family). Cases its hello refuses stay
/// unsupported.
#[test]
fn answers_without_an_id_are_said_once_and_nothing_more_is_sent() {
    let r = run("no-id", "--no-id", &["cases/antialias"], &[]);
    let report = r.report.expect("a report");
    let verdicts = verdicts(&report);
    assert_eq!(verdicts.len(), 71, "{}", r.printed);
    assert_eq!(r.received.len(), 1, "{:?}", r.received);
    let errors: Vec<_> = verdicts.iter().filter(|v| v.1 == "error").collect();
    let first = errors
        .iter()
        .find(|v| v.2.contains("protocol error"))
        .expect("the first answer's error");
    assert!(
        first
            .2
            .contains("its answers carry no `id` (the first, to request \"")
            && first
                .2
                .contains("protocol v2 answers must echo the request's id"),
        "{first:?}"
    );
    assert!(!first.2.contains("timed out"), "{first:?}");
    for v in &errors {
        if v != first {
            assert!(
                v.2.starts_with("not sent: its answers carry no `id`"),
                "{v:?}"
            );
        }
    }
    assert!(
        verdicts
            .iter()
            .all(|v| v.1 == "error" || v.1 == "unsupported"),
        "{verdicts:?}"
    );
    assert_eq!(r.code, Some(1), "{}", r.printed);
}

/// A program that answers under its own ids: the first case waits its time
/// limit (the right answer might still come, §12.7) and is told which id
/// answered which request; the second such case ends it, and no later
/// case is sent.
#[test]
fn answers_under_other_ids_are_said_and_end_the_program_the_second_time() {
    let r = run(
        "wrong-id",
        "--wrong-id",
        &[
            "cases/triangles/shared_edge_diagonal.json",
            "cases/triangles/shared_edge_vertical.json",
            "cases/triangles/snap_tie_b0.json",
            "cases/triangles/winding_cw_cull_none.json",
        ],
        &[("RASTERCHECK_EXTERNAL_TIMEOUT", "1")],
    );
    let verdicts = verdicts(&r.report.expect("a report"));
    assert_eq!(r.received.len(), 2, "{:?}", r.received);
    assert!(
        verdicts[0].2.contains("answer id \"1\" for request \""),
        "{:?}",
        verdicts[0]
    );
    assert!(
        verdicts[1].2.contains("answer id \"2\" for request \"")
            && verdicts[1].2.contains("the second time in this run"),
        "{:?}",
        verdicts[1]
    );
    for v in &verdicts[2..] {
        assert!(v.2.starts_with("not sent: answer id \"2\""), "{v:?}");
    }
}

/// A program that declares `all-edges` is sent no polygon case: each is
/// unsupported with the reason, decided from the hello before any request
/// (the program counts what it receives). A midpoint-line case, where no
/// fill rule decides anything, names no rule judged; a triangle case
/// names all-edges.
#[test]
fn what_a_declaration_rules_out_is_never_sent_and_results_name_what_applies() {
    let polygons = "cases/polygons/concave_arrow.json";
    let triangle = "cases/triangles/shared_edge_diagonal.json";
    let midpoint = "cases/lines/midpoint_endpoints_centres.json";
    let r = run(
        "all-edges",
        "--all-edges",
        &[polygons, triangle, midpoint],
        &[],
    );
    let report = r.report.expect("a report");
    let result = |id: &str| {
        case_entry(&report, id)
            .map(|c| c["results"][0].clone())
            .unwrap_or_else(|| panic!("{id}: {}", r.printed))
    };
    let polygon = result("polygons/concave_arrow");
    assert_eq!(polygon["verdict"], "unsupported", "{polygon}");
    assert!(
        polygon["reasons"][0]
            .as_str()
            .unwrap()
            .contains("follows all-edges whatever the case states (its hello's conventions.fill_rule), and all-edges is not defined for polygons"),
        "{polygon}"
    );
    assert!(
        !r.received.iter().any(|c| c.contains("concave_arrow")),
        "{:?}",
        r.received
    );
    assert_eq!(r.received.len(), 2, "{:?}", r.received);
    assert_eq!(
        result("triangles/shared_edge_diagonal")["judged_fill_rule"],
        "all-edges"
    );
    let line = result("lines/midpoint_endpoints_centres");
    assert!(line.get("judged_fill_rule").is_none(), "{line}");
    let printed_line = r
        .printed
        .lines()
        .find(|l| l.contains("midpoint_endpoints_centres"))
        .unwrap_or_default();
    assert!(!printed_line.contains("all-edges"), "{printed_line}");
}

/// A hello whose name is 2 MB is quoted at 80 characters in every refusal:
/// over the antialias family (every case refused by its `antialias:
/// false`), report.json stays under 1 MB.
#[test]
fn a_long_program_name_is_quoted_short() {
    let r = run(
        "long-name",
        &format!("--no-antialias --name-bytes {}", 2 << 20),
        &["cases/antialias"],
        &[],
    );
    assert!(r.received.is_empty(), "{:?}", r.received);
    let report = r.report.expect("a report");
    let verdicts = verdicts(&report);
    assert_eq!(verdicts.len(), 71);
    for v in &verdicts {
        assert_eq!(v.1, "unsupported", "{v:?}");
        assert!(v.2.contains("… (2097152 bytes)"), "{}", &v.2[..200]);
    }
    let size = std::fs::metadata(&r.report_file).unwrap().len();
    assert!(size < 1 << 20, "report.json is {size} bytes");
    assert!(
        r.printed.len() < 1 << 20,
        "{} bytes printed",
        r.printed.len()
    );
}

/// Commands split as a shell splits them: a program in a folder with a
/// space, quoted, runs; an unterminated quote is bad usage, said as such.
/// `-r NAME=PROGRAM` suggests `NAME=external-persistent:PROGRAM`.
#[test]
fn commands_split_as_a_shell_would_and_mistakes_are_named() {
    let dir = scratch("hello-quoted");
    let folder = dir.join("my clients");
    std::fs::create_dir_all(&folder).unwrap();
    let copy = folder.join("hello_faults.py");
    std::fs::copy(client(), &copy).unwrap();
    // The copy imports the example by a path relative to itself.
    let text_of_copy = std::fs::read_to_string(&copy).unwrap().replace(
        "os.path.join(HERE, \"..\", \"..\", \"examples\", \"python_rasterizer.py\")",
        &format!("{:?}", root().join("examples/python_rasterizer.py")),
    );
    std::fs::write(&copy, text_of_copy).unwrap();
    let log = dir.join("it's here.log");
    let spec = format!(
        "q=external-persistent:python3 \"{}\" 'it'\\''s here.log'",
        copy.display()
    );
    let case = root().join("cases/triangles/shared_edge_diagonal.json");
    let out = rastercheck(&dir, &["run", &case.display().to_string(), "-r", &spec]);
    let printed = text(&out);
    // The example overdraws shared edges: a failure, judged.
    assert_eq!(out.status.code(), Some(1), "{printed}");
    let received = std::fs::read_to_string(&log).unwrap_or_default();
    assert_eq!(received.lines().count(), 1, "{printed}");

    let out = rastercheck(
        &dir,
        &[
            "run",
            &case.display().to_string(),
            "-r",
            "q=external:python3 'open",
        ],
    );
    let printed = text(&out);
    assert_eq!(out.status.code(), Some(2), "{printed}");
    assert!(printed.contains("has an unterminated ' quote"), "{printed}");

    let out = rastercheck(
        &dir,
        &[
            "run",
            &case.display().to_string(),
            "-r",
            "mine=python3 prog.py",
        ],
    );
    let printed = text(&out);
    assert_eq!(out.status.code(), Some(2), "{printed}");
    assert!(
        printed.contains("did you mean \"mine=external-persistent:python3 prog.py\"?"),
        "{printed}"
    );
}
