//! Depth formats and polygon offset, exact (SPEC.md §18).
//!
//! For each covered sample the reference knows the exact depth before the
//! format: an interval [lo, hi] when the primitive is offset (the offset o
//! may be any value the specifications allow, §18.2), a point otherwise.
//! From it [`DepthRules::store`] derives what a candidate may read back:
//! the depths within ε (§6.3) of the interval clamped to [0, 1], on the
//! format's grid for a unorm format. That set is an interval of f64s whose
//! ends are exact (the tightest f64 bounds of exact rationals, or grid
//! values), so that judging an f32 readback against it decides exactly.
//! The golden file keeps one value per sample: the stored value of the
//! interval's midpoint.
//!
//! The slope term needs m = √((∂z/∂x)² + (∂z/∂y)²), an irrational: its
//! upper end is bounded by a rational from a big-integer square root, and
//! the bound is certified (`sqrt_bounds`).

use dashu_int::ops::{SquareRoot, UnsignedAbs};
use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

use super::exact::to_f64_round_odd;
use crate::scene::depth::{resolvable_difference, unorm_value, DepthBias, DepthFormat};
use crate::scene::{Primitive, Scene};

/// Bits of the rational bounds of √x below the binary point: the upper
/// bound exceeds √x by at most 2^-SQRT_BITS / q (x = p/q), so the slope
/// term's interval is widened by at most |slope|·2^-96, never narrowed.
pub const SQRT_BITS: usize = 96;

/// The depth rules of a scene, with what every sample's judgement needs.
pub struct DepthRules {
    format: DepthFormat,
    /// ε of SPEC.md §6.3, exact (the f64 the metrics use).
    epsilon: RBig,
    /// Each primitive's offset interval [o_lo, o_hi] in screen space
    /// (`None` for what is not offset: lines, and every primitive when
    /// the case has no `depth_bias`); clip-space pieces get theirs from
    /// `clip::visit`.
    offsets: Vec<Option<[RBig; 2]>>,
}

/// What the reference writes and allows at a sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stored {
    /// The stored value of the interval's midpoint: the golden file's.
    pub value: f64,
    /// The readbacks allowed, both ends included; an f64 c lies in it
    /// exactly when its exact value does.
    pub allowed: [f64; 2],
}

impl DepthRules {
    /// The rules of `scene`, or `None` when its depth is `exact` (judged
    /// by §6.3 against the exact value, as before §18).
    pub fn new(scene: &Scene) -> Option<DepthRules> {
        if scene.rules.depth_format == DepthFormat::Exact {
            return None;
        }
        let epsilon = RBig::try_from(scene.depth_tolerance()).expect("a finite tolerance");
        let offsets = scene
            .primitives
            .iter()
            .map(|p| match (p, &scene.rules.depth_bias) {
                (Primitive::Triangle(t), Some(bias)) if !scene.in_clip_space() => {
                    let bits = scene.rules.subpixel_bits;
                    let v = t.vertices.each_ref().map(|v| {
                        let snap = |n: &crate::scene::Number| match bits {
                            Some(b) => n.snapped(b).as_rbig().clone(),
                            None => n.as_rbig().clone(),
                        };
                        [snap(&v.x), snap(&v.y), v.z.as_rbig().clone()]
                    });
                    let largest = v.iter().map(|p| abs(&p[2])).max().expect("three");
                    Some(match plane_gradient(&v) {
                        Some(g) => offset_interval(bias, scene.rules.depth_format, &g, &largest),
                        // A triangle of no area covers nothing.
                        None => [RBig::ZERO, RBig::ZERO],
                    })
                }
                _ => None,
            })
            .collect();
        Some(DepthRules {
            format: scene.rules.depth_format,
            epsilon,
            offsets,
        })
    }

    /// The screen-space offset interval of primitive `index`, if it is
    /// offset.
    pub fn offset(&self, index: usize) -> Option<&[RBig; 2]> {
        self.offsets[index].as_ref()
    }

