//! Antialiasing metrics (SPEC.md §14.3): each pixel's resolved coverage
//! against the exact area the reference computes.
//!
//! The mask of a sample method is judged by the coverage comparison
//! (`coverage.rs`), sample by sample; this module judges what a picture
//! shows, the resolved value per pixel:
//!
//! - the **coverage error** of a pixel, resolved − exact area: its largest
//!   magnitude, its RMS over edge pixels and over all pixels, and its bias
//!   (mean signed error) over edge pixels;
//! - **piglit's rule**: a pixel whose exact area is 1 and whose every sample
//!   the reference covers exactly once must resolve to exactly 1, and one
//!   whose exact area is 0 and no sample covered to exactly 0, whatever the
//!   method (piglit's `ext_framebuffer_multisample` accuracy test);
//! - for a candidate with a mask, that its resolved value is its own mask's
//!   box resolve, or (every pixel of it) the exact area, as the reference's.
//!
//! The errors are computed in f64 from the reference's resolved value (the
//! exact area rounded once): they are measurements, not decisions. Which
//! pixels are full or empty is decided exactly when the exact areas are
//! known ([`AreaClass`], from `reference::exact_areas`); otherwise from the
//! rounded area, which is 0 or 1 exactly when the area is, except for an
//! area within 2^-54 of 1.

use serde::Serialize;

use super::area::{NothingDrawn, PixelAreas};
use super::counted::counted;
use super::error_bounds::{within, ErrorBounds};
use super::parts::PartMetrics;
use crate::frame::Frame;

/// What the exact area of a pixel is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AreaClass {
    /// Exactly 0.
    Empty,
    /// Exactly 1.
    Full,
    /// Anything else: strictly between 0 and 1, or above 1 where primitives
    /// overlap.
    Partial,
}

impl AreaClass {
    /// The class of a rounded area (see the module notes).
    pub fn of_rounded(area: f64) -> AreaClass {
        if area == 0.0 {
            AreaClass::Empty
        } else if area == 1.0 {
            AreaClass::Full
        } else {
            AreaClass::Partial
        }
    }
}

/// piglit's bound on the RMS coverage error of N-sample MSAA over edge
/// pixels: 0.333 · 0.62^log2(N) (piglit's MSAA accuracy test,
/// `tests/spec/ext_framebuffer_multisample/common.cpp`): 0.333 for 1
/// sample, 0.206 for 2, 0.128 for 4, 0.079 for 8, 0.049 for 16.
pub fn default_rms_bound(samples: u32) -> f64 {
    0.333 * 0.62f64.powf(f64::from(samples.max(1)).log2())
}

