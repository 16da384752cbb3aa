//! Traversal: each pixel row of the bounding box as one span, from the
//! exact crossings of its three edges with the row.
//!
//! An edge's value along a row is `c + x·step_x`, with the tie bias folded
//! in, so the row's samples inside it are an interval: `x ≥ ⌈-c/step_x⌉`
//! for an edge that rises to the right (a left edge), `x ≤ ⌊c/-step_x⌋` for
//! one that falls (a right edge), every sample or none for a horizontal
//! one. The span is the intersection of the three, clipped to the box.
//!
//! The crossings are stepped from row to row in integers, as Bresenham
//! steps a line: each edge keeps its crossing `x` and the value `v` of its
//! function there, `0 ≤ v < |step_x|` (the value at the first sample inside
//! a left edge, or at the last inside a right edge). A row down adds
//! `step_y` to `v`: a whole quotient of `|step_x|`, precomputed, moves `x`,
//! and the remainder at most one more pixel. One division per edge per
//! triangle, none per row, and the same integers, the same decisions, as
//! testing every pixel: the test `spans_are_the_pixels_inside` compares
//! the two.
//!
//! Covered pixels reach a [`Sink`] a span at a time, so a frame's buffers
//! are filled a run at a time.

use super::fixed::EdgeInt;
use super::setup::{EdgeEquation, TriangleSetup};

/// Receives covered pixels as horizontal runs, like tiny-skia's `Blitter`.
pub trait Sink {
    /// Pixels `x0..x1` of row `y` are covered.
    fn span(&mut self, y: i64, x0: i64, x1: i64);

    /// Row `y`'s span, somewhere in `x0..x1`, will be asked for soon: a
    /// sink that writes memory may fetch it ahead ([`prefetch`]).
    #[inline]
    fn ahead(&mut self, _y: i64, _x0: i64, _x1: i64) {}
}

/// Rows fetched ahead of the one being written: enough misses in flight to
/// hide the memory's latency behind a small triangle's few rows.
const AHEAD: i64 = 8;

/// Asks the processor to bring the cache lines of `items` at its start and
/// end into the cache, without waiting for them. Small triangles scattered
/// over a large frame touch a new line on every row, and a count is read
/// before it is written: without this, each row waits for memory in turn.
#[inline]
pub fn prefetch<T>(items: &[T]) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        if let (Some(first), Some(last)) = (items.first(), items.last()) {
            // SAFETY: SSE, which `_mm_prefetch` needs, is part of every
            // x86_64 processor; a prefetch is a hint that reads nothing and
            // cannot fault, and both pointers point into `items` anyway.
            unsafe {
                _mm_prefetch::<_MM_HINT_T0>((first as *const T).cast());
                _mm_prefetch::<_MM_HINT_T0>((last as *const T).cast());
            }
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = items;
}

/// A slanted edge's crossing with the current row: the row's samples
/// inside it are `x ≥ at` for a left edge, `x ≤ at` for a right one, and
/// `value`, in `[0, run)`, is the edge's value at `at`.
#[derive(Clone, Copy, Debug)]
struct Crossing<E> {
    at: E,
    value: E,
    /// `|step_x|`.
    run: E,
    /// What a row down moves `at` by before the remainder's carry: `step_y`
    /// in whole runs, times -1 for a left edge (whose crossing moves the
    /// other way); and the carry's own move, -1 or 1.
    whole: E,
    carry: E,
    /// `step_y`'s remainder, in `[0, run)`.
    rest: E,
}

impl<E: EdgeInt> Crossing<E> {
    /// A slanted edge's crossing with row `y`.
    fn at_row(edge: &EdgeEquation<E>, y: i64) -> Crossing<E> {
        let zero = E::default();
        let c = edge.at(0, y);
        let left = edge.step_x > zero;
        let run = if left {
            edge.step_x
        } else {
            zero - edge.step_x
        };
        let (q, value) = c.div_rem_euclid(run);
        let (whole, rest) = edge.step_y.div_rem_euclid(run);
        // Left: c + x·run ≥ 0 from x = -⌊c/run⌋ on, where the value is
        // c mod run. Right: c - x·run ≥ 0 up to x = ⌊c/run⌋.
        let toward = E::from(if left { -1 } else { 1 });
        Crossing {
            at: toward * q,
            value,
            run,
            whole: toward * whole,
            carry: toward,
            rest,
        }
    }

