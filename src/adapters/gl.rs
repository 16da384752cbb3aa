//! `gl` and `softpipe`: Mesa's OpenGL rasterizers on the CPU (llvmpipe, or
//! softpipe with `GALLIUM_DRIVER=softpipe`), driven through EGL on the
//! surfaceless platform with glow (cargo feature `gl`; system packages
//! `libegl1 libegl-mesa0 libgl1-mesa-dri`).
//!
//! # What is drawn, and how it is read back
//!
//! The structure is the `lavapipe` adapter's. A case's triangles are drawn in
//! scene order, with no depth test, into the float colour attachments of one
//! framebuffer object, in one pass, and read back into a [`Frame`]:
//!
//! - **count** (`R32F`, additive blending `1 + dst`, enabled on this draw
//!   buffer only): how many triangles cover each sample;
//! - **channel groups** (`RGBA32F`, no blending, so the last triangle in
//!   submission order wins, as GL's primitive order guarantees): the channels
//!   `[primitive + 1, depth, attribute 0, …, attribute 15]` four at a time, as
//!   many attachments as the plan needs (at most five; GL 3.3 has at least
//!   eight draw buffers).
//!
//! The primitive index (+ 1, exact in f32 up to 2^24) is a `flat` varying and
//! doubles as the coverage marker of the last writer. Depth is the case's `z`
//! as a `noperspective` varying, not the depth buffer. Attributes are
//! varyings with the case's interpolation: `smooth` (perspective),
//! `noperspective` (linear) or `flat`. GL's default provoking vertex is the
//! last; the adapter sets `glProvokingVertex(GL_FIRST_VERTEX_CONVENTION)`
//! (core since GL 3.2), the case's rule. Consecutive triangles of one
//! interpolation mode share one draw call.
//!
//! # Positions: exact to the 8-bit grid
//!
//! As in `lavapipe`: coordinates are snapped to the case's `subpixel_bits`
//! (ties to even) and rounded to f32 (exact for b ≤ 8); the attachments are
//! `P × Q`, the powers of two at or above the canvas size; the viewport is
//! the whole `P × Q`, and
//!
//! ```text
//! x_ndc = x · 2/P − 1,   y_ndc = 1 − y · 2/Q      (y down on screen)
//! clip  = (x_ndc · w, y_ndc · w, w / 2, w)
//! ```
//!
//! GL's window y points up, so a screen row y lands on window row Q − 1 − y:
//! the canvas is the top `W × H` of the target (window rows Q − H … Q − 1),
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
//! - **Lines**: unsupported (GL's lines have no choice of the case's rule).
//!   **MSAA**: not yet.
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

use std::ffi::c_void;
use std::sync::{Mutex, OnceLock};

use glow::HasContext;
use khronos_egl as egl;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, Prepared, RasterError, Rasterizer};
use crate::scene::{Cull, Interpolation, Scene};

/// The name of the adapter that draws with whatever Mesa's GL is.
pub const NAME: &str = "gl";
/// The name of the adapter that insists on softpipe.
pub const SOFTPIPE: &str = "softpipe";

/// What to install when no display or driver is found.
const INSTALL_HINT: &str =
    "install libegl1 libegl-mesa0 libgl1-mesa-dri (Debian/Ubuntu) so that EGL finds Mesa's llvmpipe";

/// `EGL_PLATFORM_SURFACELESS_MESA`.
const PLATFORM_SURFACELESS_MESA: egl::Enum = 0x31DD;

use super::gpu::{self, GROUPS, VERTEX_FLOATS};

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

    fn capabilities(&self) -> Capabilities {
        capabilities()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        rasterize(scene, plan, true)
    }

    fn prepare<'a>(
        &'a self,
        scene: &'a Scene,
        plan: &'a Plan,
    ) -> Option<Result<Box<dyn Prepared + 'a>, RasterError>> {
        Some(prepare(scene, plan, true))
    }
}

fn capabilities() -> Capabilities {
    gpu::capabilities(false)
}

