//! A rasterizer's own line parameters over a case's lines (SPEC.md §5.1):
//! which line rules it restates, to what (`projected` or `major`, clamped
//! or not), and the words a result says it with. `profile.rs`'s
//! `OwnConventions` holds one and restates the case's lines under it.

use crate::rasterizer::Rasterizer;
use crate::scene::{LineClamp, LineParameter, LineRule, LineT, Primitive, Scene};

/// A rasterizer's own line parameters over a case's lines (SPEC.md §5.1),
/// by line rule: `Some` for a rule whose lines it restates (its declared
/// parameter differs from a line's, or it declares no clamp).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LineParameters {
    pub by_rule: [Option<LineT>; 4],
    /// The parameters the restated lines state: `major`, `projected`
    /// (kept here, as a run lets the case's primitives go).
    pub stated: [bool; 2],
}

impl LineParameters {
    /// Slot of `rule` in [`LineParameters::by_rule`].
    fn slot(rule: LineRule) -> usize {
        match rule {
            LineRule::Midpoint => 0,
            LineRule::DiamondExit => 1,
            LineRule::Rectangle => 2,
            LineRule::Parallelogram => 3,
        }
    }

    pub fn get(&self, rule: LineRule) -> Option<LineT> {
        self.by_rule[Self::slot(rule)]
    }

    /// The declarations in use, with their rules.
    pub fn each(&self) -> impl Iterator<Item = (LineRule, LineT)> + '_ {
        [
            LineRule::Midpoint,
            LineRule::DiamondExit,
            LineRule::Rectangle,
            LineRule::Parallelogram,
        ]
        .into_iter()
        .filter_map(|rule| self.get(rule).map(|t| (rule, t)))
    }

    /// The one declaration in use, when every restated rule has the same.
    pub fn single(&self) -> Option<LineT> {
        let mut all = self.each().map(|(_, t)| t);
        let first = all.next()?;
        all.all(|t| t == first).then_some(first)
    }

    /// In words: "projected, unclamped", or per rule where they differ
    /// ("major, unclamped for diamond-exit lines and projected, unclamped
    /// for rectangle lines").
    pub fn words(&self) -> String {
        if let Some(t) = self.single() {
            return t.words();
        }
        self.each()
            .map(|(rule, t)| format!("{} for {} lines", t.words(), rule.name()))
            .collect::<Vec<_>>()
            .join(" and ")
    }

    /// The parameters the restated lines state, in words, for the
    /// result's "the case states ..." ("major, clamped", "major and
    /// projected, clamped").
    pub fn stated(&self) -> String {
        let names: Vec<&str> = [LineParameter::Major, LineParameter::Projected]
            .into_iter()
            .zip(self.stated)
            .filter_map(|(parameter, stated)| stated.then_some(parameter.name()))
            .collect();
        format!("{}, clamped", names.join(" and "))
    }

    /// Its name in a report: the one declaration's ([`LineT::name`]), or
    /// `per-rule` where rules differ.
    pub fn name(&self) -> &'static str {
        self.single().map_or("per-rule", LineT::name)
    }

    /// What `candidate` restates on `scene`'s lines, if anything: for
    /// each line that carries values (depth or attributes), its rule's
    /// declaration where it differs from the line's `parameter` or
    /// declares no clamp.
    pub(super) fn of(candidate: &dyn Rasterizer, scene: &Scene) -> Option<LineParameters> {
        if !scene.has_depth && scene.attribute_count == 0 {
            return None;
        }
        let mut own = LineParameters::default();
        for p in &scene.primitives {
            let Primitive::Line(line) = p else { continue };
            if let Some(t) = candidate.fixed_line_parameter(line.rule) {
                if t.parameter != line.parameter || t.clamp != scene.rules.line_clamp {
                    own.by_rule[Self::slot(line.rule)] = Some(t);
                    own.stated[usize::from(line.parameter == LineParameter::Projected)] = true;
                }
            }
        }
        (own != LineParameters::default()).then_some(own)
    }

    /// The clamp the restated case takes: one for all its lines (a case
    /// has one `line_clamp`); `None` when the rules declare different
    /// clamps.
    pub(super) fn clamp(&self) -> Option<LineClamp> {
        let mut clamps = self.each().map(|(_, t)| t.clamp);
        let first = clamps.next()?;
        clamps.all(|c| c == first).then_some(first)
    }
}
