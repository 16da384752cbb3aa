//! The driver's own multisampling: the counts and sample positions it
//! reports, and native MSAA drawing each sample where it says.

use rastercheck::adapters::gl;

use super::GL;
use rastercheck::plan::{Plan, SamplePlan};
use rastercheck::rasterizer::Rasterizer;
use rastercheck::reference;

use super::common::case;
use super::{available, triangle_around};

/// The driver's counts and positions, printed for the record (offsets
/// from the pixel's top-left corner, y down); each on the 1/256 grid.
fn offered() -> Vec<(u32, Vec<[f64; 2]>)> {
    let ms = gl::driver_multisampling().expect("the context is made");
    eprintln!("GL_MAX_SAMPLES {}", ms.max_samples);
    let offered = ms.counts;
    for (count, positions) in &offered {
        eprintln!("driver {count}×: {positions:?} (y down)");
        for p in positions {
            assert!(p.iter().all(|c| (c * 256.0).fract() == 0.0), "{p:?}");
        }
    }
    offered
}

/// Native MSAA: with a plan whose offsets are exactly the driver's
/// positions (slot order reversed, so the slot map is exercised), a tiny
/// triangle around each position lights exactly the slot at that offset,
/// in pixel (1, 1) alone. At `subpixel_bits` 10 too, which shifted passes
/// refuse (`refuses_shifted_passes_that_would_not_be_exact`): so these
/// frames are the driver's multisampling, not shifted passes.
#[test]
fn a_triangle_around_each_driver_position_lights_exactly_its_slot() {
    let Some(_record) = available() else {
        return;
    };
    let offered = offered();
    assert!(!offered.is_empty(), "llvmpipe offers multisampling");
    let mut failures = Vec::new();
    for (count, positions) in &offered {
        let slots: Vec<[f64; 2]> = positions.iter().rev().copied().collect();
        let aa = SamplePlan {
            offsets: slots
                .iter()
                .map(|p| p.map(|c| (c * 256.0) as u32))
                .collect(),
            position_bits: 8,
            adaptive: false,
        };
        for (slot, &p) in slots.iter().enumerate() {
            for bits in [8, 10] {
                let scene = triangle_around(p, &format!(r#""rules": {{"subpixel_bits": {bits}}}"#));
                let plan = Plan {
                    samples_per_pixel: *count,
                    antialias: Some(aa.clone()),
                    ..Plan::for_scene(&scene)
                };
                let frame = GL.rasterize(&scene, &plan).expect("drawn");
                let lit: Vec<usize> = (0..frame.sample_count())
                    .filter(|&k| frame.coverage[k] > 0)
                    .collect();
                let want = frame.index(1, 1) + slot;
                if lit != [want] {
                    failures.push(format!(
                        "{count}× slot {slot} at {p:?}, {bits} bits: {lit:?} lit, not [{want}]"
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Native MSAA on real geometry: with the driver's own 4× pattern as the
/// plan, triangle meshes and stencilled polygons (held to the driver's
/// tie rule, bottom-left read y down) match the reference's frame for
/// that plan sample for sample, coverage and owner.
#[test]
fn native_msaa_matches_the_reference_at_the_drivers_positions() {
    let Some(_record) = available() else {
        return;
    };
    let (count, positions) = offered().into_iter().next().expect("a count");
    let aa = SamplePlan {
        offsets: positions
            .iter()
            .map(|p| p.map(|c| (c * 256.0) as u32))
            .collect(),
        position_bits: 8,
        adaptive: false,
    };
    let mut failures = Vec::new();
    for id in [
        "triangles/fan_16_center",
        "triangles/quad_grid_rot30",
        "triangles/mesh_full_canvas_odd",
        "polygons/pentagram_nonzero",
        "polygons/hole_same_even_odd",
    ] {
        let mut scene = case(id);
        super::bottom_left(&mut scene);
        let plan = Plan {
            samples_per_pixel: count,
            antialias: Some(aa.clone()),
            ..Plan::coverage_only()
        };
        let exact = reference::render(&scene, &plan);
        let frame = GL.rasterize(&scene, &plan).expect("drawn");
        let differ = (0..exact.sample_count())
            .filter(|&k| {
                exact.coverage[k] != frame.coverage[k]
                    || (exact.coverage[k] > 0 && exact.last[k] != frame.last[k])
            })
            .count();
        eprintln!(
            "{id}: {differ} of {} samples differ ({} covered)",
            exact.sample_count(),
            exact.covered_samples()
        );
        if differ != 0 || exact.covered_samples() == 0 {
            failures.push(format!("{id}: {differ} samples differ"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