/// Also `report.json`'s `metrics.antialias` (SPEC.md §10): the fields not
/// skipped, in this order, the bounds only when there are some.
#[derive(Clone, Debug, PartialEq, Serialize, serde::Deserialize)]
pub struct AntialiasMetrics {
    /// The candidate's samples per pixel; 0 for an area method.
    pub samples: u32,
    pub pixels: u64,
    /// Pixels with an exact area strictly between 0 and 1, or a resolved
    /// value (candidate's or reference's) other than 0 and 1.
    pub edge_pixels: u64,
    /// Largest |resolved − exact area|.
    pub max_error: f64,
    /// The pixel (x, y) where it occurs (the first such pixel).
    pub worst_pixel: [u32; 2],
    /// RMS of resolved − exact area over edge pixels; 0 without any.
    pub rms_edge: f64,
    /// RMS over all pixels.
    pub rms_all: f64,
    /// Mean signed error over edge pixels: negative when the candidate
    /// under-covers edges.
    pub bias_edge: f64,
    /// Pixels piglit's rule holds to exactly 1 and to exactly 0.
    pub full_pixels: u64,
    pub empty_pixels: u64,
    /// Of those, the pixels the candidate does not resolve exactly.
    pub piglit_violations: u64,
    /// Of those, the pixels resolved within the slack of a declared
    /// quantization instead (`parts.rs`): not violations.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub piglit_within_quantization: u64,
    /// The first violation (x, y), when there is one.
    #[serde(skip)]
    pub first_violation: Option<[u32; 2]>,
    /// Pixels whose resolved value is not the box resolve of the
    /// candidate's own samples (always 0 without a mask).
    pub resolve_mismatches: u64,
    /// Pixels whose resolved value is not a number, infinite or negative:
    /// wrong whatever the bounds.
    pub invalid_values: u64,
    /// Pixels of nonzero resolved value in the reference and the candidate
    /// (reported only: a sample method may rightly miss a sliver whole).
    #[serde(skip)]
    pub reference_pixels: u64,
    #[serde(skip)]
    pub candidate_pixels: u64,
    /// The bounds this case holds the candidate to.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub allowed_error: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub allowed_rms: Option<f64>,
    /// An area method that gives each primitive's coverage: the
    /// per-primitive comparison (`parts.rs`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub primitives: Option<PartMetrics>,
    /// Such a method that drew nothing where some pixel's exact area
    /// exceeds one step (`area.rs`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nothing_drawn: Option<NothingDrawn>,
    /// An area method without coverage per primitive: each pixel's total
    /// against its exact area, within one step (`area.rs`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pixel_areas: Option<PixelAreas>,
}

fn is_zero(n: &u64) -> bool {
    *n == 0
}

impl AntialiasMetrics {
    pub fn max_error_within_bound(&self) -> bool {
        within(self.max_error, self.allowed_error)
    }

    pub fn rms_within_bound(&self) -> bool {
        within(self.rms_edge, self.allowed_rms)
    }
}

/// The bounds of a case: `expect.max_coverage_error` and
/// `expect.max_coverage_rms`, the latter by default piglit's for sample
/// methods (none for a frame without samples, `samples` = 0). An area
/// answer (`area::is_area_answer`) is held to none of them: it is held to
/// its exact area within one step, per primitive (`area.rs`, `parts.rs`).
pub fn bounds(
    max_coverage_error: Option<f64>,
    max_coverage_rms: Option<f64>,
    samples: u32,
    area_answer: bool,
) -> (Option<f64>, Option<f64>) {
    if area_answer {
        return (None, None);
    }
    let rms = max_coverage_rms.or((samples > 0).then(|| default_rms_bound(samples)));
    (max_coverage_error, rms)
}

/// The signed coverage error per pixel, candidate − reference resolved;
/// empty when either frame has no resolved coverage.
pub fn signed_errors(reference: &Frame, candidate: &Frame) -> Vec<f64> {
    super::difference::signed_differences(
        reference.resolved.as_deref(),
        candidate.resolved.as_deref(),
    )
}

/// Measures an antialiased candidate; `None` when either frame has no
/// resolved coverage, or they differ in size. `classes` gives each pixel's
/// exact area class when known.
pub fn measure(
    reference: &Frame,
    candidate: &Frame,
    classes: Option<&[AreaClass]>,
    bounds: (Option<f64>, Option<f64>),
) -> Option<AntialiasMetrics> {
    measure_with_slack(reference, candidate, classes, bounds, None)
}

