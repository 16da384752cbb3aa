//! lavapipe's WGSL: the shaders that draw a case's triangles into the count
//! and channel-group targets, and the one that spreads a 4× target's
//! samples out. Text only; the pipelines are `pipelines.rs`'s.

use crate::scene::Interpolation;

use super::super::gpu::{GROUPS, MAX_ATTRIBUTES};

/// Spreads sample s of pixel (x, y) of a 4× multisampled float target to
/// texel (4x + s, y): `textureLoad` with Vulkan's sample index s, which is
/// the standard location s.
pub(super) const UNPACK_SHADER: &str = "
@group(0) @binding(0) var source: texture_multisampled_2d<f32>;

@vertex
fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    // (-1, -1), (3, -1), (-1, 3): one triangle over the whole target.
    return vec4<f32>(f32(i32(i & 1u) * 4 - 1), f32(i32(i >> 1u) * 4 - 1), 0.0, 1.0);
}

@fragment
fn fs(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {
    let texel = vec2<i32>(floor(p.xy));
    return textureLoad(source, vec2<i32>(texel.x / 4, texel.y), texel.x % 4);
}
";

/// The WGSL for one interpolation mode: a pass-through vertex shader, and one
/// fragment entry point per group of four channels (`fs_0` also writes 1 to
/// the additive count target). `per_sample` interpolates depth and the
/// non-flat attributes at each sample's own position (`@interpolate(…,
/// sample)`, which also runs the fragment shader once per sample).
pub(super) fn shader(mode: Interpolation, per_sample: bool) -> String {
    let qualifier = match (mode, per_sample) {
        (Interpolation::Flat, _) | (_, false) => mode.name().to_owned(),
        (_, true) => format!("{}, sample", mode.name()),
    };
    let depth = if per_sample {
        "linear, sample"
    } else {
        "linear"
    };
    let mut channels = vec!["v.prim".to_owned(), "v.depth".to_owned()];
    for k in 0..MAX_ATTRIBUTES {
        channels.push(format!("v.a{}.{}", k / 4, ["x", "y", "z", "w"][k % 4]));
    }
    while channels.len() < GROUPS * 4 {
        channels.push("0.0".to_owned());
    }
    let mut wgsl = format!(
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
}}

@vertex
fn vs(v: VertexIn) -> Varyings {{
    return Varyings(v.position, v.info.x, v.info.y, v.a0, v.a1, v.a2, v.a3);
}}

struct First {{
    @location(0) count: f32,
    @location(1) values: vec4<f32>,
}}

@fragment
fn fs_0(v: Varyings) -> First {{
    return First(1.0, vec4<f32>({}, {}, {}, {}));
}}
",
        channels[0], channels[1], channels[2], channels[3]
    );
    for g in 1..GROUPS {
        let c = &channels[g * 4..g * 4 + 4];
        wgsl.push_str(&format!(
            "
@fragment
fn fs_{g}(v: Varyings) -> @location(0) vec4<f32> {{
    return vec4<f32>({}, {}, {}, {});
}}
",
            c[0], c[1], c[2], c[3]
        ));
    }
    wgsl
}
