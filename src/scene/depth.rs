//! Depth formats and polygon offset (SPEC.md §18): the names a case gives
//! them, the format's grid, and the ranges the specifications leave to an
//! implementation (the minimum resolvable difference r).
//!
//! Names, numbers and the grid's exact arithmetic only, as everywhere in
//! `scene/`: the reference and production each apply the rules on their
//! own. The grid lives here because a candidate's readback is judged on
//! it (`metrics`) and both rasterizers write onto it.

use dashu_int::ops::{BitTest, UnsignedAbs};
use dashu_int::IBig;
use dashu_ratio::RBig;

use super::number::Number;

/// The default interpolation bound relative to a channel's largest vertex
/// magnitude M: 2^-16 · max(1, M) (SPEC.md §6.3).
pub const RELATIVE_BOUND: f64 = 1.0 / 65536.0;

/// How the depth written at a sample is stored (`rules.depth_format`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthFormat {
    /// The exact depth, judged by SPEC.md §6.3 (every case before §18).
    Exact,
    /// `VK_FORMAT_D16_UNORM`: clamped to [0, 1], stored as k/(2^16 − 1).
    Unorm16,
    /// `VK_FORMAT_X8_D24_UNORM_PACK32`: clamped to [0, 1], stored as
    /// k/(2^24 − 1).
    Unorm24,
    /// `VK_FORMAT_D32_SFLOAT`: clamped to [0, 1], stored as an f32.
    Float32,
}

case_names!(DepthFormat {
    Exact => "exact",
    Unorm16 => "unorm16",
    Unorm24 => "unorm24",
    Float32 => "float32",
});

impl DepthFormat {
    /// The bits n of a unorm format; `None` for the others.
    pub fn unorm_bits(self) -> Option<u32> {
        match self {
            DepthFormat::Unorm16 => Some(16),
            DepthFormat::Unorm24 => Some(24),
            DepthFormat::Exact | DepthFormat::Float32 => None,
        }
    }
}

/// Polygon offset (`rules.depth_bias`, Vulkan's depth bias): o = m·slope +
/// r·constant, clamped by `clamp` (SPEC.md §18.2). Exact numbers, as read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DepthBias {
    pub constant: Number,
    pub slope: Number,
    /// 0: no clamp; > 0: o ≤ clamp; < 0: o ≥ clamp.
    pub clamp: Number,
}

/// The grid of an n-bit unorm format: the value k/(2^n − 1) a stored k
/// reads back as, as an f32.
///
/// k/(2^n − 1) is computed as one f64 division of two exact integers and
/// narrowed to f32, and that is the correctly rounded f32 of the exact
/// quotient (for n ≤ 24): a double rounding goes wrong only when the f64
/// quotient lands on an f32 midpoint (25 significant bits) that the exact
/// quotient is not. With N = 2^n − 1 odd, k/N is a dyadic rational only
/// for k ∈ {0, N}; otherwise |k/N − j·2^-e| = |k·2^e − j·N|/(N·2^e) ≥
/// 1/(N·2^e) > 2^-24 · 2^-e, more than half an f64 ulp (2^-53 relative)
/// from every f32 midpoint of the binade.
pub fn unorm_value(k: u32, bits: u32) -> f32 {
    debug_assert!(bits <= 24 && u64::from(k) < (1u64 << bits));
    (f64::from(k) / f64::from((1u32 << bits) - 1)) as f32
}

/// The k whose grid value is `value` exactly, if `value` is on the n-bit
/// grid: k is ⌊value·N⌋ or ⌊value·N⌋ + 1 (value·N is exact in f64: 24
/// bits times at most 24 bits), and the grid values are more than an f32
/// ulp apart, so no other k can round to `value`.
pub fn unorm_index(value: f64, bits: u32) -> Option<u32> {
    let n = f64::from((1u32 << bits) - 1);
    if !(0.0..=1.0).contains(&value) || f64::from(value as f32) != value {
        return None;
    }
    let below = (value * n).floor() as u32;
    [below, below + 1]
        .into_iter()
        .find(|&k| f64::from(k) <= n && f64::from(unorm_value(k, bits)) == value)
}

