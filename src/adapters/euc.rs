//! `euc`: euc 0.5.3's triangle rasterizer, with its vertex and fragment
//! pipeline interpolating depth and attributes.
//!
//! Each triangle is drawn by its own `Pipeline::draw` call into a target
//! that records the fragments euc writes, in order, so coverage counts and
//! the last primitive per sample are exact, and each fragment's values are
//! the ones euc's pipeline produced.
//!
//! How a case reaches euc:
//!
//! - **Positions.** euc takes clip-space `[x, y, z, w]` and maps NDC to the
//!   framebuffer itself (x right, y up in NDC; y down on screen). The adapter
//!   snaps each vertex exactly to the case's grid (see `float_input`), then
//!   computes the exact clip position (2x/W − 1)·w, (1 − 2y/H)·w, z·w and
//!   rounds each once to f32. euc's own f32 arithmetic (dividing by w,
//!   inverting the homogeneous vertex matrix, evaluating weights at each
//!   pixel centre) decides coverage; nothing is snapped again.
//! - **Perspective** comes from euc: a `perspective` triangle gets its
//!   vertices' w, and euc's homogeneous (Olano–Greer) weights are
//!   perspective-correct. A `linear` or `flat` triangle gets w = 1, so the
//!   same weights are screen-space. `flat` values are the first vertex's,
//!   returned by the fragment shader unchanged (euc has no flat qualifier).
//! - **Depth** is euc's depth-buffer value, which is screen-space linear:
//!   with z_clip = z·w it equals Σ bᵢ zᵢ. Each triangle writes into a fresh
//!   depth target that always passes, so there is no depth test, as SPEC.md
//!   asks.
//! - **Fill rule** is euc's own: a pixel is drawn when all three weights lie
//!   in [0, 1], so samples on every edge are included (closed triangles,
//!   `all-edges`), up to f32 rounding of the weights. Meshes are therefore
//!   not watertight; the adapter does not correct that.
//! - **Culling** is applied by the adapter on the exact snapped positions;
//!   euc's own back-face culling is disabled (it would cull by its f32
//!   winding, in NDC).
//!
//! Unsupported: lines (euc's `Lines` steps a float DDA over the major axis
//! between truncated endpoints, none of SPEC.md §4's rules), and more than
//! one sample per pixel.

use dashu_ratio::RBig;
use euc::buffer::Buffer2d;
use euc::rasterizer::{BackfaceCullingDisabled, Triangles};
use euc::{DepthStrategy, Interpolate, Pipeline, Target};

use super::float_input::{culled, f32_of, single_sample, snapped_triangle, to_f32, triangles_only};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{
    owners_frame, refuse_last_provoking, Capabilities, Prepared, RasterError, Rasterizer,
};
use crate::scene::rules::limits::MAX_ATTRIBUTES;
use crate::scene::{Interpolation, Scene, Triangle};

/// euc 0.5.3's triangle rasterizer.
pub struct Euc;

/// The attributes a vertex carries into euc, padded with zeros.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Varyings([f32; MAX_ATTRIBUTES]);

impl Interpolate for Varyings {
    // The same fused arithmetic as euc's own impls for f32 and vectors.
    fn lerp2(a: Self, b: Self, x: f32, y: f32) -> Self {
        Varyings(std::array::from_fn(|i| a.0[i].mul_add(x, b.0[i] * y)))
    }

    fn lerp3(a: Self, b: Self, c: Self, x: f32, y: f32, z: f32) -> Self {
        Varyings(std::array::from_fn(|i| {
            a.0[i].mul_add(x, b.0[i].mul_add(y, c.0[i] * z))
        }))
    }
}

struct Vertex {
    clip: [f32; 4],
    values: Varyings,
}

/// One triangle's pipeline: pass-through vertex shader; the fragment shader
/// returns the interpolated values, or the provoking vertex's for `flat`.
struct TrianglePipeline {
    flat: Option<Varyings>,
}

