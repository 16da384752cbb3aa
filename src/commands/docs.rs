//! `rastercheck docs`: the generated blocks of README.md and `docs/`,
//! rewritten (`--write`) or checked (the default) from the code and the
//! bundled cases, so that no figure in the documentation can go stale.
//!
//! A block is the lines between `<!-- generated:NAME:begin -->` and
//! `<!-- generated:NAME:end -->`; the same block may appear in several
//! files. Blocks whose figures take minutes to compute are written by the
//! test that computes them ([`ELSEWHERE`]); the conformance matrix has its
//! own markers and command (`matrix --write-readme`). `tests/docs.rs` fails
//! when any block here is stale.

use std::path::{Path, PathBuf};
use std::process::Command;

use clap::Args;

use super::console::outln;
use super::exit::Exit;

#[derive(Args)]
pub struct DocsArgs {
    /// Rewrite every stale block in place (default: only check, exit 1
    /// when one is stale).
    #[arg(long)]
    pub write: bool,
    /// Check only (the default), spelled out for CI scripts.
    #[arg(long, conflicts_with = "write")]
    pub check: bool,
}

/// The command that rewrites the blocks this file generates.
pub const WRITE_COMMAND: &str = "cargo run --release -- docs --write";

/// Blocks written by a test that already computes their figures:
/// (block, the command that rewrites it).
pub const ELSEWHERE: [(&str, &str); 3] = [
    (
        "example-c",
        "RASTERCHECK_BLESS=1 cargo test --release --test examples",
    ),
    (
        "example-c-3d",
        "RASTERCHECK_BLESS=1 cargo test --release --test examples",
    ),
    (
        "example-js",
        "RASTERCHECK_BLESS=1 cargo test --release --test examples",
    ),
];

/// The case families, in the order the README lists them, with what each
/// holds. A family folder missing here still gets its row.
const FAMILIES: [(&str, &str); 11] = [
    ("triangles", "fill rules, shared edges and fans, snapping, interpolation, culling"),
    ("lines", "the midpoint rule, D3D11's diamond-exit rule, thin and wide rectangles, parallelograms"),
    ("polygons", "stars under even-odd and nonzero, holes, self-intersecting contours"),
    ("antialias", "the five sample patterns, edges nearly on an axis, every standard sample position, tiny and abutting shapes"),
    ("hard", "ties at the coordinate limits, near-ties, snapping ties, T-junctions, extreme perspective, abutting antialiased fans"),
    ("motion", "motion blur: translating, rotating, scaling and collapsing triangles, samples riding an edge, every time pattern"),
    ("clip", "clip space (SPEC.md §16): w ≤ 0, near and far clipping, depth clamp, guard band, extreme w"),
    ("points", "points (SPEC.md §17): sizes, fill rules on their sides, snapping, popping, viewport bounds"),
    ("depth", "depth formats and polygon offset (SPEC.md §18): unorm16, unorm24, float32, both clamps"),
    ("conservative", "conservative rasterization (SPEC.md §19): over- and underestimation, uncertainty bands, degenerate triangles, the fully-covered flag, meshes"),
    ("invalid", "malformed files, each with the error it must give (`run cases` skips them)"),
];

/// The generated content of block `name`, or `None` for a name this
/// command does not know. `root` is the repository; `exe` the rastercheck
/// binary the sample output is taken from.
pub fn generate(name: &str, root: &Path, exe: &Path) -> Option<Result<String, String>> {
    Some(match name {
        "families" => families_table(&root.join("cases")),
        "rasterizers" => Ok(crate::registry::markdown_table()),
        "limits" => Ok(limits_table()),
        "sample-output" => sample_output(root, exe),
        "baseline-output" => baseline_output(root, exe),
        "diff-md" => diff_markdown(root, exe),
        _ => return None,
    })
}

/// One generated block found in a file: its name and the lines between its
/// markers (each ending in a newline).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Block {
    pub name: String,
    pub content: String,
}

fn begin_marker(name: &str) -> String {
    format!("<!-- generated:{name}:begin -->")
}

fn end_marker(name: &str) -> String {
    format!("<!-- generated:{name}:end -->")
}

