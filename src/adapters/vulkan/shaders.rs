//! The adapter's shaders: the Vulkan adapters' shared WGSL (`gpu/wgsl.rs`)
//! with this adapter's fragment shader, compiled to SPIR-V by naga (the
//! compiler wgpu uses).
//!
//! The fragment shader writes 1 to the additive count (location 0) and
//! the channels `[primitive + 1, depth, attribute 0, …]` four at a time to
//! locations 1 … groups, all in one pass. naga's SPIR-V writer flips y
//! (`ADJUST_COORDINATE_SPACE`), as it does for wgpu: the stream's
//! `y_ndc = 1 − 2y/Q` lands on framebuffer row y, exactly (a negation).

use crate::scene::Interpolation;

use super::super::gpu::wgsl;

/// The SPIR-V of the module with entry points `vs` and `fs`; `per_sample`
/// interpolates at each sample of a multisampled target
/// (`wgsl::interface`).
pub(super) fn spirv(
    mode: Interpolation,
    groups: usize,
    per_sample: bool,
) -> Result<Vec<u32>, String> {
    let channels = wgsl::channels();
    let fields: String = (0..groups)
        .map(|g| format!("    @location({}) g{g}: vec4<f32>,\n", g + 1))
        .collect();
    let values: String = channels[..groups * 4]
        .chunks(4)
        .map(|c| format!(", vec4<f32>({}, {}, {}, {})", c[0], c[1], c[2], c[3]))
        .collect();
    let mut source = wgsl::interface(mode, per_sample);
    source.push_str(&format!(
        "
struct Out {{
    @location(0) count: f32,
{fields}}}

@fragment
fn fs(v: Varyings) -> Out {{
    return Out(1.0{values});
}}
"
    ));
    compile(&source)
}

/// The SPIR-V of the read-back pass of an `n`-sample target
/// (`wgsl::unpack`).
pub(super) fn unpack_spirv(n: u32) -> Result<Vec<u32>, String> {
    compile(&wgsl::unpack(n))
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
