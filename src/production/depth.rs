//! Depth formats and polygon offset (SPEC.md §18), as a GPU computes them:
//! the offset in f64 from the triangle's snapped plane, with m the cheap
//! max(|∂z/∂x|, |∂z/∂y|) and r the format's smallest (2^-n for unorm n,
//! 2^(e−23) for float32), then the depth clamped to [0, 1] and stored in
//! the format (unorm: the nearest k/(2^n − 1), ties up).
//!
//! Independent of the reference: the plane is set up in f64 from the
//! snapped vertices (exact differences of 8.8 fixed-point coordinates and
//! f64 depths), and every step's rounding error is far inside §6.3's
//! tolerance, which the reference's allowed set includes.

use crate::frame::Frame;
use crate::scene::depth::{unorm_value, DepthBias, DepthFormat};
use crate::scene::{Number, Primitive, Scene};

/// The offset o of a triangle whose depth plane has gradient (gx, gy) and
/// whose largest |depth| at a vertex is `largest` (SPEC.md §18.2).
pub fn offset(bias: &DepthBias, format: DepthFormat, [gx, gy]: [f64; 2], largest: f64) -> f64 {
    let m = gx.abs().max(gy.abs());
    let r = match format.unorm_bits() {
        Some(n) => 2f64.powi(-(n as i32)),
        None => {
            // The exponent of the largest |depth|, as f32 keeps it.
            let e = if largest == 0.0 {
                -126
            } else {
                (largest.log2().floor() as i32).max(-126)
            };
            2f64.powi(e - 23)
        }
    };
    let o = m * bias.slope.to_f64_lossy() + r * bias.constant.to_f64_lossy();
    let clamp = bias.clamp.to_f64_lossy();
    if clamp > 0.0 {
        o.min(clamp)
    } else if clamp < 0.0 {
        o.max(clamp)
    } else {
        o
    }
}

/// The gradient of the plane through three screen points (x, y, z).
pub fn gradient(v: [[f64; 3]; 3]) -> [f64; 2] {
    let d = |i: usize, k: usize| v[i][k] - v[0][k];
    let det = d(1, 0) * d(2, 1) - d(2, 0) * d(1, 1);
    if det == 0.0 {
        return [0.0, 0.0];
    }
    [
        (d(1, 2) * d(2, 1) - d(2, 2) * d(1, 1)) / det,
        (d(1, 0) * d(2, 2) - d(2, 0) * d(1, 2)) / det,
    ]
}

/// A depth as the format stores it: clamped to [0, 1], then the nearest
/// grid value (unorm) or the nearest f32.
pub fn stored(format: DepthFormat, z: f64) -> f64 {
    let z = z.clamp(0.0, 1.0);
    match format.unorm_bits() {
        Some(bits) => {
            let n = f64::from((1u32 << bits) - 1);
            f64::from(unorm_value((z * n + 0.5).floor() as u32, bits))
        }
        None => f64::from(z as f32),
    }
}

/// Applies the scene's depth rules to a screen-space frame drawn without
/// them: each triangle's offset at the samples it owns last, then the
/// format. Nothing for `exact` depth.
pub fn apply(scene: &Scene, frame: &mut Frame) {
    let format = scene.rules.depth_format;
    if format == DepthFormat::Exact {
        return;
    }
    let offsets: Vec<f64> = scene
        .primitives
        .iter()
        .map(|p| match (p, &scene.rules.depth_bias) {
            (Primitive::Triangle(t), Some(bias)) => {
                let snap = |n: &Number| match scene.rules.subpixel_bits {
                    Some(bits) => n.snapped(bits).to_f64_lossy(),
                    None => n.to_f64_lossy(),
                };
                let v = t
                    .vertices
                    .each_ref()
                    .map(|v| [snap(&v.x), snap(&v.y), v.z.to_f64_lossy()]);
                let largest = v.iter().map(|p| p[2].abs()).fold(0.0, f64::max);
                offset(bias, format, gradient(v), largest)
            }
            _ => 0.0,
        })
        .collect();
    if let Some(depth) = frame.depth.as_mut() {
        for (z, &last) in depth.iter_mut().zip(&frame.last) {
            if last > 0 {
                *z += offsets[last as usize - 1];
            }
        }
    }
    store_all(format, frame);
}

/// Stores every covered sample's depth in `format` (SPEC.md §18.1).
pub fn store_all(format: DepthFormat, frame: &mut Frame) {
    if format == DepthFormat::Exact {
        return;
    }
    let Some(depth) = frame.depth.as_mut() else {
        return;
    };
    for (z, &last) in depth.iter_mut().zip(&frame.last) {
        if last > 0 {
            *z = stored(format, *z);
        }
    }
}
