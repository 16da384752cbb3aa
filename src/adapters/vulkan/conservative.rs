//! Conservative rasterization through `VK_EXT_conservative_rasterization`
//! (issue 38, SPEC.md §19): what the device offers (its
//! `VkPhysicalDeviceConservativeRasterizationPropertiesEXT`, read where it
//! lists the extension), what a conservative case asks the pipeline for
//! (`VkPipelineRasterizationConservativeStateCreateInfoEXT`: the mode and
//! the extra overestimation size), the uncertainty the device is then
//! declared to have, and why it cannot draw a case.
//!
//! **The uncertainty.** Vulkan grows the primitive "at each of its edges"
//! by `primitiveOverestimationSize` p, plus the pipeline's
//! `extraPrimitiveOverestimationSize` e ("in steps of
//! `extraPrimitiveOverestimationSizeGranularity` up to and including"
//! `maxExtraPrimitiveOverestimationSize`; a granularity of 0 "means the
//! implementation can use the smallest representable non-zero value in the
//! screen space pixel fixed-point grid", 2^-subPixelPrecisionBits). A case
//! (SPEC.md §19) states the uncertainty u it allows, so an overestimating
//! case stating u > p asks for the largest e ≤ u − p on the granularity and
//! within the maximum ([`extra`]), and 0 otherwise; the device is declared
//! to have p + e as its uncertainty for that case
//! ([`support_for`], `ConservativeSupport::overestimation_uncertainty`)
//! and judged under it, reported as judged under the device's own where
//! the case states another (SPEC.md §19.6). The size asked is the largest
//! f32 not above e, so that a device rounding to its steps cannot go past
//! e.
//!
//! Depth (SPEC.md §19.9) is drawn and read back as in any case: the same
//! depth attachment and state (`pipelines.rs`' `Stage::asked`), the
//! conservative state chained beside them.
//!
//! What it does not do: read `FullyCoveredEXT` (the shaders are naga's
//! WGSL, which has no such built-in: a case asking for the flag is
//! refused, naming why), or draw points and lines conservatively (not
//! judged in this version, SPEC.md §19.7). Underestimation has no size in
//! Vulkan; its uncertainty follows the case.

use ash::vk;
use dashu_ratio::RBig;

use crate::scene::{ConservativeMode, ConservativeSupport, Number, Scene};

/// The extension's name, as reasons quote it.
pub(super) const EXTENSION: &str = "VK_EXT_conservative_rasterization";

/// What the device offers of conservative rasterization: its
/// `VkPhysicalDeviceConservativeRasterizationPropertiesEXT`.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct ConservativeOffers {
    /// `primitiveOverestimationSize`, px.
    pub overestimation_size: f32,
    /// `maxExtraPrimitiveOverestimationSize`, px.
    pub max_extra: f32,
    /// `extraPrimitiveOverestimationSizeGranularity`, px (0: the subpixel
    /// grid).
    pub extra_granularity: f32,
    /// `primitiveUnderestimation`.
    pub underestimation: bool,
    /// `conservativePointAndLineRasterization`.
    pub points_and_lines: bool,
    /// `degenerateTrianglesRasterized`.
    pub degenerate_triangles: bool,
    /// `degenerateLinesRasterized`.
    pub degenerate_lines: bool,
    /// `fullyCoveredFragmentShaderInputVariable`.
    pub fully_covered: bool,
    /// `conservativeRasterizationPostDepthCoverage`.
    pub post_depth_coverage: bool,
    /// `subPixelPrecisionBits`: the grid of the extra size when its
    /// granularity is 0.
    pub grid_bits: u32,
}

impl ConservativeOffers {
    /// The offers of the device's properties.
    pub(super) fn of(p: &vk::PhysicalDeviceConservativeRasterizationPropertiesEXT) -> Self {
        ConservativeOffers {
            overestimation_size: p.primitive_overestimation_size,
            max_extra: p.max_extra_primitive_overestimation_size,
            extra_granularity: p.extra_primitive_overestimation_size_granularity,
            underestimation: p.primitive_underestimation == vk::TRUE,
            points_and_lines: p.conservative_point_and_line_rasterization == vk::TRUE,
            degenerate_triangles: p.degenerate_triangles_rasterized == vk::TRUE,
            degenerate_lines: p.degenerate_lines_rasterized == vk::TRUE,
            fully_covered: p.fully_covered_fragment_shader_input_variable == vk::TRUE,
            post_depth_coverage: p.conservative_rasterization_post_depth_coverage == vk::TRUE,
            grid_bits: 8,
        }
    }