    /// Moves to the next row down: value + step_y = value + rest +
    /// whole·run, so the whole runs move the crossing by as many pixels,
    /// and what is left, in [0, 2·run), by at most one more. Branch-free:
    /// whether the remainder carries is as likely as not.
    #[inline]
    fn next_row(&mut self) {
        let value = self.value + self.rest;
        let over = E::from(i64::from(value >= self.run));
        self.value = value - over * self.run;
        self.at = self.at + self.whole + over * self.carry;
    }
}

/// The rows `y0..y1` inside a horizontal edge (`step_x` = 0): its value,
/// `c + y·step_y`, is ≥ 0 from a row on (`step_y` > 0), up to one
/// (`step_y` < 0), or on every row or none (`step_y` = 0, a degenerate
/// edge).
fn level_rows<E: EdgeInt>(edge: &EdgeEquation<E>, y0: i64, y1: i64) -> (i64, i64) {
    let zero = E::default();
    let c = edge.at(0, y0);
    let step = edge.step_y;
    // Rows counted from y0; at most y1 - y0, so the bounds fit in i64.
    let rows = E::from(y1 - y0);
    let clamp = |k: E| k.max(zero).min(rows).to_i64();
    if step > zero {
        // c + k·step ≥ 0 from k = ⌈-c/step⌉ = -⌊c/step⌋ on.
        let (q, _) = c.div_rem_euclid(step);
        (y0 + clamp(zero - q), y1)
    } else if step < zero {
        // c - k·|step| ≥ 0 up to k = ⌊c/|step|⌋.
        let (q, _) = c.div_rem_euclid(zero - step);
        (y0, y0 + clamp(q + E::from(1)))
    } else if c >= zero {
        (y0, y1)
    } else {
        (y0, y0)
    }
}

/// Calls `sink` with the covered span of every row of the triangle's
/// bounding box that has one.
pub fn traverse<E: EdgeInt, S: Sink>(setup: &TriangleSetup<E>, sink: &mut S) {
    if let Some(mut walker) = Walker::new(setup, setup.bounds.y0) {
        walker.walk(i64::MAX, sink);
    }
}

/// A triangle's traversal that can stop at a row and go on later from it:
/// `sweep.rs` walks many triangles a band of rows at a time.
#[derive(Clone, Debug)]
pub struct Walker<E> {
    /// The slanted edges' crossings with row `y`.
    crossings: [Option<Crossing<E>>; 3],
    /// The next row to walk, and the end of the rows with samples inside.
    y: i64,
    y1: i64,
    /// The bounding box's columns.
    x0: i64,
    x1: i64,
}

impl<E: EdgeInt> Walker<E> {
    /// The traversal of `setup` from row `from` on (or its box's first row,
    /// if later); `None` when no row is left.
    pub fn new(setup: &TriangleSetup<E>, from: i64) -> Option<Walker<E>> {
        let bounds = setup.bounds;
        if bounds.is_empty() {
            return None;
        }
        let zero = E::default();
        // Horizontal edges only narrow the rows; the others are stepped.
        let (mut y0, mut y1) = (bounds.y0.max(from), bounds.y1);
        if y0 >= y1 {
            return None;
        }
        let mut slanted = [None; 3];
        for (slot, edge) in slanted.iter_mut().zip(&setup.edges) {
            if edge.step_x == zero {
                let (first, end) = level_rows(edge, y0, y1);
                y0 = y0.max(first);
                y1 = y1.min(end);
            } else {
                *slot = Some(edge);
            }
        }
        if y0 >= y1 {
            return None;
        }
        Some(Walker {
            crossings: slanted.map(|edge| edge.map(|e| Crossing::at_row(e, y0))),
            y: y0,
            y1,
            x0: bounds.x0,
            x1: bounds.x1,
        })
    }

    /// Whether every row has been walked.
    pub fn done(&self) -> bool {
        self.y >= self.y1
    }

