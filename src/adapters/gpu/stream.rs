//! A scene as the GPU adapters upload it: one vertex stream of every
//! primitive in scene order, cut into runs that each need one pipeline
//! state (a draw call).
//!
//! - A triangle is three vertices; consecutive triangles of one
//!   interpolation mode share a run.
//! - A line is two vertices; consecutive lines of one rule, width and
//!   interpolation share a run.
//! - A point is one vertex; consecutive points of one size share a run.
//! - A polygon is drawn by **stencil then cover**, as GPU vector renderers
//!   draw paths: a [`Draw::Stencil`] run of fan triangles (each contour's
//!   first vertex joined to each of its edges) that counts every sample's
//!   winding number in the stencil buffer, then a [`Draw::Cover`] run of
//!   two triangles over the polygon's box, one pixel wider on every side,
//!   that writes the polygon where the stencil says the fill rule fills
//!   and clears the stencil behind it.
//!
//! Why the fan is exact. Every fan triangle adds its orientation's sign to
//! the winding of the samples it covers, so a sample's sum is its winding
//! number. A sample on an inner fan edge lies on the edge of two fan
//! triangles: on opposite sides of it, the driver's tie rule gives it to
//! exactly one; on the same side, the two have opposite orientations and
//! the rule gives it to both or to neither, which adds 0. A sample on an
//! outer edge is decided by the driver's tie rule, which is SPEC §14.1's
//! nudge when the rule is top-left. So the stencil holds each sample's
//! winding number (modulo 256) under the driver's own rule.
//!
//! Positions are the snapped vertices, exact, rounded once to f32 in the
//! viewport's normalised coordinates. A shifted pass (`passes.rs`) moves
//! the scene by a shift that brings a sample slot's offset onto the pixel
//! centre; it moves the driver's **viewport** by that shift, not the
//! vertices: the stream's positions are the shifted vertex relative to the
//! shifted viewport corner, `(x + s) − (x0 + s)`, the same for every pass,
//! and [`Stream::viewport_corner`] is where the adapter must put the viewport's
//! corner, `x0 + s`. So a driver that clips at its viewport clips every
//! pass at the one rectangle `view` is in the case's coordinates, the
//! rectangle `Rasterizer::screen_viewport` reports (SPEC.md §16.9), and
//! the driver's viewport transform adds the shift back: `x_w = ndc·V/2 +
//! (x0 + s + V/2)`, exact in f32 for the viewports `view.rs` chooses.

use dashu_ratio::RBig;

use super::super::float_input::{f32_of, snapped, to_f32};
use super::channels::MAX_ATTRIBUTES;
use super::view::View;
use crate::scene::{Interpolation, LineRule, Polygon, PolygonFill, Primitive, Scene, Vertex};

/// Floats per vertex: clip position (4), `[primitive + 1, depth, lo, hi]`
/// (4), attributes (16). The depth channel is the `depth` float
/// (screen space, lo > hi), or the driver's own fragment depth clamped to
/// [lo, hi] (clip space, lo ≤ hi: the viewport's depth range; see
/// [`SCREEN_DEPTH`]).
pub(crate) const VERTEX_FLOATS: usize = 8 + MAX_ATTRIBUTES;

/// `[lo, hi]` of a screen-space vertex: lo > hi says "the depth channel is
/// the `depth` varying, not the fragment's depth" (the shaders' test).
pub(crate) const SCREEN_DEPTH: [f32; 2] = [1.0, 0.0];

/// The pipeline state a run of vertices is drawn with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Draw {
    /// Triangles whose attributes are interpolated as the mode says.
    Triangles(Interpolation),
    /// Lines of one rule and width.
    Lines {
        rule: LineRule,
        width: f32,
        interpolation: Interpolation,
    },
    /// Points of one size (in pixels), their squares drawn by the driver
    /// (`PointSize`, `gl_PointSize`).
    Points { size: f32 },
    /// A polygon's fan triangles, counted into the stencil buffer only.
    Stencil(PolygonFill),
    /// Two triangles over a stencilled polygon's box, drawn where the
    /// stencil fills under the rule, and clearing the stencil.
    Cover(PolygonFill),
}

/// Consecutive vertices `first..end` drawn with one pipeline state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Run {
    pub draw: Draw,
    pub first: u32,
    pub end: u32,
}

/// Every primitive's vertices, `VERTEX_FLOATS` floats each, and its runs.
pub(crate) struct Stream {
    pub vertices: Vec<f32>,
    pub runs: Vec<Run>,
    /// Where the driver's viewport corner must be for a screen-space
    /// stream, in the target's pixels (x right, y down): the placement's
    /// view's corner moved by its shift, `x0 + s`, exact in f32 (the
    /// module's notes). A clip-space scene's viewport is its own.
    pub viewport_corner: [f32; 2],
    /// A clip-space scene's depth range `[lo, hi]` (SPEC.md §16.1): its
    /// vertices are its clip coordinates, placed by the driver's viewport
    /// (the adapter sets it from `Scene::viewport`), and the placement's
    /// snapping, shift and instant do not apply.
    clip_depth: Option<[f32; 2]>,
    /// A screen-space scene drawn into a depth attachment (`depth.rs`):
    /// the position's z is the case's `z` (w = 1: z_ndc is the depth the
    /// driver interpolates, offsets and stores), not the constant ½.
    screen_z: bool,
}

