//! Area methods judged as area methods (SPEC.md §14.4).
//!
//! An area method answers each primitive's covered fraction of each pixel
//! (an external program's `coverage` answer, §12.9: a frame without
//! samples that keeps its [`Parts`]). It claims the exact area, so it is
//! held to the exact area within one step: the quantization it declares
//! (`coverage_bits`), or, when it declares none, [`DEFAULT_STEP`]. The
//! N-sample bounds of a case (`max_coverage_error`, `max_coverage_rms`)
//! are written for sample methods, whose samples may miss a sliver whole;
//! they do not apply to it.
//!
//! Drawing nothing where some primitive's exact area in a pixel exceeds one
//! step is a failure of its own (§6.1 applied to coverage answers). A case
//! in which every primitive's exact area in every pixel is at most one step
//! stays passable by an empty answer: that answer is within the step
//! everywhere.
//!
//! An area method that gives no coverage per primitive says so in its
//! frame ([`Frame::area_step`]: `area-f32`, `vello-cpu`): each pixel's
//! resolved value, the total of its primitives' areas, is held to the
//! reference's exact area of the pixel within one step, and drawing
//! nothing where a pixel's exact area exceeds one step fails the same way
//! ([`PixelAreas`]). A frame without samples that says neither
//! (`adaptive-resolve`, the box resolve of N samples without its mask;
//! `tiny-skia`, whose antialiasing is 4 sub-scanlines per pixel) is a
//! sample method and keeps the sample bounds.

use serde::Serialize;

use super::counted::counted;
use crate::frame::{Frame, Parts};

/// What a declared step allows beyond itself: the program's own rounding
/// of an area it computes in floats.
pub const FLOAT_SLACK: f64 = 1e-9;

/// The step an area method that declares no quantization is held to: 2^-8,
/// the finest common 8-bit encoding. A method that rounds to the nearest
/// multiple of 1/255 or of 1/256 (error at most 1/510 or 1/512), or
/// truncates to multiples of 1/256, meets it without declaring anything;
/// one that truncates to multiples of 1/255 must declare `coverage_bits`.
pub const DEFAULT_STEP: f64 = 1.0 / 256.0;

/// Whether a frame is an area method's answer, judged as such: no samples,
/// and coverage per primitive or a claimed step per pixel
/// ([`Frame::area_step`]).
pub fn is_area_answer(frame: &Frame) -> bool {
    frame.samples == 0 && (frame.parts.is_some() || frame.area_step.is_some())
}

/// An area method without coverage per primitive, each pixel's total held
/// to the pixel's exact area within one step: `report.json`'s
/// `metrics.antialias.pixel_areas`.
#[derive(Clone, Debug, PartialEq, Serialize, serde::Deserialize)]
pub struct PixelAreas {
    /// The step claimed; 0 for none (the default applies).
    pub step: f64,
    /// Pixels judged, and those whose total is more than one step off.
    pub pixels: u64,
    pub over_step: u64,
    /// The largest |total − exact area|, and where (x, y).
    pub max_error: f64,
    pub worst_pixel: [u32; 2],
    /// It drew nothing, while this many pixels' exact area exceeds one
    /// step (0 when it drew something, or when none does).
    pub nothing_drawn_over_step: u64,
}

/// [`PixelAreas`] of `candidate` against the reference's exact area per
/// pixel (its resolved value, the exact area rounded once); `None` unless
/// the candidate claims a step per pixel and both have resolved coverage
/// of the canvas's size.
pub fn pixel_areas(reference: &Frame, candidate: &Frame) -> Option<PixelAreas> {
    let step = candidate.area_step.filter(|_| candidate.parts.is_none())?;
    let (exact, total) = (reference.resolved.as_ref()?, candidate.resolved.as_ref()?);
    if exact.len() != total.len() || exact.len() != candidate.pixel_count() {
        return None;
    }
    let bound = if step > 0.0 { step } else { DEFAULT_STEP } + FLOAT_SLACK;
    let width = candidate.width.max(1) as usize;
    let mut m = PixelAreas {
        step,
        pixels: exact.len() as u64,
        over_step: 0,
        max_error: 0.0,
        worst_pixel: [0, 0],
        nothing_drawn_over_step: 0,
    };
    for (p, (&e, &t)) in exact.iter().zip(total).enumerate() {
        // A value that is not a number is off by more than any step.
        let error = if t.is_finite() {
            (t - e).abs()
        } else {
            f64::INFINITY
        };
        if error > m.max_error {
            m.max_error = error;
            m.worst_pixel = [(p % width) as u32, (p / width) as u32];
        }
        m.over_step += u64::from(error > bound);
    }
    if total.iter().all(|&t| t == 0.0) {
        m.nothing_drawn_over_step = exact.iter().filter(|&&e| e > bound).count() as u64;
    }
    Some(m)
}

