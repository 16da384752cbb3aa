//! Which conservative scenes with points and lines are judged (SPEC.md
//! §19.8): a point's square and a `rectangle` or `parallelogram` line's
//! area are drawn conservatively when `points_and_lines` is true; a
//! `midpoint` or `diamond-exit` line picks pixels rather than covering an
//! area, so it has no conservative shape; and with `points_and_lines`
//! false the API draws points and lines without conservative rasterization,
//! which a conservative case does not judge.

use super::conservative::Conservative;
use super::model::Scene;
use super::primitive::Primitive;

impl Scene {
    /// Whether the scene has a point or a line.
    pub fn has_points_or_lines(&self) -> bool {
        self.primitives
            .iter()
            .any(|p| matches!(p, Primitive::Line(_) | Primitive::Point(_)))
    }

    /// Why this version does not judge the points and lines of this
    /// conservative scene, if it does not: a line with no area to be
    /// conservative about, or points and lines the case does not draw
    /// conservatively (`points_and_lines: false`).
    pub fn conservative_lines_unjudged(&self) -> Option<String> {
        let case = self.effects.conservative.as_ref()?;
        if let Some(rule) = self.primitives.iter().find_map(|p| match p {
            Primitive::Line(l) if !l.rule.is_wide() => Some(l.rule),
            _ => None,
        }) {
            return Some(format!(
                "a {} line picks pixels and covers no area, so it has no conservative shape; conservative lines are `rectangle` or `parallelogram` lines (SPEC.md §19.8)",
                rule.name()
            ));
        }
        if self.has_points_or_lines() {
            return points_and_lines_refused(case, "the case states");
        }
        None
    }

    /// Why a candidate judged under `state` (its declared
    /// `points_and_lines`, SPEC.md §19.6) is not asked to draw this scene's
    /// points and lines, if it is not.
    pub fn conservative_lines_refused(&self, state: &Conservative) -> Option<String> {
        if !self.has_points_or_lines() {
            return None;
        }
        points_and_lines_refused(state, "this rasterizer declares")
    }
}

fn points_and_lines_refused(state: &Conservative, who: &str) -> Option<String> {
    (!state.points_and_lines).then(|| {
        format!(
            "{who} points_and_lines false (conservativePointAndLineRasterization): its points and lines are not drawn conservatively, which a conservative case does not judge (SPEC.md §19.8)"
        )
    })
}
