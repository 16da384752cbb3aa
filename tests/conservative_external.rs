//! Conservative rasterization for third parties (issue 38, SPEC.md
//! §12.11): the exact conservative example
//! (`examples/conservative_rasterizer.py`) is sent the case's conservative
//! state, and what it draws and flags comes back into the frame exactly;
//! its wrong variants (`--open`: misses pixels a triangle touches only at
//! a side or corner; `--too-much`: grows one 2^-8 step more than it
//! declares; `--flag-partial`: flags partly covered pixels) draw what the
//! classes forbid or miss what they require; a case asking for a mode or
//! flag the hello does not declare is refused unsent, naming the
//! declaration, and one stating another uncertainty is judged under the
//! program's own, said so and counted apart. Its depth (SPEC.md §19.9,
//! declared as `conservative.depth`) passes the depth cases, and its
//! wrong depths (`--depth-unclamped`, `--depth-first-vertex`) are caught
//! by the depth check. The drivers
//! here (lavapipe and SwiftShader through `vulkan`, llvmpipe through `gl`)
//! offer no conservative rasterization and refuse every conservative case
//! with the device's reason, under the validation layer with 0 messages.

mod common;

use std::collections::BTreeSet;

use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::rasterizer::RasterError;
use rastercheck::registry;
use rastercheck::scene::{parse_case, Limits, Scene};
use serde_json::{json, Value};

/// The example with `flags`.
fn example(flags: &str) -> String {
    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/conservative_rasterizer.py"
    );
    format!("external-persistent:python3 {script} {flags}")
}

fn scene(value: Value) -> Scene {
    parse_case(&value.to_string(), "test", &Limits::default()).unwrap()
}

/// A program read as a run reads it: its hello read once first (the
/// preflight), so that a slow start under load is waited for.
fn program(spec: &str) -> Box<dyn rastercheck::rasterizer::Rasterizer> {
    rastercheck::adapters::external::preflight(spec).unwrap();
    registry::by_name(spec).unwrap()
}

fn draw(flags: &str, scene: &Scene) -> Result<Frame, RasterError> {
    let r = program(&example(flags));
    r.rasterize(scene, &Plan::for_scene(scene))
}

/// The pixels a frame draws.
fn drawn(frame: &Frame) -> BTreeSet<(u32, u32)> {
    let mut out = BTreeSet::new();
    for y in 0..frame.height {
        for x in 0..frame.width {
            if frame.coverage[frame.index(x, y)] > 0 {
                out.insert((x, y));
            }
        }
    }
    out
}

/// The triangle (½, ½), (3½, ½), (½, 3½) on a 4 × 4 canvas: its closed
/// hypotenuse x + y = 4 touches pixels (3, 1), (2, 2) and (1, 3) at a
/// corner only; pixel (1, 1) alone lies inside it.
fn corner_scene(conservative: Value) -> Scene {
    scene(json!({
        "name": "corner", "canvas": {"width": 4, "height": 4},
        "rules": {"subpixel_bits": 8},
        "effects": {"conservative": conservative},
        "primitives": [{"triangle": [[0.5, 0.5], [3.5, 0.5], [0.5, 3.5]]}],
    }))
}

/// Every pixel with x + y ≤ 4: the 13 the triangle touches.
fn touched() -> BTreeSet<(u32, u32)> {
    (0..4)
        .flat_map(|y| (0..4).map(move |x| (x, y)))
        .filter(|(x, y)| x + y <= 4)
        .collect()
}

#[test]
fn the_example_draws_every_touched_pixel_and_flags_the_covered_one() {
    let s = corner_scene(json!({"mode": "overestimate", "fully_covered": true}));
    let frame = draw("", &s).unwrap();
    assert_eq!(drawn(&frame), touched());
    let flags = frame
        .fully_covered
        .as_ref()
        .expect("the flag was asked for");
    let flagged: Vec<usize> = (0..flags.len()).filter(|&i| flags[i]).collect();
    assert_eq!(flagged, vec![frame.index(1, 1)], "only (1, 1) lies inside");
    // Underestimation: (1, 1) alone.
    let under = draw("", &corner_scene(json!({"mode": "underestimate"}))).unwrap();
    assert_eq!(drawn(&under), BTreeSet::from([(1, 1)]));
}