/// Why a [`PixelAreas`] fails a case; empty when it passes.
pub fn pixel_failures(m: &PixelAreas) -> Vec<String> {
    let step = if m.step > 0.0 { m.step } else { DEFAULT_STEP };
    let mut out = Vec::new();
    if m.nothing_drawn_over_step > 0 {
        out.push(format!(
            "antialias: drew nothing where the exact area of {} {step:.3e} ({}) (SPEC.md §6.1)",
            counted(m.nothing_drawn_over_step, "pixel exceeds", "pixels exceed"),
            whose_step(m.step)
        ));
    } else if m.over_step > 0 {
        let [x, y] = m.worst_pixel;
        out.push(format!(
            "antialias: {} of {} {} more than {step:.3e} ({}) from {} exact area; the largest error, {:.3e}, is at ({x}, {y}) (SPEC.md §14.4)",
            m.over_step,
            counted(m.pixels, "pixel", "pixels"),
            if m.over_step == 1 { "is" } else { "are" },
            whose_step(m.step),
            if m.over_step == 1 { "its" } else { "their" },
            m.max_error
        ));
    }
    out
}

/// The step a primitive's coverage is held to: the declared one, else the
/// default.
pub fn step_of(parts: &Parts) -> f64 {
    if parts.step > 0.0 {
        parts.step
    } else {
        DEFAULT_STEP
    }
}

/// The bound on each primitive-pixel error: one step, and 10^-9 for the
/// program's own float arithmetic.
pub fn allowed_error(parts: &Parts) -> f64 {
    step_of(parts) + FLOAT_SLACK
}

/// What a reason names the step as.
pub fn whose_step(declared: f64) -> &'static str {
    if declared > 0.0 {
        "one step of the declared quantization"
    } else {
        "the default step 2^-8 of an area method that declares no coverage_bits, SPEC.md §14.4"
    }
}

/// What the per-primitive comparison (`parts.rs`) saw of the exact areas:
/// the (primitive, pixel) pairs whose area exceeds the bound, the largest
/// area of a pair, and where, [primitive, x, y].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct AreasSeen {
    pub over_bound: u64,
    pub largest: f64,
    pub at: [u32; 3],
}

/// An area answer that draws nothing where a primitive's exact area in a
/// pixel exceeds one step: `report.json`'s `metrics.antialias.nothing_drawn`.
/// Judged per primitive, as the step is: two primitives of 1/256 each in a
/// pixel may both round to 0.
#[derive(Clone, Debug, PartialEq, Serialize, serde::Deserialize)]
pub struct NothingDrawn {
    /// (primitive, pixel) pairs whose exact area exceeds one step.
    pub pairs: u64,
    /// The largest exact area of a pair, and where: [primitive, x, y].
    pub largest: f64,
    pub at: [u32; 3],
    /// The declared step; 0 for none (the default applies).
    pub step: f64,
}

/// [`NothingDrawn`] when `candidate` is an area answer that is 0 on every
/// pixel and for every primitive, while some primitive's exact area in a
/// pixel exceeds one step (`seen`: by the per-primitive comparison).
pub fn nothing_drawn(candidate: &Frame, seen: &AreasSeen) -> Option<NothingDrawn> {
    let parts = candidate
        .parts
        .as_ref()
        .filter(|_| is_area_answer(candidate))?;
    let drawn = candidate.resolved.iter().flatten().any(|&r| r != 0.0)
        || parts.coverage.iter().flatten().any(|&(_, f)| f != 0.0);
    (!drawn && seen.over_bound > 0).then_some(NothingDrawn {
        pairs: seen.over_bound,
        largest: seen.largest,
        at: seen.at,
        step: parts.step,
    })
}

