//! Float error maps: `DIR/exr/<case id>/<rasterizer>.exr`, one per case ×
//! rasterizer whose result is not a pass or shows any error at all.
//!
//! One layer named `error`, f32 channels, signed (candidate − reference):
//!
//! - `coverage.error`: the candidate's coverage count minus the reference's;
//! - `owner.error`: 1 where the last primitive differs, else 0;
//! - `depth.error`, `attribute.K.error`: interpolated value minus the exact
//!   value, where both drew the same primitive last; 0 where nothing is
//!   covered or the last primitives differ (not compared). Under a depth
//!   format (SPEC.md §18) `depth.error` is the signed distance from the
//!   interval the reference allows at the sample (0 inside it), as the
//!   metrics measure it.
//!
//! With antialiasing (SPEC.md §14) the `error` layer holds one value per
//! sample: it is N times wider than the canvas, sample s of pixel (x, y) at
//! column x·N + s (the frame's slot order). A second layer, `resolved`, of
//! the canvas's size, holds `resolved.error`: the candidate's resolved
//! coverage minus the exact area, signed. A candidate without samples (an
//! area method) has only the `resolved` layer.
//!
//! A scene in which something moves (SPEC.md §15.4) has no samples: its
//! map is one layer, `time`, of the canvas's size, with `time.exact` (the
//! reference's time coverage), `time.candidate` and `time.error`
//! (candidate − exact, signed; infinite where the candidate's value is not
//! a number), so that a tool can read all three from the one file.

use std::path::{Path, PathBuf};

use ::exr::prelude::{
    AnyChannel, AnyChannels, Encoding, FlatSamples, Image, ImageAttributes, IntegerBounds, Layer,
    LayerAttributes, WritableImage,
};

use crate::frame::Frame;
use crate::metrics::{antialias, coverage, depth, time, Metrics};

/// Whether sample `i` has comparable interpolated values: the reference
/// covers it and both frames drew the same primitive last (the metrics'
/// rule, `metrics::interpolation`).
pub fn compared(reference: &Frame, candidate: &Frame, i: usize) -> bool {
    reference.last[i] != 0 && reference.last[i] == candidate.last[i]
}

/// Signed interpolation errors per channel, named as in the EXR file
/// (`depth.error`, `attribute.K.error`), in the order of `Metrics::channels`
/// (depth first). `None` where the sample is not compared. With
/// `depth_allowed` (a depth format's set, one [lo, hi] per sample) the
/// depth's error is its signed distance from the interval.
pub fn interpolation_errors(
    reference: &Frame,
    candidate: &Frame,
    depth_allowed: Option<&[[f64; 2]]>,
) -> Vec<(String, Vec<Option<f64>>)> {
    if !coverage::comparable(reference, candidate) {
        return Vec::new();
    }
    let errors = |exact: &[f64], values: &[f64]| -> Vec<Option<f64>> {
        (0..reference.sample_count())
            .map(|i| compared(reference, candidate, i).then(|| values[i] - exact[i]))
            .collect()
    };
    let mut out = Vec::new();
    if let (Some(exact), Some(values)) = (&reference.depth, &candidate.depth) {
        let depth = match depth_allowed {
            Some(allowed) => (0..reference.sample_count())
                .map(|i| {
                    compared(reference, candidate, i)
                        .then(|| depth::signed_distance(values[i], allowed[i]))
                })
                .collect(),
            None => errors(exact, values),
        };
        out.push(("depth.error".to_owned(), depth));
    }
    for (k, (exact, values)) in reference
        .attributes
        .iter()
        .zip(&candidate.attributes)
        .enumerate()
    {
        out.push((format!("attribute.{k}.error"), errors(exact, values)));
    }
    out
}

/// Whether a result deserves an error map: it did not pass, or some sample
/// differs in coverage, owner or value.
pub fn has_error(passed: bool, metrics: &Metrics) -> bool {
    !passed
        || metrics.coverage.mismatched() > 0
        || metrics
            .channels
            .iter()
            .any(|ch| ch.max_abs != 0.0 || ch.max_abs.is_nan())
        || metrics
            .antialias
            .as_ref()
            .is_some_and(|a| a.max_error != 0.0 || a.max_error.is_nan())
        || metrics
            .time
            .as_ref()
            .is_some_and(|t| t.max_error != 0.0 || t.max_error.is_nan())
}

