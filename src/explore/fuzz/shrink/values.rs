//! Simpler numbers: the simplicity key every accepted move makes smaller,
//! the simpler values to try for a coordinate, and every coordinate of a
//! scene.

use dashu_int::UBig;
use dashu_ratio::RBig;

use crate::explore::fuzz::geometry::num;
use crate::reference::exact::snap;
use crate::scene::rules::limits::MAX_SUBPIXEL_BITS;
use crate::scene::{Number, Scene};

/// A simplicity key for a number: smaller denominator first, then closer to
/// `[lo, hi]`, then closer to `centre`. Every accepted move makes some key
/// smaller, and keys of bounded denominator are well-ordered, so shrinking
/// ends.
pub(super) fn key(v: &Number, lo: &Number, hi: &Number, centre: &Number) -> (UBig, Number, Number) {
    let outside = if v < lo {
        lo - v
    } else if v > hi {
        v - hi
    } else {
        Number::ZERO
    };
    (v.denominator().clone(), outside, (v - centre).abs())
}

/// Simpler values to try for `v`, in order: integers in `[lo, hi]` nearest
/// `v` first, coarser dyadic roundings of `v`, and `v` pulled halfway in
/// from far outside `[lo, hi]`.
pub(super) fn simpler(v: &Number, lo: i64, hi: i64, finest: u32) -> Vec<Number> {
    let mut out: Vec<Number> = Vec::new();
    let f = v.to_f64_lossy();
    let mut ints: Vec<i64> = (lo..=hi).collect();
    ints.sort_by(|a, b| {
        ((*a as f64) - f)
            .abs()
            .total_cmp(&((*b as f64) - f).abs())
            .then(a.cmp(b))
    });
    out.extend(ints.into_iter().take(12).map(Number::from_int));
    for k in 0..=finest.min(MAX_SUBPIXEL_BITS) {
        out.push(num(&snap(v, k)));
    }
    let (lo_n, hi_n) = (Number::from_int(lo), Number::from_int(hi));
    let edge = if *v < lo_n {
        Some(lo_n)
    } else if *v > hi_n {
        Some(hi_n)
    } else {
        None
    };
    if let Some(edge) = edge {
        let half = num(&((v.as_rbig() + edge.as_rbig()) / RBig::from(2u8)));
        out.push(num(&snap(&half, 0)));
    }
    let mut seen: Vec<Number> = Vec::new();
    out.retain(|c| {
        let fresh = c != v && !seen.contains(c);
        seen.push(c.clone());
        fresh
    });
    out
}

/// Every coordinate of every vertex: its position (`from`) and, for a
/// moving vertex, its `to`.
pub(super) fn coordinates(scene: &Scene) -> impl Iterator<Item = &Number> {
    scene.vertices().flat_map(|v| {
        [&v.x, &v.y]
            .into_iter()
            .chain(v.to.iter().flat_map(|to| to.iter()))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn simpler_values_are_simpler() {
        let v = Number::ratio(12345, 4096);
        let c = simpler(&v, 0, 4, 8);
        assert_eq!(c[0], Number::from_int(3));
        assert!(c.contains(&Number::ratio(772, 256)));
        let far = simpler(&Number::from_int(20000), 0, 4, 8);
        assert!(far.contains(&Number::from_int(10002)));
    }
}