/// The blocks of `text`, in order; an error for a begin marker with no end.
pub fn blocks(text: &str) -> Result<Vec<Block>, String> {
    let mut found = Vec::new();
    let mut open: Option<Block> = None;
    for (i, line) in text.lines().enumerate() {
        let line_trimmed = line.trim();
        if let Some(block) = &mut open {
            if line_trimmed == end_marker(&block.name) {
                found.push(open.take().expect("open block"));
            } else {
                block.content.push_str(line);
                block.content.push('\n');
            }
            continue;
        }
        if let Some(name) = line_trimmed
            .strip_prefix("<!-- generated:")
            .and_then(|rest| rest.strip_suffix(":begin -->"))
        {
            open = Some(Block {
                name: name.to_owned(),
                content: String::new(),
            });
        } else if line_trimmed.starts_with("<!-- generated:") {
            return Err(format!("line {}: a marker outside a block: {line}", i + 1));
        }
    }
    match open {
        Some(block) => Err(format!("block {} has no end marker", block.name)),
        None => Ok(found),
    }
}

/// `text` with every block named `name` holding `content` instead.
pub fn replace(text: &str, name: &str, content: &str) -> String {
    let (begin, end) = (begin_marker(name), end_marker(name));
    let mut out = String::with_capacity(text.len());
    let mut inside = false;
    for line in text.split_inclusive('\n') {
        let trimmed = line.trim();
        if inside {
            if trimmed == end {
                inside = false;
                out.push_str(line);
            }
            continue;
        }
        out.push_str(line);
        if trimmed == begin {
            inside = true;
            out.push_str(content);
        }
    }
    out
}

/// README.md and every Markdown file under `docs/`, sorted.
pub fn doc_files(root: &Path) -> Vec<PathBuf> {
    fn walk(dir: &Path, into: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                walk(&path, into);
            } else if path.extension().is_some_and(|e| e == "md") {
                into.push(path);
            }
        }
    }
    let mut files = vec![root.join("README.md")];
    let mut docs = Vec::new();
    walk(&root.join("docs"), &mut docs);
    docs.sort();
    files.extend(docs);
    files
}

/// A block whose text differs from what the code generates now.
#[derive(Debug)]
pub struct Stale {
    pub file: PathBuf,
    pub block: String,
    pub expected: String,
    pub found: String,
}

/// Every stale block of every documentation file under `root`; the
/// files rewritten first when `write` is set (then nothing is stale). An
/// error names a file whose blocks cannot be read, an unknown block, or a
/// block that cannot be generated.
pub fn check(root: &Path, exe: &Path, write: bool) -> Result<Vec<Stale>, String> {
    let mut stale = Vec::new();
    let mut cache: Vec<(String, String)> = Vec::new();
    for file in doc_files(root) {
        let text = std::fs::read_to_string(&file)
            .map_err(|e| format!("cannot read {}: {e}", file.display()))?;
        let found = blocks(&text).map_err(|e| format!("{}: {e}", file.display()))?;
        let mut rewritten = text.clone();
        for block in found {
            if ELSEWHERE.iter().any(|(name, _)| *name == block.name) {
                continue;
            }
            let expected = match cache.iter().find(|(name, _)| *name == block.name) {
                Some((_, content)) => content.clone(),
                None => {
                    let content = generate(&block.name, root, exe)
                        .ok_or_else(|| {
                            format!(
                                "{}: unknown generated block {:?}",
                                file.display(),
                                block.name
                            )
                        })?
                        .map_err(|e| format!("block {}: {e}", block.name))?;
                    cache.push((block.name.clone(), content.clone()));
                    content
                }
            };
            if expected != block.content {
                rewritten = replace(&rewritten, &block.name, &expected);
                stale.push(Stale {
                    file: file.clone(),
                    block: block.name,
                    expected,
                    found: block.content,
                });
            }
        }
        if write && rewritten != text {
            std::fs::write(&file, rewritten)
                .map_err(|e| format!("cannot write {}: {e}", file.display()))?;
        }
    }
    if write {
        stale.clear();
    }
    Ok(stale)
}