    /// These offers on a device of `subpixel_bits` (`subPixelPrecisionBits`).
    pub(super) fn on_grid(self, subpixel_bits: u32) -> Self {
        ConservativeOffers {
            grid_bits: subpixel_bits,
            ..self
        }
    }

    /// The step of the extra size, exact: the granularity, or the
    /// subpixel grid's step where it is 0.
    fn step(&self) -> Number {
        let g = number(self.extra_granularity);
        if g.is_positive() {
            g
        } else {
            Number::ratio(1, 1i64 << self.grid_bits.min(62))
        }
    }

    /// The properties in words, for the adapter's description.
    pub(super) fn words(&self) -> String {
        format!(
            "{EXTENSION}: primitiveOverestimationSize {}, extra up to {} in steps of {}{}{}{}",
            exact(self.overestimation_size),
            exact(self.max_extra),
            exact(self.extra_granularity),
            if self.underestimation {
                ", underestimation"
            } else {
                ""
            },
            if self.degenerate_triangles {
                ", degenerate triangles rasterized"
            } else {
                ""
            },
            if self.fully_covered {
                ", FullyCoveredEXT"
            } else {
                ""
            },
        )
    }
}

/// An f32 as its exact value ("1/512"); a non-finite one as written.
fn exact(v: f32) -> String {
    RBig::try_from(v).map_or_else(
        |_| v.to_string(),
        |r| Number::from_rbig(r).to_exact_string(),
    )
}

/// An f32 property as an exact number (a non-finite, zero or negative one: 0).
fn number(v: f32) -> Number {
    RBig::try_from(v)
        .ok()
        .map(Number::from_rbig)
        .filter(|n| n.is_positive())
        .unwrap_or(Number::ZERO)
}

/// The extra overestimation size, exact, that an overestimating case
/// stating uncertainty `u` asks of a device offering `offers`: the largest
/// k·g (g the step, [`ConservativeOffers::step`]) with k·g ≤ u − p (p the
/// base size) and k·g ≤ the maximum; 0 where u ≤ p or the device offers no
/// extra (SPEC.md §19.6).
pub(super) fn extra(u: &Number, offers: &ConservativeOffers) -> Number {
    let p = number(offers.overestimation_size);
    let max = number(offers.max_extra);
    let slack = u.as_rbig() - p.as_rbig();
    let room = if &slack < max.as_rbig() {
        slack
    } else {
        max.as_rbig().clone()
    };
    if room <= RBig::ZERO {
        return Number::ZERO;
    }
    let step = offers.step();
    let k = (room / step.as_rbig()).floor();
    Number::from_rbig(RBig::from(k) * step.as_rbig())
}

/// The largest f32 not above `e` (an exact extra size, from 0 to ¾ px or
/// so): what the pipeline is handed, so that the device, rounding to its
/// steps, grows by no more than `e`.
fn f32_at_most(e: &Number) -> f32 {
    let mut v = e.to_f64_lossy() as f32;
    while v > 0.0 && RBig::try_from(v).is_ok_and(|r| &r > e.as_rbig()) {
        v = f32::from_bits(v.to_bits() - 1);
    }
    v.max(0.0)
}

/// What a conservative case asks the pipeline for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) struct Ask {
    pub underestimate: bool,
    /// `extraPrimitiveOverestimationSize`, its f32 bits (0 for
    /// underestimation).
    pub extra: u32,
}

impl Ask {
    /// The create info chained into the pipeline's rasterization state.
    pub(super) fn create_info(
        &self,
    ) -> vk::PipelineRasterizationConservativeStateCreateInfoEXT<'static> {
        let mode = if self.underestimate {
            vk::ConservativeRasterizationModeEXT::UNDERESTIMATE
        } else {
            vk::ConservativeRasterizationModeEXT::OVERESTIMATE
        };
        vk::PipelineRasterizationConservativeStateCreateInfoEXT::default()
            .conservative_rasterization_mode(mode)
            .extra_primitive_overestimation_size(f32::from_bits(self.extra))
    }
}

