//! The shared context: one EGL display and OpenGL context per process,
//! made on first use, locked and made current for each case (or phase),
//! and the state every drawing relies on.

use std::ffi::c_void;
use std::sync::{Mutex, OnceLock};

use glow::HasContext;
use khronos_egl as egl;

use super::clip::{self, ProvokingFn};
use super::debug::{self, DEBUG_CONTEXT};
use super::fetch::{self, Fetch};
use super::offset_clamp;
use super::samples::{self, DriverSamples};
use super::shaders::program;
use crate::adapters::gpu::{self, GROUPS};
use crate::rasterizer::RasterError;
use crate::scene::Interpolation;

/// What to install when no display or driver is found.
const INSTALL_HINT: &str =
    "install libegl1 libegl-mesa0 libgl1-mesa-dri (Debian/Ubuntu) so that EGL finds Mesa's llvmpipe";

/// `EGL_PLATFORM_SURFACELESS_MESA`.
const PLATFORM_SURFACELESS_MESA: egl::Enum = 0x31DD;

/// Runs `f` with the shared context locked and current on this thread,
/// and releases the context after, whatever `f` returns: the cases (and
/// the phases of a prepared scene) take turns.
pub(super) fn with_context<T>(
    f: impl FnOnce(&GlContext) -> Result<T, RasterError>,
) -> Result<T, RasterError> {
    let gl = context().map_err(|why| RasterError::Failed(why.clone()))?;
    let gl = gl.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    gl.bind()?;
    let result = f(&gl);
    let _ = gl.egl.make_current(gl.display, None, None, None);
    result
}

/// Sets `GALLIUM_DRIVER=softpipe` when no display exists yet and the
/// variable is unset, so that a process that asks for softpipe first gets it.
pub(super) fn ask_for_softpipe() {
    if CONTEXT.get().is_none() && std::env::var_os("GALLIUM_DRIVER").is_none() {
        // Before Mesa is loaded: nothing outside Rust's own locked
        // environment access reads the variable yet.
        std::env::set_var("GALLIUM_DRIVER", "softpipe");
    }
}

static CONTEXT: OnceLock<Result<Mutex<GlContext>, String>> = OnceLock::new();

/// The renderer, "`GL_RENDERER` (`GL_VERSION`)", where this process has
/// made its context; nothing is made.
pub(super) fn existing_description() -> Option<String> {
    existing(|gl| format!("{} ({})", gl.renderer, gl.version))
}

/// What `f` reads of the context, where this process has made it; nothing
/// is made.
pub(super) fn existing<T>(f: impl FnOnce(&GlContext) -> T) -> Option<T> {
    let gl = CONTEXT.get()?.as_ref().ok()?;
    let gl = gl.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    Some(f(&gl))
}

pub(super) fn context() -> Result<&'static Mutex<GlContext>, &'static String> {
    CONTEXT
        .get_or_init(|| GlContext::new().map(Mutex::new))
        .as_ref()
}

type Egl = egl::DynamicInstance<egl::EGL1_5>;

pub(super) struct GlContext {
    pub(super) egl: Egl,
    pub(super) display: egl::Display,
    /// The config the context was made with (`invalid_call.rs` makes
    /// another with it).
    pub(super) config: egl::Config,
    pub(super) context: egl::Context,
    /// What the context's KHR_debug callback heard (`debug.rs`).
    pub(super) record: debug::Shared,
    pub(super) gl: glow::Context,
    pub(super) renderer: String,
    pub(super) version: String,
    pub(super) max_side: u32,
    pub(super) programs: [glow::Program; 3],
    /// The per-sample read-back of multisampled drawings.
    pub(super) fetch: Fetch,
    /// `GL_MAX_SAMPLES`.
    pub(super) max_samples: u32,
    /// The driver's sample counts and positions.
    pub(super) offered: Vec<DriverSamples>,
    /// `glProvokingVertex`, set for each scene (`clip.rs`).
    pub(super) provoking: ProvokingFn,
    /// What the context offers for clip space (`clip.rs`).
    pub(super) clip: clip::Offers,
    /// `GL_POINT_SIZE_RANGE` and `GL_POINT_SIZE_GRANULARITY`.
    pub(super) point_range: [f32; 2],
    pub(super) point_granularity: f32,
    /// `GL_SUBPIXEL_BITS`: the bits the driver snaps window coordinates to.
    pub(super) subpixel_bits: u32,
    /// `glPolygonOffsetClamp` (GL 4.6, ARB_polygon_offset_clamp) or
    /// `glPolygonOffsetClampEXT`, where the context offers one: a depth
    /// bias with a clamp needs it (`depth.rs`).
    pub(super) offset_clamp: Option<offset_clamp::OffsetClampFn>,
}

// SAFETY: the EGL handles are plain pointers that EGL lets any thread use;
// the context is made current only while the mutex is held, and released
// before it is let go.
unsafe impl Send for GlContext {}

