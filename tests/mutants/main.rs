//! Every check can fail: for each one, a wrong rasterizer that it catches,
//! next to the production rasterizer passing the same case.

#[path = "../sliding/mod.rs"]
mod sliding;

mod antialias;
mod motion;
mod static_checks;

use rastercheck::harness::judge::{CandidateRun, Verdict};
use rastercheck::harness::{judge, oracle};
use rastercheck::rasterizer::Rasterizer;
use rastercheck::scene::{parse_case, Limits, Scene};

pub fn scene(json: &str) -> Scene {
    parse_case(json, "inline.json", &Limits::default()).expect("valid inline case")
}

pub fn run(scene: &Scene, candidate: &dyn Rasterizer) -> CandidateRun {
    let reference = oracle::run_reference(scene);
    judge::run_candidate(scene, &reference, candidate)
}

pub fn reasons(run: &CandidateRun) -> Vec<String> {
    match &run.verdict {
        Verdict::Fail(reasons) => reasons.clone(),
        other => panic!("{} should have failed, got {other:?}", run.rasterizer),
    }
}
