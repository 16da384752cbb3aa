//! Helpers the test binaries share: bundled and inline cases, a readable
//! account of where a candidate's frame differs from the reference's, and a
//! seeded random source. Running the binary is in `cli.rs`; driving a
//! third-party adapter through the suite is in `adapters.rs`.

#![allow(dead_code)] // each test crate uses its own subset

pub mod adapters;
pub mod cli;
pub mod clip_drivers;
pub mod departures;
pub mod depth_drivers;
pub mod point_drivers;
pub mod sample_drivers;
pub mod shifted_view_drivers;
pub mod viewport_drivers;

#[allow(unused_imports)] // not every binary runs the binary
pub use cli::{rastercheck, text};

use std::path::Path;

use rastercheck::frame::Frame;
use rastercheck::harness::judge::CandidateRun;
use rastercheck::harness::{judge, oracle};
use rastercheck::rasterizer::Rasterizer;
use rastercheck::scene::{parse_case, Limits, Scene};

/// A bundled case by id (`triangles/fan_16_center`).
pub fn case(id: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("cases/{id}.json"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{id}: {e}"));
    parse_case(&text, &path.display().to_string(), &Limits::default())
        .unwrap_or_else(|e| panic!("{id}: {e}"))
}

pub fn inline(json: &str) -> Scene {
    parse_case(json, "inline.json", &Limits::default()).expect("valid inline case")
}

/// A rasterizer judged under each case's own fill rule, as if it followed
/// it: its fixed rule ([`Rasterizer::fixed_fill_rule`]) is not declared.
/// What its frames show against the rule a case states: the evidence for
/// the rule it declares.
pub struct AsStated<'a>(pub &'a dyn Rasterizer);

impl Rasterizer for AsStated<'_> {
    fn name(&self) -> &str {
        self.0.name()
    }
    fn capabilities(&self) -> rastercheck::rasterizer::Capabilities {
        self.0.capabilities()
    }
    fn rasterize(
        &self,
        scene: &Scene,
        plan: &rastercheck::Plan,
    ) -> Result<Frame, rastercheck::RasterError> {
        self.0.rasterize(scene, plan)
    }
}

/// [`run`], judging the frame under the case's own fill rule whatever
/// rule the candidate follows ([`AsStated`]).
pub fn run_as_stated(
    scene: &Scene,
    candidate: &dyn Rasterizer,
) -> (oracle::ReferenceRun, CandidateRun) {
    run(scene, &AsStated(candidate))
}

/// The reference's run and the candidate's, on one scene.
pub fn run(scene: &Scene, candidate: &dyn Rasterizer) -> (oracle::ReferenceRun, CandidateRun) {
    let reference = oracle::run_reference(scene);
    let run = judge::run_candidate(scene, &reference, candidate);
    (reference, run)
}

/// The samples whose count or owner differ, as "(x,y) reference
/// count/owner NAME count/owner", at most 12; "(x,y)#s" names sample slot s
/// of a multisampled frame. Frames of other sample counts (an area method's
/// resolved-only frame) have no samples to compare.
pub fn differences(reference: &Frame, candidate: &Frame, name: &str) -> Vec<String> {
    mismatched_samples(reference, candidate)
        .into_iter()
        .take(12)
        .map(|i| {
            format!(
                "{} reference {}/{} {name} {}/{}",
                sample_name(reference, i),
                reference.coverage[i],
                reference.last[i],
                candidate.coverage[i],
                candidate.last[i]
            )
        })
        .collect()
}

/// Every sample slot whose count or owner differ (none when the frames'
/// sample counts differ).
pub fn mismatched_samples(reference: &Frame, candidate: &Frame) -> Vec<usize> {
    if reference.samples != candidate.samples
        || reference.sample_count() != candidate.sample_count()
    {
        return Vec::new();
    }
    (0..reference.sample_count())
        .filter(|&i| {
            reference.coverage[i] != candidate.coverage[i] || reference.last[i] != candidate.last[i]
        })
        .collect()
}

/// Slot i as "(x,y)", or "(x,y)#s" in a frame of several samples per pixel.
pub fn sample_name(frame: &Frame, i: usize) -> String {
    let n = frame.samples.max(1) as usize;
    let (p, s) = (i / n, i % n);
    let (x, y) = (p as u32 % frame.width, p as u32 / frame.width);
    if n == 1 {
        format!("({x},{y})")
    } else {
        format!("({x},{y})#{s}")
    }
}

/// One line per case: verdict, metrics, and the first differing samples.
pub fn report(id: &str, reference: &oracle::ReferenceRun, run: &CandidateRun) -> String {
    let diffs = run
        .frame
        .as_ref()
        .map(|f| differences(&reference.frame, f, &run.rasterizer))
        .unwrap_or_default();
    format!(
        "{:<5} {id}: {}{}",
        run.verdict.label(),
        judge::describe(run),
        if diffs.is_empty() {
            String::new()
        } else {
            format!("\n        {}", diffs.join("; "))
        }
    )
}

/// SplitMix64, as the patterns use: every test replays from its seed.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in lo..=hi.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }

    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.next() as usize % items.len()]
    }
}
