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

/// The SPIR-V of the module with entry points `vs` and `fs`.
pub(super) fn spirv(mode: Interpolation, groups: usize) -> Result<Vec<u32>, String> {
    let source = wgsl(mode, groups);
    let module =
        naga::front::wgsl::parse_str(&source).map_err(|e| format!("WGSL: {}", e.message()))?;
    let info = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::empty(),
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

fn wgsl(mode: Interpolation, groups: usize) -> String {
    let qualifier = mode.name();
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
    @location(1) @interpolate(linear) depth: f32,
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
                let words = spirv(mode, groups).unwrap();
                assert_eq!(words[0], 0x0723_0203, "SPIR-V magic");
            }
        }
    }
}
