//! Exact time coverage of moving primitives, with a certified bound
//! (SPEC.md §15.2).
//!
//! (Stub: the interface the rest of the crate builds on; the oracle itself
//! is being written.)

use dashu_ratio::RBig;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::scene::Scene;

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

/// Each pixel's time coverage (row-major): the mean over its spatial
/// samples of the sum over primitives of the covered fraction of the
/// shutter, static primitives included. Only for plans with `motion`.
pub fn time_coverage(scene: &Scene, plan: &Plan) -> Vec<Certified> {
    let _ = (scene, plan);
    todo!("the certified motion-blur oracle")
}

/// The reference's frame of a scene in which something moves: each
/// pixel's certified time coverage rounded to the nearest f64.
pub fn frame(scene: &Scene, plan: &Plan) -> Frame {
    let time = time_coverage(scene, plan)
        .iter()
        .map(|c| c.value.to_f64().value())
        .collect();
    Frame::time_only(scene.canvas.width, scene.canvas.height, time)
}
