//! `gl` and `softpipe`: Mesa's OpenGL rasterizers on the CPU (llvmpipe, or
//! softpipe with `GALLIUM_DRIVER=softpipe`), driven through EGL on the
//! surfaceless platform with glow (cargo feature `gl`; system packages
//! `libegl1 libegl-mesa0 libgl1-mesa-dri`).
//!
//! # What is drawn, and how it is read back
//!
//! The structure is the `lavapipe` adapter's. A case's primitives
//! (triangles, `diamond-exit` and `rectangle` lines, polygons) are drawn
//! in scene order, with no depth test unless the case needs a depth
//! attachment (below), into the float colour attachments of one
//! framebuffer object, and read back into a [`Frame`]:
//!
//! - **count** (`R32F`, additive blending `1 + dst`, enabled on this draw
//!   buffer only): how many primitives cover each sample;
//! - **channel groups** (`RGBA32F`, no blending, so the last primitive in
//!   submission order wins, as GL's primitive order guarantees): the channels
//!   `[primitive + 1, depth, attribute 0, …, attribute 15]` four at a time, as
//!   many attachments as the plan needs (at most five; GL 3.3 has at least
//!   eight draw buffers).
//!
//! The primitive index (+ 1, exact in f32 up to 2^24) is a `flat` varying and
//! doubles as the coverage marker of the last writer. Depth is the case's `z`
//! as a `noperspective` varying, not the depth buffer (in clip space the
//! driver's `gl_FragCoord.z`, clamped: `clip.rs`), unless the case gives a
//! depth format or a polygon offset (SPEC.md §18): then it is drawn into a
//! real depth attachment of that format (`depth.rs`: `GL_DEPTH_COMPONENT16`,
//! `24` or `32F`, the test always passing with writes on, so the last
//! primitive keeps its depth; `glPolygonOffset(Clamp)` on fill only; in
//! screen space the case's z as the position's z under `GL_ZERO_TO_ONE`
//! and `GL_DEPTH_CLAMP`), and a covered sample's depth is the stored value
//! read back as integers (unorm) or float bits (float32), never through a
//! float conversion. Attributes are
//! varyings with the case's interpolation: `smooth` (perspective),
//! `noperspective` (linear) or `flat`. GL's default provoking vertex is the
//! last; the adapter sets `glProvokingVertex` (core since GL 3.2) to the
//! case's rule (first unless it says `last`) before each scene's draws, for
//! triangles and lines alike. Clip-space scenes (SPEC.md §16): `clip.rs`.
//! Consecutive triangles of one interpolation mode share one draw call, as
//! do consecutive lines of one rule, width and mode (`gpu::Stream`).
//!
//! A polygon is drawn by **stencil then cover** (`drawing.rs`): its fan
//! counts each sample's winding number into an 8-bit stencil buffer
//! (`DEPTH24_STENCIL8`, cleared with the targets), colour writes off,
//! nonzero by `GL_INCR_WRAP` on front faces and `GL_DECR_WRAP` on back
//! faces, even-odd by `GL_INVERT`; then two triangles over its box write
//! it where the stencil says its fill rule fills and set the stencil back
//! to 0. Neither run is culled. `gpu::Stream`'s notes say why the fan is
//! exact under the driver's tie rule; a polygon's samples carry z = 0 and
//! no attributes, as the reference's do.
//!
//! # Positions: exact to the 8-bit grid
//!
//! As in `lavapipe`: coordinates are snapped to the case's `subpixel_bits`
//! (ties to even) and rounded to f32 (exact for b ≤ 8); each pass is drawn
//! in a tile of `P × Q` texels of the attachments (one tile without
//! antialiasing), P and Q the powers of two at or above the canvas size;
//! the viewport is the whole tile (an integer offset in the framebuffer,
//! which keeps the transform exact), and
//!
//! ```text
//! x_ndc = x · 2/P − 1,   y_ndc = 1 − y · 2/Q      (y down on screen)
//! clip  = (x_ndc · w, y_ndc · w, w / 2, w)
//! ```
//!
//! GL's window y points up, so a screen row y lands on window row Q − 1 − y:
//! the canvas is the top `W × H` of the tile (its window rows Q − H … Q − 1),
//! the scissor and `glReadPixels` take that rectangle, and its rows, which
//! come back bottom-up, are flipped. The viewport transform back is exact for
//! snapped coordinates, as in `lavapipe`; llvmpipe then snaps to its own 8
//! subpixel bits, so cases with b > 8 are snapped twice and cases with
//! `subpixel_bits: null` are unsupported.
//!
//! # Rules
//!
//! - **Fill rule**: the driver's own, not the case's. Mesa's GL draws into an
//!   FBO with gallium's y-down memory order equal to GL's window y, so its
//!   top-left rule reads, in the case's y-down terms, as **bottom-left**
//!   (left and bottom edges include their samples); softpipe's reads as
//!   bottom-right. A case under another rule reports the departures.
//! - **Culling**: GL reads the winding in window coordinates (y up); the
//!   case's is on screen (y down), and the read-back flip makes the two the
//!   same picture, so the winding seen is the same: (0,0), (1,0), (0,1) is
//!   clockwise in both. With `glFrontFace(GL_CCW)`, `cull: cw` culls
//!   `GL_BACK` and `cull: ccw` culls `GL_FRONT`. w > 0 keeps the winding.
//! - **Lines** (`lines.rs`): `diamond-exit` is `GL_LINES` at width 1, GL's
//!   aliased line (GL 4.6 §14.5.1), drawn under GL's own tie convention
//!   (endpoints perturbed by −(ε, ε²) in y-up window coordinates, which
//!   reads, y down, as left and down), not D3D11's: a case at a tie
//!   reports the departures, as with the fill rule. llvmpipe interpolates
//!   a line's attributes along its major axis, not by GL's projection.
//!   `rectangle` is GL's multisample line (§14.5.4), which llvmpipe draws
//!   only into a multisampled target: below. `parallelogram` and
//!   `midpoint` are unsupported, each with its reason.
//! - **Polygons**: the winding under the driver's tie rule (bottom-left),
//!   counted in the stencil; the case's fill rule is not faked either.
//!
//! # Antialiasing: shifted passes, or the driver's MSAA where it is the case's
//!
//! An antialiased scene is drawn as one single-sample pass per sample slot
//! (`passes.rs`, with `gpu::shifts`): pass s draws the scene moved by the
//! exact shift that brings slot s's offset onto the pixel centre, so its
//! pixel (x, y) is slot s of pixel (x, y), with depth and attributes
//! interpolated there; it is read into slot s (`p · N + s`) and the frame
//! is box resolved ([`Frame::resolve`]). Any pattern is drawn so, as long
//! as every offset lies on llvmpipe's 1/256 grid and the case's vertices
//! do too (`subpixel_bits` ≤ 8): otherwise the shift would not commute
//! with the driver's snapping, and the case is unsupported with that
//! reason. The passes are tiles of one framebuffer, cleared, drawn and
//! read back together. Such verdicts judge the driver's single-sample
//! rasterizer at the pattern's positions.
//!
//! The driver's own multisampling (`samples.rs`, `msaa.rs`) is used where
//! it draws the case's pattern exactly: when the positions it reports for
//! one of its sample counts (`glGetMultisamplefv`, y up, flipped to the
//! case's y down) are the plan's offsets, as a set, and the scene has no
//! line (llvmpipe draws every line of a multisampled target as a
//! rectangle) and no depth attachment (a multisampled one cannot be read
//! back exactly, `depth.rs`; such scenes are drawn by shifted passes).
//! Then one pass into float multisample textures (fixed
//! sample locations) is read back sample by sample (a `texelFetch` pass
//! per sample into a single-sample copy), driver sample i into the slot
//! at its offset. llvmpipe (Mesa 22.3) reports `GL_MAX_SAMPLES` 4 and one
//! count, 4×, at (0.375, 0.125), (0.875, 0.375), (0.125, 0.625),
//! (0.625, 0.875) in GL's window terms (y up): the standard 4× pattern in
//! gallium's memory order, which read y down is (0.375, 0.875),
//! (0.875, 0.625), (0.125, 0.375), (0.625, 0.125), the standard pattern
//! flipped. No bundled pattern is that, so the bundled antialiased cases
//! are all drawn by shifted passes; `tests/gl/msaa.rs` draws the driver's
//! own pattern natively and matches the reference sample for sample.
//! Reports say which rule picks the method ([`Rasterizer::declared`]).
//!
//! # Rectangle lines: one driver sample on each pixel centre
//!
//! A single-sample scene with `rectangle` lines is drawn into a 4× target
//! (`msaa.rs`), the scene moved by position_j − (½, ½) for a driver
//! sample j on the 1/256 grid (exact for `subpixel_bits` ≤ 8, refused
//! above), which brings each pixel's centre onto the pixel's sample j;
//! sample j alone is read, into the pixel's slot. Triangles and polygons
//! beside the lines are drawn the same way, exactly; `diamond-exit` lines
//! beside them are refused (the target would draw them as rectangles), as
//! is a depth attachment (`depth.rs`).
//! Found: llvmpipe's rectangles match SPEC §4.3 wherever no sample lies
//! on a border (the bundled wide ones pass), and a sample exactly on a
//! border goes either way, by where llvmpipe's corners, computed in float
//! and snapped to its 1/256 grid, put the border, not by a tie rule (the
//! bundled tie cases fail on such samples only, `tests/gl/rectangles.rs`).
//!
//! # Motion: time passes
//!
//! A moving scene is drawn once per time test of every pixel (`time.rs`,
//! with `gpu::time_draws`, as the `vulkan` adapter draws it): the scene
//! placed at the test's instant and shifted for its spatial sample (the
//! shifted passes' shifts, refused where those are), drawn in one tile
//! with the scissor on that pixel alone, every test adding to the pixel's
//! count. The count over the M·N tests is the pixel's time coverage
//! (`Frame::time_only`); static primitives are in every placement, so they
//! count at every instant. At most 2^20 tests a scene; more is
//! unsupported. llvmpipe snaps a vertex placed at an instant to its grid,
//! as it would for any renderer drawing that instant; the time-coverage
//! bounds judge the result. Under the driver's tie rule (bottom-left, read
//! y down) every bundled moving case it draws passes; under the cases' own
//! rules `motion/ride_top_edge_top_left` fails and
//! `motion/ride_top_edge_bottom_right` passes, as the fill rule says.
//!
//! # One context per process, and softpipe
//!
//! One EGL display and context is created on first use and shared by every
//! case; a mutex serialises the cases, and each case makes the context
//! current on its own thread and releases it after. Mesa picks the gallium
//! driver (llvmpipe or softpipe) from `GALLIUM_DRIVER` when the display is
//! initialised, and the surfaceless platform gives one display per process,
//! so a process holds one of the two, never both:
//!
//! - `gl` draws with whatever the display is (llvmpipe unless the process
//!   was started with `GALLIUM_DRIVER` set) and names it in its messages;
//! - `softpipe` sets `GALLIUM_DRIVER=softpipe` when it is the first to
//!   create the display and `GALLIUM_DRIVER` is unset (the case in a
//!   `rastercheck run -r softpipe`), and otherwise insists that the renderer
//!   is softpipe: where the process already holds llvmpipe it fails, saying
//!   to start the process with `GALLIUM_DRIVER=softpipe`.
//!
//! # Set up once, drawn again and again
//!
//! A scene is set up once (its vertex stream converted and uploaded into a
//! vertex array and buffer of its own, its framebuffer made) and then
//! cleared, drawn and read back. `rasterize` does it all with the context
//! held, and deletes it; [`Rasterizer::prepare`] hands the set-up scene to
//! the bench, which clears, draws (the draw calls and `glFinish`) and reads
//! back phase by phase, the context locked and made current for each
//! phase, and so times the driver's own draw apart. Both paths share every
//! step, so the frame the bench judges is the one a case's run draws.
//!
//! # The rooms
//!
//! - this file: the [`Rasterizer`] impls, what Mesa's GL can draw and why
//!   it refuses the rest;
//! - `context.rs`: the shared EGL display and context, made on first use,
//!   locked and made current per case, and its fixed state;
//! - `shaders.rs`: the programs, one per interpolation mode;
//! - `lines.rs`: which line rules GL draws, and why not the others;
//! - `passes.rs`: the passes a scene is drawn in (one, or one per sample
//!   slot), each in a tile of the framebuffer: the layout of streams and
//!   passes every way of drawing here produces;
//! - `time.rs`: a moving scene's time passes, one per pixel and time test,
//!   scissored to its pixel;
//! - `samples.rs`: the driver's sample counts and positions, and which
//!   patterns are exactly one of them;
//! - `msaa.rs`: native MSAA and rectangle lines, drawn into multisampled
//!   targets and read back sample by sample;
//! - `drawing.rs`: one scene set up in the context (vertex buffer,
//!   framebuffer, stencil), cleared, drawn run by run with each run's
//!   state, and deleted;
//! - `depth.rs`: the depth attachment of a scene with a depth format or a
//!   polygon offset, its state, and its stored values read back;
//! - `readback.rs`: the attachments read back into a [`Frame`] (slots, or
//!   time coverage);
//! - `prepared.rs`: the same scene cleared, drawn and read back one phase
//!   at a time, for the bench to time the draw apart.