/// `rastercheck docs`: check (or with `--write` rewrite) the generated
/// blocks, from the repository in the working directory.
pub fn docs(args: DocsArgs) -> Exit {
    let root = PathBuf::from(".");
    let exe = match std::env::current_exe() {
        Ok(exe) => exe,
        Err(e) => {
            eprintln!("error: cannot find this program to take sample output from: {e}");
            return Exit::BadInput;
        }
    };
    match check(&root, &exe, args.write) {
        Err(e) => {
            eprintln!("error: {e}");
            Exit::BadInput
        }
        Ok(stale) if stale.is_empty() => {
            outln!(
                "{} generated blocks",
                if args.write { "wrote the" } else { "current:" }
            );
            Exit::Pass
        }
        Ok(stale) => {
            for s in &stale {
                outln!(
                    "stale: {} block {:?}; `{WRITE_COMMAND}` rewrites it",
                    s.file.strip_prefix(&root).unwrap_or(&s.file).display(),
                    s.block
                );
            }
            Exit::Fail
        }
    }
}

/// The case families under `cases`: one row each with its case count, the
/// top-level files, and the total.
fn families_table(cases: &Path) -> Result<String, String> {
    let mut folders: Vec<String> = std::fs::read_dir(cases)
        .map_err(|e| format!("cannot read {}: {e}", cases.display()))?
        .flatten()
        .filter(|e| e.path().is_dir())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    let order = |name: &str| {
        FAMILIES
            .iter()
            .position(|(f, _)| *f == name)
            .unwrap_or(FAMILIES.len())
    };
    folders.sort_by(|a, b| order(a).cmp(&order(b)).then(a.cmp(b)));
    let mut out = String::from("| family | cases | what they pin |\n|---|---|---|\n");
    let mut total = 0;
    let mut malformed = 0;
    for folder in &folders {
        let count = json_files(&cases.join(folder));
        let what = FAMILIES.iter().find(|(f, _)| f == folder).map_or(
            "(not described yet: add it to src/commands/docs.rs)",
            |(_, w)| w,
        );
        out.push_str(&format!("| `cases/{folder}/` | {count} | {what} |\n"));
        if folder == "invalid" {
            malformed += count;
        } else {
            total += count;
        }
    }
    let top = json_files_here(cases);
    if top > 0 {
        out.push_str(&format!(
            "| `cases/*.json` | {top} | `cases/readme.json`: every field of the format, explained |\n"
        ));
        total += top;
    }
    out.push_str(&format!(
        "| all | {total} | every bundled case `run cases` judges, besides the {malformed} malformed files |\n"
    ));
    Ok(out)
}

/// `.json` files under `dir`, at any depth.
fn json_files(dir: &Path) -> usize {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return 0;
    };
    entries
        .flatten()
        .map(|e| e.path())
        .map(|p| {
            if p.is_dir() {
                json_files(&p)
            } else {
                usize::from(p.extension().is_some_and(|e| e == "json"))
            }
        })
        .sum()
}

/// `.json` files directly in `dir`.
fn json_files_here(dir: &Path) -> usize {
    std::fs::read_dir(dir).map_or(0, |entries| {
        entries
            .flatten()
            .filter(|e| e.path().is_file() && e.path().extension().is_some_and(|x| x == "json"))
            .count()
    })
}

/// `n` as a power of two (`2^24`) when it is one, in decimal otherwise.
fn power_of_two(n: u64) -> String {
    if n.is_power_of_two() && n >= 1 << 10 {
        format!("2^{}", n.trailing_zeros())
    } else {
        n.to_string()
    }
}

/// `bytes` in the largest binary unit that divides it.
fn size(bytes: u64) -> String {
    for (shift, unit) in [(30, "GiB"), (20, "MiB"), (10, "KiB")] {
        if bytes >= 1 << shift && bytes.trailing_zeros() >= shift {
            return format!("{} {unit}", bytes >> shift);
        }
    }
    format!("{bytes} bytes")
}

