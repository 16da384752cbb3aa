//! `rastercheck diff OLD NEW`: what changed between two reports (newly
//! failing, fixed, added and removed cases, metric deltas), exit 1 on a
//! regression (SPEC.md §10.2).

use super::console::outln;
use std::path::PathBuf;

use clap::Args;

use super::exit::Exit;
use crate::report::diff::{self, render, Change, Diff};

/// Rows of each list printed on the console; `--out` files hold more.
const CONSOLE_ROWS: usize = 20;

#[derive(Args)]
pub struct DiffArgs {
    /// The earlier report: a report.json, or the folder holding it.
    pub old: PathBuf,
    /// The later report: a report.json, or the folder holding it.
    pub new: PathBuf,
    /// Write diff.md (for a pull-request comment), diff.html and diff.json
    /// into this folder.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Compare rasterizer OLD_NAME of OLD with NEW_NAME of NEW; repeat for
    /// several. Without it, equal names are paired, and two reports of one
    /// rasterizer each are paired whatever their names.
    #[arg(long = "pair", value_name = "OLD_NAME=NEW_NAME", value_parser = parse_pair)]
    pub pairs: Vec<(String, String)>,
}

fn parse_pair(text: &str) -> Result<(String, String), String> {
    match text.split_once('=') {
        Some((o, n)) if !o.is_empty() && !n.is_empty() => Ok((o.to_owned(), n.to_owned())),
        _ => Err(format!(
            "expected OLD_NAME=NEW_NAME, got {:?}",
            super::values::shorten(text)
        )),
    }
}

fn print_changes(title: &str, changes: &[Change]) {
    if changes.is_empty() {
        return;
    }
    outln!("{title} ({}):", changes.len());
    for c in changes.iter().take(CONSOLE_ROWS) {
        let why = c.reasons.first().map(String::as_str).unwrap_or("");
        outln!("  {}  {}  {} → {}  {why}", c.case, c.who(), c.old, c.new);
    }
    if changes.len() > CONSOLE_ROWS {
        outln!("  and {} more", changes.len() - CONSOLE_ROWS);
    }
}

fn print_summary(d: &Diff) {
    outln!("diff {} → {}", d.old.file, d.new.file);
    for note in render::notes(d) {
        outln!("note: {note}");
    }
    print_changes("newly failing", &d.newly_failing);
    print_changes("no longer judged", &d.no_longer_judged);
    let worse: Vec<_> = d.metrics.iter().filter(|m| m.change == "worse").collect();
    if !worse.is_empty() {
        outln!("metrics worse, worst first ({}):", worse.len());
        for m in worse.iter().take(CONSOLE_ROWS) {
            outln!(
                "  {}  {}  {}: {} → {} ({})",
                m.case,
                m.who(),
                m.metric,
                render::number(m.old),
                render::number(m.new),
                render::signed(m.delta)
            );
        }
        if worse.len() > CONSOLE_ROWS {
            outln!("  and {} more", worse.len() - CONSOLE_ROWS);
        }
    }
    print_changes("fixed", &d.fixed);
    for (title, cases) in [("cases added", &d.added), ("cases removed", &d.removed)] {
        if !cases.is_empty() {
            outln!("{title} ({}):", cases.len());
            for c in cases.iter().take(CONSOLE_ROWS) {
                outln!("  {}", c.case);
            }
            if cases.len() > CONSOLE_ROWS {
                outln!("  and {} more", cases.len() - CONSOLE_ROWS);
            }
        }
    }
    outln!(
        "{}: {}",
        if d.regression {
            "REGRESSION"
        } else {
            "no regression"
        },
        render::headline(d)
    );
}

/// `rastercheck diff OLD NEW [--out DIR] [--pair OLD=NEW]...`.
pub fn diff(args: DiffArgs) -> Exit {
    let DiffArgs {
        old,
        new,
        out,
        pairs,
    } = args;
    if let Some(dir) = &out {
        if let Err(e) = std::fs::create_dir_all(dir) {
            eprintln!("error: --out {}: {e}", dir.display());
            return Exit::BadInput;
        }
    }
    let (old, new) = match (diff::read(&old), diff::read(&new)) {
        (Ok(old), Ok(new)) => (old, new),
        (o, n) => {
            for e in [o.err(), n.err()].into_iter().flatten() {
                eprintln!("error: {e}");
            }
            return Exit::BadInput;
        }
    };
    let pairs = match diff::pair(&old, &new, &pairs) {
        Ok(pairs) => pairs,
        Err(e) => {
            eprintln!("error: {e}");
            return Exit::BadInput;
        }
    };
    let d = diff::compare(&old, &new, pairs);
    print_summary(&d);
    if let Some(dir) = &out {
        let files = [
            ("diff.json", d.to_json()),
            ("diff.md", render::markdown(&d)),
            ("diff.html", render::html(&d)),
        ];
        for (name, content) in files {
            if let Err(e) = crate::report::write_file(&dir.join(name), content.as_bytes()) {
                eprintln!("error: {e}");
                return Exit::BadInput;
            }
        }
        outln!(
            "wrote diff.json, diff.md and diff.html to {}",
            dir.display()
        );
    }
    if !d.judged() {
        eprintln!(
            "error: nothing was judged: {}",
            if d.pairs.is_empty() {
                "no rasterizer of OLD could be paired with one of NEW (use --pair OLD_NAME=NEW_NAME)"
            } else {
                "the reports share no case"
            }
        );
        return Exit::NothingJudged;
    }
    if d.regression {
        Exit::Fail
    } else {
        Exit::Pass
    }
}