mod clip;
mod context;
mod depth;
mod drawing;
mod lines;
mod msaa;
mod passes;
mod prepared;
mod readback;
mod samples;
mod shaders;
mod time;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, Prepared, RasterError, Rasterizer};
use crate::scene::{ClipXy, ClipZ, FillRule, InterpolateFrom, PointBounds, PointClip, Scene};

use super::gpu;
use super::gpu::depth::DepthTarget;
use context::{ask_for_softpipe, context, with_context};
use prepared::prepare;

/// The name of the adapter that draws with whatever Mesa's GL is.
pub const NAME: &str = "gl";
/// The name of the adapter that insists on softpipe.
pub const SOFTPIPE: &str = "softpipe";

/// Mesa's OpenGL through EGL: llvmpipe, or whatever `GALLIUM_DRIVER` names.
pub struct Gl;

/// Mesa's softpipe through EGL (see the module's notes on one driver per
/// process).
pub struct Softpipe;

impl Rasterizer for Gl {
    fn name(&self) -> &str {
        NAME
    }

    fn capabilities(&self) -> Capabilities {
        capabilities()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        rasterize(scene, plan, false)
    }

    /// llvmpipe's top-left rule, read in the case's y-down terms (see
    /// "Rules" above): GL gives no choice.
    fn fixed_fill_rule(&self) -> Option<FillRule> {
        Some(FillRule::BottomLeft)
    }