/// The subpixel bits Mesa's GL snaps the scene to, or why it cannot draw
/// it: several samples per pixel, a line, unsnapped geometry or too many
/// attributes. For `softpipe`, asks for it if no display exists yet.
fn accepted(scene: &Scene, plan: &Plan, softpipe: bool) -> Result<u32, RasterError> {
    if plan.samples_per_pixel != 1 {
        return Err(RasterError::Unsupported(
            "multisampling is not wired to the GL adapter yet".to_owned(),
        ));
    }
    let bits = gpu::snapping_bits(
        scene,
        plan,
        "GL's lines have no choice of the case's line rule",
        "Mesa's GL",
    )?;
    if softpipe {
        ask_for_softpipe();
    }
    Ok(bits)
}

/// Sets the scene up, clears, draws and reads back, with the context held
/// throughout, and deletes what it set up.
fn rasterize(scene: &Scene, plan: &Plan, softpipe: bool) -> Result<Frame, RasterError> {
    let bits = accepted(scene, plan, softpipe)?;
    with_context(|gl| {
        gl.insist_on_softpipe(softpipe)?;
        // SAFETY: GL calls on the context current on this thread, with
        // buffers sized to what is read and written.
        unsafe {
            let drawing = gl.set_up(scene, plan, bits)?;
            gl.clear(&drawing);
            gl.draw(&drawing);
            let frame = gl.read_back(&drawing);
            gl.delete(&drawing);
            frame
        }
    })
}

/// Runs `f` with the shared context locked and current on this thread,
/// and releases the context after, whatever `f` returns: the cases (and
/// the phases of a prepared scene) take turns.
fn with_context<T>(f: impl FnOnce(&GlContext) -> Result<T, RasterError>) -> Result<T, RasterError> {
    let gl = context().map_err(|why| RasterError::Failed(why.clone()))?;
    let gl = gl.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    gl.bind()?;
    let result = f(&gl);
    let _ = gl.egl.make_current(gl.display, None, None, None);
    result
}

/// Sets `GALLIUM_DRIVER=softpipe` when no display exists yet and the
/// variable is unset, so that a process that asks for softpipe first gets it.
fn ask_for_softpipe() {
    if CONTEXT.get().is_none() && std::env::var_os("GALLIUM_DRIVER").is_none() {
        // Before Mesa is loaded: nothing outside Rust's own locked
        // environment access reads the variable yet.
        std::env::set_var("GALLIUM_DRIVER", "softpipe");
    }
}

/// The renderer (`GL_RENDERER`, `GL_VERSION`), or why there is none. Creates
/// the shared context on first use.
pub fn renderer_description() -> Result<String, String> {
    let gl = context()?;
    let gl = gl.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    Ok(format!("{} ({})", gl.renderer, gl.version))
}

static CONTEXT: OnceLock<Result<Mutex<GlContext>, String>> = OnceLock::new();

fn context() -> Result<&'static Mutex<GlContext>, &'static String> {
    CONTEXT
        .get_or_init(|| GlContext::new().map(Mutex::new))
        .as_ref()
}

type Egl = egl::DynamicInstance<egl::EGL1_5>;

struct GlContext {
    egl: Egl,
    display: egl::Display,
    context: egl::Context,
    gl: glow::Context,
    renderer: String,
    version: String,
    max_side: u32,
    programs: [glow::Program; 3],
}

// SAFETY: the EGL handles are plain pointers that EGL lets any thread use;
// the context is made current only while the mutex is held, and released
// before it is let go.
unsafe impl Send for GlContext {}

