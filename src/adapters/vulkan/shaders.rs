//! The adapter's shaders: WGSL text for one interpolation mode and number
//! of channel groups, compiled to SPIR-V by naga (the compiler wgpu uses).
//!
//! The vertex shader passes the stream's vertex through. The fragment
//! shader writes 1 to the additive count (location 0) and the channels
//! `[primitive + 1, depth, attribute 0, …]` four at a time to locations
//! 1 … groups. naga's SPIR-V writer flips y (`ADJUST_COORDINATE_SPACE`),
//! as it does for wgpu: the stream's `y_ndc = 1 − 2y/Q` lands on
//! framebuffer row y, exactly (a negation).

use crate::scene::Interpolation;

use super::super::gpu::MAX_ATTRIBUTES;

/// The SPIR-V of the module with entry points `vs` and `fs`; `per_sample`
/// interpolates depth and the non-flat attributes at each sample of a
/// multisampled target (`@interpolate(…, sample)`, which also runs the
/// fragment shader once per sample).
pub(super) fn spirv(
    mode: Interpolation,
    groups: usize,
    per_sample: bool,
) -> Result<Vec<u32>, String> {
    compile(&wgsl(mode, groups, per_sample))
}

/// The SPIR-V of the read-back pass of an `n`-sample target: texel
/// (n·x + s, y) of a single-sample target n times wider gets sample s of
/// pixel (x, y) (`textureLoad` with sample index s).
pub(super) fn unpack_spirv(n: u32) -> Result<Vec<u32>, String> {
    compile(&format!(
        "@group(0) @binding(0) var source: texture_multisampled_2d<f32>;

@vertex
fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {{
    // (-1, -1), (3, -1), (-1, 3): one triangle over the whole target.
    return vec4<f32>(f32(i32(i & 1u) * 4 - 1), f32(i32(i >> 1u) * 4 - 1), 0.0, 1.0);
}}

@fragment
fn fs(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {{
    let texel = vec2<i32>(floor(p.xy));
    return textureLoad(source, vec2<i32>(texel.x / {n}, texel.y), texel.x % {n});
}}
"
    ))
}

fn compile(source: &str) -> Result<Vec<u32>, String> {
    let module =
        naga::front::wgsl::parse_str(source).map_err(|e| format!("WGSL: {}", e.message()))?;
    let info = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        // `@interpolate(…, sample)`: the adapter enables sampleRateShading.
        naga::valid::Capabilities::MULTISAMPLED_SHADING,
    )
    .validate(&module)
    .map_err(|e| format!("validating WGSL: {e}"))?;
    let options = naga::back::spv::Options {
        lang_version: (1, 0),
        ..Default::default()
    };
    naga::back::spv::write_vec(&module, &info, &options, None)
        .map_err(|e| format!("writing SPIR-V: {e}"))
}

fn wgsl(mode: Interpolation, groups: usize, per_sample: bool) -> String {
    let (qualifier, depth) = match (mode, per_sample) {
        (Interpolation::Flat, true) => ("flat".to_owned(), "linear, sample"),
        (_, true) => (format!("{}, sample", mode.name()), "linear, sample"),
        (_, false) => (mode.name().to_owned(), "linear"),
    };
    let mut channels = vec!["v.prim".to_owned(), "v.depth".to_owned()];
    for k in 0..MAX_ATTRIBUTES {
        channels.push(format!("v.a{}.{}", k / 4, ["x", "y", "z", "w"][k % 4]));
    }
    channels.resize(groups * 4, "0.0".to_owned());
    let fields: String = (0..groups)
        .map(|g| format!("    @location({}) g{g}: vec4<f32>,\n", g + 1))
        .collect();
    let values: String = channels[..groups * 4]
        .chunks(4)
        .map(|c| format!(", vec4<f32>({}, {}, {}, {})", c[0], c[1], c[2], c[3]))
        .collect();
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
}}

@vertex
fn vs(v: VertexIn) -> Varyings {{
    return Varyings(v.position, v.info.x, v.info.y, v.a0, v.a1, v.a2, v.a3);
}}

struct Out {{
    @location(0) count: f32,
{fields}}}

@fragment
fn fs(v: Varyings) -> Out {{
    return Out(1.0{values});
}}
"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_mode_and_group_count_compiles() {
        for mode in [
            Interpolation::Perspective,
            Interpolation::Linear,
            Interpolation::Flat,
        ] {
            for groups in 1..=5 {
                for per_sample in [false, true] {
                    let words = spirv(mode, groups, per_sample).unwrap();
                    assert_eq!(words[0], 0x0723_0203, "SPIR-V magic");
                }
            }
        }
    }

    #[test]
    fn the_unpack_pass_compiles() {
        for n in [2, 4, 8, 16] {
            assert_eq!(unpack_spirv(n).unwrap()[0], 0x0723_0203);
        }
    }
}
