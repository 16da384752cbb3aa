//! Exact points and numbers shared by generation, judging and shrinking: a
//! [`Number`] from a rational, rational points and their sums, snapping to a
//! case's grid, and the exact orientation of three points. No randomness and
//! no floats here.

use std::cmp::Ordering;

use dashu_ratio::RBig;

use crate::reference::exact::snap;
use crate::scene::Number;

/// A rational as a [`Number`].
pub(super) fn num(r: &RBig) -> Number {
    Number::from_string(&format!("{}/{}", r.numerator(), r.denominator()))
        .expect("a ratio of integers is a number")
}

/// An exact point, x then y.
pub(super) type Point = [RBig; 2];

pub(super) fn ratio(n: i64, d: i64) -> RBig {
    Number::ratio(n, d).as_rbig().clone()
}

pub(super) fn plus(a: &Point, b: &Point) -> Point {
    [&a[0] + &b[0], &a[1] + &b[1]]
}

pub(super) fn minus(a: &Point, b: &Point) -> Point {
    [&a[0] - &b[0], &a[1] - &b[1]]
}

pub(super) fn times(k: &RBig, a: &Point) -> Point {
    [k * &a[0], k * &a[1]]
}

/// Where `n` lies after snapping to `bits` fraction bits (as written when
/// the case snaps nothing).
pub(super) fn placed(n: &Number, bits: Option<u32>) -> RBig {
    match bits {
        Some(b) => snap(n, b),
        None => n.as_rbig().clone(),
    }
}

/// The turn a → b → c: its sign, exactly.
pub(super) fn orient(a: &Point, b: &Point, c: &Point) -> Ordering {
    let v = (&b[0] - &a[0]) * (&c[1] - &a[1]) - (&b[1] - &a[1]) * (&c[0] - &a[0]);
    v.cmp(&RBig::ZERO)
}
