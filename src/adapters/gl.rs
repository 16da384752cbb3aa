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

use std::ffi::c_void;
use std::sync::{Mutex, OnceLock};

use glow::HasContext;
use khronos_egl as egl;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
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
        draw(scene, plan, false)
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
        draw(scene, plan, true)
    }
}

fn capabilities() -> Capabilities {
    gpu::capabilities(false)
}

fn draw(scene: &Scene, plan: &Plan, softpipe: bool) -> Result<Frame, RasterError> {
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
    let gl = context().map_err(|why| RasterError::Failed(why.clone()))?;
    let mut gl = gl.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    if softpipe && !gl.renderer.contains("softpipe") {
        return Err(RasterError::Failed(format!(
            "softpipe: this process's GL is {} (Mesa picks one gallium driver per process); \
             start it with GALLIUM_DRIVER=softpipe",
            gl.renderer
        )));
    }
    gl.render(scene, plan, bits)
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
    vao: glow::VertexArray,
    vbo: glow::Buffer,
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
            let made = set_up(&gl, provoking);
            (renderer, version, made)
        };
        let _ = egl.make_current(display, None, None, None);
        let (max_side, vao, vbo, programs) =
            made.map_err(|e| format!("OpenGL ({renderer}, {version}): {e}"))?;
        Ok(GlContext {
            egl,
            display,
            context,
            gl,
            renderer,
            version,
            max_side,
            vao,
            vbo,
            programs,
        })
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

    fn render(&mut self, scene: &Scene, plan: &Plan, bits: u32) -> Result<Frame, RasterError> {
        let (tw, th) = gpu::target_size(scene, self.max_side, &self.renderer)?;
        let groups = gpu::groups(plan);
        let (vertices, runs) = gpu::vertex_stream(scene, bits, (tw, th));

        self.bind()?;
        // SAFETY: GL calls on the context current on this thread, with
        // buffers sized to what is read and written.
        let result = unsafe { self.draw_and_read(scene, plan, &vertices, &runs, groups) };
        let _ = self.egl.make_current(self.display, None, None, None);
        result
    }

    unsafe fn draw_and_read(
        &self,
        scene: &Scene,
        plan: &Plan,
        vertices: &[f32],
        runs: &[(Interpolation, u32, u32)],
        groups: usize,
    ) -> Result<Frame, RasterError> {
        let gl = &self.gl;
        let (w, h) = (scene.canvas.width, scene.canvas.height);
        let (tw, th) = (w.next_power_of_two(), h.next_power_of_two());
        let failed = |what: &str| RasterError::Failed(format!("{}: {what}", self.renderer));
        let _ = gl_error(gl);

        let fbo = gl.create_framebuffer().map_err(|e| failed(&e))?;
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
        let mut renderbuffers = Vec::with_capacity(1 + groups);
        for k in 0..=groups {
            let rb = gl.create_renderbuffer().map_err(|e| failed(&e))?;
            gl.bind_renderbuffer(glow::RENDERBUFFER, Some(rb));
            let format = if k == 0 { glow::R32F } else { glow::RGBA32F };
            gl.renderbuffer_storage(glow::RENDERBUFFER, format, tw as i32, th as i32);
            gl.framebuffer_renderbuffer(
                glow::FRAMEBUFFER,
                glow::COLOR_ATTACHMENT0 + k as u32,
                glow::RENDERBUFFER,
                Some(rb),
            );
            renderbuffers.push(rb);
        }
        let cleanup = || {
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            gl.delete_framebuffer(fbo);
            for rb in &renderbuffers {
                gl.delete_renderbuffer(*rb);
            }
        };
        let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
        if status != glow::FRAMEBUFFER_COMPLETE {
            cleanup();
            return Err(failed(&format!(
                "float framebuffer {tw}×{th} incomplete ({status:#x})"
            )));
        }
        let buffers: Vec<u32> = (0..=groups as u32)
            .map(|k| glow::COLOR_ATTACHMENT0 + k)
            .collect();
        gl.draw_buffers(&buffers);
        gl.disable(glow::SCISSOR_TEST);
        for k in 0..=groups as u32 {
            gl.clear_buffer_f32_slice(glow::COLOR, k, &[0.0; 4]);
        }
        gl.viewport(0, 0, tw as i32, th as i32);
        gl.enable(glow::SCISSOR_TEST);
        gl.scissor(0, (th - h) as i32, w as i32, h as i32);
        gl.disable(glow::BLEND);
        gl.enable_draw_buffer(glow::BLEND, 0);
        match scene.rules.cull {
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
        gl.bind_vertex_array(Some(self.vao));
        gl.bind_buffer(glow::ARRAY_BUFFER, Some(self.vbo));
        gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &f32_bytes(vertices), glow::STREAM_DRAW);
        for &(mode, a, b) in runs {
            let program = match mode {
                Interpolation::Perspective => self.programs[0],
                Interpolation::Linear => self.programs[1],
                Interpolation::Flat => self.programs[2],
            };
            gl.use_program(Some(program));
            // Vertex counts are bounded by the primitive limit (SPEC §8).
            gl.draw_arrays(glow::TRIANGLES, a as i32, (b - a) as i32);
        }

        // Read the canvas (the top W × H of the target) back, flipping rows.
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
        let values: Vec<Vec<f32>> = (1..=groups as u32).map(|k| read(k, 4)).collect();
        let error = gl_error(gl);
        cleanup();
        if let Some(e) = error {
            return Err(failed(&format!("GL error {e:#x}")));
        }

        let mut frame = Frame::new(w, h, plan.depth, plan.attributes);
        let channel = |c: usize, i: usize| values[c / 4][i * 4 + c % 4];
        for i in 0..n {
            let c = counts[i];
            if c.fract() != 0.0 || !(0.0..=65535.0).contains(&c) {
                return Err(failed(&format!(
                    "coverage count {c} read back at sample {i}"
                )));
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
}

/// What one context keeps: the largest target side, the vertex array and
/// buffer, and the three programs.
type Parts = (u32, glow::VertexArray, glow::Buffer, [glow::Program; 3]);

/// Sets up the current context: first-vertex provoking, the vertex layout,
/// the programs and the fixed state.
unsafe fn set_up(
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
    let vao = gl.create_vertex_array()?;
    let vbo = gl.create_buffer()?;
    gl.bind_vertex_array(Some(vao));
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
    Ok((max_side, vao, vbo, programs))
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
