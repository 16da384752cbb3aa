//! Fixed-point coordinates and the bit-width limits that keep edge functions
//! from overflowing.

use std::ops::{Add, BitOr, Div, Mul, Rem, Sub};

use dashu_int::ops::{BitTest, PowerOfTwo};
use dashu_int::IBig;

use crate::scene::rules::limits;
use crate::scene::Number;

/// A fixed-point format with `frac_bits` fraction bits.
///
/// The production rasterizer works one bit finer than the snapping grid, so
/// that pixel centres, at odd multiples of 2^-(subpixel_bits+1), are
/// integers too: with 8 subpixel bits, coordinates are 16.9 fixed point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Format {
    pub frac_bits: u32,
}

/// A coordinate in some [`Format`]: `raw` units of 2^-frac_bits pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Fixed(pub i64);

/// Finest format: 16 subpixel bits plus the centre bit.
pub const MAX_FRAC_BITS: u32 = limits::MAX_SUBPIXEL_BITS + 1;

/// Bits of a coordinate's integer part, sign included: |x| ≤ 2^15 px.
const INT_BITS: u32 = limits::COORD_LIMIT.trailing_zeros() + 1;

/// Bits an edge function needs at `frac_bits`, sign included.
///
/// A coordinate is at most 2^(INT_BITS - 1 + f) units (|x| ≤ 2^15 px), so a
/// difference of two (vertex to vertex, or vertex to a sample inside the
/// canvas) is at most 2^(INT_BITS + f), a product of two differences at most
/// 2^(2(INT_BITS + f)), and an edge function, two products apart plus the tie
/// bias, at most 2^(2(INT_BITS + f) + 1) + 1. That takes 2(INT_BITS + f) + 2
/// bits of magnitude and one of sign: the "2b + 3 bits" of b-bit coordinates
/// (51 for 16.8).
pub const fn edge_bits(frac_bits: u32) -> u32 {
    2 * (INT_BITS + frac_bits) + 3
}

/// The finest format whose edge functions fit in i64.
pub const I64_MAX_FRAC_BITS: u32 = 14;
const _: () = assert!(edge_bits(I64_MAX_FRAC_BITS) <= 64);
const _: () = assert!(edge_bits(I64_MAX_FRAC_BITS + 1) > 64);
const _: () = assert!(edge_bits(MAX_FRAC_BITS) <= 128);
// Sample offsets never need a format finer than the finest.
const _: () = assert!(crate::scene::samples::limits::MAX_POSITION_BITS <= MAX_FRAC_BITS);
// Coordinates themselves always fit in i64.
const _: () = assert!(INT_BITS + MAX_FRAC_BITS < 63);

impl Format {
    /// The format for a scene snapped to `subpixel_bits`.
    pub fn snapped(subpixel_bits: u32) -> Format {
        Format {
            frac_bits: subpixel_bits + 1,
        }
    }

    /// Snaps `n` to the subpixel grid (ties to even) and returns it in this
    /// format.
    pub fn snap(self, n: &Number, subpixel_bits: u32) -> Fixed {
        let units = match small(n) {
            Some((p, q)) => snap_small(p, q, subpixel_bits),
            None => snap_big(n, subpixel_bits),
        };
        Fixed(units << (self.frac_bits - subpixel_bits))
    }

    /// `n` in this format when it is exactly representable.
    pub fn exact(self, n: &Number) -> Option<Fixed> {
        if let Some((p, q)) = small(n) {
            // p·2^f < 2^(63 + 17) and q < 2^63: i128 holds both.
            let scaled = i128::from(p) << self.frac_bits;
            let q = i128::from(q);
            return (scaled.rem_euclid(q) == 0)
                .then(|| Fixed(i64::try_from(scaled.div_euclid(q)).expect("bounded coordinates")));
        }
        let scaled = n.numerator() << self.frac_bits as usize;
        let q = IBig::from(n.denominator().clone());
        let (units, rest) = div_floor(&scaled, &q);
        (rest == IBig::ZERO).then(|| Fixed((&units).try_into().expect("bounded coordinates")))
    }

