//! Depth formats and polygon offset (SPEC.md §18): the reference's allowed
//! sets judged against wrong rasterizers, production inside them on random
//! triangles, the square root's certificate, the reader's errors and the
//! adapters' refusal.
//!
//! The wrong rasterizers are frames built here: the exact depth (from the
//! reference drawing the scene without its depth rules) put through a
//! wrong offset or a wrong store, on the reference's coverage, so that
//! depth is the only thing that differs.

mod common;

use common::{case, inline, Rng};
use dashu_ratio::RBig;
use rastercheck::frame::Frame;
use rastercheck::metrics::{self, Known};
use rastercheck::plan::Plan;
use rastercheck::production::depth::stored;
use rastercheck::production::Production;
use rastercheck::rasterizer::{Capabilities, Rasterizer};
use rastercheck::reference::depth::{sqrt_bounds, SQRT_BITS};
use rastercheck::reference::{self, Arithmetic};
use rastercheck::scene::depth::unorm_value;
use rastercheck::scene::{parse_case, DepthFormat, Limits, Scene};

/// Why `candidate` fails `scene` against the reference's allowed depths;
/// empty when it passes.
fn failures(scene: &Scene, candidate: &Frame) -> Vec<String> {
    let plan = Plan::for_scene(scene);
    let (reference, allowed) = reference::render_judged(scene, &plan, Arithmetic::Auto);
    let known = Known {
        depth_allowed: allowed.as_deref(),
        ..Known::default()
    };
    let m = metrics::measure_known(scene, &reference, candidate, &known);
    metrics::failures(scene, &reference, &m)
}

/// The reference's frame of `scene` without its depth rules: coverage as
/// the scene's, depth the exact one rounded once.
fn exact_depth(scene: &Scene) -> Frame {
    let mut plain = scene.clone();
    plain.rules.depth_format = DepthFormat::Exact;
    plain.rules.depth_bias = None;
    reference::render(&plain, &Plan::for_scene(&plain))
}

/// A candidate that adds `offset` to the exact depth of every triangle
/// sample and stores it with `store`.
fn candidate(scene: &Scene, offset: f64, store: impl Fn(f64) -> f64) -> Frame {
    let mut frame = exact_depth(scene);
    let depth = frame.depth.as_mut().expect("depth");
    for (z, &last) in depth.iter_mut().zip(&frame.last) {
        if last > 0 {
            *z = store(*z + offset);
        }
    }
    frame
}

fn flat(format: &str, z: &str, extra: &str) -> Scene {
    inline(&format!(
        r#"{{"name": "flat", "canvas": {{"width": 8, "height": 8}},
            "rules": {{"depth_format": "{format}"{extra}}},
            "primitives": [{{"triangle": [{{"position": [0, 0], "z": "{z}"}},
                {{"position": [8, 0], "z": "{z}"}}, {{"position": [0, 8], "z": "{z}"}}]}}],
            "expect": {{"max_abs_error": 0}}}}"#
    ))
}

#[test]
fn bundled_depth_cases_pass_production() {
    for id in [
        "depth/spec_depth_unorm16_on_grid",
        "depth/spec_offset_slope_45",
        "depth/spec_offset_clip",
        "depth/offset_line_ignored",
    ] {
        let scene = case(id);
        let frame = Production
            .rasterize(&scene, &Plan::for_scene(&scene))
            .unwrap();
        assert_eq!(failures(&scene, &frame), Vec::<String>::new(), "{id}");
    }
}

