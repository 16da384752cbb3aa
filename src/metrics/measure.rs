//! Measuring a candidate's frame against the reference's: every metric of
//! one case, with what the oracle knows exactly beyond its frame.

use super::antialias::{self, AntialiasMetrics, AreaClass};
use super::area;
use super::conservative::ConservativeMetrics;
use super::coverage::{self, CoverageMetrics};
use super::depth;
use super::interpolation::{self, ChannelError};
use super::latitude::{self, LatitudeMetrics};
use super::line::{self, LineMetrics};
use super::parts;
use super::ties::{self, TieMetrics};
use super::time::{self, TimeMetrics};
use super::watertight::{self, WatertightMetrics};
use crate::frame::Frame;
use crate::reference::{DiamondLine, TieSet};
use crate::scene::{DepthFormat, Number, Scene};

/// The default interpolation bound, relative to the channel's largest vertex
/// magnitude M: |error| ≤ 2^-16 · max(1, M) (SPEC.md, "Interpolation
/// tolerance"). That is 128 f32 ulps of M: loose enough for any f32 plane
/// setup, tight enough to catch a wrong weight, vertex or formula.
pub const DEFAULT_RELATIVE_BOUND: f64 = crate::scene::depth::RELATIVE_BOUND;

/// Everything measured for one candidate on one case.
#[derive(Clone, Debug, PartialEq)]
pub struct Metrics {
    pub coverage: CoverageMetrics,
    pub watertight: Option<WatertightMetrics>,
    pub lines: Option<LineMetrics>,
    pub channels: Vec<ChannelError>,
    /// Antialiased cases: resolved coverage against the exact area.
    pub antialias: Option<AntialiasMetrics>,
    /// Scenes in which something moves: time coverage against the exact
    /// time coverage (SPEC.md §15.4). Such frames have no samples, so this
    /// is then the only metric with anything in it.
    pub time: Option<TimeMetrics>,
    /// A candidate with no tie rule (SPEC.md §3.1.1): its tie samples,
    /// and the overdraw and holes they got, counted apart.
    pub ties: Option<TieMetrics>,
    /// A candidate that draws diamond-exit lines with its API's latitude
    /// (SPEC.md §4.2.1): its lines judged under it, what used it counted.
    pub latitude: Option<LatitudeMetrics>,
    /// Conservative scenes (SPEC.md §19): the candidate's pixels and
    /// fully-covered flags against the reference's three classes. Then
    /// `coverage` holds the same pixels against the required set, a pixel
    /// drawn in the allowed band counted neither missing nor extra.
    pub conservative: Option<ConservativeMetrics>,
}

/// What the oracle knows exactly beyond the reference's frame, for the
/// metrics that read it; every part is optional.
#[derive(Clone, Copy, Debug, Default)]
pub struct Known<'a> {
    /// The mesh interior, for mesh cases (`expect.watertight`).
    pub interior: Option<&'a [bool]>,
    /// Each pixel's exact area class, for antialiased cases (from
    /// `reference::exact_areas`).
    pub classes: Option<&'a [AreaClass]>,
    /// Whether each pixel's exact time coverage is a whole number, for
    /// moving scenes (from the oracle's certified values).
    pub whole_time: Option<&'a [bool]>,
    /// Each primitive's exact area of each pixel it covers, for a candidate
    /// that gives its coverage per primitive (`reference::primitive_pixel_areas`).
    pub part_areas: Option<&'a [Vec<(u32, dashu_ratio::RBig)>]>,
    /// The depths a candidate may read back at each slot, for a scene with
    /// a depth format (`reference::render_judged`): required for such a
    /// scene (the metrics never draw the reference themselves).
    pub depth_allowed: Option<&'a [[f64; 2]]>,
    /// The samples exactly on an edge, for a candidate that declares no
    /// tie rule (`reference::tie_set`): judged off them.
    pub ties: Option<&'a TieSet>,
    /// Each diamond-exit line's exact fragments, for a candidate that
    /// draws them with its API's latitude (`reference::diamond_lines`):
    /// judged under it.
    pub latitude: Option<&'a [DiamondLine]>,
    /// The scene whose vertices give the magnitudes M of SPEC.md §6.3's
    /// bounds, where the judged scene's do not: a case restated clipped
    /// at a viewport has them from its whole triangles (§16.9); `None`:
    /// the judged scene's.
    pub magnitudes: Option<&'a Scene>,
}

/// Measures a candidate against the reference. `interior` is given for
/// mesh cases (`expect.watertight`). A scene with a depth format
/// (SPEC.md §18) goes through [`measure_known`] with the depths it allows.
pub fn measure(
    scene: &Scene,
    reference: &Frame,
    candidate: &Frame,
    interior: Option<&[bool]>,
) -> Metrics {
    measure_with_areas(scene, reference, candidate, interior, None)
}

