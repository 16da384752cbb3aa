//! One moving-primitive test at one instant, exact: the time format
//! (2^32 times a position, in units of 2^-(f+32) px) and the bits it needs,
//! cross products' signs compared in i128 or 256 bits, production's edge
//! ownership on an edge's direction at τ, and a triangle's coverage of a
//! sample as the static setup decides it. Which samples and instants are
//! tested is `mod.rs`'s.

use std::cmp::Ordering;

use crate::production::fixed::{Fixed, MAX_FRAC_BITS};
use crate::production::setup;
use crate::scene::rules::limits;
use crate::scene::{Cull, FillRule};

/// Fraction bits of an instant: τ = t/2^TIME_BITS. The shutter's ends are
/// multiples of 2^-16 and an instant adds (close − open)·u/2^16 with u below
/// 2^16 (`MotionBlur::instant`).
pub(super) const TIME_BITS: u32 = 2 * crate::scene::time::limits::TIME_BITS;

/// Bits of any difference a test takes, in pixels. A vertex lies within
/// 2^15 px of the origin at both ends of the shutter, so at every instant;
/// a parallelogram's corner at most width/2 ≤ 2^9 px further; a sample on
/// the canvas within 2^14 px. Two such points are less than 2^17 px apart.
const DIFF_PX_BITS: u32 = 17;
const _: () = assert!(2 * (limits::COORD_LIMIT + limits::MAX_LINE_WIDTH / 2) <= 1 << DIFF_PX_BITS);
const _: () = assert!((limits::MAX_CANVAS_SIDE as i64) <= limits::COORD_LIMIT);

/// Bits of such a difference in units of 2^-(f+32) px, f ≤ MAX_FRAC_BITS:
/// 66, held in i128 with room (and so are the positions themselves).
pub(super) const DIFF_BITS: u32 = DIFF_PX_BITS + MAX_FRAC_BITS + TIME_BITS;
const _: () = assert!(DIFF_BITS <= 126);

// A product of two differences needs 2·DIFF_BITS = 132 bits at the finest
// format: it fits i128 (below 2^127) only when f ≤ 14 (2(17 + f + 32) ≤ 126).
// A cross product's sign is the comparison of its two products, so no
// difference of products is ever formed: each product is taken in i128
// where `checked_mul` says it fits, in 256 bits otherwise, and every format
// of the case reader is drawn.
const _: () = assert!(2 * DIFF_BITS < 255);

/// A point: 2^32 times a position at an instant, in units of 2^-(f+32) px,
/// or on the fast path ([`Fast`]) a position in units of 2^-f px.
pub(super) type Point = [i128; 2];

#[inline]
pub(super) fn sub(a: Point, b: Point) -> Point {
    [a[0] - b[0], a[1] - b[1]]
}

/// a·b exactly, as the high (signed) and low halves of its 256-bit two's
/// complement form: the pairs compare as the products do.
pub(super) fn wide_product(a: i128, b: i128) -> (i128, u128) {
    const LOW: u128 = u64::MAX as u128;
    let (x, y) = (a.unsigned_abs(), b.unsigned_abs());
    let (x1, x0) = (x >> 64, x & LOW);
    let (y1, y0) = (y >> 64, y & LOW);
    let (p00, p01, p10, p11) = (x0 * y0, x0 * y1, x1 * y0, x1 * y1);
    let mid = (p00 >> 64) + (p01 & LOW) + (p10 & LOW);
    let low = (p00 & LOW) | (mid << 64);
    // |a|, |b| ≤ 2^127, so |a·b| ≤ 2^254 and the high half is below 2^127.
    let high = (p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64)) as i128;
    match ((a < 0) != (b < 0), low) {
        (false, _) => (high, low),
        // −(h·2^128 + l) = (−h − 1)·2^128 + (2^128 − l) for l > 0.
        (true, 0) => (-high, 0),
        (true, _) => (-high - 1, low.wrapping_neg()),
    }
}

/// The sign of the cross product u × v = u.x·v.y − u.y·v.x, as the
/// comparison of its two products.
#[inline]
pub(super) fn cross_sign(u: Point, v: Point) -> Ordering {
    match (u[0].checked_mul(v[1]), u[1].checked_mul(v[0])) {
        (Some(p), Some(q)) => p.cmp(&q),
        _ => wide_product(u[0], v[1]).cmp(&wide_product(u[1], v[0])),
    }
}