    /// GL lets the driver choose. llvmpipe clips against all six planes
    /// before the divide and snaps the new vertices (Mesa's draw module;
    /// measured on scenes that separate the conventions, `tests/gl/`: 6
    /// samples depart from per-sample near clipping, 3 from a guard band,
    /// none from clip then snap).
    fn fixed_clip_rules(&self) -> Option<(ClipXy, ClipZ)> {
        Some((ClipXy::ClipThenSnap, ClipZ::ClipThenSnap))
    }

    /// llvmpipe sets its planes up in floating point from the divided,
    /// unsnapped vertices, and snaps only the edges (SPEC.md §16.10: on
    /// the bundled clip-space cases its depth and attributes depart from
    /// the snapped positions' values by up to 1.3e-3, and from the
    /// unsnapped positions' by at most 2.3e-6).
    fn fixed_interpolate_from(&self) -> Option<InterpolateFrom> {
        Some(InterpolateFrom::Unsnapped)
    }

    /// GL's own rule: llvmpipe pops a point whose centre is outside the
    /// side planes (measured in screen space, `tests/gl/`: a size-4 point
    /// centred at x = 17 of a 16-pixel target draws nothing), so the
    /// adapter refuses the points where that shows (`gpu::points`).
    fn fixed_point_clip(&self) -> Option<PointClip> {
        Some(PointClip::Pop)
    }

