//! How a method's frame is scored against the exact answer: mismatched
//! samples (triangles), lit pixel sets (lines), resolved coverage against
//! exact areas (antialiasing) and time coverage against exact time coverage
//! (motion blur). Computing the exact answers is the reference's, or
//! `translation.rs`'s.

use crate::frame::Frame;

pub(super) fn mismatched(reference: &Frame, frame: &Frame) -> u64 {
    reference
        .coverage
        .iter()
        .zip(&frame.coverage)
        .zip(reference.last.iter().zip(&frame.last))
        .filter(|((r, c), (rl, cl))| r != c || rl != cl)
        .count() as u64
}

/// The pixels one line lights, in a frame holding it alone.
pub(super) fn lit(frame: &Frame) -> Vec<usize> {
    frame
        .coverage
        .iter()
        .enumerate()
        .filter(|(_, &c)| c > 0)
        .map(|(i, _)| i)
        .collect()
}

/// (RMS over edge pixels, largest |error|) of resolved coverage against
/// exact areas; an aliased frame's coverage counts stand for its resolve.
pub(super) fn coverage_error(exact: &[f64], frame: &Frame) -> (f64, f64) {
    let resolved = frame
        .resolved
        .clone()
        .unwrap_or_else(|| frame.box_resolve());
    let (mut sum, mut n, mut max) = (0.0, 0usize, 0.0f64);
    for (&e, &r) in exact.iter().zip(&resolved) {
        let edge = (e > 0.0 && e < 1.0) || (r > 0.0 && r < 1.0) || r != e;
        if edge {
            sum += (r - e) * (r - e);
            n += 1;
            max = max.max((r - e).abs());
        }
    }
    ((sum / n.max(1) as f64).sqrt(), max)
}

/// (RMS over moving pixels, largest |error|) of a time coverage against
/// the exact one (SPEC.md §15.4): moving pixels are those whose exact
/// value is not a whole number or whose candidate value is not exact.
pub fn time_error(exact: &[f64], time: &[f64]) -> (f64, f64) {
    let (mut sum, mut n, mut max) = (0.0, 0usize, 0.0f64);
    for (&e, &t) in exact.iter().zip(time) {
        if e.fract() != 0.0 || t != e {
            sum += (t - e) * (t - e);
            n += 1;
            max = max.max((t - e).abs());
        }
    }
    ((sum / n.max(1) as f64).sqrt(), max)
}
