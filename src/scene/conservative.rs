//! Conservative rasterization (SPEC.md §19): what a case states with
//! `effects.conservative`: the mode, its uncertainty (an exact rational, in
//! pixels), whether the fully-covered flag is asked for, and the API
//! properties that decide degenerate primitives, points and lines.

use super::number::Number;

/// Which way a conservative rasterizer errs (SPEC.md §19.1, §19.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ConservativeMode {
    /// Every pixel the primitive touches is drawn
    /// (`VK_CONSERVATIVE_RASTERIZATION_MODE_OVERESTIMATE_EXT`).
    Overestimate,
    /// Only pixels the primitive covers wholly are drawn
    /// (`VK_CONSERVATIVE_RASTERIZATION_MODE_UNDERESTIMATE_EXT`).
    Underestimate,
}

case_names!(ConservativeMode {
    Overestimate => "overestimate",
    Underestimate => "underestimate",
});

/// The largest uncertainty a case may state, in pixels: Vulkan's
/// `primitiveOverestimationSize` plus its largest extra size an
/// implementation reports (0.75 px on the devices we know) stays below 1;
/// D3D12 tier 1's is ½ px.
pub const MAX_UNCERTAINTY: i64 = 1;

/// `effects.conservative`: conservative rasterization and its properties.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Conservative {
    pub mode: ConservativeMode,
    /// The uncertainty u ≥ 0, in pixels, exact (SPEC.md §19.1): in
    /// overestimation a pixel may be drawn when its square grown by u on
    /// every side meets the triangle; in underestimation it must be drawn
    /// only when that grown square lies inside the triangle.
    pub uncertainty: Number,
    /// Whether the candidate's frame must carry the fully-covered flag
    /// (`FullyCoveredEXT`, D3D's inner coverage) for every pixel it draws,
    /// judged exactly (SPEC.md §19.4).
    pub fully_covered: bool,
    /// `degenerateTrianglesRasterized`: a triangle of zero area after
    /// snapping is drawn (as the segment or point it is) rather than
    /// culled (SPEC.md §19.3).
    pub degenerate_triangles: bool,
    /// `degenerateLinesRasterized`: a line of zero length after snapping
    /// is drawn rather than culled (SPEC.md §19.3).
    pub degenerate_lines: bool,
    /// `conservativePointAndLineRasterization`: points and lines are drawn
    /// conservatively too; when false they are drawn by their own rules
    /// (SPEC.md §19.3).
    pub points_and_lines: bool,
}

impl Conservative {
    /// Overestimation with no uncertainty and every property false: the
    /// start of a declaration in tests.
    pub fn overestimate() -> Conservative {
        Conservative {
            mode: ConservativeMode::Overestimate,
            uncertainty: Number::ZERO,
            fully_covered: false,
            degenerate_triangles: false,
            degenerate_lines: false,
            points_and_lines: false,
        }
    }

    /// Underestimation with no uncertainty and every property false.
    pub fn underestimate() -> Conservative {
        Conservative {
            mode: ConservativeMode::Underestimate,
            ..Conservative::overestimate()
        }
    }

    /// The properties in which `self` differs from `case` in what matters
    /// to a scene (points and lines only where it has them,
    /// `has_points_or_lines`), each with its value in both; `None` when
    /// they agree in those and in mode and uncertainty (the flag asked for
    /// is the case's in any restatement). The one relevance
    /// test: [`Conservative::restates`] and
    /// [`Conservative::restated_words`] both read it.
    fn differences(
        &self,
        case: &Conservative,
        has_points_or_lines: bool,
    ) -> Option<Vec<(&'static str, bool, bool)>> {
        let mut properties: Vec<(&str, bool, bool)> = vec![(
            "degenerate_triangles",
            self.degenerate_triangles,
            case.degenerate_triangles,
        )];
        if has_points_or_lines {
            properties.push((
                "points_and_lines",
                self.points_and_lines,
                case.points_and_lines,
            ));
            properties.push((
                "degenerate_lines",
                self.degenerate_lines,
                case.degenerate_lines,
            ));
        }
        properties.retain(|(_, own, stated)| own != stated);
        let same = self.mode == case.mode && self.uncertainty == case.uncertainty;
        (!same || !properties.is_empty()).then_some(properties)
    }

    /// Whether a candidate judged under `self` is judged under other
    /// conventions than `case` states, in what matters to a scene that has
    /// points or lines or not (`has_points_or_lines`): where it is not,
    /// the case's own classes serve.
    pub fn restates(&self, case: &Conservative, has_points_or_lines: bool) -> bool {
        self.differences(case, has_points_or_lines).is_some()
    }

    /// Whether a candidate judged under `self` is judged under other
    /// conventions than `case` states, in what matters to a scene
    /// ([`Conservative::restates`]), and the words for both:
    /// "overestimate, uncertainty 1/4 px, degenerate_lines true" against
    /// what the case states. `None` when they agree.
    pub fn restated_words(
        &self,
        case: &Conservative,
        has_points_or_lines: bool,
    ) -> Option<(String, String)> {
        let properties = self.differences(case, has_points_or_lines)?;
        let (mut own, mut stated) = (self.words(), case.words());
        for (name, o, c) in properties {
            own.push_str(&format!(", {name} {o}"));
            stated.push_str(&format!(", {name} {c}"));
        }
        Some((own, stated))
    }

