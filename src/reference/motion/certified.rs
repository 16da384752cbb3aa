//! A certified time coverage: a value and a bound on its error, and the
//! largest bound the oracle accepts.

use dashu_ratio::RBig;

/// A time coverage and a certified bound on its error:
/// |exact − value| ≤ bound. The bound is 0 when every root involved is
/// rational.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Certified {
    pub value: RBig,
    pub bound: RBig,
}

/// The largest bound the oracle accepts of one primitive at one sample:
/// 2^-40 (it asserts it).
pub fn max_bound() -> RBig {
    RBig::from_parts(1.into(), dashu_int::UBig::ONE << 40)
}

/// Whether every value within a certified bound rounds to the same f64, so
/// that the nearest f64 to the certified value is the exact value's.
pub(super) fn rounds_once(c: &Certified) -> bool {
    c.bound == RBig::ZERO
        || crate::reference::area::to_f64_nearest(&(&c.value - &c.bound))
            == crate::reference::area::to_f64_nearest(&(&c.value + &c.bound))
}
