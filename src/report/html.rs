//! `index.html`: one self-contained page for people. Inline CSS, every
//! picture embedded as a base64 `data:` URI, no script but a one-line check
//! that the pictures decoded (it writes `data-images="decoded/total"` on the
//! body, which the browser test reads).
//!
//! The page: a header with the command, the totals per rasterizer and the
//! golden files; one section per family (first segment of the case id) with
//! a table of cases × rasterizers; and cards for what deserves a look, at
//! most `MAX_PICTURED` of them, the worst first:
//!
//! 1. failures and errors, unreadable cases, broken references, golden
//!    files that differ;
//! 2. a foil's departures;
//! 3. passing results with a nonzero interpolation error (their heat maps).
//!
//! A result card shows the reference, the candidate and the difference mask
//! (the PNGs `write_pictures` wrote, colour key in `png.rs`), the reasons,
//! every metric, one heat map per interpolated channel (|candidate − exact|
//! per pixel on a viridis scale from 0 to the channel's largest error), its
//! files, and the case file (linked relative to the report folder, and
//! embedded).
//!
//! An antialiased case's card shows its resolved coverage instead (drawn
//! from the frames, for passes too): the exact area and the candidate's
//! resolved value in grey, the signed error (red too much, blue too
//! little), and for a candidate whose samples differ every sample as a dot
//! coloured by how it differs (colour keys in `png.rs`). Passing antialiased results
//! with any coverage error get a card like passes with interpolation error.
//! With several samples per pixel a heat map shows each pixel's largest
//! error over its samples.
//!
//! A scene in which something moves (SPEC.md §15.4) is shown the same way
//! by its time coverage: the exact time coverage and the candidate's in
//! grey, and the signed error, with the time metrics (and the sample test
//! efficiency of a method that counts it). Passing results with any time
//! error get a card too.

use std::fmt::Write as _;
use std::path::{Component, Path, PathBuf};

use image::{Rgb, RgbImage};

use super::exr::interpolation_errors;
use super::json::{CaseEntry, ChannelEntry, MetricsEntry, Report, ResultEntry, TimeEntry};
use super::png::{self, EXTRA, MISSING, SAME_COVERED, WRONG_OWNER};
use super::{escape, MAX_PICTURED};
use crate::frame::Frame;
use crate::harness::runner::CaseOutcome;
use crate::metrics::{coverage::comparable, SampleDiff};
use crate::scene::Scene;

/// Case files longer than this are linked but not embedded.
const MAX_EMBEDDED_CASE: usize = 64 * 1024;

/// Viridis, sampled at nine evenly spaced stops.
const VIRIDIS: [[u8; 3]; 9] = [
    [68, 1, 84],
    [71, 44, 122],
    [59, 81, 139],
    [44, 113, 142],
    [33, 144, 141],
    [39, 173, 129],
    [92, 200, 99],
    [170, 220, 50],
    [253, 231, 37],
];
/// Heat maps: samples not compared (nothing covered, or another primitive
/// drawn last).
const NOT_COMPARED: [u8; 3] = [30, 30, 30];
/// Heat maps: errors above the channel's bound.
const ABOVE_BOUND: [u8; 3] = [255, 0, 0];
const COVERAGE_TWICE: [u8; 3] = [255, 150, 0];

/// Standard base64 (RFC 4648, with padding).
pub fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = u32::from(b[0]) << 16 | u32::from(b[1]) << 8 | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ALPHABET[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// A relative URL from folder `from` to file `to` (both made absolute
/// against the current directory), with `/` separators and unsafe
/// characters percent-encoded. `None` when no relative path exists (for
/// instance another drive).
pub fn relative_url(from: &Path, to: &Path) -> Option<String> {
    let absolute = |p: &Path| -> Option<PathBuf> {
        std::fs::canonicalize(p).ok().or_else(|| {
            let cwd = std::env::current_dir().ok()?;
            Some(cwd.join(p))
        })
    };
    let (from, to) = (absolute(from)?, absolute(to)?);
    let a: Vec<Component> = from.components().collect();
    let b: Vec<Component> = to.components().collect();
    if a.first() != b.first() {
        return None;
    }
    let common = a.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let mut parts: Vec<String> = vec!["..".to_owned(); a.len() - common];
    parts.extend(
        b[common..]
            .iter()
            .map(|c| c.as_os_str().to_string_lossy().into_owned()),
    );
    Some(
        parts
            .iter()
            .map(|p| url_segment(p))
            .collect::<Vec<_>>()
            .join("/"),
    )
}

fn url_segment(segment: &str) -> String {
    let mut out = String::new();
    for b in segment.bytes() {
        if b.is_ascii_alphanumeric() || b"-._~+:@!$&'()*,;=".contains(&b) {
            out.push(b as char);
        } else {
            let _ = write!(out, "%{b:02X}");
        }
    }
    out
}

fn png_bytes(img: &RgbImage) -> Vec<u8> {
    let mut bytes = Vec::new();
    img.write_to(
        &mut std::io::Cursor::new(&mut bytes),
        image::ImageFormat::Png,
    )
    .expect("encoding a PNG in memory");
    bytes
}

fn data_uri(png: &[u8]) -> String {
    format!("data:image/png;base64,{}", base64(png))
}

fn viridis(t: f64) -> [u8; 3] {
    let t = if t.is_nan() { 1.0 } else { t.clamp(0.0, 1.0) };
    let x = t * (VIRIDIS.len() - 1) as f64;
    let k = (x.floor() as usize).min(VIRIDIS.len() - 2);
    let f = x - k as f64;
    let (a, b) = (VIRIDIS[k], VIRIDIS[k + 1]);
    std::array::from_fn(|c| {
        (f64::from(a[c]) + (f64::from(b[c]) - f64::from(a[c])) * f).round() as u8
    })
}

fn css_rgb(c: [u8; 3]) -> String {
    format!("rgb({},{},{})", c[0], c[1], c[2])
}

/// Display magnification for a native-size picture: about `target` pixels
/// across, 1 to 16.
fn display_scale(frame: &Frame, target: u32) -> u32 {
    (target / frame.width.max(frame.height).max(1)).clamp(1, 16)
}

/// A heat map of |error| at one pixel per pixel (the largest over its
/// samples), 0 → `scale_max` on viridis; red above `bound`, dark grey where
/// no sample is compared.
fn heat_map(frame: &Frame, errors: &[Option<f64>], scale_max: f64, bound: f64) -> RgbImage {
    let mut img = RgbImage::new(frame.width, frame.height);
    let n = frame.samples.max(1) as usize;
    for (i, run) in errors.chunks(n).enumerate() {
        let error = run.iter().flatten().fold(None, |worst: Option<f64>, e| {
            let e = if e.is_nan() { f64::INFINITY } else { e.abs() };
            Some(worst.map_or(e, |w| w.max(e)))
        });
        let colour = match error {
            None => NOT_COMPARED,
            Some(e) if e > bound || e.is_nan() => ABOVE_BOUND,
            Some(e) if scale_max > 0.0 => viridis(e / scale_max),
            Some(_) => viridis(0.0),
        };
        let (x, y) = (i as u32 % frame.width, i as u32 / frame.width);
        img.put_pixel(x, y, Rgb(colour));
    }
    img
}

/// Why a card is shown, in order of importance.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Kind {
    /// A failure, an error, a case that did not run, a differing golden file.
    Problem,
    /// A foil departing from the reference.
    Departure,
    /// A pass with some interpolation, coverage or time-coverage error: the
    /// heat maps and the antialiasing or time pictures are worth seeing.
    Interpolation,
}

