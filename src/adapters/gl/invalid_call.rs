//! A deliberately invalid GL call in a debug context of its own, for the
//! test that shows the API record hears what KHR_debug says (tests/gl/).
//! The process's shared context and its record are not touched.

use std::ffi::c_void;

use glow::HasContext;

use super::context::{context, gl_error};
use super::debug::{self, DEBUG_CONTEXT};
use crate::rasterizer::ApiRecord;

/// The name the driver's message gives the invalid call's error.
pub const INVALID_CALL_ERROR: &str = "GL_INVALID_ENUM";

/// Makes a second debug context on the shared display, calls `glEnable`
/// with an enum no GL defines (`GL_INVALID_ENUM`: the call does nothing),
/// clears the error, destroys the context, and returns what its KHR_debug
/// callback heard.
pub fn invalid_call_record() -> Result<ApiRecord, String> {
    let shared = context().map_err(|why| why.clone())?;
    let shared = shared.lock().unwrap_or_else(|e| e.into_inner());
    let (egl, display) = (&shared.egl, shared.display);
    let attributes = [
        khronos_egl::CONTEXT_MAJOR_VERSION,
        3,
        khronos_egl::CONTEXT_MINOR_VERSION,
        3,
        khronos_egl::CONTEXT_OPENGL_PROFILE_MASK,
        khronos_egl::CONTEXT_OPENGL_CORE_PROFILE_BIT,
        DEBUG_CONTEXT[0],
        DEBUG_CONTEXT[1],
        khronos_egl::NONE,
    ];
    // The bound API is per thread: this one may not have bound GL yet.
    egl.bind_api(khronos_egl::OPENGL_API)
        .map_err(|e| format!("EGL: no desktop OpenGL API: {e}"))?;
    let own = egl
        .create_context(display, shared.config, None, &attributes)
        .map_err(|e| format!("EGL: creating a second debug context: {e}"))?;
    let record = egl
        .make_current(display, None, None, Some(own))
        .map_err(|e| format!("EGL: making the second context current: {e}"))
        .map(|()| {
            // SAFETY: the second context is current on this thread; the
            // enum is invalid on purpose, and GL ignores such a call.
            unsafe {
                let mut gl = glow::Context::from_loader_function(|name| {
                    egl.get_proc_address(name)
                        .map_or(std::ptr::null(), |f| f as *const c_void)
                });
                let record = debug::listen(&mut gl);
                gl.enable(0xFFFF);
                let _ = gl_error(&gl);
                debug::snapshot(&record)
            }
        });
    let _ = egl.make_current(display, None, None, None);
    let _ = egl.destroy_context(display, own);
    record
}
