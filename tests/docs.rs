//! The README and the guides in `docs/`: every generated block is current
//! (regenerated in memory from the code, the cases and the binary, and
//! compared with the file), every link to a file of the repository points
//! at one, the README's commands run from the repository as written, and
//! the README's prose carries no figure that could go stale.

mod common;

use std::path::{Path, PathBuf};

use common::{rastercheck, text};
use rastercheck::commands::docs;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn exe() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_rastercheck"))
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The first line where `found` and `expected` differ, for the message.
fn first_difference(found: &str, expected: &str) -> String {
    let (f, e): (Vec<&str>, Vec<&str>) = (found.lines().collect(), expected.lines().collect());
    for i in 0..f.len().max(e.len()) {
        if f.get(i) != e.get(i) {
            return format!(
                "line {} of the block:\n  in the file: {}\n  generated:   {}",
                i + 1,
                f.get(i).unwrap_or(&"(nothing)"),
                e.get(i).unwrap_or(&"(nothing)")
            );
        }
    }
    "trailing whitespace".to_owned()
}

#[test]
fn every_generated_block_is_current() {
    let stale = docs::check(&root(), &exe(), false).unwrap_or_else(|e| panic!("{e}"));
    let message: Vec<String> = stale
        .iter()
        .map(|s| {
            format!(
                "{} block {:?} is stale ({}); `{}` rewrites it",
                s.file.strip_prefix(root()).unwrap_or(&s.file).display(),
                s.block,
                first_difference(&s.found, &s.expected),
                docs::WRITE_COMMAND
            )
        })
        .collect();
    assert!(message.is_empty(), "{}", message.join("\n"));
}

#[test]
fn the_readme_has_every_block_and_fits_on_a_few_screens() {
    let readme = read(&root().join("README.md"));
    let names: Vec<String> = docs::blocks(&readme)
        .unwrap()
        .into_iter()
        .map(|b| b.name)
        .collect();
    for name in ["sample-output", "families", "rasterizers"] {
        assert!(
            names.iter().any(|n| n == name),
            "README.md has no {name} block"
        );
    }
    let lines = readme.lines().count();
    assert!(
        lines <= 300,
        "README.md is {lines} lines; the guides in docs/ take the rest"
    );
    for heading in ["## Quick start", "## Contents"] {
        assert!(readme.contains(&format!("\n{heading}\n")), "no {heading}");
    }
    // .ci/run runs the README's two set-up commands as written.
    let ci = read(&root().join(".ci/run"));
    for command in [
        "cargo run --release -- run cases --quiet",
        "cargo test --release",
    ] {
        assert!(readme.contains(command), "README.md lacks `{command}`");
        assert!(ci.contains(command), ".ci/run lacks `{command}`");
    }
    let drivers = read(&root().join("docs/drivers.md"));
    assert!(drivers.contains("<!-- matrix:begin -->") && drivers.contains("<!-- matrix:end -->"));
    assert!(drivers.contains("matrix cases --write-readme docs/drivers.md"));
}

/// Files the adapters' branch writes from the driver modules' docs; linked
/// from here before they land. Remove each once it exists.
const PENDING: [&str; 4] = [
    "docs/drivers/gl.md",
    "docs/drivers/vulkan.md",
    "docs/drivers/lavapipe.md",
    "docs/drivers/external.md",
];

/// `](target)` links in Markdown text, outside code fences.
fn links(text: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            continue;
        }
        let mut rest = line;
        while let Some(at) = rest.find("](") {
            rest = &rest[at + 2..];
            if let Some(end) = rest.find(')') {
                found.push(rest[..end].to_owned());
                rest = &rest[end..];
            }
        }
    }
    found
}

/// GitHub's anchor for a heading: lower case, punctuation dropped, spaces
/// as hyphens.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter(|c| c.is_alphanumeric() || *c == ' ' || *c == '-' || *c == '_')
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

fn anchors(text: &str) -> Vec<String> {
    let mut fenced = false;
    let mut found = Vec::new();
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
        } else if !fenced && line.starts_with('#') {
            found.push(anchor(line.trim_start_matches('#')));
        }
    }
    found
}