/// What the pipeline is asked for to draw `scene` conservatively, `None`
/// for a scene that is not conservative, or why the device cannot: it
/// lacks the extension, underestimation, or (as this adapter reads no
/// `FullyCoveredEXT`) the flag asked for.
pub(super) fn ask(
    scene: &Scene,
    offers: Option<&ConservativeOffers>,
) -> Result<Option<Ask>, String> {
    let Some(case) = &scene.effects.conservative else {
        return Ok(None);
    };
    let Some(offers) = offers else {
        return Err(format!(
            "conservative {}: the device offers no {EXTENSION}",
            case.mode.name()
        ));
    };
    if case.mode == ConservativeMode::Underestimate && !offers.underestimation {
        return Err(format!(
            "conservative underestimate: the device's {EXTENSION} has no primitiveUnderestimation"
        ));
    }
    if scene.has_points_or_lines() && !offers.points_and_lines {
        return Err(format!(
            "conservative points and lines: the device's {EXTENSION} has no \
             conservativePointAndLineRasterization, and a point or line pipeline must then have \
             conservative rasterization disabled (VUID-VkGraphicsPipelineCreateInfo-conservativePointAndLineRasterization-08892)"
        ));
    }
    if case.fully_covered {
        return Err(if offers.fully_covered {
            "the fully-covered flag: the device offers FullyCoveredEXT, but this adapter's \
             shaders (naga's WGSL) cannot read it"
                .to_owned()
        } else {
            format!(
                "the fully-covered flag: the device's {EXTENSION} has no \
                 fullyCoveredFragmentShaderInputVariable"
            )
        });
    }
    Ok(Some(match case.mode {
        ConservativeMode::Underestimate => Ask {
            underestimate: true,
            extra: 0,
        },
        ConservativeMode::Overestimate => Ask {
            underestimate: false,
            extra: f32_at_most(&extra(&case.uncertainty, offers)).to_bits(),
        },
    }))
}

/// What the device declares for conservative cases with no extra size
/// (SPEC.md §19.6): the modes it offers, its base size as its
/// overestimation uncertainty ([`support_for`] adds a case's extra), and
/// its degenerate-primitive properties. Without the extension it still
/// claims both modes, so that a case comes to `rasterize` and is refused
/// there with the device's reason.
pub(super) fn support(offers: Option<&ConservativeOffers>) -> ConservativeSupport {
    let Some(offers) = offers else {
        return ConservativeSupport {
            overestimate: true,
            underestimate: true,
            fully_covered: true,
            depth: true,
            ..ConservativeSupport::default()
        };
    };
    ConservativeSupport {
        overestimate: true,
        underestimate: offers.underestimation,
        // Refused in `ask` with the reason (the shaders cannot read it).
        fully_covered: true,
        overestimation_uncertainty: Some(number(offers.overestimation_size)),
        underestimation_uncertainty: None,
        degenerate_triangles: Some(offers.degenerate_triangles),
        degenerate_lines: Some(offers.degenerate_lines),
        points_and_lines: Some(offers.points_and_lines),
        // Its depth is read back as an ordinary case's is: the depth
        // attachment (clamped to the viewport's [0, 1], SPEC.md §19.9) or,
        // under `exact`, the fragment's interpolated z (`pipelines.rs`'
        // `Stage::asked`).
        depth: true,
    }
}

/// What the device declares for conservative `scene` (SPEC.md §19.6):
/// [`support`], its overestimation uncertainty p + e, e the extra size the
/// case asks for ([`extra`]).
pub(super) fn support_for(
    scene: &Scene,
    offers: Option<&ConservativeOffers>,
) -> ConservativeSupport {
    let mut declared = support(offers);
    if let (Some(offers), Some(case)) = (offers, &scene.effects.conservative) {
        if case.mode == ConservativeMode::Overestimate {
            let p = number(offers.overestimation_size);
            let e = extra(&case.uncertainty, offers);
            declared.overestimation_uncertainty =
                Some(Number::from_rbig(p.as_rbig() + e.as_rbig()));
        }
    }
    declared
}

