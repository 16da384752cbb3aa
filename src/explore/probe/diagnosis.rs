//! What `probe` decides about how a rasterizer samples and breaks ties, and
//! the words for it: the one vocabulary that `probe`'s profile and the
//! matrix's findings both speak, so that they cannot disagree.
//!
//! The decisions are made in `explore::probe`; the matrix
//! ([`crate::explore::matrix::build`]) asks probe for them, and says
//! nothing about a row's sampler or tie rule that is not in its
//! [`Diagnosis`].

use serde::Serialize;

use super::evidence::SlopeRule;

/// How a rasterizer decides coverage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SamplerKind {
    /// At one point per pixel.
    Point,
    /// By the area of the pixel a primitive covers.
    Area,
    /// By whether a primitive touches the pixel at all (conservative).
    AnyCoverage,
    /// A point-sampled fill with each edge stroked over it as a hairline:
    /// more than a point sampler draws, less than any-coverage.
    OutlineOverFill,
    /// None of the above explains its frames.
    Unknown,
}

impl SamplerKind {
    /// The name in the profile: `point`, `area`, `any-coverage`, `unknown`.
    pub fn name(self) -> &'static str {
        match self {
            SamplerKind::Point => "point",
            SamplerKind::Area => "area",
            SamplerKind::AnyCoverage => "any-coverage",
            SamplerKind::OutlineOverFill => "outline-over-fill",
            SamplerKind::Unknown => "unknown",
        }
    }

    /// "point-sampled", "not point-sampled (area sampler)", ...
    pub fn words(self) -> &'static str {
        match self {
            SamplerKind::Point => "point-sampled",
            SamplerKind::Area => "not point-sampled (area sampler)",
            SamplerKind::AnyCoverage => "not point-sampled (any-coverage)",
            SamplerKind::OutlineOverFill => "not point-sampled (outline over fill)",
            SamplerKind::Unknown => "sampler unknown",
        }
    }
}

/// The sampler decision and what it rests on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Sampler {
    pub kind: SamplerKind,
    /// The frames that decided it, in a sentence.
    pub evidence: String,
}

/// A sample offset in eighths of a pixel, as the sample-position probe
/// finds it; the centre is (4, 4).
pub type Eighths = (i64, i64);

/// The pixel centre, in eighths.
pub const CENTRE: Eighths = (4, 4);

/// The sampler, and for a point sampler its sample position and tie rule.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnosis {
    pub sampler: Sampler,
    /// The sample position in words, "not applicable (...)" when it is
    /// not point-sampled.
    pub sample_position: String,
    /// The one sample offset found.
    pub offset: Option<Eighths>,
    /// The rule that explains the most tie samples (`top-left`, ...,
    /// `all-edges`, `none`); `None` when it is not point-sampled or its
    /// sample was not found.
    pub fill_rule: Option<String>,
    /// Whether that rule explains every tie sample.
    pub fill_rule_consistent: bool,
    /// When no one rule explains every tie sample but each slope's ties
    /// follow a consistent rule: the slopes the nearest rule does not
    /// explain, each with the rules it follows (the verdict is then
    /// "inconsistent": a rule by slope). Empty otherwise.
    pub tie_slopes: Vec<SlopeRule>,
    /// What the tie rule was measured on: "N tie samples over M slopes
    /// (K meshes)"; empty when it was not measured.
    pub ties_measured_on: String,
}

/// What the matrix saw on a row's mesh cases, for [`Diagnosis::cause`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Symptom {
    /// Samples drawn by two triangles of a mesh.
    Overdraw,
    /// Samples inside a mesh drawn by none.
    Holes,
    /// Watertight, but tie samples given to the other triangle.
    WrongOwner,
}

