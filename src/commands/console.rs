//! What a run prints on the console: one line per case and rasterizer
//! (coloured on a terminal), and a progress bar on a terminal once a run
//! has lasted a second.

use std::io::IsTerminal;

use crate::harness::runner::{CaseOutcome, Problem};
use crate::harness::suite::{self, GoldenStatus, Verdict};
use crate::rasterizer::Rasterizer;

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
            return println!("{} {id:width$}  {e}", paint("BAD  ", RED, colour))
        }
        Some(Problem::ReferenceFailed(e)) => {
            return println!(
                "{} {id:width$}  the reference failed on this case: {e}",
                paint("ERROR", RED, colour)
            )
        }
        Some(Problem::LimitExceeded(e)) => {
            return println!("{} {id:width$}  {e}", paint("LIMIT", RED, colour))
        }
        // Listed once, in the run's summary line.
        Some(Problem::Interrupted) => return,
        None => {}
    }
    if let Some(GoldenStatus::Differs(why)) = &outcome.golden {
        println!(
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
        };
        if quiet && matches!(result.verdict, Verdict::Pass) {
            continue;
        }
        println!(
            "{} {id:width$}  {}  {}",
            paint(&format!("{label:5}"), tint, colour),
            result.rasterizer,
            suite::describe(result)
        );
        if let Verdict::Fail(reasons) = &result.verdict {
            for reason in reasons {
                println!("        {reason}");
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

    pub(crate) fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}