#[test]
fn every_link_to_a_repository_file_points_at_one() {
    let mut broken = Vec::new();
    for file in docs::doc_files(&root()) {
        let text = read(&file);
        let dir = file.parent().unwrap();
        for link in links(&text) {
            if link.contains("://") || link.starts_with("mailto:") {
                continue;
            }
            let (path, fragment) = link.split_once('#').unwrap_or((&link, ""));
            let target = if path.is_empty() {
                file.clone()
            } else {
                dir.join(path)
            };
            let shown = file.strip_prefix(root()).unwrap().display().to_string();
            if !target.exists() {
                let relative = target
                    .canonicalize()
                    .ok()
                    .or_else(|| Some(normalize(&target)))
                    .and_then(|t| t.strip_prefix(root()).ok().map(Path::to_path_buf));
                let pending = relative
                    .as_ref()
                    .is_some_and(|r| PENDING.iter().any(|p| Path::new(p) == r));
                if !pending {
                    broken.push(format!("{shown}: ({link}) points at nothing"));
                }
                continue;
            }
            if !fragment.is_empty()
                && target.extension().is_some_and(|e| e == "md")
                && !anchors(&read(&target)).iter().any(|a| a == fragment)
            {
                broken.push(format!("{shown}: ({link}) has no heading #{fragment}"));
            }
        }
    }
    assert!(broken.is_empty(), "{}", broken.join("\n"));
}

/// `path` with `.` and `..` resolved without touching the file system.
fn normalize(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for part in path.components() {
        match part {
            std::path::Component::ParentDir => {
                out.pop();
            }
            std::path::Component::CurDir => {}
            other => out.push(other),
        }
    }
    out
}

/// The words of a shell command line: whitespace-separated, with single
/// and double quotes grouping (no escapes, no expansions).
fn shell_words(line: &str) -> Vec<String> {
    let mut words = Vec::new();
    let mut word = String::new();
    let mut quote: Option<char> = None;
    let mut started = false;
    for c in line.chars() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), c) => word.push(c),
            (None, '\'' | '"') => {
                quote = Some(c);
                started = true;
            }
            (None, c) if c.is_whitespace() => {
                if started || !word.is_empty() {
                    words.push(std::mem::take(&mut word));
                    started = false;
                }
            }
            (None, c) => word.push(c),
        }
    }
    if started || !word.is_empty() {
        words.push(word);
    }
    words
}

/// The command lines of the ```sh blocks of `text` (comments and blank
/// lines dropped), each with the heading of its section.
fn sh_commands(text: &str) -> Vec<(String, String)> {
    let mut commands = Vec::new();
    let mut section = String::new();
    let mut in_sh = false;
    for line in text.lines() {
        if let Some(heading) = line.strip_prefix("## ") {
            heading.clone_into(&mut section);
        }
        if line.trim_start().starts_with("```") {
            in_sh = !in_sh && line.trim() == "```sh";
            continue;
        }
        if !in_sh {
            continue;
        }
        let command = line.split(" #").next().unwrap().trim();
        if !command.is_empty() && !command.starts_with('#') {
            commands.push((section.clone(), command.to_owned()));
        }
    }
    commands
}

/// The binary's arguments for a README command that runs the binary
/// (`rastercheck ARGS` or `cargo run --release -- ARGS`), `out/` paths
/// moved into `out`; `None` for other commands (cargo's own, a shell's).
fn binary_args(command: &str, out: &Path) -> Option<Vec<String>> {
    let words = shell_words(command);
    let args = if words.first().is_some_and(|w| w == "rastercheck") {
        &words[1..]
    } else if words.starts_with(&[
        "cargo".into(),
        "run".into(),
        "--release".into(),
        "--".into(),
    ]) {
        &words[4..]
    } else {
        return None;
    };
    Some(
        args.iter()
            .map(|a| match a.strip_prefix("out/") {
                Some(rest) => out.join(rest).display().to_string(),
                None => a.clone(),
            })
            .collect(),
    )
}

