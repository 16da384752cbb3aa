//! What a run prints on the console: one line per case and rasterizer
//! (coloured on a terminal), and a progress bar on a terminal once a run
//! has lasted a second.

use std::io::{IsTerminal, Write};
use std::sync::atomic::{AtomicBool, Ordering};

use crate::harness::golden::GoldenStatus;
use crate::harness::judge;
use crate::harness::judge::Verdict;
use crate::harness::profile::OwnConventions;
use crate::harness::runner::{CaseOutcome, Problem};
use crate::rasterizer::Rasterizer;

/// Set once stdout could not be written (a reader that closed the pipe,
/// as `rastercheck run | head` does): nothing more is printed, and the
/// command goes on to its reports and its exit code.
static STDOUT_CLOSED: AtomicBool = AtomicBool::new(false);

/// Writes `text` to stdout, unless stdout has been closed. A broken pipe
/// ends printing quietly (no panic, no message); another error says so once
/// on stderr. Every command prints through this ([`out!`], [`outln!`]),
/// never through `println!`, which panics on a broken pipe.
pub(crate) fn write_stdout(text: std::fmt::Arguments) {
    if STDOUT_CLOSED.load(Ordering::Relaxed) {
        return;
    }
    let mut stdout = std::io::stdout().lock();
    let written = stdout.write_fmt(text).and_then(|()| stdout.flush());
    if let Err(e) = written {
        STDOUT_CLOSED.store(true, Ordering::Relaxed);
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            let _ = writeln!(std::io::stderr(), "note: stdout: {e}; printing stops here");
        }
    }
}

/// `print!` that survives a closed stdout ([`write_stdout`]).
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::commands::console::write_stdout(format_args!($($arg)*))
    };
}

/// `println!` that survives a closed stdout ([`write_stdout`]).
macro_rules! outln {
    () => {
        $crate::commands::console::write_stdout(format_args!("\n"))
    };
    ($($arg:tt)*) => {
        $crate::commands::console::write_stdout(format_args!("{}\n", format_args!($($arg)*)))
    };
}

pub(crate) use {out, outln};