/// The reason a [`NothingDrawn`] fails a case.
pub fn failure(n: &NothingDrawn) -> String {
    let [p, x, y] = n.at;
    format!(
        "antialias: drew nothing where the exact area of {} {:.3e} ({}); the largest, {:.3e}, is primitive {p}'s at ({x}, {y}) (SPEC.md §6.1)",
        counted(n.pairs, "primitive-pixel exceeds", "primitive-pixels exceed"),
        if n.step > 0.0 { n.step } else { DEFAULT_STEP },
        whose_step(n.step),
        n.largest
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn answer(fractions: Vec<(u32, f64)>, step: f64) -> Frame {
        let mut resolved = vec![0.0; 2];
        for &(p, f) in &fractions {
            resolved[p as usize] += f;
        }
        let mut f = Frame::resolved_only(2, 1, resolved);
        f.parts = Some(Parts {
            saturates: false,
            coverage: vec![fractions, vec![]],
            step,
        });
        f
    }

    fn seen(over_bound: u64, largest: f64) -> AreasSeen {
        AreasSeen {
            over_bound,
            largest,
            at: [0, 1, 0],
        }
    }

    #[test]
    fn nothing_is_a_failure_only_where_an_area_exceeds_one_step() {
        let n = nothing_drawn(&answer(vec![], 0.0), &seen(1, 0.5)).unwrap();
        assert_eq!((n.pairs, n.largest, n.at), (1, 0.5, [0, 1, 0]));
        assert!(failure(&n).contains("default step 2^-8"));
        assert!(failure(&n).contains("primitive 0's at (1, 0)"));
        let n = nothing_drawn(&answer(vec![], 0.25), &seen(1, 0.5)).unwrap();
        assert!(failure(&n).contains("2.500e-1 (one step of the declared quantization)"));
        // No area over one step: passable.
        assert_eq!(nothing_drawn(&answer(vec![], 0.0), &seen(0, 0.003)), None);
        // Something drawn, or no parts (not told apart from a sample
        // method): not this rule.
        assert_eq!(
            nothing_drawn(&answer(vec![(0, 0.5)], 0.0), &seen(1, 0.5)),
            None
        );
        let bare = Frame::resolved_only(2, 1, vec![0.0, 0.0]);
        assert_eq!(nothing_drawn(&bare, &seen(1, 0.5)), None);
    }

    #[test]
    fn an_area_method_without_parts_is_held_to_each_pixel_area() {
        let reference = Frame::resolved_only(2, 1, vec![0.5, 0.003]);
        let mut close = Frame::resolved_only(2, 1, vec![0.5 + 1.0 / 512.0, 0.0]);
        // Unclaimed: a resolved sample method, not judged here.
        assert_eq!(pixel_areas(&reference, &close), None);
        close.area_step = Some(0.0);
        let m = pixel_areas(&reference, &close).unwrap();
        assert_eq!((m.over_step, m.nothing_drawn_over_step), (0, 0));
        assert!(pixel_failures(&m).is_empty());
        let mut far = Frame::resolved_only(2, 1, vec![0.45, 0.003]);
        far.area_step = Some(0.0);
        let m = pixel_areas(&reference, &far).unwrap();
        assert_eq!((m.over_step, m.worst_pixel), (1, [0, 0]));
        assert!(pixel_failures(&m)[0].contains("default step 2^-8"));
        let mut nothing = Frame::resolved_only(2, 1, vec![0.0, 0.0]);
        nothing.area_step = Some(0.0);
        let m = pixel_areas(&reference, &nothing).unwrap();
        // 0.5 is over one step, 0.003 is not.
        assert_eq!(m.nothing_drawn_over_step, 1);
        assert!(pixel_failures(&m)[0].contains("drew nothing"));
        // Where no pixel's area exceeds a step, nothing is within it.
        let tiny = Frame::resolved_only(2, 1, vec![0.003, 0.0]);
        let m = pixel_areas(&tiny, &nothing).unwrap();
        assert!(pixel_failures(&m).is_empty());
    }

    #[test]
    fn pixel_area_reasons_take_the_number_of_their_counts() {
        let areas = |over_step, pixels, nothing_drawn_over_step| PixelAreas {
            step: 0.25,
            pixels,
            over_step,
            max_error: 0.5,
            worst_pixel: [1, 2],
            nothing_drawn_over_step,
        };
        let one = pixel_failures(&areas(1, 1, 0));
        assert!(
            one[0].starts_with("antialias: 1 of 1 pixel is more than 2.500e-1 (one step of the declared quantization) from its exact area;"),
            "{one:?}"
        );
        let two = pixel_failures(&areas(2, 4, 0));
        assert!(
            two[0].starts_with("antialias: 2 of 4 pixels are more than 2.500e-1 (one step of the declared quantization) from their exact area;"),
            "{two:?}"
        );
        let one = pixel_failures(&areas(0, 4, 1));
        assert!(
            one[0].starts_with(
                "antialias: drew nothing where the exact area of 1 pixel exceeds 2.500e-1"
            ),
            "{one:?}"
        );
        let two = pixel_failures(&areas(0, 4, 3));
        assert!(
            two[0].starts_with(
                "antialias: drew nothing where the exact area of 3 pixels exceed 2.500e-1"
            ),
            "{two:?}"
        );
    }

    #[test]
    fn the_nothing_drawn_reason_takes_the_number_of_its_count() {
        let nothing = |pairs| NothingDrawn {
            pairs,
            largest: 0.5,
            at: [0, 1, 1],
            step: 0.25,
        };
        assert!(
            failure(&nothing(1)).starts_with(
                "antialias: drew nothing where the exact area of 1 primitive-pixel exceeds 2.500e-1"
            ),
            "{}",
            failure(&nothing(1))
        );
        assert!(
            failure(&nothing(2)).starts_with(
                "antialias: drew nothing where the exact area of 2 primitive-pixels exceed 2.500e-1"
            ),
            "{}",
            failure(&nothing(2))
        );
    }
}