/// Which quantizers the exact rule catches on unorm16 with no tolerance:
/// at z = (k + 0.7)/N, Vulkan allows k or k + 1 ("one of the two
/// integers closest"), so round-to-nearest and floor both pass; k − 1,
/// k + 2, an unquantized depth and a 2^16-step grid do not.
#[test]
fn quantizers_outside_the_two_nearest_or_off_the_grid_are_caught() {
    let n = 65535.0;
    let k = 40000.0;
    let scene = flat("unorm16", "400007/655350", "");
    let grid = |k: f64| f64::from(unorm_value(k as u32, 16));
    let nearest = candidate(&scene, 0.0, |z| stored(DepthFormat::Unorm16, z));
    assert!(failures(&scene, &nearest).is_empty());
    let floor = candidate(&scene, 0.0, |z| grid((z * n).floor()));
    assert!(
        failures(&scene, &floor).is_empty(),
        "floor is one of the two nearest"
    );
    for (name, wrong) in [
        ("one below", candidate(&scene, 0.0, |_| grid(k - 1.0))),
        ("two above", candidate(&scene, 0.0, |_| grid(k + 2.0))),
        (
            "not quantized",
            candidate(&scene, 0.0, |z| f64::from(z as f32)),
        ),
        (
            "2^16 steps",
            candidate(&scene, 0.0, |z| {
                f64::from(((z * 65536.0).round() / 65536.0) as f32)
            }),
        ),
    ] {
        let why = failures(&scene, &wrong);
        assert!(
            why.iter().any(|w| w.contains("unorm16")),
            "{name} passed: {why:?}"
        );
    }
}

/// The golden value of a half-way depth is the upper neighbour; both
/// neighbours are allowed.
#[test]
fn half_way_allows_both_neighbours() {
    let scene = case("depth/spec_depth_unorm16_half_way");
    let plan = Plan::for_scene(&scene);
    let (frame, allowed) = reference::render_judged(&scene, &plan, Arithmetic::Auto);
    let allowed = allowed.unwrap();
    let [lo, hi] = [32768, 32769].map(|k| f64::from(unorm_value(k, 16)));
    assert_eq!(frame.depth.as_ref().unwrap()[0], hi);
    assert_eq!(allowed[0], [lo, hi]);
    for k in [32767u32, 32770] {
        let wrong = candidate(&scene, 0.0, |_| f64::from(unorm_value(k, 16)));
        assert!(!failures(&scene, &wrong).is_empty(), "k = {k}");
    }
}

/// Polygon offset: m anywhere in [m_max, m_sqrt] and r in [2^-16, 2^-15]
/// pass; r 4 times too large, the wrong sign and an ignored clamp fail.
#[test]
fn wrong_offsets_are_caught() {
    // z = (x + y)/64: m_max = 1/64, m_sqrt = √2/64; slope 1/2, constant 8.
    let json = |clamp: &str| {
        format!(
            r#"{{"name": "o", "canvas": {{"width": 16, "height": 16}},
            "rules": {{"depth_format": "unorm16", "depth_bias": {{"slope": "1/2", "constant": 8, "clamp": {clamp}}}}},
            "primitives": [{{"triangle": [{{"position": [0, 0], "z": 0}},
                {{"position": [16, 0], "z": "1/4"}}, {{"position": [0, 16], "z": "1/4"}}]}}],
            "expect": {{"max_abs_error": 0}}}}"#
        )
    };
    let scene = inline(&json("0"));
    let store = |z| stored(DepthFormat::Unorm16, z);
    let (m_max, m_sqrt) = (1.0 / 64.0, 2f64.sqrt() / 64.0);
    let r = [2f64.powi(-16), 2f64.powi(-15)];
    for m in [m_max, m_sqrt] {
        for r in r {
            let right = candidate(&scene, m / 2.0 + 8.0 * r, store);
            assert!(failures(&scene, &right).is_empty(), "m = {m}, r = {r}");
        }
    }
    let four_r = candidate(&scene, m_sqrt / 2.0 + 8.0 * 4.0 * r[1], store);
    assert!(!failures(&scene, &four_r).is_empty(), "r 4 times too large");
    let sign = candidate(&scene, -(m_max / 2.0 + 8.0 * r[0]), store);
    assert!(!failures(&scene, &sign).is_empty(), "the wrong sign");
    let none = candidate(&scene, 0.0, store);
    assert!(!failures(&scene, &none).is_empty(), "no offset");
    // Clamped to 2^-10, below every unclamped offset (at least 1/128).
    let clamped = inline(&json("\"1/1024\""));
    let ignored = candidate(&clamped, m_max / 2.0 + 8.0 * r[0], store);
    assert!(
        !failures(&clamped, &ignored).is_empty(),
        "the clamp ignored"
    );
    let honoured = candidate(&clamped, 1.0 / 1024.0, store);
    assert!(failures(&clamped, &honoured).is_empty());
}