    /// The finest-needed format for unsnapped coordinates, when all of them
    /// are dyadic with at most MAX_FRAC_BITS - 1 fraction bits.
    pub fn for_exact<'a>(numbers: impl Iterator<Item = &'a Number>) -> Option<Format> {
        let mut frac_bits = 1;
        for n in numbers {
            let d = n.denominator();
            if !d.is_power_of_two() {
                return None;
            }
            frac_bits = frac_bits.max(d.bit_len() as u32); // 2^k has k+1 bits
        }
        (frac_bits <= MAX_FRAC_BITS).then_some(Format { frac_bits })
    }

    /// This format, made fine enough to hold sample offsets that are
    /// multiples of 2^-position_bits pixel as integers. Snapping is
    /// unchanged ([`Format::snap`] shifts by `frac_bits − subpixel_bits`),
    /// and position_bits ≤ MAX_POSITION_BITS ≤ [`MAX_FRAC_BITS`] (asserted
    /// above), so the result is never finer than the finest format and the
    /// edge-function bounds above hold.
    pub fn with_samples(self, position_bits: u32) -> Format {
        Format {
            frac_bits: self.frac_bits.max(position_bits),
        }
    }

    /// Units per pixel.
    pub fn one(self) -> i64 {
        1 << self.frac_bits
    }

    /// The centre of pixel column or row `i`.
    pub fn centre(self, i: i64) -> Fixed {
        Fixed((i << self.frac_bits) + (1 << (self.frac_bits - 1)))
    }

    /// Whether edge functions fit in i64 at this format.
    pub fn fits_i64(self) -> bool {
        self.frac_bits <= I64_MAX_FRAC_BITS
    }
}

/// (numerator, denominator) of `n` when both are below 2^63: the common
/// case, snapped in i128.
#[inline]
fn small(n: &Number) -> Option<(i64, i64)> {
    let p = i64::try_from(n.numerator()).ok()?;
    let q = i64::try_from(n.denominator()).ok()?;
    Some((p, q))
}

/// round(p·2^b / q), ties to even, as ⌊(2p·2^b + q) / 2q⌋, with the result
/// made even again where the division was an exact tie. With |p|, q below
/// 2^63 and b ≤ 16, every intermediate is below 2^81.
fn snap_small(p: i64, q: i64, subpixel_bits: u32) -> i64 {
    let q = i128::from(q);
    let twice = (i128::from(p) << (subpixel_bits + 1)) + q;
    let two_q = 2 * q;
    let mut rounded = twice.div_euclid(two_q);
    if twice.rem_euclid(two_q) == 0 && rounded.rem_euclid(2) != 0 {
        rounded -= 1;
    }
    i64::try_from(rounded).expect("coordinates are bounded by COORD_LIMIT")
}

/// [`snap_small`] for any size, in big integers.
fn snap_big(n: &Number, subpixel_bits: u32) -> i64 {
    let p = n.numerator();
    let q = IBig::from(n.denominator().clone());
    let twice = (p << (subpixel_bits as usize + 1)) + &q;
    let two_q = &q * IBig::from(2u8);
    let (mut rounded, rest) = div_floor(&twice, &two_q);
    if rest == IBig::ZERO && (&rounded % IBig::from(2u8)) != IBig::ZERO {
        rounded -= IBig::ONE;
    }
    (&rounded)
        .try_into()
        .expect("coordinates are bounded by COORD_LIMIT")
}

fn div_floor(a: &IBig, b: &IBig) -> (IBig, IBig) {
    let mut q = a / b;
    let mut r = a - &q * b;
    if r < IBig::ZERO {
        q -= IBig::ONE;
        r += b;
    }
    (q, r)
}

/// Integers an edge function can be held in: i64 where
/// [`Format::fits_i64`], i128 otherwise.
pub trait EdgeInt:
    Copy
    + Ord
    + Default
    + From<i64>
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Rem<Output = Self>
    + BitOr<Output = Self>
    + Send
    + Sync
{
    fn to_f64(self) -> f64;

    /// The value as an i64, which it must fit (a pixel position).
    fn to_i64(self) -> i64;

    /// Euclidean quotient and remainder: `self = q·d + r` with
    /// `0 ≤ r < |d|`.
    #[inline]
    fn div_rem_euclid(self, d: Self) -> (Self, Self) {
        // One hardware division for both, then the remainder made
        // non-negative (`div_euclid` and `rem_euclid` would divide twice).
        let (q, r) = (self / d, self % d);
        let (zero, one) = (Self::default(), Self::from(1));
        if r < zero {
            if d > zero {
                (q - one, r + d)
            } else {
                (q + one, r - d)
            }
        } else {
            (q, r)
        }
    }
}

impl EdgeInt for i64 {
    fn to_f64(self) -> f64 {
        self as f64
    }

    #[inline]
    fn to_i64(self) -> i64 {
        self
    }
}

impl EdgeInt for i128 {
    fn to_f64(self) -> f64 {
        self as f64
    }

