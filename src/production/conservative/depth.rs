//! The depth production writes at a conservatively drawn pixel (SPEC.md
//! §19.9), as a GPU does: the triangle's depth plane, set up in f64 from
//! its placed vertices, evaluated at the pixel's centre (extrapolated
//! where the centre lies outside the triangle), plus the triangle's
//! polygon offset, then clamped to [0, 1] and stored in the case's format
//! (`production/depth.rs`); `exact` depth is written as computed. A
//! triangle of no area drawn has its provoking vertex's depth and no
//! offset.

use crate::production::depth::{gradient, offset, stored};
use crate::scene::depth::DepthFormat;
use crate::scene::rules::ProvokingVertex;
use crate::scene::{Primitive, Scene};

/// One triangle's depth over the screen.
#[derive(Clone, Copy, Debug)]
pub(crate) struct DepthPlane {
    /// The placed vertices, in units of 1/`one` px, and their depths.
    v: [[i128; 2]; 3],
    z: [f64; 3],
    one: i128,
    /// Twice the signed area, in units²: 0 for a triangle of no area
    /// (then `z[0]` is its provoking vertex's depth).
    area: i128,
    offset: f64,
    format: DepthFormat,
}

/// (b − a) × (p − a), exact.
fn orient(a: [i128; 2], b: [i128; 2], p: [i128; 2]) -> i128 {
    (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
}

impl DepthPlane {
    /// Primitive `index` of `scene` on its placed vertices `v` (units of
    /// 1/`one` px, `one` even), or `None` when it is not a triangle.
    pub(crate) fn new(scene: &Scene, index: usize, v: [[i128; 2]; 3], one: i128) -> Option<Self> {
        let Primitive::Triangle(t) = &scene.primitives[index] else {
            return None;
        };
        let mut z = t.vertices.each_ref().map(|v| v.z.to_f64_lossy());
        let area = orient(v[0], v[1], v[2]);
        let format = scene.rules.depth_format;
        if area == 0 {
            if scene.rules.provoking_vertex == ProvokingVertex::Last {
                z[0] = z[2];
            }
            return Some(DepthPlane {
                v,
                z,
                one,
                area,
                offset: 0.0,
                format,
            });
        }
        let bias = scene
            .rules
            .depth_bias
            .as_ref()
            .filter(|_| scene.offset_applies(index));
        let offset = bias.map_or(0.0, |bias| {
            let unit = one as f64;
            let p = [0, 1, 2].map(|k| [v[k][0] as f64 / unit, v[k][1] as f64 / unit, z[k]]);
            let largest = z.iter().map(|q| q.abs()).fold(0.0, f64::max);
            offset(bias, format, gradient(p), largest)
        });
        Some(DepthPlane {
            v,
            z,
            one,
            area,
            offset,
            format,
        })
    }

    /// The depth at pixel (x, y)'s centre before the format: the
    /// barycentric weights of the centre, exact integer areas divided in
    /// f64 (outside the triangle some are negative: extrapolation), plus
    /// the offset.
    pub(crate) fn unclamped(&self, x: i64, y: i64) -> f64 {
        if self.area == 0 {
            return self.z[0];
        }
        let half = self.one / 2;
        let c = [
            i128::from(x) * self.one + half,
            i128::from(y) * self.one + half,
        ];
        let v = self.v;
        let area = self.area as f64;
        let b = [
            orient(v[1], v[2], c) as f64 / area,
            orient(v[2], v[0], c) as f64 / area,
            orient(v[0], v[1], c) as f64 / area,
        ];
        b[0] * self.z[0] + b[1] * self.z[1] + b[2] * self.z[2] + self.offset
    }

    /// The depth stored at pixel (x, y): [`DepthPlane::unclamped`], then
    /// the format's clamp to [0, 1] and its grid.
    pub(crate) fn at(&self, x: i64, y: i64) -> f64 {
        match self.format {
            DepthFormat::Exact => self.unclamped(x, y),
            format => stored(format, self.unclamped(x, y)),
        }
    }
}
