//! The coverage encoding of an area method (SPEC.md §12.9): are its
//! fractions multiples of 1/(2^k − 1) (`unorm`: a byte over 255) or of
//! 1/2^k capped at 1 − 2^-k (`fraction`: area × 256 capped at 255, as one
//! 2D library stores it, issue 40)?
//!
//! One antialiased scene, two triangles on a 16 × 8 canvas with edges of
//! many slopes, at 8 subpixel bits and in pixels of their own (each pixel's
//! value is one primitive's fraction, whether the frame gives fractions per
//! primitive or only their sums). Their partial pixels give dozens of
//! distinct exact areas (multiples of 2^-17, no finer); their interiors
//! hold whole pixels, exact area 1 by the reference.
//!
//! For k = 1..16 the partial fractions are read as multiples of 1/2^k and
//! of 1/(2^k − 1): k/(2^k − 1) and j/2^k meet only at 0 and 1 (2^k − 1 is
//! odd), so the two cannot both fit, and the smallest k that fits is the
//! encoding's. A value fits when it lies within 10^-3 of a step of a
//! multiple (a library's f32 arithmetic; a value off the grid lands there
//! by chance one time in 500, and every partial value must). The whole
//! pixels then say whether it saturates: `fraction` gives them
//! (2^k − 1)/2^k, `unorm` 1. A sample method (a frame with sample slots)
//! steps by 1/N of its N samples and has no encoding to declare; one whose
//! fractions fit no k ≤ 16 is not quantized (`area-f32`).

use serde_json::json;

use super::infer::draw;
use crate::frame::Frame;
use crate::harness::profile::CoverageEncoding;
use crate::rasterizer::{RasterError, Rasterizer};
use crate::reference::area::primitive_pixel_areas;
use crate::scene::{parse_case, Limits, Scene};

/// What the scene is, in the words a finding gives.
pub const MEASURED_ON: &str = "two antialiased triangles on a 16 × 8 canvas at 8 subpixel bits, in pixels of their own: their partial pixels read as multiples of 1/(2^k − 1) and of 1/2^k (k = 1..16), their whole pixels (exact area 1) for saturation";

/// What the coverage probe found.
#[derive(Clone, Debug, PartialEq)]
pub struct CoverageFinding {
    /// The encoding measured, when it is one SPEC.md §12.9 names.
    pub encoding: Option<CoverageEncoding>,
    /// The finding in words, with what it rests on.
    pub words: String,
    /// What the candidate's frame declares, when it declares a step.
    pub declared: Option<CoverageEncoding>,
}

/// The most bits read.
const MAX_BITS: u32 = 16;

/// How far from a multiple, in steps, a value may lie and still fit.
const SLACK: f64 = 1e-3;

/// Fewer distinct partial values than this decide nothing.
const ENOUGH: usize = 12;

fn scene() -> Scene {
    let tri = |p: [(f64, f64); 3]| json!({"triangle": p.map(|(x, y)| json!([x, y]))});
    parse_case(
        &json!({
            "name": "probe_coverage_encoding",
            "canvas": {"width": 16, "height": 8},
            "rules": {"subpixel_bits": 8, "cull": "none"},
            "effects": {"antialias": {"samples": 4}},
            "primitives": [
                tri([(0.3, 0.45), (7.7, 1.15), (1.2, 7.6)]),
                tri([(8.35, 0.2), (15.6, 3.3), (9.1, 7.8)]),
            ],
        })
        .to_string(),
        "probe",
        &Limits::default(),
    )
    .unwrap_or_else(|e| panic!("a probe scene is invalid: {e}"))
}

/// Whether every value is a multiple of 1/`steps`, within [`SLACK`].
fn fits(values: &[f64], steps: f64) -> bool {
    values
        .iter()
        .all(|v| (v * steps - (v * steps).round()).abs() <= SLACK)
}

/// The encoding a frame's parts declare (`Parts::step`, `saturates`).
fn declared(frame: &Frame) -> Option<CoverageEncoding> {
    let parts = frame.parts.as_ref().filter(|p| p.step > 0.0)?;
    let whole = if parts.saturates {
        1.0 / parts.step
    } else {
        1.0 / parts.step + 1.0
    };
    let bits = whole.log2().round() as u32;
    Some(CoverageEncoding {
        fraction: parts.saturates,
        bits,
    })
}