impl GlContext {
    fn new() -> Result<GlContext, String> {
        // SAFETY: loading libEGL runs its initialisers, as any EGL program does.
        let egl = unsafe { Egl::load_required() }
            .map_err(|e| format!("no EGL 1.5 library (libEGL.so.1): {INSTALL_HINT} ({e})"))?;
        // SAFETY: the surfaceless platform takes no native display.
        let display = unsafe {
            egl.get_platform_display(
                PLATFORM_SURFACELESS_MESA,
                std::ptr::null_mut::<c_void>(),
                &[egl::ATTRIB_NONE],
            )
        }
        .map_err(|e| format!("no surfaceless EGL display: {INSTALL_HINT} ({e})"))?;
        egl.initialize(display).map_err(|e| {
            format!("the surfaceless EGL display did not initialise: {INSTALL_HINT} ({e})")
        })?;
        let fail = |what: &str, e: egl::Error| {
            format!(
                "EGL: {what}: {e} (vendor {:?}); {INSTALL_HINT}",
                egl.query_string(Some(display), egl::VENDOR).ok()
            )
        };
        egl.bind_api(egl::OPENGL_API)
            .map_err(|e| fail("no desktop OpenGL API", e))?;
        let config = egl
            .choose_first_config(
                display,
                &[
                    egl::SURFACE_TYPE,
                    egl::PBUFFER_BIT,
                    egl::RENDERABLE_TYPE,
                    egl::OPENGL_BIT,
                    egl::NONE,
                ],
            )
            .map_err(|e| fail("choosing a config", e))?
            .ok_or_else(|| format!("EGL: no OpenGL pbuffer config; {INSTALL_HINT}"))?;
        let context = egl
            .create_context(
                display,
                config,
                None,
                &[
                    egl::CONTEXT_MAJOR_VERSION,
                    3,
                    egl::CONTEXT_MINOR_VERSION,
                    3,
                    egl::CONTEXT_OPENGL_PROFILE_MASK,
                    egl::CONTEXT_OPENGL_CORE_PROFILE_BIT,
                    egl::NONE,
                ],
            )
            .map_err(|e| fail("creating an OpenGL 3.3 core context", e))?;
        egl.make_current(display, None, None, Some(context))
            .map_err(|e| fail("making the context current (surfaceless)", e))?;
        // SAFETY: the context is current; the loader returns its entry points.
        let gl = unsafe {
            glow::Context::from_loader_function(|name| {
                egl.get_proc_address(name)
                    .map_or(std::ptr::null(), |f| f as *const c_void)
            })
        };
        let provoking = egl.get_proc_address("glProvokingVertex");
        // SAFETY: plain queries and object creation on the current context.
        let (renderer, version, made) = unsafe {
            let renderer = gl.get_parameter_string(glow::RENDERER);
            let version = gl.get_parameter_string(glow::VERSION);
            let made = set_up_context(&gl, provoking);
            (renderer, version, made)
        };
        let _ = egl.make_current(display, None, None, None);
        let (max_side, programs) =
            made.map_err(|e| format!("OpenGL ({renderer}, {version}): {e}"))?;
        Ok(GlContext {
            egl,
            display,
            context,
            gl,
            renderer,
            version,
            max_side,
            programs,
        })
    }

    /// Fails where `softpipe` is asked for and this process's GL is
    /// another driver.
    fn insist_on_softpipe(&self, softpipe: bool) -> Result<(), RasterError> {
        if softpipe && !self.renderer.contains("softpipe") {
            return Err(RasterError::Failed(format!(
                "softpipe: this process's GL is {} (Mesa picks one gallium driver per process); \
                 start it with GALLIUM_DRIVER=softpipe",
                self.renderer
            )));
        }
        Ok(())
    }

    /// Makes the context current on this thread for one case.
    fn bind(&self) -> Result<(), RasterError> {
        self.egl
            .make_current(self.display, None, None, Some(self.context))
            .map_err(|e| {
                RasterError::Failed(format!(
                    "{}: making the context current: {e}",
                    self.renderer
                ))
            })
    }

    fn failed(&self, what: &str) -> RasterError {
        RasterError::Failed(format!("{}: {what}", self.renderer))
    }

    /// The first pending GL error as a failure of `what`.
    unsafe fn check(&self, what: &str) -> Result<(), RasterError> {
        match gl_error(&self.gl) {
            Some(e) => Err(self.failed(&format!("{what}: GL error {e:#x}"))),
            None => Ok(()),
        }
    }

