//! The oracle's answer for a case, computed once and shared by every
//! candidate: the reference's frame, and what the exact rationals say
//! beyond it (the mesh interior, each pixel's exact area class, the
//! certified time coverage of a moving scene), with the case's promises
//! about the reference (`expect.area`, `expect.time_coverage`) checked.
//! A panic of the oracle fails the case with the reason, never the run.

use std::time::{Duration, Instant};

use dashu_int::ops::Abs;
use dashu_ratio::RBig;

use super::panics::pass_on_deadline;
use crate::frame::Frame;
use crate::metrics::AreaClass;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::reference;
use crate::reference::conservative::ConservativeClasses;
use crate::reference::motion::Certified;
use crate::scene::Scene;

/// The reference's answer for a case, computed once and shared by every
/// candidate.
pub struct ReferenceRun {
    pub plan: Plan,
    pub frame: Frame,
    /// The mesh interior, for cases that expect watertightness.
    pub interior: Option<Vec<bool>>,
    /// For antialiased scenes only: what the exact areas say
    /// ([`check_areas`]), or why the oracle failed to compute them (a panic
    /// there fails the case with the reason instead of ending the run).
    pub areas: Option<Result<AreaCheck, String>>,
    /// For scenes in which something moves only: what the certified time
    /// coverage says ([`check_time`]), or why the oracle failed to compute
    /// it (then `frame` holds NaN, which no golden file matches).
    pub time: Option<Result<TimeCheck, String>>,
    /// For scenes with a depth format (SPEC.md §18) only: the depths a
    /// candidate may read back at each slot (`reference::render_judged`).
    pub depth_allowed: Option<Vec<[f64; 2]>>,
    /// For conservative scenes only (SPEC.md §19): each pixel's class,
    /// three-valued, or why the reference gives none (`Unsupported`: this
    /// version does not judge the scene; `Failed`: it panicked).
    pub conservative: Option<Result<ConservativeClasses, RasterError>>,
    pub elapsed: Duration,
}

/// The reference's answer for a scene, its plan made here: for callers
/// that start from a scene (tests, probe, the fuzzer). A case on the
/// judging path is planned once when it is loaded and comes through
/// [`run_reference_planned`].
pub fn run_reference(scene: &Scene) -> ReferenceRun {
    run_reference_with(scene, reference::motion::time_coverage)
}

/// [`run_reference`] for a scene whose plan is made already
/// (`Plan::for_scene`), which the answer keeps in [`ReferenceRun::plan`].
pub fn run_reference_planned(scene: &Scene, plan: Plan) -> ReferenceRun {
    run_planned_with(scene, plan, reference::motion::time_coverage)
}

/// [`run_reference`] with the time-coverage oracle given, so that tests
/// can judge moving scenes against exact values they computed themselves.
/// A scene in which something moves gets its frame from the oracle's
/// certified values, computed once; it has no mesh interior and no exact
/// areas (it is judged on time coverage only).
pub fn run_reference_with(
    scene: &Scene,
    time_coverage: impl FnOnce(&Scene, &Plan) -> Vec<Certified>,
) -> ReferenceRun {
    run_planned_with(scene, Plan::for_scene(scene), time_coverage)
}

/// [`run_reference_with`] for a scene whose plan is made already.
fn run_planned_with(
    scene: &Scene,
    plan: Plan,
    time_coverage: impl FnOnce(&Scene, &Plan) -> Vec<Certified>,
) -> ReferenceRun {
    let started = Instant::now();
    if plan.motion.is_some() {
        let (frame, time) = time_reference(scene, &plan, time_coverage);
        return ReferenceRun {
            plan,
            frame,
            interior: None,
            areas: None,
            time: Some(time),
            depth_allowed: None,
            conservative: None,
            elapsed: started.elapsed(),
        };
    }
    if scene.is_conservative() {
        let classes = super::conservative::oracle_classes(scene);
        let frame = match &classes {
            Ok(classes) => reference::conservative::frame_with_depth(scene, &plan, classes),
            Err(_) => Frame::for_plan(scene.canvas.width, scene.canvas.height, &plan),
        };
        return ReferenceRun {
            plan,
            frame,
            interior: None,
            areas: None,
            time: None,
            depth_allowed: None,
            conservative: Some(classes),
            elapsed: started.elapsed(),
        };
    }
    let (frame, depth_allowed) =
        reference::render_judged(scene, &plan, reference::Arithmetic::Auto);
    let interior = scene
        .expect
        .watertight
        .then(|| reference::mesh_interior(scene, &plan));
    let areas = area_check(scene);
    ReferenceRun {
        plan,
        frame,
        interior,
        areas,
        time: None,
        depth_allowed,
        conservative: None,
        elapsed: started.elapsed(),
    }
}

/// What the certified time coverage of a moving scene says: whether each
/// pixel's exact value is a whole number (for the moving pixels of SPEC.md
/// §15.4), the largest certified bound, and the promises of the case the
/// reference breaks (`expect.time_coverage`), which fail every candidate,
/// as `expect.area` does.
pub struct TimeCheck {
    pub whole: Vec<bool>,
    /// The largest bound of any pixel (0 when every value is exact).
    pub max_bound: f64,
    pub broken_promises: Vec<String>,
}

