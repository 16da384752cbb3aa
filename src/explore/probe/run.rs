//! [`probe`]: every probe run in turn on one rasterizer, into its profile.

use super::clip::probe_clip;
use super::describe::departures;
use super::diagnose::{diagnose_with_evidence, not_measured};
use super::evidence::{Resolved, PROBE_BITS};
use super::infer::{probe_axis, probe_interpolation, probe_y};
use super::points::probe_points;
use super::profile::Profile;
use crate::harness::profile::SCHEMA;
use crate::rasterizer::Rasterizer;

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