    /// Mesa limits a point's square to the viewport rectangle (measured on
    /// the bundled point cases, SPEC.md §17.4).
    fn fixed_point_bounds(&self) -> Option<PointBounds> {
        Some(PointBounds::Viewport)
    }

    fn declared(&self) -> Option<String> {
        declared()
    }

    fn prepare<'a>(
        &'a self,
        scene: &'a Scene,
        plan: &'a Plan,
    ) -> Option<Result<Box<dyn Prepared + 'a>, RasterError>> {
        Some(prepare(scene, plan, false))
    }
}

impl Rasterizer for Softpipe {
    fn name(&self) -> &str {
        SOFTPIPE
    }

    /// llvmpipe's, but clip space and points: softpipe's clipping and
    /// point conventions have not been measured (`tests/gl/` measures
    /// llvmpipe's), so it claims neither.
    fn capabilities(&self) -> Capabilities {
        Capabilities {
            clip_space: false,
            points: false,
            ..capabilities()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        rasterize(scene, plan, true)
    }

    /// softpipe's rule, read in the case's y-down terms.
    fn fixed_fill_rule(&self) -> Option<FillRule> {
        Some(FillRule::BottomRight)
    }

    fn declared(&self) -> Option<String> {
        declared()
    }

    fn prepare<'a>(
        &'a self,
        scene: &'a Scene,
        plan: &'a Plan,
    ) -> Option<Result<Box<dyn Prepared + 'a>, RasterError>> {
        Some(prepare(scene, plan, true))
    }
}