    /// Sets a scene up: uploads its vertex stream into a vertex array and
    /// buffer of its own, and makes a framebuffer of `P × Q` float
    /// attachments (the count, then the channel groups).
    unsafe fn set_up<'a>(
        &self,
        scene: &Scene,
        plan: &'a Plan,
        bits: u32,
    ) -> Result<Drawing<'a>, RasterError> {
        let (tw, th) = gpu::target_size(scene, self.max_side, &self.renderer)?;
        let groups = gpu::groups(plan);
        let gpu::Stream { vertices, runs } =
            gpu::Stream::new(scene, &gpu::Placement::at_centres(bits, (tw, th)));
        let gl = &self.gl;
        let _ = gl_error(gl);

        let mut drawing = Drawing {
            plan,
            canvas: (scene.canvas.width, scene.canvas.height),
            target: (tw, th),
            cull: scene.rules.cull,
            runs,
            vao: gl.create_vertex_array().map_err(|e| self.failed(&e))?,
            vbo: None,
            fbo: None,
            renderbuffers: Vec::with_capacity(1 + groups),
        };
        if let Err(e) = self.make(&mut drawing, &vertices, groups) {
            self.delete(&drawing);
            return Err(e);
        }
        Ok(drawing)
    }

    /// Makes the vertex buffer (filled with `vertices`) and the framebuffer
    /// of `drawing`; what is made before a failure is left for
    /// [`GlContext::delete`].
    unsafe fn make(
        &self,
        drawing: &mut Drawing,
        vertices: &[f32],
        groups: usize,
    ) -> Result<(), RasterError> {
        let gl = &self.gl;
        gl.bind_vertex_array(Some(drawing.vao));
        let vbo = gl.create_buffer().map_err(|e| self.failed(&e))?;
        drawing.vbo = Some(vbo);
        gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
        for i in 0..VERTEX_FLOATS / 4 {
            gl.enable_vertex_attrib_array(i as u32);
            gl.vertex_attrib_pointer_f32(
                i as u32,
                4,
                glow::FLOAT,
                false,
                (VERTEX_FLOATS * 4) as i32,
                (i * 16) as i32,
            );
        }
        gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &f32_bytes(vertices), glow::STATIC_DRAW);
        gl.bind_vertex_array(None);

        let fbo = gl.create_framebuffer().map_err(|e| self.failed(&e))?;
        drawing.fbo = Some(fbo);
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
        let (tw, th) = drawing.target;
        for k in 0..=groups {
            let rb = gl.create_renderbuffer().map_err(|e| self.failed(&e))?;
            drawing.renderbuffers.push(rb);
            gl.bind_renderbuffer(glow::RENDERBUFFER, Some(rb));
            let format = if k == 0 { glow::R32F } else { glow::RGBA32F };
            gl.renderbuffer_storage(glow::RENDERBUFFER, format, tw as i32, th as i32);
            gl.framebuffer_renderbuffer(
                glow::FRAMEBUFFER,
                glow::COLOR_ATTACHMENT0 + k as u32,
                glow::RENDERBUFFER,
                Some(rb),
            );
        }
        let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
        if status != glow::FRAMEBUFFER_COMPLETE {
            return Err(self.failed(&format!(
                "float framebuffer {tw}×{th} incomplete ({status:#x})"
            )));
        }
        let buffers: Vec<u32> = (0..=groups as u32)
            .map(|k| glow::COLOR_ATTACHMENT0 + k)
            .collect();
        gl.draw_buffers(&buffers);
        self.check("setting up")
    }

    /// Binds `drawing`'s framebuffer, in which its draw buffers are kept.
    unsafe fn bind_framebuffer(&self, drawing: &Drawing) {
        self.gl.bind_framebuffer(glow::FRAMEBUFFER, drawing.fbo);
    }

    /// Clears every attachment of `drawing`.
    unsafe fn clear(&self, drawing: &Drawing) {
        let gl = &self.gl;
        self.bind_framebuffer(drawing);
        gl.disable(glow::SCISSOR_TEST);
        for k in 0..drawing.renderbuffers.len() as u32 {
            gl.clear_buffer_f32_slice(glow::COLOR, k, &[0.0; 4]);
        }
    }

    /// Issues `drawing`'s draw calls into its attachments as they stand:
    /// the viewport, scissor, blending and culling its scene asks for (the
    /// context's state is every case's, so it is set each time), then one
    /// `glDrawArrays` per run of triangles. Returns without waiting.
    unsafe fn draw(&self, drawing: &Drawing) {
        let gl = &self.gl;
        let ((w, h), (tw, th)) = (drawing.canvas, drawing.target);
        self.bind_framebuffer(drawing);
        gl.viewport(0, 0, tw as i32, th as i32);
        gl.enable(glow::SCISSOR_TEST);
        gl.scissor(0, (th - h) as i32, w as i32, h as i32);
        gl.disable(glow::BLEND);
        gl.enable_draw_buffer(glow::BLEND, 0);
        match drawing.cull {
            Cull::None => gl.disable(glow::CULL_FACE),
            Cull::Clockwise => {
                gl.enable(glow::CULL_FACE);
                gl.cull_face(glow::BACK);
            }
            Cull::CounterClockwise => {
                gl.enable(glow::CULL_FACE);
                gl.cull_face(glow::FRONT);
            }
        }
        gl.bind_vertex_array(Some(drawing.vao));
        for run in &drawing.runs {
            // The adapter refuses lines and polygons (`accepted`).
            let gpu::Draw::Triangles(mode) = run.draw else {
                continue;
            };
            let (a, b) = (run.first, run.end);
            let program = match mode {
                Interpolation::Perspective => self.programs[0],
                Interpolation::Linear => self.programs[1],
                Interpolation::Flat => self.programs[2],
            };
            gl.use_program(Some(program));
            // Vertex counts are bounded by the primitive limit (SPEC §8).
            gl.draw_arrays(glow::TRIANGLES, a as i32, (b - a) as i32);
        }
        gl.bind_vertex_array(None);
    }

    /// Reads the canvas (the top `W × H` of the attachments) back, flipping
    /// the rows, into a frame: the counts, the last primitives, and where
    /// covered the depth and attributes. `glReadPixels` waits for the
    /// drawing.
    unsafe fn read_back(&self, drawing: &Drawing) -> Result<Frame, RasterError> {
        let gl = &self.gl;
        let ((w, h), th) = (drawing.canvas, drawing.target.1);
        let groups = drawing.renderbuffers.len() as u32 - 1;
        self.bind_framebuffer(drawing);
        let n = w as usize * h as usize;
        let read = |k: u32, components: usize| -> Vec<f32> {
            let mut bytes = vec![0u8; n * components * 4];
            gl.read_buffer(glow::COLOR_ATTACHMENT0 + k);
            gl.read_pixels(
                0,
                (th - h) as i32,
                w as i32,
                h as i32,
                if components == 1 {
                    glow::RED
                } else {
                    glow::RGBA
                },
                glow::FLOAT,
                glow::PixelPackData::Slice(Some(&mut bytes)),
            );
            let row = w as usize * components;
            let mut out = Vec::with_capacity(n * components);
            for y in (0..h as usize).rev() {
                out.extend(
                    bytes[y * row * 4..(y + 1) * row * 4]
                        .chunks_exact(4)
                        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]])),
                );
            }
            out
        };
        let counts = read(0, 1);
        let values: Vec<Vec<f32>> = (1..=groups).map(|k| read(k, 4)).collect();
        self.check("drawing and reading back")?;

        let plan = drawing.plan;
        let mut frame = Frame::new(w, h, plan.depth, plan.attributes);
        let channel = |c: usize, i: usize| values[c / 4][i * 4 + c % 4];
        for i in 0..n {
            let c = counts[i];
            if c.fract() != 0.0 || !(0.0..=65535.0).contains(&c) {
                return Err(self.failed(&format!("coverage count {c} read back at sample {i}")));
            }
            frame.coverage[i] = c as u16;
            frame.last[i] = channel(0, i) as u32;
            if c > 0.0 {
                if let Some(depth) = &mut frame.depth {
                    depth[i] = f64::from(channel(1, i));
                }
                for (k, a) in frame.attributes.iter_mut().enumerate() {
                    a[i] = f64::from(channel(2 + k, i));
                }
            }
        }
        Ok(frame)
    }

    /// Deletes `drawing`'s objects.
    unsafe fn delete(&self, drawing: &Drawing) {
        let gl = &self.gl;
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        if let Some(fbo) = drawing.fbo {
            gl.delete_framebuffer(fbo);
        }
        for &rb in &drawing.renderbuffers {
            gl.delete_renderbuffer(rb);
        }
        if let Some(vbo) = drawing.vbo {
            gl.delete_buffer(vbo);
        }
        gl.delete_vertex_array(drawing.vao);
    }
}

