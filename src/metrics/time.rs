//! Time-coverage metrics (SPEC.md §15.4): each pixel's time coverage
//! against the exact value the reference computes.
//!
//! A frame of a scene in which something moves holds one value per pixel
//! and no sample slots, so this is the whole judgement of such a scene:
//!
//! - the **error** of a pixel, candidate − exact: its largest magnitude
//!   (and where), its RMS over **moving pixels** (exact value not a whole
//!   number, or candidate ≠ exact) and over all pixels, and its bias (mean
//!   signed error) over moving pixels;
//! - values that are not a finite number ≥ 0, wrong whatever the bounds;
//! - the **sample test efficiency** a sample method reports (covered tests
//!   over all tests): reported, never judged.
//!
//! Like the antialiasing errors, the errors are measurements in f64 from
//! the reference's value (the exact time coverage rounded once), not
//! decisions. Which exact values are whole numbers is known exactly when
//! the oracle's certified values are at hand (`whole`, from the suite);
//! otherwise it is read from the rounded value.
//!
//! Not here: the case's pins on the oracle (`expect.time_coverage`), which
//! are checked once per case in exact rationals by the suite.

use serde::ser::{SerializeStruct, Serializer};
use serde::Serialize;

use super::counted::counted;
use super::error_bounds::{within, ErrorBounds};
use crate::frame::{Frame, SampleTests};
use crate::scene::Scene;

/// The default bound on the RMS error over moving pixels with M spatial
/// and N time samples: 0.75·(M·N)^-1/2 (SPEC.md §15.4). M·N independent
/// uniform instants estimate a coverage c with a standard deviation of
/// √(c(1 − c)/(M·N)), at most 0.5·(M·N)^-1/2 and about 0.39·(M·N)^-1/2 on
/// average over c; the bound is about twice the latter, so that an honest
/// sampler passes and one that wastes or misplaces its instants does not.
pub fn default_rms_bound(spatial: u32, time: u32) -> f64 {
    0.75 / (f64::from(spatial.max(1)) * f64::from(time.max(1))).sqrt()
}

/// The bounds of a moving scene: `expect.max_time_error` (none by
/// default) and `expect.max_time_rms`, by default [`default_rms_bound`]
/// with M the antialiasing samples (1 without) and N the motion samples.
pub fn bounds(scene: &Scene) -> (Option<f64>, Option<f64>) {
    let spatial = scene.effects.antialias.as_ref().map_or(1, |a| a.samples);
    let time = scene.effects.motion_blur.as_ref().map_or(1, |m| m.samples);
    let rms = scene
        .expect
        .max_time_rms
        .unwrap_or_else(|| default_rms_bound(spatial, time));
    (scene.expect.max_time_error, Some(rms))
}

/// Also `report.json`'s `metrics.time` (SPEC.md §10): the fields not
/// skipped, in this order, the sample tests and the bounds only when there
/// are some.
#[derive(Clone, Debug, PartialEq, Serialize, serde::Deserialize)]
pub struct TimeMetrics {
    pub pixels: u64,
    /// Pixels whose exact time coverage is not a whole number, or whose
    /// candidate value differs from it.
    pub moving_pixels: u64,
    /// Largest |candidate − exact|; infinite where a value is not a number.
    pub max_error: f64,
    /// The pixel (x, y) where it occurs (the first such pixel), and the
    /// two values there.
    pub worst_pixel: [u32; 2],
    pub worst_candidate: f64,
    pub worst_exact: f64,
    /// RMS of candidate − exact over moving pixels; 0 without any.
    pub rms_moving: f64,
    /// RMS over all pixels.
    pub rms_all: f64,
    /// Mean signed error over moving pixels: negative when the candidate
    /// under-covers (as one that misses part of the shutter does).
    pub bias_moving: f64,
    /// Pixels whose value is not a number, infinite or negative, and the
    /// first of them.
    pub invalid_values: u64,
    #[serde(skip)]
    pub first_invalid: Option<[u32; 2]>,
    /// Pixels of nonzero time coverage in the reference and the candidate
    /// (reported only: a sampler may rightly miss a fast sliver whole).
    pub reference_pixels: u64,
    pub candidate_pixels: u64,
    /// What the candidate spent on its time loop, when it counts it.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "serialize_sample_tests",
        deserialize_with = "deserialize_sample_tests"
    )]
    pub sample_tests: Option<SampleTests>,
    /// The bounds this case holds the candidate to.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub allowed_error: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub allowed_rms: Option<f64>,
}

