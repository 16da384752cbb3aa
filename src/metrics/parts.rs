//! Per-primitive coverage (SPEC.md §14.3): an area method that gives each
//! primitive's covered fraction of each pixel (an external program's
//! `coverage` answer, §12.9) is judged primitive by primitive against the
//! exact area of that primitive in that pixel, not only on their sum.
//!
//! Why: an 8-bit library rounds each primitive's coverage before it adds
//! them, so two triangles that share an edge through a pixel give, say,
//! 77/255 + 179/255 = 256/255 where the exact areas sum to 1. Judged on the
//! sum alone, such a library fails piglit's full-pixel rule for a rounding
//! it declared; and a library that moves coverage from one primitive to its
//! neighbour passes, since the sum hides it. So, per primitive:
//!
//! - where the primitive's exact area is 1 its fraction must be exactly 1,
//!   and where it is 0 exactly 0 (piglit's rule, primitive by primitive);
//! - elsewhere |fraction − area| must be at most the declared quantization
//!   step (a k-bit method claims the exact area as a multiple of
//!   1/(2^k − 1); one step allows rounding either way, and 10^-9 more the
//!   program's float arithmetic), or, where no
//!   quantization is declared, at most the default step 2^-8 (`area.rs`);
//! - the sum is then held to piglit's rule within the sum of the steps of
//!   the primitives that partly cover the pixel ([`PartCheck::slack`]): the
//!   error their roundings can add up to, and no more.
//!
//! Which areas are 0 or 1 is decided on the exact rationals; the errors are
//! measured in f64 against the areas rounded once (measurements, not
//! decisions).

use dashu_ratio::RBig;
use serde::Serialize;

use crate::frame::Parts;
use crate::reference::area::to_f64_nearest;

pub use super::area::FLOAT_SLACK;
use super::area::{self, AreasSeen};

/// What the per-primitive comparison found; `report.json`'s
/// `metrics.antialias.primitives` (SPEC.md §10.1).
#[derive(Clone, Debug, PartialEq, Serialize, serde::Deserialize)]
pub struct PartMetrics {
    /// (primitive, pixel) pairs where the exact area or the fraction given
    /// is not 0.
    pub judged: u64,
    /// Largest |fraction − exact area| over them.
    pub max_error: f64,
    /// [primitive index, x, y] where it occurs (the first such pair).
    pub worst: [u32; 3],
    /// The quantization step the rasterizer declares; 0 for none.
    pub step: f64,
    /// The bound on each pair's error: the declared step, else the default
    /// step 2^-8 (`area.rs`), and 10^-9; never none any more.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub allowed_error: Option<f64>,
    /// Pairs over that bound.
    pub over_bound: u64,
    /// Pairs whose exact area is 0 or 1 and whose fraction is not exactly
    /// that.
    pub exactness_violations: u64,
    /// The first such pair, [primitive, x, y].
    #[serde(skip)]
    pub first_violation: Option<[u32; 3]>,
}

/// [`PartMetrics`], and the slack the sum is allowed under piglit's rule.
pub struct PartCheck {
    pub metrics: PartMetrics,
    /// Per pixel: the sum of the declared steps of the primitives whose
    /// exact area there is strictly between 0 and 1.
    pub slack: Vec<f64>,
    /// Pairs whose exact area exceeds the bound (`area.rs`: an empty answer
    /// fails there), the largest exact area of a pair, and where.
    pub areas: AreasSeen,
}

/// Compares each primitive's fractions with its exact areas (`exact[p]`:
/// (pixel, area) for the pixels where primitive p's area is not 0, as
/// `reference::primitive_pixel_areas` gives them). Without a declared
/// step each pair is held to the default step (`area.rs`).
pub fn measure(parts: &Parts, exact: &[Vec<(u32, RBig)>], width: u32, pixels: usize) -> PartCheck {
    // One step, and 10^-9 for the program's own float arithmetic (an area
    // a hair below k/255 computed in doubles, truncated).
    let allowed = Some(area::allowed_error(parts));
    let mut m = PartMetrics {
        judged: 0,
        max_error: 0.0,
        worst: [0, 0, 0],
        step: parts.step,
        allowed_error: allowed,
        over_bound: 0,
        exactness_violations: 0,
        first_violation: None,
    };
    let mut slack = vec![0.0; pixels];
    let mut seen = AreasSeen::default();
    let width = width.max(1);
    for (p, (given, areas)) in parts.coverage.iter().zip(exact).enumerate() {
        for (pixel, fraction, area) in pairs(given, areas) {
            let at = [p as u32, pixel % width, pixel / width];
            m.judged += 1;
            let zero_or_one = area.as_ref().is_none_or(|a| *a == RBig::ONE);
            if zero_or_one {
                let want = if area.is_some() { 1.0 } else { 0.0 };
                // A saturating encoding's top code stands for a whole
                // pixel; the sum is then allowed the step it lacks.
                let capped = parts.saturates && area.is_some() && fraction == 1.0 - parts.step;
                if fraction != want && !capped {
                    m.exactness_violations += 1;
                    m.first_violation.get_or_insert(at);
                }
                if let Some(s) = slack.get_mut(pixel as usize).filter(|_| capped) {
                    *s += parts.step;
                }
            } else if let Some(s) = slack.get_mut(pixel as usize) {
                *s += parts.step;
            }
            let exact = area.as_ref().map_or(0.0, to_f64_nearest);
            seen.over_bound += u64::from(allowed.is_some_and(|b| exact > b));
            if exact > seen.largest {
                (seen.largest, seen.at) = (exact, at);
            }
            let error = (fraction - exact).abs();
            let error = if error.is_nan() { f64::INFINITY } else { error };
            if error > m.max_error {
                m.max_error = error;
                m.worst = at;
            }
            m.over_bound += u64::from(allowed.is_some_and(|b| error > b));
        }
    }
    PartCheck {
        metrics: m,
        slack,
        areas: seen,
    }
}