#[test]
fn the_readme_commands_run_from_the_repository_as_written() {
    let readme = read(&root().join("README.md"));
    let commands = sh_commands(&readme);
    let quick: Vec<&String> = commands
        .iter()
        .filter(|(section, _)| section == "Quick start")
        .map(|(_, c)| c)
        .collect();
    assert!(
        quick.len() >= 3 && quick[0].starts_with("cargo install --path ."),
        "the quick start installs rastercheck, then runs it: {quick:?}"
    );
    let out = common::cli::scratch("docs-readme");
    let mut ran = 0;
    for (section, command) in &commands {
        // A whole external program's run takes minutes; tests/examples.rs
        // and tests/external.rs run them.
        if command.contains("external") {
            continue;
        }
        let Some(args) = binary_args(command, &out) else {
            continue;
        };
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let result = rastercheck(&root(), &args);
        let code = result.status.code();
        // The quick start passes; anything else may find a failure (a
        // mutant), never bad usage.
        let expected: &[i32] = if section == "Quick start" || section.starts_with("Set-up") {
            &[0]
        } else {
            &[0, 1]
        };
        assert!(
            code.is_some_and(|c| expected.contains(&c)),
            "README ({section}) `{command}` exited {code:?}:\n{}",
            text(&result)
        );
        ran += 1;
    }
    assert!(ran >= 4, "only {ran} README commands ran");
    let listed = rastercheck(&root(), &["rasterizers"]);
    assert!(text(&listed).contains("production"), "{}", text(&listed));
    // The README's examples write under out/, which git ignores.
    let ignore = read(&root().join(".gitignore"));
    assert!(ignore.lines().any(|l| l.trim() == "/out"), "{ignore}");
    let _ = std::fs::remove_dir_all(&out);
}

/// Every README and guide command that writes a file writes it under
/// `out/` (ignored) or into the file it documents, never into the
/// repository's root.
#[test]
fn documented_commands_write_under_out() {
    let mut loose = Vec::new();
    for file in docs::doc_files(&root()) {
        for (_, command) in sh_commands(&read(&file)) {
            let words = shell_words(&command);
            for pair in words.windows(2) {
                let writes = ["--report", "--out", "save"].contains(&pair[0].as_str());
                let target = &pair[1];
                let allowed = target.starts_with("out/")
                    || target.starts_with('/')
                    || target.starts_with("docs/")
                    || target.starts_with('$');
                if writes && !allowed {
                    loose.push(format!("{}: `{command}`", file.display()));
                }
            }
        }
    }
    assert!(loose.is_empty(), "{}", loose.join("\n"));
}

/// The README's prose (outside generated blocks, code, links and the exit
/// codes) has no digits: counts belong in generated blocks.
#[test]
fn the_readme_prose_carries_no_figures() {
    let readme = read(&root().join("README.md"));
    let allowed = |word: &str| {
        // SPEC sections, versions, and number types (f32, i128).
        let number_type = word.len() > 1
            && word.starts_with(['f', 'i', 'u'])
            && word[1..].chars().all(|c| c.is_ascii_digit());
        word.starts_with('§')
            || number_type
            || ["2D", "3D", "1.87", "1.89"].contains(&word)
            || word.starts_with("docs/")
    };
    let mut flagged = Vec::new();
    let mut fenced = false;
    let mut generated = false;
    let mut section = "";
    for line in readme.lines() {
        if line.starts_with("## ") {
            section = line;
        }
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if line.starts_with("<!-- generated:") || line.starts_with("<!-- matrix:") {
            generated = line.ends_with(":begin -->");
            continue;
        }
        if fenced || generated || section == "## Exit codes" {
            continue;
        }
        let mut prose = String::new();
        let mut in_code = false;
        let mut rest = line;
        while let Some(c) = rest.chars().next() {
            if c == '`' {
                in_code = !in_code;
            } else if !in_code {
                prose.push(c);
            }
            rest = &rest[c.len_utf8()..];
        }
        // Link targets are checked by the link test.
        let prose = prose
            .split("](")
            .enumerate()
            .map(|(i, part)| match part.split_once(')') {
                Some((_, after)) if i > 0 => after,
                _ => part,
            })
            .collect::<Vec<_>>()
            .join(" ");
        for word in prose.split(|c: char| c.is_whitespace() || "(),;:*".contains(c)) {
            let word = word.trim_end_matches('.');
            if word.chars().any(|c| c.is_ascii_digit()) && !allowed(word) {
                flagged.push(format!("{word:?} in: {line}"));
            }
        }
    }
    assert!(
        flagged.is_empty(),
        "figures in README.md prose (put them in a generated block, or say it without a count):\n{}",
        flagged.join("\n")
    );
}
