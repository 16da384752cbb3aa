//! The sampler decision, then for a point sampler its sample position and
//! tie rule: what the matrix's findings say about a row, and where a full
//! probe starts.

use super::diagnosis::{Diagnosis, SamplerKind};
use super::evidence::MeshEvidence;
use super::infer::{nearest_rule, probe_fill_rule, probe_sample_position, slope_findings};
use super::sampler;
use crate::rasterizer::Rasterizer;

/// Why the point-sampler probes were not run, or `None` when they were.
pub(super) fn not_measured(d: &Diagnosis) -> Option<String> {
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
pub(super) fn diagnose_with_evidence(
    candidate: &dyn Rasterizer,
) -> Result<(Diagnosis, Vec<MeshEvidence>), String> {
    let sampler = sampler::decide(candidate)
        .map_err(|e| format!("{} could not draw the probe scenes: {e}", candidate.name()))?;
    let mut d = Diagnosis {
        sample_position: String::new(),
        offset: None,
        fill_rule: None,
        fill_rule_consistent: false,
        tie_slopes: Vec::new(),
        ties_measured_on: String::new(),
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
    if let Some((nearest, consistent)) = &rule {
        let (slopes, measured_on) = slope_findings(&evidence, nearest);
        d.ties_measured_on = measured_on;
        if !consistent {
            d.tie_slopes = slopes.unwrap_or_default();
        }
    }
    Ok((d, evidence))
}
