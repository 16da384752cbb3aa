//! Convention probing: what a rasterizer does, found from its rendered
//! frames alone, and the profile (`rastercheck-profile/1`) that `run
//! --profile` judges it by.
//!
//! Every probe draws small scenes built here (no case files) and reads the
//! frames back; nothing about the rasterizer is assumed or asked:
//!
//! - **Sampler, first.** Slivers off every point of the 1/8 lattice, a
//!   mesh of strips 1/8 px high and a triangle over whole pixels tell a
//!   point sampler from an area sampler and an any-coverage (conservative)
//!   one (`sampler.rs` shows why exactly). The fill-rule, subpixel and
//!   sample-position probes below ask where one point per pixel falls;
//!   for a rasterizer that is not point-sampled they are not run, and the
//!   profile says "not applicable" instead of inventing a rule and bits.
//!   [`diagnose`] is the sampler, position and tie-rule decision alone: the
//!   matrix takes its words about a row's sampler and rule from it, so the
//!   two cannot disagree.
//! - **Fill rule.** Meshes whose samples lie exactly on shared horizontal,
//!   vertical and diagonal edges and on fan centres, in several windings
//!   and draw orders. The reference draws each under all five rules; the
//!   samples where the rules disagree are the tie samples, and the
//!   candidate's count and owner there are compared with each rule and with
//!   "none" (open edges: holes). The rule that explains every tie sample is
//!   the answer; when none does, the nearest is named and the rule is
//!   reported inconsistent, with the meshes where it departs.
//! - **y direction.** A triangle in the top half of the canvas: does it
//!   appear in the top rows?
//! - **Subpixel precision.** For k = 1..16, a vertex B of a thin triangle
//!   is drawn at three consecutive steps p_j → p_j + 2^-k of the 2^-k
//!   grid (j = 0, 1, 2), each in its own cell whose geometry puts one
//!   sample exactly on the edge when B is at τ_j = p_j + ⅓·2^-k or
//!   p_j + ⅔·2^-k: never a dyadic number, so never a rounding boundary or
//!   a tie, and strictly inside the step. The other vertices lie on the
//!   2^-k grid and do not move within a step. A rasterizer that keeps
//!   k bits (and is exact once it has snapped) draws each sample in one
//!   render of its step and not in the other. One that keeps b < k bits
//!   moves B to a point of its 2^-b grid less than 2^-b away (truncation,
//!   rounding with any ties): the four points p_0 … p_3 span 3·2^-k, and
//!   four distinct grid points 2^-b ≥ 2·2^-k apart cannot lie within 2^-b
//!   of them, so at least one step is drawn twice the same and its sample
//!   does not change. The finest k at which every step changes, for every
//!   k up to it, is therefore exactly the bits kept. The sweep is made
//!   along x and along y; one that rounds edge positions between vertices
//!   (tiny-skia rounds each edge's x on its first scanline to 1/64)
//!   resolves fewer bits along that axis, never more than its grid, so the
//!   grid is the finer of the two (both are reported). Scenes state 16
//!   subpixel bits, the most a case can: "exact" means the rasterizer
//!   keeps all of them.
//! - **Sample position.** 64 tiny triangles (3/32 px) around the offsets
//!   (i/8, j/8) of separate pixels, with a margin: the ones drawn say where
//!   the sample is, from −2 to 3 px, inside the pixel or not. It runs
//!   before the fill-rule and precision probes, whose scenes are then moved
//!   by (sample − centre) so that a shifted raster (a sample at (1, 1)) is
//!   read against the reference's centre samples, not as a wrong rule.
//! - **Interpolation.** A linear and a perspective mesh (w from 0.1 to 10)
//!   with depth and two attributes, measured as in `run` (SPEC §6.3).
//! - **Clipping** (`clip.rs`), for a rasterizer that takes clip space:
//!   which `clip_xy` and `clip_z` it follows, or whether it follows each
//!   case's (SPEC §16.9).
//! - **Points** (`points.rs`), for one that also draws points: whether a
//!   point whose centre leaves the side planes pops, and whether its
//!   square is cut at the viewport (`clip_points`, `point_bounds`, SPEC
//!   §17.2).
//!
//! `run --profile FILE` overrides each case's `rules.fill_rule` with the
//! profile's rule for the rasterizer the profile names (and drops the
//! case's `expect.samples_covered`, which pins the reference to the case's
//! own rule); snapping, sample position and interpolation are still judged
//! against the case as written.
//!
//! The rooms: this file holds the profile model and [`probe`], which runs
//! every probe; `scenes.rs` builds the probe scenes, `infer.rs` decides
//! what each probe found, `describe.rs` puts the profile into words and
//! JSON. Reading a profile for `run --profile` is the harness's
//! (`harness/profile.rs`).

