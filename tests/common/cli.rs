//! Helpers the CLI tests share: running the binary as a user would, fresh
//! folders to run it in, and reading back what it wrote (`report.json`,
//! golden files, pictures). No assertions about any one command's output.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs the rastercheck binary in `dir`, as a user would.
pub fn rastercheck(dir: &Path, args: &[&str]) -> Output {
    rastercheck_env(dir, args, &[])
}

/// Runs the rastercheck binary in `dir` with extra environment variables.
pub fn rastercheck_env(dir: &Path, args: &[&str], env: &[(&str, &str)]) -> Output {
    let mut command = Command::new(env!("CARGO_BIN_EXE_rastercheck"));
    command.args(args).current_dir(dir);
    for (k, v) in env {
        command.env(k, v);
    }
    command.output().expect("the binary runs")
}

/// A finished child process: what it printed and its peak resident memory.
pub struct Measured {
    pub output: Output,
    /// The largest resident set of the process (or of a child it reaped)
    /// over its life, in KiB: `ru_maxrss` as `wait4` reports it.
    pub peak_rss_kib: u64,
}

impl Measured {
    pub fn peak_rss_mib(&self) -> f64 {
        self.peak_rss_kib as f64 / 1024.0
    }
}

/// Runs `command` with stdout and stderr piped (drained on threads, so a
/// full pipe cannot block it) and reaps it with `wait4` for its own peak
/// RSS, which std's `Child::wait` does not give. Killed, and the caller
/// panics, if it is not over within `guard`: a hang fails a test instead
/// of hanging it.
#[cfg(unix)]
#[allow(clippy::zombie_processes)] // reaped by wait4, which clippy does not see
pub fn run_measured(command: &mut Command, guard: std::time::Duration) -> Measured {
    use std::io::Read;
    use std::os::unix::process::{CommandExt, ExitStatusExt};
    use std::process::Stdio;

    // Linux records, when the child execs, the memory it had until then as
    // part of its peak: under posix_spawn (which std prefers) that is this
    // test process's own peak so far; a hook forces fork, which makes it
    // this process's current RSS (a few MiB), the floor of every number.
    // SAFETY: the hook does nothing, so it is async-signal-safe.
    unsafe {
        command.pre_exec(|| Ok(()));
    }
    let mut child = command
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    let drain = |mut pipe: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut v = Vec::new();
            let _ = pipe.read_to_end(&mut v);
            v
        })
    };
    let stdout = drain(Box::new(child.stdout.take().unwrap()));
    let stderr = drain(Box::new(child.stderr.take().unwrap()));
    let pid = child.id() as libc::pid_t;
    let started = std::time::Instant::now();
    let mut killed = false;
    let (status, usage) = loop {
        let mut status = 0;
        // SAFETY: rusage is plain old data, written by wait4 before it is read.
        let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
        // SAFETY: pid is our own unreaped child (std never waits for it here).
        let got = unsafe { libc::wait4(pid, &mut status, libc::WNOHANG, &mut usage) };
        if got == pid {
            break (status, usage);
        }
        let error = std::io::Error::last_os_error();
        assert!(
            got == 0 || error.kind() == std::io::ErrorKind::Interrupted,
            "wait4: {error}"
        );
        if !killed && started.elapsed() > guard {
            // Still unreaped, so the pid is still ours to kill.
            let _ = child.kill();
            killed = true;
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    };
    let output = Output {
        status: std::process::ExitStatus::from_raw(status),
        stdout: stdout.join().unwrap(),
        stderr: stderr.join().unwrap(),
    };
    assert!(
        !killed,
        "{:?} hung (killed after {guard:?}):\n{}",
        command.get_args().collect::<Vec<_>>(),
        text(&output)
    );
    Measured {
        output,
        peak_rss_kib: usage.ru_maxrss as u64,
    }
}

/// Everything the binary printed, stdout then stderr.
pub fn text(out: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

/// The binary never panics, whatever it is given.
pub fn assert_no_panic(out: &Output) {
    let t = text(out);
    assert!(!t.contains("panicked"), "{t}");
}

/// A fresh, empty folder `rastercheck-{name}-{pid}` in the system's
/// temporary folder.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rastercheck-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A fresh folder with a `cases/` tree holding the given files.
pub fn workspace(name: &str, files: &[(&str, &str)]) -> PathBuf {
    let dir = scratch(&format!("cli-{name}"));
    for (path, content) in files {
        let path = dir.join(path);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, content).unwrap();
    }
    dir
}

/// Runs the repository's test client `tests/clients/{client}` (Python, in
/// persistent mode, called `name`) with `flags` over `cases` (folders or
/// files of the repository) on one thread, its report in a fresh scratch
/// folder `tag`: the report, and what was printed.
pub fn run_client(
    tag: &str,
    client: &str,
    name: &str,
    flags: &str,
    cases: &[&str],
) -> (serde_json::Value, String) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = scratch(tag);
    let program = root.join("tests/clients").join(client);
    let spec = format!(
        "{name}=external-persistent:python3 {} {flags}",
        program.display()
    );
    let report = dir.join("report");
    let report_arg = report.display().to_string();
    let mut args = vec!["run"];
    args.extend_from_slice(cases);
    args.extend(["-r", &spec, "--threads", "1", "--report", &report_arg]);
    let out = rastercheck(root, &args);
    (read_json(&report.join("report.json")), text(&out))
}

