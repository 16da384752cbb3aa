//! Lines (SPEC.md §4): an incremental integer midpoint rasterizer, the
//! parallelogram (non-strict wide) line through the triangle path, and the
//! rectangle line tested exactly sample by sample on tight row spans.
//!
//! Every coverage decision is an integer comparison in the production
//! fixed-point format, one bit finer than the snapping grid so that pixel
//! centres are integers. Floats appear only in interpolation and, for the
//! rectangle, in choosing which candidate samples to test (with a margin
//! far wider than their error; every candidate is then decided exactly).
//! Values along a line are interpolated in f32 from the line parameter of
//! SPEC.md §5, never from triangle barycentrics. Antialiased, a
//! parallelogram line's two triangles are sampled like any triangle's
//! (`antialias::cover`), and its values are taken at each sample.

use super::antialias::{self, SampleSink, Samples};
use super::fixed::{EdgeInt, Fixed, Format, I64_MAX_FRAC_BITS, MAX_FRAC_BITS};
use super::setup::{self, Footprint};
use super::traverse::{self, Sink};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::rules::limits;
use crate::scene::{
    Canvas, Cull, FillRule, Interpolation, LastPixel, Line, LineParameter, LineRule, Number,
    Triangle, Vertex,
};

/// Bits of the largest coordinate difference along one axis, in pixels:
/// two vertices, or a vertex and a sample on the canvas, are at most 2^16 px
/// apart (|x|, |y| ≤ 2^15 px).
const DIFF_PX_BITS: u32 = limits::COORD_LIMIT.trailing_zeros() + 1;

// Midpoint: the first row needs y0·dx + (c − x0)·dy, at most
// 2·2^(2(DIFF_PX_BITS + f)) in magnitude: i128 at every format.
const _: () = assert!(2 * (DIFF_PX_BITS + MAX_FRAC_BITS) + 2 <= 127);
// Midpoint stepping: the remainder lies in [0, D) with D = |du|·one ≤
// 2^(DIFF_PX_BITS + 2f), and one step adds at most D: i64 at every format.
const _: () = assert!(DIFF_PX_BITS + 2 * MAX_FRAC_BITS + 2 <= 63);

// Parallelogram corners lie up to width/2 ≤ 2^9 px beyond the vertex range,
// so a difference of two corners, or of a corner and a sample on the canvas,
// stays below 2^(DIFF_PX_BITS + 1) px. An edge function, two products of such
// differences plus the tie bias, is then below 2^(2(DIFF_PX_BITS + 1 + f) + 1):
// that many bits of magnitude and one of sign. It fits i64 up to
// I64_MAX_FRAC_BITS (the integer the parallelogram picks with
// Format::fits_i64), and i128 at every format.
const fn corner_edge_bits(frac_bits: u32) -> u32 {
    2 * (DIFF_PX_BITS + 1 + frac_bits) + 2
}
const _: () = assert!(limits::MAX_LINE_WIDTH < 1 << DIFF_PX_BITS);
const _: () = assert!(corner_edge_bits(I64_MAX_FRAC_BITS) <= 64);
const _: () = assert!(corner_edge_bits(MAX_FRAC_BITS) <= 128);

/// Rectangle: the largest width denominator b (width = a/b in lowest terms)
/// for which the exact squared test is proven not to overflow. With
/// |q·d|, |q×d|, |d|² ≤ 2^(2(DIFF_PX_BITS + f) + 1) = 2^67 at f = 17,
/// X = 2|q×d|·b stays below 2^128, and Y = a·2^f (a ≤ 1024·b) has Y² below
/// 2^128; the products X² and Y²·|d|² are compared in 256 bits.
pub const MAX_WIDTH_DENOMINATOR_BITS: u32 = 36;
const RECT_CROSS_BITS: u32 = 2 * (DIFF_PX_BITS + MAX_FRAC_BITS) + 1;
const _: () = assert!(RECT_CROSS_BITS + 1 + MAX_WIDTH_DENOMINATOR_BITS <= 128);
const MAX_WIDTH_NUMERATOR_BITS: u32 =
    MAX_WIDTH_DENOMINATOR_BITS + (limits::MAX_LINE_WIDTH.trailing_zeros());
const _: () = assert!((limits::MAX_LINE_WIDTH as u64).is_power_of_two());
const _: () = assert!(2 * (MAX_WIDTH_NUMERATOR_BITS + MAX_FRAC_BITS) <= 128);

/// Pixels of slack around the rectangle's f64 row spans. The f64 span ends
/// are off by at most about 2^(f − 19) px (numerators below 2^(35 + 2f)
/// units² with a few roundings, divided by a direction component of at
/// least one unit), a quarter pixel at f = 17.
const RECT_MARGIN_PX: f64 = 2.0;

/// A line's snapped endpoints in fixed point, with its major axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Geometry {
    pub v0: [i64; 2],
    pub v1: [i64; 2],
    /// v1 − v0.
    pub d: [i64; 2],
    /// 0 for an x-major line (|dx| ≥ |dy|), 1 for a y-major one.
    pub major: usize,
}

impl Geometry {
    pub fn new(ends: [[Fixed; 2]; 2]) -> Geometry {
        let v0 = [ends[0][0].0, ends[0][1].0];
        let v1 = [ends[1][0].0, ends[1][1].0];
        let d = [v1[0] - v0[0], v1[1] - v0[1]];
        let major = if d[0].abs() >= d[1].abs() { 0 } else { 1 };
        Geometry { v0, v1, d, major }
    }

    pub fn is_point(&self) -> bool {
        self.d == [0, 0]
    }
}

/// The pixels along the major axis whose centres lie between the endpoints
/// (half-open at v1 for `last_pixel: exclude`), clipped to the canvas:
/// `first..end`.
pub(crate) fn major_range(
    g: &Geometry,
    format: Format,
    last_pixel: LastPixel,
    canvas: Canvas,
) -> (i64, i64) {
    let u = g.major;
    let (one, half) = (format.one(), format.one() / 2);
    let (lo, hi) = (g.v0[u].min(g.v1[u]), g.v0[u].max(g.v1[u]));
    // First centre ≥ lo: i·one + half ≥ lo. Last centre ≤ hi.
    let mut first = (lo - half + one - 1).div_euclid(one);
    let mut last = (hi - half).div_euclid(one);
    if last_pixel == LastPixel::Exclude && (g.v1[u] - half).rem_euclid(one) == 0 {
        // v1 sits exactly on a centre, at one end of the range.
        if g.v1[u] < g.v0[u] {
            first += 1;
        } else {
            last -= 1;
        }
    }
    let size = i64::from(if u == 0 { canvas.width } else { canvas.height });
    (first.max(0), (last + 1).min(size))
}

/// Calls `visit(x, y)` for each pixel of a `midpoint` line on the canvas.
///
/// Along the major axis u, the pixel is ⌈v(c)⌉ − 1 on the minor axis v,
/// with v(c) = a_v + (c − a_u)·dv/du measured in pixels: in units that is
/// ⌊(N − 1)/D⌋ with N = a_v·du + (c − a_u)·dv and D = du·one (du > 0). The
/// first is one exact i128 division; each next centre adds dv·one to N,
/// which moves the remainder by at most D, so one comparison steps it.
/// The walk starts from the endpoint with the smaller major coordinate,
/// and depends only on the segment's points: v1→v0 draws what v0→v1 does.
pub(crate) fn midpoint(
    g: &Geometry,
    format: Format,
    last_pixel: LastPixel,
    canvas: Canvas,
    mut visit: impl FnMut(i64, i64),
) {
    let (u, v) = (g.major, 1 - g.major);
    let (first, end) = major_range(g, format, last_pixel, canvas);
    if first >= end {
        return;
    }
    let minor_size = i64::from(if v == 0 { canvas.width } else { canvas.height });
    let (a, b) = if g.v0[u] < g.v1[u] {
        (g.v0, g.v1)
    } else {
        (g.v1, g.v0)
    };
    let du = b[u] - a[u];
    let dv = b[v] - a[v];
    let one = format.one();
    let denominator = du * one;
    let c = format.centre(first).0;
    let numerator = i128::from(a[v]) * i128::from(du) + i128::from(c - a[u]) * i128::from(dv) - 1;
    let wide_denominator = i128::from(denominator);
    // Bounded by the coordinate limits: the row is within 2^16 of the
    // canvas, the remainder below D.
    let mut minor = numerator.div_euclid(wide_denominator) as i64;
    let mut rest = numerator.rem_euclid(wide_denominator) as i64;
    let step = dv * one;
    for m in first..end {
        if (0..minor_size).contains(&minor) {
            if u == 0 {
                visit(m, minor);
            } else {
                visit(minor, m);
            }
        }
        rest += step;
        if rest >= denominator {
            rest -= denominator;
            minor += 1;
        } else if rest < 0 {
            rest += denominator;
            minor -= 1;
        }
    }
}

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
/// The pixels are [`midpoint`]'s: the minor pixel at major coordinate m is
/// ⌊R(m)/D⌋ with R(m) = N(m) − 1, a function of m alone, so the walk may
/// start at either end. An x-major line walks forward when its row rises
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
        let (a, b) = if g.v0[u] < g.v1[u] {
            (g.v0, g.v1)
        } else {
            (g.v1, g.v0)
        };
        let (du, dv) = (b[u] - a[u], b[v] - a[v]);
        let one = format.one();
        let den = du * one;
        let step = dv * one;
        // R(first + k) = r0 + k·step; the pixel is on the canvas when
        // 0 ≤ R ≤ S·D − 1 (S the minor side). i128 as in `midpoint`.
        let c = format.centre(first).0;
        let r0 = i128::from(a[v]) * i128::from(du) + i128::from(c - a[u]) * i128::from(dv) - 1;
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

