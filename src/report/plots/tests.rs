//! Tests of the plots: well-formed SVG, series per pattern, points at
//! their pixels, notes instead of empty charts, escaping, the summary.

use super::all::{notes, plots};
use super::plot::Plot;
use super::svg;
use crate::metrics::antialias::AntialiasMetrics;
use crate::metrics::time::TimeMetrics;
use crate::report::json::{
    AntialiasRules, ChannelEntry, CoverageEntry, LimitsInfo, MotionBlurRules, RasterizerInfo,
    RulesInfo,
};
use crate::report::json::{CaseEntry, MetricsEntry, Report, ResultEntry};
use crate::scene::samples::Pattern;

/// Checks that `svg` is well-formed XML of the kind the charts write:
/// balanced tags, quoted attributes without repeats, entities only
/// where `&` appears, no scripts or external references.
pub fn check_well_formed(svg: &str) {
    assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\""));
    assert!(svg.contains("viewBox=\"0 0 "));
    assert!(!svg.contains("<script") && !svg.contains("href"));
    let mut stack: Vec<&str> = Vec::new();
    let mut rest = svg;
    while let Some(open) = rest.find('<') {
        let text = &rest[..open];
        check_text(text);
        let close = rest[open..].find('>').expect("a tag ends") + open;
        let tag = &rest[open + 1..close];
        rest = &rest[close + 1..];
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop(), Some(name), "closing tag {name}");
            continue;
        }
        let self_closing = tag.ends_with('/');
        let tag = tag.trim_end_matches('/');
        let (name, mut attrs) = tag.split_once(' ').unwrap_or((tag, ""));
        let mut seen = Vec::new();
        loop {
            attrs = attrs.trim_start();
            if attrs.is_empty() {
                break;
            }
            let (key, after) = attrs.split_once("=\"").expect("key=\"value\"");
            assert!(!key.contains(['"', ' ', '<']), "attribute {key:?} in {tag}");
            assert!(!seen.contains(&key), "repeated {key} in {tag}");
            seen.push(key);
            let end = after.find('"').expect("a quoted value");
            check_text(&after[..end]);
            attrs = &after[end + 1..];
        }
        if !self_closing {
            stack.push(name);
        }
    }
    check_text(rest.trim());
    assert!(stack.is_empty(), "unclosed {stack:?}");
}

fn check_text(text: &str) {
    assert!(!text.contains('<') && !text.contains('>'), "{text}");
    for (i, _) in text.match_indices('&') {
        let entity = &text[i..text[i..].find(';').map_or(text.len(), |e| i + e + 1)];
        assert!(
            ["&amp;", "&lt;", "&gt;", "&quot;", "&#39;"].contains(&entity),
            "bad entity {entity:?}"
        );
    }
}

fn report(rasterizers: &[&str]) -> Report {
    Report::new(
        vec!["rastercheck".into()],
        rasterizers
            .iter()
            .map(|n| RasterizerInfo {
                name: (*n).into(),
                foil: false,
                declared: None,
                api_record: None,
            })
            .collect(),
        LimitsInfo {
            max_canvas_pixels: 1,
            max_primitives: 1,
            max_samples: 1,
            max_case_bytes: 1,
            max_case_memory: 1,
            case_timeout_s: None,
        },
    )
}

fn metrics() -> MetricsEntry {
    MetricsEntry {
        coverage: CoverageEntry {
            samples: 1,
            reference_covered: 0,
            candidate_covered: 0,
            missing: 0,
            extra: 0,
            wrong_owner: 0,
            mismatched: 0,
        },
        watertight: None,
        lines: None,
        channels: Vec::new(),
        antialias: None,
        time: None,
    }
}

fn aa(samples: u32, rms_edge: f64) -> AntialiasMetrics {
    AntialiasMetrics {
        samples,
        pixels: 16,
        edge_pixels: 4,
        max_error: rms_edge * 2.0,
        worst_pixel: [0, 0],
        rms_edge,
        rms_all: rms_edge / 2.0,
        bias_edge: 0.0,
        full_pixels: 0,
        empty_pixels: 0,
        piglit_violations: 0,
        piglit_within_quantization: 0,
        first_violation: None,
        resolve_mismatches: 0,
        invalid_values: 0,
        reference_pixels: 0,
        candidate_pixels: 0,
        primitives: None,
        nothing_drawn: None,
        pixel_areas: None,
        allowed_error: None,
        allowed_rms: None,
    }
}

