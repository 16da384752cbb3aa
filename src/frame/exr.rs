//! A frame as EXR channels: the layers and channels a [`Frame`] is stored
//! as, written and read back. The golden files (`harness::golden`) and
//! external rasterizers' EXR answers (`adapters::external`) share it; where
//! a golden file lives and how it is compared stay with the harness.
//!
//! A file holds one f32 channel per output: `coverage` (how many
//! primitives cover each sample), `primitive` (index + 1 of the last one;
//! 0 for none), `depth` when the case has depth, and `attribute.K` for each
//! attribute. In a golden file, depth and attribute values are the
//! correctly rounded f32 of the exact value (the reference's round-to-odd
//! f64, narrowed).
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

use std::path::Path;

use exr::prelude::{
    read_all_flat_layers_from_file, AnyChannel, AnyChannels, Encoding, FlatSamples, Image,
    ImageAttributes, IntegerBounds, Layer, LayerAttributes, WritableImage,
};

use super::model::Frame;

/// The layer of the sample channels.
pub(crate) const SAMPLES_LAYER: &str = "reference";
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
    pub(crate) fn len(&self) -> usize {
        match self {
            Values::F32(v) => v.len(),
            Values::U32(v) => v.len(),
        }
    }

    /// The stored bits of value `i`.
    pub(crate) fn bits(&self, i: usize) -> u32 {
        match self {
            Values::F32(v) => v[i].to_bits(),
            Values::U32(v) => v[i],
        }
    }

    pub(crate) fn show(&self, i: usize) -> String {
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
pub(crate) struct LayerData {
    pub(crate) name: String,
    pub(crate) size: (usize, usize),
    pub(crate) channels: Vec<(String, Values)>,
}

/// The layers a frame is stored as, named as stored.
pub(crate) fn layers(frame: &Frame) -> Vec<LayerData> {
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

/// The size of each layer of an EXR file, from its header alone, before
/// anything is decoded. Anything but a regular file (after symbolic links:
/// a FIFO, a device, a folder) is refused without being opened, so that
/// reading it can neither hang nor take unbounded memory.
pub(crate) fn layer_sizes(path: &Path) -> Result<Vec<(usize, usize)>, String> {
    let meta = std::fs::metadata(path).map_err(|e| format!("{}: {e}", path.display()))?;
    if !meta.is_file() {
        return Err(format!(
            "{}: not a regular file (a FIFO, device or folder is not read)",
            path.display()
        ));
    }
    let data = ::exr::meta::MetaData::read_from_file(path, false)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(data
        .headers
        .iter()
        .map(|h| (h.layer_size.width(), h.layer_size.height()))
        .collect())
}

/// Refuses a file with a layer of more than `max_pixels` pixels, from its
/// header, before decoding it.
fn check_size(path: &Path, max_pixels: usize, what: &str) -> Result<(), String> {
    for (w, h) in layer_sizes(path)? {
        if w.saturating_mul(h) > max_pixels {
            return Err(format!(
                "{}: its header says a layer of {w}×{h} pixels, more than {what} \
                 ({max_pixels} pixels); not decoded",
                path.display()
            ));
        }
    }
    Ok(())
}

/// Reads every f32 channel of an EXR file of one layer of `size` pixels (an
/// external rasterizer's answer), with the image size. Another size in its
/// header is refused before anything is decoded.
pub fn read(path: &Path, size: (usize, usize)) -> Result<Channels, String> {
    if let Some(&(w, h)) = layer_sizes(path)?.first() {
        if (w, h) != size {
            return Err(format!(
                "{}: the image is {w}×{h} by its header; the canvas is {}×{}",
                path.display(),
                size.0,
                size.1
            ));
        }
    }
    check_size(path, size.0.saturating_mul(size.1), "the canvas")?;
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
/// u32 words as stored). A file with a layer of more than `max_pixels`
/// pixels (the largest layer the case's canvas can have) is refused from
/// its header, before anything is decoded.
pub(crate) fn read_layers(path: &Path, max_pixels: usize) -> Result<Vec<LayerData>, String> {
    check_size(path, max_pixels, "any layer of this canvas")?;
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
