//! What every line rule steps on: a line's snapped endpoints in fixed
//! point with its major axis ([`Geometry`]), the pixels of the major axis it
//! spans ([`major_range`]), and the exact stepping of its minor coordinate
//! from one major pixel's centre to the next ([`Slope`], [`MinorSteps`]),
//! which the midpoint walk, the banded walkers and the diamond-exit walk
//! share. No rule's decision is made here.

use crate::production::fixed::{Fixed, Format, MAX_FRAC_BITS};
use crate::scene::rules::limits;
use crate::scene::{Canvas, LastPixel};

/// Bits of the largest coordinate difference along one axis, in pixels:
/// two vertices, or a vertex and a sample on the canvas, are at most 2^16 px
/// apart (|x|, |y| ≤ 2^15 px).
pub(super) const DIFF_PX_BITS: u32 = limits::COORD_LIMIT.trailing_zeros() + 1;

// Midpoint: the first row needs y0·dx + (c − x0)·dy, at most
// 2·2^(2(DIFF_PX_BITS + f)) in magnitude: i128 at every format.
const _: () = assert!(2 * (DIFF_PX_BITS + MAX_FRAC_BITS) + 2 <= 127);
// Midpoint stepping: the remainder lies in [0, D) with D = |du|·one ≤
// 2^(DIFF_PX_BITS + 2f), and one step adds at most D: i64 at every format.
const _: () = assert!(DIFF_PX_BITS + 2 * MAX_FRAC_BITS + 2 <= 63);

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

/// A line (not a point) over the centres of its major pixels, from its end
/// `a` with the smaller major coordinate to the other, `b`: at the centre c
/// of a major pixel the minor coordinate, in units, is N/D with
/// N = a_v·du + (c − a_u)·dv and D = du·one (du > 0), and each next centre
/// adds dv·one to N.
#[derive(Clone, Copy, Debug)]
pub(super) struct Slope {
    pub a: [i64; 2],
    pub b: [i64; 2],
    /// D = du·one.
    pub den: i64,
    /// dv·one: what N gains from one major pixel to the next.
    pub step: i64,
    /// N at the centre of major pixel `first`.
    pub numerator: i128,
}

impl Slope {
    /// The line's slope from the centre of major pixel `first` on.
    #[inline]
    pub fn new(g: &Geometry, format: Format, first: i64) -> Slope {
        let (u, v) = (g.major, 1 - g.major);
        let (a, b) = if g.v0[u] < g.v1[u] {
            (g.v0, g.v1)
        } else {
            (g.v1, g.v0)
        };
        let du = b[u] - a[u];
        let dv = b[v] - a[v];
        let one = format.one();
        let c = format.centre(first).0;
        Slope {
            a,
            b,
            den: du * one,
            step: dv * one,
            numerator: i128::from(a[v]) * i128::from(du) + i128::from(c - a[u]) * i128::from(dv),
        }
    }

    /// ⌊(N + offset)/D⌋ from the centre of major pixel `first` on: the first
    /// is one exact i128 division, the next ones are [`MinorSteps::advance`].
    #[inline]
    pub fn steps(&self, offset: i128) -> MinorSteps {
        let numerator = self.numerator + offset;
        let wide_denominator = i128::from(self.den);
        // Bounded by the coordinate limits: the row is within 2^16 of the
        // canvas, the remainder below D.
        MinorSteps {
            minor: numerator.div_euclid(wide_denominator) as i64,
            rest: numerator.rem_euclid(wide_denominator) as i64,
            step: self.step,
            den: self.den,
        }
    }
}

/// ⌊(N + offset)/D⌋ of a [`Slope`] at one major pixel after another.
#[derive(Clone, Copy, Debug)]
pub(super) struct MinorSteps {
    /// The quotient: the minor pixel at the current major pixel.
    pub minor: i64,
    /// The remainder, in [0, D).
    rest: i64,
    step: i64,
    den: i64,
}

impl MinorSteps {
    /// To the next major pixel: N gains dv·one, which moves the remainder
    /// by at most D, so one comparison steps it.
    #[inline]
    pub fn advance(&mut self) {
        self.rest += self.step;
        if self.rest >= self.den {
            self.rest -= self.den;
            self.minor += 1;
        } else if self.rest < 0 {
            self.rest += self.den;
            self.minor -= 1;
        }
    }
}

/// |d|², exact.
pub(super) fn length2(g: &Geometry) -> i128 {
    let d = [i128::from(g.d[0]), i128::from(g.d[1])];
    d[0] * d[0] + d[1] * d[1]
}