/// [`measure`], with piglit's rule relaxed on each pixel by `slack[p]`:
/// the error the declared quantization of the primitives' coverages can
/// add up to there (`parts.rs`).
pub fn measure_with_slack(
    reference: &Frame,
    candidate: &Frame,
    classes: Option<&[AreaClass]>,
    bounds: (Option<f64>, Option<f64>),
    slack: Option<&[f64]>,
) -> Option<AntialiasMetrics> {
    let (exact, resolved) = (reference.resolved.as_ref()?, candidate.resolved.as_ref()?);
    let n = reference.pixel_count();
    if exact.len() != n
        || resolved.len() != n
        || classes.is_some_and(|c| c.len() != n)
        || slack.is_some_and(|s| s.len() != n)
    {
        return None;
    }
    let width = reference.width.max(1) as usize;
    let at = |p: usize| [(p % width) as u32, (p / width) as u32];
    let mask = candidate.samples > 0 && candidate.sample_count() == n * candidate.samples as usize;
    let own_resolve = mask.then(|| candidate.box_resolve());
    let ref_slots = reference.samples as usize;
    let mut m = AntialiasMetrics {
        samples: candidate.samples,
        pixels: n as u64,
        edge_pixels: 0,
        max_error: 0.0,
        worst_pixel: [0, 0],
        rms_edge: 0.0,
        rms_all: 0.0,
        bias_edge: 0.0,
        full_pixels: 0,
        empty_pixels: 0,
        piglit_violations: 0,
        piglit_within_quantization: 0,
        first_violation: None,
        resolve_mismatches: 0,
        invalid_values: 0,
        reference_pixels: 0,
        candidate_pixels: 0,
        allowed_error: bounds.0,
        allowed_rms: bounds.1,
        primitives: None,
        nothing_drawn: None,
        pixel_areas: None,
    };
    let (mut sum_sq_edge, mut sum_sq_all, mut sum_edge) = (0f64, 0f64, 0f64);
    let errors = signed_errors(reference, candidate);
    for p in 0..n {
        let (e, r, error) = (exact[p], resolved[p], errors[p]);
        let class = classes.map_or_else(|| AreaClass::of_rounded(e), |c| c[p]);
        let unit = |v: f64| v == 0.0 || v == 1.0;
        let edge = class == AreaClass::Partial || !unit(e) || !unit(r);
        if error.abs() > m.max_error {
            m.max_error = error.abs();
            m.worst_pixel = at(p);
        }
        sum_sq_all += error * error;
        if edge {
            m.edge_pixels += 1;
            sum_sq_edge += error * error;
            sum_edge += error;
        }
        m.invalid_values += u64::from(!r.is_finite() || r < 0.0);
        m.reference_pixels += u64::from(e != 0.0);
        m.candidate_pixels += u64::from(r != 0.0);
        let slots = &reference.coverage[p * ref_slots..(p + 1) * ref_slots];
        let rule = match class {
            AreaClass::Full if slots.iter().all(|&c| c == 1) => Some(1.0),
            AreaClass::Empty if slots.iter().all(|&c| c == 0) => Some(0.0),
            _ => None,
        };
        if let Some(want) = rule {
            if want == 1.0 {
                m.full_pixels += 1;
            } else {
                m.empty_pixels += 1;
            }
            let within = |s: &[f64]| (r - want).abs() <= s[p];
            if r != want && slack.is_some_and(within) {
                m.piglit_within_quantization += 1;
            } else if r != want {
                m.piglit_violations += 1;
                m.first_violation.get_or_insert(at(p));
            }
        }
        if let Some(own) = &own_resolve {
            m.resolve_mismatches += u64::from(own[p] != r);
        }
    }
    // A method may also resolve every pixel to its exact area, as the
    // reference does (SPEC.md §14.3): the whole frame, to the bit, never a
    // mix of the two.
    if m.resolve_mismatches > 0
        && resolved
            .iter()
            .zip(exact)
            .all(|(r, e)| r.to_bits() == e.to_bits())
    {
        m.resolve_mismatches = 0;
    }
    if m.edge_pixels > 0 {
        m.rms_edge = (sum_sq_edge / m.edge_pixels as f64).sqrt();
        m.bias_edge = sum_edge / m.edge_pixels as f64;
    }
    if n > 0 {
        m.rms_all = (sum_sq_all / n as f64).sqrt();
    }
    Some(m)
}

