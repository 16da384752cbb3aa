//! Time passes: a moving scene drawn once for every time test of every
//! pixel, as renderers emulate stochastic rasterization.
//!
//! SPEC §15.3 gives each pixel p its own instants: slot s·N + k holds the
//! u of test k of spatial sample s. For each such test, the scene is placed
//! at that instant (every moving vertex at (1 − τ)·snap(from) +
//! τ·snap(to), exactly, then rounded once to f32; `stream.rs`), shifted
//! for spatial sample s (`passes.rs`), and drawn with the scissor on pixel
//! p alone, adding each primitive that covers p's centre to p's count.
//! The count over all of p's tests, divided by M·N, is p's time coverage,
//! as a sample method's is (static primitives count at every instant).
//!
//! The device snaps each placed vertex to its own grid, as it snaps every
//! vertex it is given: a position between grid points at an instant is
//! the device's to round, and the time-coverage verdict (a bound on the
//! error, SPEC §15.4) judges the result. Placements are shared between
//! the pixels whose tests fall on the same (spatial sample, u).

use std::collections::HashMap;

use dashu_int::UBig;
use dashu_ratio::RBig;

use super::stream::Placement;
use super::view::View;
use crate::plan::MotionPlan;

/// The most time tests one scene is drawn with: one draw each.
pub(crate) const MAX_TESTS: u64 = 1 << 20;

/// Every placement the tests need, and each test as (pixel, placement).
pub(crate) struct TimeDraws {
    pub placements: Vec<Placement>,
    pub draws: Vec<(u32, usize)>,
}

/// The draws of a moving scene on a `width × height` canvas, its spatial
/// samples given by their shifts, or why there would be too many.
pub(crate) fn time_draws(
    motion: &MotionPlan,
    (width, height): (u32, u32),
    bits: u32,
    view: View,
    shifts: &[[RBig; 2]],
) -> Result<TimeDraws, String> {
    let blur = &motion.blur;
    let m = shifts.len() as u32;
    let tests = u64::from(width) * u64::from(height) * u64::from(m) * u64::from(blur.samples);
    if tests > MAX_TESTS {
        return Err(format!(
            "{tests} time tests, drawn one at a time; this adapter draws at most {MAX_TESTS}"
        ));
    }
    let unit = RBig::from(UBig::ONE << 32);
    let mut index: HashMap<(usize, u32), usize> = HashMap::new();
    let mut placements = Vec::new();
    let mut draws = Vec::with_capacity(tests as usize);
    for p in 0..width * height {
        crate::deadline::check();
        let times = blur.pixel_times(u64::from(p), m);
        for (j, &u) in times.iter().enumerate() {
            let s = j / blur.samples as usize;
            let at = *index.entry((s, u)).or_insert_with(|| {
                placements.push(Placement {
                    bits,
                    view,
                    shift: shifts[s].clone(),
                    time: RBig::from(blur.instant(u)) / &unit,
                });
                placements.len() - 1
            });
            draws.push((p, at));
        }
    }
    Ok(TimeDraws { placements, draws })
}