/// How a stream places the scene on the target.
pub(crate) struct Placement {
    /// The case's subpixel bits: each position is snapped to them.
    pub bits: u32,
    /// The viewport, in the target's pixels: positions map to clip space
    /// over it (`view.rs`).
    pub view: View,
    /// Added to every snapped position, in pixels (exact).
    pub shift: [RBig; 2],
    /// The instant τ ∈ [0, 1] a moving vertex is placed at:
    /// (1 − τ)·snap(from) + τ·snap(to), exactly (SPEC.md §15.1), before
    /// the one rounding to f32. Static vertices ignore it.
    pub time: RBig,
}

impl Placement {
    /// No shift: pixel centres sample the scene.
    pub(crate) fn at_centres(bits: u32, view: View) -> Placement {
        Placement {
            bits,
            view,
            shift: [RBig::ZERO, RBig::ZERO],
            time: RBig::ZERO,
        }
    }
}

impl Placement {
    /// A vertex's position in pixels, exact: snapped, at the instant if it
    /// moves, shifted.
    fn pixels(&self, v: &Vertex) -> [RBig; 2] {
        let from = [&v.x, &v.y].map(|c| snapped(c, Some(self.bits)));
        let at = match v.to.as_deref() {
            Some(to) if v.moves() => {
                let to = to.each_ref().map(|c| snapped(c, Some(self.bits)));
                let [a, b] = from;
                let [c, d] = to;
                let rest = RBig::ONE - &self.time;
                [&rest * a + &self.time * c, &rest * b + &self.time * d]
            }
            _ => from,
        };
        let [x, y] = at;
        [x + &self.shift[0], y + &self.shift[1]]
    }

    /// The viewport's corner, moved by the shift, exact: `x0 + s`.
    fn viewport_corner(&self) -> [RBig; 2] {
        let [x0, y0] = self.view.origin.map(RBig::from);
        [x0 + &self.shift[0], y0 + &self.shift[1]]
    }
}

impl Stream {
    /// The scene's primitives in scene order, placed.
    pub(crate) fn new(scene: &Scene, place: &Placement) -> Stream {
        let mut stream = Stream {
            vertices: Vec::with_capacity(scene.primitives.len() * 3 * VERTEX_FLOATS),
            runs: Vec::new(),
            viewport_corner: place.viewport_corner().each_ref().map(to_f32),
            clip_depth: scene.viewport.as_ref().map(|v| {
                let [a, b] = [&v.min_depth, &v.max_depth].map(f32_of);
                [a.min(b), a.max(b)]
            }),
            screen_z: scene.depth_rules_need_attachment(),
        };
        for (i, primitive) in scene.primitives.iter().enumerate() {
            let id = (i + 1) as f32;
            match primitive {
                Primitive::Triangle(t) => {
                    for v in &t.vertices {
                        stream.vertex(v, id, place);
                    }
                    stream.close(Draw::Triangles(t.interpolation), 3);
                }
                Primitive::Line(l) => {
                    for v in &l.vertices {
                        stream.vertex(v, id, place);
                    }
                    let draw = Draw::Lines {
                        rule: l.rule,
                        width: f32_of(&l.width),
                        interpolation: l.interpolation,
                    };
                    stream.close(draw, 2);
                }
                Primitive::Polygon(p) => stream.polygon(p, id, place),
                Primitive::Point(p) => {
                    stream.vertex(&p.vertices[0], id, place);
                    stream.close(
                        Draw::Points {
                            size: f32_of(&p.size),
                        },
                        1,
                    );
                }
            }
        }
        stream
    }

    /// Appends one vertex: position, `[id, depth, lo, hi]`, attributes.
    ///
    /// A clip-space vertex (SPEC.md §16.1) is the case's clip coordinates
    /// unchanged but for y, negated (exact): the stream's clip space is
    /// y up, as GL's is and as wgpu's is before naga's SPIR-V flips it
    /// back, so that the driver sees the case's y (Vulkan's y down). Its
    /// depth channel is the driver's fragment depth, clamped to the
    /// viewport's depth range (what `depth: clamp` asks for; under
    /// `depth: clip` it only trims the driver's rounding past the range).
    fn vertex(&mut self, v: &Vertex, id: f32, place: &Placement) {
        if let Some([lo, hi]) = self.clip_depth {
            let [x, y, z, w] = [&v.x, &v.y, &v.z, &v.w].map(f32_of);
            self.vertices.extend([x, -y, z, w]);
            self.vertices.extend([id, 0.0, lo, hi]);
        } else {
            let [x, y] = self.position(v, place);
            let w = f32_of(&v.w);
            let z = if self.screen_z { f32_of(&v.z) } else { 0.5 };
            self.vertices.extend([x * w, y * w, z * w, w]);
            self.vertices
                .extend([id, f32_of(&v.z), SCREEN_DEPTH[0], SCREEN_DEPTH[1]]);
        }
        let mut attributes = [0f32; MAX_ATTRIBUTES];
        for (slot, a) in attributes.iter_mut().zip(&v.attributes) {
            *slot = f32_of(a);
        }
        self.vertices.extend(attributes);
    }

