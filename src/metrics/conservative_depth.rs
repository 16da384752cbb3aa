//! The depth at conservatively drawn pixels judged (SPEC.md §19.9): each
//! drawn pixel's depth must lie in the allowed interval of one of its
//! possible last writers (`reference::conservative::depth_allowed`), and,
//! for a unorm format, on the format's grid. The largest excursion beyond
//! the nearest allowed interval is reported, and the first pixel outside
//! is named with its value and its intervals.
//!
//! Every comparison is exact: a depth is an f32 widened to f64 (or
//! production's f64), the intervals' ends are f64s that decide exactly.

use serde::{Deserialize, Serialize};

use super::depth::signed_distance;
use crate::frame::Frame;
use crate::reference::conservative::ConservativeDepth;
use crate::scene::depth::unorm_index;

/// The first drawn pixel whose depth lies outside what it allows.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DepthExcursion {
    pub pixel: [u32; 2],
    pub value: f64,
    /// The allowed intervals there, one per possible last writer.
    pub allowed: Vec<[f64; 2]>,
}

/// The depth measured at a conservative candidate's drawn pixels
/// (`report.json`'s `metrics.conservative.depth`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ConservativeDepthMetrics {
    /// The depth format judged under (`exact`, `unorm16`, …).
    pub format: String,
    /// Whether the frame gave depth at all.
    pub given: bool,
    /// Drawn pixels some primitive may draw, whose depth was judged.
    pub judged: u64,
    /// Of them, those whose depth lies outside every allowed interval.
    pub outside: u64,
    /// Of them, those off the unorm format's grid.
    pub off_grid: u64,
    /// The largest distance from a judged depth to the nearest allowed
    /// interval (0 when every one lies inside; infinite for NaN).
    pub largest_excursion: f64,
    pub first_outside: Option<DepthExcursion>,
}

/// Measures `frame`'s depth at its drawn pixels against `allowed`.
pub fn measure(allowed: &ConservativeDepth, frame: &Frame) -> ConservativeDepthMetrics {
    let mut m = ConservativeDepthMetrics {
        format: allowed.format.name().to_owned(),
        given: frame.depth.is_some() && !frame.coverage_only,
        judged: 0,
        outside: 0,
        off_grid: 0,
        largest_excursion: 0.0,
        first_outside: None,
    };
    let Some(depth) = frame.depth.as_ref().filter(|_| m.given) else {
        return m;
    };
    let width = allowed.width as usize;
    for (i, intervals) in allowed.allowed.iter().enumerate() {
        if frame.coverage[i] == 0 || intervals.is_empty() {
            continue;
        }
        m.judged += 1;
        let c = depth[i];
        let distance = if c.is_nan() {
            f64::INFINITY
        } else {
            intervals
                .iter()
                .map(|&interval| signed_distance(c, interval).abs())
                .fold(f64::INFINITY, f64::min)
        };
        let off_grid = allowed
            .format
            .unorm_bits()
            .is_some_and(|bits| unorm_index(c, bits).is_none());
        m.off_grid += u64::from(off_grid);
        if distance > 0.0 || off_grid {
            m.outside += u64::from(distance > 0.0);
            m.first_outside.get_or_insert_with(|| DepthExcursion {
                pixel: [(i % width) as u32, (i / width) as u32],
                value: c,
                allowed: intervals.clone(),
            });
        }
        m.largest_excursion = m.largest_excursion.max(distance);
    }
    m
}

/// The reasons the depth fails, if it does.
pub fn failures(m: &ConservativeDepthMetrics) -> Vec<String> {
    if !m.given {
        return vec![
            "conservative depth: the case has depth and the frame gives none (SPEC.md §19.9)"
                .to_owned(),
        ];
    }
    let Some(first) = &m.first_outside else {
        return Vec::new();
    };
    let [x, y] = first.pixel;
    let intervals: Vec<String> = first
        .allowed
        .iter()
        .map(|[lo, hi]| format!("[{lo}, {hi}]"))
        .collect();
    let mut out = Vec::new();
    if m.outside > 0 {
        out.push(format!(
            "conservative depth: {} of {} drawn pixel(s) outside the depths {} allows there (SPEC.md §19.9), largest excursion {}; first ({x}, {y}): {} not in {}",
            m.outside,
            m.judged,
            m.format,
            m.largest_excursion,
            first.value,
            intervals.join(" or ")
        ));
    }
    if m.off_grid > 0 {
        out.push(format!(
            "conservative depth: {} drawn pixel(s) off the {} grid; first ({x}, {y}): {}",
            m.off_grid, m.format, first.value
        ));
    }
    out
}

/// One line for the console.
pub fn summary(m: &ConservativeDepthMetrics) -> String {
    format!(
        "depth ({}): {} of {} drawn pixels outside, largest excursion {}",
        m.format, m.outside, m.judged, m.largest_excursion
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::depth::DepthFormat;

    fn allowed(format: DepthFormat, intervals: Vec<Vec<[f64; 2]>>) -> ConservativeDepth {
        let n = intervals.len();
        ConservativeDepth {
            width: n as u32,
            format,
            allowed: intervals,
            value: vec![0.0; n],
        }
    }

    fn frame(depth: Vec<f64>) -> Frame {
        let mut f = Frame::new(depth.len() as u32, 1, true, 0);
        for i in 0..depth.len() {
            f.hit(i, 0);
        }
        f.depth = Some(depth);
        f
    }

    #[test]
    fn inside_any_writer_passes_and_beyond_all_fails_with_the_distance() {
        let a = allowed(
            DepthFormat::Exact,
            vec![vec![[0.0, 0.25], [0.5, 0.75]], vec![[0.0, 1.0]], vec![]],
        );
        let m = measure(&a, &frame(vec![0.6, 0.5, 9.0]));
        assert_eq!((m.judged, m.outside), (2, 0));
        assert!(failures(&m).is_empty());
        let m = measure(&a, &frame(vec![0.375, 0.5, 0.0]));
        assert_eq!((m.outside, m.largest_excursion), (1, 0.125));
        let why = failures(&m).join("");
        assert!(
            why.contains("first (0, 0): 0.375 not in [0, 0.25] or [0.5, 0.75]"),
            "{why}"
        );
    }

    #[test]
    fn off_the_unorm_grid_fails() {
        let a = allowed(DepthFormat::Unorm16, vec![vec![[0.0, 1.0]]]);
        let m = measure(&a, &frame(vec![0.3]));
        assert_eq!((m.outside, m.off_grid), (0, 1));
        assert_eq!(failures(&m).len(), 1);
        let m = measure(&a, &frame(vec![f64::NAN]));
        assert_eq!(m.outside, 1);
    }
}