/// `--open` misses the three corner pixels; `--flag-partial` flags all 13.
#[test]
fn the_wrong_variants_miss_corners_and_flag_partial_pixels() {
    let s = corner_scene(json!({"mode": "overestimate", "fully_covered": true}));
    let open = drawn(&draw("--open", &s).unwrap());
    let missing: BTreeSet<_> = touched().difference(&open).copied().collect();
    assert_eq!(missing, BTreeSet::from([(3, 1), (2, 2), (1, 3)]));
    let partial = draw("--flag-partial", &s).unwrap();
    let flags = partial.fully_covered.unwrap();
    assert_eq!(flags.iter().filter(|&&f| f).count(), 13);
}

/// A right edge 3/512 px left of column 3: within the declared 1/256 the
/// column may not be drawn; `--too-much` (1/256 + 1/256) draws it.
#[test]
fn growing_past_the_declared_uncertainty_draws_a_forbidden_column() {
    let edge = "1533/512"; // 3 − 3/512
    let s = scene(json!({
        "name": "gap", "canvas": {"width": 5, "height": 3},
        "rules": {"subpixel_bits": 16},
        "effects": {"conservative": {"mode": "overestimate", "uncertainty": "1/256"}},
        "primitives": [{"triangle": [[0.5, 0.5], [edge, 0.5], [edge, 2.5]]}],
    }));
    let right = |set: &BTreeSet<(u32, u32)>| set.iter().map(|p| p.0).max();
    let exact = drawn(&draw("--uncertainty 1/256", &s).unwrap());
    assert_eq!(right(&exact), Some(2));
    let much = drawn(&draw("--uncertainty 1/256 --too-much", &s).unwrap());
    assert_eq!(right(&much), Some(3), "grown by 2/256 ≥ 3/512");
}

/// A conservative case goes only to a program declaring it; one stating
/// another uncertainty than the program's is sent all the same (SPEC.md
/// §12.11, §19.6).
#[test]
fn a_case_asking_more_than_declared_is_refused_naming_it() {
    let tight = corner_scene(json!({"mode": "overestimate", "uncertainty": "1/512"}));
    let frame = draw("--uncertainty 1/256", &tight).expect("a tighter case is sent");
    assert_eq!(drawn(&frame), touched());
    let none = program(&format!(
        "external-persistent:python3 {}/examples/python_rasterizer.py",
        env!("CARGO_MANIFEST_DIR")
    ));
    let s = corner_scene(json!({"mode": "overestimate"}));
    match none.rasterize(&s, &Plan::for_scene(&s)) {
        Err(RasterError::Unsupported(why)) => {
            assert!(why.contains("capabilities.conservative"), "{why}")
        }
        other => panic!("{:?}", other.map(|_| ())),
    }
}

/// lavapipe and SwiftShader (`vulkan`) and llvmpipe (`gl`) refuse a
/// conservative case with the device's reason, under the Khronos
/// validation layer with 0 messages.
#[cfg(all(feature = "vulkan", feature = "gl"))]
#[test]
fn the_drivers_here_refuse_with_their_reason() {
    use common::cli::{rastercheck_env, read_json, scratch, text};
    let icd = "/usr/lib/chromium/vk_swiftshader_icd.json";
    let swiftshader = std::path::Path::new(icd).exists();
    if !swiftshader {
        common::adapters::skipped("SwiftShader", "chromium", "its ICD is not installed");
    }
    let dir = scratch("conservative_drivers");
    std::fs::create_dir_all(dir.join("cases")).unwrap();
    let case = json!({
        "name": "over", "canvas": {"width": 4, "height": 4},
        "effects": {"conservative": {"mode": "overestimate"}},
        "primitives": [{"triangle": [[0.5, 0.5], [3.5, 0.5], [0.5, 3.5]]}],
    });
    std::fs::write(dir.join("cases/over.json"), case.to_string()).unwrap();
    let mut args = vec!["run", "cases", "-r", "vulkan@llvmpipe", "-r", "gl"];
    if swiftshader {
        args.extend(["-r", "vulkan@swiftshader"]);
    }
    args.extend(["--report", "report"]);
    let out = rastercheck_env(
        &dir,
        &args,
        &[
            ("VK_ADD_DRIVER_FILES", icd),
            ("RASTERCHECK_VULKAN_VALIDATION", "1"),
        ],
    );
    let report = read_json(&dir.join("report/report.json"));
    let results = report["cases"][0]["results"].as_array().unwrap();
    for r in results {
        let name = r["rasterizer"].as_str().unwrap();
        assert_eq!(r["verdict"], "unsupported", "{name}: {}", text(&out));
        let why = r["reasons"].to_string();
        let expected = if name == "gl" {
            "offers neither GL_NV_conservative_raster nor GL_INTEL_conservative_rasterization"
        } else {
            "the device offers no VK_EXT_conservative_rasterization"
        };
        assert!(why.contains(expected), "{name}: {why}");
    }
    for r in report["rasterizers"].as_array().unwrap() {
        let record = &r["api_record"];
        assert_eq!(record["errors"], 0, "{r}");
        assert_eq!(record["warnings"], 0, "{r}");
    }
}