/// Draws a coverage-only `midpoint` line as primitive `index`: each pixel
/// written in place, as `Frame::hit` does.
fn midpoint_coverage(
    g: &Geometry,
    format: Format,
    last_pixel: LastPixel,
    canvas: Canvas,
    index: usize,
    frame: &mut Frame,
) {
    let width = frame.width as usize;
    let id = index as u32 + 1;
    let (coverage, last) = (&mut frame.coverage, &mut frame.last);
    midpoint(g, format, last_pixel, canvas, |x, y| {
        let i = y as usize * width + x as usize;
        coverage[i] = coverage[i].saturating_add(1);
        last[i] = id;
    });
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
/// loop leaves it, and `coverage` is a count. The frame equals [`draw`]'s
/// line by line, coverage only.
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

// Diamond-exit: a candidate pixel is on the canvas (centre below 2^14 px)
// and each endpoint within 2^15 px of the origin, so an endpoint's offset
// from a centre is below 2^DIFF_PX_BITS px per axis, and its rotated
// coordinates (sum and difference of the two offsets) below
// 2^(DIFF_PX_BITS + 1) px; so are those of d (at most, as |dx|, |dy| ≤
// 2^DIFF_PX_BITS px). A bound on the segment parameter is a quotient of a
// rotated offset plus or minus half a pixel (below 2^(DIFF_PX_BITS + 2 + f)
// units) by a rotated component of d (at most 2^(DIFF_PX_BITS + 1 + f)), and
// two bounds are compared by cross-multiplying: below
// 2^(2(DIFF_PX_BITS + f) + 3), i128 at every format. The rotated values
// themselves, with their sign, fit i64.
const DIAMOND_ROTATED_BITS: u32 = DIFF_PX_BITS + 1 + MAX_FRAC_BITS;
const _: () = assert!(limits::MAX_CANVAS_SIDE <= 1 << (DIFF_PX_BITS - 2));
const _: () = assert!(2 * DIAMOND_ROTATED_BITS + 1 < 128);
const _: () = assert!(DIAMOND_ROTATED_BITS < 64);

/// A bound num/den (den > 0) on the segment parameter s, open when
/// `strict`.
#[derive(Clone, Copy, Debug)]
struct Bound {
    num: i128,
    den: i128,
    strict: bool,
}

impl Bound {
    fn cmp(&self, other: &Bound) -> std::cmp::Ordering {
        (self.num * other.den).cmp(&(other.num * self.den))
    }
}

/// The parameters s ∈ [0, 1] of the segment's points that satisfy some
/// slab constraints: an interval, open or closed at either end, or empty.
#[derive(Clone, Copy, Debug)]
struct Span {
    lo: Bound,
    hi: Bound,
    /// A constraint with a constant value failed.
    void: bool,
}

impl Span {
    const SEGMENT: Span = Span {
        lo: Bound {
            num: 0,
            den: 1,
            strict: false,
        },
        hi: Bound {
            num: 1,
            den: 1,
            strict: false,
        },
        void: false,
    };

    fn raise(&mut self, b: Bound) {
        match b.cmp(&self.lo) {
            std::cmp::Ordering::Greater => self.lo = b,
            std::cmp::Ordering::Equal => self.lo.strict |= b.strict,
            std::cmp::Ordering::Less => {}
        }
    }

    fn lower(&mut self, b: Bound) {
        match b.cmp(&self.hi) {
            std::cmp::Ordering::Less => self.hi = b,
            std::cmp::Ordering::Equal => self.hi.strict |= b.strict,
            std::cmp::Ordering::Greater => {}
        }
    }

    /// Keeps the s with `low` ◁ w0 + s·dw ◁ `high`, each ◁ being < when
    /// its flag says strict and ≤ otherwise.
    fn clip(
        &mut self,
        w0: i64,
        dw: i64,
        (low, low_strict): (i64, bool),
        (high, high_strict): (i64, bool),
    ) {
        let (w0, dw, low, high) = (
            i128::from(w0),
            i128::from(dw),
            i128::from(low),
            i128::from(high),
        );
        let holds = |a: i128, b: i128, strict: bool| if strict { a < b } else { a <= b };
        match dw.cmp(&0) {
            std::cmp::Ordering::Equal => {
                self.void |= !(holds(low, w0, low_strict) && holds(w0, high, high_strict));
            }
            std::cmp::Ordering::Greater => {
                self.raise(Bound {
                    num: low - w0,
                    den: dw,
                    strict: low_strict,
                });
                self.lower(Bound {
                    num: high - w0,
                    den: dw,
                    strict: high_strict,
                });
            }
            std::cmp::Ordering::Less => {
                // Dividing by dw < 0 turns w ≤ high into s ≥ (w0 − high)/−dw.
                self.raise(Bound {
                    num: w0 - high,
                    den: -dw,
                    strict: high_strict,
                });
                self.lower(Bound {
                    num: w0 - low,
                    den: -dw,
                    strict: low_strict,
                });
            }
        }
    }

    fn is_empty(&self) -> bool {
        self.void
            || match self.lo.cmp(&self.hi) {
                std::cmp::Ordering::Less => false,
                std::cmp::Ordering::Equal => self.lo.strict || self.hi.strict,
                std::cmp::Ordering::Greater => true,
            }
    }
}

/// SPEC.md §4.2's diamonds, seen in rotated coordinates a = u + v and
/// b = u − v around a pixel centre. The four borders become two slabs, and
/// the diamond a half-open square:
///
///   −h < a ≤ h  (−u − v < ½, u + v ≤ ½),
///   −h ≤ b < h  (−u + v ≤ ½, u − v < ½),
///
/// with h half a pixel, plus the corner a = b = h, the right corner
/// (½, 0), for a y-major line. The segment meets the square when the two
/// slabs' parameter intervals overlap inside [0, 1]; it passes the corner
/// when both rotated coordinates equal h at one parameter in [0, 1].
#[derive(Clone, Copy, Debug)]
struct DiamondExit {
    v0: [i64; 2],
    v1: [i64; 2],
    /// (dx + dy, dx − dy).
    d_rotated: [i64; 2],
    half: i64,
    y_major: bool,
}

impl DiamondExit {
    fn new(g: &Geometry, format: Format) -> DiamondExit {
        DiamondExit {
            v0: g.v0,
            v1: g.v1,
            d_rotated: [g.d[0] + g.d[1], g.d[0] - g.d[1]],
            half: format.one() / 2,
            y_major: g.major == 1,
        }
    }

    /// A point's rotated coordinates around the centre `c`.
    fn rotated(p: [i64; 2], c: [i64; 2]) -> [i64; 2] {
        let (u, v) = (p[0] - c[0], p[1] - c[1]);
        [u + v, u - v]
    }

    fn contains(&self, [a, b]: [i64; 2]) -> bool {
        let h = self.half;
        (-h < a && a <= h && -h <= b && b < h) || (self.y_major && a == h && b == h)
    }

    /// Whether the pixel with centre `c` is lit.
    fn lights(&self, c: [i64; 2]) -> bool {
        if self.contains(Self::rotated(self.v1, c)) {
            return false;
        }
        let [a0, b0] = Self::rotated(self.v0, c);
        let [da, db] = self.d_rotated;
        let h = self.half;
        let mut square = Span::SEGMENT;
        square.clip(a0, da, (-h, true), (h, false));
        square.clip(b0, db, (-h, false), (h, true));
        if !square.is_empty() {
            return true;
        }
        if !self.y_major {
            return false;
        }
        let mut corner = Span::SEGMENT;
        corner.clip(a0, da, (h, false), (h, false));
        corner.clip(b0, db, (h, false), (h, false));
        !corner.is_empty()
    }
}

/// Calls `visit(x, y)` for each pixel of a `diamond-exit` line on the
/// canvas (SPEC.md §4.2).
///
/// A diamond lies in its pixel's closed square, so only the columns (rows,
/// for y-major) whose closed extent meets the segment's are walked. In
/// column i, a point of the diamond is at most ½ − |v| from the centre
/// across and |v| down, and the line's slope is at most 1 in magnitude, so
/// the line's height y(c) at the centre's abscissa c is within ½ of the
/// centre's: the only candidates are rows ⌊y(c)⌋ and ⌊y(c)⌋ − 1 (the second
/// only when y(c) is an integer). ⌊y(c)⌋ is stepped as in [`midpoint`];
/// each candidate is then decided exactly by [`DiamondExit::lights`].
pub(crate) fn diamond_exit(
    g: &Geometry,
    format: Format,
    canvas: Canvas,
    mut visit: impl FnMut(i64, i64),
) {
    let (u, v) = (g.major, 1 - g.major);
    let one = format.one();
    let sizes = [i64::from(canvas.width), i64::from(canvas.height)];
    let (lo, hi) = (g.v0[u].min(g.v1[u]), g.v0[u].max(g.v1[u]));
    // Pixel m spans [m·one, (m + 1)·one] closed: from ⌈lo/one⌉ − 1 to ⌊hi/one⌋.
    let first = ((lo + one - 1).div_euclid(one) - 1).max(0);
    let end = (hi.div_euclid(one) + 1).min(sizes[u]);
    if first >= end {
        return;
    }
    let test = DiamondExit::new(g, format);
    let (a, b) = if g.v0[u] < g.v1[u] {
        (g.v0, g.v1)
    } else {
        (g.v1, g.v0)
    };
    let du = b[u] - a[u];
    let dv = b[v] - a[v];
    // y(c)/one = N/D with N = a_v·du + (c − a_u)·dv, D = du·one (du > 0).
    let denominator = du * one;
    let c = format.centre(first).0;
    let numerator = i128::from(a[v]) * i128::from(du) + i128::from(c - a[u]) * i128::from(dv);
    let wide_denominator = i128::from(denominator);
    // Bounded as in `midpoint`: the row is within 2^16 of the canvas, the
    // remainder below D.
    let mut minor = numerator.div_euclid(wide_denominator) as i64;
    let mut rest = numerator.rem_euclid(wide_denominator) as i64;
    let step = dv * one;
    for m in first..end {
        for n in [minor - 1, minor] {
            if !(0..sizes[v]).contains(&n) {
                continue;
            }
            let (x, y) = if u == 0 { (m, n) } else { (n, m) };
            if test.lights([format.centre(x).0, format.centre(y).0]) {
                visit(x, y);
            }
        }
        rest += step;
        if rest >= denominator {
            rest -= denominator;
            minor += 1;
        } else if rest < 0 {
            rest += denominator;
            minor -= 1;
        }
    }
}

/// Per-line values for f32 interpolation along the line parameter.
#[derive(Clone, Debug)]
pub(crate) struct LineShading {
    interpolation: Interpolation,
    parameter: LineParameter,
    v0: [i64; 2],
    d: [i64; 2],
    major: usize,
    /// 1 / |d_major| for `major`, 1 / |d|² for `projected`.
    inv_denominator: f64,
    depth: Option<[f32; 2]>,
    /// Per attribute: a/w at each end for perspective, a otherwise.
    attributes: Vec<[f32; 2]>,
    inv_w: [f32; 2],
}

impl LineShading {
    pub fn new(line: &Line, g: &Geometry, plan: &Plan) -> LineShading {
        let vs = &line.vertices;
        let inv_w = [0, 1].map(|i| 1.0 / vs[i].w.to_f64_lossy());
        let interpolation = line.interpolation;
        let attributes = (0..plan.attributes)
            .map(|k| {
                [0, 1].map(|i| {
                    let a = vs[i].attributes[k].to_f64_lossy();
                    let a = if interpolation == Interpolation::Perspective {
                        a * inv_w[i]
                    } else {
                        a
                    };
                    a as f32
                })
            })
            .collect();
        let denominator = match line.parameter {
            LineParameter::Major => g.d[g.major].abs() as f64,
            LineParameter::Projected => length2(g) as f64,
        };
        LineShading {
            interpolation,
            parameter: line.parameter,
            v0: g.v0,
            d: g.d,
            major: g.major,
            inv_denominator: 1.0 / denominator,
            depth: plan
                .depth
                .then(|| [0, 1].map(|i| vs[i].z.to_f64_lossy() as f32)),
            attributes,
            inv_w: inv_w.map(|w| w as f32),
        }
    }

    /// The weights (1 − t, t) of the ends at the sample `p` (fixed point),
    /// t clamped to [0, 1]. Each weight is its own exact integer over the
    /// exact denominator, rounded once, so neither loses precision near an
    /// end.
    pub fn weights(&self, p: [i64; 2]) -> [f32; 2] {
        let q = [i128::from(p[0] - self.v0[0]), i128::from(p[1] - self.v0[1])];
        let d = [i128::from(self.d[0]), i128::from(self.d[1])];
        let (along, whole) = match self.parameter {
            LineParameter::Major => {
                let sign = d[self.major].signum();
                (q[self.major] * sign, d[self.major] * sign)
            }
            LineParameter::Projected => (q[0] * d[0] + q[1] * d[1], d[0] * d[0] + d[1] * d[1]),
        };
        if along <= 0 {
            [1.0, 0.0]
        } else if along >= whole {
            [0.0, 1.0]
        } else {
            [
                ((whole - along) as f64 * self.inv_denominator) as f32,
                (along as f64 * self.inv_denominator) as f32,
            ]
        }
    }

    /// Writes depth and attributes for sample `i` with the ends' weights.
    pub fn write(&self, frame: &mut Frame, i: usize, [s, t]: [f32; 2]) {
        if let (Some([z0, z1]), Some(out)) = (self.depth, frame.depth.as_mut()) {
            out[i] = f64::from(s * z0 + t * z1);
        }
        let perspective_w = match self.interpolation {
            Interpolation::Perspective => s * self.inv_w[0] + t * self.inv_w[1],
            _ => 1.0,
        };
        for (channel, [a0, a1]) in frame.attributes.iter_mut().zip(&self.attributes) {
            let value = match self.interpolation {
                Interpolation::Flat => *a0,
                Interpolation::Linear => s * a0 + t * a1,
                Interpolation::Perspective => (s * a0 + t * a1) / perspective_w,
            };
            channel[i] = f64::from(value);
        }
    }
}

fn length2(g: &Geometry) -> i128 {
    let d = [i128::from(g.d[0]), i128::from(g.d[1])];
    d[0] * d[0] + d[1] * d[1]
}

/// Draws one line into the frame as primitive `index`.
///
/// `E` is production's integer for the case's format; lines choose their own
/// (the midpoint walk steps in i64 at every format, a parallelogram may be
/// drawn in a finer format than the case's).
#[allow(clippy::too_many_arguments, clippy::extra_unused_type_parameters)]
pub fn draw<E: EdgeInt>(
    line: &Line,
    ends: [[Fixed; 2]; 2],
    format: Format,
    rule: FillRule,
    canvas: Canvas,
    plan: &Plan,
    samples: Option<&Samples>,
    index: usize,
    frame: &mut Frame,
) -> Result<(), RasterError> {
    if samples.is_some() && line.rule != LineRule::Parallelogram {
        // SPEC.md §14.2: the case reader refuses these.
        return Err(RasterError::Unsupported(format!(
            "a {} line has no samples to antialias",
            line.rule.name()
        )));
    }
    let g = Geometry::new(ends);
    if g.is_point() {
        return Ok(());
    }
    let shading = plan
        .interpolates()
        .then(|| LineShading::new(line, &g, plan));
    if line.rule == LineRule::Midpoint && shading.is_none() {
        midpoint_coverage(&g, format, line.last_pixel, canvas, index, frame);
        return Ok(());
    }
    let mut sink = LineSink {
        frame,
        index,
        shading: shading.as_ref(),
        format,
        offsets: samples.map(|s| s.offsets_in(format)).unwrap_or_default(),
        samples,
    };
    match line.rule {
        LineRule::Midpoint => {
            midpoint(&g, format, line.last_pixel, canvas, |x, y| sink.pixel(x, y));
            Ok(())
        }
        LineRule::DiamondExit => {
            diamond_exit(&g, format, canvas, |x, y| sink.pixel(x, y));
            Ok(())
        }
        LineRule::Parallelogram => parallelogram(line, &g, format, rule, canvas, &mut sink),
        LineRule::Rectangle => rectangle(line, &g, format, rule, canvas, &mut sink),
    }
}

/// Writes a line's pixels, and their values, into the frame.
struct LineSink<'a> {
    frame: &'a mut Frame,
    index: usize,
    shading: Option<&'a LineShading>,
    format: Format,
    /// Antialiased scenes: the samples, and their offsets in `format`.
    samples: Option<&'a Samples<'a>>,
    offsets: Vec<[i64; 2]>,
}

