//! The verdict: why a candidate fails a case, from its metrics.

use super::antialias;
use super::measure::Metrics;
use super::time;
use crate::frame::Frame;
use crate::scene::Scene;

/// Why a candidate fails a case; empty when it passes.
pub fn failures(scene: &Scene, reference: &Frame, m: &Metrics) -> Vec<String> {
    let mut out = Vec::new();
    let expect = &scene.expect;
    let c = &m.coverage;
    if c.mismatched() > expect.max_mismatched_samples {
        out.push(format!(
            "coverage: {} samples differ from the reference ({} missing, {} extra, {} wrong owner; {} allowed)",
            c.mismatched(),
            c.missing,
            c.extra,
            c.wrong_owner,
            expect.max_mismatched_samples
        ));
    }
    // With no tie rule (SPEC.md §3.1.1), drawing nothing is a choice of
    // sides where the reference covers only tie samples.
    let tied = m.ties.as_ref().map_or(0, |t| t.reference_covered);
    if c.has_mask() && c.reference_covered > tied && c.candidate_covered == 0 {
        out.push(
            "coverage: the candidate drew nothing where the reference draws something".to_owned(),
        );
    }
    if let Some(l) = &m.latitude {
        out.extend(l.failures());
    }
    if let Some(w) = &m.watertight {
        if !w.is_watertight() {
            out.push(format!(
                "watertight: {} holes and {} overdrawn samples",
                w.holes, w.overdraw
            ));
        }
    }
    if let Some(l) = &m.lines {
        if l.crowded_steps > 0 {
            out.push(format!(
                "lines: {} major-axis steps hold more than one pixel of the same midpoint line",
                l.crowded_steps
            ));
        }
    }
    for ch in &m.channels {
        if let (Some(miss), false) = (&ch.depth_set, ch.within_bounds()) {
            out.push(format!(
                "{}: {} samples outside the depths {} allows (largest distance {:.3e}), {} off its grid (SPEC.md §18)",
                ch.channel, miss.outside, miss.format, ch.max_abs, miss.off_grid
            ));
        } else if !ch.within_bounds() {
            let ulp = ch
                .allowed_ulp
                .map(|u| format!(" or {u} ulp"))
                .unwrap_or_default();
            out.push(format!(
                "{}: max error {:.3e} ({:.1} ulp) exceeds {:.3e}{ulp}",
                ch.channel, ch.max_abs, ch.max_ulp, ch.allowed_abs
            ));
        }
    }
    if let Some(aa) = &m.antialias {
        out.extend(antialias::failures(aa));
    }
    if reference.time.is_some() {
        match &m.time {
            Some(t) => out.extend(time::failures(t)),
            None => out.push(
                "time: the candidate returned no time coverage of the right size for a scene in which something moves".to_owned(),
            ),
        }
        // Judged on time coverage only: the sample expectations cannot
        // hold or fail, so a case that gives them is wrong.
        for key in expect.sample_expectations() {
            out.push(format!(
                "case: expect.{key} does not apply to a scene in which something moves (it is judged on time coverage only, SPEC.md §15.1)"
            ));
        }
        return out;
    }
    if let Some(expected) = expect.samples_covered {
        let covered = reference.covered_samples();
        if covered != expected {
            out.push(format!(
                "reference: covers {covered} samples but the case expects {expected}"
            ));
        }
    }
    out
}
