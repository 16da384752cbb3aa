//! A coverage-only scene of `midpoint` lines on a large canvas, drawn in
//! cache-sized bands of padded rows: each line a resumable [`Walker`] over
//! its pixels (the very pixels of `midpoint.rs`), the lines drawn in scene
//! order in each band, the band then added into the frame. The frame is
//! the one line-by-line drawing leaves. Lines with values, of other rules,
//! or antialiased are not drawn here.

use super::midpoint::midpoint_coverage;
use super::step::{major_range, Geometry, Slope};
use crate::frame::Frame;
use crate::production::fixed::Format;
use crate::scene::{Canvas, LastPixel};

/// How a [`Walker`] moves: along its row in runs (an x-major line, its
/// column stepped by `dir`), or down its column pixel by pixel (a y-major
/// line, its column moved by `dir` on a carry).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Walk {
    Row,
    Column,
}

/// One `midpoint` line's walk over its pixels on the canvas, resumable at
/// any row: its row never decreases along the walk, so a band of rows
/// takes a contiguous piece of it.
///
/// The pixels are [`midpoint`](super::midpoint::midpoint)'s: the minor
/// pixel at major coordinate m is ⌊R(m)/D⌋ with R(m) = N(m) − 1, a
/// function of m alone, so the walk may start at either end. An x-major line walks forward when its row rises
/// with x and backward from its last column otherwise; a y-major line
/// walks down. Either way the remainder of R mod D only grows, by `inc`
/// per major step (reflected, D − 1 − rest, for a y-major line whose column
/// falls), and the minor pixel moves by one on each carry.
#[derive(Clone, Copy, Debug)]
struct Walker {
    /// Index + 1 of the primitive, as `Frame::last` holds it.
    id: u32,
    walk: Walk,
    /// The column step: ±1.
    dir: i64,
    /// The current pixel's index, row · stride + column (rows padded to
    /// the band's stride).
    at: i64,
    row: i64,
    /// Pixels left to draw, the current one included.
    left: i64,
    /// Row walks: pixels left in the current row, the current one included.
    run: i64,
    /// Row walks: the remainder at the first pixel of the next row. Column
    /// walks: the current pixel's. In [0, D).
    rest: i64,
    inc: i64,
    den: i64,
    /// Row walks: D = q·inc + f. After a carry the remainder r lies in
    /// [0, inc), and the next row holds ⌈(D − r)/inc⌉ = q + [r < f]
    /// pixels, after which the remainder is r + [r < f]·inc − f: no
    /// division per row.
    q: i64,
    f: i64,
}

