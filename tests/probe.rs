//! `probe` recovers each rasterizer's conventions from its frames alone, and
//! `run --profile` judges a rasterizer under the fill rule it declares.

mod common;

use common::{rastercheck, text};
use std::path::{Path, PathBuf};

use rastercheck::explore::probe::{self, Profile, SamplerKind};
use rastercheck::registry;

fn probe_of(name: &str) -> Profile {
    let r = registry::by_name(name).unwrap_or_else(|| panic!("no rasterizer {name}"));
    let p = probe::probe(r.as_ref()).unwrap_or_else(|e| panic!("{name}: {e}"));
    eprintln!("{}", p.describe());
    p
}

#[test]
fn production_is_top_left_exact_and_centred() {
    let p = probe_of("production");
    assert_eq!(p.sampler, SamplerKind::Point);
    assert_eq!(p.fill_rule.as_deref(), Some("top-left"));
    assert!(p.fill_rule_consistent);
    assert_eq!(p.y_down, Some(true));
    assert_eq!(p.subpixel_bits, None);
    assert_eq!(p.subpixel, "exact");
    assert_eq!(p.sample_offset, Some([0.5, 0.5]));
    assert!(p
        .interpolation
        .iter()
        .all(|i| i.status == "measured" && i.channels.iter().all(|c| c.within_bound)));
    // The only departure is keeping more than D3D11's 8 bits.
    assert_eq!(p.departures.len(), 1, "{:?}", p.departures);
}

#[test]
fn mutants_show_their_tie_rules() {
    let flipped = probe_of("mutant:flipped-ties");
    assert_eq!(flipped.sampler, SamplerKind::Point);
    assert_eq!(flipped.fill_rule.as_deref(), Some("bottom-right"));
    assert!(flipped.fill_rule_consistent);
    let closed = probe_of("mutant:closed-edges");
    assert_eq!(closed.sampler, SamplerKind::Point);
    assert_eq!(closed.fill_rule.as_deref(), Some("all-edges"));
    assert!(closed.fill_rule_consistent);
    assert!(closed.departures[0].contains("drawn twice"));
}

#[cfg(feature = "tiny-skia")]
#[test]
fn tiny_skia_is_bottom_right_on_most_slopes_on_a_64th_grid() {
    let p = probe_of("tiny-skia");
    assert_eq!(p.sampler, SamplerKind::Point);
    assert_eq!(p.fill_rule.as_deref(), Some("bottom-right"));
    // Its edges step in fixed point: on slopes ±3/2 and ±3 ties go the
    // other way (the tie meshes of every slope, SPEC.md §13).
    assert!(!p.fill_rule_consistent);
    assert_eq!(p.tie_verdict, "inconsistent");
    let mut slopes: Vec<&str> = p.tie_slopes.iter().map(|s| s.slope.as_str()).collect();
    slopes.sort_unstable();
    assert_eq!(slopes, ["-3", "-3/2", "3", "3/2"]);
    assert_eq!(p.subpixel_bits, Some(6), "{}", p.subpixel);
    assert_eq!(p.y_down, Some(true));
    assert_eq!(p.sample_position, "centre");
    assert!(p.interpolation.iter().all(|i| i.status == "unsupported"));
    assert!(p.departures.iter().any(|d| d.contains("6 subpixel bits")));
}

#[cfg(feature = "euc")]
#[test]
fn euc_is_all_edges_but_not_consistently() {
    let p = probe_of("euc");
    assert_eq!(p.sampler, SamplerKind::Point);
    assert_eq!(p.fill_rule.as_deref(), Some("all-edges"));
    // Its f32 barycentrics miss some samples of its own closed rule.
    assert!(!p.fill_rule_consistent);
    assert!(p.departures.iter().any(|d| d.contains("not consistent")));
    assert_eq!(p.sample_position, "centre");
}

#[cfg(feature = "lavapipe")]
#[test]
fn lavapipe_is_top_left_with_8_bits() {
    if let Err(why) = rastercheck::adapters::lavapipe::adapter_description() {
        eprintln!("skipped: no Vulkan adapter (install mesa-vulkan-drivers libvulkan1): {why}");
        return;
    }
    let p = probe_of("lavapipe");
    assert_eq!(p.sampler, SamplerKind::Point);
    assert_eq!(p.fill_rule.as_deref(), Some("top-left"));
    assert!(p.fill_rule_consistent);
    assert_eq!(p.subpixel_bits, Some(8), "{}", p.subpixel);
    assert_eq!(p.sample_position, "centre");
    assert_eq!(p.y_down, Some(true));
}