/// One scene set up in the shared context: its vertex stream in a vertex
/// array and buffer of its own, and its framebuffer of float attachments,
/// so that it can be cleared, drawn and read back again and again while
/// other cases use the context in between.
struct Drawing<'a> {
    plan: &'a Plan,
    canvas: (u32, u32),
    /// The attachments' power-of-two size.
    target: (u32, u32),
    cull: Cull,
    /// The runs of consecutive vertices (first, end) of one interpolation
    /// mode: one draw call each.
    runs: Vec<gpu::Run>,
    vao: glow::VertexArray,
    vbo: Option<glow::Buffer>,
    fbo: Option<glow::Framebuffer>,
    /// The count's, then the channel groups'.
    renderbuffers: Vec<glow::Renderbuffer>,
}

/// A scene set up in the shared context, to be cleared, drawn and read back
/// again and again: the bench's view of the driver's own draw. The context
/// is locked and made current for each phase, not held between them, so
/// that a whole call (the bench's own, or another case's) can run in
/// between; the scene's objects are its own, untouched by it, and deleted
/// when it is dropped.
struct PreparedGl<'a> {
    drawing: Drawing<'a>,
}

/// Sets `scene` up, its upload finished (`glFinish`) before it returns.
fn prepare<'a>(
    scene: &Scene,
    plan: &'a Plan,
    softpipe: bool,
) -> Result<Box<dyn Prepared + 'a>, RasterError> {
    let bits = accepted(scene, plan, softpipe)?;
    let drawing = with_context(|gl| {
        gl.insist_on_softpipe(softpipe)?;
        // SAFETY: GL calls on the context current on this thread.
        unsafe {
            let drawing = gl.set_up(scene, plan, bits)?;
            gl.gl.finish();
            Ok(drawing)
        }
    })?;
    Ok(Box::new(PreparedGl { drawing }))
}