impl LineSink<'_> {
    /// Sample `s` of pixel (x, y) of an antialiased frame is covered.
    #[inline]
    fn sample(&mut self, x: i64, y: i64, s: usize) {
        let n = self.offsets.len();
        let i = (y as usize * self.frame.width as usize + x as usize) * n + s;
        self.frame.hit(i, self.index);
        if let Some(shading) = self.shading {
            let one = self.format.one();
            let [ox, oy] = self.offsets[s];
            let p = [x * one + ox, y * one + oy];
            shading.write(self.frame, i, shading.weights(p));
        }
    }

    #[inline]
    fn pixel(&mut self, x: i64, y: i64) {
        let i = y as usize * self.frame.width as usize + x as usize;
        self.frame.hit(i, self.index);
        if let Some(shading) = self.shading {
            let p = [self.format.centre(x).0, self.format.centre(y).0];
            shading.write(self.frame, i, shading.weights(p));
        }
    }
}

impl<E: EdgeInt> SampleSink<E> for LineSink<'_> {
    #[inline]
    fn sample(&mut self, x: i64, y: i64, s: usize, _: antialias::At<E>) {
        LineSink::sample(self, x, y, s);
    }
}

impl Sink for LineSink<'_> {
    fn span(&mut self, y: i64, x0: i64, x1: i64) {
        for x in x0..x1 {
            self.pixel(x, y);
        }
    }
}