/// One card: a case (`result` None: the case itself has a problem) or a
/// case × rasterizer.
#[derive(Clone, Copy)]
struct Card {
    kind: Kind,
    case: usize,
    result: Option<usize>,
}

fn anchor(case: &CaseEntry, result: Option<&ResultEntry>) -> String {
    let mut id = format!("card-{}", case.id);
    if let Some(r) = result {
        id.push_str("--");
        id.push_str(&r.rasterizer);
    }
    id.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect()
}

fn interpolation_error(m: &MetricsEntry) -> bool {
    m.channels
        .iter()
        .any(|ch| ch.max_abs != 0.0 || ch.max_abs.is_nan())
        || m.antialias
            .as_ref()
            .is_some_and(|a| a.max_error != 0.0 || a.max_error.is_nan())
        || m.time
            .as_ref()
            .is_some_and(|t| t.max_error != 0.0 || t.max_error.is_nan())
}

/// Every card the run deserves, the most important first (case order within
/// a kind).
fn cards(report: &Report) -> Vec<Card> {
    let mut out = Vec::new();
    for (c, case) in report.cases.iter().enumerate() {
        if case.error.is_some() || case.golden == Some("differ") {
            out.push(Card {
                kind: Kind::Problem,
                case: c,
                result: None,
            });
        }
        for (r, result) in case.results.iter().enumerate() {
            let kind = match result.verdict {
                "fail" | "error" => Kind::Problem,
                "foil" => Kind::Departure,
                "pass" if result.metrics.as_ref().is_some_and(interpolation_error) => {
                    Kind::Interpolation
                }
                _ => continue,
            };
            out.push(Card {
                kind,
                case: c,
                result: Some(r),
            });
        }
    }
    out.sort_by_key(|card| card.kind);
    out
}

