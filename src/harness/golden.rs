//! Golden files: the blessed reference output of every case, as EXR.
//!
//! `reference/<case id>.exr` holds one f32 channel per output: `coverage`
//! (how many primitives cover each sample), `primitive` (index + 1 of the
//! last one; 0 for none), `depth` when the case has depth, and
//! `attribute.K` for each attribute. Depth and attribute values are the
//! correctly rounded f32 of the exact value (the reference's round-to-odd
//! f64, narrowed). A change to the oracle that moves any of them shows up
//! as a failing test and, once blessed, as a binary diff in review.
//!
//! An antialiased case (SPEC.md §14) has N samples per pixel and a resolved
//! coverage per pixel. Its sample channels are stored in the same layer,
//! `reference`, made N times wider: sample s of pixel (x, y) is at column
//! x·N + s, which is exactly the frame's slot order. A second layer,
//! `resolved`, of the canvas's size, holds the resolved coverage (the exact
//! area rounded to f64) as `resolved` (its nearest f32, for people) and as
//! the two 32-bit halves of the f64's bits, `resolved.f64.high` and
//! `resolved.f64.low` (u32), so that it is checked to the bit. A
//! single-sample case without antialiasing keeps its one layer as before.
//!
//! A scene in which something moves (SPEC.md §15.4) has no samples: its
//! file holds one layer, `time`, of the canvas's size, with each pixel's
//! exact time coverage rounded to f64, stored like `resolved`: as `time`
//! (f32, for people) and as `time.f64.high` and `time.f64.low` (u32), so
//! that it is checked to the bit.

use std::path::{Path, PathBuf};

use exr::prelude::{
    read_all_flat_layers_from_file, AnyChannel, AnyChannels, Encoding, FlatSamples, Image,
    ImageAttributes, IntegerBounds, Layer, LayerAttributes, WritableImage,
};

use crate::frame::Frame;

/// Where a case's golden file lives: `reference/<id>.exr` under `root`.
pub fn path_for(root: &Path, case_id: &str) -> PathBuf {
    root.join("reference").join(format!("{case_id}.exr"))
}

/// The layer of the sample channels.
const SAMPLES_LAYER: &str = "reference";
/// The layer of the resolved coverage (antialiased cases only).
const RESOLVED_LAYER: &str = "resolved";
/// The layer of the time coverage (scenes in which something moves).
const TIME_LAYER: &str = "time";

/// Stored values of one channel: f32 for values, u32 for exact bits.
#[derive(Clone, Debug, PartialEq)]
pub enum Values {
    F32(Vec<f32>),
    U32(Vec<u32>),
}

impl Values {
    fn len(&self) -> usize {
        match self {
            Values::F32(v) => v.len(),
            Values::U32(v) => v.len(),
        }
    }

    /// The stored bits of value `i`.
    fn bits(&self, i: usize) -> u32 {
        match self {
            Values::F32(v) => v[i].to_bits(),
            Values::U32(v) => v[i],
        }
    }

    fn show(&self, i: usize) -> String {
        match self {
            Values::F32(v) => v[i].to_string(),
            Values::U32(v) => format!("{:#010x}", v[i]),
        }
    }

    fn samples(self) -> FlatSamples {
        match self {
            Values::F32(v) => FlatSamples::F32(v),
            Values::U32(v) => FlatSamples::U32(v),
        }
    }
}

/// One stored layer: its name, size and channels.
struct LayerData {
    name: String,
    size: (usize, usize),
    channels: Vec<(String, Values)>,
}

/// The layers a frame is stored as, named as stored.
fn layers(frame: &Frame) -> Vec<LayerData> {
    let mut out = Vec::new();
    let n = frame.samples as usize;
    if n > 0 {
        out.push(LayerData {
            name: SAMPLES_LAYER.to_owned(),
            size: (frame.width as usize * n, frame.height as usize),
            channels: channels(frame)
                .into_iter()
                .map(|(name, v)| (name, Values::F32(v)))
                .collect(),
        });
    }
    for (name, values) in [(RESOLVED_LAYER, &frame.resolved), (TIME_LAYER, &frame.time)] {
        if let Some(values) = values {
            out.push(per_pixel_f64(name, frame, values));
        }
    }
    out
}