/// The pixels of one primitive where the fraction given or the exact area
/// is not 0, in pixel order: (pixel, fraction summed over the pixel's
/// entries, exact area or `None` for 0).
fn pairs(given: &[(u32, f64)], areas: &[(u32, RBig)]) -> Vec<(u32, f64, Option<RBig>)> {
    let mut given = given.to_vec();
    given.sort_by_key(|&(pixel, _)| pixel);
    let mut summed: Vec<(u32, f64)> = Vec::with_capacity(given.len());
    for (pixel, fraction) in given {
        match summed.last_mut() {
            Some((last, sum)) if *last == pixel => *sum += fraction,
            _ => summed.push((pixel, fraction)),
        }
    }
    let mut out = Vec::with_capacity(summed.len().max(areas.len()));
    let (mut i, mut j) = (0, 0);
    while i < summed.len() || j < areas.len() {
        let g = summed.get(i).map_or(u32::MAX, |e| e.0);
        let a = areas.get(j).map_or(u32::MAX, |e| e.0);
        if g < a {
            out.push((g, summed[i].1, None));
            i += 1;
        } else if a < g {
            out.push((a, 0.0, Some(areas[j].1.clone())));
            j += 1;
        } else {
            out.push((g, summed[i].1, Some(areas[j].1.clone())));
            i += 1;
            j += 1;
        }
    }
    // A fraction of 0 where the area is 0 says nothing.
    out.retain(|(_, f, a)| *f != 0.0 || a.is_some());
    out
}

/// Why the per-primitive comparison fails a case; empty when it passes.
pub fn failures(m: &PartMetrics) -> Vec<String> {
    let mut out = Vec::new();
    if m.exactness_violations > 0 {
        let [p, x, y] = m.first_violation.unwrap_or([0, 0, 0]);
        out.push(format!(
            "antialias: {} primitive-pixel coverages are not exactly 1 or 0 where the primitive covers the pixel fully or not at all (piglit's rule, per primitive), first primitive {p} at ({x}, {y})",
            m.exactness_violations
        ));
    }
    if let Some(bound) = m.allowed_error.filter(|_| m.over_bound > 0) {
        let [p, x, y] = m.worst;
        let whose = area::whose_step(m.step);
        out.push(format!(
            "antialias: {} primitive-pixel coverages are more than {bound:.3e} ({whose}) from the primitive's exact area; the largest, {:.3e}, is primitive {p}'s at ({x}, {y})",
            m.over_bound, m.max_error
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn third() -> RBig {
        RBig::from_parts(1.into(), 3u8.into())
    }

    /// Two primitives sharing pixel 0 (areas 1/3 and 2/3), the first also
    /// covering pixel 1 fully.
    fn exact() -> Vec<Vec<(u32, RBig)>> {
        vec![
            vec![(0, third()), (1, RBig::ONE)],
            vec![(0, &third() + &third())],
        ]
    }

    fn parts(a: f64, b: f64, full: f64, step: f64) -> Parts {
        Parts {
            saturates: false,
            coverage: vec![vec![(0, a), (1, full)], vec![(0, b)]],
            step,
        }
    }

    #[test]
    fn rounding_each_primitive_to_8_bits_passes_and_gives_the_sum_its_slack() {
        let step = 1.0 / 255.0;
        let c = measure(
            &parts(85.0 / 255.0, 170.0 / 255.0, 1.0, step),
            &exact(),
            2,
            2,
        );
        assert!(
            failures(&c.metrics).is_empty(),
            "{:?}",
            failures(&c.metrics)
        );
        assert_eq!(c.metrics.judged, 3);
        assert_eq!(c.slack, vec![2.0 * step, 0.0]);
    }

    #[test]
    fn coverage_moved_between_neighbours_is_caught_though_the_sum_is_right() {
        let step = 1.0 / 255.0;
        let c = measure(
            &parts(1.0 / 3.0 + 0.1, 2.0 / 3.0 - 0.1, 1.0, step),
            &exact(),
            2,
            2,
        );
        assert_eq!(c.metrics.over_bound, 2);
        assert_eq!(failures(&c.metrics).len(), 1);
        // Without a declared step the default step holds instead.
        let c = measure(
            &parts(1.0 / 3.0 + 0.1, 2.0 / 3.0 - 0.1, 1.0, 0.0),
            &exact(),
            2,
            2,
        );
        assert_eq!(c.metrics.over_bound, 2);
        assert_eq!(c.metrics.allowed_error, Some(1.0 / 256.0 + FLOAT_SLACK));
        assert!(failures(&c.metrics)[0].contains("default step 2^-8"));
    }

    #[test]
    fn a_full_or_empty_primitive_pixel_must_be_exact() {
        let step = 1.0 / 255.0;
        let c = measure(
            &parts(1.0 / 3.0, 2.0 / 3.0, 254.0 / 255.0, step),
            &exact(),
            2,
            2,
        );
        assert_eq!(c.metrics.exactness_violations, 1);
        assert_eq!(c.metrics.first_violation, Some([0, 1, 0]));
        // A fraction where the primitive does not reach, listed twice.
        let mut p = parts(1.0 / 3.0, 2.0 / 3.0, 1.0, step);
        p.coverage[1].extend([(1, 0.5 / 255.0), (1, 0.5 / 255.0)]);
        let c = measure(&p, &exact(), 2, 2);
        assert_eq!((c.metrics.exactness_violations, c.metrics.judged), (1, 4));
        assert_eq!(c.metrics.first_violation, Some([1, 1, 0]));
    }
}