/// Whether the edge a→b of a clockwise triangle owns the samples on it:
/// production's own rule, which reads only the signs of the edge's
/// direction.
pub(super) fn edge_owned(a: Point, b: Point, rule: FillRule) -> bool {
    let sign = |k: usize| Fixed((b[k] - a[k]).signum() as i64);
    setup::edge_owned([Fixed(0), Fixed(0)], [sign(0), sign(1)], rule)
}

/// Whether the triangle `p` (one instant's vertices, in the case's order)
/// covers the sample `q`, as the static setup decides: nothing at zero area
/// or when the winding is culled; then, walked clockwise, every edge's
/// cross product with the sample is positive, or zero on an edge that
/// `owned(a, b)` gives the sample.
#[inline]
pub(super) fn triangle_covers(
    p: [Point; 3],
    q: Point,
    cull: Cull,
    owned: impl Fn(Point, Point) -> bool,
) -> bool {
    let clockwise = match cross_sign(sub(p[1], p[0]), sub(p[2], p[0])) {
        Ordering::Equal => return false,
        o => o == Ordering::Greater,
    };
    match cull {
        Cull::Clockwise if clockwise => return false,
        Cull::CounterClockwise if !clockwise => return false,
        _ => {}
    }
    let order = if clockwise { p } else { [p[0], p[2], p[1]] };
    (0..3).all(|i| {
        let (a, b) = (order[i], order[(i + 1) % 3]);
        match cross_sign(sub(b, a), sub(q, a)) {
            Ordering::Greater => true,
            Ordering::Equal => owned(a, b),
            Ordering::Less => false,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wide_products_order_as_the_products() {
        let values = [
            0i128,
            1,
            -1,
            3,
            -7,
            1 << 63,
            -(1 << 64) + 5,
            (1 << 100) + 12345,
            -(1 << 110),
            i128::MAX,
            i128::MIN + 1,
            i128::MIN,
        ];
        for &a in &values {
            for &b in &values {
                if let Some(p) = a.checked_mul(b) {
                    let low = p as u128;
                    let high = if p < 0 { -1 } else { 0 };
                    assert_eq!(wide_product(a, b), (high, low), "{a}·{b}");
                }
                for &c in &values {
                    for &d in &values {
                        let want = match (a.checked_mul(b), c.checked_mul(d)) {
                            (Some(p), Some(q)) => p.cmp(&q),
                            _ => continue,
                        };
                        assert_eq!(wide_product(a, b).cmp(&wide_product(c, d)), want);
                    }
                }
            }
        }
        // Beyond i128: 2^127 · 2^127 = 2^254, and its negation.
        assert_eq!(wide_product(i128::MIN, i128::MIN), (1 << 126, 0));
        // 2^127·(2^127 − 1) = (2^126 − 1)·2^128 + 2^127, negated.
        assert_eq!(wide_product(i128::MIN, i128::MAX), (-(1 << 126), 1 << 127));
        assert!(wide_product(1 << 100, 1 << 30) > wide_product((1 << 100) - 1, 1 << 30));
        assert!(wide_product(-(1 << 100), 1 << 30) < wide_product(-(1 << 100) + 1, 1 << 30));
    }

    /// The sign of a cross product beyond i128 (at 16 subpixel bits and
    /// coordinates near the limit) agrees with an exact big-integer one.
    #[test]
    fn cross_signs_beyond_i128_are_exact() {
        use dashu_int::IBig;
        let mut state = 0x1234_5678_9abc_def0u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let bound = 1i128 << DIFF_BITS;
        let mut wide = 0;
        for round in 0..20_000 {
            let mut draw = || {
                let r = (i128::from(next()) << 64 | i128::from(next())).rem_euclid(2 * bound);
                r - bound
            };
            let mut u = [draw(), draw()];
            let v = [draw(), draw()];
            if round % 3 == 0 {
                // Parallel, or nearly: the two products tie or differ by little.
                u = [v[0] * 3 / 5, v[1] * 3 / 5 + i128::from(round % 2)];
            }
            let big = |a: i128| IBig::from(a);
            let exact = (big(u[0]) * big(v[1]) - big(u[1]) * big(v[0])).cmp(&IBig::ZERO);
            assert_eq!(cross_sign(u, v), exact, "{u:?} × {v:?}");
            wide += usize::from(u[0].checked_mul(v[1]).is_none());
        }
        assert!(wide > 1000, "{wide} products beyond i128");
    }
}
