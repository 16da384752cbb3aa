//! lavapipe's WGSL: the fragment entry points that draw a case's triangles
//! into the count and channel-group targets, over the interface the Vulkan
//! adapters share (`gpu/wgsl.rs`, which also has the pass that spreads a 4×
//! target's samples out). Text only; the pipelines are `pipelines.rs`'s.

use crate::scene::Interpolation;

use super::super::gpu::{wgsl, GROUPS};

/// The WGSL for one interpolation mode: the shared interface, and one
/// fragment entry point per group of four channels (`fs_0` also writes 1
/// to the additive count target, in the same pass). `per_sample`
/// interpolates at each sample (`wgsl::interface`).
pub(super) fn shader(mode: Interpolation, per_sample: bool) -> String {
    let channels = wgsl::channels();
    let mut wgsl = wgsl::interface(mode, per_sample);
    wgsl.push_str(&format!(
        "
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
    ));
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
