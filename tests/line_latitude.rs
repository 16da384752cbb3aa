//! The latitude for diamond-exit lines (SPEC.md §4.2.1), end to end: a
//! rasterizer that declares it (as the `vulkan` and `gl` adapters do) is
//! judged under the spec's four rules against the exact fragments. The
//! exact rule passes with nothing counted; a line moved by one unit
//! passes with the move counted; four foils, each breaking one rule, are
//! caught with that rule named. The worked example of SPEC.md §4.2.1 is
//! pinned on `cases/lines/diamond_exit_worked_example.json`.

use std::path::Path;

use rastercheck::frame::Frame;
use rastercheck::harness::judge::{run_candidate, Verdict};
use rastercheck::harness::oracle::run_reference;
use rastercheck::metrics::LatitudeMetrics;
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::registry;
use rastercheck::scene::{parse_case, Limits, Scene};

/// Production's exact frame with `edit` applied, declaring the latitude.
struct Edited {
    name: &'static str,
    edit: fn(&mut Frame),
}

impl Rasterizer for Edited {
    fn name(&self) -> &str {
        self.name
    }
    fn capabilities(&self) -> Capabilities {
        Capabilities::everything()
    }
    fn is_foil(&self) -> bool {
        true
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut frame = registry::by_name("production")
            .expect("production")
            .rasterize(scene, plan)?;
        (self.edit)(&mut frame);
        Ok(frame)
    }
    fn diamond_exit_latitude(&self) -> bool {
        true
    }
}

/// Sets pixel (x, y)'s one sample to `count` covers, the last by primitive `last`.
fn set(frame: &mut Frame, x: u32, y: u32, count: u16, last: u32) {
    let i = frame.index(x, y);
    frame.coverage[i] = count;
    frame.last[i] = last;
}

fn case(name: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("cases/lines/{name}.json"));
    let text = std::fs::read_to_string(&path).unwrap();
    parse_case(&text, &path.display().to_string(), &Limits::default()).unwrap()
}

/// The verdict's reasons (empty for a pass) and the latitude counts.
fn judged(scene: &Scene, edit: fn(&mut Frame)) -> (Vec<String>, LatitudeMetrics) {
    let reference = run_reference(scene);
    let foil = Edited {
        name: "edited",
        edit,
    };
    let run = run_candidate(scene, &reference, &foil);
    assert!(run.judged.line_latitude, "judged under the latitude");
    let reasons = match &run.verdict {
        Verdict::Pass => Vec::new(),
        Verdict::Fail(reasons) => reasons.clone(),
        other => panic!("{other:?}"),
    };
    let latitude = run
        .metrics
        .and_then(|m| m.latitude)
        .expect("latitude metrics");
    (reasons, latitude)
}

// The worked example's line 1 lights (1,1) (2,1) (3,2) (4,2) (5,3) (6,3)
// (7,4) (8,4); line 2 lights (2,6) (2,7) (3,8) (3,9) (SPEC.md §4.2).
const WORKED: &str = "diamond_exit_worked_example";

#[test]
fn the_exact_rule_passes_with_nothing_counted() {
    let (reasons, m) = judged(&case(WORKED), |_| {});
    assert!(reasons.is_empty(), "{reasons:?}");
    assert_eq!((m.lines, m.moved, m.count_changed), (2, 0, 0));
}

#[test]
fn the_worked_example_a_bresenham_walk_keeps_to_the_latitude() {
    // SPEC.md §4.2.1's example: a walk that breaks the ties the other way lights
    // (2,2) (4,3) (6,4) (8,5) instead of (2,1) (4,2) (6,3) (8,4), and adds
    // the last pixel (9,5): 4 moved by one unit, 9 fragments for 8.
    let (reasons, m) = judged(&case(WORKED), |f| {
        for (x, y) in [(2, 1), (4, 2), (6, 3), (8, 4)] {
            set(f, x, y, 0, 0);
            set(f, x, y + 1, 1, 1);
        }
        set(f, 9, 5, 1, 1);
    });
    assert!(reasons.is_empty(), "{reasons:?}");
    assert_eq!((m.moved, m.count_changed), (5, 1), "{m:?}");
}

#[test]
fn foil_a_fragment_moved_by_two_units_is_caught() {
    let (reasons, m) = judged(&case(WORKED), |f| {
        set(f, 5, 3, 0, 0);
        set(f, 5, 5, 1, 1);
    });
    assert_eq!(m.too_far, 1, "{m:?}");
    assert!(
        reasons.iter().any(|r| r.contains("more than one unit")),
        "{reasons:?}"
    );
}

#[test]
fn foil_two_extra_fragments_are_caught() {
    let (reasons, m) = judged(&case(WORKED), |f| {
        set(f, 9, 5, 1, 1);
        set(f, 0, 0, 1, 1);
    });
    assert_eq!(m.count_off, 1, "{m:?}");
    assert!(
        reasons.iter().any(|r| r.contains("fragment count")),
        "{reasons:?}"
    );
}

#[test]
fn foil_two_fragments_in_one_column_of_an_x_major_line_are_caught() {
    let (reasons, m) = judged(&case(WORKED), |f| set(f, 3, 3, 1, 1));
    assert_eq!(m.crowded, 1, "{m:?}");
    assert!(
        reasons
            .iter()
            .any(|r| r.contains("two fragments of one line")),
        "{reasons:?}"
    );
}

#[test]
fn foil_a_shared_endpoint_of_two_x_major_segments_drawn_twice_is_caught() {
    // Its two x-major segments join end to start, both left to right.
    let scene = case("diamond_latitude_joint");
    let (reasons, _) = judged(&scene, |_| {});
    assert!(reasons.is_empty(), "the exact strip passes: {reasons:?}");
    let (reasons, m) = judged(&scene, double_joint);
    assert!(m.duplicated >= 1, "{m:?}");
    assert!(
        reasons
            .iter()
            .any(|r| r.contains("both of two connected segments")),
        "{reasons:?}"
    );
}

/// The later segment's first pixel next to the earlier one's fragments,
/// on the joined segments of `diamond_latitude_joint`: covered by both.
fn double_joint(f: &mut Frame) {
    let scene = case("diamond_latitude_joint");
    let plan = Plan::for_scene(&scene);
    let lines = rastercheck::reference::diamond_lines(&scene, &plan).unwrap();
    let (a, b) = (0..lines.len())
        .flat_map(|a| (0..lines.len()).map(move |b| (a, b)))
        .find(|&(a, b)| a != b && lines[a].joins(&lines[b]))
        .expect("two joined segments of one major axis");
    // The pixel both may reach nearest the joint: the later segment's first.
    let w = f.width as usize;
    let p = lines[b].pixels.iter().copied().find(|&p| {
        lines[a]
            .pixels
            .iter()
            .any(|&q| (p % w).abs_diff(q % w) <= 1 && (p / w).abs_diff(q / w) <= 1)
    });
    let p = p.expect("a pixel near the joint");
    f.coverage[p] += 1;
    f.last[p] = lines[a].primitive.max(lines[b].primitive) as u32 + 1;
}