    /// The words reports use: "overestimate, uncertainty 1/256 px".
    pub fn words(&self) -> String {
        format!(
            "{}, uncertainty {} px",
            self.mode.name(),
            self.uncertainty.as_rbig()
        )
    }
}

/// What a rasterizer that draws conservative cases declares
/// ([`crate::rasterizer::Rasterizer::conservative`]): the modes it draws,
/// and the conventions it cannot choose, each `None` where it follows the
/// case's. A case under other conventions is judged against the reference
/// restated under these, and reported as such (SPEC.md §19.6).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ConservativeSupport {
    pub overestimate: bool,
    pub underestimate: bool,
    /// Whether it gives the fully-covered flag.
    pub fully_covered: bool,
    /// Its own uncertainty in each mode, when fixed (a device's
    /// `primitiveOverestimationSize` plus the extra size it was asked for).
    pub overestimation_uncertainty: Option<Number>,
    pub underestimation_uncertainty: Option<Number>,
    /// `degenerateTrianglesRasterized`, when fixed.
    pub degenerate_triangles: Option<bool>,
    /// `degenerateLinesRasterized`, when fixed.
    pub degenerate_lines: Option<bool>,
    /// `conservativePointAndLineRasterization`, when fixed.
    pub points_and_lines: Option<bool>,
    /// Whether it gives the depth of each pixel it draws, judged against
    /// the interval SPEC.md §19.9 allows.
    pub depth: bool,
}

impl ConservativeSupport {
    /// Why a conservative case asks for what this support lacks, if it
    /// does: a mode it does not draw, or a flag it does not give.
    pub fn refuses(&self, case: &Conservative) -> Option<String> {
        let drawn = match case.mode {
            ConservativeMode::Overestimate => self.overestimate,
            ConservativeMode::Underestimate => self.underestimate,
        };
        if !drawn {
            return Some(format!(
                "this rasterizer does not draw conservative {} (SPEC.md §19)",
                case.mode.name()
            ));
        }
        if case.fully_covered && !self.fully_covered {
            return Some("this rasterizer gives no fully-covered flag (SPEC.md §19.4)".to_owned());
        }
        None
    }

    /// Why a conservative scene with depth (`has_depth`) is not asked of
    /// this support, if it is not: it gives no depth under conservative
    /// rasterization (SPEC.md §19.9).
    pub fn refuses_depth(&self, has_depth: bool) -> Option<String> {
        (has_depth && !self.depth).then(|| {
            "this rasterizer gives no depth under conservative rasterization (SPEC.md §19.9)"
                .to_owned()
        })
    }

    /// The case's conservative state under this support's fixed
    /// conventions: what the candidate is judged against.
    pub fn restate(&self, case: &Conservative) -> Conservative {
        let fixed = match case.mode {
            ConservativeMode::Overestimate => &self.overestimation_uncertainty,
            ConservativeMode::Underestimate => &self.underestimation_uncertainty,
        };
        Conservative {
            mode: case.mode,
            uncertainty: fixed.clone().unwrap_or_else(|| case.uncertainty.clone()),
            fully_covered: case.fully_covered,
            degenerate_triangles: self
                .degenerate_triangles
                .unwrap_or(case.degenerate_triangles),
            degenerate_lines: self.degenerate_lines.unwrap_or(case.degenerate_lines),
            points_and_lines: self.points_and_lines.unwrap_or(case.points_and_lines),
        }
    }
}

/// `expect.conservative`: what the reference's classes of a conservative
/// case must be (SPEC.md §19), as counts and, for the worked examples,
/// as the exact pixel sets. A broken promise fails every candidate, as
/// `expect.samples_covered` does.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ConservativePromise {
    /// How many pixels are required.
    pub required: Option<u64>,
    /// How many pixels are in the allowed band (allowed, not required).
    pub allowed: Option<u64>,
    /// How many pixels' fully-covered flag must be true.
    pub fully_covered: Option<u64>,
    /// The required pixels, exactly, in any order.
    pub required_pixels: Option<Vec<[u32; 2]>>,
    /// The allowed band's pixels, exactly, in any order.
    pub allowed_pixels: Option<Vec<[u32; 2]>>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn restated_words_name_only_what_differs_and_matters() {
        let case = Conservative::overestimate();
        let mut own = Conservative {
            points_and_lines: true,
            ..Conservative::overestimate()
        };
        // A declared property of points and lines is no restatement of a
        // scene of triangles.
        assert_eq!(own.restated_words(&case, false), None);
        assert!(!own.restates(&case, false));
        assert!(own.restates(&case, true));
        assert_eq!(
            own.restated_words(&case, true),
            Some((
                "overestimate, uncertainty 0 px, points_and_lines true".to_owned(),
                "overestimate, uncertainty 0 px, points_and_lines false".to_owned()
            ))
        );
        own.uncertainty = Number::ratio(1, 4);
        assert!(own.restates(&case, false));
        let (mine, stated) = own.restated_words(&case, false).unwrap();
        assert_eq!(mine, "overestimate, uncertainty 1/4 px");
        assert_eq!(stated, "overestimate, uncertainty 0 px");
    }
}