/// Why the antialiasing metrics fail a case; empty when they pass.
pub fn failures(m: &AntialiasMetrics) -> Vec<String> {
    let [x, y] = m.worst_pixel;
    let mut out = ErrorBounds {
        family: "antialias",
        quantity: "coverage",
        max_error: m.max_error,
        worst: format!("pixel ({x}, {y})"),
        allowed_error: m.allowed_error,
        rms: m.rms_edge,
        bias: m.bias_edge,
        pixels: m.edge_pixels,
        kind: "edge",
        allowed_rms: m.allowed_rms,
        worst_in_rms: false,
    }
    .failures();
    if m.piglit_violations > 0 {
        let [x, y] = m.first_violation.unwrap_or([0, 0]);
        out.push(format!(
            "antialias: {} to exactly 1 or 0 (piglit's rule), first at ({x}, {y})",
            counted(
                m.piglit_violations,
                "full or empty pixel does not resolve",
                "full or empty pixels do not resolve"
            )
        ));
    }
    if m.invalid_values > 0 {
        out.push(format!(
            "antialias: {} to a value that is not a finite number ≥ 0",
            counted(m.invalid_values, "pixel resolves", "pixels resolve")
        ));
    }
    if m.resolve_mismatches > 0 {
        out.push(format!(
            "antialias: {} to other than the box resolve of {} own samples",
            counted(m.resolve_mismatches, "pixel resolves", "pixels resolve"),
            if m.resolve_mismatches == 1 {
                "its"
            } else {
                "their"
            }
        ));
    }
    if let Some(nothing) = &m.nothing_drawn {
        out.push(super::area::failure(nothing));
    }
    if let Some(pixels) = &m.pixel_areas {
        out.extend(super::area::pixel_failures(pixels));
    }
    if let Some(parts) = &m.primitives {
        out.extend(super::parts::failures(parts));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(samples: u32, coverage: &[u16], resolved: &[f64]) -> Frame {
        let mut f = Frame::resolved_only(2, 1, resolved.to_vec());
        f.samples = samples;
        f.coverage = coverage.to_vec();
        f.last = coverage.iter().map(|&c| u32::from(c > 0)).collect();
        f
    }

    #[test]
    fn piglit_bound_halves_about_every_two_doublings() {
        assert_eq!(default_rms_bound(1), 0.333);
        assert!((default_rms_bound(4) - 0.333 * 0.62 * 0.62).abs() < 1e-15);
        assert!((default_rms_bound(16) - 0.04919).abs() < 1e-4);
    }

    #[test]
    fn errors_edges_and_piglit() {
        // Pixel 0 fully covered (2 of 2 samples), pixel 1 a quarter.
        let reference = frame(2, &[1, 1, 1, 0], &[1.0, 0.25]);
        let good = frame(2, &[1, 1, 1, 0], &[1.0, 0.5]);
        let m = measure(&reference, &good, None, (None, Some(0.3))).unwrap();
        assert_eq!((m.edge_pixels, m.full_pixels, m.empty_pixels), (1, 1, 0));
        assert_eq!((m.max_error, m.worst_pixel), (0.25, [1, 0]));
        assert_eq!(
            (m.rms_edge, m.bias_edge, m.piglit_violations),
            (0.25, 0.25, 0)
        );
        assert!(failures(&m).is_empty());

        let leaky = frame(2, &[1, 1, 1, 0], &[1.0 - 1.0 / 1048576.0, 0.5]);
        let m = measure(&reference, &leaky, None, (None, Some(0.3))).unwrap();
        assert_eq!((m.piglit_violations, m.resolve_mismatches), (1, 1));
        assert_eq!(failures(&m).len(), 2);

        let area_only = Frame::resolved_only(2, 1, vec![1.0, 0.0]);
        let m = measure(&reference, &area_only, None, (Some(0.2), None)).unwrap();
        assert_eq!((m.samples, m.resolve_mismatches), (0, 0));
        assert_eq!(failures(&m).len(), 1, "{:?}", failures(&m));

        let nan = Frame::resolved_only(2, 1, vec![1.0, f64::NAN]);
        let m = measure(&reference, &nan, None, (None, None)).unwrap();
        assert_eq!((m.invalid_values, m.max_error), (1, f64::INFINITY));
        assert_eq!(failures(&m).len(), 1, "{:?}", failures(&m));

        // Drawing nothing breaks piglit's rule on the full pixel. (Nothing
        // at all is not itself a failure: 16 samples may all miss a
        // sliver.)
        let nothing = Frame::resolved_only(2, 1, vec![0.0, 0.0]);
        let m = measure(&reference, &nothing, None, (None, None)).unwrap();
        assert_eq!((m.candidate_pixels, m.reference_pixels), (0, 2));
        assert!(failures(&m).iter().any(|f| f.contains("piglit")));
    }

    #[test]
    fn an_exact_area_resolve_is_a_resolve_but_only_for_the_whole_frame() {
        // Pixel 1's exact area is a third; its 2 samples resolve to a half.
        let reference = frame(2, &[1, 1, 1, 0], &[1.0, 1.0 / 3.0]);
        let exact = frame(2, &[1, 1, 1, 0], &[1.0, 1.0 / 3.0]);
        let m = measure(&reference, &exact, None, (None, None)).unwrap();
        assert_eq!(m.resolve_mismatches, 0);
        // Neither its box resolve nor the exact area: caught.
        let other = frame(2, &[1, 1, 1, 0], &[1.0, 0.25]);
        let m = measure(&reference, &other, None, (None, None)).unwrap();
        assert_eq!(m.resolve_mismatches, 1);
        // Exact on one pixel, neither on another: a mix is no resolve.
        let reference = frame(2, &[1, 0, 1, 0], &[0.3, 1.0 / 3.0]);
        let mixed = frame(2, &[1, 0, 1, 0], &[0.3, 0.25]);
        let m = measure(&reference, &mixed, None, (None, None)).unwrap();
        assert_eq!(m.resolve_mismatches, 2);
    }

    #[test]
    fn exact_classes_decide_full_pixels() {
        // An area just below 1 that rounds to 1.0: not held to piglit's rule.
        let reference = frame(2, &[1, 1, 0, 0], &[1.0, 0.0]);
        let candidate = frame(2, &[1, 1, 0, 0], &[0.5, 0.0]);
        let classes = [AreaClass::Partial, AreaClass::Empty];
        let m = measure(&reference, &candidate, Some(&classes), (None, None)).unwrap();
        assert_eq!(
            (m.piglit_violations, m.full_pixels, m.edge_pixels),
            (0, 0, 1)
        );
        let m = measure(&reference, &candidate, None, (None, None)).unwrap();
        assert_eq!(m.piglit_violations, 1);
    }

    #[test]
    fn pixel_count_reasons_take_the_number_of_their_counts() {
        let reference = frame(2, &[1, 1, 1, 0], &[1.0, 0.5]);
        let exact = measure(&reference, &reference, None, (None, None)).unwrap();
        let with = |n: u64| {
            let mut m = exact.clone();
            m.piglit_violations = n;
            m.invalid_values = n;
            m.resolve_mismatches = n;
            m.first_violation = Some([1, 0]);
            failures(&m)
        };
        assert_eq!(
            with(1),
            [
                "antialias: 1 full or empty pixel does not resolve to exactly 1 or 0 (piglit's rule), first at (1, 0)",
                "antialias: 1 pixel resolves to a value that is not a finite number ≥ 0",
                "antialias: 1 pixel resolves to other than the box resolve of its own samples",
            ]
        );
        assert_eq!(
            with(2),
            [
                "antialias: 2 full or empty pixels do not resolve to exactly 1 or 0 (piglit's rule), first at (1, 0)",
                "antialias: 2 pixels resolve to a value that is not a finite number ≥ 0",
                "antialias: 2 pixels resolve to other than the box resolve of their own samples",
            ]
        );
    }
}