impl Walker {
    /// The walk of a `midpoint` line's pixels on the canvas (`g` not a
    /// point), or `None` when none is. The major range is clipped by [`major_range`] and the
    /// minor one exactly here (the minor pixel is monotone in m), so the
    /// walk never leaves the canvas.
    fn new(
        g: &Geometry,
        format: Format,
        last_pixel: LastPixel,
        canvas: Canvas,
        stride: i64,
        id: u32,
    ) -> Option<Walker> {
        let (u, v) = (g.major, 1 - g.major);
        let (first, end) = major_range(g, format, last_pixel, canvas);
        if first >= end {
            return None;
        }
        let minor_size = i64::from(if v == 0 { canvas.width } else { canvas.height });
        let Slope {
            a,
            b,
            den,
            step,
            numerator,
        } = Slope::new(g, format, first);
        let one = format.one();
        // R(first + k) = r0 + k·step; the pixel is on the canvas when
        // 0 ≤ R ≤ S·D − 1 (S the minor side). i128 as in `midpoint`.
        let r0 = numerator - 1;
        let (wide_den, wide_step) = (i128::from(den), i128::from(step));
        let (mut lo, mut hi) = (0, i128::from(end - first - 1));
        // The minor pixel is ⌈w⌉ − 1 for w between the ends' minor
        // coordinates: on the canvas throughout when both lie in (0, S].
        let inside = |w: i64| 0 < w && w <= minor_size * one;
        if !(inside(a[v]) && inside(b[v])) {
            let top = i128::from(minor_size) * wide_den - 1;
            let ceil = |n: i128, d: i128| -(-n).div_euclid(d);
            match step.signum() {
                1 => {
                    lo = lo.max(ceil(-r0, wide_step));
                    hi = hi.min((top - r0).div_euclid(wide_step));
                }
                -1 => {
                    lo = lo.max(ceil(r0 - top, -wide_step));
                    hi = hi.min(r0.div_euclid(-wide_step));
                }
                _ => {
                    if !(0..=top).contains(&r0) {
                        return None;
                    }
                }
            }
            if lo > hi {
                return None;
            }
        }
        let left = (hi - lo + 1) as i64;
        let backward = u == 0 && step < 0;
        let k = if backward { hi } else { lo };
        let r = r0 + k * wide_step;
        // On the canvas: the pixel below 2^14, the remainder below D.
        let minor = r.div_euclid(wide_den) as i64;
        let rest = (r - i128::from(minor) * wide_den) as i64;
        let major = first + k as i64;
        let inc = step.abs();
        let walker = Walker {
            id,
            walk: Walk::Column,
            dir: 1,
            at: major * stride + minor,
            row: major,
            left,
            run: 0,
            rest,
            inc,
            den,
            q: 0,
            f: 0,
        };
        if u == 1 {
            return Some(match step < 0 {
                true => Walker {
                    dir: -1,
                    rest: den - 1 - rest,
                    ..walker
                },
                false => walker,
            });
        }
        // The first row's pixels: ⌈(D − rest)/inc⌉, all of them when flat.
        let (run, q, f) = match inc {
            0 => (left, 0, 0),
            _ => ((den - rest + inc - 1) / inc, den / inc, den % inc),
        };
        Some(Walker {
            walk: Walk::Row,
            dir: if backward { -1 } else { 1 },
            at: minor * stride + major,
            row: minor,
            run,
            rest: rest + run * inc - den,
            q,
            f,
            ..walker
        })
    }

    /// Draws the walk's pixels in rows before `row_end` into `band`; true
    /// when the walk is done.
    #[inline]
    fn advance(&mut self, row_end: i64, stride: i64, band: &mut Band) -> bool {
        let (coverage, last) = (&mut band.coverage[..], &mut band.last[..]);
        match self.walk {
            Walk::Row => loop {
                let n = self.run.min(self.left);
                let from = if self.dir > 0 {
                    self.at
                } else {
                    self.at - n + 1
                };
                let from = (from - band.base) as usize;
                let to = from + n as usize;
                for c in &mut coverage[from..to] {
                    *c = c.saturating_add(1);
                }
                last[from..to].fill(self.id);
                self.left -= n;
                if self.left == 0 {
                    return true;
                }
                self.at += self.dir * n + stride;
                self.row += 1;
                let long = self.rest < self.f;
                self.run = self.q + i64::from(long);
                self.rest += if long { self.inc } else { 0 } - self.f;
                if self.row >= row_end {
                    return false;
                }
            },
            Walk::Column => {
                // Runs down a column are short but for steep lines: a
                // carry per pixel, without a branch, took 29 ms on the
                // bench's 2048² lines where column runs took 35.
                let n = self.left.min(row_end - self.row);
                let (mut at, mut rest) = (self.at - band.base, self.rest);
                for _ in 0..n {
                    let i = at as usize;
                    coverage[i] = coverage[i].saturating_add(1);
                    last[i] = self.id;
                    rest += self.inc;
                    let carry = rest >= self.den;
                    at += stride + if carry { self.dir } else { 0 };
                    rest -= if carry { self.den } else { 0 };
                }
                self.at = at + band.base;
                self.rest = rest;
                self.row += n;
                self.left -= n;
                self.left == 0
            }
        }
    }
}

