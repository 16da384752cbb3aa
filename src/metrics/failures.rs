//! The verdict: why a candidate fails a case, from its metrics.

use super::antialias;
use super::counted::counted;
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
            "coverage: {} from the reference ({} missing, {} extra, {} wrong owner; {} allowed)",
            counted(c.mismatched(), "sample differs", "samples differ"),
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
                "watertight: {} and {}",
                counted(w.holes, "hole", "holes"),
                counted(w.overdraw, "overdrawn sample", "overdrawn samples")
            ));
        }
    }
    if let Some(l) = &m.lines {
        if l.crowded_steps > 0 {
            out.push(format!(
                "lines: {} more than one pixel of the same midpoint line",
                counted(
                    l.crowded_steps,
                    "major-axis step holds",
                    "major-axis steps hold"
                )
            ));
        }
    }
    for ch in &m.channels {
        if let (Some(miss), false) = (&ch.depth_set, ch.within_bounds()) {
            out.push(format!(
                "{}: {} outside the depths {} allows (largest distance {:.3e}), {} off its grid (SPEC.md §18)",
                ch.channel,
                counted(miss.outside, "sample", "samples"),
                miss.format,
                ch.max_abs,
                miss.off_grid
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::interpolation::{ChannelError, DepthSetMiss};
    use crate::metrics::line::LineMetrics;
    use crate::metrics::measure::measure;
    use crate::metrics::watertight::WatertightMetrics;
    use crate::plan::Plan;
    use crate::reference::render;
    use crate::scene::{parse_case, Limits};

    /// The reasons for one triangle drawn exactly, with `edit` made to its
    /// metrics.
    fn reasons(edit: impl Fn(&mut Metrics)) -> Vec<String> {
        let scene = parse_case(
            r#"{"name": "t", "canvas": {"width": 4, "height": 4},
                "primitives": [{"triangle": [[0, 0], [4, 0], [0, 4]]}]}"#,
            "t.json",
            &Limits::default(),
        )
        .unwrap();
        let reference = render(&scene, &Plan::for_scene(&scene));
        let mut m = measure(&scene, &reference, &reference, None);
        edit(&mut m);
        failures(&scene, &reference, &m)
    }

    #[test]
    fn the_coverage_reason_takes_the_number_of_its_count() {
        let one = reasons(|m| m.coverage.missing = 1);
        assert!(
            one[0].starts_with("coverage: 1 sample differs from the reference (1 missing,"),
            "{one:?}"
        );
        let two = reasons(|m| m.coverage.extra = 2);
        assert!(
            two[0]
                .starts_with("coverage: 2 samples differ from the reference (0 missing, 2 extra,"),
            "{two:?}"
        );
    }

    #[test]
    fn the_watertight_reason_takes_the_number_of_each_count() {
        let with = |holes, overdraw| {
            reasons(move |m| {
                m.watertight = Some(WatertightMetrics {
                    interior: 16,
                    holes,
                    overdraw,
                })
            })
        };
        assert_eq!(with(1, 0), ["watertight: 1 hole and 0 overdrawn samples"]);
        assert_eq!(with(2, 1), ["watertight: 2 holes and 1 overdrawn sample"]);
    }

    #[test]
    fn the_midpoint_line_reason_takes_the_number_of_its_count() {
        let with = |crowded_steps| {
            reasons(move |m| {
                m.lines = Some(LineMetrics {
                    lines: 1,
                    crowded_steps,
                })
            })
        };
        assert_eq!(
            with(1),
            ["lines: 1 major-axis step holds more than one pixel of the same midpoint line"]
        );
        assert_eq!(
            with(3),
            ["lines: 3 major-axis steps hold more than one pixel of the same midpoint line"]
        );
    }

    #[test]
    fn the_depth_set_reason_takes_the_number_of_its_count() {
        let with = |outside| {
            reasons(move |m| {
                m.channels = vec![ChannelError {
                    channel: "depth".into(),
                    samples: 8,
                    max_abs: 0.5,
                    max_ulp: 0.0,
                    rms: 0.0,
                    allowed_abs: 0.0,
                    allowed_ulp: None,
                    depth_set: Some(DepthSetMiss {
                        format: "unorm16",
                        off_grid: 0,
                        outside,
                    }),
                }]
            })
        };
        assert!(
            with(1)[0].starts_with("depth: 1 sample outside the depths unorm16 allows"),
            "{:?}",
            with(1)
        );
        assert!(
            with(7)[0].starts_with("depth: 7 samples outside the depths unorm16 allows"),
            "{:?}",
            with(7)
        );
    }
}