/// The constant's r for float32 is 2^(e−23) or 2^(e−22): 4 times either
/// is caught.
#[test]
fn float32_r_follows_the_exponent() {
    let scene = flat("float32", "3/4", r#", "depth_bias": {"constant": 65536}"#);
    let scene = Scene {
        expect: Default::default(),
        ..scene
    };
    let store = |z: f64| f64::from(z.clamp(0.0, 1.0) as f32);
    // e = −1: r in [2^-24, 2^-23], so o in [2^-8, 2^-7].
    for o in [2f64.powi(-8), 2f64.powi(-7)] {
        assert!(failures(&scene, &candidate(&scene, o, store)).is_empty());
    }
    let four = candidate(&scene, 4.0 * 2f64.powi(-7), store);
    assert!(!failures(&scene, &four).is_empty());
}

#[test]
fn square_root_certificates_hold() {
    let mut rng = Rng(21);
    for _ in 0..500 {
        let p = rng.range(0, 1 << 40);
        let q = rng.range(1, 1 << 30);
        let x = RBig::from_parts(p.into(), (q as u64).into());
        let [lo, hi] = sqrt_bounds(&x);
        assert!(&lo * &lo <= x && x <= &hi * &hi);
        // x in lowest terms: its denominator divides q.
        let width = RBig::from_parts(
            1.into(),
            (dashu_int::UBig::ONE << SQRT_BITS) * x.denominator(),
        );
        assert!(&hi - &lo <= width);
    }
}

/// Production's depth lies in the reference's allowed set on random
/// triangles, formats and offsets, in screen and clip space.
#[test]
fn production_is_inside_the_allowed_set_on_random_triangles() {
    let mut rng = Rng(0xdead_beef);
    let formats = ["unorm16", "unorm24", "float32"];
    let mut judged = 0;
    for round in 0..300 {
        let format = rng.pick(&formats);
        let bias = match rng.range(0, 3) {
            0 => String::new(),
            _ => format!(
                r#", "depth_bias": {{"constant": {}, "slope": "{}/8", "clamp": "{}/4096"}}"#,
                rng.range(-200, 200),
                rng.range(-32, 32),
                rng.range(-8, 8) * rng.range(0, 1)
            ),
        };
        let clip = round % 5 == 0;
        let vertex = |rng: &mut Rng| {
            if clip {
                let w = rng.range(64, 256);
                format!(
                    r#"{{"clip": ["{}/128", "{}/128", "{}/128", "{w}/128"]}}"#,
                    rng.range(-w, w),
                    rng.range(-w, w),
                    rng.range(0, w)
                )
            } else {
                format!(
                    r#"{{"position": ["{}/16", "{}/16"], "z": "{}/256"}}"#,
                    rng.range(0, 256),
                    rng.range(0, 256),
                    rng.range(-64, 320)
                )
            }
        };
        let v: Vec<String> = (0..3).map(|_| vertex(&mut rng)).collect();
        let json = format!(
            r#"{{"name": "r{round}", "canvas": {{"width": 16, "height": 16}},
            "rules": {{"depth_format": "{format}"{bias}}},
            "primitives": [{{"triangle": [{}]}}]}}"#,
            v.join(", ")
        );
        let scene = parse_case(&json, "r.json", &Limits::default()).unwrap();
        let frame = Production
            .rasterize(&scene, &Plan::for_scene(&scene))
            .unwrap();
        let why = failures(&scene, &frame);
        assert!(why.is_empty(), "{json}\n{why:?}");
        judged += u64::from(frame.coverage.iter().any(|&c| c > 0));
    }
    assert!(judged > 150, "only {judged} scenes drew anything");
}

