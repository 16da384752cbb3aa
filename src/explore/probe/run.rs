//! [`probe`]: every probe run in turn on one rasterizer, into its profile.
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
//!   [`diagnose`](super::diagnose) is the sampler, position and tie-rule decision alone: the
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
//!   k up to it, is therefore exactly the bits kept. Two sweeps are made
//!   along x and two along y: the vertex cells put the sample on the first
//!   sample row below the edge's top, where no edge is stepped (the vertex
//!   grid, per axis), the edge cells three rows down a slanted edge (the
//!   grid and the edge stepping together); one that rounds edge positions
//!   between vertices (tiny-skia rounds each edge's x on its first
//!   scanline to 1/64) resolves fewer bits in the edge cells, never more
//!   than its grid, and is reported apart. Scenes state 16
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
//! - **Coverage encoding** (`coverage.rs`), for one that antialiases: an
//!   area method's fractions read as multiples of 1/(2^k − 1) or of 1/2^k,
//!   its whole pixels for saturation (SPEC §12.9).
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

use super::clip::probe_clip;
use super::conservative::probe_conservative;
use super::coverage::{against_declared as coverage_against_declared, probe_coverage};
use super::describe::departures;
use super::diagnose::{diagnose_with_evidence, not_measured};
use super::evidence::{Resolved, PROBE_BITS};
use super::infer::{probe_axis, probe_interpolation, probe_y, Along};
use super::points::probe_points;
use super::profile::Profile;
use super::truncation::{truncates, MEASURED_ON as TRUNCATION_ON};
use crate::harness::profile::SCHEMA;
use crate::rasterizer::{Rasterizer, Snapping};

/// Probes a rasterizer. `Err` when it draws none of the probe scenes.
pub fn probe(candidate: &dyn Rasterizer) -> Result<Profile, String> {
    let (d, evidence) = diagnose_with_evidence(candidate)?;
    let y_down = probe_y(candidate);
    let truncates = truncates(candidate, d.offset);
    let measured = |along: Along| match (not_measured(&d), d.offset) {
        (None, Some(o)) => (
            probe_axis(candidate, along, false, o),
            probe_axis(candidate, along, true, o),
        ),
        (why, _) => {
            let why = why.unwrap_or_default();
            (Err(why.clone()), Err(why))
        }
    };
    let (vertex_x, vertex_y) = measured(Along::Vertex);
    let (x_bits, y_bits) = measured(Along::Edge);
    let precision = precision(
        truncates == Some(true),
        (&vertex_x, &vertex_y),
        (&x_bits, &y_bits),
    );
    let (subpixel_bits, subpixel) = (precision.bits, precision.words.clone());
    let declared_snapping = candidate
        .fixed_snapping()
        .map(|declared| against_declared(declared, subpixel_bits, &subpixel));
    let interpolation = probe_interpolation(candidate);
    let coverage = probe_coverage(candidate);
    let declared_coverage = coverage.as_ref().and_then(coverage_against_declared);
    let encoding = coverage.as_ref().and_then(|c| c.encoding);
    let mut profile = Profile {
        schema: SCHEMA,
        tool: crate::report::json::Tool {
            name: "rastercheck",
            version: env!("CARGO_PKG_VERSION"),
        },
        rasterizer: candidate.name().to_owned(),
        sampler: d.sampler.kind,
        sampler_evidence: d.sampler.evidence,
        tie_verdict: match (
            &d.fill_rule,
            d.fill_rule_consistent,
            d.tie_slopes.is_empty(),
        ) {
            (None, _, _) => "not measured",
            (Some(_), true, _) => "consistent",
            (Some(_), false, false) => "inconsistent",
            (Some(_), false, true) => "unexplained",
        },
        tie_slopes: d.tie_slopes,
        ties_measured_on: d.ties_measured_on,
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
        vertex_resolved: Resolved {
            x: vertex_x.ok(),
            y: vertex_y.ok(),
        },
        vertex_precision: precision.vertex,
        edge_precision: precision.edges,
        precision_measured_on: PRECISION_MEASURED_ON.to_owned(),
        truncation: match truncates {
            Some(true) => format!("truncates vertices to whole pixels (⌊x⌋, ⌊y⌋): {TRUNCATION_ON}"),
            Some(false) => {
                format!("does not truncate vertices to whole pixels (not drawn as {TRUNCATION_ON})")
            }
            None => "not measured: it could not draw the truncation squares".to_owned(),
        },
        declared_snapping: declared_snapping.clone(),
        sample_position: d.sample_position,
        sample_offset: d.offset.map(|(x, y)| [x as f64 / 8.0, y as f64 / 8.0]),
        interpolation,
        clip: probe_clip(candidate),
        points: probe_points(candidate),
        coverage_encoding: encoding.map(|e| e.word()),
        coverage_bits: encoding.map(|e| e.bits),
        coverage: coverage.map(|c| c.words),
        declared_coverage: declared_coverage.clone(),
        conservative: probe_conservative(candidate, d.sampler.kind),
        departures: Vec::new(),
    };
    profile.departures = departures(&profile);
    if let Some(words) = declared_snapping.filter(|w| !w.ends_with("(agrees)")) {
        profile.departures.push(words);
    }
    if let Some(words) = declared_coverage.filter(|w| !w.ends_with("(agrees)")) {
        profile.departures.push(format!(
            "It {words}: judged as declared, its answers are read wrongly (SPEC.md §12.9); declare the measured encoding"
        ));
    }
    Ok(profile)
}