const STYLE: &str = r#"
:root { --fg:#1d2330; --muted:#667085; --line:#d9dee7; --bg:#f6f7f9; --card:#fff;
  --pass:#1a7f37; --fail:#c62828; --foil:#8250df; --unsupported:#9a6700; --error:#b42318; }
* { box-sizing: border-box; }
body { margin:0; font:14px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,sans-serif; color:var(--fg); background:var(--bg); }
main { max-width:1760px; margin:0 auto; padding:20px 28px 60px; }
h1 { font-size:24px; margin:0 0 4px; } h2 { font-size:20px; margin:32px 0 10px; border-bottom:2px solid var(--line); padding-bottom:4px; }
h3 { font-size:16px; margin:0; } h4 { font-size:13px; margin:14px 0 6px; text-transform:uppercase; letter-spacing:.04em; color:var(--muted); }
code, pre { font:12.5px/1.4 ui-monospace,SFMono-Regular,Menlo,Consolas,monospace; }
pre { background:#f1f3f6; border:1px solid var(--line); border-radius:6px; padding:8px 10px; overflow:auto; max-height:420px; white-space:pre-wrap; word-break:break-word; }
a { color:#0b62c4; text-decoration:none; } a:hover { text-decoration:underline; }
.muted { color:var(--muted); }
.banner { background:#fff4e5; border:1px solid #f0b35a; border-radius:6px; padding:8px 12px; margin:10px 0; }
.summary { display:flex; flex-wrap:wrap; gap:16px; align-items:flex-start; margin-top:14px; }
.panel { background:var(--card); border:1px solid var(--line); border-radius:8px; padding:12px 14px; }
table { border-collapse:collapse; background:var(--card); }
th, td { border:1px solid var(--line); padding:4px 8px; text-align:left; vertical-align:top; }
th { background:#eef1f5; font-weight:600; }
td.n, th.n { text-align:right; font-variant-numeric:tabular-nums; }
table.cases { width:100%; } table.cases td { font-size:13px; }
table.cases td.id { font-family:ui-monospace,Menlo,Consolas,monospace; font-size:12.5px; white-space:nowrap; }
.badge { display:inline-block; min-width:44px; text-align:center; font-size:11px; font-weight:700; letter-spacing:.03em; color:#fff; border-radius:4px; padding:1px 6px; margin-right:6px; }
.pass { background:var(--pass); } .fail { background:var(--fail); } .foil { background:var(--foil); }
.unsupported { background:var(--unsupported); } .error, .unreadable, .reference-failed, .limit-exceeded, .differ { background:var(--error); }
.not-run, .missing { background:#8c959f; } .match { background:var(--pass); }
.metric { color:var(--muted); font-size:12px; }
.card { background:var(--card); border:1px solid var(--line); border-left:5px solid var(--line); border-radius:8px; padding:14px 16px; margin:16px 0; }
.card.k-fail, .card.k-error, .card.k-problem { border-left-color:var(--fail); }
.card.k-foil { border-left-color:var(--foil); } .card.k-pass { border-left-color:var(--pass); }
.card header { display:flex; flex-wrap:wrap; align-items:baseline; gap:8px 12px; }
.card header .id { font-family:ui-monospace,Menlo,Consolas,monospace; font-size:15px; font-weight:600; }
.reasons { margin:8px 0; padding-left:20px; color:#7a1c1c; }
.pictures { display:flex; gap:14px; padding-bottom:6px; align-items:flex-start; }
.pictures figure { flex:0 1 auto; min-width:0; }
.pictures.stack { flex-direction:column; overflow-x:auto; }
.pictures.stack figure { flex:none; } .pictures.stack img { max-width:none; }
.pictures.tall { max-height:640px; overflow-y:auto; } .pictures.tall figure { flex:none; }
.pictures.heat { flex-wrap:wrap; }
figure { margin:0; } figcaption { font-size:12px; color:var(--muted); margin-top:3px; }
figure img { display:block; image-rendering:pixelated; border:1px solid #000; max-width:100%; height:auto; }
.key { display:flex; flex-wrap:wrap; gap:4px 14px; font-size:12px; margin:8px 0 2px; color:var(--fg); }
.key span { white-space:nowrap; } .key i { display:inline-block; width:12px; height:12px; border:1px solid #555; vertical-align:-2px; margin-right:4px; }
.metrics { display:flex; flex-wrap:wrap; gap:14px; align-items:flex-start; }
.ramp { display:inline-block; width:140px; height:12px; border:1px solid #555; vertical-align:-2px; margin:0 4px; }
details { margin-top:8px; } summary { cursor:pointer; color:#0b62c4; }
.files { font-size:12px; }
"#;

/// After load, counts the pictures that decoded.
const SCRIPT: &str = r#"window.addEventListener('load', function () {
  var imgs = document.images, ok = 0;
  for (var i = 0; i < imgs.length; i++) { if (imgs[i].complete && imgs[i].naturalWidth > 0) ok++; }
  document.body.dataset.images = ok + '/' + imgs.length;
});"#;

fn badge(class: &str, text: &str) -> String {
    format!(
        "<span class=\"badge {}\">{}</span>",
        escape(class),
        escape(text)
    )
}

fn shell_quote(arg: &str) -> String {
    if !arg.is_empty()
        && arg
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_./:=+,@%".contains(c))
    {
        arg.to_owned()
    } else {
        format!("'{}'", arg.replace('\'', "'\\''"))
    }
}

fn worst_channel(m: &MetricsEntry) -> Option<&ChannelEntry> {
    m.channels
        .iter()
        .max_by(|a, b| (a.max_abs / a.allowed_abs).total_cmp(&(b.max_abs / b.allowed_abs)))
}

/// The table cell of one result: verdict and key metrics.
fn cell(result: &ResultEntry, link: Option<&str>) -> String {
    let mut html = badge(result.verdict, &result.verdict.to_uppercase());
    if let Some(m) = &result.metrics {
        let c = &m.coverage;
        let mut parts = vec![if m.time.is_some() {
            "time coverage".to_owned()
        } else if c.samples == 0 {
            "no samples".to_owned()
        } else {
            format!("{} mismatched", c.mismatched)
        }];
        if let Some(w) = &m.watertight {
            parts.push(format!("{} holes, {} overdraw", w.holes, w.overdraw));
        }
        if let Some(l) = &m.lines {
            if l.crowded_steps > 0 {
                parts.push(format!("{} crowded steps", l.crowded_steps));
            }
        }
        if let Some(a) = &m.antialias {
            parts.push(format!(
                "aa max {:.2e} · edge rms {:.2e}",
                a.max_error, a.rms_edge
            ));
            if a.piglit_violations > 0 {
                parts.push(format!("{} piglit violations", a.piglit_violations));
            }
        }
        if let Some(t) = &m.time {
            parts.push(format!(
                "time max {:.2e} · rms {:.2e}",
                t.max_error, t.rms_moving
            ));
            if t.invalid_values > 0 {
                parts.push(format!("{} invalid values", t.invalid_values));
            }
        }
        if let Some(ch) = worst_channel(m) {
            let ratio = ch.max_abs / ch.allowed_abs;
            let share = if ratio < 0.01 {
                "< 1% of bound".to_owned()
            } else {
                format!("{:.0}% of bound", ratio * 100.0)
            };
            parts.push(format!("interp {:.2e} ({share})", ch.max_abs));
        }
        let _ = write!(
            html,
            "<span class=\"metric\">{}</span>",
            escape(&parts.join(" · "))
        );
    } else if let Some(why) = result.reasons.first() {
        let _ = write!(
            html,
            "<span class=\"metric\" title=\"{}\">{}</span>",
            escape(why),
            escape(&shorten(why, 80))
        );
    }
    if let Some(link) = link {
        let _ = write!(html, " <a href=\"#{link}\">details</a>");
    }
    html
}

fn shorten(text: &str, n: usize) -> String {
    let line = text.replace('\n', " ");
    if line.chars().count() > n {
        format!("{}…", line.chars().take(n).collect::<String>())
    } else {
        line
    }
}

fn colour_key(entries: &[([u8; 3], &str)]) -> String {
    let mut html = String::from("<div class=\"key\">");
    for (colour, label) in entries {
        let _ = write!(
            html,
            "<span><i style=\"background:{}\"></i>{}</span>",
            css_rgb(*colour),
            escape(label)
        );
    }
    html.push_str("</div>");
    html
}

fn metrics_tables(m: &MetricsEntry) -> String {
    let c = &m.coverage;
    let mut html = String::from("<div class=\"metrics\">");
    let mut rows = vec![
        ("samples", c.samples.to_string()),
        ("reference covers", c.reference_covered.to_string()),
        ("candidate covers", c.candidate_covered.to_string()),
        ("missing", c.missing.to_string()),
        ("extra", c.extra.to_string()),
        ("wrong owner", c.wrong_owner.to_string()),
        ("mismatched", c.mismatched.to_string()),
    ];
    if let Some(w) = &m.watertight {
        rows.push(("mesh interior", w.interior.to_string()));
        rows.push(("holes", w.holes.to_string()));
        rows.push(("overdraw", w.overdraw.to_string()));
    }
    if let Some(l) = &m.lines {
        rows.push(("midpoint lines", l.lines.to_string()));
        rows.push(("crowded steps", l.crowded_steps.to_string()));
    }
    // A moving scene has no samples: its table is the time table alone.
    if m.time.is_none() {
        html.push_str("<table><tr><th colspan=\"2\">coverage</th></tr>");
        for (name, value) in rows {
            let _ = write!(
                html,
                "<tr><td>{name}</td><td class=\"n\">{}</td></tr>",
                escape(&value)
            );
        }
        html.push_str("</table>");
    }
    if let Some(a) = &m.antialias {
        let bound = |b: Option<f64>| b.map_or("—".to_owned(), |b| format!("{b:.3e}"));
        let rows = [
            (
                "samples per pixel",
                if a.samples == 0 {
                    "none (area)".to_owned()
                } else {
                    a.samples.to_string()
                },
            ),
            ("edge pixels", format!("{} of {}", a.edge_pixels, a.pixels)),
            (
                "max |error|",
                format!(
                    "{:.3e} at ({}, {})",
                    a.max_error, a.worst_pixel[0], a.worst_pixel[1]
                ),
            ),
            ("bound", bound(a.allowed_error)),
            ("edge RMS", format!("{:.3e}", a.rms_edge)),
            ("RMS bound", bound(a.allowed_rms)),
            ("RMS, all pixels", format!("{:.3e}", a.rms_all)),
            ("edge bias", format!("{:+.3e}", a.bias_edge)),
            (
                "full / empty pixels",
                format!("{} / {}", a.full_pixels, a.empty_pixels),
            ),
            ("piglit violations", a.piglit_violations.to_string()),
            (
                "not their own box resolve",
                a.resolve_mismatches.to_string(),
            ),
            ("not a finite number ≥ 0", a.invalid_values.to_string()),
        ];
        html.push_str("<table><tr><th colspan=\"2\">resolved coverage − exact area</th></tr>");
        for (name, value) in rows {
            let _ = write!(
                html,
                "<tr><td>{name}</td><td class=\"n\">{}</td></tr>",
                escape(&value)
            );
        }
        html.push_str("</table>");
    }
    if let Some(t) = &m.time {
        html.push_str(&time_table(t));
    }
    if !m.channels.is_empty() {
        html.push_str("<table><tr><th>channel</th><th class=\"n\">samples</th><th class=\"n\">max |error|</th><th class=\"n\">max ulp</th><th class=\"n\">rms</th><th class=\"n\">bound</th><th class=\"n\">ulp bound</th></tr>");
        for ch in &m.channels {
            let _ = write!(
                html,
                "<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{:.3e}</td><td class=\"n\">{:.1}</td><td class=\"n\">{:.3e}</td><td class=\"n\">{:.3e}</td><td class=\"n\">{}</td></tr>",
                escape(&ch.channel),
                ch.samples,
                ch.max_abs,
                ch.max_ulp,
                ch.rms,
                ch.allowed_abs,
                ch.allowed_ulp.map_or("—".to_owned(), |u| format!("{u}"))
            );
        }
        html.push_str("</table>");
    }
    html.push_str("</div>");
    html
}

/// The time metrics of a moving scene (SPEC.md §15.4).
fn time_table(t: &TimeEntry) -> String {
    let bound = |b: Option<f64>| b.map_or("—".to_owned(), |b| format!("{b:.3e}"));
    let mut rows = vec![
        (
            "moving pixels",
            format!("{} of {}", t.moving_pixels, t.pixels),
        ),
        (
            "max |error|",
            format!(
                "{:.3e} at ({}, {})",
                t.max_error, t.worst_pixel[0], t.worst_pixel[1]
            ),
        ),
        (
            "there: candidate / exact",
            format!("{:.6} / {:.6}", t.worst_candidate, t.worst_exact),
        ),
        ("bound", bound(t.allowed_error)),
        ("moving RMS", format!("{:.3e}", t.rms_moving)),
        ("RMS bound", bound(t.allowed_rms)),
        ("RMS, all pixels", format!("{:.3e}", t.rms_all)),
        ("moving bias", format!("{:+.3e}", t.bias_moving)),
        (
            "nonzero pixels: reference / candidate",
            format!("{} / {}", t.reference_pixels, t.candidate_pixels),
        ),
        ("not a finite number ≥ 0", t.invalid_values.to_string()),
    ];
    if let Some(s) = &t.sample_tests {
        rows.push((
            "sample tests: covered / all",
            format!("{} / {} ({:.1}%)", s.covered, s.tests, s.efficiency * 100.0),
        ));
    }
    let mut html = String::from("<table><tr><th colspan=\"2\">time coverage − exact</th></tr>");
    for (name, value) in rows {
        let _ = write!(
            html,
            "<tr><td>{name}</td><td class=\"n\">{}</td></tr>",
            escape(&value)
        );
    }
    html.push_str("</table>");
    html
}

fn figure(src: &str, role: &str, caption: &str, width: Option<u32>) -> String {
    let style = width.map_or(String::new(), |w| format!(" style=\"width:{w}px\""));
    format!(
        "<figure><img data-role=\"{}\" src=\"{src}\" alt=\"{}\"{style}><figcaption>{}</figcaption></figure>",
        escape(role),
        escape(caption),
        escape(caption)
    )
}

/// The case file: a relative link and, when small enough, its text.
fn case_file(dir: &Path, case: &CaseEntry) -> String {
    let mut html = String::from("<div class=\"files\">case file: ");
    match relative_url(dir, Path::new(&case.path)) {
        Some(url) => {
            let _ = write!(
                html,
                "<a class=\"case-json\" href=\"{}\">{}</a>",
                escape(&url),
                escape(&case.path)
            );
        }
        None => html.push_str(&escape(&case.path)),
    }
    html.push_str("</div>");
    if let Ok(text) = std::fs::read_to_string(&case.path) {
        if text.len() <= MAX_EMBEDDED_CASE {
            let _ = write!(
                html,
                "<details><summary>case JSON</summary><pre>{}</pre></details>",
                escape(&text)
            );
        }
    }
    html
}

fn card_header(case: &CaseEntry, result: Option<&ResultEntry>, kind_class: &str) -> String {
    let mut html = format!("<header><span class=\"id\">{}</span>", escape(&case.id));
    if let Some(r) = result {
        let _ = write!(
            html,
            "<span>{}</span>{}",
            escape(&r.rasterizer),
            badge(r.verdict, &r.verdict.to_uppercase())
        );
    } else {
        html.push_str(&badge(kind_class, case.status));
    }
    if let Some(rules) = &case.rules {
        let _ = write!(
            html,
            "<span class=\"muted\">{}×{} · {} · fill {} · cull {} · {} primitives</span>",
            rules.canvas[0],
            rules.canvas[1],
            rules
                .subpixel_bits
                .map_or("unsnapped".to_owned(), |b| format!("{b} subpixel bits")),
            rules.fill_rule,
            rules.cull,
            rules.primitives
        );
        if let Some(aa) = &rules.antialias {
            let _ = write!(
                html,
                "<span class=\"muted\">antialiased: {} samples, {} pattern</span>",
                aa.samples,
                escape(aa.pattern)
            );
        }
        if let Some(mb) = rules.motion_blur.as_ref().filter(|mb| mb.moving > 0) {
            let _ = write!(
                html,
                "<span class=\"muted\">motion blur: {} moving primitives, shutter [{}, {}], {} time samples, {} pattern</span>",
                mb.moving,
                mb.shutter[0],
                mb.shutter[1],
                mb.samples,
                escape(mb.pattern)
            );
        }
    }
    html.push_str("</header>");
    if let Some(d) = case.description.as_deref().filter(|d| !d.is_empty()) {
        let _ = write!(html, "<div class=\"muted\">{}</div>", escape(d));
    }
    html
}

/// A card for a case that has a problem of its own.
fn case_card(dir: &Path, case: &CaseEntry) -> String {
    let class = if case.status == "ran" {
        "differ"
    } else {
        case.status
    };
    let mut html = format!(
        "<article class=\"card k-problem\" id=\"{}\" data-case=\"{}\" data-verdict=\"{}\">",
        anchor(case, None),
        escape(&case.id),
        escape(class)
    );
    html.push_str(&card_header(case, None, class));
    if let Some(error) = &case.error {
        let _ = write!(html, "<pre>{}</pre>", escape(error));
    }
    if case.golden == Some("differ") {
        let _ = write!(
            html,
            "<p>The reference no longer reproduces its golden file:</p><pre>{}</pre>",
            escape(case.golden_detail.as_deref().unwrap_or(""))
        );
    }
    html.push_str(&case_file(dir, case));
    html.push_str("</article>");
    html
}

struct ResultView<'a> {
    case: &'a CaseEntry,
    result: &'a ResultEntry,
    scene: Option<&'a Scene>,
    reference: Option<&'a Frame>,
    candidate: Option<&'a Frame>,
}

fn result_card(dir: &Path, v: &ResultView) -> String {
    let (case, result) = (v.case, v.result);
    let mut html = format!(
        "<article class=\"card k-{}\" id=\"{}\" data-case=\"{}\" data-rasterizer=\"{}\" data-verdict=\"{}\">",
        escape(result.verdict),
        anchor(case, Some(result)),
        escape(&case.id),
        escape(&result.rasterizer),
        escape(result.verdict)
    );
    html.push_str(&card_header(case, Some(result), result.verdict));
    if !result.reasons.is_empty() {
        html.push_str("<ul class=\"reasons\">");
        for reason in &result.reasons {
            let _ = write!(html, "<li>{}</li>", escape(reason));
        }
        html.push_str("</ul>");
    }

    // An antialiased case: its resolved coverage, drawn from the frames; a
    // moving scene: its time coverage, likewise.
    let resolved = v.reference.filter(|r| png::pictured_resolved(r));
    if let (Some(scene), Some(r), Some(c)) = (v.scene, resolved, v.candidate) {
        html.push_str(&coverage_pictures(case, scene, r, c, &result.rasterizer));
    }

    // The three pictures, as written under images/.
    let pngs: Vec<&String> = result
        .files
        .iter()
        .filter(|f| f.starts_with("images/") && f.ends_with(".png"))
        .collect();
    if !pngs.is_empty() && resolved.is_none() {
        let find = |pred: &dyn Fn(&str) -> bool| pngs.iter().find(|f| pred(f)).copied();
        let reference = find(&|f| f.ends_with("/reference.png"));
        let diff = find(&|f| f.ends_with(".diff.png"));
        let candidate = find(&|f| !f.ends_with("/reference.png") && !f.ends_with(".diff.png"));
        let shape = picture_shape(case);
        let _ = write!(html, "<h4>coverage</h4><div class=\"pictures{shape}\">");
        let mut show = |file: Option<&String>, role: &str, caption: &str| {
            if let Some(bytes) = file.and_then(|f| std::fs::read(dir.join(f)).ok()) {
                html.push_str(&figure(&data_uri(&bytes), role, caption, None));
            }
        };
        show(reference, "reference", "reference (exact)");
        show(candidate, "candidate", &result.rasterizer);
        show(diff, "diff", "difference mask");
        html.push_str("</div>");
        if let (Some(r), Some(c)) = (v.reference, v.candidate) {
            html.push_str(&first_differences(r, c));
        }
        html.push_str(&colour_key(&[
            ([255, 255, 255], "covered once"),
            (COVERAGE_TWICE, "twice (overdraw)"),
            (EXTRA, "3+ times"),
            ([0, 200, 255], "snapped edges"),
        ]));
        html.push_str(&colour_key(&[
            (MISSING, "missing (holes in a mesh show here)"),
            (EXTRA, "extra"),
            (WRONG_OWNER, "wrong owner"),
            (SAME_COVERED, "covered alike"),
            ([0, 0, 0], "empty in both"),
        ]));
    }

    if let Some(m) = &result.metrics {
        html.push_str("<h4>metrics</h4>");
        html.push_str(&metrics_tables(m));
        if let (Some(r), Some(c)) = (v.reference, v.candidate) {
            html.push_str(&heat_maps(r, c, m));
        }
    }

    let files: Vec<&String> = result.files.iter().collect();
    if !files.is_empty() {
        html.push_str("<div class=\"files\">files: ");
        let links: Vec<String> = files
            .iter()
            .map(|f| {
                let url: Vec<String> = f.split('/').map(url_segment).collect();
                format!("<a href=\"{}\">{}</a>", escape(&url.join("/")), escape(f))
            })
            .collect();
        html.push_str(&links.join(" · "));
        html.push_str("</div>");
    }
    html.push_str(&case_file(dir, case));
    html.push_str("</article>");
    html
}

/// The shape class of a case's pictures: wide canvases stack their
/// pictures, so each keeps its scale; tall ones scroll inside a box of
/// bounded height.
fn picture_shape(case: &CaseEntry) -> &'static str {
    case.rules.as_ref().map_or("", |r| {
        if r.canvas[0] >= 2 * r.canvas[1] {
            " stack"
        } else if r.canvas[1] >= 2 * r.canvas[0] {
            " tall"
        } else {
            ""
        }
    })
}

/// The resolved coverage of an antialiased case: the exact area and the
/// candidate's resolved value in grey, the signed error, and for a
/// candidate with samples, the samples picture. A moving scene's time
/// coverage likewise, with the exact time coverage (it has no samples).
fn coverage_pictures(
    case: &CaseEntry,
    scene: &Scene,
    reference: &Frame,
    candidate: &Frame,
    name: &str,
) -> String {
    let scale = png::auto_scale(reference);
    let (exact, resolved) = (png::resolved_of(reference), png::resolved_of(candidate));
    let errors: Vec<f64> = resolved.iter().zip(&exact).map(|(r, e)| r - e).collect();
    let full = png::error_scale(&errors);
    let shape = picture_shape(case);
    // A moving scene's time coverage is pictured as resolved coverage is.
    let timed = reference.time.is_some();
    let heading = if timed {
        "time coverage"
    } else {
        "resolved coverage"
    };
    let mut html = format!("<h4>{heading}</h4><div class=\"pictures{shape}\">");
    let mut show = |img: &RgbImage, role: &str, caption: &str| {
        html.push_str(&figure(&data_uri(&png_bytes(img)), role, caption, None));
    };
    show(
        &png::resolved_picture(scene, &exact, scale),
        "reference",
        if timed {
            "exact time coverage (reference)"
        } else {
            "exact area (reference)"
        },
    );
    let caption = match (timed, candidate.sample_tests) {
        (true, Some(tests)) => format!(
            "{name}: time coverage ({:.1}% of {} sample tests covered)",
            tests.efficiency() * 100.0,
            tests.tests
        ),
        (true, None) => format!("{name}: time coverage"),
        (false, _) if candidate.samples == 0 => format!("{name}: resolved (area method)"),
        (false, _) => format!("{name}: resolved ({} samples)", candidate.samples),
    };
    show(
        &png::resolved_picture(scene, &resolved, scale),
        "candidate",
        &caption,
    );
    show(
        &png::error_picture(scene, &errors, full, scale),
        "diff",
        &format!("signed error, full colour at ±{full:.2e}"),
    );
    let mask = if comparable(reference, candidate) {
        diff_mask(reference, candidate)
    } else {
        Vec::new()
    };
    let samples = png::samples_picture(scene, reference, &mask, scale.max(png::SAMPLES_MIN_SCALE));
    if let Some(img) = &samples {
        show(img, "samples", "samples (positions as drawn)");
    }
    html.push_str("</div>");
    if comparable(reference, candidate) {
        html.push_str(&first_differences(reference, candidate));
    }
    let mut key = vec![
        ([0, 0, 0], "0"),
        ([255, 255, 255], "1 (fully covered)"),
        (png::OVER_ONE, "above 1 (overlap)"),
        (png::TOO_MUCH, "error > 0: too much coverage"),
        (png::TOO_LITTLE, "error < 0: too little"),
    ];
    if timed {
        key.push(([0, 200, 255], "snapped edges at shutter open"));
        key.push((png::EDGE_AT_CLOSE, "at shutter close"));
    } else {
        key.push(([0, 200, 255], "snapped edges"));
    }
    html.push_str(&colour_key(&key));
    if samples.is_some() {
        html.push_str(&colour_key(&[
            (png::SAMPLE_SAME, "sample covered alike"),
            (png::SAMPLE_EMPTY, "empty in both"),
            (MISSING, "missing"),
            (EXTRA, "extra"),
            (WRONG_OWNER, "wrong owner"),
        ]));
    }
    html
}

/// The difference of every sample, as `metrics::coverage` finds it.
fn diff_mask(reference: &Frame, candidate: &Frame) -> Vec<SampleDiff> {
    crate::metrics::coverage::compare(reference, candidate).mask
}

/// The first few differing pixels, so that one can be found on a large
/// canvas.
fn first_differences(reference: &Frame, candidate: &Frame) -> String {
    const SHOWN: usize = 12;
    let mut listed = Vec::new();
    let mut total = 0usize;
    if !comparable(reference, candidate) {
        return String::new();
    }
    let n = reference.samples.max(1) as usize;
    for i in 0..reference.sample_count() {
        let (r, c) = (reference.coverage[i], candidate.coverage[i]);
        let kind = if c < r {
            "missing"
        } else if c > r {
            "extra"
        } else if reference.last[i] != candidate.last[i] {
            "wrong owner"
        } else {
            continue;
        };
        total += 1;
        if listed.len() < SHOWN {
            let pixel = (i / n) as u32;
            let (x, y) = (pixel % reference.width, pixel / reference.width);
            if n > 1 {
                listed.push(format!("({x}, {y}) sample {} {kind}", i % n));
            } else {
                listed.push(format!("({x}, {y}) {kind}"));
            }
        }
    }
    if total == 0 {
        return String::new();
    }
    format!(
        "<div class=\"files\">differing pixels (x, y from the top left): {}{}</div>",
        listed.join(" · "),
        if total > SHOWN {
            format!(" · … {} more", total - SHOWN)
        } else {
            String::new()
        }
    )
}

/// One heat map per interpolated channel with a nonzero error.
fn heat_maps(reference: &Frame, candidate: &Frame, m: &MetricsEntry) -> String {
    if m.channels.is_empty() {
        return String::new();
    }
    let errors = interpolation_errors(reference, candidate);
    let scale = display_scale(reference, 256);
    let mut figures = String::new();
    let mut exact = Vec::new();
    for (ch, (_, values)) in m.channels.iter().zip(&errors) {
        if ch.max_abs == 0.0 {
            exact.push(ch.channel.as_str());
            continue;
        }
        let top = if ch.max_abs.is_finite() {
            ch.max_abs
        } else {
            ch.allowed_abs
        };
        let img = heat_map(reference, values, top, ch.allowed_abs);
        let caption = format!(
            "{}: 0 → {:.2e} (bound {:.2e})",
            ch.channel, ch.max_abs, ch.allowed_abs
        );
        figures.push_str(&figure(
            &data_uri(&png_bytes(&img)),
            "heat",
            &caption,
            Some(reference.width * scale),
        ));
    }
    let mut html = String::from("<h4>interpolation error |candidate − exact|</h4>");
    if !figures.is_empty() {
        let ramp: Vec<String> = VIRIDIS.iter().map(|c| css_rgb(*c)).collect();
        let _ = write!(
            html,
            "<div class=\"pictures heat\">{figures}</div><div class=\"key\"><span>0<span class=\"ramp\" style=\"background:linear-gradient(to right,{})\"></span>largest error of the channel (linear)</span><span><i style=\"background:{}\"></i>above the bound</span><span><i style=\"background:{}\"></i>not compared (uncovered, or another primitive drawn last)</span></div>",
            ramp.join(","),
            css_rgb(ABOVE_BOUND),
            css_rgb(NOT_COMPARED)
        );
    }
    if !exact.is_empty() {
        let _ = write!(
            html,
            "<p class=\"muted\">Exact at every compared sample: {}.</p>",
            escape(&exact.join(", "))
        );
    }
    html
}

/// The whole page. `dir` is the report folder (links are relative to it);
/// `outcomes` are in the order of `report.cases`.
pub fn render(dir: &Path, report: &Report, outcomes: &[CaseOutcome]) -> String {
    let t = &report.totals;
    let mut html = String::from("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>rastercheck report</title>\n<style>");
    html.push_str(STYLE);
    html.push_str("</style>\n<script>");
    html.push_str(SCRIPT);
    html.push_str("</script></head>\n<body><main>\n");

    // Header.
    let _ = write!(
        html,
        "<h1>rastercheck report</h1><div class=\"muted\">{} {} · schema {}</div>",
        report.tool.name, report.tool.version, report.schema
    );
    if !report.complete {
        let _ = write!(
            html,
            "<div class=\"banner\">The run did not finish: {} cases did not run.</div>",
            t.not_run
        );
    }
    let command: Vec<String> = report.command.iter().map(|a| shell_quote(a)).collect();
    let _ = write!(
        html,
        "<p>Command: <code>rastercheck {}</code></p>",
        escape(&command.join(" "))
    );
    html.push_str("<div class=\"summary\"><table><tr><th>rasterizer</th><th class=\"n\">pass</th><th class=\"n\">fail</th><th class=\"n\">foil departures</th><th class=\"n\">unsupported</th><th class=\"n\">error</th></tr>");
    for (v, info) in t.verdicts.iter().zip(&report.rasterizers) {
        let x = &v.tally;
        let _ = write!(
            html,
            "<tr><td><b>{}</b>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>",
            escape(&v.rasterizer),
            if info.foil { " <span class=\"muted\">(foil)</span>" } else { "" },
            x.pass,
            x.fail,
            x.foil,
            x.unsupported,
            x.error
        );
    }
    html.push_str("</table>");
    let g = &t.golden;
    let _ = write!(
        html,
        "<div class=\"panel\"><b>{}</b> case files · {} unreadable · {} reference failures · {} over the time limit · {} not run<br>golden files: {} match, {} differ, {} missing</div></div>",
        t.cases, t.unreadable, t.reference_failed, t.limit_exceeded, t.not_run, g.matching, g.differing, g.missing
    );

    // Cards: chosen over the whole run, the most important first.
    let all = cards(report);
    let shown: Vec<Card> = all.iter().copied().take(MAX_PICTURED).collect();
    if all.len() > shown.len() {
        let left: Vec<String> = [
            (Kind::Problem, "failures and problems"),
            (Kind::Departure, "foil departures"),
            (
                Kind::Interpolation,
                "error maps of passing results (interpolation, antialiasing, time coverage)",
            ),
        ]
        .iter()
        .filter_map(|(kind, name)| {
            let n = all[shown.len()..]
                .iter()
                .filter(|c| c.kind == *kind)
                .count();
            (n > 0).then(|| format!("{n} {name}"))
        })
        .collect();
        let _ = write!(
            html,
            "<div class=\"banner\">{} of {} cards shown (at most {MAX_PICTURED}); left out: {}. report.json has every result.</div>",
            shown.len(),
            all.len(),
            left.join(", ")
        );
    }
    let carded = |case: usize, result: Option<usize>| {
        shown.iter().any(|c| c.case == case && c.result == result)
    };

    // Families, in order of first appearance.
    let mut families: Vec<&str> = Vec::new();
    for case in &report.cases {
        if !families.contains(&case.family.as_str()) {
            families.push(&case.family);
        }
    }
    html.push_str("<p>Families: ");
    let nav: Vec<String> = families
        .iter()
        .map(|f| {
            let n = report.cases.iter().filter(|c| c.family == *f).count();
            format!(
                "<a href=\"#family-{}\">{}</a> ({n})",
                escape(&slug(f)),
                escape(f)
            )
        })
        .collect();
    html.push_str(&nav.join(" · "));
    html.push_str("</p>\n");

    for family in &families {
        let members: Vec<usize> = (0..report.cases.len())
            .filter(|&c| report.cases[c].family == *family)
            .collect();
        let _ = write!(
            html,
            "<section class=\"family\" id=\"family-{}\"><h2>{} <span class=\"muted\">({} case{})</span></h2>",
            escape(&slug(family)),
            escape(family),
            members.len(),
            if members.len() == 1 { "" } else { "s" }
        );
        html.push_str("<table class=\"cases\"><tr><th>case</th><th>golden</th>");
        for r in &report.rasterizers {
            let _ = write!(html, "<th>{}</th>", escape(&r.name));
        }
        html.push_str("</tr>\n");
        for &c in &members {
            let case = &report.cases[c];
            let id_cell = if carded(c, None) {
                format!(
                    "<a href=\"#{}\">{}</a>",
                    anchor(case, None),
                    escape(&case.id)
                )
            } else {
                escape(&case.id)
            };
            let _ = write!(html, "<tr><td class=\"id\">{id_cell}</td><td>");
            if let Some(golden) = case.golden {
                html.push_str(&badge(golden, golden));
            }
            html.push_str("</td>");
            if case.status != "ran" {
                let why = case.error.as_deref().unwrap_or("");
                let _ = write!(
                    html,
                    "<td colspan=\"{}\">{}<span class=\"metric\">{}</span></td>",
                    report.rasterizers.len().max(1),
                    badge(case.status, case.status),
                    escape(&shorten(why, 160))
                );
            } else {
                for (r, result) in case.results.iter().enumerate() {
                    let link = carded(c, Some(r)).then(|| anchor(case, Some(result)));
                    let _ = write!(html, "<td>{}</td>", cell(result, link.as_deref()));
                }
            }
            html.push_str("</tr>\n");
        }
        html.push_str("</table>\n");

        // This family's cards, worst first.
        for card in shown.iter().filter(|card| members.contains(&card.case)) {
            let case = &report.cases[card.case];
            let outcome = outcomes.get(card.case).filter(|o| o.file.id == case.id);
            match card.result {
                None => html.push_str(&case_card(dir, case)),
                Some(r) => {
                    let result = &case.results[r];
                    let view = ResultView {
                        case,
                        result,
                        scene: outcome.and_then(|o| o.scene.as_ref()),
                        reference: outcome.and_then(|o| o.reference.as_ref()).map(|r| &r.frame),
                        candidate: outcome
                            .and_then(|o| o.candidates.get(r))
                            .and_then(|run| run.frame.as_ref())
                            .filter(|f| {
                                outcome
                                    .and_then(|o| o.reference.as_ref())
                                    .is_some_and(|r| same_shape(&r.frame, f))
                            }),
                    };
                    html.push_str(&result_card(dir, &view));
                }
            }
            html.push('\n');
        }
        html.push_str("</section>\n");
    }
    html.push_str("</main></body></html>\n");
    html
}

/// Whether a candidate's frame can be pictured beside the reference's: the
/// same samples, or resolved or time coverage of the same canvas.
fn same_shape(reference: &Frame, candidate: &Frame) -> bool {
    if reference.time.is_some() || candidate.time.is_some() {
        let time = |f: &Frame| f.time.as_ref().map(Vec::len);
        return time(candidate) == time(reference);
    }
    let resolved = |f: &Frame| f.resolved.as_ref().map(Vec::len);
    reference.sample_count() == candidate.sample_count() && candidate.samples == reference.samples
        || candidate.samples == 0
            && resolved(candidate).is_some()
            && resolved(candidate) == resolved(reference)
}

fn slug(text: &str) -> String {
    text.chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc_4648() {
        for (plain, encoded) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(plain.as_bytes()), encoded, "{plain:?}");
        }
        assert_eq!(base64(&[0xff, 0xfe, 0xfd]), "//79");
    }

    #[test]
    fn relative_urls_climb_and_descend() {
        let url = relative_url(Path::new("/a/b/report"), Path::new("/a/cases/x y#1.json"));
        assert_eq!(url.as_deref(), Some("../../cases/x%20y%231.json"));
        let url = relative_url(Path::new("/a"), Path::new("/a/c.json"));
        assert_eq!(url.as_deref(), Some("c.json"));
    }

    #[test]
    fn viridis_runs_dark_to_yellow() {
        assert_eq!(viridis(0.0), VIRIDIS[0]);
        assert_eq!(viridis(1.0), VIRIDIS[8]);
        assert_eq!(viridis(f64::NAN), VIRIDIS[8]);
    }
}