fn time(rms_moving: f64) -> TimeMetrics {
    TimeMetrics {
        pixels: 16,
        moving_pixels: 4,
        max_error: rms_moving * 2.0,
        worst_pixel: [0, 0],
        worst_candidate: 0.0,
        worst_exact: 0.0,
        rms_moving,
        rms_all: rms_moving,
        bias_moving: 0.0,
        invalid_values: 0,
        first_invalid: None,
        reference_pixels: 0,
        candidate_pixels: 0,
        sample_tests: None,
        allowed_error: None,
        allowed_rms: None,
    }
}

fn rules(antialias: Option<(&'static str, u32)>, motion: Option<(&'static str, u32)>) -> RulesInfo {
    RulesInfo {
        canvas: [4, 4],
        subpixel_bits: None,
        fill_rule: "top-left",
        cull: "none",
        provoking_vertex: "first",
        clip: None,
        depth: None,
        primitives: 1,
        antialias: antialias.map(|(pattern, samples)| AntialiasRules {
            samples,
            pattern,
            seed: 0,
            adaptive: false,
            position_bits: 8,
        }),
        motion_blur: motion.map(|(pattern, samples)| MotionBlurRules {
            shutter: [0.0, 1.0],
            samples,
            pattern,
            seed: 0,
            moving: 1,
        }),
    }
}

/// A case that ran, with one result per (rasterizer, metrics).
fn case(id: &str, rules: RulesInfo, results: Vec<(&str, MetricsEntry)>) -> CaseEntry {
    CaseEntry {
        id: id.into(),
        path: format!("cases/{id}.json"),
        family: crate::report::json::family(id),
        status: "ran",
        error: None,
        name: None,
        description: None,
        rules: Some(rules),
        golden: None,
        hash: None,
        golden_detail: None,
        reference_ms: 0.0,
        page: None,
        results: results
            .into_iter()
            .map(|(r, m)| ResultEntry {
                metrics: Some(m),
                ..ResultEntry::bare(r, "pass")
            })
            .collect(),
    }
}

fn aa_case(id: &str, pattern: &'static str, samples: u32, errors: &[(&str, f64)]) -> CaseEntry {
    let results = errors
        .iter()
        .map(|&(r, e)| {
            let mut m = metrics();
            m.antialias = Some(aa(samples, e));
            (r, m)
        })
        .collect();
    case(id, rules(Some((pattern, samples)), None), results)
}

fn find<'a>(plots: &'a [Plot], file: &str) -> &'a Plot {
    plots
        .iter()
        .find(|p| p.file == file)
        .unwrap_or_else(|| panic!("no {file} among {:?}", files(plots)))
}

fn files(plots: &[Plot]) -> Vec<&str> {
    plots.iter().map(|p| p.file.as_str()).collect()
}

/// Three patterns at three counts, two rasterizers, two families.
fn sweep() -> Report {
    let mut r = report(&["prod", "coarse:x"]);
    for (pattern, base) in [("grid", 0.3), ("n-rooks", 0.4), ("random", 0.5)] {
        for (k, samples) in [1u32, 4, 16].into_iter().enumerate() {
            let e = base / 2f64.powi(k as i32);
            r.cases.push(aa_case(
                &format!("antialias/{pattern}_{samples}"),
                pattern,
                samples,
                &[("prod", e), ("coarse:x", 0.2)],
            ));
        }
    }
    let mut m = metrics();
    m.channels.push(ChannelEntry {
        channel: "depth".into(),
        samples: 4,
        max_abs: 1e-7,
        max_ulp: 3.0,
        rms: 1e-8,
        allowed_abs: 1e-5,
        allowed_ulp: None,
        depth_set: None,
    });
    let mut exact = m.clone();
    exact.channels[0].max_ulp = 0.0;
    r.cases.push(case(
        "triangles/one",
        rules(None, None),
        vec![("prod", m), ("coarse:x", exact)],
    ));
    for (pattern, samples, e) in [
        ("stratified", 4, 0.1),
        ("stratified", 16, 0.05),
        ("random", 16, 0.08),
    ] {
        let mut m = metrics();
        m.time = Some(time(e));
        r.cases.push(case(
            &format!("motion/{pattern}_{samples}"),
            rules(None, Some((pattern, samples))),
            vec![("prod", m.clone()), ("coarse:x", m)],
        ));
    }
    r
}

