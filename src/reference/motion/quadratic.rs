//! Polynomials of degree at most 2 in the instant τ, with integer
//! coefficients, and their real roots: exact rationals where they are
//! rational, isolating intervals with rational ends where they are not.
//!
//! Every quantity whose sign decides coverage of a moving primitive is such
//! a polynomial: vertices move linearly in τ, so coordinates are linear and
//! orientations (products of two differences) quadratic.

use dashu_int::ops::{SquareRoot, SquareRootRem, UnsignedAbs};
use dashu_int::IBig;
use dashu_ratio::RBig;

/// c[0] + c[1]·τ + c[2]·τ².
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Quadratic {
    pub c: [IBig; 3],
}

/// A real root: exactly, or strictly inside the open interval (lo, hi)
/// with lo < hi (an irrational root, which no rational equals).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Root {
    At(RBig),
    Within(RBig, RBig),
}

impl Quadratic {
    /// c0 + c1·τ.
    pub fn linear(c0: IBig, c1: IBig) -> Quadratic {
        Quadratic {
            c: [c0, c1, IBig::ZERO],
        }
    }

    pub fn is_zero(&self) -> bool {
        self.c.iter().all(|c| *c == IBig::ZERO)
    }

    pub fn add(&self, other: &Quadratic) -> Quadratic {
        Quadratic {
            c: [0, 1, 2].map(|i| &self.c[i] + &other.c[i]),
        }
    }

    pub fn sub(&self, other: &Quadratic) -> Quadratic {
        Quadratic {
            c: [0, 1, 2].map(|i| &self.c[i] - &other.c[i]),
        }
    }

    pub fn scaled(&self, k: &IBig) -> Quadratic {
        Quadratic {
            c: [0, 1, 2].map(|i| &self.c[i] * k),
        }
    }

    /// The product of two polynomials of degree at most 1.
    ///
    /// # Panics
    /// When either has a τ² term.
    pub fn product(a: &Quadratic, b: &Quadratic) -> Quadratic {
        assert!(
            a.c[2] == IBig::ZERO && b.c[2] == IBig::ZERO,
            "only linear factors multiply into a quadratic"
        );
        Quadratic {
            c: [
                &a.c[0] * &b.c[0],
                &a.c[0] * &b.c[1] + &a.c[1] * &b.c[0],
                &a.c[1] * &b.c[1],
            ],
        }
    }

    /// The same polynomial without its τ² term: a deliberately wrong
    /// variant (see `Mutation::LinearEdges`).
    pub fn without_square(&self) -> Quadratic {
        Quadratic::linear(self.c[0].clone(), self.c[1].clone())
    }

    /// Every real root, in no particular order; none for a polynomial that
    /// is constant (identically zero included). An irrational root of
    /// c2 τ² + c1 τ + c0 is (−c1 ± √Δ)/(2 c2); with s = ⌊√(Δ·4^bits)⌋,
    /// s < √Δ·2^bits < s + 1 strictly (Δ·4^bits is not a square when Δ is
    /// not), so the root lies strictly between the two rationals obtained
    /// with √Δ replaced by s/2^bits and (s + 1)/2^bits: an interval of
    /// width 1/(2^(bits+1)·|c2|).
    pub fn roots(&self, bits: usize) -> Vec<Root> {
        let [c0, c1, c2] = &self.c;
        if *c2 == IBig::ZERO {
            if *c1 == IBig::ZERO {
                return Vec::new();
            }
            return vec![Root::At(RBig::from_parts_signed(-c0, c1.clone()))];
        }
        let twice = c2 * IBig::from(2u8);
        let delta = c1 * c1 - IBig::from(4u8) * c2 * c0;
        if delta < IBig::ZERO {
            return Vec::new();
        }
        let delta = delta.unsigned_abs();
        let (s, rem) = delta.sqrt_rem();
        if rem == dashu_int::UBig::ZERO {
            let s = IBig::from(s);
            let mut roots = vec![Root::At(RBig::from_parts_signed(-c1 + &s, twice.clone()))];
            if s != IBig::ZERO {
                roots.push(Root::At(RBig::from_parts_signed(-c1 - s, twice)));
            }
            return roots;
        }
        let s = IBig::from((delta << (2 * bits)).sqrt());
        let base = -(c1 << bits);
        let den = twice << bits;
        [IBig::ONE, -IBig::ONE]
            .into_iter()
            .map(|sign| {
                let a = RBig::from_parts_signed(&base + &sign * &s, den.clone());
                let b = RBig::from_parts_signed(&base + &sign * (&s + IBig::ONE), den.clone());
                if a < b {
                    Root::Within(a, b)
                } else {
                    Root::Within(b, a)
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(c0: i64, c1: i64, c2: i64) -> Quadratic {
        Quadratic {
            c: [c0.into(), c1.into(), c2.into()],
        }
    }

    fn value(p: &Quadratic, t: &RBig) -> RBig {
        let c = p.c.clone().map(RBig::from);
        &c[0] + &c[1] * t + &c[2] * t * t
    }

    #[test]
    fn rational_roots_are_exact() {
        let half = RBig::from_parts(1.into(), 2u8.into());
        assert_eq!(q(-1, 2, 0).roots(8), [Root::At(half.clone())]);
        // (2τ − 1)²: a double root, once.
        assert_eq!(q(1, -4, 4).roots(8), [Root::At(half)]);
        // (τ − 1)(τ + 2).
        let mut roots = q(-2, 1, 1).roots(8);
        roots.sort_by_key(|r| match r {
            Root::At(t) => t.clone(),
            Root::Within(..) => unreachable!(),
        });
        assert_eq!(roots, [Root::At(RBig::from(-2)), Root::At(RBig::ONE)]);
        assert!(q(1, 0, 1).roots(8).is_empty());
        assert!(q(3, 0, 0).roots(8).is_empty());
        assert!(q(0, 0, 0).roots(8).is_empty());
    }

    #[test]
    fn irrational_roots_are_isolated_strictly_and_narrowly() {
        // 2τ² − 1 = 0 at ±1/√2; −3τ² + 2τ + 7 has Δ = 88.
        for p in [q(-1, 0, 2), q(7, 2, -3), q(-5, 9, 1)] {
            for bits in [4, 30, 64] {
                let roots = p.roots(bits);
                assert_eq!(roots.len(), 2);
                for root in roots {
                    let Root::Within(lo, hi) = root else {
                        panic!("irrational")
                    };
                    let width = RBig::from_parts(1.into(), (dashu_int::UBig::ONE << bits) * 2u8);
                    assert!(lo < hi && &hi - &lo <= width);
                    // A sign change strictly inside.
                    let (a, b) = (value(&p, &lo), value(&p, &hi));
                    assert!(a != RBig::ZERO && b != RBig::ZERO);
                    assert!((a < RBig::ZERO) != (b < RBig::ZERO), "{p:?} {lo} {hi}");
                }
            }
        }
    }
}