/// What the precision probes draw, in the words a profile gives.
pub const PRECISION_MEASURED_ON: &str = "48 cells, a vertex moved by 2^-k (k = 1..16, three steps each): the vertex grid along x and along y, with the sample on the first sample row below the edge's top (no edge stepped); the edges along x and y, with the sample three rows down a slanted edge";

/// The precision findings: the vertex grid (bits, `None` when exact or
/// unmeasured), the profile's `subpixel` words, and the vertex and edge
/// findings apart.
struct Precision {
    bits: Option<u32>,
    words: String,
    vertex: String,
    edges: String,
}

/// Bits per axis in words: "8 bits", or "x 6, y 8 bits" when they differ;
/// "exact" at the probe's bits.
fn axes_words(x: u32, y: u32) -> String {
    match (x.min(y) >= PROBE_BITS, x == y) {
        (true, _) => "exact".to_owned(),
        (false, true) => format!("{x} bits"),
        (false, false) => format!("x {x}, y {y} bits"),
    }
}

/// The vertex grid is what the vertex cells resolve along x and along y
/// (one number when they agree; "x 8, y 6 bits" and no single `bits` when
/// they do not, since SPEC.md §3.2's snapping is one grid); edges are
/// reported apart when they resolve fewer bits three rows on than the
/// vertex grid along the same axis; truncation to whole pixels is 0 bits,
/// found on its own scene, whether or not the cells could be read.
fn precision(
    truncates: bool,
    vertex: (&Result<u32, String>, &Result<u32, String>),
    edges: (&Result<u32, String>, &Result<u32, String>),
) -> Precision {
    let why = |e: &String| {
        if e.starts_with("not ") {
            e.clone()
        } else {
            format!("unknown: {e}")
        }
    };
    let (bits, vertex_words) = match vertex {
        (Ok(x), Ok(y)) => (
            (x == y && *x < PROBE_BITS).then_some(*x),
            axes_words(*x, *y),
        ),
        (Err(e), _) | (_, Err(e)) => (None, why(e)),
    };
    let edge_words = match (vertex, edges) {
        ((Ok(vx), Ok(vy)), (Ok(ex), Ok(ey))) if ex >= vx && ey >= vy => {
            "as the vertices".to_owned()
        }
        (_, (Ok(ex), Ok(ey))) => format!(
            "{}, three rows down a slanted edge: stepped coarser than the vertex grid",
            axes_words(*ex, *ey)
        ),
        (_, (Err(e), _) | (_, Err(e))) => why(e),
    };
    if truncates {
        let words = "0 bits: vertices truncated to whole pixels".to_owned();
        return Precision {
            bits: Some(0),
            words: words.clone(),
            vertex: words,
            edges: edge_words,
        };
    }
    let mut words = vertex_words.clone();
    if !edge_words.starts_with("as the")
        && !edge_words.starts_with("not ")
        && !edge_words.starts_with("unknown")
    {
        words += &format!(" (slanted edges resolve {edge_words})");
    }
    Precision {
        bits,
        words,
        vertex: vertex_words,
        edges: edge_words,
    }
}

/// A declared snapping against the measured one (`measured`: the bits kept,
/// `None` when exact or unmeasured; `words`: probe's account): "declares 8
/// subpixel bits; measured 4", ending "(agrees)" when they agree. Truncation
/// to whole pixels keeps 0 bits; no snapping keeps all the probe states.
pub fn against_declared(declared: Snapping, measured: Option<u32>, words: &str) -> String {
    let exact = measured.is_none() && words.starts_with("exact");
    let agrees = match declared {
        Snapping::Bits(bits) => measured == Some(bits) || exact && bits >= PROBE_BITS,
        Snapping::Truncate => measured == Some(0),
        Snapping::None => exact,
    };
    let measured = match measured {
        Some(bits) => bits.to_string(),
        None => words.to_owned(),
    };
    let declared = match declared {
        Snapping::Bits(bits) => format!("{bits} subpixel bits"),
        other => other.words(),
    };
    let verdict = if agrees { " (agrees)" } else { "" };
    format!("declares {declared}; measured {measured}{verdict}")
}
