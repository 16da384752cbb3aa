//! Golden files: the blessed reference output of every case, as EXR.
//!
//! `reference/<case id>.exr` holds one f32 channel per output: `coverage`
//! (how many primitives cover each sample), `primitive` (index + 1 of the
//! last one; 0 for none), `depth` when the case has depth, and
//! `attribute.K` for each attribute. Depth and attribute values are the
//! correctly rounded f32 of the exact value (the reference's round-to-odd
//! f64, narrowed). A change to the oracle that moves any of them shows up
//! as a failing test and, once blessed, as a binary diff in review.

use std::path::{Path, PathBuf};

use exr::prelude::{
    read_all_flat_layers_from_file, AnyChannel, AnyChannels, Encoding, FlatSamples, Image, Layer,
    LayerAttributes, WritableImage,
};

use crate::frame::Frame;

/// Where a case's golden file lives: `reference/<id>.exr` under `root`.
pub fn path_for(root: &Path, case_id: &str) -> PathBuf {
    root.join("reference").join(format!("{case_id}.exr"))
}

/// The channels of a frame, named as stored, in f32.
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

/// Writes a frame as its golden file, creating folders as needed.
pub fn write(frame: &Frame, path: &Path) -> Result<(), String> {
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
    }
    let size = (frame.width as usize, frame.height as usize);
    let list = channels(frame)
        .into_iter()
        .map(|(name, values)| AnyChannel::new(name.as_str(), FlatSamples::F32(values)))
        .collect();
    let layer = Layer::new(
        size,
        LayerAttributes::named("reference"),
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(list),
    );
    Image::from_layer(layer)
        .write()
        .to_file(path)
        .map_err(|e| format!("{}: {e}", path.display()))
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

/// Compares a freshly computed reference frame with its golden file.
/// `Ok` when every channel matches to the bit; otherwise what differs.
pub fn check(frame: &Frame, path: &Path) -> Result<(), String> {
    let (size, mut stored) = read(path)?;
    if size != (frame.width as usize, frame.height as usize) {
        return Err(format!(
            "golden file is {}×{}, the case's canvas is {}×{}",
            size.0, size.1, frame.width, frame.height
        ));
    }
    let mut problems = Vec::new();
    for (name, values) in channels(frame) {
        let Some(at) = stored.iter().position(|(n, _)| *n == name) else {
            problems.push(format!("channel {name} is missing from the golden file"));
            continue;
        };
        let (_, golden) = stored.swap_remove(at);
        let differing = values
            .iter()
            .zip(&golden)
            .filter(|(a, b)| a.to_bits() != b.to_bits())
            .count();
        if differing > 0 {
            let first = values
                .iter()
                .zip(&golden)
                .position(|(a, b)| a.to_bits() != b.to_bits())
                .unwrap();
            let (x, y) = (first % size.0, first / size.0);
            problems.push(format!(
                "channel {name}: {differing} samples differ; first at pixel ({x}, {y}): now {}, golden {}",
                values[first], golden[first]
            ));
        }
    }
    for (name, _) in stored {
        problems.push(format!(
            "golden file has channel {name}, which the reference no longer produces"
        ));
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(problems.join("; "))
    }
}
