//! The report of a run with moving scenes (SPEC.md §10, §15.4), without
//! the oracle: the outcomes are built in process from the sliding square's
//! exact time coverage (tests/sliding), then the whole report folder is
//! written and read back: `report.json`'s time metrics, the EXR `time`
//! layer, the PNGs, the HTML cards, `summary.md`, `junit.xml`, and a
//! baseline that a worse time error regresses.

mod common;
mod sliding;

use std::path::{Path, PathBuf};

use serde_json::Value;

use common::cli::exr_channel;
use rastercheck::frame::Frame;
use rastercheck::harness::baseline::{Baseline, Change, Observed, SelectionInfo};
use rastercheck::harness::discover::CaseFile;
use rastercheck::harness::golden::GoldenStatus;
use rastercheck::harness::runner::{CaseOutcome, Selection};
use rastercheck::harness::{judge, oracle};
use rastercheck::plan::Plan;
use rastercheck::production::mutants::{Mutant, Mutation};
use rastercheck::rasterizer::Rasterizer;
use rastercheck::report::json::{CaseEntry, LimitsInfo, RasterizerInfo, Report};
use rastercheck::report::{self, png};
use rastercheck::scene::{Limits, Scene};
use sliding::{Given, Slide};

fn sampler(slide: &Slide) -> Box<dyn Rasterizer + '_> {
    Box::new(Given("sampler", move |s: &Scene, p: &Plan| {
        slide.sampled(s, p)
    }))
}

/// Every case run by the honest sampler and the two motion mutants, the
/// case files written under `dir/cases`.
fn outcomes(dir: &Path, slides: &[Slide]) -> Vec<CaseOutcome> {
    slides
        .iter()
        .map(|slide| {
            let path = dir.join(format!("cases/motion/{}.json", slide.name));
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(&path, slide.json()).unwrap();
            let scene = slide.scene();
            let reference = oracle::run_reference_with(&scene, |_, plan| slide.exact(plan));
            let candidates: Vec<Box<dyn Rasterizer + '_>> = vec![
                sampler(slide),
                Box::new(Mutant(Mutation::MotionAtOpen)),
                Box::new(Mutant(Mutation::MotionHalfShutter)),
            ];
            let runs = candidates
                .iter()
                .map(|c| judge::run_candidate(&scene, &reference, c.as_ref()))
                .collect();
            CaseOutcome {
                file: CaseFile {
                    id: format!("motion/{}", slide.name),
                    path,
                },
                scene: Some(scene),
                problem: None,
                reference: Some(reference),
                golden: Some(GoldenStatus::Matches),
                candidates: runs,
                hash: None,
            }
        })
        .collect()
}

const NAMES: [&str; 3] = [
    "sampler",
    "mutant:motion-at-open",
    "mutant:motion-half-shutter",
];

fn write_report(dir: &Path, outcomes: &[CaseOutcome]) -> (PathBuf, Value) {
    let out = dir.join("report");
    let mut report = Report::new(
        vec!["run".into(), "cases".into()],
        NAMES
            .iter()
            .map(|n| RasterizerInfo {
                name: (*n).to_owned(),
                foil: false,
                declared: None,
                api_record: None,
            })
            .collect(),
        LimitsInfo::of(&Limits::default()),
    );
    report.cases = outcomes
        .iter()
        .map(|o| CaseEntry::from_outcome(o, &[false; 3]))
        .collect();
    report.complete = true;
    report::write_all(&out, &mut report, outcomes).expect("the report is written");
    let json = std::fs::read_to_string(out.join("report.json")).unwrap();
    (out, serde_json::from_str(&json).unwrap())
}

/// The text of every case page in the report folder `out`.
fn pages(out: &Path) -> String {
    let folder = out.join("pages/motion");
    let mut names: Vec<PathBuf> = std::fs::read_dir(&folder)
        .unwrap_or_else(|e| panic!("{}: {e}", folder.display()))
        .map(|e| e.unwrap().path())
        .collect();
    names.sort();
    names
        .iter()
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect()
}

fn slides() -> Vec<Slide> {
    vec![
        Slide {
            dx: 7,
            ..Slide::new("slide")
        },
        Slide {
            antialias: Some(4),
            expect: r#""max_time_error": 0.5"#.to_owned(),
            ..Slide::new("slide_aa4")
        },
    ]
}

