//! An answer given as an EXR file (SPEC.md §12.2): its path in the
//! answer line, its channels those of a golden file (`frame::exr`), read
//! into a frame and checked against the canvas and the primitives.

use std::path::Path;

use crate::frame::{exr, Frame};
use crate::plan::Plan;
use crate::scene::Scene;

/// Reads a frame from an EXR file with the channels of a golden file
/// (`frame::exr`).
pub fn frame_from_exr(path: &Path, scene: &Scene, plan: &Plan) -> Result<Frame, String> {
    let (width, height) = (scene.canvas.width, scene.canvas.height);
    let ((w, h), mut channels) = exr::read(path, (width as usize, height as usize))?;
    if (w, h) != (width as usize, height as usize) {
        return Err(format!(
            "{}: the image is {w}×{h}; the canvas is {width}×{height}",
            path.display()
        ));
    }
    let mut take = |name: &str| {
        channels
            .iter()
            .position(|(n, _)| n == name)
            .map(|at| channels.swap_remove(at).1)
            .ok_or_else(|| format!("{}: no channel {name}", path.display()))
    };
    let coverage = take("coverage")?;
    let primitive = take("primitive")?;
    let mut frame = Frame::new(width, height, plan.depth, plan.attributes);
    let count = scene.primitives.len() as f32;
    for (i, (&c, &p)) in coverage.iter().zip(&primitive).enumerate() {
        let (x, y) = (i % w, i / w);
        if !(c.fract() == 0.0 && (0.0..=f32::from(u16::MAX)).contains(&c)) {
            return Err(format!("coverage at pixel ({x}, {y}) is {c}, not a count"));
        }
        if !(p.fract() == 0.0 && (0.0..=count).contains(&p)) || (p == 0.0) != (c == 0.0) {
            return Err(format!(
                "primitive at pixel ({x}, {y}) is {p} with coverage {c}: it must be index + 1 \
                 of a primitive where coverage > 0, and 0 where coverage is 0"
            ));
        }
        frame.coverage[i] = c as u16;
        frame.last[i] = p as u32;
    }
    if let Some(depth) = &mut frame.depth {
        *depth = take("depth")?.into_iter().map(f64::from).collect();
    }
    for k in 0..plan.attributes {
        frame.attributes[k] = take(&format!("attribute.{k}"))?
            .into_iter()
            .map(f64::from)
            .collect();
    }
    Ok(frame)
}