impl TimeMetrics {
    pub fn max_error_within_bound(&self) -> bool {
        within(self.max_error, self.allowed_error)
    }

    pub fn rms_within_bound(&self) -> bool {
        within(self.rms_moving, self.allowed_rms)
    }

    /// Covered sample tests over all sample tests, when the candidate
    /// counts them.
    pub fn efficiency(&self) -> Option<f64> {
        self.sample_tests.map(|t| t.efficiency())
    }
}

/// A method's sample tests as `report.json` writes them: `tests`,
/// `covered`, and `efficiency` (covered / tests, the cost measure of
/// stochastic rasterization).
fn serialize_sample_tests<S: Serializer>(
    tests: &Option<SampleTests>,
    s: S,
) -> Result<S::Ok, S::Error> {
    let t = tests.expect("skipped when there are none");
    let mut entry = s.serialize_struct("SampleTests", 3)?;
    entry.serialize_field("tests", &t.tests)?;
    entry.serialize_field("covered", &t.covered)?;
    entry.serialize_field("efficiency", &t.efficiency())?;
    entry.end()
}

/// `metrics.time.sample_tests` read back from a `report.json` (its
/// `efficiency` is derived, and ignored).
fn deserialize_sample_tests<'de, D: serde::Deserializer<'de>>(
    d: D,
) -> Result<Option<SampleTests>, D::Error> {
    #[derive(serde::Deserialize)]
    struct Counts {
        tests: u64,
        covered: u64,
    }
    let counts: Option<Counts> = serde::Deserialize::deserialize(d)?;
    Ok(counts.map(|c| SampleTests {
        tests: c.tests,
        covered: c.covered,
    }))
}

/// The signed error per pixel, candidate − reference time coverage (a NaN
/// error is infinite); empty when either frame has no time coverage or
/// they differ in size.
pub fn signed_errors(reference: &Frame, candidate: &Frame) -> Vec<f64> {
    super::difference::signed_differences(reference.time.as_deref(), candidate.time.as_deref())
}

/// Measures a candidate of a moving scene; `None` when either frame has no
/// time coverage, or they differ in size. `whole[p]` says whether pixel p's
/// exact time coverage is a whole number, when that is known exactly.
pub fn measure(
    reference: &Frame,
    candidate: &Frame,
    whole: Option<&[bool]>,
    bounds: (Option<f64>, Option<f64>),
) -> Option<TimeMetrics> {
    let (exact, time) = (reference.time.as_ref()?, candidate.time.as_ref()?);
    let n = reference.pixel_count();
    if exact.len() != n || time.len() != n || whole.is_some_and(|w| w.len() != n) {
        return None;
    }
    let width = reference.width.max(1) as usize;
    let at = |p: usize| [(p % width) as u32, (p / width) as u32];
    let mut m = TimeMetrics {
        pixels: n as u64,
        moving_pixels: 0,
        max_error: 0.0,
        worst_pixel: [0, 0],
        worst_candidate: time.first().copied().unwrap_or(0.0),
        worst_exact: exact.first().copied().unwrap_or(0.0),
        rms_moving: 0.0,
        rms_all: 0.0,
        bias_moving: 0.0,
        invalid_values: 0,
        first_invalid: None,
        reference_pixels: 0,
        candidate_pixels: 0,
        sample_tests: candidate.sample_tests,
        allowed_error: bounds.0,
        allowed_rms: bounds.1,
    };
    let (mut sum_sq_moving, mut sum_sq_all, mut sum_moving) = (0f64, 0f64, 0f64);
    let errors = signed_errors(reference, candidate);
    for p in 0..n {
        let (e, c, error) = (exact[p], time[p], errors[p]);
        let is_whole = whole.map_or(e.fract() == 0.0, |w| w[p]);
        if error.abs() > m.max_error {
            m.max_error = error.abs();
            (m.worst_pixel, m.worst_candidate, m.worst_exact) = (at(p), c, e);
        }
        sum_sq_all += error * error;
        if !is_whole || c != e {
            m.moving_pixels += 1;
            sum_sq_moving += error * error;
            sum_moving += error;
        }
        if !c.is_finite() || c < 0.0 {
            m.invalid_values += 1;
            m.first_invalid.get_or_insert(at(p));
        }
        m.reference_pixels += u64::from(e != 0.0);
        m.candidate_pixels += u64::from(c != 0.0);
    }
    if m.moving_pixels > 0 {
        m.rms_moving = (sum_sq_moving / m.moving_pixels as f64).sqrt();
        m.bias_moving = sum_moving / m.moving_pixels as f64;
    }
    if n > 0 {
        m.rms_all = (sum_sq_all / n as f64).sqrt();
    }
    Some(m)
}

