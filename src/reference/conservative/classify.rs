//! The classes of every pixel of a conservative scene (SPEC.md §19), and
//! the frame the reference draws from them (its required pixels).
//!
//! Each vertex is snapped, then every coordinate, the uncertainty u and
//! the pixel boundaries are put on one integer grid (the least common
//! multiple of their denominators), and each primitive becomes its closed
//! shape T there (`outline.rs`), so each test is the sign of an integer.
//! Per primitive, pixel (x, y)'s closed square S and S grown by u on every
//! side, S_u, decide:
//!
//! - overestimate: required iff S meets T, allowed iff S_u meets T;
//! - underestimate: required iff S_u ⊆ T, allowed iff S ⊆ T;
//! - the fully-covered flag: true iff S_u ⊆ T, either iff S ⊆ T.
//!
//! Primitives combine in order (SPEC.md §19.5): a pixel is required when
//! some primitive requires it, forbidden when none may draw it; its flag is
//! the flag of its last writer, which may be any primitive that may draw
//! it after the last one that must.

use dashu_int::IBig;

use super::classes::{ConservativeClasses, PixelClass};
use super::geometry::Rect;
use super::outline::{grid_scene, GridScene, Outline};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::{Conservative, ConservativeMode, Scene};

/// Each pixel's class for a conservative scene (SPEC.md §19), or why this
/// version does not judge it.
pub fn classify(scene: &Scene) -> Result<ConservativeClasses, RasterError> {
    let Some(case) = &scene.effects.conservative else {
        return Err(RasterError::Unsupported(
            "the scene is not conservative (no effects.conservative)".to_owned(),
        ));
    };
    if let Some(why) = scene.conservative_unjudged() {
        return Err(RasterError::Unsupported(why));
    }
    Ok(classify_under(scene, case))
}

/// [`classify`] under `case`, a conservative state of the caller's (a
/// candidate's declared uncertainty, SPEC.md §19.6), whatever the scene
/// states. The scene holds triangles, points and area lines only
/// (`Scene::conservative_unjudged`).
pub fn classify_under(scene: &Scene, case: &Conservative) -> ConservativeClasses {
    let (width, height) = (scene.canvas.width, scene.canvas.height);
    let mut out = ConservativeClasses::empty(width, height, case.fully_covered);
    let GridScene { scale, u, shapes } = grid_scene(scene, case);
    // The fold of each pixel's possible last writers' flag classes.
    let mut flag: Vec<Option<PixelClass>> = vec![None; out.drawn.len()];
    for (index, shape) in &shapes {
        let Some((xs, ys)) = pixel_range(&shape.bounds(), &u, &scale, width, height) else {
            continue;
        };
        for y in ys {
            for x in xs.clone() {
                let (drawn, full) = pixel_class(case.mode, shape, x, y, &scale, &u);
                if drawn == PixelClass::Forbidden {
                    continue;
                }
                let i = y as usize * width as usize + x as usize;
                out.drawn[i] = out.drawn[i].union(drawn);
                flag[i] = match (drawn, flag[i]) {
                    (PixelClass::Required, _) | (_, None) => Some(full),
                    (_, Some(before)) if before == full => Some(full),
                    _ => Some(PixelClass::Allowed),
                };
                if drawn == PixelClass::Required {
                    out.last_required[i] = *index as u32 + 1;
                }
            }
        }
    }
    if let Some(flags) = &mut out.fully_covered {
        for (f, fold) in flags.iter_mut().zip(flag) {
            *f = fold.unwrap_or(PixelClass::Forbidden);
        }
    }
    out
}

/// One primitive's classes at pixel (x, y): whether it draws it, and its
/// fragment's fully-covered flag there.
pub(super) fn pixel_class(
    mode: ConservativeMode,
    t: &Outline,
    x: u32,
    y: u32,
    scale: &IBig,
    u: &IBig,
) -> (PixelClass, PixelClass) {
    let x0 = IBig::from(x) * scale;
    let y0 = IBig::from(y) * scale;
    let square = Rect {
        x1: &x0 + scale,
        y1: &y0 + scale,
        x0: x0.clone(),
        y0: y0.clone(),
    };
    let grown = Rect {
        x0: &square.x0 - u,
        y0: &square.y0 - u,
        x1: &square.x1 + u,
        y1: &square.y1 + u,
    };
    let full = if t.holds(&grown) {
        PixelClass::Required
    } else if t.holds(&square) {
        PixelClass::Allowed
    } else {
        PixelClass::Forbidden
    };
    let drawn = match mode {
        ConservativeMode::Overestimate => {
            if t.meets(&square) {
                PixelClass::Required
            } else if t.meets(&grown) {
                PixelClass::Allowed
            } else {
                PixelClass::Forbidden
            }
        }
        ConservativeMode::Underestimate => full,
    };
    (drawn, full)
}

/// The pixels whose grown square may meet a shape of box `bounds`: the
/// box grown by u and one pixel, within the canvas; `None` when that is
/// empty.
pub(super) fn pixel_range(
    bounds: &[IBig; 4],
    u: &IBig,
    scale: &IBig,
    width: u32,
    height: u32,
) -> Option<(std::ops::Range<u32>, std::ops::Range<u32>)> {
    let axis = |k: usize, size: u32| -> Option<std::ops::Range<u32>> {
        let lo = &bounds[k] - u;
        let hi = &bounds[k + 2] + u;
        let first = floor_div(&lo, scale) - IBig::ONE;
        let last = floor_div(&hi, scale) + IBig::ONE;
        let first = first.max(IBig::ZERO);
        let last = last.min(IBig::from(size) - IBig::ONE);
        if first > last {
            return None;
        }
        let first: u32 = u32::try_from(&first).ok()?;
        let last: u32 = u32::try_from(&last).ok()?;
        Some(first..last + 1)
    };
    Some((axis(0, width)?, axis(1, height)?))
}

fn floor_div(a: &IBig, b: &IBig) -> IBig {
    crate::reference::exact::floor_div(a, b)
}

/// The reference's own frame of a conservative scene: its required pixels
/// drawn, each by the last primitive required there.
pub fn render(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    let classes = classify(scene)?;
    Ok(frame_of(scene, plan, &classes))
}

/// The frame of `classes`: every required pixel drawn once (all its
/// samples, multisampled), by the last primitive required there, its flag true where it must be (a frame that
/// passes).
pub fn frame_of(scene: &Scene, plan: &Plan, classes: &ConservativeClasses) -> Frame {
    let mut frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, plan);
    // Multisampled (SPEC.md §19.10): every sample of a drawn pixel.
    let samples = frame.samples.max(1) as usize;
    for (i, class) in classes.drawn.iter().enumerate() {
        if *class == PixelClass::Required {
            let last = classes.last_required[i].max(1) - 1;
            for slot in i * samples..(i + 1) * samples {
                frame.hit(slot, last as usize);
            }
        }
    }
    if frame.resolved.is_some() {
        frame.resolved = Some(frame.box_resolve());
    }
    frame.fully_covered = classes.fully_covered.as_ref().map(|flags| {
        flags
            .iter()
            .zip(&classes.drawn)
            .map(|(f, d)| *f == PixelClass::Required && *d == PixelClass::Required)
            .collect()
    });
    frame
}