impl GlContext {
    fn new() -> Result<GlContext, String> {
        gpu::quiet_mesa();
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
                    DEBUG_CONTEXT[0],
                    DEBUG_CONTEXT[1],
                    egl::NONE,
                ],
            )
            .map_err(|e| fail("creating an OpenGL 3.3 core debug context", e))?;
        egl.make_current(display, None, None, Some(context))
            .map_err(|e| fail("making the context current (surfaceless)", e))?;
        // SAFETY: the context is current; the loader returns its entry points.
        let mut gl = unsafe {
            glow::Context::from_loader_function(|name| {
                egl.get_proc_address(name)
                    .map_or(std::ptr::null(), |f| f as *const c_void)
            })
        };
        // SAFETY: the context is current.
        let record = unsafe { debug::listen(&mut gl) };
        let provoking = egl.get_proc_address("glProvokingVertex");
        let clip_control = egl.get_proc_address("glClipControl");
        let multisample = egl.get_proc_address("glGetMultisamplefv");
        // SAFETY: plain queries and object creation on the current context.
        let (renderer, version, point_range, point_granularity, subpixel_bits, made) = unsafe {
            let renderer = gl.get_parameter_string(glow::RENDERER);
            let version = gl.get_parameter_string(glow::VERSION);
            let offset_clamp = offset_clamp::offset_clamp(&gl, |name| egl.get_proc_address(name));
            let mut point_range = [0f32; 2];
            gl.get_parameter_f32_slice(glow::POINT_SIZE_RANGE, &mut point_range);
            let point_granularity = gl.get_parameter_f32(glow::POINT_SIZE_GRANULARITY);
            let subpixel_bits = gl.get_parameter_i32(glow::SUBPIXEL_BITS).max(0) as u32;
            let made =
                set_up_context(&gl, provoking).and_then(|(max_side, programs, provoking)| {
                    let fetch = fetch::fetch(&gl)?;
                    let offered = samples::query(&gl, multisample)?;
                    // SAFETY: glClipControl(GLenum, GLenum) is this entry
                    // point's signature.
                    let clip_control = clip_control.map(|f| {
                        std::mem::transmute::<extern "system" fn(), clip::ClipControlFn>(f)
                    });
                    let clip = clip::Offers::set_up(&gl, clip_control);
                    Ok((
                        (max_side, programs, fetch, offered),
                        (provoking, clip, offset_clamp),
                    ))
                });
            (
                renderer,
                version,
                point_range,
                point_granularity,
                subpixel_bits,
                made,
            )
        };
        let _ = egl.make_current(display, None, None, None);
        let ((max_side, programs, fetch, (max_samples, offered)), (provoking, clip, offset_clamp)) =
            made.map_err(|e| format!("OpenGL ({renderer}, {version}): {e}"))?;
        Ok(GlContext {
            egl,
            display,
            config,
            context,
            record,
            gl,
            renderer,
            version,
            max_side,
            programs,
            fetch,
            max_samples,
            offered,
            provoking,
            clip,
            point_range,
            point_granularity,
            subpixel_bits,
            offset_clamp,
        })
    }

    /// Fails where `softpipe` is asked for and this process's GL is
    /// another driver.
    pub(super) fn insist_on_softpipe(&self, softpipe: bool) -> Result<(), RasterError> {
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
    pub(super) fn bind(&self) -> Result<(), RasterError> {
        self.egl
            .make_current(self.display, None, None, Some(self.context))
            .map_err(|e| {
                RasterError::Failed(format!(
                    "{}: making the context current: {e}",
                    self.renderer
                ))
            })
    }

    pub(super) fn failed(&self, what: &str) -> RasterError {
        RasterError::Failed(format!("{}: {what}", self.renderer))
    }

    /// The first pending GL error as a failure of `what`.
    pub(super) unsafe fn check(&self, what: &str) -> Result<(), RasterError> {
        match gl_error(&self.gl) {
            Some(e) => Err(self.failed(&format!("{what}: GL error {e:#x}"))),
            None => Ok(()),
        }
    }
}

/// What one context keeps: the largest target side, the three programs
/// and `glProvokingVertex`.
type Parts = (u32, [glow::Program; 3], ProvokingFn);

/// Sets up the current context: first-vertex provoking, the programs and
/// the fixed state.
pub(super) unsafe fn set_up_context(
    gl: &glow::Context,
    provoking: Option<extern "system" fn()>,
) -> Result<Parts, String> {
    let Some(provoking) = provoking else {
        return Err("no glProvokingVertex (GL 3.2)".to_owned());
    };
    // SAFETY: glProvokingVertex(GLenum) is this entry point's signature.
    let provoking: ProvokingFn = std::mem::transmute(provoking);
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
    Ok((max_side, programs, provoking))
}

/// The first pending GL error, clearing the rest.
pub(super) unsafe fn gl_error(gl: &glow::Context) -> Option<u32> {
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
