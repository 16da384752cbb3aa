//! The fetch program: a full-screen triangle that `texelFetch`es one
//! sample of a multisample texture into a single-sample copy, made once
//! per context for `msaa.rs`'s per-sample read-back.

use glow::HasContext;

use super::shaders;

/// The fetch program's pair: a full-screen triangle from `gl_VertexID`,
/// and one sample of a multisample texture written out.
pub(super) const FETCH_SHADERS: (&str, &str) = (
    "#version 330 core
void main() {
    vec2 p = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1)) - 1.0;
    gl_Position = vec4(p, 0.0, 1.0);
}
",
    "#version 330 core
uniform sampler2DMS source;
uniform int slot;
layout(location = 0) out vec4 value;
void main() {
    value = texelFetch(source, ivec2(gl_FragCoord.xy), slot);
}
",
);

/// The fetch program, its uniforms, and an empty vertex array to draw it
/// with (core profile draws need one bound).
pub(super) struct Fetch {
    pub program: glow::Program,
    pub source: Option<glow::UniformLocation>,
    pub sample: Option<glow::UniformLocation>,
    pub vao: glow::VertexArray,
}

/// Makes the fetch program on the current context.
pub(super) unsafe fn fetch(gl: &glow::Context) -> Result<Fetch, String> {
    let program = shaders::link(gl, "fetch", FETCH_SHADERS.0, FETCH_SHADERS.1)?;
    Ok(Fetch {
        source: gl.get_uniform_location(program, "source"),
        sample: gl.get_uniform_location(program, "slot"),
        program,
        vao: gl.create_vertex_array()?,
    })
}