/// The channels of the `time` layer: exact, candidate and signed error;
/// empty when either frame has no time coverage of the canvas's size.
pub fn time_channels(reference: &Frame, candidate: &Frame) -> Vec<(String, Vec<f32>)> {
    let errors = time::signed_errors(reference, candidate);
    let (Some(exact), Some(values)) = (&reference.time, &candidate.time) else {
        return Vec::new();
    };
    if errors.len() != reference.pixel_count() {
        return Vec::new();
    }
    let narrow = |v: &[f64]| v.iter().map(|&x| x as f32).collect();
    vec![
        ("time.exact".to_owned(), narrow(exact)),
        ("time.candidate".to_owned(), narrow(values)),
        ("time.error".to_owned(), narrow(&errors)),
    ]
}

/// Every per-sample channel of the error map, named as stored; empty when
/// the candidate's samples do not line up with the reference's.
pub fn error_channels(
    reference: &Frame,
    candidate: &Frame,
    depth_allowed: Option<&[[f64; 2]]>,
) -> Vec<(String, Vec<f32>)> {
    if !coverage::comparable(reference, candidate) {
        return Vec::new();
    }
    let n = reference.sample_count();
    let mut out = vec![
        (
            "coverage.error".to_owned(),
            (0..n)
                .map(|i| f32::from(candidate.coverage[i]) - f32::from(reference.coverage[i]))
                .collect(),
        ),
        (
            "owner.error".to_owned(),
            (0..n)
                .map(|i| f32::from(u8::from(candidate.last[i] != reference.last[i])))
                .collect(),
        ),
    ];
    for (name, errors) in interpolation_errors(reference, candidate, depth_allowed) {
        out.push((
            name,
            errors.iter().map(|e| e.unwrap_or(0.0) as f32).collect(),
        ));
    }
    out
}

/// The file name of a rasterizer's map (as for its PNG: `:` and `/`
/// become `-`).
pub fn file_name(rasterizer: &str) -> String {
    format!("{}.exr", rasterizer.replace([':', '/'], "-"))
}

/// Writes the error map of `candidate` against `reference` (and the depth
/// set a depth format allows, if any) to `path`.
pub fn write(
    reference: &Frame,
    candidate: &Frame,
    depth_allowed: Option<&[[f64; 2]]>,
    path: &Path,
) -> Result<PathBuf, String> {
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
    }
    let canvas = (reference.width as usize, reference.height as usize);
    let layer = |name: &str, size: (usize, usize), channels: Vec<(String, Vec<f32>)>| {
        let list = channels
            .into_iter()
            .map(|(name, values)| AnyChannel::new(name.as_str(), FlatSamples::F32(values)))
            .collect();
        Layer::new(
            size,
            LayerAttributes::named(name),
            Encoding::SMALL_LOSSLESS,
            AnyChannels::sort(list),
        )
    };
    let mut layers = Vec::new();
    let samples = error_channels(reference, candidate, depth_allowed);
    if !samples.is_empty() {
        let wide = (canvas.0 * reference.samples as usize, canvas.1);
        layers.push(layer("error", wide, samples));
    }
    let resolved = antialias::signed_errors(reference, candidate);
    if !resolved.is_empty() {
        let values = resolved.iter().map(|&e| e as f32).collect();
        layers.push(layer(
            "resolved",
            canvas,
            vec![("resolved.error".to_owned(), values)],
        ));
    }
    let time = time_channels(reference, candidate);
    if !time.is_empty() {
        layers.push(layer("time", canvas, time));
    }
    let mut bytes = Vec::new();
    let buffer = std::io::Cursor::new(&mut bytes);
    let written = match layers.len() {
        0 => return Err(format!("{}: nothing to compare", path.display())),
        1 => Image::from_layer(layers.pop().expect("one layer"))
            .write()
            .to_buffered(buffer),
        _ => Image::from_layers(
            ImageAttributes::new(IntegerBounds::new((0, 0), canvas)),
            layers,
        )
        .write()
        .to_buffered(buffer),
    };
    written.map_err(|e| format!("{}: {e}", path.display()))?;
    super::files::write_file(path, &bytes)
}
