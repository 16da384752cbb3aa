//! The foils that are no centre-point samplers (at (1, 1), by area, by any
//! coverage), by name: what `probe`'s sampler decision must tell apart.

/// The foils that sample otherwise than at one point per pixel centre,
/// each wrong in that one way (what `probe` must tell apart).
pub const SAMPLER_FOILS: [&str; 3] = [
    "foil-offset-sampler",
    "foil-area-sampler",
    "foil-any-coverage",
];

#[cfg(test)]
mod tests {
    use crate::frame::Frame;
    use crate::plan::Plan;
    use crate::production::dispatch::Production;
    use crate::production::foils::{AnyCoverage, AreaSampler, OffsetSampler};
    use crate::rasterizer::Rasterizer;
    use crate::scene::{parse_case, Limits};

    /// A 3 × 3 canvas with the given triangles, drawn by `r`: which
    /// pixels it covers, row-major.
    fn drawn(r: &dyn Rasterizer, triangles: &str) -> Vec<u16> {
        let scene = parse_case(
            &format!(
                r#"{{"name": "t", "canvas": {{"width": 3, "height": 3}},
                    "rules": {{"subpixel_bits": 8, "cull": "none"}}, "primitives": [{triangles}]}}"#
            ),
            "t",
            &Limits::default(),
        )
        .unwrap();
        let frame: Frame = r.rasterize(&scene, &Plan::for_scene(&scene)).unwrap();
        frame.coverage
    }

    /// A tiny triangle around (1, 1): production's centres miss it.
    const AROUND_1_1: &str = r#"{"triangle": [[0.9, 0.9], [1.2, 0.9], [0.9, 1.2]]}"#;
    /// A sliver through the centre of pixel (1, 1).
    const SLIVER_THROUGH_CENTRE: &str = r#"{"triangle": [[1.1, 1.45], [1.9, 1.5], [1.1, 1.55]]}"#;
    /// A sliver in pixel (1, 1) far from its centre.
    const SLIVER_OFF_CENTRE: &str = r#"{"triangle": [[1.1, 1.05], [1.9, 1.05], [1.5, 1.1]]}"#;

    #[test]
    fn the_offset_sampler_draws_the_pixel_whose_corner_is_covered() {
        assert!(drawn(&Production, AROUND_1_1).iter().all(|&c| c == 0));
        let got = drawn(&OffsetSampler, AROUND_1_1);
        assert_eq!(got, [1, 0, 0, 0, 0, 0, 0, 0, 0]);
    }

    #[test]
    fn the_area_sampler_draws_by_area_not_at_the_centre() {
        assert_eq!(drawn(&Production, SLIVER_THROUGH_CENTRE)[4], 1);
        assert_eq!(drawn(&AreaSampler, SLIVER_THROUGH_CENTRE)[4], 0);
        // Three quarters of pixel (1, 1) and its centre: drawn by both.
        let big = r#"{"triangle": [[1, 1], [2.5, 1], [1, 2.5]]}"#;
        assert_eq!(drawn(&AreaSampler, big)[4], 1);
    }

    #[test]
    fn the_any_coverage_foil_draws_what_a_triangle_touches() {
        assert_eq!(drawn(&Production, SLIVER_OFF_CENTRE)[4], 0);
        assert_eq!(
            drawn(&AnyCoverage, SLIVER_OFF_CENTRE),
            [0, 0, 0, 0, 1, 0, 0, 0, 0]
        );
        // A triangle whose edges run along pixel borders touches only the
        // pixels it has area in; two sharing a diagonal both draw the
        // pixels it crosses.
        let square =
            r#"{"triangle": [[1, 1], [2, 1], [2, 2]]}, {"triangle": [[1, 1], [2, 2], [1, 2]]}"#;
        assert_eq!(drawn(&AnyCoverage, square), [0, 0, 0, 0, 2, 0, 0, 0, 0]);
    }
}