#[cfg(not(feature = "lavapipe"))]
#[test]
fn lavapipe_is_top_left_with_8_bits() {
    eprintln!("skipped: built without the lavapipe feature");
}

/// A rasterizer that is not point-sampled gets no fill rule, subpixel bits
/// or sample position: "not applicable", never an invented one.
fn assert_not_point(p: &Profile, kind: SamplerKind, words: &str) {
    assert_eq!(p.sampler, kind, "{}", p.sampler_evidence);
    assert_eq!(p.fill_rule, None);
    assert!(!p.fill_rule_consistent);
    assert!(p.fill_rule_evidence.is_empty());
    assert_eq!(p.subpixel_bits, None);
    assert!(p.subpixel.starts_with("not applicable"), "{}", p.subpixel);
    assert_eq!(p.subpixel_resolved.x, None);
    assert_eq!(p.sample_offset, None);
    assert!(
        p.sample_position.starts_with("not applicable"),
        "{}",
        p.sample_position
    );
    let shown = p.describe();
    assert!(shown.contains(words), "{shown}");
    assert!(!shown.contains("bits ("), "{shown}");
    assert!(p.departures[0].contains(words), "{:?}", p.departures);
}

#[test]
fn the_area_foil_is_an_area_sampler_with_no_rule_or_bits() {
    let p = probe_of("foil-area-sampler");
    assert_not_point(&p, SamplerKind::Area, "not point-sampled (area sampler)");
    assert_eq!(p.y_down, Some(true));
}

#[test]
fn the_any_coverage_foil_is_any_coverage_not_closed_edges() {
    let p = probe_of("foil-any-coverage");
    assert_not_point(
        &p,
        SamplerKind::AnyCoverage,
        "not point-sampled (any-coverage)",
    );
    assert!(!p.departures.iter().any(|d| d.contains("closed edges")));
}

#[test]
fn an_area_method_that_draws_antialiased_scenes_only_is_an_area_sampler() {
    // area-f32 refuses single-sample scenes; its antialiased frames hold
    // resolved coverage only.
    let p = probe_of("area-f32");
    assert_not_point(&p, SamplerKind::Area, "not point-sampled (area sampler)");
    assert!(p.sampler_evidence.contains("antialiased"));
}

#[cfg(feature = "vello")]
#[test]
fn vello_is_an_area_sampler() {
    // vello_cpu refuses single-sample scenes (it has no pixel-centre mode)
    // and answers antialiased ones with exact-area coverage only.
    let p = probe_of("vello-cpu");
    assert_not_point(&p, SamplerKind::Area, "not point-sampled (area sampler)");
}

#[test]
fn a_sample_outside_the_pixel_is_found_and_not_read_as_a_rule() {
    let p = probe_of("foil-offset-sampler");
    assert_eq!(p.sampler, SamplerKind::Point);
    assert_eq!(p.sample_offset, Some([1.0, 1.0]));
    assert!(
        p.sample_position.starts_with("(1, 1) of the pixel"),
        "{}",
        p.sample_position
    );
    // Its raster is production's shifted by half a pixel: read against the
    // reference's centre samples moved by the same, its ties are top-left
    // and it keeps every bit, as production does.
    assert_eq!(p.fill_rule.as_deref(), Some("top-left"));
    assert!(p.fill_rule_consistent);
    assert!(p
        .fill_rule_evidence
        .iter()
        .all(|e| e.off_edge_differences == 0));
    assert_eq!(p.subpixel, "exact");
    assert_eq!(p.y_down, Some(true));
    assert!(p
        .departures
        .iter()
        .any(|d| d.starts_with("Sample position: (1, 1) of the pixel")));
}

#[test]
fn the_python_example_is_point_sampled_with_closed_edges() {
    let p = probe_of(rastercheck::registry::PYTHON_EXAMPLE);
    assert_eq!(p.sampler, SamplerKind::Point);
    assert_eq!(p.fill_rule.as_deref(), Some("all-edges"));
    assert!(p.fill_rule_consistent);
    assert_eq!(p.sample_position, "centre");
    assert_eq!(p.y_down, Some(true));
}

