//! The programs: a GLSL 3.30 pair per interpolation mode, compiled and
//! linked once per context (and `msaa.rs`'s fetch program, linked here).

use glow::HasContext;

use crate::scene::Interpolation;

/// The vertex shaders' uniform written to `gl_PointSize`: the size of the
/// points a run draws (`GL_PROGRAM_POINT_SIZE` on for points only).
pub(super) const POINT_SIZE_UNIFORM: &str = "point_size";

/// Compiles and links the program for one interpolation mode.
pub(super) unsafe fn program(
    gl: &glow::Context,
    mode: Interpolation,
) -> Result<glow::Program, String> {
    let (vs, fs) = shaders(mode);
    link(gl, mode.name(), &vs, &fs)
}

/// Compiles and links a vertex and fragment shader pair; `name` says
/// which in a failure.
pub(super) unsafe fn link(
    gl: &glow::Context,
    name: &str,
    vs: &str,
    fs: &str,
) -> Result<glow::Program, String> {
    let program = gl.create_program()?;
    let mut shaders = Vec::new();
    for (kind, source) in [(glow::VERTEX_SHADER, vs), (glow::FRAGMENT_SHADER, fs)] {
        let shader = gl.create_shader(kind)?;
        gl.shader_source(shader, source);
        gl.compile_shader(shader);
        if !gl.get_shader_compile_status(shader) {
            return Err(format!(
                "compiling the {name} shader: {}",
                gl.get_shader_info_log(shader)
            ));
        }
        gl.attach_shader(program, shader);
        shaders.push(shader);
    }
    gl.link_program(program);
    if !gl.get_program_link_status(program) {
        return Err(format!(
            "linking the {name} program: {}",
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
uniform float {POINT_SIZE_UNIFORM};
flat out float prim;
noperspective out float depth;
flat out vec2 range;
{qualifier} out vec4 v0;
{qualifier} out vec4 v1;
{qualifier} out vec4 v2;
{qualifier} out vec4 v3;
void main() {{
    gl_Position = position;
    gl_PointSize = {POINT_SIZE_UNIFORM};
    prim = info.x;
    depth = info.y;
    range = info.zw;
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
flat in vec2 range;
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
    // Screen space: the depth varying; clip space (range.x <= range.y):
    // the driver's own depth, clamped to the viewport's range.
    float z = range.x <= range.y ? clamp(gl_FragCoord.z, range.x, range.y) : depth;
    g0 = vec4(prim, z, v0.xy);
    g1 = vec4(v0.zw, v1.xy);
    g2 = vec4(v1.zw, v2.xy);
    g3 = vec4(v2.zw, v3.xy);
    g4 = vec4(v3.zw, 0.0, 0.0);
}}
"
    );
    (vs, fs)
}
