//! The profile (`rastercheck-profile/1`): everything a probe found about a
//! rasterizer, as `probe` writes it and `run --profile` reads it.

use serde::Serialize;

use super::clip::ClipProbe;
use super::conservative::ConservativeProbe;
use super::diagnosis::SamplerKind;
use super::evidence::{InterpolationProbe, MeshEvidence, Resolved, SlopeRule};
use super::points::PointProbe;

/// What a probe found.
#[derive(Clone, Debug, Serialize)]
pub struct Profile {
    pub schema: &'static str,
    pub tool: crate::report::json::Tool,
    pub rasterizer: String,
    /// How it decides coverage: `point`, `area`, `any-coverage` or
    /// `unknown`. Only for `point` are the fill rule, subpixel bits and
    /// sample position measured; otherwise they are `null` / "not
    /// applicable". (Optional in `rastercheck-profile/1`: a profile
    /// without it was written for a point sampler.)
    pub sampler: SamplerKind,
    /// The frames that decided the sampler, in a sentence.
    pub sampler_evidence: String,
    /// The rule that explains the most tie samples (`top-left`, ...,
    /// `all-edges`, or `none` for open edges); `null` when nothing was
    /// drawn, or when it is not point-sampled.
    pub fill_rule: Option<String>,
    /// Whether that rule explains every tie sample.
    pub fill_rule_consistent: bool,
    /// `consistent` (one rule explains every tie sample), `inconsistent`
    /// (no one rule does, but each slope's ties follow a consistent rule:
    /// `tie_slopes` names those the nearest rule does not explain; `run
    /// --profile` then judges it as declaring no tie rule, `none`, SPEC.md
    /// §3.1.1), `unexplained` (some ties follow no consistent rule), or
    /// `not measured`.
    pub tie_verdict: &'static str,
    /// The slopes whose ties the nearest rule does not explain, each with
    /// the consistent rules that do, when the verdict is `inconsistent`.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub tie_slopes: Vec<SlopeRule>,
    /// What the tie rule was measured on: "N tie samples over M slopes
    /// (K meshes)".
    pub ties_measured_on: String,
    /// One entry per probe mesh.
    pub fill_rule_evidence: Vec<MeshEvidence>,
    /// `true` when y points down on screen (a triangle in the top half is
    /// drawn in the top rows), `false` when up, `null` when unclear.
    pub y_down: Option<bool>,
    /// Subpixel bits the rasterizer keeps for its vertices (`vertex_precision`;
    /// 0 when it truncates to whole pixels); `null` when it keeps all the
    /// case states (`exact`), when its x and y grids differ (then
    /// `vertex_precision` gives both), or when it could not be measured.
    pub subpixel_bits: Option<u32>,
    /// "8 bits", "exact", or why it is unknown.
    pub subpixel: String,
    /// Bits resolved along x and along y by slanted edges three rows from
    /// the vertex that moves: the vertex grid and the edge stepping
    /// together.
    pub subpixel_resolved: Resolved,
    /// Bits resolved along x and along y on the first sample row below
    /// the edge's top, where no edge has been stepped: the vertex grid.
    pub vertex_resolved: Resolved,
    /// The vertex grid in words: "8 bits", "exact", "0 bits: truncated to
    /// whole pixels", or why it was not measured.
    pub vertex_precision: String,
    /// How slanted edges are stepped: "as the vertices" when they resolve
    /// the vertex grid three rows on, or the bits they resolve when fewer.
    pub edge_precision: String,
    /// What the precision findings were measured on.
    pub precision_measured_on: String,
    /// Whether vertices are truncated to whole pixels, and on what scene.
    pub truncation: String,
    /// What the rasterizer declares about its snapping
    /// ([`crate::rasterizer::Rasterizer::fixed_snapping`]) against what was
    /// measured: "declares 4 subpixel bits; measured 4 (agrees)", or, when
    /// they disagree, "declares 8 subpixel bits; measured 4" (also a
    /// departure). Absent when it declares nothing.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub declared_snapping: Option<String>,
    /// "centre", "(x, y) in the pixel", "(1, 1) of the pixel, outside it
    /// ...", "several: ...", "none found" or "not applicable (...)".
    pub sample_position: String,
    /// The sample's offset in its pixel, when there is exactly one.
    pub sample_offset: Option<[f64; 2]>,
    pub interpolation: Vec<InterpolationProbe>,
    /// Its clipping (SPEC.md §16.9), when it takes clip space.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub clip: Option<ClipProbe>,
    /// What it does with clip-space points at the sides (SPEC.md §17.2),
    /// when it draws them.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub points: Option<PointProbe>,
    /// An area method's coverage encoding (SPEC.md §12.9), as `run
    /// --profile` reads it: `"unorm"` or `"fraction"`, with
    /// `coverage_bits`; `null` when none was measured (a sample method, a
    /// method that does not quantize, one that does not antialias).
    pub coverage_encoding: Option<&'static str>,
    pub coverage_bits: Option<u32>,
    /// The coverage finding in words, with what it was measured on;
    /// absent for a rasterizer that does not antialias.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub coverage: Option<String>,
    /// What its frames declare about their coverage encoding against what
    /// was measured, when they declare one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub declared_coverage: Option<String>,
    /// For an any-coverage (conservative) rasterizer, its uncertainty: how
    /// far outside a pixel's square a triangle still draws it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub conservative: Option<ConservativeProbe>,
    /// Departures from D3D11 and Vulkan, as sentences.
    pub departures: Vec<String>,
}
