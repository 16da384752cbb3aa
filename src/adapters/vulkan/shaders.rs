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
/// (`wgsl::interface`); `point_size` makes `vs` write that `PointSize`
/// (`point_vertex`), for point lists.
pub(super) fn spirv(
    mode: Interpolation,
    groups: usize,
    per_sample: bool,
    point_size: Option<f32>,
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
    if let Some(size) = point_size {
        source = point_vertex(&source, size)?;
    }
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
pub(super) fn unpack_spirv(n: u32, depth: bool) -> Result<Vec<u32>, String> {
    compile(&wgsl::unpack(n, depth))
}

/// Where `point_vertex` puts the point size before `compile` makes it the
/// `PointSize` built-in.
const SIZE_LOCATION: u32 = 15;

/// The shared interface with `vs` returning `PointVaryings`: `Varyings`
/// (every varying as it is, so `fs` still matches) plus `size` at
/// `SIZE_LOCATION`, the constant `size` in pixels. WGSL has no point size
/// built-in; `compile` rebinds that member to SPIR-V's `PointSize` in
/// naga's IR, which the SPIR-V writer emits as any built-in. (naga's
/// `FORCE_POINT_SIZE` writes 1.0 only; patching the SPIR-V words, or the
/// GLSL front end, would be more fragile or a second shading language.)
fn point_vertex(source: &str, size: f32) -> Result<String, String> {
    let missing = |what: &str| format!("the shared WGSL has no {what}");
    let start = source
        .find("struct Varyings {")
        .ok_or_else(|| missing("Varyings"))?;
    let end = start
        + source[start..]
            .find("\n}\n")
            .ok_or_else(|| missing("Varyings' end"))?;
    let members = &source[start + "struct Varyings {".len()..end];
    let returns = "-> Varyings {\n    return Varyings(";
    let ends = "v.info.zw);";
    if !source.contains(returns) || !source.contains(ends) {
        return Err(missing("`vs` returning Varyings"));
    }
    let vs = source
        .replace(returns, "-> PointVaryings {\n    return PointVaryings(")
        .replace(ends, &format!("v.info.zw, {size:?});"));
    Ok(format!(
        "struct PointVaryings {{{members}\n    @location({SIZE_LOCATION}) size: f32,\n}}\n\n{vs}"
    ))
}

/// Rebinds `PointVaryings.size` (`point_vertex`) to the `PointSize`
/// built-in; a module without the struct is left as it is.
fn bind_point_size(module: &mut naga::Module) {
    let found = module.types.iter().find_map(|(handle, ty)| {
        (ty.name.as_deref() == Some("PointVaryings")).then(|| (handle, ty.clone()))
    });
    let Some((handle, mut ty)) = found else {
        return;
    };
    if let naga::TypeInner::Struct { members, .. } = &mut ty.inner {
        for member in members {
            if matches!(member.binding, Some(naga::Binding::Location { location, .. })
                if location == SIZE_LOCATION)
            {
                member.binding = Some(naga::Binding::BuiltIn(naga::BuiltIn::PointSize));
            }
        }
    }
    module.types.replace(handle, ty);
}

fn compile(source: &str) -> Result<Vec<u32>, String> {
    let mut module =
        naga::front::wgsl::parse_str(source).map_err(|e| format!("WGSL: {}", e.message()))?;
    bind_point_size(&mut module);
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
                for (per_sample, size) in [(false, None), (true, None), (false, Some(2.5))] {
                    let words = spirv(mode, groups, per_sample, size).unwrap();
                    assert_eq!(words[0], 0x0723_0203, "SPIR-V magic");
                }
            }
        }
    }

    #[test]
    fn the_unpack_pass_compiles() {
        for n in [2, 4, 8, 16] {
            for depth in [false, true] {
                assert_eq!(unpack_spirv(n, depth).unwrap()[0], 0x0723_0203);
            }
        }
    }
}