#[test]
fn every_chart_is_well_formed_svg() {
    let plots = plots(&sweep());
    assert_eq!(
        files(&plots),
        [
            "aa-error-by-family.svg",
            "interpolation-ulp-by-family.svg",
            "aa-error-vs-samples-prod.svg",
            "aa-error-vs-samples-coarse-x.svg",
            "time-error-vs-samples-prod.svg",
            "time-error-vs-samples-coarse-x.svg",
        ]
    );
    for p in &plots {
        check_well_formed(&p.svg);
        assert!(p
            .svg
            .contains(&format!("<title>{}</title>", escape_title(&p.title))));
    }
}

#[test]
fn names_are_escaped() {
    let mut r = report(&["ext:<a&b>\"'"]);
    for samples in [1, 4] {
        r.cases.push(aa_case(
            &format!("fam<&>/g{samples}"),
            "grid",
            samples,
            &[("ext:<a&b>\"'", 0.1 / f64::from(samples))],
        ));
    }
    let plots = plots(&r);
    assert_eq!(
        files(&plots),
        [
            "aa-error-by-family.svg",
            "aa-error-vs-samples-ext--a-b---.svg"
        ]
    );
    for p in &plots {
        check_well_formed(&p.svg);
    }
    assert!(plots[0].svg.contains(">fam&lt;&amp;&gt;</text>"));
}

fn escape_title(t: &str) -> String {
    crate::report::escape::escape(t)
}

#[test]
fn the_checker_rejects_broken_svg() {
    let good = plots(&sweep()).remove(0).svg;
    for bad in [
        good.replacen("</text>", "", 1),
        good.replacen("stroke=\"#666\"", "stroke=\"#666\" stroke=\"#000\"", 1),
        good.replacen("family", "a & b", 1),
        good.replacen("<title>", "<title><", 1),
    ] {
        assert!(std::panic::catch_unwind(|| check_well_formed(&bad)).is_err());
    }
}

/// The colours of the series of a line chart, from their median
/// markers (white outlines), in order of appearance.
fn median_lines(svg: &str) -> Vec<&str> {
    let mut colours: Vec<&str> = Vec::new();
    for l in svg.lines().filter(|l| l.contains("stroke=\"white\"")) {
        let s = l.split("fill=\"").nth(1).unwrap();
        let c = &s[..s.find('"').unwrap()];
        if !colours.contains(&c) {
            colours.push(c);
        }
    }
    colours
}

#[test]
fn one_line_per_sample_pattern() {
    let plots = plots(&sweep());
    let p = find(&plots, "aa-error-vs-samples-prod.svg");
    // grid, random and n-rooks, in the documented order's colours.
    let colour = |name| svg::style(Pattern::NAMES.iter().position(|n| *n == name).unwrap()).0;
    assert_eq!(
        median_lines(&p.svg),
        [colour("grid"), colour("random"), colour("n-rooks")]
    );
    for name in ["grid", "random", "n-rooks"] {
        assert!(p.svg.contains(&format!(">{name}</text>")), "{name}");
    }
    assert!(!p.svg.contains(">standard</text>"));
    assert!(p.svg.contains("default RMS bound"));
    let t = find(&plots, "time-error-vs-samples-prod.svg");
    assert_eq!(median_lines(&t.svg).len(), 2, "random and stratified");
    assert!(t.svg.contains(">stratified</text>") && t.svg.contains(">random</text>"));
}

#[test]
fn points_land_where_they_belong() {
    // One series: 0.1 at 1 sample, 10^-1.5 at 4, 0.01 at 16. The y axis
    // runs from 10^-2 at its foot (y = 316) to 10^-1 at its head
    // (y = 58); the x axis from 1 (x = 78) to 16 (x = 608).
    let mut r = report(&["a"]);
    for (samples, e) in [(1, 0.1), (4, 10f64.powf(-1.5)), (16, 0.01)] {
        r.cases.push(aa_case(
            &format!("antialias/g{samples}"),
            "grid",
            samples,
            &[("a", e)],
        ));
    }
    let plots = plots(&r);
    let svg = &find(&plots, "aa-error-vs-samples-a.svg").svg;
    for (x, y) in [(78, 58), (343, 187), (608, 316)] {
        assert!(
            svg.contains(&format!(
                "<circle cx=\"{x}\" cy=\"{y}\" r=\"4\" fill=\"#0072B2\" stroke=\"white\"/>"
            )),
            "no median marker at ({x}, {y})"
        );
    }
    assert!(svg.contains("<polyline points=\"78,58 343,187 608,316\""));
    // The axis labels name the decades at those heights.
    assert!(svg.contains("<text x=\"56\" y=\"62\" text-anchor=\"end\">0.1</text>"));
    assert!(svg.contains("<text x=\"56\" y=\"320\" text-anchor=\"end\">0.01</text>"));
}