/// What Mesa's GL draws here: triangles, `diamond-exit` and `rectangle`
/// lines (`lines.rs` refuses the other rules) and polygons by stencil then
/// cover, snapped to the case's grid; antialiased scenes by shifted passes
/// (`passes.rs`) or native MSAA (`msaa.rs`); moving scenes by time passes
/// (`time.rs`); clip-space scenes, clipped by the driver (`clip.rs`); depth
/// formats and polygon offsets into a real depth attachment (`depth.rs`).
fn capabilities() -> Capabilities {
    Capabilities {
        polygons: true,
        motion_blur: true,
        clip_space: true,
        points: true,
        depth_attachment: true,
        ..gpu::capabilities(true)
    }
}

/// What the reports show beside the adapter's name, once the context
/// exists: the renderer, when antialiased cases are drawn by the driver's
/// multisampling (its positions listed) and when by shifted passes, how
/// rectangle lines are drawn, that moving scenes are drawn by time
/// passes, and that depth formats and offsets use a depth attachment.
fn declared() -> Option<String> {
    let description = context::existing_description()?;
    let offered = context::existing(|gl| {
        gl.offered
            .iter()
            .map(|o| o.describe())
            .collect::<Vec<_>>()
            .join("; ")
    })?;
    Some(format!(
        "{description}; antialiasing by the driver's MSAA where a case's sample positions \
         are exactly the driver's ({offered}; y down), by shifted passes (one single-sample \
         pass per sample slot) otherwise and with a depth attachment; rectangle lines in a \
         multisampled target, one sample read; motion by time passes (one scissored draw per \
         pixel and time test); depth formats and polygon offsets into a real depth attachment, \
         its stored values read back"
    ))
}

