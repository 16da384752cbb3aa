//! The `exact_arithmetic` target: the reference's i128 fast paths against
//! big integers, its exact roundings against their definitions, and
//! production's fixed-point snapping against the reference's, all decided
//! in big rationals.

use arbitrary::Unstructured;
use dashu_int::ops::Abs;
use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

use crate::production::fixed::Format;
use crate::reference::exact::{
    fits_fast_path, quotient_to_f64_round_odd, to_f32, ExactInt, I128_COORD_BOUND,
};
use crate::reference::grid::orient;
use crate::reference::triangle::SpanInt;
use crate::scene::rules::limits::COORD_LIMIT;
use crate::scene::Number;

/// A coordinate the fast path takes: small, near the bound, or anywhere.
fn coordinate(u: &mut Unstructured) -> arbitrary::Result<i64> {
    let bound = (1i64 << I128_COORD_BOUND) - 1;
    Ok(match u.int_in_range(0..=3)? {
        0 => u.int_in_range(-64..=64)?,
        1 => bound - u.int_in_range(0..=1024)?,
        2 => -bound + u.int_in_range(0..=1024)?,
        _ => u.int_in_range(-bound..=bound)?,
    })
}

fn exact(v: f64) -> RBig {
    RBig::try_from(v).expect("a finite float")
}

/// Runs every check on the numbers `data` draws.
pub fn exact_arithmetic(data: &[u8]) {
    let mut u = Unstructured::new(data);
    let _ = checks(&mut u);
}

fn checks(u: &mut Unstructured) -> arbitrary::Result<()> {
    // The orientation, the oracle's deepest expression, on the i128 path
    // and in big integers.
    let mut c = [0i64; 6];
    for v in &mut c {
        *v = coordinate(u)?;
        assert!(fits_fast_path(&IBig::from(*v)), "{v} is inside the bound");
    }
    let outside = IBig::from(1i64 << I128_COORD_BOUND);
    assert!(!fits_fast_path(&outside) && !fits_fast_path(&-outside));
    let small = |i: usize| [i128::from(c[i]), i128::from(c[i + 1])];
    let big = |i: usize| [IBig::from(c[i]), IBig::from(c[i + 1])];
    let fast = orient(&small(0), &small(2), &small(4));
    let slow = orient(&big(0), &big(2), &big(4));
    assert_eq!(fast.to_ibig(), slow, "orientation of {c:?}");
    assert_eq!(ExactInt::signum(&fast), ExactInt::signum(&slow));

    // A row's span: exact floor and ceiling division, sums, clamps.
    let d = i128::from(u.int_in_range(1..=i64::MAX)?) >> u.int_in_range(0..=62)?;
    let d = d.max(1);
    let q = RBig::from_parts(IBig::from(fast), UBig::from(d as u128));
    assert_eq!(
        SpanInt::floor_div(&fast, &d).to_ibig(),
        q.floor(),
        "⌊{fast} / {d}⌋"
    );
    assert_eq!(
        SpanInt::ceil_div(&fast, &d).to_ibig(),
        q.ceil(),
        "⌈{fast} / {d}⌉"
    );
    assert_eq!(
        SpanInt::floor_div(&slow, &IBig::from(d)),
        q.floor(),
        "⌊{fast} / {d}⌋ in big integers"
    );
    assert_eq!(SpanInt::add(&fast, &d).to_ibig(), &slow + IBig::from(d));
    let (lo, hi) = (c[0].min(c[1]), c[0].max(c[1]));
    assert_eq!(fast.clamp_to(lo, hi), slow.clamp_to(lo, hi));

    // Rounding an exact quotient to f64 (round to odd) and to f32 (nearest,
    // ties to even).
    let r = quotient_to_f64_round_odd(&IBig::from(fast), &IBig::from(d));
    if fast == 0 {
        assert_eq!(r, 0.0);
    } else {
        let at = exact(r);
        if at != q {
            assert!(r.to_bits() & 1 == 1, "{q} rounds to {r}, which is even");
            let (down, up) = (exact(r.next_down()), exact(r.next_up()));
            assert!(down < q && q < up, "{q} is not within one ulp of {r}");
        }
    }
    let f = to_f32(&q);
    let (e, up, down) = (
        (exact(f64::from(f)) - &q).abs(),
        (exact(f64::from(f.next_up())) - &q).abs(),
        (exact(f64::from(f.next_down())) - &q).abs(),
    );
    assert!(
        e <= up && e <= down,
        "{q} rounds to {f}, not the nearest f32"
    );
    if e == up || e == down {
        assert!(f.to_bits() & 1 == 0, "{q} is a tie and {f} is odd");
    }

    // Snapping to 2^-bits, ties to even (D3D11.3 §3.2.4.1).
    let bits = u.int_in_range(0..=16u32)?;
    let n = Number::from_rbig(RBig::from_parts(
        IBig::from(c[2] >> u.int_in_range(0..=40)?),
        UBig::from(u.int_in_range(1..=1u64 << 40)?),
    ));
    let snapped = n.snapped(bits).as_rbig().clone();
    let scale = RBig::from(IBig::ONE << bits as usize);
    let k = &snapped * &scale;
    assert!(k.denominator() == &UBig::ONE, "{n} snapped to {snapped}");
    let off = (&snapped - n.as_rbig()).abs() * &scale * RBig::from(2u8);
    assert!(
        off <= RBig::ONE,
        "{n} snapped to {snapped}, more than half a step"
    );
    if off == RBig::ONE {
        assert!(
            k.numerator() % IBig::from(2u8) == IBig::ZERO,
            "{n}: a tie snapped to odd"
        );
    }

    // Production's snapping to fixed point (an i64/i128 path for fractions
    // whose parts fit i64, big integers otherwise) against the reference's,
    // on coordinates within SPEC.md's range, with denominators to 2^128.
    let q = UBig::from(u.int_in_range(1..=u64::MAX)?) << u.int_in_range(0..=64usize)?;
    let reach = COORD_LIMIT << 20;
    let t = IBig::from(u.int_in_range(-reach..=reach)?);
    let p = ((IBig::from(q.clone()) * t) >> 20) + IBig::from(u.int_in_range(-3..=3i8)?);
    let n = Number::from_rbig(RBig::from_parts(p, q));
    if n.abs() <= Number::from_int(COORD_LIMIT) {
        let format = Format::snapped(bits);
        let scale = RBig::from(IBig::ONE << format.frac_bits as usize);
        let want = n.snapped(bits).as_rbig() * &scale;
        assert_eq!(
            RBig::from(format.snap(&n, bits).0),
            want,
            "production snaps {n} to {bits} bits unlike the reference"
        );
        let scaled = n.as_rbig() * &scale;
        let exact = (scaled.denominator() == &UBig::ONE).then(|| scaled.numerator().clone());
        assert_eq!(
            format.exact(&n).map(|f| IBig::from(f.0)),
            exact,
            "production's exact {n} in {} fraction bits",
            format.frac_bits
        );
    }
    Ok(())
}