/// A layer of one f64 per pixel: `<name>` as its nearest f32, for people,
/// and the f64's bits as `<name>.f64.high` and `<name>.f64.low`.
fn per_pixel_f64(name: &str, frame: &Frame, values: &[f64]) -> LayerData {
    let word = |shift: u32| {
        values
            .iter()
            .map(|v| (v.to_bits() >> shift) as u32)
            .collect()
    };
    LayerData {
        name: name.to_owned(),
        size: (frame.width as usize, frame.height as usize),
        channels: vec![
            (
                name.to_owned(),
                Values::F32(values.iter().map(|&v| v as f32).collect()),
            ),
            (format!("{name}.f64.high"), Values::U32(word(32))),
            (format!("{name}.f64.low"), Values::U32(word(0))),
        ],
    }
}

/// The sample channels of a frame, named as stored, in f32.
fn channels(frame: &Frame) -> Vec<(String, Vec<f32>)> {
    let mut out = vec![
        (
            "coverage".to_owned(),
            frame.coverage.iter().map(|&c| f32::from(c)).collect(),
        ),
        (
            "primitive".to_owned(),
            frame.last.iter().map(|&p| p as f32).collect(),
        ),
    ];
    if let Some(depth) = &frame.depth {
        out.push((
            "depth".to_owned(),
            depth.iter().map(|&v| v as f32).collect(),
        ));
    }
    for (k, values) in frame.attributes.iter().enumerate() {
        out.push((
            format!("attribute.{k}"),
            values.iter().map(|&v| v as f32).collect(),
        ));
    }
    out
}

/// Writes a frame as its golden file, creating folders as needed. A time
/// coverage that is not a number (what the suite holds when the oracle
/// failed) is refused: a golden file records what the oracle computed.
pub fn write(frame: &Frame, path: &Path) -> Result<(), String> {
    if let Some(p) = frame.time.iter().flatten().position(|v| v.is_nan()) {
        let width = frame.width.max(1) as usize;
        return Err(format!(
            "{}: the time coverage of pixel ({}, {}) is not a number (the oracle failed); nothing written",
            path.display(),
            p % width,
            p / width
        ));
    }
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
    }
    let layers: Vec<_> = layers(frame)
        .into_iter()
        .map(|layer| {
            let list = layer
                .channels
                .into_iter()
                .map(|(name, values)| AnyChannel::new(name.as_str(), values.samples()))
                .collect();
            Layer::new(
                layer.size,
                LayerAttributes::named(layer.name.as_str()),
                Encoding::SMALL_LOSSLESS,
                AnyChannels::sort(list),
            )
        })
        .collect();
    let written = if layers.len() == 1 {
        // One layer, written exactly as before antialiasing existed.
        let layer = layers.into_iter().next().expect("one layer");
        Image::from_layer(layer).write().to_file(path)
    } else {
        let canvas = IntegerBounds::new((0, 0), (frame.width as usize, frame.height as usize));
        Image::from_layers(ImageAttributes::new(canvas), layers)
            .write()
            .to_file(path)
    };
    written.map_err(|e| format!("{}: {e}", path.display()))
}

/// A golden file's size and its named f32 channels.
pub type Channels = ((usize, usize), Vec<(String, Vec<f32>)>);