impl Diagnosis {
    /// One phrase: the sampler, and for a point sampler its position and
    /// tie rule. The matrix groups rows by it.
    pub fn summary(&self) -> String {
        if self.sampler.kind != SamplerKind::Point {
            return self.sampler.kind.words().to_owned();
        }
        let at = match self.offset {
            Some(CENTRE) => "at the pixel centre".to_owned(),
            Some(_) => format!("at {}", self.sample_position),
            None => format!("sample position {}", self.sample_position),
        };
        let rule = match (&self.fill_rule, self.fill_rule_consistent) {
            (None, _) => "tie rule not measured".to_owned(),
            (Some(r), false) if !self.tie_slopes.is_empty() => {
                format!(
                    "tie rule inconsistent ({r} but {})",
                    slope_list(&self.tie_slopes)
                )
            }
            (Some(r), true) => format!("tie rule {r}"),
            (Some(r), false) => format!("tie rule nearest {r}, not consistent"),
        };
        format!("point-sampled {at}, {rule}")
    }

    /// Why a row shows `symptom` on its mesh cases, as probe's decision
    /// explains it: the matrix's only words about a row's sampler and rule.
    /// `judged` is the rule its mesh cases were judged under: top-left, as
    /// they state, or the rule it follows whatever a case states (SPEC.md
    /// §3.1).
    pub fn cause(&self, symptom: Symptom, judged: &str) -> String {
        let probe = "Probe finds it";
        match self.sampler.kind {
            SamplerKind::AnyCoverage => {
                return format!("{probe} not point-sampled (any-coverage): every pixel a triangle touches is drawn, so pixels along shared edges are drawn by both triangles; no tie rule applies.")
            }
            SamplerKind::OutlineOverFill => {
                return format!("{probe} not point-sampled (outline over fill): each triangle's fill is point-sampled, then its edges are stroked over it as hairlines, so pixels along shared edges are drawn by both triangles; no tie rule applies.")
            }
            SamplerKind::Area => {
                return format!("{probe} not point-sampled (area sampler): a pixel is drawn by how much of it a triangle covers, not at a sample, so shared edges are not decided by a tie rule.")
            }
            SamplerKind::Unknown => {
                return format!("{probe} neither point-, area- nor any-coverage-sampled ({}), so its tie rule is unknown.", self.sampler.evidence)
            }
            SamplerKind::Point => {}
        }
        if self.offset.is_some_and(|o| o != CENTRE) {
            return format!("{probe} point-sampled at {}: its whole raster is shifted against the reference's centre samples, so samples differ along every edge, not by a tie rule.", self.sample_position);
        }
        let Some(rule) = &self.fill_rule else {
            return format!(
                "{probe} point-sampled, but its tie rule was not measured (sample position {}).",
                self.sample_position
            );
        };
        if !self.tie_slopes.is_empty() {
            return format!(
                "{probe} point-sampled with no consistent tie rule: {rule} on most slopes, but {} ({}); declared fill_rule \"none\" it is judged off the ties (SPEC.md §3.1.1).",
                slope_list(&self.tie_slopes),
                self.ties_measured_on
            );
        }
        let consistent = if self.fill_rule_consistent {
            "consistently"
        } else {
            "though not consistently"
        };
        match (symptom, rule.as_str()) {
            (Symptom::Overdraw, "all-edges") => format!("{probe} point-sampled with closed edges (all-edges, {consistent}): samples on shared edges are drawn by both triangles."),
            (Symptom::Holes, "none") => format!("{probe} point-sampled with open edges (none, {consistent}): samples on shared edges are owned by neither triangle."),
            (Symptom::WrongOwner, r) if r != judged && self.fill_rule_consistent => format!("{probe} point-sampled with a different consistent tie rule than {judged}: {r}."),
            (_, r) => format!("{probe} point-sampled with the {r} tie rule ({consistent}), which does not do this: its snapping, clipping or float arithmetic moves those edges."),
        }
    }
}

/// The slopes that disagree, as "slope 3: top-left, slope -1/3: top-left".
pub fn slope_list(slopes: &[SlopeRule]) -> String {
    slopes
        .iter()
        .map(|s| format!("slope {}: {}", s.slope, s.follows.join(" or ")))
        .collect::<Vec<_>>()
        .join(", ")
}