mod clip;
mod describe;
mod infer;
mod points;
mod sampler;
mod scenes;
mod verdict;

use serde::Serialize;

use crate::rasterizer::Rasterizer;

pub use clip::{probe_clip, ClipProbe};
use describe::departures;
use infer::{
    nearest_rule, probe_axis, probe_fill_rule, probe_interpolation, probe_sample_position, probe_y,
};
pub use points::{probe_points, PointProbe};

pub use crate::harness::diagnosis::{Diagnosis, Sampler, SamplerKind};

pub use crate::harness::profile::SCHEMA;

/// The subpixel bits the probe scenes state: the most a case can.
pub const PROBE_BITS: u32 = 16;

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
    /// One entry per probe mesh.
    pub fill_rule_evidence: Vec<MeshEvidence>,
    /// `true` when y points down on screen (a triangle in the top half is
    /// drawn in the top rows), `false` when up, `null` when unclear.
    pub y_down: Option<bool>,
    /// Subpixel bits the rasterizer keeps; `null` when it keeps all the
    /// case states (`exact`) or when it could not be measured.
    pub subpixel_bits: Option<u32>,
    /// "8 bits", "exact", or why it is unknown.
    pub subpixel: String,
    /// Bits resolved along x and along y.
    pub subpixel_resolved: Resolved,
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
    /// Departures from D3D11 and Vulkan, as sentences.
    pub departures: Vec<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct Resolved {
    pub x: Option<u32>,
    pub y: Option<u32>,
}

#[derive(Clone, Debug, Serialize)]
pub struct MeshEvidence {
    pub mesh: String,
    pub tie_samples: usize,
    /// Tie samples each rule explains, in the order top-left, bottom-right,
    /// top-right, bottom-left, all-edges, none.
    pub explained: Vec<RuleCount>,
    /// Samples away from every edge that differ from the reference.
    pub off_edge_differences: usize,
    /// Why the rasterizer drew nothing, when it did not.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct RuleCount {
    pub rule: String,
    pub samples: usize,
}

#[derive(Clone, Debug, Serialize)]
pub struct InterpolationProbe {
    pub case: String,
    /// `measured`, `unsupported` or `error`.
    pub status: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub why: Option<String>,
    pub channels: Vec<ChannelProbe>,
}

#[derive(Clone, Debug, Serialize)]
pub struct ChannelProbe {
    pub channel: String,
    pub max_abs: f64,
    pub max_ulp: f64,
    pub allowed_abs: f64,
    pub within_bound: bool,
}

/// The candidate rules: the five fill rules, then "none" (open edges).
pub const RULE_NAMES: [&str; 6] = [
    "top-left",
    "bottom-right",
    "top-right",
    "bottom-left",
    "all-edges",
    "none",
];

/// Why the point-sampler probes were not run, or `None` when they were.
fn not_measured(d: &Diagnosis) -> Option<String> {
    match (d.sampler.kind, d.offset) {
        (SamplerKind::Point, Some(_)) => None,
        (SamplerKind::Point, None) => Some(format!(
            "not measured: its sample position was not found ({})",
            d.sample_position
        )),
        (kind, _) => Some(format!("not applicable ({})", kind.words())),
    }
}

/// The sampler decision, then for a point sampler its sample position and
/// tie rule (the meshes moved for its sample): what the matrix's findings
/// say about a row. `Err` when it draws none of the probe scenes.
pub fn diagnose(candidate: &dyn Rasterizer) -> Result<Diagnosis, String> {
    diagnose_with_evidence(candidate).map(|(d, _)| d)
}

