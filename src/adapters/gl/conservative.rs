//! Conservative rasterization in GL (SPEC.md §19): GL offers it only
//! through `GL_NV_conservative_raster` or
//! `GL_INTEL_conservative_rasterization`, which this adapter does not
//! drive; a conservative case is refused with what the context offers, so
//! that llvmpipe's refusal names the missing extensions, and a context
//! that offers one says that the adapter does not drive it yet.

use std::collections::HashSet;

use glow::HasContext;

use super::context::GlContext;

/// The extensions that draw conservatively in GL.
pub(super) const EXTENSIONS: [&str; 2] = [
    "GL_NV_conservative_raster",
    "GL_INTEL_conservative_rasterization",
];

/// Why the context does not draw a conservative case.
pub(super) fn refusal(gl: &GlContext) -> String {
    why(gl.gl.supported_extensions(), &gl.renderer)
}

fn why(extensions: &HashSet<String>, renderer: &str) -> String {
    match EXTENSIONS.iter().find(|e| extensions.contains(**e)) {
        Some(e) => format!(
            "conservative rasterization: {renderer} offers {e}, which this adapter does not \
             drive yet"
        ),
        None => format!(
            "conservative rasterization: the driver, {renderer}, offers neither {} nor {}",
            EXTENSIONS[0], EXTENSIONS[1]
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_refusal_names_what_the_context_offers() {
        let none = why(&HashSet::new(), "llvmpipe (LLVM 15.0.6, 256 bits)");
        assert_eq!(
            none,
            "conservative rasterization: the driver, llvmpipe (LLVM 15.0.6, 256 bits), offers \
             neither GL_NV_conservative_raster nor GL_INTEL_conservative_rasterization"
        );
        let nv: HashSet<String> = ["GL_NV_conservative_raster".to_owned()].into();
        assert!(why(&nv, "NVIDIA H100").contains("does not drive yet"));
    }
}