#[test]
fn the_reader_names_the_path() {
    let base = |rules: &str, vertex: &str| {
        format!(
            r#"{{"name": "e", "canvas": {{"width": 4, "height": 4}}, "rules": {{{rules}}},
            "primitives": [{{"triangle": [{vertex}, {vertex}, {vertex}]}}]}}"#
        )
    };
    let z = r#"{"position": [1, 1], "z": 0.5}"#;
    for (rules, vertex, path, words) in [
        (
            r#""depth_format": "unorm61""#,
            z,
            "$.rules.depth_format",
            "did you mean \"unorm16\"",
        ),
        (
            r#""depth_format": "unorm16", "depth_bias": {"slop": 1}"#,
            z,
            "$.rules.depth_bias.slop",
            "did you mean \"slope\"",
        ),
        (
            r#""depth_bias": {"slope": 1}"#,
            z,
            "$.rules.depth_bias",
            "give rules.depth_format",
        ),
        (
            r#""depth_format": "float32""#,
            "[1, 1]",
            "$.rules.depth_format",
            "has none",
        ),
        (
            r#""depth_format": "float32", "depth_bias": {"constant": 1}"#,
            r#"{"clip": [0, 0, 0, -1]}"#,
            "$.primitives[0].triangle[0]",
            "every w > 0",
        ),
        (
            r#""depth_format": "unorm16", "depth_bias": {"clamp": "1e13"}"#,
            z,
            "$.rules.depth_bias.clamp",
            "outside",
        ),
    ] {
        let json = base(rules, vertex);
        let err = parse_case(&json, "e.json", &Limits::default())
            .expect_err(&json)
            .to_string();
        assert!(err.contains(path) && err.contains(words), "{err}\n{json}");
    }
}

/// One capability decides the refusal: a rasterizer without a depth
/// attachment answers `unsupported` for a format or an offset, and only
/// for those.
#[test]
fn rasterizers_without_an_attachment_refuse() {
    let without = Capabilities {
        depth_attachment: false,
        ..Capabilities::everything()
    };
    let exact = flat("exact", "1/2", "");
    assert_eq!(without.refuses(&exact), None);
    for id in [
        "depth/unorm16_plane",
        "depth/spec_offset_constant",
        "depth/spec_depth_float32",
    ] {
        let why = without.refuses(&case(id)).unwrap_or_default();
        assert!(why.contains("depth attachment"), "{id}: {why}");
    }
    assert_eq!(
        Production
            .capabilities()
            .refuses(&case("depth/unorm16_plane")),
        None
    );
}

/// Every case SPEC.md §18 names as a worked example exists and reads.
#[test]
fn the_worked_examples_spec_section_18_names_exist() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let spec = std::fs::read_to_string(root.join("SPEC.md")).unwrap();
    let section = &spec[spec.find("## 18.").expect("§18")..];
    let mut named = 0;
    for piece in section.split('`') {
        if let Some(id) = piece
            .strip_prefix("cases/")
            .and_then(|p| p.strip_suffix(".json"))
        {
            case(id);
            named += 1;
        }
    }
    assert!(named >= 12, "§18 names {named} cases");
}

/// report.json names a case's depth rules (exact fractions) and a depth
/// channel's misses; euc, which has no depth attachment, is unsupported.
#[test]
fn report_json_shows_the_depth_rules() {
    use common::cli::{rastercheck, read_json, text, workspace};
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let file = "cases/depth/spec_offset_constant.json";
    let dir = workspace(
        "depth-report",
        &[(file, &std::fs::read_to_string(root.join(file)).unwrap())],
    );
    rastercheck(&dir, &["bless", "cases"]);
    let out = rastercheck(
        &dir,
        &[
            "run",
            "cases",
            "-r",
            "production",
            "-r",
            "euc",
            "-r",
            "float-f32",
            "--report",
            "rep",
        ],
    );
    let report = read_json(&dir.join("rep/report.json"));
    let case = &report["cases"][0];
    let depth = &case["rules"]["depth"];
    assert_eq!(depth["depth_format"], "unorm16", "{}", text(&out));
    assert_eq!(depth["depth_bias"]["constant"], "4");
    assert_eq!(depth["depth_bias"]["clamp"], "0");
    let result = |name: &str| {
        case["results"]
            .as_array()
            .unwrap()
            .iter()
            .find(|r| r["rasterizer"] == name)
            .unwrap()
            .clone()
    };
    assert_eq!(result("production")["verdict"], "pass");
    assert_eq!(result("euc")["verdict"], "unsupported");
    // float-f32 interpolates without the offset or the grid: every sample
    // misses, and the channel says how.
    let channel = &result("float-f32")["metrics"]["channels"][0];
    assert_eq!(channel["depth_set"]["format"], "unorm16", "{channel}");
    assert_eq!(channel["depth_set"]["outside"], channel["samples"]);
}
