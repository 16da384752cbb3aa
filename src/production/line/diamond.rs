//! The `diamond-exit` rule (SPEC.md §4.2): the two candidate pixels per
//! major step that the stepped line height leaves, each decided exactly by
//! the segment's parameter interval in the pixel's diamond (rotated
//! coordinates, open or closed borders as D3D11 words them).

use super::step::{Geometry, Slope, DIFF_PX_BITS};
use crate::production::fixed::{Format, MAX_FRAC_BITS};
use crate::scene::rules::limits;
use crate::scene::Canvas;

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
/// only when y(c) is an integer). ⌊y(c)⌋ is stepped as in
/// [`midpoint`](super::midpoint::midpoint) ([`Slope`]); each candidate is
/// then decided exactly by [`DiamondExit::lights`].
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
    // y(c)/one = N/D with N = a_v·du + (c − a_u)·dv, D = du·one (du > 0).
    let mut steps = Slope::new(g, format, first).steps(0);
    for m in first..end {
        let minor = steps.minor;
        for n in [minor - 1, minor] {
            if !(0..sizes[v]).contains(&n) {
                continue;
            }
            let (x, y) = if u == 0 { (m, n) } else { (n, m) };
            if test.lights([format.centre(x).0, format.centre(y).0]) {
                visit(x, y);
            }
        }
        steps.advance();
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_support::*;
    use super::*;
    use crate::production::fixed::Fixed;

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
}