/// The driver's multisampling, as queried once per context.
#[derive(Clone, Debug, PartialEq)]
pub struct DriverMultisampling {
    /// `GL_MAX_SAMPLES`.
    pub max_samples: u32,
    /// Each count it grants, with its samples' positions in its sample
    /// order: offsets from the pixel's top-left corner, y down, in pixels
    /// (GL's `GL_SAMPLE_POSITION`, y up, flipped).
    pub counts: Vec<(u32, Vec<[f64; 2]>)>,
}

/// The driver's multisampling, or why there is no context. Creates the
/// shared context on first use.
pub fn driver_multisampling() -> Result<DriverMultisampling, String> {
    let gl = context()?;
    let gl = gl.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    Ok(DriverMultisampling {
        max_samples: gl.max_samples,
        counts: gl
            .offered
            .iter()
            .map(|o| (o.count, o.positions.clone()))
            .collect(),
    })
}

/// The subpixel bits Mesa's GL snaps the scene to and the depth
/// attachment it needs (`depth.rs`), or why it cannot draw it: several
/// samples per pixel, a line rule GL does not draw (`lines.rs`),
/// unsnapped geometry, too many attributes, or a depth attachment
/// `gpu::depth::target` refuses. For `softpipe`, asks for it if no display
/// exists yet.
pub(super) fn accepted(
    scene: &Scene,
    plan: &Plan,
    softpipe: bool,
) -> Result<(u32, Option<DepthTarget>), RasterError> {
    if plan.antialias.is_none() && plan.samples_per_pixel != 1 {
        return Err(RasterError::Unsupported(format!(
            "{} samples per pixel without a sample pattern",
            plan.samples_per_pixel
        )));
    }
    let bits = gpu::snapping_bits(scene, plan, lines::refusal, "Mesa's GL")?;
    if let Some(why) = lines::scene_refusal(scene, plan) {
        return Err(RasterError::Unsupported(format!("lines: {why}")));
    }
    if softpipe {
        ask_for_softpipe();
    }
    if let Some(why) = point_refusal(scene) {
        return Err(RasterError::Unsupported(why));
    }
    // GL_DEPTH_CLAMP (core since 3.2) clamps depth without clipping it.
    let depth = gpu::depth::target(scene, true, "Mesa's GL").map_err(RasterError::Unsupported)?;
    Ok((bits, depth))
}

/// Why Mesa's GL cannot draw a point of the scene as the rule's square
/// (`gpu::points`), if it cannot: the context's point sizes, on llvmpipe's
/// grid of 8 subpixel bits.
fn point_refusal(scene: &Scene) -> Option<String> {
    let mut points = gpu::points::points(scene).peekable();
    points.peek()?;
    let gl = match context() {
        Ok(gl) => gl,
        Err(why) => return Some(format!("no context to ask for point sizes: {why}")),
    };
    let offers = {
        let gl = gl.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
        gpu::points::PointOffers {
            large: true,
            range: gl.point_range,
            granularity: gl.point_granularity,
            subpixel_bits: 8,
            pops: true,
        }
    };
    points.find_map(|p| gpu::points::refusal(scene, p, &offers))
}

/// Sets the scene up, clears, draws and reads back, with the context held
/// throughout, and deletes what it set up.
fn rasterize(scene: &Scene, plan: &Plan, softpipe: bool) -> Result<Frame, RasterError> {
    let (bits, depth) = accepted(scene, plan, softpipe)?;
    with_context(|gl| {
        gl.insist_on_softpipe(softpipe)?;
        // SAFETY: GL calls on the context current on this thread, with
        // buffers sized to what is read and written.
        unsafe {
            let drawing = gl.set_up(scene, plan, bits, depth)?;
            gl.clear(&drawing);
            gl.draw(&drawing);
            let frame = gl.read_back(&drawing);
            gl.delete(&drawing);
            frame
        }
    })
}

/// The renderer (`GL_RENDERER`, `GL_VERSION`), or why there is none. Creates
/// the shared context on first use.
pub fn renderer_description() -> Result<String, String> {
    let gl = context()?;
    let gl = gl.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    Ok(format!("{} ({})", gl.renderer, gl.version))
}