    /// What a sample whose exact depth before the format lies in
    /// `[lo, hi]` stores and allows (SPEC.md §18.1): clamped to [0, 1],
    /// widened by ε, and for unorm n the grid values k/(2^n − 1) from the
    /// one at or below the low end to the one at or above the high end
    /// ("one of the two integers closest", Vulkan's conversion to
    /// normalized fixed point, at each end).
    pub fn store(&self, [lo, hi]: [&RBig; 2]) -> Stored {
        let unit = |q: &RBig| q.clone().clamp(RBig::ZERO, RBig::ONE);
        let (lo, hi) = (unit(lo), unit(hi));
        let mid = (&lo + &hi) / RBig::from(2);
        let (low, high) = (&lo - &self.epsilon, &hi + &self.epsilon);
        match self.format.unorm_bits() {
            Some(bits) => {
                let top = (1u32 << bits) - 1;
                let n = RBig::from(top);
                let index = |k: IBig| -> u32 {
                    let k = k.clamp(IBig::ZERO, IBig::from(top));
                    u32::try_from(k).expect("within [0, 2^24)")
                };
                let k_lo = index((&low * &n).floor());
                let k_hi = index((&high * &n).ceil());
                // The midpoint's nearest grid value, ties up.
                let half = RBig::from_parts(IBig::ONE, UBig::from(2u8));
                let k_mid = index((&mid * &n + half).floor());
                let grid = |k| f64::from(unorm_value(k, bits));
                Stored {
                    value: grid(k_mid),
                    allowed: [grid(k_lo), grid(k_hi)],
                }
            }
            None => Stored {
                value: to_f64_round_odd(&mid),
                allowed: [f64_below(&low), f64_above(&high)],
            },
        }
    }
}

/// |q|.
fn abs(q: &RBig) -> RBig {
    if *q < RBig::ZERO {
        -q.clone()
    } else {
        q.clone()
    }
}

/// The gradient (∂z/∂x, ∂z/∂y) of the plane through three points (x, y,
/// z) on the screen, exact; `None` when they are collinear on the screen.
pub fn plane_gradient(v: &[[RBig; 3]; 3]) -> Option<[RBig; 2]> {
    let d = |i: usize, k: usize| &v[i][k] - &v[0][k];
    let det = d(1, 0) * d(2, 1) - d(2, 0) * d(1, 1);
    if det == RBig::ZERO {
        return None;
    }
    let gx = (d(1, 2) * d(2, 1) - d(2, 2) * d(1, 1)) / &det;
    let gy = (d(1, 0) * d(2, 2) - d(2, 0) * d(1, 2)) / &det;
    Some([gx, gy])
}

/// The interval of the offset o = m·slope + r·constant over every m in
/// [max(|gx|, |gy|), √(gx² + gy²)] and r in the format's range
/// ([`resolvable_difference`], `largest` the primitive's largest |depth|),
/// clamped as `bias.clamp` says (SPEC.md §18.2). Both terms are linear in
/// their variable, so the ends are attained at the ends of the ranges; the
/// clamp is monotone, so it maps the ends to the ends.
pub fn offset_interval(
    bias: &DepthBias,
    format: DepthFormat,
    gradient: &[RBig; 2],
    largest: &RBig,
) -> [RBig; 2] {
    let [gx, gy] = gradient.each_ref().map(abs);
    let m_low = gx.clone().max(gy.clone());
    let [_, m_high] = sqrt_bounds(&(&gx * &gx + &gy * &gy));
    let r = resolvable_difference(format, largest).expect("depth_bias needs a format");
    let ends = |a: [RBig; 2], factor: &RBig| {
        let [p, q] = a.map(|x| x * factor);
        if p <= q {
            [p, q]
        } else {
            [q, p]
        }
    };
    let [s_lo, s_hi] = ends([m_low, m_high], bias.slope.as_rbig());
    let [c_lo, c_hi] = ends(r, bias.constant.as_rbig());
    let clamp = bias.clamp.as_rbig();
    let clamped = |o: RBig| {
        if *clamp > RBig::ZERO {
            o.min(clamp.clone())
        } else if *clamp < RBig::ZERO {
            o.max(clamp.clone())
        } else {
            o
        }
    };
    [clamped(s_lo + c_lo), clamped(s_hi + c_hi)]
}

/// Rational bounds [lo, hi] of √x for x = p/q ≥ 0: with s = ⌊√(p·q·4^b)⌋
/// (b = [`SQRT_BITS`]), lo = s/(q·2^b) and hi = (s + 1)/(q·2^b), or hi =
/// lo when s² = p·q·4^b (x is a perfect square, its root exact). The
/// certificate lo² ≤ x ≤ hi² is checked exactly before they are returned.
///
/// # Panics
/// When x < 0, or (never) when the certificate fails.
pub fn sqrt_bounds(x: &RBig) -> [RBig; 2] {
    assert!(*x >= RBig::ZERO, "√ of a negative number");
    let p = x.numerator().clone().unsigned_abs();
    let q = x.denominator().clone();
    let s = ((&p * &q) << (2 * SQRT_BITS)).sqrt();
    let den = IBig::from(&q << SQRT_BITS);
    // A perfect square's root is exact: both ends are it (SPEC.md §18.2's
    // m of a gradient along an axis, zero included).
    let exact = &s * &s == (&p * &q) << (2 * SQRT_BITS);
    let lo = RBig::from_parts_signed(IBig::from(s.clone()), den.clone());
    let hi = if exact {
        lo.clone()
    } else {
        RBig::from_parts_signed(IBig::from(s + UBig::ONE), den)
    };
    assert!(
        &lo * &lo <= *x && *x <= &hi * &hi,
        "the square root's certificate failed"
    );
    [lo, hi]
}