/// Draws coverage-only `midpoint` lines, each `(index, geometry,
/// last_pixel)` in scene order, into `frame` band by band. Line by line,
/// the frame (6 bytes a pixel) is far beyond cache on large canvases, and
/// a steep line touches two new cache lines a pixel: memory traffic bounds
/// the loop. A band of rows ([`BAND_BYTES`]) stays in cache while every
/// line crossing it draws its piece.
///
/// Each line's [`Walker`] draws its pixels in rising rows, so each band
/// takes a contiguous piece of each walk, and the walks resume where they
/// stopped. In a band the lines draw in scene order, so every pixel (in
/// one band) is written in scene order: `last` ends as the line-by-line
/// loop leaves it, and `coverage` is a count. The frame equals
/// [`draw`](super::draw::draw)'s line by line, coverage only.
///
/// A frame of at most [`BANDED_FROM_BYTES`] is drawn line by line.
pub(crate) fn midpoint_lines(
    lines: &[(usize, Geometry, LastPixel)],
    format: Format,
    canvas: Canvas,
    frame: &mut Frame,
) {
    let pixels = i64::from(canvas.width) * i64::from(canvas.height);
    if pixels * BAND_BYTES_PER_PIXEL <= BANDED_FROM_BYTES {
        for (index, g, last_pixel) in lines {
            if !g.is_point() {
                midpoint_coverage(g, format, *last_pixel, canvas, *index, frame);
            }
        }
        return;
    }
    let row_bytes = band_stride(canvas.width) * BAND_BYTES_PER_PIXEL;
    let rows = (BAND_BYTES / row_bytes).max(1);
    midpoint_lines_in(lines, format, canvas, rows, frame);
}

/// [`midpoint_lines`] in bands of `band_rows` rows.
fn midpoint_lines_in(
    lines: &[(usize, Geometry, LastPixel)],
    format: Format,
    canvas: Canvas,
    band_rows: i64,
    frame: &mut Frame,
) {
    let width = i64::from(canvas.width);
    let height = i64::from(canvas.height);
    let stride = band_stride(canvas.width);
    // In scene order: a walker's position orders it as its id does.
    let mut walkers: Vec<Walker> = lines
        .iter()
        .filter(|(_, g, _)| !g.is_point())
        .filter_map(|&(index, ref g, last_pixel)| {
            Walker::new(g, format, last_pixel, canvas, stride, index as u32 + 1)
        })
        .collect();
    if walkers.is_empty() {
        return;
    }
    // Stable: in scene order within each band.
    let mut starting: Vec<u32> = (0..walkers.len() as u32).collect();
    starting.sort_by_key(|&p| walkers[p as usize].row / band_rows);
    let size = (stride * band_rows.min(height)) as usize;
    let mut band = Band {
        base: 0,
        coverage: vec![0; size],
        last: vec![0; size],
    };
    let mut active: Vec<u32> = Vec::new();
    let mut next: Vec<u32> = Vec::new();
    let mut new = starting.iter().copied().peekable();
    let mut band_start = 0;
    while band_start < height && (!active.is_empty() || new.peek().is_some()) {
        let band_end = (band_start + band_rows).min(height);
        band.base = band_start * stride;
        // Merge the lines starting in this band into the active ones, in
        // scene order, drawing each as it comes.
        let mut old = active.iter().copied().peekable();
        loop {
            let starts = new
                .peek()
                .filter(|&&p| walkers[p as usize].row < band_end)
                .copied();
            let p = match (old.peek(), starts) {
                (Some(&o), Some(n)) if n < o => new.next(),
                (Some(_), _) => old.next(),
                (None, Some(_)) => new.next(),
                (None, None) => break,
            }
            .expect("peeked");
            if !walkers[p as usize].advance(band_end, stride, &mut band) {
                next.push(p);
            }
        }
        active.clear();
        std::mem::swap(&mut active, &mut next);
        // Into the frame's rows, and the buffer cleared for the next band.
        // Added, not copied, so that the frame may already hold pixels.
        let w = width as usize;
        for row in 0..(band_end - band_start) as usize {
            let from = row * stride as usize;
            let to = (band_start as usize + row) * w;
            let counts = &mut band.coverage[from..from + w];
            for (f, b) in frame.coverage[to..to + w].iter_mut().zip(counts.iter()) {
                *f = f.saturating_add(*b);
            }
            counts.fill(0);
            let ids = &mut band.last[from..from + w];
            for (f, b) in frame.last[to..to + w].iter_mut().zip(ids.iter()) {
                *f = if *b == 0 { *f } else { *b };
            }
            ids.fill(0);
        }
        band_start = band_end;
    }
}