impl PreparedGl<'_> {
    /// Runs one phase on the drawing, with the context current.
    fn phase<T>(
        &self,
        f: impl FnOnce(&GlContext, &Drawing) -> Result<T, RasterError>,
    ) -> Result<T, RasterError> {
        with_context(|gl| f(gl, &self.drawing))
    }
}

impl Prepared for PreparedGl<'_> {
    /// Clears every attachment, and waits (`glFinish`).
    fn clear(&mut self) -> Result<(), RasterError> {
        // SAFETY: GL calls on the context current on this thread.
        self.phase(|gl, drawing| unsafe {
            gl.clear(drawing);
            gl.gl.finish();
            gl.check("clearing")
        })
    }

    /// The draw calls into the attachments as they stand (no clear), and
    /// `glFinish`: the state the draw needs is set too, as the context is
    /// shared, but nothing is uploaded or read.
    fn draw(&mut self) -> Result<(), RasterError> {
        // SAFETY: GL calls on the context current on this thread.
        self.phase(|gl, drawing| unsafe {
            gl.draw(drawing);
            gl.gl.finish();
            gl.check("drawing")
        })
    }

    /// Reads the attachments back as a whole call does (`glReadPixels`
    /// waits for any drawing still pending).
    fn read_back(&mut self) -> Result<Frame, RasterError> {
        // SAFETY: GL calls on the context current on this thread, with
        // buffers sized to what is read.
        self.phase(|gl, drawing| unsafe { gl.read_back(drawing) })
    }
}

impl Drop for PreparedGl<'_> {
    fn drop(&mut self) {
        // SAFETY: deleting the drawing's own objects, the context current.
        let _ = self.phase(|gl, drawing| {
            unsafe { gl.delete(drawing) };
            Ok(())
        });
    }
}

/// What one context keeps: the largest target side and the three programs.
type Parts = (u32, [glow::Program; 3]);

/// Sets up the current context: first-vertex provoking, the programs and
/// the fixed state.
unsafe fn set_up_context(
    gl: &glow::Context,
    provoking: Option<extern "system" fn()>,
) -> Result<Parts, String> {
    let Some(provoking) = provoking else {
        return Err("no glProvokingVertex (GL 3.2)".to_owned());
    };
    // SAFETY: glProvokingVertex(GLenum) is this entry point's signature.
    let provoking: unsafe extern "system" fn(u32) = std::mem::transmute(provoking);
    provoking(glow::FIRST_VERTEX_CONVENTION);
    let mut dims = [0i32; 2];
    gl.get_parameter_i32_slice(glow::MAX_VIEWPORT_DIMS, &mut dims);
    let max_side = gl
        .get_parameter_i32(glow::MAX_RENDERBUFFER_SIZE)
        .min(dims[0])
        .min(dims[1])
        .max(0) as u32;
    let draw_buffers = gl.get_parameter_i32(glow::MAX_DRAW_BUFFERS);
    if draw_buffers < 1 + GROUPS as i32 {
        return Err(format!("only {draw_buffers} draw buffers"));
    }
    let programs = [
        program(gl, Interpolation::Perspective)?,
        program(gl, Interpolation::Linear)?,
        program(gl, Interpolation::Flat)?,
    ];
    gl.disable(glow::DEPTH_TEST);
    gl.disable(glow::DITHER);
    gl.front_face(glow::CCW);
    gl.blend_func(glow::ONE, glow::ONE);
    gl.blend_equation(glow::FUNC_ADD);
    gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
    if let Some(e) = gl_error(gl) {
        return Err(format!("setting up: GL error {e:#x}"));
    }
    Ok((max_side, programs))
}