/// The parallelogram line as two triangles of production's triangle path.
///
/// Corners A = v0 − h, B = v1 − h, C = v1 + h, D = v0 + h with h = width/2
/// along the minor axis; triangles ABC and ACD. Their outer edges follow the
/// fill rule, classified by direction exactly as §4.3's outward normals do.
/// The diagonal AC goes to ABC when the fill rule gives it to ABC and to ACD
/// otherwise: for the four consistent rules that is what the rule does
/// anyway, and under `all-edges` it keeps the diagonal's samples from being
/// counted twice. So the triangles are disjoint and their union is exactly
/// the parallelogram, corners included (at A, ABC covers a sample exactly
/// when the nudge of §3 points into ABC, ACD never does when it does not
/// own the diagonal, and the nudge lies in the parallelogram's corner).
fn parallelogram(
    line: &Line,
    g: &Geometry,
    format: Format,
    rule: FillRule,
    canvas: Canvas,
    sink: &mut LineSink,
) -> Result<(), RasterError> {
    // The corners need width/2 in fixed point. A dyadic half-width finer
    // than the case's format is drawn in a finer one (the endpoints are exact
    // in it too): the first with enough fraction bits, up to the finest.
    // width/2 in units of 2^-f is width in units of 2^-(f − 1).
    let (fine, half) = (format.frac_bits..=MAX_FRAC_BITS)
        .find_map(|frac_bits| {
            let half = Format {
                frac_bits: frac_bits - 1,
            }
            .exact(&line.width)?;
            Some((Format { frac_bits }, half.0))
        })
        .ok_or_else(|| {
            RasterError::Unsupported(format!(
                "a parallelogram line's corners need half its width in fixed point, and width {} \
                 is not a multiple of 2^-{}",
                line.width.to_exact_string(),
                MAX_FRAC_BITS - 1
            ))
        })?;
    let scale = fine.frac_bits - format.frac_bits;
    let g = &Geometry::new([g.v0, g.v1].map(|p| p.map(|c| Fixed(c << scale))));
    if fine.fits_i64() {
        parallelogram_in::<i64>(g, half, fine, rule, canvas, sink);
    } else {
        parallelogram_in::<i128>(g, half, fine, rule, canvas, sink);
    }
    Ok(())
}

/// [`parallelogram`] in a format that holds its corners.
fn parallelogram_in<E: EdgeInt>(
    g: &Geometry,
    half: i64,
    format: Format,
    rule: FillRule,
    canvas: Canvas,
    sink: &mut LineSink,
) {
    let minor = 1 - g.major;
    let corner = |p: [i64; 2], sign: i64| {
        let mut q = p;
        q[minor] += sign * half;
        [Fixed(q[0]), Fixed(q[1])]
    };
    let (a, b, c, d) = (
        corner(g.v0, -1),
        corner(g.v1, -1),
        corner(g.v1, 1),
        corner(g.v0, 1),
    );
    let coverage_only = Plan {
        samples_per_pixel: 1,
        antialias: None,
        depth: false,
        attributes: 0,
        motion: None,
    };
    let placeholder = Triangle {
        vertices: [0, 1, 2].map(|_| Vertex::at(Number::ZERO, Number::ZERO)),
        interpolation: Interpolation::Linear,
    };
    let is_diagonal = |p: [Fixed; 2], q: [Fixed; 2]| (p == a && q == c) || (p == c && q == a);
    let footprint = match sink.samples {
        Some(_) => Footprint::Squares,
        None => Footprint::Centres,
    };
    let first = setup::setup_in::<E>(
        [a, b, c],
        &placeholder,
        format,
        rule,
        Cull::None,
        canvas,
        &coverage_only,
        |_, _| None,
        footprint,
    );
    // ACD walks the diagonal the other way round from ABC (both clockwise
    // once set up), so ABC's ownership is that of the reversed edge.
    let second = setup::setup_in::<E>(
        [a, c, d],
        &placeholder,
        format,
        rule,
        Cull::None,
        canvas,
        &coverage_only,
        |p, q| is_diagonal(p, q).then(|| !setup::edge_owned(q, p, rule)),
        footprint,
    );
    match sink.samples {
        None => {
            for triangle in [first, second].iter().flatten() {
                traverse::traverse(triangle, sink);
            }
        }
        Some(samples) => {
            // The corners' format may be finer than the case's: offsets in
            // it for the decisions, the sink's own for the values.
            let offsets = samples.offsets_in(format);
            for triangle in [first, second].iter().flatten() {
                antialias::cover(triangle, format, &offsets, samples.sampling, sink);
            }
        }
    }
}

/// Whether an edge of a wide line with outward normal n owns its samples
/// (SPEC.md §4.3).
fn owns(rule: FillRule, n: [i64; 2]) -> bool {
    if n[0] == 0 {
        if n[1] < 0 {
            rule.owns_top()
        } else {
            rule.owns_bottom()
        }
    } else if n[0] < 0 {
        rule.owns_left()
    } else {
        rule.owns_right()
    }
}

/// a·b as a 256-bit (high, low) pair.
fn mul_wide(a: u128, b: u128) -> (u128, u128) {
    const LOW: u128 = u64::MAX as u128;
    let (a1, a0) = (a >> 64, a & LOW);
    let (b1, b0) = (b >> 64, b & LOW);
    let (p00, p01, p10, p11) = (a0 * b0, a0 * b1, a1 * b0, a1 * b1);
    let mid = (p00 >> 64) + (p01 & LOW) + (p10 & LOW);
    let low = (p00 & LOW) | (mid << 64);
    let high = p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64);
    (high, low)
}

/// The rectangle line's exact test and its border ownership.
#[derive(Clone, Copy, Debug)]
struct RectangleTest {
    length2: i128,
    /// 2·b, for X = 2|q×d|·b.
    twice_b: u128,
    /// a²·one²·|d|², in 256 bits.
    bound: (u128, u128),
    own_start: bool,
    own_end: bool,
    /// The side where q×d > 0, and the other one.
    own_positive: bool,
    own_negative: bool,
}

impl RectangleTest {
    /// `along` = q·d, `across` = q×d for q = p − v0.
    #[inline]
    fn covers(&self, along: i128, across: i128) -> bool {
        let within_ends = match along.cmp(&0) {
            std::cmp::Ordering::Less => false,
            std::cmp::Ordering::Equal => self.own_start,
            std::cmp::Ordering::Greater => match along.cmp(&self.length2) {
                std::cmp::Ordering::Less => true,
                std::cmp::Ordering::Equal => self.own_end,
                std::cmp::Ordering::Greater => false,
            },
        };
        if !within_ends {
            return false;
        }
        let x = across.unsigned_abs() * self.twice_b;
        match mul_wide(x, x).cmp(&self.bound) {
            std::cmp::Ordering::Less => true,
            std::cmp::Ordering::Equal => {
                if across > 0 {
                    self.own_positive
                } else {
                    self.own_negative
                }
            }
            std::cmp::Ordering::Greater => false,
        }
    }
}

