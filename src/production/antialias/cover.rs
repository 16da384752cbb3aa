//! The samples a set-up triangle covers, handed to a sink: every sample
//! tested, or pixels and 8 × 8 blocks settled from their corners first.
//!
//! Every sample is decided like a pixel centre: the integer edge functions
//! with the tie bias folded in, evaluated at the sample's exact fixed-point
//! position. The offsets are integers once the format has at least
//! `position_bits` fraction bits ([`Format::with_samples`]), so a sample's
//! edge value is the pixel centre's plus a per-sample constant, and nothing
//! on a decision path is a float.
//!
//! Adaptive sampling classifies each pixel from its closed square's four
//! corners first. Edge functions are linear, so over the square they are
//! extreme at the corners: strictly positive at all four means every
//! sample is strictly inside that edge, whatever the tie rule; strictly
//! negative at all four means every sample is strictly outside. Only the
//! remaining pixels, which an edge touches, are tested sample by sample,
//! and the mask is the same as full supersampling's. The same test on an
//! 8 × 8 block's square first ([`BLOCK`]) settles whole blocks without
//! looking at their pixels. Covered
//! pixels still have every sample written (depth and attributes are per
//! sample), so the cost of the tests grows with the edge pixels, that of
//! the writes with the area. A non-strict
//! classification would not be: a sample on an edge through a corner is
//! decided by the tie rule, not by the corners (the test
//! `non_strict_corners_are_caught` shows it).
//!
//! What this file does not do: polygons (their fill decides its own
//! samples, `polygon::draw`), and `midpoint`, `diamond-exit` or `rectangle`
//! lines, which an antialiased case may not hold.

use super::sampling::Sampling;
use crate::production::fixed::{EdgeInt, Format};
use crate::production::setup::TriangleSetup;

/// Side of a square block of pixels settled from its corners, in pixels.
pub const BLOCK: i64 = 8;

/// Where one pixel stands against one edge, judged from its closed square.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Class {
    /// Every sample covered.
    Inside,
    /// No sample covered.
    Outside,
    /// Test each sample.
    Edge,
}

/// `|v|` for an edge integer.
#[inline]
pub(crate) fn abs<E: EdgeInt>(v: E) -> E {
    v.max(E::default() - v)
}

/// A covered sample as [`cover`] hands it over: its edge values are
/// computed only when asked for.
#[derive(Clone, Copy, Debug)]
pub struct At<E> {
    centre: [E; 3],
    delta: [E; 3],
    bias: [E; 3],
}

impl<E: EdgeInt> At<E> {
    /// The three exact edge values at the sample with the tie bias removed
    /// (what interpolation weighs).
    #[inline]
    pub fn values(&self) -> [E; 3] {
        [0, 1, 2].map(|k| self.centre[k] + self.delta[k] - self.bias[k])
    }
}

/// Receives the covered samples of a primitive, like [`crate::production::traverse::Sink`]
/// receives covered pixels.
pub trait SampleSink<E: EdgeInt> {
    /// Sample `s` of pixel (x, y) is covered; `at` gives the edge values
    /// there.
    fn sample(&mut self, x: i64, y: i64, s: usize, at: At<E>);

    /// Every sample of pixel (x, y) is covered; `at(s)` gives sample s's
    /// edge values. A sink that needs no values can fill the pixel's run of
    /// slots at once.
    fn whole(&mut self, x: i64, y: i64, samples: usize, at: impl Fn(usize) -> At<E>) {
        for s in 0..samples {
            self.sample(x, y, s, at(s));
        }
    }
}