/// [`measure`], with each pixel's exact area class for antialiased cases
/// (from `reference::exact_areas`; without it, the class is read from the
/// reference's rounded area).
pub fn measure_with_areas(
    scene: &Scene,
    reference: &Frame,
    candidate: &Frame,
    interior: Option<&[bool]>,
    classes: Option<&[AreaClass]>,
) -> Metrics {
    let known = Known {
        interior,
        classes,
        ..Known::default()
    };
    measure_known(scene, reference, candidate, &known)
}

/// [`measure`], with what the oracle knows exactly ([`Known`]).
///
/// # Panics
/// For a scene with a depth format whose reference has depth, when
/// `known.depth_allowed` is not given.
pub fn measure_known(
    scene: &Scene,
    reference: &Frame,
    candidate: &Frame,
    known: &Known,
) -> Metrics {
    let (interior, classes) = (known.interior, known.classes);
    let mut coverage = coverage::compare_off_ties(reference, candidate, known.ties);
    let latitude = known
        .latitude
        .and_then(|lines| latitude::measure(lines, reference, candidate, &mut coverage));
    let watertight = interior
        .and_then(|inside| watertight::measure_off_ties(inside, reference, candidate, known.ties));
    let ties = known
        .ties
        .and_then(|set| ties::measure(set, reference, candidate));
    let time = time::measure(reference, candidate, known.whole_time, time::bounds(scene));
    let parts = match (&candidate.parts, known.part_areas) {
        (Some(given), Some(exact)) => Some(parts::measure(
            given,
            exact,
            scene.canvas.width,
            candidate.pixel_count(),
        )),
        _ => None,
    };
    let mut antialias = antialias::measure_with_slack(
        reference,
        candidate,
        classes,
        antialias::bounds(
            scene.expect.max_coverage_error,
            scene.expect.max_coverage_rms,
            candidate.samples,
            area::is_area_answer(candidate),
        ),
        parts.as_ref().map(|p| p.slack.as_slice()),
    );
    if let Some(aa) = &mut antialias {
        aa.pixel_areas = area::pixel_areas(reference, candidate);
    }
    if let (Some(aa), Some(p)) = (&mut antialias, parts) {
        aa.nothing_drawn = area::nothing_drawn(candidate, &p.areas);
        aa.primitives = Some(p.metrics);
    }
    let mut channels = Vec::new();
    if !coverage.has_mask() {
        return Metrics {
            coverage,
            watertight,
            lines: None,
            channels,
            antialias,
            time,
            ties,
            latitude,
            conservative: None,
        };
    }
    let expect = &scene.expect;
    let bounds = |magnitude: f64| interpolation::Bounds {
        allowed_abs: expect
            .max_abs_error
            .unwrap_or(DEFAULT_RELATIVE_BOUND * magnitude.max(1.0)),
        allowed_ulp: expect.max_ulp_error,
        ulp_floor: DEFAULT_RELATIVE_BOUND * magnitude.max(1.0),
    };
    let format = scene.rules.depth_format;
    match (&reference.depth, &candidate.depth) {
        (Some(_), Some(values)) if format != DepthFormat::Exact => {
            // Judged against the set the format allows (SPEC.md §18.1).
            let allowed = known
                .depth_allowed
                .expect("Known::depth_allowed for a scene with a depth format");
            channels.push(depth::measure(
                format, reference, candidate, allowed, values,
            ));
        }
        (Some(exact), Some(values)) => {
            // A clip-space scene writes depths in the viewport's range,
            // within [0, 1] (SPEC.md §16.1), whatever its clip z.
            channels.push(interpolation::channel_error(
                "depth",
                reference,
                candidate,
                exact,
                values,
                bounds(known.magnitudes.unwrap_or(scene).depth_magnitude()),
            ));
        }
        _ => {}
    }
    for (k, (exact, values)) in reference
        .attributes
        .iter()
        .zip(&candidate.attributes)
        .enumerate()
    {
        // A polygon's vertices carry no attributes.
        let vertices = known.magnitudes.unwrap_or(scene).vertices();
        let m = largest(vertices.filter_map(|v| v.attributes.get(k)));
        channels.push(interpolation::channel_error(
            &format!("attribute {k}"),
            reference,
            candidate,
            exact,
            values,
            bounds(m),
        ));
    }
    Metrics {
        coverage,
        watertight,
        lines: line::measure(scene, candidate),
        channels,
        antialias,
        time,
        ties,
        latitude,
        conservative: None,
    }
}

fn largest<'a>(values: impl Iterator<Item = &'a Number>) -> f64 {
    values.map(|v| v.abs().to_f64_lossy()).fold(0.0, f64::max)
}