impl Pipeline for TrianglePipeline {
    type Vertex = Vertex;
    type VsOut = Varyings;
    type Pixel = Varyings;

    fn vert(&self, vertex: &Vertex) -> ([f32; 4], Varyings) {
        (vertex.clip, vertex.values)
    }

    fn frag(&self, values: &Varyings) -> Varyings {
        self.flat.unwrap_or(*values)
    }

    fn get_depth_strategy(&self) -> DepthStrategy {
        // With a target whose every read is +∞, this writes every fragment.
        DepthStrategy::IfLessWrite
    }
}

/// A target that records euc's writes in order instead of storing pixels;
/// every read returns `background`.
struct Recorder<T> {
    size: [usize; 2],
    background: T,
    writes: Vec<([usize; 2], T)>,
}

impl<T: Clone> Recorder<T> {
    fn new(width: u32, height: u32, background: T) -> Self {
        Recorder {
            size: [width as usize, height as usize],
            background,
            writes: Vec::new(),
        }
    }
}

impl<T: Clone> Target for Recorder<T> {
    type Item = T;

    fn size(&self) -> [usize; 2] {
        self.size
    }

    unsafe fn set(&mut self, pos: [usize; 2], item: T) {
        self.writes.push((pos, item));
    }

    unsafe fn get(&self, _pos: [usize; 2]) -> T {
        self.background.clone()
    }

    fn clear(&mut self, _fill: T) {
        self.writes.clear();
    }
}

impl Rasterizer for Euc {
    fn name(&self) -> &str {
        "euc"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            triangles: true,
            ideal_geometry: true,
            attributes: true,
            depth: true,
            ..Capabilities::none()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        triangles_only(scene, "euc")?;
        single_sample(plan, "euc")?;
        refuse_last_provoking(scene, "euc")?;
        let (width, height) = (scene.canvas.width, scene.canvas.height);
        let mut frame = Frame::new(width, height, plan.depth, plan.attributes);
        let mut color = Recorder::new(width, height, Varyings::default());
        let mut depth = Recorder::new(width, height, f32::INFINITY);
        for (index, triangle, clips) in clip_triangles(scene) {
            let vertices: Vec<Vertex> = triangle
                .vertices
                .iter()
                .zip(clips)
                .map(|(v, clip)| {
                    let mut values = Varyings::default();
                    for (slot, a) in values.0.iter_mut().zip(&v.attributes) {
                        *slot = f32_of(a);
                    }
                    Vertex { clip, values }
                })
                .collect();
            let pipeline = TrianglePipeline {
                flat: (triangle.interpolation == Interpolation::Flat).then(|| vertices[0].values),
            };
            color.writes.clear();
            depth.writes.clear();
            pipeline.draw::<Triangles<'_, Recorder<f32>, BackfaceCullingDisabled>, _>(
                &vertices,
                &mut color,
                plan.depth.then_some(&mut depth),
            );
            if plan.depth && depth.writes.len() != color.writes.len() {
                return Err(RasterError::Failed(format!(
                    "euc wrote {} fragments but {} depth values for primitive {index}",
                    color.writes.len(),
                    depth.writes.len()
                )));
            }
            for (k, ([x, y], values)) in color.writes.iter().enumerate() {
                let i = frame.index(*x as u32, *y as u32);
                frame.hit(i, index);
                for (channel, value) in frame.attributes.iter_mut().zip(values.0) {
                    channel[i] = f64::from(value);
                }
                if let Some(d) = frame.depth.as_mut() {
                    let (at, z) = depth.writes[k];
                    if at != [*x, *y] {
                        return Err(RasterError::Failed(format!(
                            "euc's depth and colour writes diverge for primitive {index}"
                        )));
                    }
                    d[i] = f64::from(z);
                }
            }
        }
        Ok(frame)
    }

    /// Coverage-only scenes: every triangle in one `Pipeline::draw` call
    /// into a reused `Buffer2d` of primitive numbers, with no depth buffer.
    fn prepare<'a>(
        &'a self,
        scene: &'a Scene,
        plan: &'a Plan,
    ) -> Option<Result<Box<dyn Prepared + 'a>, RasterError>> {
        if plan.interpolates() {
            return None;
        }
        let ready = || -> Result<Box<dyn Prepared>, RasterError> {
            triangles_only(scene, "euc")?;
            single_sample(plan, "euc")?;
            let vertices = clip_triangles(scene)
                .flat_map(|(index, _, clips)| clips.map(|clip| (clip, index as u32 + 1)))
                .collect();
            let size = [scene.canvas.width as usize, scene.canvas.height as usize];
            Ok(Box::new(PreparedDraw {
                vertices,
                target: Buffer2d::new(size, 0),
            }))
        };
        Some(ready())
    }
}

