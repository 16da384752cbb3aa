//! Motion by time passes: one scissored draw per pixel and time test, the
//! counts summed into each pixel's time coverage.

use super::GL;
use rastercheck::harness::judge::Verdict;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::scene::{Primitive, Scene};

use super::common::adapters::{assert_each, assert_wrong_instants_fail, bundled_ids};
use super::common::{case, report, run_as_stated};
use super::{available, run};

/// Whether a case has a `parallelogram` line, which GL does not draw.
fn has_parallelogram_lines(scene: &Scene) -> bool {
    scene.primitives.iter().any(|p| {
        matches!(p, Primitive::Line(l) if l.rule == rastercheck::scene::LineRule::Parallelogram)
    })
}

/// Holds a moving case to the driver's rule (bottom-left, read y down).
/// Its `expect.time_coverage` pins are the exact coverages under the
/// case's own rule, which the reference must reproduce: under another rule
/// they no longer hold, so they go with it (the bounds stay).
fn bottom_left_unpinned(scene: &mut Scene) {
    super::bottom_left(scene);
    scene.expect.time_coverage.clear();
}

/// Every bundled moving case but those with `parallelogram` lines is
/// drawn by time passes; held to the driver's tie rule (bottom-left, read
/// y down), each passes its time-coverage bounds, and so does each judged
/// under the driver's own rule with the case's pins dropped. Held to the
/// case's own rule, `ride_top_edge_top_left` fails (a triangle riding the
/// sample row along its top edge: llvmpipe includes the bottom, not the
/// top).
#[test]
fn moving_cases_by_time_passes_pass_under_the_drivers_rule() {
    let Some(_record) = available() else {
        return;
    };
    let ids: Vec<String> = bundled_ids("motion", |_| true)
        .into_iter()
        .filter(|id| !has_parallelogram_lines(&case(id)))
        .collect();
    let ids: Vec<&str> = ids.iter().map(String::as_str).collect();
    assert!(ids.len() >= 29, "{ids:?}");
    for id in &ids {
        let (reference, own) = run(&case(id));
        eprintln!("own rule: {}", report(id, &reference, &own));
        assert!(
            matches!(own.verdict, Verdict::Pass | Verdict::Fail(_)),
            "{id}: {:?}",
            own.verdict
        );
    }
    assert_each(&ids, &GL, bottom_left_unpinned, |_, run, line, failures| {
        if run.verdict != Verdict::Pass {
            failures.push(line.to_owned());
        }
    });
    // Held to the case's own top-left rule, the riding edge's samples go
    // the other way: it fails. Judged under the driver's own rule (the
    // case's pins dropped with its rule), it passes.
    let top = case("motion/ride_top_edge_top_left");
    let (_, stated) = run_as_stated(&top, &GL);
    assert!(
        matches!(stated.verdict, Verdict::Fail(_)),
        "{:?}",
        stated.verdict
    );
    let (_, own) = run(&top);
    assert_eq!(own.verdict, Verdict::Pass);
}

/// A wrong shutter is caught (`assert_wrong_instants_fail`).
#[test]
fn wrong_instants_fail() {
    let Some(_record) = available() else {
        return;
    };
    assert_wrong_instants_fail(&GL);
}

/// The reports say how moving scenes are drawn.
#[test]
fn declares_time_passes() {
    let Some(_record) = available() else {
        return;
    };
    let _ = run(&case("motion/spec_moves_as_written"));
    let declared = GL.declared().expect("the context is made");
    assert!(declared.contains("motion by time passes"), "{declared}");
    assert!(GL.capabilities().motion_blur);
}
