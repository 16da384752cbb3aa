//! The real drivers over every bundled case, twice (`run --repeat 2`,
//! other cases between a case's repetitions), on each implementation here:
//! lavapipe through `-r vulkan`, SwiftShader through `-r vulkan` with
//! `VK_DRIVER_FILES` on its ICD file (from Debian's chromium), llvmpipe
//! through `-r gl`. Two things are held:
//!
//! - determinism (SPEC.md §6.6): a FLAKY case fails the test unless a
//!   departure marked `Flaky: yes` names it;
//! - named departures (issue 35): every case that fails is named by a
//!   departure in `docs/drivers/departures/<implementation>/`, and every
//!   named case fails (`tests/common/departures.rs`);
//! - unsupported for the device's reasons (issue 35): every case left
//!   unsupported gives a reason that names a limit of the device or the
//!   API (a property or feature it lacks, a rule no mode draws, what the
//!   driver does), never one of the adapter's (`device_limit`).
//!
//! Without a driver each test says loudly that it skipped; under `CI=true`
//! a missing driver fails it instead (`tests/common/adapters.rs`).
//!
//! A case drawn through one adapter never depends on the case drawn
//! before it: a difference here is either state that survived from one
//! case to the next inside an adapter (ours to fix) or the driver's own
//! nondeterminism (written as a departure marked `Flaky: yes`).
#![cfg(any(feature = "vulkan", feature = "gl"))]

mod common;

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::Instant;

use common::cli::{rastercheck_env, read_json, scratch, text};
use common::departures;

/// SwiftShader's Vulkan ICD, as Debian's chromium package installs it.
const SWIFTSHADER_ICD: &str = "/usr/lib/chromium/vk_swiftshader_icd.json";

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Runs every bundled case twice through `rasterizer` under `env`, and
/// fails on a flaky case no flaky departure of `implementation` names, or
/// on a failure no departure names. Says SKIPPED (or fails, under CI) when
/// the binary found no such driver.
fn every_case_twice(implementation: &str, rasterizer: &str, env: &[(&str, &str)]) {
    let dir = scratch(&format!("driver-repeat-{implementation}"));
    let report = dir.join("report");
    let started = Instant::now();
    let out = rastercheck_env(
        &root(),
        &[
            "run",
            "cases",
            "-r",
            rasterizer,
            "--repeat",
            "2",
            "-q",
            "--report",
            &report.display().to_string(),
        ],
        env,
    );
    let printed = text(&out);
    eprintln!(
        "{implementation}: every bundled case twice in {:.0} s",
        started.elapsed().as_secs_f64()
    );
    if !report.join("report.json").exists() {
        common::adapters::skipped(
            &format!("{implementation} driver"),
            "mesa-vulkan-drivers libvulkan1 libegl1 chromium",
            &printed,
        );
        return;
    }
    let json = read_json(&report.join("report.json"));
    assert_eq!(json["complete"], true, "{printed}");
    let mut unknown = Vec::new();
    let mut adapter_side = Vec::new();
    let mut judged = 0;
    let mut verdicts = BTreeMap::new();
    for case in json["cases"].as_array().unwrap() {
        let id = case["id"].as_str().unwrap();
        let result = &case["results"][0];
        let verdict = result["verdict"].as_str().unwrap_or("not run");
        verdicts.insert(id.to_string(), verdict.to_string());
        judged += usize::from(!matches!(verdict, "unsupported" | "not run"));
        if verdict == "unsupported" {
            let why = result["reasons"][0].as_str().unwrap_or("");
            if !device_limit(why) {
                adapter_side.push(format!("{id}: {why}"));
            }
        }
        if verdict != "flaky" {
            continue;
        }
        match departures::flaky(implementation, id) {
            Some(why) => eprintln!("known flaky case {id} on {implementation}: {why}"),
            None => unknown.push(format!("{id}: {}", result["reasons"][0])),
        }
    }
    assert!(
        judged > 100,
        "{implementation} judged {judged} cases:\n{printed}"
    );
    assert!(
        unknown.is_empty(),
        "{implementation}: {} cases drew different frames on their two repetitions, and no known driver behaviour explains them:\n{}",
        unknown.len(),
        unknown.join("\n")
    );
    assert!(
        adapter_side.is_empty(),
        "{implementation}: {} cases are unsupported for a reason that names no limit of the device:\n{}",
        adapter_side.len(),
        adapter_side.join("\n")
    );
    assert!(printed.contains(" flaky over 2 repetitions"), "{printed}");
    departures::assert_every_failure_is_named(implementation, &verdicts);
}

/// Whether an unsupported reason names a limit of the device: a property
/// or feature it reports (or lacks), a rule no mode of its API draws, a
/// type its API takes, or what the driver was measured to do, and nothing
/// left unmeasured.
fn device_limit(why: &str) -> bool {
    const DEVICE: [&str; 14] = [
        "the device",
        "the driver",
        "the Vulkan device",
        "Mesa",
        "no Vulkan line mode",
        "no GL mode",
        "GL's wide aliased lines",
        "strictLines",
        "wideLines",
        "pointSizeGranularity",
        "largePoints",
        "subPixelPrecisionBits",
        "stencil attachment format",
        "the type the Vulkan device takes",
    ];
    !why.contains("unmeasured") && DEVICE.iter().any(|word| why.contains(word))
}

#[test]
fn an_unsupported_reason_must_name_the_device() {
    assert!(device_limit(
        "parallelogram line: the device has strictLines: its DEFAULT lines are rectangles"
    ));
    assert!(device_limit(
        "midpoint line: no Vulkan line mode draws the midpoint rule"
    ));
    assert!(device_limit(
        "conservative rasterization: the device offers no VK_EXT_conservative_rasterization"
    ));
    assert!(device_limit(
        "conservative rasterization: the driver, llvmpipe (LLVM 15.0.6, 256 bits), offers \
         neither GL_NV_conservative_raster nor GL_INTEL_conservative_rasterization"
    ));
    // The reason this file's check was written against: the adapter's.
    assert!(!device_limit(
        "a point of size 4 whose square reaches outside a viewport rectangle with an edge off \
         the pixel grid: where Mesa cuts the square there is unmeasured (SPEC.md §17.4)"
    ));
    assert!(!device_limit(
        "4 attributes (this adapter carries at most 3)"
    ));
}

#[cfg(feature = "vulkan")]
#[test]
fn lavapipe_draws_every_case_the_same_twice_and_fails_only_named_departures() {
    every_case_twice("lavapipe", "vulkan", &[]);
}

#[cfg(feature = "vulkan")]
#[test]
fn swiftshader_draws_every_case_the_same_twice_and_fails_only_named_departures() {
    if !std::path::Path::new(SWIFTSHADER_ICD).exists() {
        common::adapters::skipped(
            "SwiftShader Vulkan ICD",
            "chromium",
            &format!("{SWIFTSHADER_ICD} is missing"),
        );
        return;
    }
    every_case_twice(
        "swiftshader",
        "vulkan",
        &[("VK_DRIVER_FILES", SWIFTSHADER_ICD)],
    );
}

#[cfg(feature = "gl")]
#[test]
fn llvmpipe_draws_every_case_the_same_twice_and_fails_only_named_departures() {
    every_case_twice("llvmpipe", "gl", &[]);
}