/// The range [r_low, r_high] of the minimum resolvable difference r
/// (SPEC.md §18.2) for a primitive whose largest |depth| is `largest`:
/// - unorm n: [2^-n, 2^(1-n)] (Vulkan: "at most 2 × 2^-n"; it covers the
///   2^-n and the 1/(2^n − 1) implementations use);
/// - float32: [2^(e−23), 2^(e−22)], e the exponent of `largest` (2^e ≤
///   largest < 2^(e+1), at least −126): the specifications' 2^(e−n)
///   read both ways, as drivers do ("the exponent" of a depth in
///   [2^e, 2^(e+1)) taken as e or e + 1);
/// - exact: none (the reader refuses `depth_bias` without a format).
pub fn resolvable_difference(format: DepthFormat, largest: &RBig) -> Option<[RBig; 2]> {
    let power = |e: i64| {
        if e >= 0 {
            RBig::from(IBig::ONE << e as usize)
        } else {
            RBig::from_parts(IBig::ONE, dashu_int::UBig::ONE << (-e) as usize)
        }
    };
    match format {
        DepthFormat::Exact => None,
        DepthFormat::Unorm16 | DepthFormat::Unorm24 => {
            let n = i64::from(format.unorm_bits().expect("unorm"));
            Some([power(-n), power(1 - n)])
        }
        DepthFormat::Float32 => {
            let e = exponent(largest).max(-126);
            Some([power(e - 23), power(e - 22)])
        }
    }
}

/// The e with 2^e ≤ |q| < 2^(e+1); −126 for q = 0.
pub fn exponent(q: &RBig) -> i64 {
    if *q == RBig::ZERO {
        return -126;
    }
    let num = &q.numerator().clone().unsigned_abs();
    let den = q.denominator();
    let mut e = num.bit_len() as i64 - den.bit_len() as i64;
    // 2^(e-1) < |q| < 2^(e+1): step down once if |q| < 2^e.
    let at = |e: i64| -> bool {
        // |q| ≥ 2^e ?
        if e >= 0 {
            num >= &(den << e as usize)
        } else {
            &(num << (-e) as usize) >= den
        }
    };
    if !at(e) {
        e -= 1;
    }
    e
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grid_reads_back_exactly() {
        for bits in [16, 24] {
            let n = (1u32 << bits) - 1;
            for k in [0, 1, 2, 3, n / 3, n / 2, n / 2 + 1, n - 2, n - 1, n] {
                let v = f64::from(unorm_value(k, bits));
                assert_eq!(unorm_index(v, bits), Some(k), "k = {k}, bits = {bits}");
                if k > 0 {
                    let exact = RBig::from_parts(k.into(), n.into());
                    assert_eq!(unorm_value(k, bits), nearest(&exact));
                }
            }
            assert_eq!(unorm_index(0.3, bits), None);
        }
    }

    /// The correctly rounded f32 of q by exact comparison with its
    /// neighbours, for the test above.
    fn nearest(q: &RBig) -> f32 {
        let guess = q.to_f32().value();
        let exact = |f: f32| RBig::try_from(f).expect("finite");
        let [down, up] = [guess.to_bits() - 1, guess.to_bits() + 1].map(f32::from_bits);
        let d = |f: f32| {
            let e = exact(f) - q;
            if e < RBig::ZERO {
                -e
            } else {
                e
            }
        };
        assert!(d(guess) <= d(down) && d(guess) <= d(up));
        guess
    }

    #[test]
    fn exponents() {
        let q = |n: i64, d: u64| RBig::from_parts(n.into(), d.into());
        assert_eq!(exponent(&q(1, 1)), 0);
        assert_eq!(exponent(&q(3, 4)), -1);
        assert_eq!(exponent(&q(1, 2)), -1);
        assert_eq!(exponent(&q(-5, 1)), 2);
        assert_eq!(exponent(&q(1023, 1024)), -1);
    }
}