/// The bytes of one band of [`midpoint_lines`]: 63 rows of a 2048-px
/// canvas. Measured on the bench's lines (2048², 10,000 lines of
/// 1000–1400 px; 2 cores, 1 MiB L2): bands of 16 to 240 rows took within
/// 10% of each other, of 8 rows 25% more. Beyond the walks, each band
/// resumes every line crossing it and adds its rows to the frame, so
/// fewer, taller bands cost less.
const BAND_BYTES: i64 = 768 << 10;

/// The largest frame drawn line by line by [`midpoint_lines`]: bands pay
/// for a buffer, its merge into the frame and a resumption of every line
/// in every band, and win only once the frame is well beyond cache.
/// Measured (2 cores, 1 MiB L2, 32 MiB L3; lines of 0.5–0.7 canvas, 10,000
/// per 2048², banded against line by line): 256² 0.78×, 512² 0.89×, 724²
/// 0.95×, 1024² 1.96×, 1448² 1.38×, 2048² 3.47×.
const BANDED_FROM_BYTES: i64 = 4 << 20;

/// A band's bytes per pixel: a count (u16) and a last primitive (u32).
const BAND_BYTES_PER_PIXEL: i64 = 6;

/// A band of the frame's rows as [`Walker`]s write them: counts and last
/// primitives, rows `stride` apart, the first pixel of the band's first
/// row at index `base` of the walks.
struct Band {
    base: i64,
    coverage: Vec<u16>,
    last: Vec<u32>,
}

/// Pixels per row of a [`Band`]: the width rounded up to an odd multiple
/// of 32. Rows of a 2048-px frame are 4 KiB of counts apart, so a steep
/// line's successive pixels share their address's low 12 bits, and each
/// load waits on the store a row before it (4K aliasing) and falls in the
/// same L1 set; an odd multiple of 64 bytes puts successive rows in
/// different sets. Measured on the bench's 2048² lines in bands of 32
/// rows: 43 ms in the frame's own rows, 29 ms on rows padded by 24 px.
fn band_stride(width: u32) -> i64 {
    let stride = i64::from(width.div_ceil(32) * 32);
    if stride % 64 == 0 {
        stride + 32
    } else {
        stride
    }
}

#[cfg(test)]
mod tests {
    use super::super::draw::draw;
    use super::super::test_support::*;
    use super::*;
    use crate::plan::Plan;
    use crate::production::fixed::Fixed;
    use crate::scene::{FillRule, Line, LineRule, Number};