/// Each drawn triangle (culled ones left out) with its vertices' clip
/// positions: snapped exactly to the case's grid, mapped to NDC and scaled
/// by w, each rounded once to f32.
fn clip_triangles(scene: &Scene) -> impl Iterator<Item = (usize, &Triangle, [[f32; 4]; 3])> {
    let (w_canvas, h_canvas) = (
        RBig::from(scene.canvas.width),
        RBig::from(scene.canvas.height),
    );
    let two = RBig::from(2u8);
    scene.triangles().filter_map(move |(index, triangle)| {
        let exact = snapped_triangle(triangle, scene.rules.subpixel_bits);
        if culled(&exact, scene.rules.cull) {
            return None;
        }
        let perspective = triangle.interpolation == Interpolation::Perspective;
        let clips = std::array::from_fn(|k| {
            let (v, [x, y]) = (&triangle.vertices[k], &exact[k]);
            let w = if perspective {
                v.w.as_rbig().clone()
            } else {
                RBig::ONE
            };
            let x_ndc = &two * x / &w_canvas - RBig::ONE;
            let y_ndc = RBig::ONE - &two * y / &h_canvas;
            [
                to_f32(&(x_ndc * &w)),
                to_f32(&(y_ndc * &w)),
                to_f32(&(v.z.as_rbig() * &w)),
                to_f32(&w),
            ]
        });
        Some((index, triangle, clips))
    })
}

/// A primitive's number (index + 1), the same at its three vertices, so
/// interpolating it gives it back unchanged.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Number(u32);

impl Interpolate for Number {
    fn lerp2(a: Self, _: Self, _: f32, _: f32) -> Self {
        a
    }

    fn lerp3(a: Self, _: Self, _: Self, _: f32, _: f32, _: f32) -> Self {
        a
    }
}

/// The coverage-only pipeline: the fragment is its primitive's number.
struct NumberPipeline;

impl Pipeline for NumberPipeline {
    type Vertex = ([f32; 4], u32);
    type VsOut = Number;
    type Pixel = u32;

    fn vert(&self, vertex: &([f32; 4], u32)) -> ([f32; 4], Number) {
        (vertex.0, Number(vertex.1))
    }

    fn frag(&self, number: &Number) -> u32 {
        number.0
    }

    fn get_depth_strategy(&self) -> DepthStrategy {
        DepthStrategy::None
    }
}

/// euc's draw call with the vertices converted once and its target reused.
struct PreparedDraw {
    vertices: Vec<([f32; 4], u32)>,
    target: Buffer2d<u32>,
}

impl Prepared for PreparedDraw {
    fn clear(&mut self) -> Result<(), RasterError> {
        self.target.clear(0);
        Ok(())
    }

    fn draw(&mut self) -> Result<(), RasterError> {
        NumberPipeline.draw::<Triangles<'_, Buffer2d<f32>, BackfaceCullingDisabled>, _>(
            &self.vertices,
            &mut self.target,
            None,
        );
        Ok(())
    }

    fn read_back(&mut self) -> Result<Frame, RasterError> {
        let [width, height] = self.target.size();
        Ok(owners_frame(
            width as u32,
            height as u32,
            self.target.as_ref(),
        ))
    }
}
