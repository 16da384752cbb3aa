//! The certified time coverage of one primitive at one exact point, over
//! any shutter: the oracle's single-sample question, for tests and the
//! fuzzer.

use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

use super::certified::Certified;
use super::moving::{Moving, Mutation, Rules};
use super::sample::{sample_measure, ISOLATION_BITS};
use crate::reference::grid::gcd;
use crate::scene::Scene;

/// The time coverage of one primitive at one exact point (in pixels) over
/// the shutter [open, close] (instants in [0, 1]), as a fraction of the
/// shutter; the primitive may move or not.
///
/// # Panics
/// When the primitive is neither a triangle nor a `parallelogram` line,
/// when the scene has no `subpixel_bits`, when open ≥ close, or when the
/// bound exceeds [`max_bound`](super::certified::max_bound).
pub fn point_coverage(
    scene: &Scene,
    primitive: usize,
    point: [&RBig; 2],
    shutter: [&RBig; 2],
) -> Certified {
    point_coverage_with(scene, primitive, point, shutter, Mutation::None)
}

/// [`point_coverage`] of a deliberately wrong oracle.
#[doc(hidden)]
pub fn point_coverage_with(
    scene: &Scene,
    primitive: usize,
    point: [&RBig; 2],
    shutter: [&RBig; 2],
    mutation: Mutation,
) -> Certified {
    let bits = scene
        .rules
        .subpixel_bits
        .expect("a moving scene has subpixel_bits");
    assert!(
        shutter[0] < shutter[1],
        "the shutter opens before it closes"
    );
    // The grid: 2^bits and the point's denominators divide its scale.
    let scale = point.iter().fold(UBig::ONE << bits as usize, |l, c| {
        let d = c.denominator();
        let g = gcd(&l, d);
        &l / g * d
    });
    let scale = IBig::from(scale);
    let p = point.map(|c| c.numerator() * (&scale / IBig::from(c.denominator().clone())));
    let mover = Moving::new(&scene.primitives[primitive], bits, &scale);
    let rules = Rules {
        fill: scene.rules.fill_rule,
        cull: scene.rules.cull,
        mutation,
    };
    let (value, bound) = sample_measure(&mover, &p, shutter, rules, ISOLATION_BITS);
    let length = shutter[1] - shutter[0];
    Certified {
        value: value / &length,
        bound: bound / &length,
    }
}
