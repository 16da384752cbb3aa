//! The `rectangle` line (SPEC.md §4.3, the strict wide line): each row's
//! candidate pixels found on an f64 span widened by a margin, each then
//! decided exactly by a 256-bit squared comparison (no irrational corner
//! ever appears), borders owned by their outward normals as the fill rule
//! says.

use super::shading::LineSink;
use super::step::{length2, Geometry, DIFF_PX_BITS};
use crate::production::fixed::{Format, MAX_FRAC_BITS};
use crate::rasterizer::RasterError;
use crate::scene::rules::limits;
use crate::scene::{Canvas, FillRule, Line};

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

/// Whether an edge of a wide line with outward normal n owns its samples
/// (SPEC.md §4.3).
pub(super) fn owns(rule: FillRule, n: [i64; 2]) -> bool {
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
pub(super) fn rectangle(
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
    use super::super::test_support::*;
    use super::*;
    use crate::production::fixed::Fixed;
    use crate::scene::{LineRule, Number};

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
}