/// The resource limits (SPEC.md §8) with their defaults, from the
/// constants the code uses.
fn limits_table() -> String {
    use crate::adapters::external;
    use crate::scene::rules::limits as l;
    let rows = [
        ("canvas pixels".to_owned(), power_of_two(l::DEFAULT_MAX_CANVAS_PIXELS), "`--max-canvas-pixels`".to_owned()),
        ("primitives in one case".to_owned(), l::DEFAULT_MAX_PRIMITIVES.to_string(), "`--max-primitives`".to_owned()),
        ("sample points: pixels × samples × time samples".to_owned(), power_of_two(l::DEFAULT_MAX_SAMPLES), "`--max-samples`".to_owned()),
        ("a case file's size, checked before it is read".to_owned(), size(l::DEFAULT_MAX_CASE_BYTES), "`--max-case-bytes`".to_owned()),
        ("memory of one case: its frames and each external program's answer line (its output limit), estimated from the scene before any is allocated; answers are read and requests written as they stream, so a case takes its estimate plus a constant (a run holds the cases in flight only)".to_owned(), size(l::DEFAULT_MAX_CASE_MEMORY), "`--max-case-memory`".to_owned()),
        ("seconds per rasterizer and case (the reference and production poll it; an external program is stopped at it)".to_owned(), l::DEFAULT_CASE_TIMEOUT.as_secs().to_string(), "`--case-timeout` (0: none)".to_owned()),
        ("seconds an external program may take to answer one case".to_owned(), external::DEFAULT_TIMEOUT.as_secs().to_string(), format!("`{}`", external::TIMEOUT_ENV)),
        ("bytes an external program may write to stdout for one answer (of its stderr, only the tail is kept)".to_owned(), size(external::DEFAULT_MAX_OUTPUT), format!("`{}`", external::MAX_OUTPUT_ENV)),
        ("an EXR answer's or golden file's size, read from its header before decoding".to_owned(), "the case's canvas".to_owned(), "—".to_owned()),
    ];
    let mut out = String::from("| limit | default | set with |\n|---|---|---|\n");
    for (what, default, flag) in rows {
        out.push_str(&format!("| {what} | {default} | {flag} |\n"));
    }
    out
}

/// The console lines shown as sample output: the first results and the
/// summary of a run of production and a mutant over one family.
const SAMPLE: [&str; 6] = [
    "run",
    "cases/triangles",
    "-r",
    "production",
    "-r",
    "mutant:flipped-ties",
];

/// Lines of results kept before the summary.
const SAMPLE_LINES: usize = 3;

fn sample_output(root: &Path, exe: &Path) -> Result<String, String> {
    let out = Command::new(exe)
        .args(SAMPLE)
        .current_dir(root)
        .env_remove("RASTERCHECK_THREADS")
        .output()
        .map_err(|e| format!("cannot run {}: {e}", exe.display()))?;
    let text = String::from_utf8_lossy(&out.stdout);
    let lines: Vec<&str> = text.lines().collect();
    let summary = lines.iter().rposition(|l| l.is_empty()).ok_or_else(|| {
        format!(
            "no summary in the output of `rastercheck {}`",
            SAMPLE.join(" ")
        )
    })?;
    let mut block = format!("```text\n$ rastercheck {}\n", SAMPLE.join(" "));
    for line in lines.iter().take(SAMPLE_LINES.min(summary)) {
        block.push_str(line.trim_end());
        block.push('\n');
    }
    block.push_str("...\n");
    for line in &lines[summary + 1..] {
        block.push_str(line.trim_end());
        block.push('\n');
    }
    block.push_str(&format!(
        "$ echo $?\n{}\n```\n",
        out.status
            .code()
            .map_or("(killed)".to_owned(), |c| c.to_string())
    ));
    Ok(block)
}

/// A scratch folder for the runs a block shows, removed when dropped.
struct Scratch(PathBuf);

