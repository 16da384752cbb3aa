//! Golden files: the blessed reference output of every case, as EXR.
//!
//! `reference/<case id>.exr` holds the reference's frame in the layers and
//! channels of `frame::exr` (the sample channels, and the resolved or time
//! coverage to the bit). A change to the oracle that moves any of them
//! shows up as a failing test and, once blessed, as a binary diff in
//! review. This file says where a golden file lives and compares a frame
//! with it; writing and reading the channels are `frame::exr`'s, re-exported
//! here for the harness's callers.

use std::path::{Path, PathBuf};

use crate::frame::exr::{layers, read_layers, LayerData, SAMPLES_LAYER};
use crate::frame::Frame;
use crate::metrics::counted::counted;

pub use crate::frame::exr::{read, write, Channels, Values};

/// Where a case's golden file lives: `reference/<id>.exr` under `root`.
pub fn path_for(root: &Path, case_id: &str) -> PathBuf {
    root.join("reference").join(format!("{case_id}.exr"))
}

/// Compares a freshly computed reference frame with its golden file.
/// `Ok` when every channel of every layer matches to the bit; otherwise
/// what differs.
pub fn check(frame: &Frame, path: &Path) -> Result<(), String> {
    let expected = layers(frame);
    // The largest layer a golden file of this canvas can hold, at any
    // sample count a case may ask for: a file of another sample count is
    // still read, and then said to differ in its sample count; a header
    // claiming more is refused before anything is decoded.
    let any_count = frame.width as usize
        * frame.height as usize
        * crate::scene::samples::limits::MAX_SAMPLES as usize;
    let largest = expected
        .iter()
        .map(|l| l.size.0 * l.size.1)
        .chain([any_count])
        .max()
        .unwrap_or(0);
    let mut stored = read_layers(path, largest)?;
    let mut problems = Vec::new();
    let samples = frame.samples.max(1) as usize;
    for layer in expected {
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
                "channel {name}: {}; first at pixel ({x}, {y}){sample}: now {}, golden {}",
                counted(differing as u64, "sample differs", "samples differ"),
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

/// Whether the reference still reproduces a case's golden file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum GoldenStatus {
    Matches,
    Missing(PathBuf),
    Differs(String),
}

pub fn check_golden(root: &Path, id: &str, frame: &Frame) -> GoldenStatus {
    let path = path_for(root, id);
    if !path.exists() {
        return GoldenStatus::Missing(path);
    }
    match check(frame, &path) {
        Ok(()) => GoldenStatus::Matches,
        Err(why) => GoldenStatus::Differs(why),
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
        assert_eq!(read(&path, (3, 2)).unwrap().0, (3, 2));
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
        let layers = read_layers(&path, usize::MAX).unwrap();
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
            err.contains("channel time.f64.low: 1 sample differs; first at pixel (2, 1)"),
            "{err}"
        );
        // And of pixels (2, 1) and (3, 1): counted in the plural.
        let t = changed.time.as_mut().unwrap();
        t[7] = f64::from_bits(t[7].to_bits() + 1);
        let err = check(&changed, &path).unwrap_err();
        assert!(
            err.contains("channel time.f64.low: 2 samples differ; first at pixel (2, 1)"),
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