/// The example over `cases/conservative` (the verdict of SPEC.md §19.5,
/// through the binary, one thread): what it was built for, and each
/// wrong variant caught by its own check.
#[test]
fn the_example_passes_the_conservative_cases_and_each_foil_is_caught() {
    use common::cli::{rastercheck, read_json, scratch, text, verdicts};
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let run = |tag: &str, flags: &str| {
        let dir = scratch(&format!("conservative_example_{tag}"));
        let report = dir.join("report");
        let spec = format!(
            "example=external-persistent:python3 {}/examples/conservative_rasterizer.py {flags}",
            root.display()
        );
        let out = rastercheck(
            root,
            &[
                "run",
                "cases/conservative",
                "-r",
                &spec,
                "--threads",
                "1",
                "--report",
                report.to_str().unwrap(),
            ],
        );
        (
            verdicts(&read_json(&report.join("report.json"))),
            text(&out),
        )
    };
    let count = |v: &[(String, String, String)], verdict: &str| {
        v.iter().filter(|(_, w, _)| w == verdict).count()
    };
    let (exact, out) = run("exact", "");
    assert_eq!(count(&exact, "fail") + count(&exact, "error"), 0, "{out}");
    assert!(count(&exact, "pass") >= 40, "{out}");
    for (flags, reason) in [
        ("--open", "required pixel"),
        ("--too-much", "forbidden pixel"),
        ("--flag-partial", "fully-covered flag wrong"),
    ] {
        let (v, out) = run(flags.trim_start_matches("--"), flags);
        let caught: Vec<_> = v
            .iter()
            .filter(|(_, w, why)| w == "fail" && why.contains(reason))
            .map(|(id, _, _)| id.as_str())
            .collect();
        eprintln!("{flags}: {} caught ({reason}): {caught:?}", caught.len());
        assert!(!caught.is_empty(), "{flags}: {out}");
        assert_eq!(count(&v, "error"), 0, "{flags}: {out}");
    }
}

/// One rule for a declared uncertainty (SPEC.md §12.11, §19.6): a program
/// declaring 1/4 px that grows by 1/4 passes a case stating 1/256 under
/// its own conventions, said so in the console and `report.json` and
/// counted apart; one declaring 1/256 that grows by 1/4 fails it.
#[test]
fn a_declared_uncertainty_is_judged_under_and_said_so() {
    use common::cli::{rastercheck, read_json, scratch, text};
    let dir = scratch("conservative_declared_uncertainty");
    std::fs::create_dir_all(dir.join("cases")).unwrap();
    // A right edge 1/8 px left of column 3: a square grown by 1/4 reaches
    // it, one grown by 1/256 does not.
    let case = json!({
        "name": "gap", "canvas": {"width": 5, "height": 3},
        "rules": {"subpixel_bits": 8},
        "effects": {"conservative": {"mode": "overestimate", "uncertainty": "1/256"}},
        "primitives": [{"triangle": [[0.5, 0.5], ["23/8", 0.5], ["23/8", 2.5]]}],
    });
    std::fs::write(dir.join("cases/gap.json"), case.to_string()).unwrap();
    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/conservative_rasterizer.py"
    );
    let wide = format!("wide=external-persistent:python3 {script} --uncertainty 1/4 --grow 1/4");
    let liar = format!("liar=external-persistent:python3 {script} --uncertainty 1/256 --grow 1/4");
    let out = rastercheck(
        &dir,
        &[
            "run",
            "cases",
            "-r",
            &wide,
            "-r",
            &liar,
            "--threads",
            "1",
            "--report",
            "report",
        ],
    );
    let console = text(&out);
    let report = read_json(&dir.join("report/report.json"));
    let results = report["cases"][0]["results"].as_array().unwrap();
    let (wide, liar) = (&results[0], &results[1]);
    assert_eq!(wide["verdict"], "pass", "{console}");
    let under = wide["conservative"]["judged_under"].as_str().unwrap();
    assert_eq!(
        under,
        "overestimate, uncertainty 1/4 px, its own conventions; the case states overestimate, uncertainty 1/256 px"
    );
    assert_eq!(
        wide["conservative"]["case_states"],
        "overestimate, uncertainty 1/256 px"
    );
    assert!(
        wide["conservative"]["band_drawn"].as_u64().unwrap() > 0,
        "{wide}"
    );
    assert!(console.contains(under), "{console}");
    assert_eq!(liar["verdict"], "fail", "{console}");
    assert!(
        liar["reasons"].to_string().contains("forbidden pixel"),
        "{liar}"
    );
    assert!(liar["conservative"].get("case_states").is_none(), "{liar}");
    let line = console
        .lines()
        .find(|l| l.starts_with("wide: "))
        .unwrap_or_default();
    assert!(
        line.contains("1 passed") && line.contains("1 judged under its own conventions"),
        "{console}"
    );
}

