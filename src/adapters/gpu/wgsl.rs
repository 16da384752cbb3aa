//! The WGSL the Vulkan adapters share (`lavapipe` hands it to wgpu,
//! `vulkan` compiles it to SPIR-V with naga): the vertex interface and
//! pass-through vertex shader of the drawing pipelines, the channel each
//! fragment output carries, and the pass that spreads a multisampled
//! target's samples out. Text only; each adapter adds its fragment entry
//! points and makes its own pipelines.

use super::channels::{GROUPS, MAX_ATTRIBUTES};
use crate::scene::Interpolation;

/// The vertex input (the stream's six vec4s), the varyings with the case's
/// interpolation, and `vs`, which passes the vertex through. `per_sample`
/// interpolates depth and the non-flat attributes at each sample's own
/// position (`@interpolate(…, sample)`, which also runs the fragment
/// shader once per sample).
pub(crate) fn interface(mode: Interpolation, per_sample: bool) -> String {
    let qualifier = match (mode, per_sample) {
        (Interpolation::Flat, _) | (_, false) => mode.name().to_owned(),
        (_, true) => format!("{}, sample", mode.name()),
    };
    let depth = if per_sample {
        "linear, sample"
    } else {
        "linear"
    };
    format!(
        "struct VertexIn {{
    @location(0) position: vec4<f32>,
    @location(1) info: vec4<f32>,
    @location(2) a0: vec4<f32>,
    @location(3) a1: vec4<f32>,
    @location(4) a2: vec4<f32>,
    @location(5) a3: vec4<f32>,
}}

struct Varyings {{
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) prim: f32,
    @location(1) @interpolate({depth}) depth: f32,
    @location(2) @interpolate({qualifier}) a0: vec4<f32>,
    @location(3) @interpolate({qualifier}) a1: vec4<f32>,
    @location(4) @interpolate({qualifier}) a2: vec4<f32>,
    @location(5) @interpolate({qualifier}) a3: vec4<f32>,
    @location(6) @interpolate(flat) range: vec2<f32>,
}}

@vertex
fn vs(v: VertexIn) -> Varyings {{
    return Varyings(v.position, v.info.x, v.info.y, v.a0, v.a1, v.a2, v.a3, v.info.zw);
}}
"
    )
}

/// The expression of each channel `[primitive + 1, depth, attribute 0, …]`
/// in a fragment shader over `Varyings v`, padded with zeros to
/// `GROUPS` groups of four. Depth is the `depth` varying in screen space,
/// the fragment's own depth clamped to `range` in clip space (the
/// stream's `[lo, hi]`, `gpu::stream`).
pub(crate) fn channels() -> Vec<String> {
    let depth =
        "select(v.depth, clamp(v.position.z, v.range.x, v.range.y), v.range.x <= v.range.y)";
    let mut channels = vec!["v.prim".to_owned(), depth.to_owned()];
    for k in 0..MAX_ATTRIBUTES {
        channels.push(format!("v.a{}.{}", k / 4, ["x", "y", "z", "w"][k % 4]));
    }
    channels.resize(GROUPS * 4, "0.0".to_owned());
    channels
}

/// The read-back pass of an `n`-sample target: texel (n·x + s, y) of a
/// single-sample target n times wider gets sample s of pixel (x, y)
/// (`textureLoad` with sample index s, which is standard location s). A
/// `depth` target is read as a depth texture, its value in the red
/// channel.
pub(crate) fn unpack(n: u32, depth: bool) -> String {
    let sample = format!("textureLoad(source, at, texel.x % {n})");
    let (source, load) = if depth {
        (
            "texture_depth_multisampled_2d",
            format!("vec4<f32>({sample}, 0.0, 0.0, 0.0)"),
        )
    } else {
        ("texture_multisampled_2d<f32>", sample)
    };
    format!(
        "@group(0) @binding(0) var source: {source};

@vertex
fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {{
    // (-1, -1), (3, -1), (-1, 3): one triangle over the whole target.
    return vec4<f32>(f32(i32(i & 1u) * 4 - 1), f32(i32(i >> 1u) * 4 - 1), 0.0, 1.0);
}}

@fragment
fn fs(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {{
    let texel = vec2<i32>(floor(p.xy));
    let at = vec2<i32>(texel.x / {n}, texel.y);
    return {load};
}}
"
    )
}
