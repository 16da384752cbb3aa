//! Exact arithmetic for the oracle: snapping, the integer grid, an i128 fast
//! path with a proven bound and a big-integer fallback, and rounding of exact
//! values to floats.
//!
//! Nothing here uses a float except the final rounding of a finished exact
//! value for output.

use dashu_int::ops::{BitTest, UnsignedAbs};
use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

use crate::scene::Number;

/// Rounds `n` to the nearest multiple of 2^-bits, ties to even
/// (D3D11.3 §3.2.4.1 rounds to nearest-even when it snaps to 16.8).
pub fn snap(n: &Number, bits: u32) -> RBig {
    n.snapped(bits).as_rbig().clone()
}

/// ⌊a / b⌋ for b > 0.
pub fn floor_div(a: &IBig, b: &IBig) -> IBig {
    debug_assert!(*b > IBig::ZERO);
    let q = a / b;
    if &q * b > *a {
        q - IBig::ONE
    } else {
        q
    }
}

/// ⌈a / b⌉ for b > 0.
pub fn ceil_div(a: &IBig, b: &IBig) -> IBig {
    -floor_div(&-a, b)
}

/// Integers the oracle computes with: `i128` where a bound proves that no
/// intermediate can overflow, [`IBig`] otherwise.
pub trait ExactInt: Clone + Ord + std::fmt::Debug {
    fn zero() -> Self;
    fn sub(&self, other: &Self) -> Self;
    fn mul(&self, other: &Self) -> Self;
    fn to_ibig(&self) -> IBig;
    fn signum(&self) -> i32 {
        match self.cmp(&Self::zero()) {
            std::cmp::Ordering::Less => -1,
            std::cmp::Ordering::Equal => 0,
            std::cmp::Ordering::Greater => 1,
        }
    }
}

/// The largest |grid coordinate| for which the i128 path is used.
///
/// The oracle's deepest expression is an orientation,
/// `(bx - ax)(py - ay) - (by - ay)(px - ax)`. With every coordinate below
/// 2^60 in magnitude, each difference is below 2^61, each product below
/// 2^122, and the result below 2^123: inside i128 with 4 bits to spare.
pub const I128_COORD_BOUND: u32 = 60;
const _: () = assert!(2 * (I128_COORD_BOUND + 1) + 1 < 127);

impl ExactInt for i128 {
    fn zero() -> Self {
        0
    }
    fn sub(&self, other: &Self) -> Self {
        self.checked_sub(*other)
            .expect("i128 bound proven by I128_COORD_BOUND")
    }
    fn mul(&self, other: &Self) -> Self {
        self.checked_mul(*other)
            .expect("i128 bound proven by I128_COORD_BOUND")
    }
    fn to_ibig(&self) -> IBig {
        IBig::from(*self)
    }
}

impl ExactInt for IBig {
    fn zero() -> Self {
        IBig::ZERO
    }
    fn sub(&self, other: &Self) -> Self {
        self - other
    }
    fn mul(&self, other: &Self) -> Self {
        self * other
    }
    fn to_ibig(&self) -> IBig {
        self.clone()
    }
}

/// Whether `v` fits the i128 fast path.
pub fn fits_fast_path(v: &IBig) -> bool {
    let bound = IBig::ONE << I128_COORD_BOUND as usize;
    *v < bound && *v > -bound
}

/// Rounds an exact value to f64 with round-to-odd: truncate, and set the
/// last bit when anything was dropped.
///
/// The result is within one f64 ulp of `q`, and rounding it to f32 with
/// round-half-even (Rust's `as f32`) gives the correctly rounded f32 of `q`,
/// because f64 carries at least 2 more bits than twice f32's 24 (S. Boldo and
/// G. Melquiond, "Emulation of FMA and correctly rounded sums: proved
/// algorithms using rounding to odd", IEEE TC 2008).
pub fn to_f64_round_odd(q: &RBig) -> f64 {
    quotient_to_f64_round_odd(q.numerator(), &IBig::from(q.denominator().clone()))
}