/// The example's depth over the nine conservative depth cases (SPEC.md
/// §12.11, §19.9, through the binary): every one passes; storing the
/// plane unclamped fails the float32 case below 0 on its depth (and the
/// unorm16 one is an error: no unorm integer above 65535); the first
/// vertex's z everywhere fails a sloped plane's depth.
#[test]
fn the_example_gives_conservative_depth_and_wrong_depths_are_caught() {
    use common::cli::{rastercheck, read_json, scratch, text, verdicts};
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = scratch("conservative_example_depth");
    let cases = dir.join("cases");
    std::fs::create_dir_all(&cases).unwrap();
    for entry in std::fs::read_dir(root.join("cases/conservative")).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_str().unwrap().to_owned();
        if name.starts_with("depth_") {
            std::fs::copy(&path, cases.join(&name)).unwrap();
        }
    }
    let run = |tag: &str, flags: &str| {
        let report = dir.join(format!("report_{tag}"));
        let spec = format!(
            "example=external-persistent:python3 {}/examples/conservative_rasterizer.py {flags}",
            root.display()
        );
        let out = rastercheck(
            &dir,
            &[
                "run",
                "cases",
                "-r",
                &spec,
                "--report",
                report.to_str().unwrap(),
            ],
        );
        (
            verdicts(&read_json(&report.join("report.json"))),
            text(&out),
        )
    };
    let of = |v: &[(String, String, String)], case: &str| {
        v.iter()
            .find(|(id, _, _)| id.ends_with(case))
            .cloned()
            .unwrap_or_else(|| panic!("{case} not run: {v:?}"))
    };
    let (exact, out) = run("exact", "");
    assert_eq!(exact.len(), 9, "{out}");
    for (id, verdict, why) in &exact {
        assert_eq!(verdict, "pass", "{id}: {why}\n{out}");
    }
    let (unclamped, out) = run("unclamped", "--depth-unclamped");
    let (_, verdict, why) = of(&unclamped, "depth_clamp_float32_below");
    assert_eq!(verdict, "fail", "{out}");
    assert!(
        why.contains("conservative depth:") && why.contains("outside the depths float32 allows"),
        "{why}"
    );
    let (_, verdict, why) = of(&unclamped, "depth_clamp_unorm16");
    assert_eq!(verdict, "error", "{out}");
    assert!(why.contains("is not a unorm16 depth"), "{why}");
    let (first, out) = run("first_vertex", "--depth-first-vertex");
    let (_, verdict, why) = of(&first, "depth_inside");
    assert_eq!(verdict, "fail", "{out}");
    assert!(
        why.contains("conservative depth:") && why.contains("outside the depths"),
        "{why}"
    );
    for (flags, v) in [
        ("--depth-unclamped", &unclamped),
        ("--depth-first-vertex", &first),
    ] {
        let caught: Vec<_> = v
            .iter()
            .filter(|(_, w, _)| w != "pass")
            .map(|(id, w, _)| format!("{id} {w}"))
            .collect();
        eprintln!("{flags}: {} caught: {caught:?}", caught.len());
    }
}
