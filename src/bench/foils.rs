//! The bench's own rasterizers, kept only to be measured against: the naive
//! bounding-box floor ([`NaiveBbox`]) and the plain midpoint loop
//! ([`PlainMidpoint`]). Coverage only, 16.8 fixed point; neither is a
//! candidate the harness judges.

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{FillRule, LastPixel, LineRule, Number, Primitive, Scene};

/// What the foils take: coverage on the snapping grid, no attributes,
/// depth, polygons or effects; triangles for the naive floor only.
fn coverage_only(triangles: bool) -> Capabilities {
    Capabilities {
        triangles,
        ..Capabilities::none()
    }
}

// --- The naive floor --------------------------------------------------------

/// The floor every real rasterizer should beat: for each triangle, every
/// pixel of its bounding box is tested against the three edge functions,
/// each evaluated in full (no incremental stepping), in i64 on 16.8 fixed
/// point, with the top-left rule. Triangles only, coverage only.
#[derive(Clone, Copy, Debug, Default)]
pub struct NaiveBbox;

impl Rasterizer for NaiveBbox {
    fn name(&self) -> &str {
        "naive"
    }

    fn capabilities(&self) -> Capabilities {
        coverage_only(true)
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        if scene.rules.subpixel_bits != Some(8) || scene.rules.fill_rule != FillRule::TopLeft {
            return Err(RasterError::Unsupported(
                "only 16.8 fixed point under the top-left rule".to_owned(),
            ));
        }
        if plan.interpolates() {
            return Err(RasterError::Unsupported("coverage only".to_owned()));
        }
        let (w, h) = (scene.canvas.width as i64, scene.canvas.height as i64);
        let mut frame = Frame::new(scene.canvas.width, scene.canvas.height, false, 0);
        let fixed = |n: &Number| (n.to_f64_lossy() * 256.0).round_ties_even() as i64;
        for (index, primitive) in scene.primitives.iter().enumerate() {
            let Primitive::Triangle(t) = primitive else {
                return Err(RasterError::Unsupported("triangles only".to_owned()));
            };
            let v = t.vertices.each_ref().map(|p| [fixed(&p.x), fixed(&p.y)]);
            let area = orient(v[0], v[1], v[2]);
            if area == 0 {
                continue;
            }
            let sign = area.signum();
            let owns = [0, 1, 2].map(|i| top_left_owns(v[i], v[(i + 1) % 3], v[(i + 2) % 3]));
            let lo = |a: usize| v.iter().map(|p| p[a]).min().unwrap();
            let hi = |a: usize| v.iter().map(|p| p[a]).max().unwrap();
            // Pixel centres (k + 0.5) within [lo, hi], clamped to the canvas.
            let first = |l: i64| ((l - 128 + 255) >> 8).max(0);
            let last = |h: i64, size: i64| ((h - 128) >> 8).min(size - 1);
            for y in first(lo(1))..=last(hi(1), h) {
                for x in first(lo(0))..=last(hi(0), w) {
                    let p = [x * 256 + 128, y * 256 + 128];
                    let inside = (0..3).all(|i| {
                        let e = orient(v[i], v[(i + 1) % 3], p).signum() * sign;
                        e > 0 || (e == 0 && owns[i])
                    });
                    if inside {
                        let i = frame.index(x as u32, y as u32);
                        frame.hit(i, index);
                    }
                }
            }
        }
        Ok(frame)
    }
}

fn orient(a: [i64; 2], b: [i64; 2], p: [i64; 2]) -> i64 {
    (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
}

/// Top-left ownership of edge a→b of a triangle whose third vertex is c
/// (y down): a top edge is horizontal with the triangle below; a left edge
/// is not horizontal and has the triangle to its right.
fn top_left_owns(a: [i64; 2], b: [i64; 2], c: [i64; 2]) -> bool {
    if a[1] == b[1] {
        return c[1] > a[1];
    }
    let s = (c[0] - a[0]) * (b[1] - a[1]) - (c[1] - a[1]) * (b[0] - a[0]);
    s.signum() == (b[1] - a[1]).signum()
}

/// The plain midpoint loop a line rasterizer is first written as: 16.9
/// fixed point, the major axis stepped pixel by pixel from the endpoint
/// with the smaller major coordinate, the minor pixel from a remainder
/// updated by adding, each pixel bounds-checked and written with
/// `Frame::hit`. Midpoint lines with their last pixel, 16.8 snapping,
/// coverage only: the rule production's midpoint walk implements.
#[derive(Clone, Copy, Debug, Default)]
pub struct PlainMidpoint;

impl Rasterizer for PlainMidpoint {
    fn name(&self) -> &str {
        "midpoint-plain"
    }

    fn capabilities(&self) -> Capabilities {
        coverage_only(false)
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let unsupported = |why: &str| Err(RasterError::Unsupported(why.to_owned()));
        if scene.rules.subpixel_bits != Some(8) || plan.interpolates() {
            return unsupported("16.8 fixed point, coverage only");
        }
        let (w, h) = (scene.canvas.width as i64, scene.canvas.height as i64);
        let mut frame = Frame::new(scene.canvas.width, scene.canvas.height, false, 0);
        let fixed = |n: &Number| (n.to_f64_lossy() * 256.0).round_ties_even() as i64;
        for (index, primitive) in scene.primitives.iter().enumerate() {
            let Primitive::Line(line) = primitive else {
                return unsupported("lines only");
            };
            if line.rule != LineRule::Midpoint || line.last_pixel != LastPixel::Include {
                return unsupported("midpoint lines with their last pixel");
            }
            // 16.9 fixed point: pixel centres k·512 + 256 are integers.
            let [a, b] = line
                .vertices
                .each_ref()
                .map(|v| [2 * fixed(&v.x), 2 * fixed(&v.y)]);
            let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
            if dx == 0 && dy == 0 {
                continue;
            }
            // u: the major axis (x on a diagonal), v: the minor one.
            let (u, v) = if dx.abs() >= dy.abs() { (0, 1) } else { (1, 0) };
            let (a, b) = if b[u] < a[u] { (b, a) } else { (a, b) };
            let (du, dv) = (b[u] - a[u], b[v] - a[v]);
            // Centres within [a_u, b_u], clipped to the canvas.
            let size = if u == 0 { w } else { h };
            let first = (a[u] - 256 + 511).div_euclid(512).max(0);
            let last = (b[u] - 256).div_euclid(512).min(size - 1);
            if first > last {
                continue;
            }
            // The minor pixel at centre c is ⌈v(c)⌉ − 1 = ⌊(N − 1)/D⌋,
            // N = a_v·du + (c − a_u)·dv, D = 512·du: one division, then a
            // remainder stepped by adding.
            let den = 512 * du;
            let c = first * 512 + 256;
            let num = a[v] * du + (c - a[u]) * dv - 1;
            let (mut m, mut rest) = (num.div_euclid(den), num.rem_euclid(den));
            let minor_size = if u == 0 { h } else { w };
            for k in first..=last {
                if (0..minor_size).contains(&m) {
                    let (x, y) = if u == 0 { (k, m) } else { (m, k) };
                    let i = frame.index(x as u32, y as u32);
                    frame.hit(i, index);
                }
                rest += 512 * dv;
                if rest >= den {
                    rest -= den;
                    m += 1;
                } else if rest < 0 {
                    rest += den;
                    m -= 1;
                }
            }
        }
        Ok(frame)
    }
}