/// The first pending GL error, clearing the rest.
unsafe fn gl_error(gl: &glow::Context) -> Option<u32> {
    let first = gl.get_error();
    if first == glow::NO_ERROR {
        return None;
    }
    for _ in 0..16 {
        if gl.get_error() == glow::NO_ERROR {
            break;
        }
    }
    Some(first)
}

/// Compiles and links the program for one interpolation mode.
unsafe fn program(gl: &glow::Context, mode: Interpolation) -> Result<glow::Program, String> {
    let (vs, fs) = shaders(mode);
    let program = gl.create_program()?;
    let mut shaders = Vec::new();
    for (kind, source) in [(glow::VERTEX_SHADER, vs), (glow::FRAGMENT_SHADER, fs)] {
        let shader = gl.create_shader(kind)?;
        gl.shader_source(shader, &source);
        gl.compile_shader(shader);
        if !gl.get_shader_compile_status(shader) {
            return Err(format!(
                "compiling the {} shader: {}",
                mode.name(),
                gl.get_shader_info_log(shader)
            ));
        }
        gl.attach_shader(program, shader);
        shaders.push(shader);
    }
    gl.link_program(program);
    if !gl.get_program_link_status(program) {
        return Err(format!(
            "linking the {} program: {}",
            mode.name(),
            gl.get_program_info_log(program)
        ));
    }
    for shader in shaders {
        gl.detach_shader(program, shader);
        gl.delete_shader(shader);
    }
    Ok(program)
}

/// The GLSL 3.30 pair for one interpolation mode: a pass-through vertex
/// shader, and a fragment shader writing 1 to the count and the channels to
/// the groups.
fn shaders(mode: Interpolation) -> (String, String) {
    let qualifier = match mode {
        Interpolation::Perspective => "smooth",
        Interpolation::Linear => "noperspective",
        Interpolation::Flat => "flat",
    };
    let vs = format!(
        "#version 330 core
layout(location = 0) in vec4 position;
layout(location = 1) in vec4 info;
layout(location = 2) in vec4 a0;
layout(location = 3) in vec4 a1;
layout(location = 4) in vec4 a2;
layout(location = 5) in vec4 a3;
flat out float prim;
noperspective out float depth;
{qualifier} out vec4 v0;
{qualifier} out vec4 v1;
{qualifier} out vec4 v2;
{qualifier} out vec4 v3;
void main() {{
    gl_Position = position;
    prim = info.x;
    depth = info.y;
    v0 = a0;
    v1 = a1;
    v2 = a2;
    v3 = a3;
}}
"
    );
    let fs = format!(
        "#version 330 core
flat in float prim;
noperspective in float depth;
{qualifier} in vec4 v0;
{qualifier} in vec4 v1;
{qualifier} in vec4 v2;
{qualifier} in vec4 v3;
layout(location = 0) out float count;
layout(location = 1) out vec4 g0;
layout(location = 2) out vec4 g1;
layout(location = 3) out vec4 g2;
layout(location = 4) out vec4 g3;
layout(location = 5) out vec4 g4;
void main() {{
    count = 1.0;
    g0 = vec4(prim, depth, v0.xy);
    g1 = vec4(v0.zw, v1.xy);
    g2 = vec4(v1.zw, v2.xy);
    g3 = vec4(v2.zw, v3.xy);
    g4 = vec4(v3.zw, 0.0, 0.0);
}}
"
    );
    (vs, fs)
}

fn f32_bytes(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}