fn scratch() -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("motion-report-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

#[test]
fn the_report_shows_time_coverage() {
    let dir = scratch();
    let slides = slides();
    let outcomes = outcomes(&dir, &slides);
    let (out, report) = write_report(&dir, &outcomes);

    for (case, slide) in report["cases"].as_array().unwrap().iter().zip(&slides) {
        let id = case["id"].as_str().unwrap();
        let mb = &case["rules"]["motion_blur"];
        assert_eq!(mb["shutter"], serde_json::json!([0.0, 1.0]), "{case}");
        assert_eq!(
            (mb["samples"].as_u64(), mb["moving"].as_u64()),
            (Some(16), Some(2))
        );
        assert_eq!(mb["pattern"], "stratified");
        let [sampler, at_open, half] = [0, 1, 2].map(|k| &case["results"][k]);
        assert_eq!(sampler["verdict"], "pass", "{sampler}");
        for mutant in [at_open, half] {
            assert_eq!(mutant["verdict"], "fail", "{mutant}");
            let reasons = mutant["reasons"].as_array().unwrap();
            assert!(
                reasons
                    .iter()
                    .all(|r| r.as_str().unwrap().starts_with("time: ")),
                "{reasons:?}"
            );
        }
        let t = &sampler["metrics"]["time"];
        assert_eq!(sampler["metrics"]["coverage"]["samples"], 0);
        assert_eq!(t["pixels"], 96);
        // The moving pixels are those the square passes over.
        assert_eq!(t["moving_pixels"], t["reference_pixels"], "{t}");
        assert!(t["moving_pixels"].as_u64().unwrap() >= 44, "{t}");
        assert!(t["max_error"].as_f64().unwrap() > 0.0, "{t}");
        let m = f64::from(slide.antialias.unwrap_or(1));
        let bound = 0.75 / (m * 16.0).sqrt();
        assert_eq!(t["allowed_rms"].as_f64(), Some(bound));
        let tests = &t["sample_tests"];
        assert_eq!(tests["tests"].as_f64(), Some(96.0 * m * 16.0));
        let efficiency = tests["covered"].as_f64().unwrap() / tests["tests"].as_f64().unwrap();
        assert_eq!(tests["efficiency"].as_f64(), Some(efficiency));
        assert!(at_open["metrics"]["time"].get("sample_tests").is_none());

        // Error maps: one layer, `time`, that agrees with the metrics.
        let plan = Plan::for_scene(&slide.scene());
        let exact: Vec<f32> = slide.exact_f64(&plan).iter().map(|&v| v as f32).collect();
        for (result, name) in case["results"].as_array().unwrap().iter().zip(NAMES) {
            let files: Vec<&str> = result["files"]
                .as_array()
                .unwrap()
                .iter()
                .map(|f| f.as_str().unwrap())
                .collect();
            let exr = files
                .iter()
                .find(|f| f.ends_with(".exr"))
                .unwrap_or_else(|| panic!("{id} {name}: no error map in {files:?}"));
            let image = exr::prelude::read_all_flat_layers_from_file(out.join(exr)).unwrap();
            assert_eq!(image.layer_data.len(), 1);
            let layer = &image.layer_data[0];
            assert_eq!(
                layer.attributes.layer_name.as_ref().map(|n| n.to_string()),
                Some("time".to_owned())
            );
            assert_eq!((layer.size.width(), layer.size.height()), (16, 6));
            let channel = |n: &str| exr_channel(layer, n, exr);
            assert_eq!(channel("time.exact"), exact, "{exr}");
            let largest = channel("time.error")
                .iter()
                .map(|e| f64::from(e.abs()))
                .fold(0.0, f64::max);
            let expected = result["metrics"]["time"]["max_error"].as_f64().unwrap();
            assert!((largest - expected).abs() <= expected * 1e-6, "{exr}");
            let candidate = channel("time.candidate");
            assert_eq!(candidate.len(), 96);
            // Pictures for the failures: exact, candidate, signed error.
            if result["verdict"] == "fail" {
                let file = name.replace(':', "-");
                for suffix in [
                    "/reference.png",
                    &format!("/{file}.png"),
                    &format!("/{file}.diff.png"),
                ] {
                    assert!(
                        files.iter().any(|f| f.ends_with(suffix)),
                        "{suffix} in {files:?}"
                    );
                }
            }
        }
    }

    // The pictures: greys for the exact time coverage, both outlines, and
    // for the square drawn at shutter open, too much on the left (red)
    // and too little on the right (blue).
    let folder = out.join("images/motion/slide");
    let reference = image::open(folder.join("reference.png")).unwrap().to_rgb8();
    assert!(reference
        .pixels()
        .any(|p| p.0[0] == p.0[1] && p.0[1] == p.0[2] && (40..220).contains(&p.0[0])));
    assert!(reference.pixels().any(|p| p.0 == png::EDGE_AT_CLOSE));
    let diff = image::open(folder.join("mutant-motion-at-open.diff.png"))
        .unwrap()
        .to_rgb8();
    assert!(diff.pixels().any(|p| p.0[0] > 200 && p.0[2] < 100), "red");
    assert!(diff.pixels().any(|p| p.0[2] > 200 && p.0[0] < 100), "blue");

    // The case pages: a time card per result (the sampler's error is not
    // zero), each with its three pictures and the time metrics.
    let html = pages(&out);
    let cards: Vec<&str> = html
        .split("<article")
        .skip(1)
        .filter(|c| c.contains("<h4>time coverage</h4>"))
        .collect();
    assert_eq!(cards.len(), 6, "{html}");
    for card in &cards {
        for role in ["reference", "candidate", "diff"] {
            assert!(
                card.contains(&format!(
                    "data-role=\"{role}\" src=\"data:image/png;base64,"
                )),
                "{role}"
            );
        }
        assert!(!card.contains("data-role=\"samples\""));
        assert!(card.contains("time coverage − exact") && card.contains("moving RMS"));
        assert!(
            !card.contains("<th colspan=\"2\">coverage</th>"),
            "no empty sample table"
        );
        assert!(card.contains("motion blur: 2 moving primitives, shutter [0, 1], 16 time samples"));
        assert!(card.contains("at shutter close"));
    }
    let sampler_card = cards
        .iter()
        .find(|c| c.contains("data-rasterizer=\"sampler\""))
        .unwrap();
    assert!(
        sampler_card.contains("sample tests covered"),
        "{sampler_card}"
    );
    assert!(sampler_card.contains("sample tests: covered / all"));

    let summary = std::fs::read_to_string(out.join("summary.md")).unwrap();
    let table = &summary[summary
        .find("## Worst time-coverage errors")
        .expect("a time table")..];
    let rows: Vec<&str> = table.lines().filter(|l| l.starts_with("| `")).collect();
    assert_eq!(rows.len(), 6, "{table}");
    assert!(rows[0].contains("mutant:motion-"), "{table}");
    assert!(rows.iter().any(|r| r.contains("| 4×16 |")), "{table}");
    let junit = std::fs::read_to_string(out.join("junit.xml")).unwrap();
    assert!(junit.contains("time: time-coverage RMS"), "{junit}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_worse_time_error_regresses_against_a_baseline() {
    let dir = scratch().with_extension("baseline");
    let slides = slides();
    let outcomes = outcomes(&dir, &slides);
    // The sampler recorded; then the mutants run under its name.
    let as_sampler = |k: usize| {
        let mut names = vec!["unused".to_owned(); 3];
        names[k] = "sampler".to_owned();
        let observed = Observed::from_outcomes(&outcomes, &names, &[false; 3]);
        Observed {
            entries: observed
                .entries
                .into_iter()
                .filter(|e| e.rasterizer == "sampler")
                .collect(),
            problems: observed.problems,
        }
    };
    let saved = Baseline::new(vec![], SelectionInfo::default(), &as_sampler(0));
    let metrics = &saved.results[0].metrics;
    for name in [
        "time.max_error",
        "time.rms_moving",
        "time.rms_all",
        "time.abs_bias",
    ] {
        assert!(metrics.contains_key(name), "{name} in {metrics:?}");
    }
    let names = ["sampler".to_owned()];
    let same = saved.compare(&as_sampler(0), &names, &Selection::default());
    assert_eq!(same.regressions(), 0, "{same:?}");
    for k in [1, 2] {
        let worse = saved.compare(&as_sampler(k), &names, &Selection::default());
        let regressed: Vec<&str> = worse
            .findings
            .iter()
            .filter(|f| f.change == Change::Regression)
            .map(|f| f.metric.as_str())
            .collect();
        for metric in [
            "verdict",
            "time.max_error",
            "time.rms_moving",
            "time.rms_all",
        ] {
            assert!(
                regressed.contains(&metric),
                "{k}: {metric} in {regressed:?}"
            );
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_frame_that_is_not_time_coverage_gets_no_time_pictures() {
    // A wrong-shaped frame is an error without metrics: no pictures, no
    // map, and the page still renders.
    let dir = scratch().with_extension("shape");
    let slide = Slide::new("slide");
    let mut outcomes = outcomes(&dir, std::slice::from_ref(&slide));
    let scene = outcomes[0].scene.clone().unwrap();
    let wrong = Given("sampler", |s: &Scene, _: &Plan| {
        Frame::new(s.canvas.width, s.canvas.height, false, 0)
    });
    outcomes[0].candidates[0] =
        judge::run_candidate(&scene, outcomes[0].reference.as_ref().unwrap(), &wrong);
    let (out, report) = write_report(&dir, &outcomes);
    let result = &report["cases"][0]["results"][0];
    assert_eq!(result["verdict"], "error", "{result}");
    assert!(result.get("files").is_none(), "{result}");
    let html = pages(&out);
    assert!(html.contains("needs a time coverage per pixel"));
    let _ = std::fs::remove_dir_all(&dir);
}