    /// Walks the rows before `until` (and before the triangle's end),
    /// giving `sink` each row's span.
    #[inline]
    pub fn walk<S: Sink>(&mut self, until: i64, sink: &mut S) {
        let end = self.y1.min(until);
        let zero = E::default();
        for y in self.y..end.min(self.y + AHEAD) {
            sink.ahead(y, self.x0, self.x1);
        }
        let (x0, x1) = (E::from(self.x0), E::from(self.x1));
        for y in self.y..end {
            if y + AHEAD < end {
                sink.ahead(y + AHEAD, self.x0, self.x1);
            }
            let (mut from, mut to) = (x0, x1);
            for crossing in self.crossings.iter_mut().flatten() {
                if crossing.carry < zero {
                    from = from.max(crossing.at);
                } else {
                    to = to.min(crossing.at + E::from(1));
                }
                crossing.next_row();
            }
            if from < to {
                sink.span(y, from.to_i64(), to.to_i64());
            }
        }
        self.y = self.y.max(end);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::production::fixed::{Fixed, Format};
    use crate::production::setup;
    use crate::scene::{Canvas, Cull, FillRule, Interpolation, Triangle, Vertex};

    /// Every pixel of the box tested on its own, the way traversal used to.
    fn pixels_inside<E: EdgeInt>(s: &TriangleSetup<E>) -> Vec<(i64, i64)> {
        let b = s.bounds;
        let mut out = Vec::new();
        for y in b.y0..b.y1 {
            for x in b.x0..b.x1 {
                if s.edges.iter().all(|e| e.at(x, y) >= E::default()) {
                    out.push((x, y));
                }
            }
        }
        out
    }

    struct Collect(Vec<(i64, i64)>);

    impl Sink for Collect {
        fn span(&mut self, y: i64, x0: i64, x1: i64) {
            assert!(x0 < x1, "an empty span");
            self.0.extend((x0..x1).map(|x| (x, y)));
        }
    }

    fn check<E: EdgeInt>(units: [[i64; 2]; 3], bits: u32, rule: FillRule) -> usize {
        let format = Format::snapped(bits);
        let positions = units.map(|[x, y]| [Fixed(x), Fixed(y)]);
        let triangle = Triangle {
            vertices: [0, 1, 2]
                .map(|_| Vertex::at(crate::scene::Number::ZERO, crate::scene::Number::ZERO)),
            interpolation: Interpolation::Linear,
        };
        let canvas = Canvas {
            width: 40,
            height: 40,
        };
        let plan = crate::plan::Plan::coverage_only();
        let Some(s) = setup::setup::<E>(
            positions,
            &triangle,
            format,
            rule,
            Cull::None,
            canvas,
            &plan,
        ) else {
            return 0;
        };
        let mut spans = Collect(Vec::new());
        traverse(&s, &mut spans);
        let mut got = spans.0;
        got.sort_by_key(|&(x, y)| (y, x));
        let want = pixels_inside(&s);
        assert_eq!(got, want, "{units:?} at {bits} bits, {rule:?}");
        // Started below the box's top and walked three rows at a time, as
        // a sweep resumes it band by band: the same pixels of those rows.
        let from = s.bounds.y0 + (s.bounds.y1 - s.bounds.y0) / 3;
        let mut pieces = Collect(Vec::new());
        if let Some(mut walker) = Walker::new(&s, from) {
            let mut until = from;
            while !walker.done() {
                until += 3;
                walker.walk(until, &mut pieces);
            }
        }
        let mut got = pieces.0;
        got.sort_by_key(|&(x, y)| (y, x));
        let below: Vec<_> = want.iter().copied().filter(|&(_, y)| y >= from).collect();
        assert_eq!(got, below, "{units:?} from row {from}, in pieces");
        want.len()
    }

    #[test]
    fn spans_are_the_pixels_inside() {
        // Vertices on a coarse grid (2 subpixel bits, so many samples lie
        // on edges) and a fine one, off and on the canvas, every rule.
        // SplitMix64, so that production's tests import nothing above it.
        let mut state = 0x7370_616e_u64;
        let mut below = |n: i64| {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            ((z ^ (z >> 31)) % n as u64) as i64
        };
        let rules = [
            FillRule::TopLeft,
            FillRule::BottomRight,
            FillRule::TopRight,
            FillRule::BottomLeft,
            FillRule::AllEdges,
        ];
        let mut covered = 0;
        for round in 0..4000 {
            let bits = if round % 2 == 0 { 2 } else { 8 };
            let one = 1i64 << (bits + 1);
            let reach = if round % 3 == 0 { 60 } else { 44 };
            // Multiples of 2 units: the snapping grid, one bit coarser
            // than the format.
            let mut coordinate = || 2 * below(reach * one / 2) - 10 * one;
            let units = [0, 1, 2].map(|_| [coordinate(), coordinate()]);
            let rule = rules[round % rules.len()];
            covered += check::<i64>(units, bits, rule);
            check::<i128>(units, bits, rule);
        }
        assert!(
            covered > 100_000,
            "the triangles covered too little: {covered}"
        );
        // Horizontal and vertical edges through pixel centres.
        let one = 8;
        let half = 4;
        for rule in rules {
            let square = [
                [half, half],
                [10 * one + half, half],
                [half, 10 * one + half],
            ];
            check::<i64>(square, 2, rule);
            let flipped = [
                [10 * one + half, 10 * one + half],
                [10 * one + half, half],
                [half, 10 * one + half],
            ];
            check::<i64>(flipped, 2, rule);
        }
    }
}