/// Hands `sink` every sample `s` of pixel (x, y) that the triangle covers,
/// over its footprint, row by row. `offsets` are the samples' offsets from
/// the pixel's top-left corner in the setup's format, `format`.
pub fn cover<E: EdgeInt, S: SampleSink<E>>(
    setup: &TriangleSetup<E>,
    format: Format,
    offsets: &[[i64; 2]],
    sampling: Sampling,
    sink: &mut S,
) {
    let zero = E::default();
    let half = format.one() / 2;
    let edges = &setup.edges;
    // What each sample adds to the edge values at the pixel centre.
    let deltas: Vec<[E; 3]> = offsets
        .iter()
        .map(|o| {
            edges.map(|e| {
                e.per_unit[0] * E::from(o[0] - half) + e.per_unit[1] * E::from(o[1] - half)
            })
        })
        .collect();
    // Over the closed square the edge value lies within ± spread of the
    // centre's: half a pixel along each axis, the sign taken at the worst
    // corner.
    let spread = edges.map(|e| (abs(e.per_unit[0]) + abs(e.per_unit[1])) * E::from(half));
    let bias = edges.map(|e| e.bias);
    let n = offsets.len();
    // Refine's first samples: a quarter of them, at least one, spread
    // through the pattern.
    let quarter = (n / 4).max(1);
    let first: Vec<usize> = (0..quarter).map(|i| i * n / quarter).collect();

    let covered = |centre: &[E; 3], s: usize| {
        let d = &deltas[s];
        ((centre[0] + d[0]) | (centre[1] + d[1]) | (centre[2] + d[2])) >= zero
    };

    // Adaptive sampling classifies, strictly (or, to be caught, not).
    let classifying = match sampling {
        Sampling::Full | Sampling::Refine => None,
        Sampling::Adaptive => Some(true),
        #[cfg(test)]
        Sampling::NonStrictCorners => Some(false),
    };
    let at = |centre: [E; 3], s: usize| At {
        centre,
        delta: deltas[s],
        bias,
    };
    // One pixel, its centre's biased edge values given.
    let pixel = |sink: &mut S, x: i64, y: i64, centre: [E; 3]| {
        let class = match classifying {
            Some(strict) => classify(&centre, &bias, spread.map(|v| zero - v), spread, strict),
            None => Class::Edge,
        };
        let agreed = match (class, sampling) {
            (Class::Outside, _) => Some(false),
            (Class::Inside, _) => Some(true),
            (Class::Edge, Sampling::Refine) => {
                let answer = covered(&centre, first[0]);
                first
                    .iter()
                    .all(|&s| covered(&centre, s) == answer)
                    .then_some(answer)
            }
            (Class::Edge, _) => None,
        };
        match agreed {
            Some(false) => {}
            Some(true) => sink.whole(x, y, n, |s| at(centre, s)),
            None => {
                for s in 0..n {
                    if covered(&centre, s) {
                        sink.sample(x, y, s, at(centre, s));
                    }
                }
            }
        }
    };

    // Blocks of pixels, classified first from their own closed squares
    // when sampling is adaptive: over a block of w × h pixels the edge
    // values lie within its first centre's, plus the steps to its far
    // pixels, plus one pixel's spread.
    let b = setup.bounds;
    let mut by = b.y0;
    while by < b.y1 {
        let bh = BLOCK.min(b.y1 - by);
        let mut bx = b.x0;
        while bx < b.x1 {
            let bw = BLOCK.min(b.x1 - bx);
            let class = match classifying {
                Some(strict) => {
                    let first_centre = edges.map(|e| e.at(bx, by));
                    let reach = |k: usize, pick: fn(E, E) -> E| {
                        let e = &edges[k];
                        pick(zero, e.step_x * E::from(bw - 1))
                            + pick(zero, e.step_y * E::from(bh - 1))
                    };
                    let low = [0, 1, 2].map(|k| reach(k, E::min) - spread[k]);
                    let high = [0, 1, 2].map(|k| reach(k, E::max) + spread[k]);
                    classify(&first_centre, &bias, low, high, strict)
                }
                None => Class::Edge,
            };
            if class != Class::Outside {
                for y in by..by + bh {
                    let mut centre = edges.map(|e| e.at(bx, y));
                    for x in bx..bx + bw {
                        if class == Class::Inside {
                            sink.whole(x, y, n, |s| at(centre, s));
                        } else {
                            pixel(sink, x, y, centre);
                        }
                        for (value, e) in centre.iter_mut().zip(edges) {
                            *value = *value + e.step_x;
                        }
                    }
                }
            }
            bx += BLOCK;
        }
        by += BLOCK;
    }
}

/// Classifies a closed square from the biased edge values at a pixel
/// centre: the raw value (bias removed) over the square lies within
/// [raw + low, raw + high]. `strict` is the correct test; the non-strict
/// one exists to be caught by the tests.
#[inline]
pub(crate) fn classify<E: EdgeInt>(
    centre: &[E; 3],
    bias: &[E; 3],
    low: [E; 3],
    high: [E; 3],
    strict: bool,
) -> Class {
    let zero = E::default();
    let mut inside = true;
    for k in 0..3 {
        let raw = centre[k] - bias[k];
        let (low, high) = (raw + low[k], raw + high[k]);
        if high < zero || (!strict && high == zero) {
            return Class::Outside;
        }
        inside &= low > zero || (!strict && low == zero);
    }
    if inside {
        Class::Inside
    } else {
        Class::Edge
    }
}