/// Reads every f32 channel of a golden file, with the image size.
pub fn read(path: &Path) -> Result<Channels, String> {
    let image =
        read_all_flat_layers_from_file(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let layer = image
        .layer_data
        .first()
        .ok_or_else(|| format!("{}: no layer", path.display()))?;
    let size = (layer.size.width(), layer.size.height());
    let channels = layer
        .channel_data
        .list
        .iter()
        .map(|c| (c.name.to_string(), c.sample_data.values_as_f32().collect()))
        .collect();
    Ok((size, channels))
}

/// Every layer of a golden file with its size and channels (f32 values;
/// u32 words as stored).
fn read_layers(path: &Path) -> Result<Vec<LayerData>, String> {
    let image =
        read_all_flat_layers_from_file(path).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(image
        .layer_data
        .iter()
        .map(|layer| LayerData {
            name: layer
                .attributes
                .layer_name
                .as_ref()
                .map_or_else(|| SAMPLES_LAYER.to_owned(), |n| n.to_string()),
            size: (layer.size.width(), layer.size.height()),
            channels: layer
                .channel_data
                .list
                .iter()
                .map(|c| {
                    let values = match &c.sample_data {
                        FlatSamples::U32(words) => Values::U32(words.clone()),
                        other => Values::F32(other.values_as_f32().collect()),
                    };
                    (c.name.to_string(), values)
                })
                .collect(),
        })
        .collect())
}

/// Compares a freshly computed reference frame with its golden file.
/// `Ok` when every channel of every layer matches to the bit; otherwise
/// what differs.
pub fn check(frame: &Frame, path: &Path) -> Result<(), String> {
    let mut stored = read_layers(path)?;
    let mut problems = Vec::new();
    let samples = frame.samples.max(1) as usize;
    for layer in layers(frame) {
        let Some(at) = stored.iter().position(|l| l.name == layer.name) else {
            problems.push(format!(
                "layer {} is missing from the golden file",
                layer.name
            ));
            continue;
        };
        let golden = stored.swap_remove(at);
        if golden.size != layer.size {
            let what = if layer.name == SAMPLES_LAYER && samples > 1 {
                format!(
                    "{}×{} ({} samples per pixel)",
                    frame.width, frame.height, samples
                )
            } else {
                format!("{}×{}", frame.width, frame.height)
            };
            problems.push(format!(
                "golden file's layer {} is {}×{}, the case's canvas is {what}",
                layer.name, golden.size.0, golden.size.1
            ));
            continue;
        }
        let per_pixel = if layer.name == SAMPLES_LAYER {
            samples
        } else {
            1
        };
        compare_channels(
            layer,
            golden,
            per_pixel,
            frame.width as usize,
            &mut problems,
        );
    }
    for layer in stored {
        problems.push(format!(
            "golden file has layer {}, which the reference no longer produces",
            layer.name
        ));
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(problems.join("; "))
    }
}

/// Compares the channels of one layer to the bit; `per_pixel` values make
/// one pixel of a canvas `width` pixels wide.
fn compare_channels(
    now: LayerData,
    golden: LayerData,
    per_pixel: usize,
    width: usize,
    problems: &mut Vec<String>,
) {
    let mut stored = golden.channels;
    for (name, values) in now.channels {
        let Some(at) = stored.iter().position(|(n, _)| *n == name) else {
            problems.push(format!("channel {name} is missing from the golden file"));
            continue;
        };
        let (_, golden) = stored.swap_remove(at);
        if std::mem::discriminant(&golden) != std::mem::discriminant(&values)
            || golden.len() != values.len()
        {
            problems.push(format!(
                "channel {name} has another type or size in the golden file"
            ));
            continue;
        }
        let differs = |i: &usize| values.bits(*i) != golden.bits(*i);
        let differing = (0..values.len()).filter(differs).count();
        if let Some(first) = (0..values.len()).find(differs) {
            let pixel = first / per_pixel;
            let (x, y) = (pixel % width.max(1), pixel / width.max(1));
            let sample = if per_pixel > 1 {
                format!(" sample {}", first % per_pixel)
            } else {
                String::new()
            };
            problems.push(format!(
                "channel {name}: {differing} samples differ; first at pixel ({x}, {y}){sample}: now {}, golden {}",
                values.show(first),
                golden.show(first)
            ));
        }
    }
    for (name, _) in stored {
        problems.push(format!(
            "golden file has channel {name}, which the reference no longer produces"
        ));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn antialiased() -> Frame {
        let mut frame = Frame::new(3, 2, false, 1);
        frame.samples = 4;
        let n = 3 * 2 * 4;
        frame.coverage = (0..n).map(|i| (i % 3 == 0) as u16).collect();
        frame.last = frame.coverage.iter().map(|&c| u32::from(c)).collect();
        frame.attributes = vec![(0..n).map(|i| i as f64 / 7.0).collect()];
        frame.resolved = Some((0..6).map(|p| p as f64 / 3.0).collect());
        frame
    }

    #[test]
    fn antialiased_frames_round_trip_to_the_bit() {
        let dir = std::env::temp_dir().join(format!("rastercheck-golden-{}", std::process::id()));
        let path = dir.join("aa.exr");
        let frame = antialiased();
        write(&frame, &path).unwrap();
        assert_eq!(check(&frame, &path), Ok(()));

        // One ulp of one resolved f64: invisible in f32, caught in the bits.
        let mut changed = frame.clone();
        let r = changed.resolved.as_mut().unwrap();
        r[4] = f64::from_bits(r[4].to_bits() + 1);
        let err = check(&changed, &path).unwrap_err();
        assert!(
            err.contains("resolved.f64.low") && err.contains("(1, 1)"),
            "{err}"
        );
        assert!(!err.contains("channel resolved:"), "{err}");

        // One sample of pixel (2, 0).
        let mut changed = frame.clone();
        changed.coverage[2 * 4 + 3] += 1;
        let err = check(&changed, &path).unwrap_err();
        assert!(err.contains("pixel (2, 0) sample 3"), "{err}");

        // The same canvas with another sample count.
        let mut changed = frame.clone();
        changed.samples = 2;
        changed.coverage.truncate(12);
        changed.last.truncate(12);
        changed.attributes[0].truncate(12);
        let err = check(&changed, &path).unwrap_err();
        assert!(err.contains("2 samples per pixel"), "{err}");

        // A single-sample frame is one layer, as before.
        let plain = Frame::new(3, 2, false, 0);
        write(&plain, &path).unwrap();
        assert_eq!(check(&plain, &path), Ok(()));
        assert_eq!(read(&path).unwrap().0, (3, 2));
        let err = check(&frame, &path).unwrap_err();
        assert!(err.contains("layer resolved is missing"), "{err}");
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn time_coverage_round_trips_to_the_bit() {
        let dir = std::env::temp_dir().join(format!("rastercheck-golden-t-{}", std::process::id()));
        let path = dir.join("time.exr");
        let frame = Frame::time_only(4, 3, (0..12).map(|p| p as f64 / 7.0).collect());
        write(&frame, &path).unwrap();
        assert_eq!(check(&frame, &path), Ok(()));
        let layers = read_layers(&path).unwrap();
        assert_eq!(layers.len(), 1);
        assert_eq!((layers[0].name.as_str(), layers[0].size), ("time", (4, 3)));
        let mut names: Vec<&str> = layers[0].channels.iter().map(|(n, _)| n.as_str()).collect();
        names.sort();
        assert_eq!(names, ["time", "time.f64.high", "time.f64.low"]);

        // One ulp of pixel (2, 1): caught in the low word only.
        let mut changed = frame.clone();
        let t = changed.time.as_mut().unwrap();
        t[6] = f64::from_bits(t[6].to_bits() + 1);
        let err = check(&changed, &path).unwrap_err();
        assert!(
            err.contains("channel time.f64.low: 1 samples differ; first at pixel (2, 1)"),
            "{err}"
        );
        assert!(!err.contains("channel time:"), "{err}");

        // A static frame against a moving scene's file, and back.
        let plain = Frame::new(4, 3, false, 0);
        let err = check(&plain, &path).unwrap_err();
        assert!(
            err.contains("layer reference is missing") && err.contains("layer time, which"),
            "{err}"
        );
        write(&plain, &path).unwrap();
        let err = check(&frame, &path).unwrap_err();
        assert!(err.contains("layer time is missing"), "{err}");

        // A failed oracle's NaN is never written.
        let mut broken = frame.clone();
        broken.time.as_mut().unwrap()[5] = f64::NAN;
        let err = write(&broken, &path).unwrap_err();
        assert!(err.contains("pixel (1, 1) is not a number"), "{err}");
        assert_eq!(check(&plain, &path), Ok(()), "the file is unchanged");
        std::fs::remove_dir_all(&dir).ok();
    }
}