#[test]
fn zeros_go_to_their_own_lane_and_break_the_line() {
    let mut r = report(&["a"]);
    for (samples, e) in [(1, 0.1), (4, 0.0), (16, 0.01)] {
        r.cases.push(aa_case(
            &format!("antialias/g{samples}"),
            "grid",
            samples,
            &[("a", e)],
        ));
    }
    let plots = plots(&r);
    let svg = &find(&plots, "aa-error-vs-samples-a.svg").svg;
    // The zero lane at y = 310, below the log axis' foot at 292.
    assert!(svg.contains("<text x=\"56\" y=\"314\" text-anchor=\"end\">0</text>"));
    assert!(svg.contains("<circle cx=\"343\" cy=\"310\" r=\"4\""));
    assert!(
        !svg.contains("<polyline points=\"78,58 343,310"),
        "no line into the lane"
    );
}

#[test]
fn distributions_have_a_column_per_rasterizer_and_family() {
    let plots = plots(&sweep());
    let p = find(&plots, "aa-error-by-family.svg");
    assert!(p.svg.contains(">antialias</text>"));
    assert!(!p.svg.contains(">motion</text>"), "no AA metrics there");
    for r in ["prod", "coarse:x"] {
        assert!(p.svg.contains(&format!(">{r}</text>")));
    }
    // Nine cases per rasterizer: nine dots each (circles for prod, squares
    // for coarse:x), plus the legend's marker.
    let dots = |shape: &str, colour: &str| {
        p.svg
            .lines()
            .filter(|l| l.starts_with(shape) && l.contains(&format!("fill=\"{colour}\"")))
            .count()
    };
    assert_eq!(dots("<circle", "#0072B2"), 9 + 1);
    assert_eq!(dots("<rect", "#D55E00"), 9 + 1 + 1, "dots, legend, box");
    let u = find(&plots, "interpolation-ulp-by-family.svg");
    assert!(u.svg.contains(">triangles</text>"));
    assert!(
        u.caption
            .contains("coarse:x: zero interpolation error on every case"),
        "{}",
        u.caption
    );
}

#[test]
fn no_data_no_chart() {
    assert!(plots(&report(&["a"])).is_empty());
    assert!(notes(&report(&["a"])).is_empty());
    // Zero error everywhere: no chart, a note instead.
    let mut r = report(&["exact"]);
    r.cases
        .push(aa_case("antialias/g4", "grid", 4, &[("exact", 0.0)]));
    assert!(plots(&r).is_empty(), "{:?}", files(&plots(&r)));
    let notes = notes(&r);
    assert!(
        notes.contains(&"exact: zero antialiasing error on every case (1 case)".to_owned()),
        "{notes:?}"
    );
    assert!(
        notes.contains(&"exact: zero antialiasing error at every sample count".to_owned()),
        "{notes:?}"
    );
    // An area method is not drawn against samples.
    let mut r = report(&["area"]);
    r.cases
        .push(aa_case("antialias/g4", "grid", 0, &[("area", 1e-7)]));
    assert_eq!(files(&plots(&r)), ["aa-error-by-family.svg"]);
    assert!(notes_of(&r).contains("area (median 1.00e-7 over 1 case)"));
}

fn notes_of(r: &Report) -> String {
    notes(r).join("\n")
}

#[test]
fn the_summary_links_every_chart() {
    let mut r = sweep();
    r.complete = true;
    let md = crate::report::summary::render(&r);
    let section = &md[md.find("\n## Plots\n").expect("a Plots section")..];
    for p in plots(&r) {
        assert!(section.contains(&format!(
            "![{}](plots/{})\n\n{}\n",
            p.title, p.file, p.caption
        )));
    }
    assert!(!crate::report::summary::render(&report(&["a"])).contains("## Plots"));
}