/// Probes the coverage encoding; `None` when the candidate does not
/// antialias (nothing is drawn then).
pub(super) fn probe_coverage(candidate: &dyn Rasterizer) -> Option<CoverageFinding> {
    if !candidate.capabilities().antialias {
        return None;
    }
    let s = scene();
    let finding = |encoding, words: String, declared| {
        Some(CoverageFinding {
            encoding,
            words,
            declared,
        })
    };
    let frame = match draw(candidate, &s) {
        Ok(f) => f,
        Err(RasterError::Unsupported(why)) => {
            return finding(None, format!("not measured: unsupported: {why}"), None)
        }
        Err(e) => return finding(None, format!("not measured: {e}"), None),
    };
    let pixels = s.canvas.pixel_count();
    if frame.samples > 0 {
        return finding(
            None,
            format!(
                "a sample method ({} samples a pixel): its coverage steps by 1/{} of its samples, with no encoding to declare",
                frame.samples, frame.samples
            ),
            None,
        );
    }
    let Some(resolved) = frame.resolved.as_ref().filter(|r| r.len() == pixels) else {
        return finding(
            None,
            "not measured: its frame carries neither samples nor resolved coverage".to_owned(),
            None,
        );
    };
    let declared = declared(&frame);
    // Every pixel holds one primitive's fraction: the two lie apart.
    let mut whole = Vec::new();
    let mut partial = Vec::new();
    for index in 0..s.primitives.len() {
        for (pixel, area) in primitive_pixel_areas(&s, index) {
            let value = resolved[pixel as usize];
            if area == dashu_ratio::RBig::ONE {
                whole.push(value);
            } else {
                partial.push(value);
            }
        }
    }
    partial.retain(|&v| v != 0.0 && v != 1.0);
    let mut distinct = partial.clone();
    distinct.sort_by(f64::total_cmp);
    distinct.dedup();
    if distinct.len() < ENOUGH {
        return finding(
            None,
            format!(
                "not measured: only {} distinct fractions strictly between 0 and 1 on {MEASURED_ON}",
                distinct.len()
            ),
            declared,
        );
    }
    let n = distinct.len();
    let fitting = (1..=MAX_BITS).find_map(|k| {
        let whole = 2f64.powi(k as i32);
        if fits(&distinct, whole) {
            Some((true, k))
        } else if fits(&distinct, whole - 1.0) {
            Some((false, k))
        } else {
            None
        }
    });
    let Some((fraction, k)) = fitting else {
        return finding(
            None,
            format!(
                "not quantized: its {n} distinct partial fractions are multiples of no 1/(2^k − 1) or 1/2^k for k ≤ {MAX_BITS} (measured on {MEASURED_ON})"
            ),
            declared,
        );
    };
    let encoding = CoverageEncoding { fraction, bits: k };
    let top = 1.0 - encoding.step();
    let at_top = whole.iter().filter(|&&v| v == top).count();
    let at_one = whole.iter().filter(|&&v| v == 1.0).count();
    let seen = format!(
        "its {n} distinct partial fractions are multiples of 1/{}, and of its {} whole pixels {at_one} are 1 and {at_top} are {}/{}",
        if fraction { 1u64 << k } else { (1u64 << k) - 1 },
        whole.len(),
        (1u64 << k) - 1,
        if fraction { 1u64 << k } else { (1u64 << k) - 1 },
    );
    match (
        fraction,
        at_top == whole.len() && !whole.is_empty(),
        at_one == whole.len(),
    ) {
        (true, true, _) => finding(
            Some(encoding),
            format!(
                "{}: area × {} capped at {}; {seen} (measured on {MEASURED_ON})",
                encoding.words(),
                1u64 << k,
                (1u64 << k) - 1
            ),
            declared,
        ),
        (false, _, true) => finding(
            Some(encoding),
            format!("{}: {seen} (measured on {MEASURED_ON})", encoding.words()),
            declared,
        ),
        _ => finding(
            None,
            format!("no encoding SPEC.md §12.9 names: {seen} (measured on {MEASURED_ON})"),
            declared,
        ),
    }
}

/// A declared encoding against the one measured: "declares 8-bit unorm
/// (…); measured 8-bit fraction (…)", ending "(agrees)" when they agree.
pub(super) fn against_declared(found: &CoverageFinding) -> Option<String> {
    let declared = found.declared?;
    let measured = found.encoding?;
    let verdict = if declared == measured {
        " (agrees)"
    } else {
        ""
    };
    Some(format!(
        "declares coverage as {}; measured {}{verdict}",
        declared.words(),
        measured.words()
    ))
}
