//! The difference mask of a candidate with no tie rule (`fill_rule:
//! "none"`, SPEC.md §3.1.1) draws its accepted tie samples as accepted (a
//! colour of their own, `png::TIE_ACCEPTED`), not as mismatches, so that
//! the picture agrees with the card's ties line; a real mismatch beside
//! them keeps its colour.

use rastercheck::frame::Frame;
use rastercheck::metrics::coverage::compare_off_ties;
use rastercheck::metrics::SampleDiff;
use rastercheck::plan::Plan;
use rastercheck::reference;
use rastercheck::report::png;
use rastercheck::scene::{parse_case, FillRule, Limits, Scene};

/// Two triangles sharing the vertical edge x = 4.5, through the centres
/// of column 4: eight tie samples.
fn scene() -> Scene {
    parse_case(
        r#"{"name": "tie_mask", "canvas": {"width": 8, "height": 8},
            "rules": {"fill_rule": "top-left", "cull": "none"},
            "primitives": [
                {"triangle": [[4.5, 0], [4.5, 8], [0, 4]]},
                {"triangle": [[4.5, 0], [8, 4], [4.5, 8]]}]}"#,
        "tie_mask",
        &Limits::default(),
    )
    .unwrap()
}

/// The reference under the other rule (every tie the other side), with
/// one sample drawn that nothing covers: (0, 0).
fn candidate(s: &Scene, plan: &Plan) -> Frame {
    let mut c = reference::render(&s.with_fill_rule(FillRule::BottomRight), plan);
    let i = c.index(0, 0);
    c.coverage[i] = 1;
    c.last[i] = 1;
    c
}

#[test]
fn accepted_ties_are_drawn_as_accepted_and_a_real_mismatch_as_one() {
    let s = scene();
    let plan = Plan::for_scene(&s);
    let r = reference::render(&s, &plan);
    let c = candidate(&s, &plan);
    let ties = reference::tie_set(&s, &plan);
    let m = compare_off_ties(&r, &c, Some(&ties));
    let ties_in_mask = m.mask.iter().filter(|d| **d == SampleDiff::Tie).count();
    assert!(ties_in_mask >= 6, "{ties_in_mask} accepted ties");
    assert_eq!(m.mismatched(), 1, "only (0, 0) is a mismatch");
    assert_eq!(m.mask[r.index(0, 0)], SampleDiff::Extra);
    assert_eq!(m.mask[r.index(4, 3)], SampleDiff::Tie);
    // Judged under a rule, the same samples are mismatches.
    let under_rule = compare_off_ties(&r, &c, None);
    assert_eq!(under_rule.mask[r.index(4, 3)], SampleDiff::WrongOwner);

    let dir = std::env::temp_dir().join(format!("rastercheck-tie-mask-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let paths = png::write_comparison(&s, &r, "none", &c, &m.mask, &dir, 8).unwrap();
    let diff = paths
        .iter()
        .find(|p| p.to_string_lossy().ends_with(".diff.png"))
        .unwrap();
    let img = image::open(diff).unwrap().to_rgb8();
    // Inside pixel (4, 3), clear of its border and of the cyan edge at
    // x = 4.5 (36 in the picture).
    let at = |x: u32, y: u32| img.get_pixel(x, y).0;
    assert_eq!(at(34, 28), png::TIE_ACCEPTED);
    // The extra sample at (0, 0) is red, a covered-alike one grey.
    assert_eq!(at(3, 3), png::EXTRA);
    assert_eq!(at(3 * 8 + 3, 4 * 8 + 3), png::SAME_COVERED);
    let _ = std::fs::remove_dir_all(&dir);
}