/// One line per candidate (failures only with `quiet`), with reasons.
pub(crate) fn print_outcome(
    outcome: &CaseOutcome,
    candidates: &[Box<dyn Rasterizer>],
    quiet: bool,
    colour: bool,
    width: usize,
) {
    let id = &outcome.file.id;
    match &outcome.problem {
        Some(Problem::Unreadable(e)) => {
            return outln!("{} {id:width$}  {e}", paint("BAD  ", RED, colour))
        }
        Some(Problem::ReferenceFailed(e)) => {
            return outln!(
                "{} {id:width$}  the reference failed on this case: {e}",
                paint("ERROR", RED, colour)
            )
        }
        Some(Problem::LimitExceeded(e)) => {
            outln!("{} {id:width$}  {e}", paint("LIMIT", RED, colour));
            // A candidate over the limit: the others' verdicts follow.
            if outcome.candidates.is_empty() {
                return;
            }
        }
        // Listed once, in the run's summary line.
        Some(Problem::Interrupted) => return,
        None => {}
    }
    if let Some(GoldenStatus::Differs(why)) = &outcome.golden {
        outln!(
            "{} {id:width$}  the reference no longer reproduces its golden file: {why}",
            paint("GOLDEN", RED, colour)
        );
    }
    for (result, candidate) in outcome.candidates.iter().zip(candidates) {
        let (label, tint) = match &result.verdict {
            Verdict::Pass => ("PASS", GREEN),
            Verdict::Fail(_) if candidate.is_foil() => ("FOIL", YELLOW),
            Verdict::Fail(_) => ("FAIL", RED),
            Verdict::Unsupported(_) => ("UNSUPPORTED", YELLOW),
            Verdict::Error(_) => ("ERROR", RED),
            Verdict::Flaky(_) => ("FLAKY", RED),
        };
        if quiet && matches!(result.verdict, Verdict::Pass | Verdict::Unsupported(_)) {
            continue;
        }
        let mut method = result.method.map(|m| format!(" ({m})")).unwrap_or_default();
        if let (Some(rule), Some(scene)) = (result.judged.fill_rule, &outcome.scene) {
            method.push_str(&format!(
                " (judged under its own {rule} rule; the case states {})",
                scene.rules.fill_rule
            ));
        }
        if let Some(viewport) = result.judged.viewport {
            let values = match result.judged.viewport_values {
                true => format!(", {}", OwnConventions::WHOLE_VALUES),
                false => String::new(),
            };
            method.push_str(&format!(
                " (judged under its own clip-then-snap at {}{values}; the case is drawn unclipped)",
                viewport.words()
            ));
        } else if let (Some(clip), Some(scene)) = (result.judged.clip, &outcome.scene) {
            let stated = scene.rules.clip;
            method.push_str(&format!(
                " (judged under its own clipping, {}; the case states {})",
                clip.words(),
                stated.words()
            ));
        }
        if let (Some(bits), Some(scene)) = (result.judged.subpixel_bits, &outcome.scene) {
            let stated = scene
                .rules
                .subpixel_bits
                .map_or("no snapping".to_owned(), |b| b.to_string());
            method.push_str(&format!(
                " (judged under its own {bits} subpixel bits; the case states {stated})"
            ));
        }
        if let (Some(snapping), Some(scene)) = (result.judged.snapping, &outcome.scene) {
            let stated = scene
                .rules
                .subpixel_bits
                .map_or("no snapping".to_owned(), |b| format!("{b} subpixel bits"));
            method.push_str(&format!(
                " (judged under its own {}; the case states {stated})",
                snapping.words()
            ));
        }
        if let (Some(pattern), Some(aa)) = (
            result.judged.sample_pattern,
            outcome
                .scene
                .as_ref()
                .and_then(|s| s.effects.antialias.as_ref()),
        ) {
            method.push_str(&format!(
                " (judged under its own {}{} sample positions; the case states {}{})",
                pattern.name(),
                aa.samples,
                aa.pattern.name(),
                aa.samples
            ));
        }
        if result.judged.y_up {
            method.push_str(
                " (judged with its own y axis up: the case's cull and fill rule read mirrored)",
            );
        }
        if result.judged.integer_centre {
            method.push_str(
                " (judged with its own samples at whole coordinates: the case moved by (½, ½))",
            );
        }
        if let Some(own) = result.judged.line_parameter {
            method.push_str(&format!(
                " (judged under its own {} line parameter; the case states {})",
                own.words(),
                own.stated()
            ));
        }
        if result.judged.rectangle_border_ties {
            method.push_str(
                " (judged with no tie rule on rectangle lines' borders: border samples either way, counted apart)",
            );
        }
        outln!(
            "{} {id:width$}  {}{method}  {}",
            paint(&format!("{label:5}"), tint, colour),
            result.rasterizer,
            judge::describe(result)
        );
        // No tie rule (SPEC.md §3.1.1): its ties counted apart, never hidden.
        if let Some(ties) = result.metrics.as_ref().and_then(|m| m.ties.as_ref()) {
            outln!("        {}", ties.line());
        }
        // A conservative case (SPEC.md §19): the allowed band it used.
        if let Some(m) = result
            .metrics
            .as_ref()
            .and_then(|m| m.conservative.as_ref())
        {
            outln!("        {}", crate::metrics::conservative::summary(m));
        }
        // The latitude for diamond-exit lines (SPEC.md §4.2.1): what used it.
        if let Some(lines) = result.metrics.as_ref().and_then(|m| m.latitude.as_ref()) {
            outln!("        {}", lines.line());
        }
        if let Verdict::Fail(reasons) = &result.verdict {
            for reason in reasons {
                outln!("        {reason}");
            }
        }
        if let Verdict::Flaky(flaky) = &result.verdict {
            for rep in &flaky.outcomes {
                outln!("        repetition {}: {}", rep.repetition, rep.describe());
            }
            for difference in &flaky.differences {
                outln!("        {}", difference.describe());
            }
        }
    }
}

const RED: &str = "31";
const GREEN: &str = "32";
const YELLOW: &str = "33";

/// ANSI colour, only on a terminal.
fn paint(text: &str, colour_code: &str, colour: bool) -> String {
    if colour {
        format!("\x1b[{colour_code}m{text}\x1b[0m")
    } else {
        text.to_owned()
    }
}

/// A progress bar on a terminal, shown once a run has lasted a second.
pub(crate) struct Progress {
    bar: Option<indicatif::ProgressBar>,
    started: std::time::Instant,
}

impl Progress {
    pub(crate) fn new(total: usize, quiet: bool) -> Progress {
        let tty = std::io::stderr().is_terminal();
        let bar = (tty && !quiet).then(|| {
            let bar = indicatif::ProgressBar::with_draw_target(
                Some(total as u64),
                indicatif::ProgressDrawTarget::hidden(),
            );
            if let Ok(style) =
                indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} cases {elapsed}")
            {
                bar.set_style(style);
            }
            bar
        });
        Progress {
            bar,
            started: std::time::Instant::now(),
        }
    }

    pub(crate) fn tick(&self) {
        if let Some(bar) = &self.bar {
            if bar.is_hidden() && self.started.elapsed().as_secs_f64() > 1.0 {
                bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
            }
            bar.inc(1);
        }
    }

    /// Runs `f` (which prints) with the bar out of the way.
    pub(crate) fn suspend<R>(&self, f: impl FnOnce() -> R) -> R {
        match &self.bar {
            Some(bar) => bar.suspend(f),
            None => f(),
        }
    }

    pub(crate) fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}