/// [`to_f64_round_odd`] of num / den, for any den ≠ 0 (0 for den = 0):
/// the fraction need not be in lowest terms, so callers skip the gcd.
pub fn quotient_to_f64_round_odd(num: &IBig, den: &IBig) -> f64 {
    if *num == IBig::ZERO || *den == IBig::ZERO {
        return 0.0;
    }
    let negative = (*num < IBig::ZERO) != (*den < IBig::ZERO);
    let n: UBig = num.unsigned_abs();
    let d: &UBig = &den.unsigned_abs();
    // Choose e with 2^52 <= n / (d 2^e) < 2^53, or the subnormal exponent.
    let mut e = n.bit_len() as i64 - d.bit_len() as i64 - 53;
    e = e.max(-1074);
    loop {
        let (m, exact) = shifted_quotient(&n, d, e);
        if m.bit_len() > 53 {
            e += 1;
            continue;
        }
        let mut m: u64 = m.try_into().unwrap();
        if !exact {
            m |= 1;
        }
        let half = e / 2;
        let magnitude = (m as f64) * 2f64.powi(half as i32) * 2f64.powi((e - half) as i32);
        return if negative { -magnitude } else { magnitude };
    }
}

/// ⌊n / (d · 2^e)⌋ and whether the division was exact.
fn shifted_quotient(n: &UBig, d: &UBig, e: i64) -> (UBig, bool) {
    let (num, den) = if e >= 0 {
        (n.clone(), d << e as usize)
    } else {
        (n << (-e) as usize, d.clone())
    };
    let m = &num / &den;
    let exact = &m * &den == num;
    (m, exact)
}

/// The correctly rounded f32 of an exact value (round half to even).
pub fn to_f32(q: &RBig) -> f32 {
    to_f64_round_odd(q) as f32
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> RBig {
        RBig::from_parts_signed(n.into(), d.into())
    }

    #[test]
    fn snapping_rounds_half_to_even() {
        let n = |s: &str| Number::from_string(s).unwrap();
        assert_eq!(snap(&n("0.5"), 0), RBig::ZERO);
        assert_eq!(snap(&n("1.5"), 0), RBig::from(2u8));
        assert_eq!(snap(&n("-0.5"), 0), RBig::ZERO);
        assert_eq!(snap(&n("-1.5"), 0), RBig::from(-2i8));
        assert_eq!(snap(&n("1/3"), 8), q(85, 256));
        assert_eq!(snap(&n("2/3"), 8), q(171, 256));
        // Half a subpixel: 1/512 at 8 bits rounds to 0, 3/512 to 4/512.
        assert_eq!(snap(&n("1/512"), 8), RBig::ZERO);
        assert_eq!(snap(&n("3/512"), 8), q(2, 256));
    }

    #[test]
    fn round_to_odd_then_f32_is_correctly_rounded() {
        // Cross-check against dashu's correctly rounded conversion.
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for _ in 0..20_000 {
            let n = (next() >> (next() % 60)) as i64 * if next() % 2 == 0 { 1 } else { -1 };
            let d = (next() >> (next() % 62)).max(1) as i64 & i64::MAX;
            let value = q(n, d.max(1));
            assert_eq!(to_f32(&value), value.to_f32().value(), "{n}/{d}");
            let f = to_f64_round_odd(&value);
            let nearest = value.to_f64().value();
            assert!(
                (f - nearest).abs() <= f64::EPSILON * nearest.abs(),
                "{n}/{d}"
            );
        }
    }

    #[test]
    fn f32_midpoints_round_to_even() {
        // 1 + 2^-24 lies exactly halfway between two f32s; ties go to even (1.0).
        let half_ulp = q(1, 1 << 24);
        assert_eq!(to_f32(&(RBig::ONE + half_ulp.clone())), 1.0);
        // A hair above the midpoint rounds up, even though f64 would hold it.
        let above = RBig::ONE + half_ulp + RBig::from_parts(1.into(), UBig::ONE << 80);
        assert_eq!(to_f32(&above), 1.0 + f32::EPSILON);
    }
}
