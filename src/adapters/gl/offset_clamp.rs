//! `glPolygonOffsetClamp`: the entry point a context offers for a
//! clamped polygon offset, looked up once when the context is made.

use glow::HasContext;

/// `glPolygonOffsetClamp(GLfloat factor, GLfloat units, GLfloat clamp)`.
pub(super) type OffsetClampFn = unsafe extern "system" fn(f32, f32, f32);

/// The context's polygon offset clamp entry point, where its version or
/// extensions offer one (`load` is EGL's `get_proc_address`; Mesa hands
/// out entry points for functions a context does not support, so the
/// version and extension strings decide).
pub(super) unsafe fn offset_clamp(
    gl: &glow::Context,
    load: impl Fn(&str) -> Option<extern "system" fn()>,
) -> Option<OffsetClampFn> {
    let version = gl.version();
    let extensions = gl.supported_extensions();
    let name = if (version.major, version.minor) >= (4, 6)
        || extensions.contains("GL_ARB_polygon_offset_clamp")
    {
        "glPolygonOffsetClamp"
    } else if extensions.contains("GL_EXT_polygon_offset_clamp") {
        "glPolygonOffsetClampEXT"
    } else {
        return None;
    };
    // SAFETY: glPolygonOffsetClamp(EXT)(GLfloat, GLfloat, GLfloat) is this
    // entry point's signature.
    load(name).map(|f| std::mem::transmute::<extern "system" fn(), OffsetClampFn>(f))
}