/// A JSON file, parsed.
pub fn read_json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The report's entry for case `id`, if it has one.
pub fn case_entry<'a>(report: &'a serde_json::Value, id: &str) -> Option<&'a serde_json::Value> {
    report["cases"].as_array()?.iter().find(|c| c["id"] == id)
}

/// Each case's (id, verdict, reasons joined by "; ") for the report's
/// first candidate, in the report's order.
pub fn verdicts(report: &serde_json::Value) -> Vec<(String, String, String)> {
    report["cases"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            let r = &c["results"][0];
            let reasons: Vec<&str> = r["reasons"]
                .as_array()
                .map(|r| r.iter().filter_map(serde_json::Value::as_str).collect())
                .unwrap_or_default();
            (
                c["id"].as_str().unwrap().to_owned(),
                r["verdict"].as_str().unwrap_or("").to_owned(),
                reasons.join("; "),
            )
        })
        .collect()
}

/// The case ids of `dir/report.json`, in its order.
pub fn report_ids(dir: &Path) -> Vec<String> {
    read_json(&dir.join("report.json"))["cases"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["id"].as_str().unwrap().to_owned())
        .collect()
}

/// `bless cases` in `dir`, which succeeds.
pub fn bless_cases(dir: &Path) {
    let out = rastercheck(dir, &["bless", "cases"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
}

/// `run cases` with `more` arguments in `dir`, which exits with `code`:
/// what it printed.
pub fn run_cases(dir: &Path, more: &[&str], code: i32) -> String {
    let args = [&["run", "cases"], more].concat();
    let out = rastercheck(dir, &args);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(code), "{t}");
    t
}

/// Blesses case `id` written as `json` in a workspace of its own (`name`)
/// and copies the golden file it gets over `dir`'s: a golden file that no
/// longer belongs to `dir`'s case.
pub fn bless_elsewhere(dir: &Path, name: &str, id: &str, json: &str) {
    let other = workspace(name, &[(&format!("cases/{id}.json"), json)]);
    assert_eq!(rastercheck(&other, &["bless"]).status.code(), Some(0));
    std::fs::copy(
        other.join(format!("reference/{id}.exr")),
        dir.join(format!("reference/{id}.exr")),
    )
    .unwrap();
}

/// `show` of `cases/{id}.json` in `dir` against `rasterizer`, into
/// `dir/shown`: it fails (exit 1) and panics nowhere. The printed text, and
/// the pictures `reference.png` and `{stem}{suffix}` for each of `suffixes`
/// (the stem is the rasterizer's name with `:` as `-`), decoded, with their
/// names.
pub fn show_failing(
    dir: &Path,
    id: &str,
    rasterizer: &str,
    suffixes: &[&str],
) -> (String, Vec<(String, image::DynamicImage)>) {
    let stem = rasterizer.replace(':', "-");
    let case = format!("cases/{id}.json");
    let out = rastercheck(dir, &["show", &case, "--out", "shown", "-r", rasterizer]);
    let t = text(&out);
    assert_no_panic(&out);
    assert_eq!(out.status.code(), Some(1), "{t}");
    let names = std::iter::once("reference.png".to_owned())
        .chain(suffixes.iter().map(|s| format!("{stem}{s}")));
    let pictures = names
        .map(|name| {
            let img = image::open(dir.join("shown").join(&name))
                .unwrap_or_else(|e| panic!("{name}: {e}\n{t}"));
            (name, img)
        })
        .collect();
    (t, pictures)
}

/// The values of channel `name` of an EXR layer read from `file`.
pub fn exr_channel(
    layer: &exr::prelude::Layer<exr::prelude::AnyChannels<exr::prelude::FlatSamples>>,
    name: &str,
    file: &str,
) -> Vec<f32> {
    layer
        .channel_data
        .list
        .iter()
        .find(|c| c.name.to_string() == name)
        .unwrap_or_else(|| panic!("{file} has no channel {name}"))
        .sample_data
        .values_as_f32()
        .collect()
}

/// The run's peak RSS stays under `bound_mib`, the bound a test states
/// (with its reason beside the call). Printed either way, for `--nocapture`.
pub fn assert_peak_rss(what: &str, m: &Measured, bound_mib: f64) {
    let peak = m.peak_rss_mib();
    eprintln!("peak RSS {what}: {peak:.1} MiB (bound {bound_mib} MiB)");
    assert!(
        peak < bound_mib,
        "{what}: peak RSS {peak:.1} MiB is over the bound of {bound_mib} MiB\n{}",
        text(&m.output)
    );
}
