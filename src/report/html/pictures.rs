//! The pictures of the HTML page: PNGs as base64 `data:` URIs, the
//! resolved or time coverage of an antialiased or moving case (exact,
//! candidate, signed error, samples), the first differing pixels, and one
//! viridis heat map per interpolated channel; figures and colour keys.
//!
//! The PNG files under `images/` and their colours are `png.rs`'s; this
//! file only embeds and keys them.

use std::fmt::Write as _;

use image::{Rgb, RgbImage};

use crate::frame::Frame;
use crate::metrics::{coverage::comparable, SampleDiff};
use crate::report::escape::escape;
use crate::report::exr::interpolation_errors;
use crate::report::json::{CaseEntry, MetricsEntry};
use crate::report::png::{self, EXTRA, MISSING, WRONG_OWNER};
use crate::scene::Scene;

/// Viridis, sampled at nine evenly spaced stops.
pub(super) const VIRIDIS: [[u8; 3]; 9] = [
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
pub(super) const NOT_COMPARED: [u8; 3] = [30, 30, 30];
/// Heat maps: errors above the channel's bound.
pub(super) const ABOVE_BOUND: [u8; 3] = [255, 0, 0];
pub(super) const COVERAGE_TWICE: [u8; 3] = [255, 150, 0];

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

pub(super) fn png_bytes(img: &RgbImage) -> Vec<u8> {
    let mut bytes = Vec::new();
    img.write_to(
        &mut std::io::Cursor::new(&mut bytes),
        image::ImageFormat::Png,
    )
    .expect("encoding a PNG in memory");
    bytes
}

pub(super) fn data_uri(png: &[u8]) -> String {
    format!("data:image/png;base64,{}", base64(png))
}

pub(super) fn viridis(t: f64) -> [u8; 3] {
    let t = if t.is_nan() { 1.0 } else { t.clamp(0.0, 1.0) };
    let x = t * (VIRIDIS.len() - 1) as f64;
    let k = (x.floor() as usize).min(VIRIDIS.len() - 2);
    let f = x - k as f64;
    let (a, b) = (VIRIDIS[k], VIRIDIS[k + 1]);
    std::array::from_fn(|c| {
        (f64::from(a[c]) + (f64::from(b[c]) - f64::from(a[c])) * f).round() as u8
    })
}

pub(super) fn css_rgb(c: [u8; 3]) -> String {
    format!("rgb({},{},{})", c[0], c[1], c[2])
}

/// Display magnification for a native-size picture: about `target` pixels
/// across, 1 to 16.
pub(super) fn display_scale(frame: &Frame, target: u32) -> u32 {
    (target / frame.width.max(frame.height).max(1)).clamp(1, 16)
}

/// A heat map of |error| at one pixel per pixel (the largest over its
/// samples), 0 → `scale_max` on viridis; red above `bound`, dark grey where
/// no sample is compared.
pub(super) fn heat_map(
    frame: &Frame,
    errors: &[Option<f64>],
    scale_max: f64,
    bound: f64,
) -> RgbImage {
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

pub(super) fn figure(src: &str, role: &str, caption: &str, width: Option<u32>) -> String {
    let style = width.map_or(String::new(), |w| format!(" style=\"width:{w}px\""));
    format!(
        "<figure><img data-role=\"{}\" src=\"{src}\" alt=\"{}\"{style}><figcaption>{}</figcaption></figure>",
        escape(role),
        escape(caption),
        escape(caption)
    )
}

pub(super) fn colour_key(entries: &[([u8; 3], &str)]) -> String {
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

/// The shape class of a case's pictures: wide canvases stack their
/// pictures, so each keeps its scale; tall ones scroll inside a box of
/// bounded height.
pub(super) fn picture_shape(case: &CaseEntry) -> &'static str {
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
pub(super) fn coverage_pictures(
    case: &CaseEntry,
    scene: &Scene,
    (reference, candidate): (&Frame, &Frame),
    judged: Option<&[SampleDiff]>,
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
        judged.map_or_else(|| diff_mask(reference, candidate), <[SampleDiff]>::to_vec)
    } else {
        Vec::new()
    };
    let samples = png::samples_picture(scene, reference, &mask, scale.max(png::SAMPLES_MIN_SCALE));
    if let Some(img) = &samples {
        show(img, "samples", "samples (positions as drawn)");
    }
    html.push_str("</div>");
    if comparable(reference, candidate) {
        html.push_str(&first_differences(reference, candidate, judged));
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
        if mask.contains(&SampleDiff::Tie) {
            html.push_str(&colour_key(&[(png::TIE_ACCEPTED, TIE_WORDS)]));
        }
    }
    html
}

/// The colour key's words for an accepted tie sample.
pub(super) const TIE_WORDS: &str =
    "tie sample taken by a choice of sides: accepted (no tie rule, counted on the ties line)";

/// The difference of every sample, as `metrics::coverage` finds it.
pub(super) fn diff_mask(reference: &Frame, candidate: &Frame) -> Vec<SampleDiff> {
    crate::metrics::coverage::compare(reference, candidate).mask
}

/// The first few differing pixels, so that one can be found on a large
/// canvas; with the mask the candidate was judged by (`judged`), accepted
/// tie samples are not among them.
pub(super) fn first_differences(
    reference: &Frame,
    candidate: &Frame,
    judged: Option<&[SampleDiff]>,
) -> String {
    const SHOWN: usize = 12;
    let mut listed = Vec::new();
    let mut total = 0usize;
    if !comparable(reference, candidate) {
        return String::new();
    }
    let n = reference.samples.max(1) as usize;
    for i in 0..reference.sample_count() {
        let (r, c) = (reference.coverage[i], candidate.coverage[i]);
        let accepted = judged.and_then(|m| m.get(i)) == Some(&SampleDiff::Tie);
        let kind = if accepted {
            continue;
        } else if c < r {
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
pub(super) fn heat_maps(
    reference: &Frame,
    candidate: &Frame,
    depth_allowed: Option<&[[f64; 2]]>,
    m: &MetricsEntry,
) -> String {
    if m.channels.is_empty() {
        return String::new();
    }
    let errors = interpolation_errors(reference, candidate, depth_allowed);
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

    /// Accepted tie samples are not listed among the differing pixels;
    /// judged without the mask, they are.
    #[test]
    fn accepted_ties_are_not_differences() {
        let reference = Frame::new(3, 1, false, 0);
        let mut candidate = Frame::new(3, 1, false, 0);
        for i in [0, 2] {
            candidate.coverage[i] = 1;
            candidate.last[i] = 1;
        }
        let mask = [SampleDiff::Tie, SampleDiff::Same, SampleDiff::Extra];
        let judged = first_differences(&reference, &candidate, Some(&mask));
        assert!(judged.contains("(2, 0) extra"), "{judged}");
        assert!(!judged.contains("(0, 0)"), "{judged}");
        let plain = first_differences(&reference, &candidate, None);
        assert!(plain.contains("(0, 0) extra"), "{plain}");
    }

    #[test]
    fn viridis_runs_dark_to_yellow() {
        assert_eq!(viridis(0.0), VIRIDIS[0]);
        assert_eq!(viridis(1.0), VIRIDIS[8]);
        assert_eq!(viridis(f64::NAN), VIRIDIS[8]);
    }
}
