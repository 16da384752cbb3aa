//! `foil-any-coverage`: a pixel is drawn by every triangle that touches it,
//! however little (conservative rasterization, overestimating), instead of
//! by the triangle that covers its centre. **A foil**, wrong in that one
//! way: D3D12 and Vulkan offer it as an opt-in mode
//! (`VK_EXT_conservative_rasterization`), never as the default. Pixels
//! along a shared edge are drawn by both triangles, and a sliver far from
//! every sample still draws its pixels: what `probe` must call
//! any-coverage rather than "closed edges".
//!
//! A triangle touches a pixel when their interiors meet (an area in
//! common: a triangle whose edge only runs along the pixel's border does
//! not draw it). Convex shapes' interiors are disjoint exactly when one of
//! their edge directions separates them, so the test is: the bounding boxes
//! overlap with positive width and height, and no triangle edge has the
//! whole square on its outside (each edge function, positive inside, is
//! positive at some corner of the pixel). Vertices snap to the case's grid
//! and are held as integers in units of 2^-16 px; the edge functions are
//! exact in i128. Triangles only; depth and attributes are unsupported.

use dashu_ratio::RBig;

use super::declare::coverage_foil;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{Number, Primitive, Scene};

coverage_foil!(
    /// The any-coverage foil.
    AnyCoverage,
    "foil-any-coverage",
    draw_touched
);

/// Fraction bits of the integer coordinates: the most a case can snap to.
const FRAC: u32 = 16;

/// Every pixel each triangle touches, counted once per triangle.
fn draw_touched(scene: &Scene, _plan: &Plan) -> Result<Frame, RasterError> {
    let unsupported = |why: &str| Err(RasterError::Unsupported(why.to_owned()));
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let mut frame = Frame::new(w, h, false, 0);
    for (index, primitive) in scene.primitives.iter().enumerate() {
        let Primitive::Triangle(t) = primitive else {
            return unsupported("foil-any-coverage draws triangles only");
        };
        let mut p = [[0i128; 2]; 3];
        for (q, v) in p.iter_mut().zip(&t.vertices) {
            for (c, n) in q.iter_mut().zip([&v.x, &v.y]) {
                *c = fixed(n, scene.rules.subpixel_bits).ok_or_else(|| {
                    RasterError::Unsupported(format!(
                        "foil-any-coverage holds coordinates in units of 2^-{FRAC} px; {n} is not one or is too large"
                    ))
                })?;
            }
        }
        let area = cross(p[0], p[1], p[2]);
        if area == 0 || scene.rules.cull.discards(area.cmp(&0)) {
            continue;
        }
        // Counter-clockwise in y-down terms, so that inside is positive.
        if area < 0 {
            p.swap(1, 2);
        }
        let one = 1i128 << FRAC;
        let lo = |k: usize| p.iter().map(|q| q[k]).min().unwrap_or(0);
        let hi = |k: usize| p.iter().map(|q| q[k]).max().unwrap_or(0);
        // Pixels whose open square meets the open bounding box.
        let range = |k: usize, size: u32| {
            let first = (lo(k) >> FRAC).max(0);
            let last = ((hi(k) + one - 1) >> FRAC).min(i128::from(size));
            first..last
        };
        for y in range(1, h) {
            for x in range(0, w) {
                let corners = [(0, 0), (1, 0), (0, 1), (1, 1)]
                    .map(|(dx, dy)| [(x + dx) * one, (y + dy) * one]);
                let touches =
                    (0..3).all(|e| corners.iter().any(|&c| cross(p[e], p[(e + 1) % 3], c) > 0));
                if touches {
                    let i = frame.index(x as u32, y as u32);
                    frame.coverage[i] = frame.coverage[i].saturating_add(1);
                    frame.last[i] = index as u32 + 1;
                }
            }
        }
    }
    Ok(frame)
}

/// (b − a) × (c − a): positive when c lies left of a→b in y-down terms
/// (inside a triangle wound that way). Coordinates below 2^48 units keep
/// each product below 2^98.
fn cross(a: [i128; 2], b: [i128; 2], c: [i128; 2]) -> i128 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// A coordinate snapped to the case's grid, in units of 2^-16 px; `None`
/// when it is not a multiple of that or not below 2^31 px.
fn fixed(n: &Number, bits: Option<u32>) -> Option<i128> {
    let snapped = bits.map_or_else(|| n.clone(), |b| n.snapped(b));
    let scaled = Number::from_rbig(snapped.as_rbig() * RBig::from(1u32 << FRAC));
    if !scaled.is_integer() || scaled.abs() >= Number::from_int(1 << (31 + FRAC)) {
        return None;
    }
    Some(scaled.to_f64_lossy() as i128)
}