/// `rastercheck probe -r NAME --out FILE`: what it printed, and the
/// profile it wrote.
fn probe_into(dir: &Path, name: &str, file: &Path) -> (String, serde_json::Value) {
    let out = rastercheck(dir, &["probe", "-r", name, "--out", file.to_str().unwrap()]);
    assert!(out.status.success(), "{}", text(&out));
    let written = serde_json::from_str(&std::fs::read_to_string(file).unwrap()).unwrap();
    (text(&out), written)
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rastercheck-probe-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[cfg(feature = "tiny-skia")]
#[test]
fn run_with_a_profile_judges_tiny_skia_by_its_own_rule() {
    let dir = temp("tiny-skia");
    let case =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/triangles/shared_edge_vertical.json");
    let case = case.to_str().unwrap();
    let profile = dir.join("tiny-skia.json");
    let (shown, written) = probe_into(&dir, "tiny-skia", &profile);
    assert!(shown.contains("bottom-right"), "{shown}");
    assert_eq!(written["schema"], "rastercheck-profile/1");
    assert_eq!(written["rasterizer"], "tiny-skia");
    assert_eq!(written["fill_rule"], "bottom-right");
    assert_eq!(written["subpixel_bits"], 6);

    // A top-left tie case: tiny-skia fails it as written...
    let plain = rastercheck(&dir, &["run", case, "-r", "tiny-skia"]);
    assert_eq!(plain.status.code(), Some(1), "{}", text(&plain));
    assert!(text(&plain).contains("FAIL"), "{}", text(&plain));
    // ...and passes it under its declared rule.
    let judged = rastercheck(
        &dir,
        &[
            "run",
            case,
            "-r",
            "tiny-skia",
            "--profile",
            profile.to_str().unwrap(),
        ],
    );
    assert_eq!(judged.status.code(), Some(0), "{}", text(&judged));
    // Its ties go by slope, so the profile declares no tie rule.
    assert!(
        text(&judged).contains("declares no tie rule"),
        "{}",
        text(&judged)
    );
    assert!(text(&judged).contains("PASS"), "{}", text(&judged));
    // Without -r, the profile's rasterizer is run; production is untouched
    // when it runs beside it.
    let both = rastercheck(
        &dir,
        &[
            "run",
            case,
            "-r",
            "production",
            "-r",
            "tiny-skia",
            "--profile",
            profile.to_str().unwrap(),
        ],
    );
    assert_eq!(both.status.code(), Some(0), "{}", text(&both));
    let alone = rastercheck(&dir, &["run", case, "--profile", profile.to_str().unwrap()]);
    assert!(
        text(&alone).contains("tiny-skia: 1 passed"),
        "{}",
        text(&alone)
    );
}

#[test]
fn an_area_samplers_profile_says_so_and_declares_no_rule() {
    let dir = temp("area");
    let profile = dir.join("area.json");
    let (_, written) = probe_into(&dir, "foil-area-sampler", &profile);
    assert_eq!(written["schema"], "rastercheck-profile/1");
    assert_eq!(written["sampler"], "area");
    assert!(written["fill_rule"].is_null());
    assert!(written["subpixel_bits"].is_null());
    assert!(written["sample_offset"].is_null());
    // `run --profile` has no rule to judge it by: bad input, saying why.
    let case =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/triangles/shared_edge_vertical.json");
    let run = rastercheck(
        &dir,
        &[
            "run",
            case.to_str().unwrap(),
            "--profile",
            profile.to_str().unwrap(),
        ],
    );
    assert_eq!(run.status.code(), Some(2), "{}", text(&run));
    assert!(text(&run).contains("$.fill_rule"), "{}", text(&run));
    assert!(text(&run).contains("area"), "{}", text(&run));
}

#[test]
fn bad_profiles_are_bad_input() {
    let dir = temp("bad");
    let case =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/triangles/shared_edge_vertical.json");
    let case = case.to_str().unwrap();
    let file = dir.join("p.json");
    for (content, phrase) in [
        ("not json", "not JSON"),
        (r#"{"schema": "other"}"#, "$.schema"),
        (
            r#"{"schema": "rastercheck-profile/1", "rasterizer": "production", "fill_rule": "nothing"}"#,
            "$.fill_rule",
        ),
    ] {
        std::fs::write(&file, content).unwrap();
        let out = rastercheck(&dir, &["run", case, "--profile", file.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(2), "{}", text(&out));
        assert!(text(&out).contains(phrase), "{phrase}: {}", text(&out));
    }
    std::fs::write(
        &file,
        r#"{"schema": "rastercheck-profile/1", "rasterizer": "mutant:flipped-ties", "fill_rule": "top-left"}"#,
    )
    .unwrap();
    let out = rastercheck(
        &dir,
        &[
            "run",
            case,
            "-r",
            "production",
            "--profile",
            file.to_str().unwrap(),
        ],
    );
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(text(&out).contains("does not check"), "{}", text(&out));
}