/// The largest f64 at or below q.
pub fn f64_below(q: &RBig) -> f64 {
    let v = to_f64_round_odd(q);
    if RBig::try_from(v).expect("finite") > *q {
        v.next_down()
    } else {
        v
    }
}

/// The smallest f64 at or above q.
pub fn f64_above(q: &RBig) -> f64 {
    let v = to_f64_round_odd(q);
    if RBig::try_from(v).expect("finite") < *q {
        v.next_up()
    } else {
        v
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: u64) -> RBig {
        RBig::from_parts(n.into(), d.into())
    }

    #[test]
    fn square_roots_are_certified_and_tight() {
        for x in [q(0, 1), q(1, 1), q(2, 1), q(1, 3), q(10_000, 7), q(2, 9)] {
            let [lo, hi] = sqrt_bounds(&x);
            assert!(&lo * &lo <= x && x <= &hi * &hi);
            assert!(&hi - &lo <= q(1, 1) / RBig::from(IBig::ONE << SQRT_BITS));
        }
        // A perfect square's root is both of its bounds, exactly (the upper
        // one was (s + 1)/(q·2^b) before, so a zero gradient had m up to
        // 2^-96 and a unorm24 depth at 1/2 could store 8388607).
        assert_eq!(sqrt_bounds(&q(9, 4)), [q(3, 2), q(3, 2)]);
        assert_eq!(sqrt_bounds(&q(0, 1)), [q(0, 1), q(0, 1)]);
        assert_eq!(sqrt_bounds(&q(1, 1)), [q(1, 1), q(1, 1)]);
        let [lo, hi] = sqrt_bounds(&q(2, 1));
        assert!(lo < hi);
    }

    #[test]
    fn a_plane_along_an_axis_has_an_exact_offset() {
        let bias = DepthBias {
            constant: crate::scene::Number::ZERO,
            slope: crate::scene::Number::ONE,
            clamp: crate::scene::Number::ZERO,
        };
        // A flat plane: m = 0 exactly, so the offset is 0 exactly.
        let zero = offset_interval(&bias, DepthFormat::Float32, &[q(0, 1), q(0, 1)], &q(1, 2));
        assert_eq!(zero, [q(0, 1), q(0, 1)]);
        // z = -3x/4: m = 3/4 exactly.
        let along = offset_interval(&bias, DepthFormat::Float32, &[q(-3, 4), q(0, 1)], &q(1, 2));
        assert_eq!(along, [q(3, 4), q(3, 4)]);
    }

    #[test]
    fn directed_f64_bounds_are_tight() {
        for x in [q(1, 3), q(-1, 3), q(1, 2), q(2, 7)] {
            let (b, a) = (f64_below(&x), f64_above(&x));
            assert!(RBig::try_from(b).unwrap() <= x && x <= RBig::try_from(a).unwrap());
            assert!(a == b || a == b.next_up());
        }
    }

    #[test]
    fn a_45_degree_plane_allows_m_from_max_to_root_two() {
        // z = x + y: m ranges over [1, √2].
        let v = [
            [q(0, 1), q(0, 1), q(0, 1)],
            [q(1, 1), q(0, 1), q(1, 1)],
            [q(0, 1), q(1, 1), q(1, 1)],
        ];
        let g = plane_gradient(&v).unwrap();
        assert_eq!(g, [q(1, 1), q(1, 1)]);
        let bias = DepthBias {
            constant: crate::scene::Number::ZERO,
            slope: crate::scene::Number::ONE,
            clamp: crate::scene::Number::ZERO,
        };
        let [lo, hi] = offset_interval(&bias, DepthFormat::Float32, &g, &q(1, 1));
        assert_eq!(lo, q(1, 1));
        let root2 = sqrt_bounds(&q(2, 1));
        assert!(root2[0] < hi && hi <= root2[1]);
    }
}