    /// A snapped, shifted position (at the placement's instant, if the
    /// vertex moves) in normalised device coordinates over the viewport
    /// `(x0 + s, y0 + s, P, Q)`, moved by the same shift:
    /// `(x − x0) · 2/P − 1`, `1 − (y − y0) · 2/Q` (y down on screen), the
    /// difference exact before the one rounding; exact in f32 for the
    /// viewports `view.rs` chooses.
    fn position(&self, v: &Vertex, place: &Placement) -> [f32; 2] {
        let [x0, y0] = place.viewport_corner();
        let [x, y] = place.pixels(v);
        let [x, y] = [x - x0, y - y0].map(|c| to_f32(&c));
        let (sx, sy) = (
            2.0 / place.view.size.0 as f32,
            2.0 / place.view.size.1 as f32,
        );
        [x * sx - 1.0, 1.0 - y * sy]
    }

    /// Appends a bare vertex at a position in pixels (a cover's corner,
    /// an integer as is the view's unshifted corner: the difference is
    /// exact). Drawn through the shifted viewport it lands the shift
    /// (under half a pixel) away, inside the pixel of margin the cover
    /// keeps around the polygon.
    fn corner(&mut self, x: f32, y: f32, id: f32, place: &Placement) {
        let [x0, y0] = place.view.origin.map(|c| c as f32);
        let (sx, sy) = (
            2.0 / place.view.size.0 as f32,
            2.0 / place.view.size.1 as f32,
        );
        let (x, y) = (x - x0, y - y0);
        self.vertices.extend([x * sx - 1.0, 1.0 - y * sy, 0.5, 1.0]);
        self.vertices
            .extend([id, 0.0, SCREEN_DEPTH[0], SCREEN_DEPTH[1]]);
        self.vertices.extend([0f32; MAX_ATTRIBUTES]);
    }

    /// A polygon's fan into the stencil, then its cover.
    fn polygon(&mut self, p: &Polygon, id: f32, place: &Placement) {
        let mut fan = 0;
        for contour in p.contours() {
            for pair in contour[1..].windows(2) {
                for v in [&contour[0], &pair[0], &pair[1]] {
                    self.vertex(v, id, place);
                }
                fan += 3;
            }
        }
        if fan > 0 {
            self.close(Draw::Stencil(p.fill), fan);
        }
        // The box of the snapped vertices, a pixel wider on every side, so
        // that no sample the polygon covers lies on the cover's border.
        let (mut lo, mut hi) = ([f32::INFINITY; 2], [f32::NEG_INFINITY; 2]);
        for v in &p.vertices {
            for (axis, c) in place.pixels(v).into_iter().enumerate() {
                let c = to_f32(&c);
                lo[axis] = lo[axis].min(c.floor() - 1.0);
                hi[axis] = hi[axis].max(c.ceil() + 1.0);
            }
        }
        let corners = [
            (lo[0], lo[1]),
            (hi[0], lo[1]),
            (lo[0], hi[1]),
            (hi[0], lo[1]),
            (hi[0], hi[1]),
            (lo[0], hi[1]),
        ];
        for (x, y) in corners {
            self.corner(x, y, id, place);
        }
        self.close(Draw::Cover(p.fill), 6);
    }

    /// Ends a primitive of `n` vertices drawn as `draw`: joins the last
    /// run when it has the same state (covers never join: each clears the
    /// stencil its own fan set), or starts a run.
    fn close(&mut self, draw: Draw, n: u32) {
        let end = (self.vertices.len() / VERTEX_FLOATS) as u32;
        let joins = !matches!(draw, Draw::Stencil(_) | Draw::Cover(_));
        match self.runs.last_mut() {
            Some(run) if joins && run.draw == draw => run.end = end,
            _ => self.runs.push(Run {
                draw,
                first: end - n,
                end,
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_ndc_mapping_is_exact_for_snapped_coordinates() {
        // x · 2/P − 1 and back, for 8-bit coordinates across the whole range.
        for p in [1u32, 8, 1024, 16384] {
            let s = 2.0 / p as f32;
            for x in [
                -32768.0f32,
                -32768.0 + 1.0 / 256.0,
                -0.00390625,
                0.5,
                1023.5,
                32768.0 - 1.0 / 256.0,
            ] {
                let ndc = x * s - 1.0;
                assert_eq!(f64::from(ndc), f64::from(x) * 2.0 / f64::from(p) - 1.0);
                assert_eq!((ndc + 1.0) * (p as f32 / 2.0), x);
            }
        }
    }
}