    #[inline]
    fn to_i64(self) -> i64 {
        i64::try_from(self).expect("a pixel position fits in i64")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn euclidean_division_is_exact() {
        // Against i128's: near 2^52, near whole quotients, negative
        // dividends and divisors, and the whole i64 range. (A float
        // estimate corrected by the exact remainder was tried, and was
        // slower: without SSE4.1, `floor` is a library call.)
        let mut x = 0x6469_7669_6465_u64;
        let mut next = move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let edge = 1i64 << 52;
        let mut checked = 0;
        for _ in 0..200_000 {
            let d = match next() % 4 {
                0 => (next() % 1000) as i64 + 1,
                1 => edge - 1 - (next() % 1000) as i64,
                2 => (next() >> 12) as i64 + 1,
                _ => (next() >> 2) as i64 + 1,
            };
            let n = match next() % 4 {
                0 => (next() >> 11) as i64 - (1 << 52),
                1 => {
                    // q·d - 1, q·d, q·d + 1 for a q that keeps them in range.
                    let q = (next() % (edge as u64 / d as u64 + 1)) as i64;
                    q.saturating_mul(d) + (next() % 3) as i64 - 1
                }
                2 => edge - 1 - (next() % 3) as i64,
                _ => next() as i64,
            };
            let (q, r) = n.div_rem_euclid(d);
            let want = (
                i128::from(n).div_euclid(i128::from(d)),
                i128::from(n).rem_euclid(i128::from(d)),
            );
            assert_eq!((i128::from(q), i128::from(r)), want, "{n} / {d}");
            let (q, r) = n.div_rem_euclid(-d);
            let want = (
                i128::from(n).div_euclid(-i128::from(d)),
                i128::from(n).rem_euclid(-i128::from(d)),
            );
            assert_eq!((i128::from(q), i128::from(r)), want, "{n} / -{d}");
            checked += 1;
        }
        assert_eq!(checked, 200_000);
    }

    #[test]
    fn snapping_ties_go_to_even() {
        let f = Format::snapped(0);
        let n = |s: &str| Number::from_string(s).unwrap();
        assert_eq!(f.snap(&n("0.5"), 0), Fixed(0));
        assert_eq!(f.snap(&n("1.5"), 0), Fixed(4));
        assert_eq!(f.snap(&n("2.5"), 0), Fixed(4));
        assert_eq!(f.snap(&n("-0.5"), 0), Fixed(0));
        assert_eq!(f.snap(&n("-1.5"), 0), Fixed(-4));
        assert_eq!(f.snap(&n("-1.25"), 0), Fixed(-2));
        let f8 = Format::snapped(8);
        assert_eq!(f8.snap(&n("1/3"), 8), Fixed(85 * 2));
        assert_eq!(f8.snap(&n("32768"), 8), Fixed(32768 << 9));
    }

    /// The i128 path snaps as the big-integer one on random ratios,
    /// ties and both signs included; a path that rounded ties away from
    /// zero would differ on the ties.
    #[test]
    fn small_snapping_is_big_snapping() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut ties = 0;
        for round in 0..20_000 {
            let bits = (next() % 17) as u32;
            let q = match round % 3 {
                0 => 1i64 << (next() % 20),
                1 => (next() % 1000) as i64 + 1,
                _ => (next() >> 2) as i64 % (1 << 40) + 1,
            };
            let limit = (1i64 << 14) * q.min(1 << 40);
            let p = (next() % (2 * limit as u64)) as i64 - limit;
            let n = Number::ratio(p, q);
            let (sp, sq) = small(&n).unwrap();
            assert_eq!(
                snap_small(sp, sq, bits),
                snap_big(&n, bits),
                "{p}/{q} at {bits}"
            );
            ties += i32::from(
                (i128::from(sp) << (bits + 1)).rem_euclid(i128::from(2 * sq)) == i128::from(sq),
            );
            let f = Format {
                frac_bits: bits + 1,
            };
            let big_exact = {
                let scaled = n.numerator() << f.frac_bits as usize;
                let q = IBig::from(n.denominator().clone());
                let (units, rest) = div_floor(&scaled, &q);
                (rest == IBig::ZERO).then(|| Fixed((&units).try_into().unwrap()))
            };
            assert_eq!(f.exact(&n), big_exact, "{p}/{q}");
        }
        assert!(ties > 100, "{ties} ties");
    }

    #[test]
    fn exact_formats_need_dyadic_coordinates() {
        let n = |s: &str| Number::from_string(s).unwrap();
        let dyadic = [n("1/4"), n("3"), n("-5/1024")];
        assert_eq!(
            Format::for_exact(dyadic.iter()),
            Some(Format { frac_bits: 11 })
        );
        assert_eq!(Format::for_exact([n("0.1")].iter()), None);
    }
}