/// Why the time metrics fail a case; empty when they pass. Each message
/// names the worst pixel, so that it can be found on the pictures.
pub fn failures(m: &TimeMetrics) -> Vec<String> {
    let [x, y] = m.worst_pixel;
    let mut out = ErrorBounds {
        family: "time",
        quantity: "time-coverage",
        max_error: m.max_error,
        worst: format!(
            "pixel ({x}, {y}): candidate {:.6}, exact {:.6}",
            m.worst_candidate, m.worst_exact
        ),
        allowed_error: m.allowed_error,
        rms: m.rms_moving,
        bias: m.bias_moving,
        pixels: m.moving_pixels,
        kind: "moving",
        allowed_rms: m.allowed_rms,
        worst_in_rms: true,
    }
    .failures();
    if m.invalid_values > 0 {
        let [x, y] = m.first_invalid.unwrap_or([0, 0]);
        out.push(format!(
            "time: {} a time coverage that is not a finite number ≥ 0, first at ({x}, {y})",
            counted(m.invalid_values, "pixel has", "pixels have")
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Expect;

    fn frame(time: &[f64]) -> Frame {
        Frame::time_only(time.len() as u32, 1, time.to_vec())
    }

    #[test]
    fn default_bound_halves_with_four_times_the_samples() {
        assert_eq!(default_rms_bound(1, 1), 0.75);
        assert_eq!(default_rms_bound(1, 16), 0.1875);
        assert_eq!(default_rms_bound(4, 4), 0.1875);
        assert_eq!(default_rms_bound(4, 16), 0.09375);
        // An honest sampler's worst case, c = ½, is within it.
        assert!(0.5 / 16f64.sqrt() < default_rms_bound(1, 16));
    }

    #[test]
    fn errors_moving_pixels_and_bias() {
        // Pixel 0 empty, 1 full (a static primitive), 2 and 3 moving.
        let reference = frame(&[0.0, 1.0, 0.25, 0.5]);
        let candidate = frame(&[0.0, 1.0, 0.375, 0.375]);
        let m = measure(&reference, &candidate, None, (None, Some(0.2))).unwrap();
        assert_eq!((m.pixels, m.moving_pixels), (4, 2));
        assert_eq!((m.max_error, m.worst_pixel), (0.125, [2, 0]));
        assert_eq!((m.worst_candidate, m.worst_exact), (0.375, 0.25));
        assert_eq!((m.rms_moving, m.bias_moving), (0.125, 0.0));
        assert_eq!(m.rms_all, (2.0 * 0.125f64 * 0.125 / 4.0).sqrt());
        assert_eq!((m.reference_pixels, m.candidate_pixels), (3, 3));
        assert_eq!(m.efficiency(), None);
        assert!(failures(&m).is_empty(), "{:?}", failures(&m));

        // A full pixel drawn short counts as moving.
        let short = frame(&[0.0, 0.5, 0.25, 0.5]);
        let m = measure(&reference, &short, None, (None, None)).unwrap();
        assert_eq!((m.moving_pixels, m.bias_moving), (3, -0.5 / 3.0));
        assert_eq!(m.worst_pixel, [1, 0]);
    }

    #[test]
    fn bounds_fail_naming_the_worst_pixel() {
        let reference = frame(&[0.0, 0.25, 0.5]);
        let candidate = frame(&[0.0, 0.25, 0.0]);
        let m = measure(&reference, &candidate, None, (Some(0.4), Some(0.3))).unwrap();
        assert_eq!(m.rms_moving, 0.125f64.sqrt());
        let f = failures(&m);
        assert_eq!(f.len(), 2, "{f:?}");
        assert!(
            f[0].starts_with("time: max time-coverage error 5.000e-1 at pixel (2, 0)"),
            "{f:?}"
        );
        assert!(f[0].contains("candidate 0.000000, exact 0.500000"), "{f:?}");
        assert!(
            f[1].contains("over 2 moving pixels exceeds 3.000e-1"),
            "{f:?}"
        );
        // Within both bounds, it passes.
        let m = measure(&reference, &candidate, None, (Some(0.5), Some(0.36))).unwrap();
        assert!(failures(&m).is_empty(), "{:?}", failures(&m));
    }

    #[test]
    fn invalid_values_fail_whatever_the_bounds() {
        let reference = frame(&[0.5, 0.5, 0.5]);
        for bad in [f64::NAN, f64::INFINITY, -0.25] {
            let candidate = frame(&[0.5, bad, 0.5]);
            let m = measure(&reference, &candidate, None, (None, None)).unwrap();
            assert_eq!((m.invalid_values, m.first_invalid), (1, Some([1, 0])));
            let f = failures(&m);
            assert_eq!(f.len(), 1, "{f:?}");
            assert!(f[0].contains("not a finite number ≥ 0, first at (1, 0)"));
        }
        let nan = frame(&[0.5, f64::NAN, 0.5]);
        let m = measure(&reference, &nan, None, (None, Some(1.0))).unwrap();
        assert_eq!(m.max_error, f64::INFINITY);
        assert_eq!(failures(&m).len(), 2, "the RMS is infinite too");
    }

    #[test]
    fn exact_wholeness_decides_moving_pixels() {
        // 1 − 2^-60 rounds to 1.0: known not whole, it is a moving pixel.
        let reference = frame(&[1.0, 0.0]);
        let candidate = frame(&[1.0, 0.0]);
        let m = measure(&reference, &candidate, Some(&[false, true]), (None, None)).unwrap();
        assert_eq!(m.moving_pixels, 1);
        let m = measure(&reference, &candidate, None, (None, None)).unwrap();
        assert_eq!(m.moving_pixels, 0);
    }

    #[test]
    fn sample_tests_are_reported() {
        let reference = frame(&[0.5]);
        let mut candidate = frame(&[0.5]);
        candidate.sample_tests = Some(SampleTests {
            tests: 64,
            covered: 16,
        });
        let m = measure(&reference, &candidate, None, (None, None)).unwrap();
        assert_eq!(m.efficiency(), Some(0.25));
    }

    #[test]
    fn frames_without_time_are_not_measured() {
        let reference = frame(&[0.5, 0.5]);
        let resolved = Frame::resolved_only(2, 1, vec![0.5, 0.5]);
        assert!(measure(&reference, &resolved, None, (None, None)).is_none());
        assert!(measure(&frame(&[0.5]), &reference, None, (None, None)).is_none());
    }

    #[test]
    fn expectations_of_static_scenes_are_named() {
        let expect = Expect {
            watertight: true,
            max_coverage_rms: Some(0.1),
            max_time_rms: Some(0.1),
            ..Expect::default()
        };
        assert_eq!(
            expect.sample_expectations(),
            ["watertight", "max_coverage_rms"]
        );
        assert!(Expect::default().sample_expectations().is_empty());
    }

    #[test]
    fn the_invalid_value_reason_takes_the_number_of_its_count() {
        let reference = frame(&[0.0, 1.0, 0.25]);
        let one = measure(
            &reference,
            &frame(&[0.0, 1.0, f64::NAN]),
            None,
            (None, None),
        )
        .unwrap();
        assert_eq!(
            failures(&one),
            ["time: 1 pixel has a time coverage that is not a finite number ≥ 0, first at (2, 0)"]
        );
        let two = measure(
            &reference,
            &frame(&[-1.0, 1.0, f64::NAN]),
            None,
            (None, None),
        )
        .unwrap();
        assert_eq!(
            failures(&two),
            ["time: 2 pixels have a time coverage that is not a finite number ≥ 0, first at (0, 0)"]
        );
    }
}