impl Scratch {
    fn new(tag: &str) -> Result<Scratch, String> {
        let dir =
            std::env::temp_dir().join(format!("rastercheck-docs-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir)
            .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
        Ok(Scratch(dir))
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// `exe args` run in `dir`: its stdout and exit code.
fn run_in(exe: &Path, dir: &Path, args: &[&str]) -> Result<(String, i32), String> {
    let out = Command::new(exe)
        .args(args)
        .current_dir(dir)
        .output()
        .map_err(|e| format!("cannot run {}: {e}", exe.display()))?;
    Ok((
        String::from_utf8_lossy(&out.stdout).into_owned(),
        out.status.code().unwrap_or(-1),
    ))
}

/// A baseline of one DDA over the line cases, checked against the other:
/// what `baseline check` prints for regressions.
fn baseline_output(root: &Path, exe: &Path) -> Result<String, String> {
    let scratch = Scratch::new("baseline")?;
    let cases = root
        .join("cases/lines")
        .canonicalize()
        .map_err(|e| e.to_string())?;
    let cases = cases.to_string_lossy();
    let save = ["baseline", "save", "lines.json", &cases, "-r", "dda-f64"];
    let (_, code) = run_in(exe, &scratch.0, &save)?;
    if code != 0 {
        return Err(format!("`rastercheck {}` exited {code}", save.join(" ")));
    }
    let check = ["baseline", "check", "lines.json", "-r", "dda-f32=dda-f64"];
    let (text, code) = run_in(exe, &scratch.0, &check)?;
    let mut block = String::from(
        "```text\n$ rastercheck baseline save out/baselines/lines.json cases/lines -r dda-f64\n",
    );
    block.push_str("$ rastercheck baseline check out/baselines/lines.json -r dda-f32=dda-f64\n");
    let lines: Vec<&str> = text.lines().collect();
    for line in lines.iter().take(3) {
        block.push_str(&format!("{}\n", line.trim_end()));
    }
    if lines.len() > 4 {
        block.push_str("...\n");
    }
    if let Some(last) = lines.last().filter(|_| lines.len() > 3) {
        block.push_str(&format!("{}\n", last.trim_end()));
    }
    block.push_str(&format!("$ echo $?\n{code}\n```\n"));
    Ok(block)
}

/// `diff.md` for production against `mutant:no-perspective` over the
/// triangle cases, each table cut to its first row.
fn diff_markdown(root: &Path, exe: &Path) -> Result<String, String> {
    let scratch = Scratch::new("diff")?;
    let cases = root
        .join("cases/triangles")
        .canonicalize()
        .map_err(|e| e.to_string())?;
    let cases = cases.to_string_lossy();
    for (name, report) in [("production", "main"), ("mutant:no-perspective", "pr")] {
        let args = ["run", &cases, "-r", name, "--report", report, "--quiet"];
        run_in(exe, &scratch.0, &args)?;
    }
    run_in(exe, &scratch.0, &["diff", "main", "pr", "--out", "pr-diff"])?;
    let path = scratch.0.join("pr-diff/diff.md");
    let text = std::fs::read_to_string(&path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let mut block = String::from("```markdown\n");
    let mut rows_left: Option<usize> = None;
    for line in text.lines() {
        if line.starts_with("### ") {
            rows_left = Some(2);
        }
        match &mut rows_left {
            Some(0) => continue,
            Some(n) if line.starts_with("| ") && !line.starts_with("| case") => {
                *n -= 1;
                if *n == 0 {
                    block.push_str("...\n");
                    continue;
                }
            }
            _ => {}
        }
        block.push_str(line.trim_end());
        block.push('\n');
    }
    block.push_str("```\n");
    Ok(block)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_are_found_and_replaced_between_their_markers_only() {
        let text = "a\n<!-- generated:x:begin -->\nold\n<!-- generated:x:end -->\nb\n";
        assert_eq!(
            blocks(text).unwrap(),
            vec![Block {
                name: "x".into(),
                content: "old\n".into()
            }]
        );
        assert_eq!(
            replace(text, "x", "new\nlines\n"),
            "a\n<!-- generated:x:begin -->\nnew\nlines\n<!-- generated:x:end -->\nb\n"
        );
        assert!(blocks("<!-- generated:y:begin -->\n").is_err());
    }

    #[test]
    fn limits_are_spelled_as_powers_of_two_and_binary_units() {
        assert_eq!(power_of_two(1 << 24), "2^24");
        assert_eq!(power_of_two(100_000), "100000");
        assert_eq!(size(16 << 20), "16 MiB");
        assert_eq!(size(4 << 30), "4 GiB");
        assert_eq!(size(1000), "1000 bytes");
    }
}