/// An NVIDIA H100's properties (shared/GPU.md, ANCHORS.md), for the
/// adapter's unit tests: base 2^-9 px, extra up to 0.75 px in steps of
/// 2^-8, underestimation, degenerate triangles rasterized, the
/// fully-covered input.
#[cfg(test)]
pub(super) fn h100() -> ConservativeOffers {
    ConservativeOffers::of(
        &vk::PhysicalDeviceConservativeRasterizationPropertiesEXT::default()
            .primitive_overestimation_size(1.0 / 512.0)
            .max_extra_primitive_overestimation_size(0.75)
            .extra_primitive_overestimation_size_granularity(1.0 / 256.0)
            .primitive_underestimation(true)
            .degenerate_triangles_rasterized(true)
            .fully_covered_fragment_shader_input_variable(true),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{parse_case, Limits};
    use serde_json::json;

    fn scene(conservative: serde_json::Value) -> Scene {
        parse_case(
            &json!({
                "name": "c", "canvas": {"width": 4, "height": 4},
                "rules": {"subpixel_bits": 8},
                "effects": {"conservative": conservative},
                "primitives": [{"triangle": [[0.5, 0.5], [3.5, 0.5], [0.5, 3.5]]}],
            })
            .to_string(),
            "c",
            &Limits::default(),
        )
        .unwrap()
    }

    fn n(s: &str) -> Number {
        Number::from_string(s).unwrap()
    }

    /// What the pipeline is asked for, and what the device then declares,
    /// on an H100's properties (p = 2^-9, steps of 2^-8 up to ¾): the
    /// case's mode, the structure type the chain needs, and the largest
    /// extra size e on the steps with p + e ≤ the case's u (0 where u ≤ p),
    /// the device judged under p + e.
    #[test]
    fn a_case_asks_for_the_largest_extra_size_it_allows() {
        let o = h100();
        // (the case's u, the extra asked, the uncertainty declared)
        for (u, e, declared) in [
            ("0", "0", "1/512"),
            ("1/1024", "0", "1/512"),
            ("1/512", "0", "1/512"),
            ("1/256", "0", "1/512"),
            ("3/512", "1/256", "3/512"),
            ("1/64", "3/256", "7/512"),
            ("1/2", "127/256", "255/512"),
            ("3/4", "191/256", "383/512"),
            ("1", "3/4", "385/512"),
        ] {
            let over = scene(json!({"mode": "overestimate", "uncertainty": u}));
            let info = ask(&over, Some(&o)).unwrap().unwrap().create_info();
            assert_eq!(
                info.conservative_rasterization_mode,
                vk::ConservativeRasterizationModeEXT::OVERESTIMATE
            );
            assert_eq!(
                Number::from_rbig(
                    RBig::try_from(info.extra_primitive_overestimation_size).unwrap()
                ),
                n(e),
                "u = {u}"
            );
            assert_eq!(
                info.s_type,
                vk::StructureType::PIPELINE_RASTERIZATION_CONSERVATIVE_STATE_CREATE_INFO_EXT
            );
            let support = support_for(&over, Some(&o));
            assert_eq!(
                support.overestimation_uncertainty,
                Some(n(declared)),
                "u = {u}"
            );
            assert!(
                n(declared) <= n(u) || e == "0",
                "u = {u}: never above the case's but for p"
            );
            let judged = support.restate(over.effects.conservative.as_ref().unwrap());
            assert_eq!(judged.uncertainty, n(declared));
        }
        let declared = support(Some(&o));
        assert_eq!(declared.overestimation_uncertainty, Some(n("1/512")));
        assert_eq!(declared.underestimation_uncertainty, None);
        assert_eq!(declared.degenerate_triangles, Some(true));
        assert!(declared.overestimate && declared.underestimate);
        let under = scene(json!({"mode": "underestimate", "uncertainty": "1/8"}));
        let info = ask(&under, Some(&o)).unwrap().unwrap().create_info();
        assert_eq!(
            info.conservative_rasterization_mode,
            vk::ConservativeRasterizationModeEXT::UNDERESTIMATE
        );
        assert_eq!(info.extra_primitive_overestimation_size, 0.0);
        assert_eq!(
            support_for(&under, Some(&o)).underestimation_uncertainty,
            None,
            "underestimation has no size: it follows the case"
        );
        assert!(
            o.words().contains(
                "primitiveOverestimationSize 0.001953125, extra up to 0.75 in steps of 0.00390625"
            ),
            "{}",
            o.words()
        );
    }

    /// A device offering no extra size is judged at its base size; one
    /// whose granularity is 0 steps on its subpixel grid; one whose
    /// granularity is no power of two is handed an f32 not above k·g.
    #[test]
    fn the_extra_size_follows_the_maximum_and_the_granularity() {
        let half = scene(json!({"mode": "overestimate", "uncertainty": "1/2"}));
        let none = ConservativeOffers {
            max_extra: 0.0,
            ..h100()
        };
        assert_eq!(
            ask(&half, Some(&none))
                .unwrap()
                .unwrap()
                .create_info()
                .extra_primitive_overestimation_size,
            0.0
        );
        assert_eq!(
            support_for(&half, Some(&none)).overestimation_uncertainty,
            Some(n("1/512"))
        );
        let grid = ConservativeOffers {
            extra_granularity: 0.0,
            ..h100()
        }
        .on_grid(4);
        // u − p = 255/512: 7 steps of 1/16.
        assert_eq!(extra(&n("1/2"), &grid), n("7/16"));
        let tenth = ConservativeOffers {
            extra_granularity: 0.1,
            ..h100()
        };
        let e = extra(&n("1/2"), &tenth);
        let g = Number::from_rbig(RBig::try_from(0.1f32).unwrap());
        assert_eq!(e, Number::from_rbig(RBig::from(4) * g.as_rbig()));
        let asked = ask(&half, Some(&tenth))
            .unwrap()
            .unwrap()
            .create_info()
            .extra_primitive_overestimation_size;
        let asked = Number::from_rbig(RBig::try_from(asked).unwrap());
        assert!(
            asked <= e && asked > Number::from_rbig(RBig::from(3) * g.as_rbig()),
            "{asked}"
        );
        assert_eq!(support_for(&half, None).overestimation_uncertainty, None);
    }

    /// Without the extension (lavapipe, SwiftShader): refused with the
    /// device's reason; without underestimation or with the flag asked:
    /// refused naming the property or the shaders.
    #[test]
    fn what_the_device_lacks_refuses_the_case_with_its_reason() {
        let over = scene(json!({"mode": "overestimate"}));
        assert_eq!(
            ask(&over, None).unwrap_err(),
            "conservative overestimate: the device offers no VK_EXT_conservative_rasterization"
        );
        let no_under = ConservativeOffers {
            underestimation: false,
            ..h100()
        };
        let under = scene(json!({"mode": "underestimate"}));
        assert!(ask(&under, Some(&no_under))
            .unwrap_err()
            .contains("no primitiveUnderestimation"));
        let flagged = scene(json!({"mode": "overestimate", "fully_covered": true}));
        assert!(ask(&flagged, Some(&h100()))
            .unwrap_err()
            .contains("cannot read it"));
        assert!(ask(&scene_plain(), None).unwrap().is_none());
    }

    fn scene_plain() -> Scene {
        parse_case(
            &json!({"name": "p", "canvas": {"width": 2, "height": 2},
                    "primitives": [{"triangle": [[0, 0], [2, 0], [0, 2]]}]})
            .to_string(),
            "p",
            &Limits::default(),
        )
        .unwrap()
    }

    /// A device without `conservativePointAndLineRasterization` refuses a
    /// conservative case with a line (SPEC.md §19.8); one with it asks.
    #[test]
    fn points_and_lines_need_the_device_property() {
        let line = parse_case(
            &json!({
                "name": "c", "canvas": {"width": 4, "height": 4},
                "effects": {"conservative": {"mode": "overestimate", "points_and_lines": true}},
                "primitives": [{"line": [[0.5, 0.5], [3.5, 2.5]], "rule": "rectangle", "width": 1}],
            })
            .to_string(),
            "c",
            &Limits::default(),
        )
        .unwrap();
        let mut o = h100();
        let why = ask(&line, Some(&o)).unwrap_err();
        assert!(
            why.contains("conservativePointAndLineRasterization"),
            "{why}"
        );
        assert_eq!(support(Some(&o)).points_and_lines, Some(false));
        o.points_and_lines = true;
        assert!(ask(&line, Some(&o)).unwrap().is_some());
    }
}