/// [`diagnose`], with the fill-rule evidence per mesh.
fn diagnose_with_evidence(
    candidate: &dyn Rasterizer,
) -> Result<(Diagnosis, Vec<MeshEvidence>), String> {
    let sampler = sampler::decide(candidate)
        .map_err(|e| format!("{} could not draw the probe scenes: {e}", candidate.name()))?;
    let mut d = Diagnosis {
        sample_position: String::new(),
        offset: None,
        fill_rule: None,
        fill_rule_consistent: false,
        sampler,
    };
    if d.sampler.kind != SamplerKind::Point {
        d.sample_position = not_measured(&d).unwrap_or_default();
        return Ok((d, Vec::new()));
    }
    let position = probe_sample_position(candidate);
    d.sample_position = position.words;
    d.offset = position.offset;
    let Some(o) = d.offset else {
        return Ok((d, Vec::new()));
    };
    let evidence = probe_fill_rule(candidate, o);
    if let Some(e) = evidence.iter().find_map(|e| e.error.clone()) {
        if evidence.iter().all(|e| e.error.is_some()) {
            return Err(format!(
                "{} could not draw the probe meshes: {e}",
                candidate.name()
            ));
        }
    }
    let rule = nearest_rule(&evidence);
    d.fill_rule = rule.as_ref().map(|r| r.0.clone());
    d.fill_rule_consistent = rule.as_ref().is_some_and(|r| r.1);
    Ok((d, evidence))
}

/// Probes a rasterizer. `Err` when it draws none of the probe scenes.
pub fn probe(candidate: &dyn Rasterizer) -> Result<Profile, String> {
    let (d, evidence) = diagnose_with_evidence(candidate)?;
    let y_down = probe_y(candidate);
    let (x_bits, y_bits) = match (not_measured(&d), d.offset) {
        (None, Some(o)) => (
            probe_axis(candidate, false, o),
            probe_axis(candidate, true, o),
        ),
        (why, _) => {
            let why = why.unwrap_or_default();
            (Err(why.clone()), Err(why))
        }
    };
    let (subpixel_bits, subpixel) = match (&x_bits, &y_bits) {
        (Ok(x), Ok(y)) => {
            // A rasterizer cannot resolve finer than its vertex grid along
            // any axis, but may resolve less along one where it rounds edge
            // positions between vertices: the grid is the finer of the two.
            let b = (*x).max(*y);
            let axes = if x == y {
                String::new()
            } else {
                format!(
                    " (x {x}, y {y}: edges resolve fewer bits along {} than the vertex grid)",
                    if x < y { "x" } else { "y" }
                )
            };
            if b >= PROBE_BITS {
                (None, format!("exact{axes}"))
            } else {
                (Some(b), format!("{b} bits{axes}"))
            }
        }
        (Err(e), _) | (_, Err(e)) if e.starts_with("not ") => (None, e.clone()),
        (Err(e), _) | (_, Err(e)) => (None, format!("unknown: {e}")),
    };
    let interpolation = probe_interpolation(candidate);
    let mut profile = Profile {
        schema: SCHEMA,
        tool: crate::report::json::Tool {
            name: "rastercheck",
            version: env!("CARGO_PKG_VERSION"),
        },
        rasterizer: candidate.name().to_owned(),
        sampler: d.sampler.kind,
        sampler_evidence: d.sampler.evidence,
        fill_rule: d.fill_rule,
        fill_rule_consistent: d.fill_rule_consistent,
        fill_rule_evidence: evidence,
        y_down,
        subpixel_bits,
        subpixel,
        subpixel_resolved: Resolved {
            x: x_bits.ok(),
            y: y_bits.ok(),
        },
        sample_position: d.sample_position,
        sample_offset: d.offset.map(|(x, y)| [x as f64 / 8.0, y as f64 / 8.0]),
        interpolation,
        clip: probe_clip(candidate),
        points: probe_points(candidate),
        departures: Vec::new(),
    };
    profile.departures = departures(&profile);
    Ok(profile)
}