    /// A random segment for the banded test: anywhere around the canvas
    /// (often partly or wholly off it, now and then far away), in a random
    /// direction or one of the edge cases: flat, upright, diagonal, or one
    /// unit off each.
    fn banded_test_line(rng: &mut Rng, format: Format, canvas: Canvas) -> Geometry {
        let one = format.one();
        let (w, h) = (i64::from(canvas.width), i64::from(canvas.height));
        let far = rng.range(0, 15) == 0;
        let spread = |rng: &mut Rng, side: i64| {
            if far {
                rng.range(-32768 * one, 32768 * one)
            } else {
                rng.range(-side / 2 * one, (side + side / 2) * one)
            }
        };
        let v0 = [spread(rng, w), spread(rng, h)];
        let k = rng.range(1, 2 * w.max(h)) * one + rng.range(0, one - 1);
        let s = if rng.range(0, 1) == 0 { 1 } else { -1 };
        let t = if rng.range(0, 1) == 0 { 1 } else { -1 };
        let d = match rng.range(0, 9) {
            0 => [s * k, 0],
            1 => [0, t * k],
            2 => [s * k, t * k],
            3 => [s * k, t * (k - 1)],
            4 => [s * (k - 1), t * k],
            5 => [s * k, t],
            6 => [s, t * k],
            _ => {
                let v1 = [spread(rng, w), spread(rng, h)];
                [v1[0] - v0[0], v1[1] - v0[1]]
            }
        };
        let v1 = [v0[0] + d[0], v0[1] + d[1]];
        let clamp = |c: i64| c.clamp(-32768 * one, 32768 * one);
        Geometry::new([
            [Fixed(clamp(v0[0])), Fixed(clamp(v0[1]))],
            [Fixed(clamp(v1[0])), Fixed(clamp(v1[1]))],
        ])
    }

    #[test]
    fn banded_midpoint_lines_equal_line_by_line() {
        let mut rng = Rng(0x6261_6e64_6564);
        let plan = Plan::coverage_only();
        let line = test_line(LineRule::Midpoint, Number::ONE);
        // Heights that are not multiples of the band, bands of one row, and
        // (None) production's choice: line by line on the small canvas, six
        // bands (87 rows each but the last) on the large one.
        let canvas = |width, height| Canvas { width, height };
        let setups = [
            (canvas(23, 29), Some(1), 40),
            (canvas(31, 26), Some(3), 40),
            (canvas(17, 41), Some(4), 40),
            (canvas(40, 37), Some(8), 40),
            (canvas(9, 70), Some(5), 40),
            (canvas(70, 9), Some(2), 40),
            (canvas(45, 101), Some(32), 40),
            (canvas(45, 101), None, 20),
            (canvas(1500, 500), None, 4),
        ];
        let mut drawn = 0;
        for (canvas, band_rows, scenes) in setups {
            for frac_bits in [1, 2, 5, 9, 17] {
                let format = Format { frac_bits };
                for _ in 0..scenes {
                    let count = rng.range(1, 80) as usize;
                    let lines: Vec<(usize, Geometry, LastPixel)> = (0..count)
                        .map(|index| {
                            let last = if rng.range(0, 1) == 0 {
                                LastPixel::Include
                            } else {
                                LastPixel::Exclude
                            };
                            (index, banded_test_line(&mut rng, format, canvas), last)
                        })
                        .collect();
                    let mut expected = frame_for(canvas);
                    for (index, g, last) in &lines {
                        let line = Line {
                            last_pixel: *last,
                            ..line.clone()
                        };
                        let ends = [
                            [Fixed(g.v0[0]), Fixed(g.v0[1])],
                            [Fixed(g.v1[0]), Fixed(g.v1[1])],
                        ];
                        draw::<i64>(
                            &line,
                            ends,
                            format,
                            FillRule::TopLeft,
                            canvas,
                            &plan,
                            None,
                            *index,
                            crate::scene::ProvokingVertex::First,
                            &mut expected,
                        )
                        .unwrap();
                    }
                    let mut banded = frame_for(canvas);
                    match band_rows {
                        Some(rows) => midpoint_lines_in(&lines, format, canvas, rows, &mut banded),
                        None => midpoint_lines(&lines, format, canvas, &mut banded),
                    }
                    assert_eq!(
                        (&banded.coverage, &banded.last),
                        (&expected.coverage, &expected.last),
                        "{canvas:?}, bands of {band_rows:?}, {frac_bits} bits: {lines:?}"
                    );
                    drawn += expected.covered_samples();
                }
            }
        }
        assert!(drawn > 100_000, "the scenes drew too little: {drawn}");
    }
}