/// The frame and the [`TimeCheck`] of a moving scene from the oracle
/// `time_coverage`; a panic there, or an answer of the wrong length, is
/// `Err(why)` with a frame of NaN.
fn time_reference(
    scene: &Scene,
    plan: &Plan,
    time_coverage: impl FnOnce(&Scene, &Plan) -> Vec<Certified>,
) -> (Frame, Result<TimeCheck, String>) {
    let (width, height) = (scene.canvas.width, scene.canvas.height);
    let pixels = scene.canvas.pixel_count();
    let computed = catch_oracle(|| time_coverage(scene, plan)).and_then(|certified| {
        if certified.len() == pixels {
            Ok(certified)
        } else {
            let n = certified.len();
            Err(format!(
                "reference: the time-coverage oracle returned {n} values for {pixels} pixels"
            ))
        }
    });
    match computed {
        Ok(certified) => (
            reference::motion::frame_of(scene, &certified),
            Ok(check_time(scene, &certified)),
        ),
        Err(why) => (
            Frame::time_only(width, height, vec![f64::NAN; pixels]),
            Err(why),
        ),
    }
}

/// The time-coverage oracle's answer, or why it panicked.
fn catch_oracle(oracle: impl FnOnce() -> Vec<Certified>) -> Result<Vec<Certified>, String> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(oracle))
        .map_err(|panic| pass_on_deadline(panic, "reference: the time-coverage oracle failed"))
}

/// The [`TimeCheck`] of certified per-pixel time coverage: each pin of
/// `expect.time_coverage` must hold as SPEC.md §15.4 says,
/// |value − pinned| ≤ bound + 10^-12, decided in exact rationals (pins are
/// written with 15 significant digits, hence the 10^-12).
pub fn check_time(scene: &Scene, certified: &[Certified]) -> TimeCheck {
    let slack = RBig::from_parts(1.into(), dashu_int::UBig::from(10u8).pow(12));
    let width = scene.canvas.width as usize;
    let mut broken = Vec::new();
    for pin in &scene.expect.time_coverage {
        let [x, y] = pin.pixel;
        let Some(c) = certified.get(y as usize * width + x as usize) else {
            continue;
        };
        let off = (&c.value - pin.value.as_rbig()).abs();
        if off > &c.bound + &slack {
            broken.push(format!(
                "reference: its time coverage of pixel ({x}, {y}) is {value} (≈ {:.15}, certified within {:.3e}) but the case pins {pinned}: off by {:.3e}, more than the bound + 1e-12",
                reference::area::to_f64_nearest(&c.value),
                reference::area::to_f64_nearest(&c.bound),
                reference::area::to_f64_nearest(&off),
                value = c.value,
                pinned = pin.value,
            ));
        }
    }
    TimeCheck {
        whole: certified
            .iter()
            .map(|c| c.bound == RBig::ZERO && c.value.is_int())
            .collect(),
        max_bound: certified
            .iter()
            .map(|c| reference::area::to_f64_nearest(&c.bound))
            .fold(0.0, f64::max),
        broken_promises: broken,
    }
}

/// What the exact areas of an antialiased case say: whether each pixel's
/// area is exactly 0, 1 or neither (for piglit's rule, SPEC.md §14.3), and
/// the promises of the case the reference breaks (`expect.area`), which
/// fail every candidate, as `expect.samples_covered` does.
pub struct AreaCheck {
    pub classes: Vec<AreaClass>,
    pub broken_promises: Vec<String>,
}

/// The [`AreaCheck`] of a scene, computed from the reference's exact areas:
/// `None` when the scene does not antialias, `Some(Err(why))` when the
/// exact areas panicked.
pub fn area_check(scene: &Scene) -> Option<Result<AreaCheck, String>> {
    scene.effects.antialias.as_ref()?;
    let computed = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        check_areas(scene, &reference::exact_areas(scene))
    }));
    Some(computed.map_err(|panic| pass_on_deadline(panic, "reference: the exact areas failed")))
}

/// The exact area class of every pixel, and `expect.area` against the
/// exact sum of the reference's per-pixel areas `areas` (a rational
/// equality): the reasons the promise is broken, if it is.
pub fn check_areas(scene: &Scene, areas: &[RBig]) -> AreaCheck {
    let (zero, one) = (RBig::ZERO, RBig::ONE);
    let classes = areas
        .iter()
        .map(|a| {
            if *a == zero {
                AreaClass::Empty
            } else if *a == one {
                AreaClass::Full
            } else {
                AreaClass::Partial
            }
        })
        .collect();
    let mut broken = Vec::new();
    if let Some(expected) = &scene.expect.area {
        let total = areas.iter().fold(RBig::ZERO, |sum, a| sum + a);
        if &total != expected.as_rbig() {
            broken.push(format!(
                "reference: its pixel areas sum to {total} (≈ {:.6}) but the case expects an area of {expected}",
                total.to_f64().value()
            ));
        }
    }
    AreaCheck {
        classes,
        broken_promises: broken,
    }
}

/// The reference's run, or why it panicked.
pub(super) fn catch_oracle_run(run: impl FnOnce() -> ReferenceRun) -> Result<ReferenceRun, String> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(run))
        .map_err(|panic| pass_on_deadline(panic, "panicked"))
}

/// Each primitive's exact area of each pixel it covers.
pub(super) fn primitive_areas(scene: &Scene) -> Vec<Vec<(u32, RBig)>> {
    (0..scene.primitives.len())
        .map(|p| reference::primitive_pixel_areas(scene, p))
        .collect()
}