/// The rectangle line: each row of its bounding box, candidates on a span
/// found in f64 and widened, each candidate tested exactly:
/// 0 ≤ q·d ≤ |d|² and 4(q×d)²b² ≤ a²·one²·|d|² for width a/b.
fn rectangle(
    line: &Line,
    g: &Geometry,
    format: Format,
    rule: FillRule,
    canvas: Canvas,
    sink: &mut LineSink,
) -> Result<(), RasterError> {
    let too_fine = || {
        RasterError::Unsupported(format!(
            "a rectangle line's width {} must have a denominator below 2^{} for its exact test \
             to fit 256 bits",
            line.width.to_exact_string(),
            MAX_WIDTH_DENOMINATOR_BITS
        ))
    };
    let a = u128::try_from(line.width.numerator()).map_err(|_| too_fine())?;
    let b = u128::try_from(line.width.denominator()).map_err(|_| too_fine())?;
    if b >= 1 << MAX_WIDTH_DENOMINATOR_BITS || a >= 1 << MAX_WIDTH_NUMERATOR_BITS {
        return Err(too_fine());
    }
    let one = format.one();
    let [dx, dy] = g.d;
    let length2 = length2(g);
    let y = a * one as u128;
    let test = RectangleTest {
        length2,
        twice_b: 2 * b,
        bound: mul_wide(y * y, length2 as u128),
        own_start: owns(rule, [-dx, -dy]),
        own_end: owns(rule, [dx, dy]),
        own_positive: owns(rule, [dy, -dx]),
        own_negative: owns(rule, [-dy, dx]),
    };

    // Candidate spans in f64, in pixels.
    let px = |units: i64| units as f64 / one as f64;
    let (x0, y0) = (px(g.v0[0]), px(g.v0[1]));
    let (fdx, fdy) = (px(dx), px(dy));
    let flength2 = fdx * fdx + fdy * fdy;
    let flength = flength2.sqrt();
    let half_width = line.width.to_f64_lossy() / 2.0;
    let (nx, ny) = (-fdy / flength * half_width, fdx / flength * half_width);
    let xs = [x0 - nx, x0 + nx, x0 + fdx - nx, x0 + fdx + nx];
    let ys = [y0 - ny, y0 + ny, y0 + fdy - ny, y0 + fdy + ny];
    let fmin = |v: [f64; 4]| v.into_iter().fold(f64::INFINITY, f64::min);
    let fmax = |v: [f64; 4]| v.into_iter().fold(f64::NEG_INFINITY, f64::max);
    // Pixels whose centres lie in [lo − margin, hi + margin], on the canvas.
    let pixels = |lo: f64, hi: f64, size: u32| {
        let first = (lo - 0.5 - RECT_MARGIN_PX).ceil().max(0.0) as i64;
        let last = (hi - 0.5 + RECT_MARGIN_PX)
            .floor()
            .min(f64::from(size) - 1.0) as i64;
        (first, last)
    };
    let (box_x0, box_x1) = pixels(fmin(xs), fmax(xs), canvas.width);
    let (row0, row1) = pixels(fmin(ys), fmax(ys), canvas.height);
    let cross_limit = half_width * flength;
    for row in row0..=row1 {
        let qy = row as f64 + 0.5 - y0;
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        let mut clip = |k0: f64, k1: f64, slope: f64| {
            let (a, b) = (k0 / slope, k1 / slope);
            lo = lo.max(a.min(b));
            hi = hi.min(a.max(b));
        };
        if dx != 0 {
            // 0 ≤ qx·dx + qy·dy ≤ |d|².
            clip(-qy * fdy, flength2 - qy * fdy, fdx);
        }
        if dy != 0 {
            // −w/2·|d| ≤ qx·dy − qy·dx ≤ w/2·|d|.
            clip(qy * fdx - cross_limit, qy * fdx + cross_limit, fdy);
        }
        let (first, last) = pixels(x0 + lo, x0 + hi, canvas.width);
        let (first, last) = (first.max(box_x0), last.min(box_x1));
        if first > last {
            continue;
        }
        let q = [
            i128::from(format.centre(first).0 - g.v0[0]),
            i128::from(format.centre(row).0 - g.v0[1]),
        ];
        let (wdx, wdy) = (i128::from(dx), i128::from(dy));
        let mut along = q[0] * wdx + q[1] * wdy;
        let mut across = q[0] * wdy - q[1] * wdx;
        let (along_step, across_step) = (wdx * i128::from(one), wdy * i128::from(one));
        for x in first..=last {
            if test.covers(along, across) {
                sink.pixel(x, row);
            }
            along += along_step;
            across += across_step;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tiny deterministic generator (xorshift), so the tests need no
    /// dependency.
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }
        fn range(&mut self, lo: i64, hi: i64) -> i64 {
            lo + (self.next() % (hi - lo + 1) as u64) as i64
        }
    }

    const CANVAS: Canvas = Canvas {
        width: 24,
        height: 20,
    };

    fn pixels_of(g: &Geometry, format: Format, last: LastPixel, canvas: Canvas) -> Vec<(i64, i64)> {
        let mut out = Vec::new();
        midpoint(g, format, last, canvas, |x, y| out.push((x, y)));
        out.sort();
        out
    }

    /// SPEC.md §4.1 written out directly, each pixel from scratch, i128.
    fn brute_midpoint(
        g: &Geometry,
        format: Format,
        last: LastPixel,
        canvas: Canvas,
    ) -> Vec<(i64, i64)> {
        let (u, v) = (g.major, 1 - g.major);
        let one = i128::from(format.one());
        let sizes = [i64::from(canvas.width), i64::from(canvas.height)];
        let mut out = Vec::new();
        for i in -2..sizes[u] + 2 {
            let c = i128::from(i) * one + one / 2;
            let (p, q) = (i128::from(g.v0[u]), i128::from(g.v1[u]));
            if c < p.min(q) || c > p.max(q) {
                continue;
            }
            if last == LastPixel::Exclude && c == q {
                continue;
            }
            // v(c)/one = (v0·du + (c − u0)·dv) / (du·one); ceil − 1.
            let (mut n, mut den) = (
                i128::from(g.v0[v]) * (q - p) + (c - p) * i128::from(g.d[v]),
                (q - p) * one,
            );
            if den < 0 {
                n = -n;
                den = -den;
            }
            let ceil = if n >= 0 {
                (n + den - 1) / den
            } else {
                -((-n) / den)
            };
            let j = (ceil - 1) as i64;
            if i < 0 || i >= sizes[u] || j < 0 || j >= sizes[v] {
                continue;
            }
            out.push(if u == 0 { (i, j) } else { (j, i) });
        }
        out.sort();
        out
    }

    fn random_geometry(rng: &mut Rng, format: Format, spread: i64) -> Geometry {
        let one = format.one();
        let mut p = || rng.range(-2 * one, spread * one);
        let ends = [[Fixed(p()), Fixed(p())], [Fixed(p()), Fixed(p())]];
        Geometry::new(ends)
    }

    #[test]
    fn midpoint_matches_the_rule_in_every_octant() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        for frac_bits in [1, 2, 3, 5, 9, 17] {
            let format = Format { frac_bits };
            for _ in 0..3000 {
                let g = random_geometry(&mut rng, format, 26);
                if g.is_point() {
                    continue;
                }
                for last in [LastPixel::Include, LastPixel::Exclude] {
                    assert_eq!(
                        pixels_of(&g, format, last, CANVAS),
                        brute_midpoint(&g, format, last, CANVAS),
                        "{g:?} at {frac_bits} bits, {last:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn midpoint_is_symmetric_under_reversal() {
        let mut rng = Rng(12345);
        for frac_bits in [1, 4, 9] {
            let format = Format { frac_bits };
            for _ in 0..2000 {
                let g = random_geometry(&mut rng, format, 26);
                if g.is_point() {
                    continue;
                }
                let back = Geometry::new([
                    [Fixed(g.v1[0]), Fixed(g.v1[1])],
                    [Fixed(g.v0[0]), Fixed(g.v0[1])],
                ]);
                assert_eq!(
                    pixels_of(&g, format, LastPixel::Include, CANVAS),
                    pixels_of(&back, format, LastPixel::Include, CANVAS),
                    "{g:?}"
                );
            }
        }
    }

    #[test]
    fn midpoint_ties_go_up_and_left() {
        let format = Format { frac_bits: 1 }; // units of half a pixel
        let at = |x: i64, y: i64| [Fixed(x), Fixed(y)];
        // From (0.5, 1) to (4.5, 1): y(c) = 1 everywhere, row 0.
        let g = Geometry::new([at(1, 2), at(9, 2)]);
        assert_eq!(
            pixels_of(&g, format, LastPixel::Include, CANVAS),
            vec![(0, 0), (1, 0), (2, 0), (3, 0), (4, 0)]
        );
        // Vertical at x = 2: column 1.
        let g = Geometry::new([at(4, 1), at(4, 7)]);
        assert_eq!(
            pixels_of(&g, format, LastPixel::Include, CANVAS),
            vec![(1, 0), (1, 1), (1, 2), (1, 3)]
        );
        assert_eq!(
            pixels_of(&g, format, LastPixel::Exclude, CANVAS),
            vec![(1, 0), (1, 1), (1, 2)]
        );
    }

    #[test]
    fn strips_with_last_pixel_excluded_share_no_joint() {
        let format = Format { frac_bits: 9 };
        let mut rng = Rng(777);
        let centre = |rng: &mut Rng| {
            let mut c = || format.centre(rng.range(0, 19));
            [c(), c()]
        };
        for _ in 0..300 {
            // Joints at pixel centres, where an included last pixel would be
            // drawn by both lines meeting there.
            let points: Vec<[Fixed; 2]> = (0..5).map(|_| centre(&mut rng)).collect();
            for pair in points.windows(2) {
                let g = Geometry::new([pair[0], pair[1]]);
                if g.is_point() {
                    continue;
                }
                let drawn = pixels_of(&g, format, LastPixel::Exclude, CANVAS);
                let pixel = |p: [Fixed; 2]| (p[0].0 >> 9, p[1].0 >> 9);
                assert!(
                    !drawn.contains(&pixel(pair[1])),
                    "{pair:?} drew its last pixel"
                );
                assert!(
                    drawn.contains(&pixel(pair[0])),
                    "{pair:?} missed its first pixel"
                );
            }
        }
    }

    #[test]
    fn midpoint_clips_far_lines_cheaply() {
        let format = Format { frac_bits: 9 };
        let one = format.one();
        let g = Geometry::new([
            [Fixed(-32768 * one), Fixed(-32768 * one)],
            [Fixed(32768 * one), Fixed(32768 * one)],
        ]);
        let pixels = pixels_of(&g, format, LastPixel::Include, CANVAS);
        // The diagonal y = x: pixel centres (i + ½) have y(c) = i + ½.
        assert_eq!(pixels, (0..20).map(|i| (i, i)).collect::<Vec<_>>());
    }

    /// A convex polygon's coverage under SPEC.md §4.3's border rule, from
    /// scratch: corners in order, each edge's outward normal from the
    /// winding.
    fn brute_polygon(corners: &[[i128; 2]], rule: FillRule, p: [i128; 2]) -> bool {
        let n = corners.len();
        let area: i128 = (0..n)
            .map(|i| {
                let (a, b) = (corners[i], corners[(i + 1) % n]);
                a[0] * b[1] - a[1] * b[0]
            })
            .sum();
        assert!(area != 0);
        (0..n).all(|i| {
            let (a, b) = (corners[i], corners[(i + 1) % n]);
            let e = [b[0] - a[0], b[1] - a[1]];
            // Outward normal: right of the edge for positive area (y down, clockwise).
            let normal = if area > 0 {
                [-e[1], e[0]]
            } else {
                [e[1], -e[0]]
            };
            let side = (p[0] - a[0]) * normal[0] + (p[1] - a[1]) * normal[1];
            let out = -side;
            if out > 0 {
                false
            } else if out < 0 {
                true
            } else {
                let n = [(-normal[0]).signum() as i64, (-normal[1]).signum() as i64];
                owns(rule, n)
            }
        })
    }

    fn frame_for(canvas: Canvas) -> Frame {
        Frame::new(canvas.width, canvas.height, false, 0)
    }

    fn test_line(rule: LineRule, width: Number) -> Line {
        Line {
            vertices: [
                Vertex::at(Number::ZERO, Number::ZERO),
                Vertex::at(Number::ZERO, Number::ZERO),
            ],
            rule,
            width,
            last_pixel: LastPixel::Include,
            parameter: LineParameter::Major,
            interpolation: Interpolation::Perspective,
        }
    }

    fn draw_one<E: EdgeInt>(
        line: &Line,
        g: &Geometry,
        format: Format,
        rule: FillRule,
        canvas: Canvas,
    ) -> Result<Frame, RasterError> {
        let mut frame = frame_for(canvas);
        let plan = Plan {
            samples_per_pixel: 1,
            antialias: None,
            depth: false,
            attributes: 0,
            motion: None,
        };
        let ends = [
            [Fixed(g.v0[0]), Fixed(g.v0[1])],
            [Fixed(g.v1[0]), Fixed(g.v1[1])],
        ];
        draw::<E>(line, ends, format, rule, canvas, &plan, None, 0, &mut frame)?;
        Ok(frame)
    }

    #[test]
    fn parallelogram_is_exactly_the_swept_segment() {
        let mut rng = Rng(4242);
        for frac_bits in [1, 3, 9] {
            let format = Format { frac_bits };
            let one = i128::from(format.one());
            for trial in 0..600 {
                let g = random_geometry(&mut rng, format, 24);
                if g.is_point() {
                    continue;
                }
                // Widths in sixteenths: finer than the format at few bits,
                // drawn then in a finer one.
                let sixteenths = rng.range(1, 64);
                let width = Number::ratio(sixteenths, 16);
                // Brute force on a grid 32 times finer, where half the width
                // is an integer.
                let half = i128::from(sixteenths) * one;
                let rule = FillRule::ALL[trial % 5];
                let line = test_line(LineRule::Parallelogram, width);
                let frame = draw_one::<i64>(&line, &g, format, rule, CANVAS).unwrap();
                let minor = 1 - g.major;
                let v = |p: [i64; 2], s: i128| {
                    let mut q = [32 * i128::from(p[0]), 32 * i128::from(p[1])];
                    q[minor] += s * half;
                    q
                };
                let corners = [v(g.v0, -1), v(g.v1, -1), v(g.v1, 1), v(g.v0, 1)];
                for y in 0..CANVAS.height as i64 {
                    for x in 0..CANVAS.width as i64 {
                        let p = [
                            32 * i128::from(format.centre(x).0),
                            32 * i128::from(format.centre(y).0),
                        ];
                        let want = u16::from(brute_polygon(&corners, rule, p));
                        let got = frame.coverage[(y * 24 + x) as usize];
                        assert_eq!(got, want, "{g:?} {rule:?} width {half} at ({x}, {y})");
                    }
                }
            }
        }
    }

    #[test]
    fn parallelogram_needs_a_representable_half_width() {
        let format = Format { frac_bits: 9 };
        let g = Geometry::new([[Fixed(0), Fixed(0)], [Fixed(4096), Fixed(512)]]);
        let line = test_line(LineRule::Parallelogram, Number::ratio(1, 3));
        let err = draw_one::<i64>(&line, &g, format, FillRule::TopLeft, CANVAS).unwrap_err();
        assert!(matches!(err, RasterError::Unsupported(_)), "{err}");
    }

    /// §4.3 from scratch in exact rationals-as-integers, over the whole
    /// canvas (no spans).
    fn brute_rectangle(
        g: &Geometry,
        format: Format,
        a: i128,
        b: i128,
        rule: FillRule,
        p: [i128; 2],
    ) -> bool {
        let d = [i128::from(g.d[0]), i128::from(g.d[1])];
        let q = [p[0] - i128::from(g.v0[0]), p[1] - i128::from(g.v0[1])];
        let along = q[0] * d[0] + q[1] * d[1];
        let l2 = d[0] * d[0] + d[1] * d[1];
        let across = q[0] * d[1] - q[1] * d[0];
        let one = i128::from(format.one());
        if along < 0 || along > l2 {
            return false;
        }
        let lhs = 4 * across * across * b * b;
        let rhs = a * a * one * one * l2;
        if lhs > rhs {
            return false;
        }
        let mut ok = true;
        let (dx, dy) = (g.d[0], g.d[1]);
        if along == 0 {
            ok &= owns(rule, [-dx, -dy]);
        }
        if along == l2 {
            ok &= owns(rule, [dx, dy]);
        }
        if lhs == rhs {
            ok &= owns(rule, if across > 0 { [dy, -dx] } else { [-dy, dx] });
        }
        ok
    }

    #[test]
    fn rectangle_spans_miss_no_sample() {
        let mut rng = Rng(99);
        for frac_bits in [1, 2, 5, 9] {
            let format = Format { frac_bits };
            for trial in 0..800 {
                let g = random_geometry(&mut rng, format, 24);
                if g.is_point() {
                    continue;
                }
                let (a, b) = [(1, 1), (2, 1), (1, 2), (3, 2), (1, 3), (7, 5), (5, 1)][trial % 7];
                let rule = FillRule::ALL[trial % 5];
                let line = test_line(LineRule::Rectangle, Number::ratio(a, b));
                let frame = draw_one::<i64>(&line, &g, format, rule, CANVAS).unwrap();
                for y in 0..CANVAS.height as i64 {
                    for x in 0..CANVAS.width as i64 {
                        let p = [
                            i128::from(format.centre(x).0),
                            i128::from(format.centre(y).0),
                        ];
                        let want =
                            u16::from(brute_rectangle(&g, format, a.into(), b.into(), rule, p));
                        let got = frame.coverage[(y * 24 + x) as usize];
                        assert_eq!(got, want, "{g:?} {rule:?} width {a}/{b} at ({x}, {y})");
                    }
                }
            }
        }
    }

    #[test]
    fn rectangle_spans_hold_at_the_finest_format_far_away() {
        // Long lines from far outside the canvas, at 17 fraction bits, where
        // f64 span ends are least accurate.
        let format = Format { frac_bits: 17 };
        let one = format.one();
        let mut rng = Rng(31337);
        for trial in 0..300 {
            let mut far = || rng.range(-32768 * one, 32768 * one);
            let mut g = Geometry::new([[Fixed(far()), Fixed(far())], [Fixed(far()), Fixed(far())]]);
            // Aim it through the canvas: move v0 so the line passes near (10, 10).
            let mid = [(g.v0[0] + g.v1[0]) / 2, (g.v0[1] + g.v1[1]) / 2];
            let shift = [10 * one - mid[0], 10 * one - mid[1]];
            let clamp = |v: i64| v.clamp(-32768 * one, 32768 * one);
            g = Geometry::new([
                [
                    Fixed(clamp(g.v0[0] + shift[0])),
                    Fixed(clamp(g.v0[1] + shift[1])),
                ],
                [
                    Fixed(clamp(g.v1[0] + shift[0])),
                    Fixed(clamp(g.v1[1] + shift[1])),
                ],
            ]);
            if g.is_point() {
                continue;
            }
            let (a, b) = [(1, 1), (3, 1), (1, 7), (1024, 1)][trial % 4];
            let rule = FillRule::ALL[trial % 5];
            let line = test_line(LineRule::Rectangle, Number::ratio(a, b));
            let frame = draw_one::<i128>(&line, &g, format, rule, CANVAS).unwrap();
            for y in 0..CANVAS.height as i64 {
                for x in 0..CANVAS.width as i64 {
                    let p = [
                        i128::from(format.centre(x).0),
                        i128::from(format.centre(y).0),
                    ];
                    let want = u16::from(brute_rectangle(&g, format, a.into(), b.into(), rule, p));
                    assert_eq!(
                        frame.coverage[(y * 24 + x) as usize],
                        want,
                        "{g:?} at ({x}, {y})"
                    );
                }
            }
        }
    }

    #[test]
    fn rectangle_worked_by_hand() {
        // (1, 2) to (5, 2), width 1, top-left: the top border y = 1.5 is
        // owned, the bottom one y = 2.5 is not; centres x = 1.5 … 4.5.
        let format = Format { frac_bits: 1 };
        let g = Geometry::new([[Fixed(2), Fixed(4)], [Fixed(10), Fixed(4)]]);
        let line = test_line(LineRule::Rectangle, Number::ONE);
        let frame = draw_one::<i64>(&line, &g, format, FillRule::TopLeft, CANVAS).unwrap();
        let covered: Vec<usize> = (0..frame.coverage.len())
            .filter(|&i| frame.coverage[i] > 0)
            .collect();
        assert_eq!(covered, vec![24 + 1, 24 + 2, 24 + 3, 24 + 4]);
        let frame = draw_one::<i64>(&line, &g, format, FillRule::BottomRight, CANVAS).unwrap();
        let covered: Vec<usize> = (0..frame.coverage.len())
            .filter(|&i| frame.coverage[i] > 0)
            .collect();
        assert_eq!(covered, vec![48 + 1, 48 + 2, 48 + 3, 48 + 4]);
    }

    #[test]
    fn wide_products_are_exact() {
        let a = u128::MAX;
        assert_eq!(mul_wide(a, a), (u128::MAX - 1, 1));
        assert_eq!(mul_wide(1 << 100, 1 << 100), (1 << 72, 0));
        assert_eq!(mul_wide(12345, 678910), (0, 12345 * 678910));
    }

    #[test]
    fn weights_are_clamped_and_exact_at_the_ends() {
        let g = Geometry::new([[Fixed(0), Fixed(0)], [Fixed(8), Fixed(2)]]);
        let mut line = test_line(LineRule::Midpoint, Number::ONE);
        let plan = Plan {
            samples_per_pixel: 1,
            antialias: None,
            depth: true,
            attributes: 0,
            motion: None,
        };
        let shading = LineShading::new(&line, &g, &plan);
        assert_eq!(shading.weights([-3, 5]), [1.0, 0.0]);
        assert_eq!(shading.weights([8, 0]), [0.0, 1.0]);
        assert_eq!(shading.weights([2, 100]), [0.75, 0.25]);
        line.parameter = LineParameter::Projected;
        let shading = LineShading::new(&line, &g, &plan);
        // (2, 100)·(8, 2) = 216 > 68: clamped.
        assert_eq!(shading.weights([2, 100]), [0.0, 1.0]);
        assert_eq!(shading.weights([4, 1]), [0.5, 0.5]);
    }

    fn diamond_pixels(g: &Geometry, format: Format, canvas: Canvas) -> Vec<(i64, i64)> {
        let mut out = Vec::new();
        diamond_exit(g, format, canvas, |x, y| out.push((x, y)));
        let count = out.len();
        out.sort();
        out.dedup();
        assert_eq!(out.len(), count, "{g:?} visited a pixel twice");
        out
    }

    /// A fraction n/d with d > 0.
    #[derive(Clone, Copy, Debug)]
    struct Frac(i128, i128);

    fn frac_cmp(p: Frac, q: Frac) -> std::cmp::Ordering {
        (p.0 * q.1).cmp(&(q.0 * p.1))
    }

    /// SPEC.md §4.2 written out directly: whether the point (X/den, Y/den)
    /// (units) lies in the diamond around `c`, by the four inequalities in
    /// u and v plus the right corner for y-major lines.
    fn brute_in_diamond(p: [i128; 2], den: i128, c: [i128; 2], h: i128, y_major: bool) -> bool {
        // u·den, v·den.
        let (u, v) = (p[0] - c[0] * den, p[1] - c[1] * den);
        let hd = h * den;
        let four = -u - v < hd && u - v < hd && -u + v <= hd && u + v <= hd;
        four || (y_major && u == hd && v == 0)
    }

    /// SPEC.md §4.2 from scratch: a pixel is lit when some point of the
    /// segment lies in its diamond and v1 does not. The points tried are
    /// the segment's ends, every parameter where it crosses one of the
    /// four border lines, and the midpoints between consecutive ones: the
    /// parameters of the segment's points in the diamond form an interval
    /// whose ends are among those, so a non-empty one holds one of them.
    fn brute_diamond_exit(g: &Geometry, format: Format, canvas: Canvas) -> Vec<(i64, i64)> {
        let one = i128::from(format.one());
        let h = one / 2;
        let y_major = g.d[1].abs() > g.d[0].abs();
        let p0 = [i128::from(g.v0[0]), i128::from(g.v0[1])];
        let p1 = [i128::from(g.v1[0]), i128::from(g.v1[1])];
        let d = [p1[0] - p0[0], p1[1] - p0[1]];
        let mut out = Vec::new();
        let range = |k: usize, size: u32| {
            let lo = p0[k].min(p1[k]).div_euclid(one) - 1;
            let hi = p0[k].max(p1[k]).div_euclid(one) + 1;
            (lo.max(0) as i64)..=(hi.min(i128::from(size) - 1) as i64)
        };
        for y in range(1, canvas.height) {
            for x in range(0, canvas.width) {
                let c = [
                    i128::from(format.centre(x).0),
                    i128::from(format.centre(y).0),
                ];
                if brute_in_diamond(p1, 1, c, h, y_major) {
                    continue;
                }
                let mut crit = vec![Frac(0, 1), Frac(1, 1)];
                for (alpha, beta) in [(-1, -1), (1, -1), (-1, 1), (1, 1)] {
                    // α·u(s) + β·v(s) = h.
                    let e = alpha * (p0[0] - c[0]) + beta * (p0[1] - c[1]);
                    let f = alpha * d[0] + beta * d[1];
                    if f != 0 {
                        let s = if f > 0 {
                            Frac(h - e, f)
                        } else {
                            Frac(e - h, -f)
                        };
                        if s.0 >= 0 && s.0 <= s.1 {
                            crit.push(s);
                        }
                    }
                }
                crit.sort_by(|&p, &q| frac_cmp(p, q));
                let mut tries = crit.clone();
                for w in crit.windows(2) {
                    tries.push(Frac(w[0].0 * w[1].1 + w[1].0 * w[0].1, 2 * w[0].1 * w[1].1));
                }
                let meets = tries.iter().any(|&Frac(n, den)| {
                    let p = [p0[0] * den + n * d[0], p0[1] * den + n * d[1]];
                    brute_in_diamond(p, den, c, h, y_major)
                });
                if meets {
                    out.push((x, y));
                }
            }
        }
        out.sort();
        out
    }

    /// Endpoints on the features of §4.2's diamonds: centres, corners,
    /// points on the edges, and anywhere.
    fn diamond_point(rng: &mut Rng, format: Format, spread: i64) -> [Fixed; 2] {
        let one = format.one();
        let h = one / 2;
        let c = [
            format.centre(rng.range(-2, spread)).0,
            format.centre(rng.range(-2, spread)).0,
        ];
        let (du, dv) = match rng.range(0, 5) {
            0 => (0, 0),
            1 | 2 => [(h, 0), (-h, 0), (0, h), (0, -h)][rng.range(0, 3) as usize],
            3 => {
                let k = rng.range(-h, h);
                let rest = h - k.abs();
                (k, if rng.range(0, 1) == 0 { rest } else { -rest })
            }
            _ => (rng.range(-one, one), rng.range(-one, one)),
        };
        [Fixed(c[0] + du), Fixed(c[1] + dv)]
    }

    #[test]
    fn diamond_exit_matches_the_rule_in_every_octant() {
        let mut rng = Rng(0xd1a_304d);
        for frac_bits in [1, 2, 3, 5, 9, 17] {
            let format = Format { frac_bits };
            for trial in 0..2500 {
                let g = if trial % 2 == 0 {
                    Geometry::new([
                        diamond_point(&mut rng, format, 26),
                        diamond_point(&mut rng, format, 26),
                    ])
                } else {
                    random_geometry(&mut rng, format, 26)
                };
                if g.is_point() {
                    continue;
                }
                assert_eq!(
                    diamond_pixels(&g, format, CANVAS),
                    brute_diamond_exit(&g, format, CANVAS),
                    "{g:?} at {frac_bits} bits"
                );
            }
        }
    }

    #[test]
    fn diamond_exit_matches_the_rule_on_diagonals_and_axes() {
        // Slopes 0, ±1, ∞ and 1:2 from diamond features: lines along
        // diamond edges and through rows of corners.
        let mut rng = Rng(2024);
        for frac_bits in [1, 2, 5, 9, 17] {
            let format = Format { frac_bits };
            let h = format.one() / 2;
            for _ in 0..1500 {
                let p = diamond_point(&mut rng, format, 22);
                let k = rng.range(1, 16) * h;
                let (sx, sy) = (
                    [-1, 0, 1, 2, -2][rng.range(0, 4) as usize],
                    [-1, 0, 1, 2, -2][rng.range(0, 4) as usize],
                );
                let q = [Fixed(p[0].0 + sx * k), Fixed(p[1].0 + sy * k)];
                let g = Geometry::new([p, q]);
                if g.is_point() {
                    continue;
                }
                assert_eq!(
                    diamond_pixels(&g, format, CANVAS),
                    brute_diamond_exit(&g, format, CANVAS),
                    "{g:?} at {frac_bits} bits"
                );
            }
        }
    }

    #[test]
    fn diamond_exit_matches_the_rule_far_away() {
        let mut rng = Rng(0x5eed);
        for frac_bits in [1, 9, 17] {
            let format = Format { frac_bits };
            let one = format.one();
            let limit = 32768 * one;
            for _ in 0..400 {
                // One end at the coordinate limit, the other near the
                // canvas or through it to the opposite limit.
                let side = rng.range(0, 3);
                let edge = |t: i64| match side {
                    0 => [-limit, t],
                    1 => [limit, t],
                    2 => [t, -limit],
                    _ => [t, limit],
                };
                let far = edge(rng.range(-limit, limit));
                let near = diamond_point(&mut rng, format, 22);
                let mut ends = [[Fixed(far[0]), Fixed(far[1])], near];
                if rng.range(0, 2) == 0 {
                    // Through the near point, out to the other side.
                    let other = [
                        (2 * near[0].0 - far[0]).clamp(-limit, limit),
                        (2 * near[1].0 - far[1]).clamp(-limit, limit),
                    ];
                    ends[1] = [Fixed(other[0]), Fixed(other[1])];
                }
                if rng.range(0, 1) == 0 {
                    ends.swap(0, 1);
                }
                let g = Geometry::new(ends);
                if g.is_point() {
                    continue;
                }
                assert_eq!(
                    diamond_pixels(&g, format, CANVAS),
                    brute_diamond_exit(&g, format, CANVAS),
                    "{g:?} at {frac_bits} bits"
                );
            }
        }
    }

    #[test]
    fn diamond_exit_by_hand() {
        let format = Format { frac_bits: 1 }; // units of half a pixel
        let at = |x: i64, y: i64| [Fixed(x), Fixed(y)];
        let lit = |p, q| diamond_pixels(&Geometry::new([p, q]), format, CANVAS);
        // Through centres, (0.5, 0.5) to (4.5, 0.5): the last diamond holds v1.
        assert_eq!(lit(at(1, 1), at(9, 1)), [(0, 0), (1, 0), (2, 0), (3, 0)]);
        assert_eq!(lit(at(9, 1), at(1, 1)), [(1, 0), (2, 0), (3, 0), (4, 0)]);
        // Along y = 1: bottom corners of row 0 count, top corners of row 1
        // do not; v1 = (4.5, 1) is the bottom corner of (4, 0).
        assert_eq!(lit(at(1, 2), at(9, 2)), [(0, 0), (1, 0), (2, 0), (3, 0)]);
        // Along x = 1, y-major: right corners of column 0 count.
        assert_eq!(lit(at(2, 1), at(2, 9)), [(0, 0), (0, 1), (0, 2), (0, 3)]);
        assert_eq!(lit(at(2, 9), at(2, 1)), [(0, 1), (0, 2), (0, 3), (0, 4)]);
        // x-major from a left corner to a right corner: only (1, 2).
        assert_eq!(lit(at(2, 5), at(4, 5)), [(1, 2)]);
        // y-major from a bottom corner to the next one down: v1 is the
        // bottom corner of (1, 1), so only (1, 0).
        assert_eq!(lit(at(3, 2), at(3, 4)), [(1, 0)]);
        // 45° along the lower-left edges, (0, 0.5) to (4, 4.5): x-major,
        // so the right corners (i + 1, i + 1.5) it passes light nothing.
        assert_eq!(lit(at(0, 1), at(8, 9)), [(0, 0), (1, 1), (2, 2), (3, 3)]);
        // 45° along the upper-right edges of (i, i), (1, 0.5) to (5, 4.5): those
        // edges are excluded, but they are the lower-left edges of the
        // diamonds (i + 1, i), which light.
        assert_eq!(lit(at(2, 1), at(10, 9)), [(1, 0), (2, 1), (3, 2), (4, 3)]);
    }

    #[test]
    fn diamond_exit_clips_far_lines() {
        let format = Format { frac_bits: 17 };
        let one = format.one();
        let g = Geometry::new([
            [Fixed(-32768 * one), Fixed(-32768 * one)],
            [Fixed(32768 * one), Fixed(32768 * one)],
        ]);
        // The diagonal through every centre (i + ½, i + ½).
        assert_eq!(
            diamond_pixels(&g, format, CANVAS),
            (0..20).map(|i| (i, i)).collect::<Vec<_>>()
        );
    }

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
        let plan = Plan {
            samples_per_pixel: 1,
            antialias: None,
            depth: false,
            attributes: 0,
            motion: None,
        };
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
