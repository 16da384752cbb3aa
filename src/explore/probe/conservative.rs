//! The uncertainty of a conservative rasterizer, measured (issue 38): for
//! a rasterizer whose sampler is any-coverage (`sampler.rs`), how far
//! outside a pixel's closed square a triangle may lie and still draw the
//! pixel. Overestimation with uncertainty u draws a pixel whose square
//! meets the triangle grown by u (Vulkan: "increased at each of its edges"
//! by `primitiveOverestimationSize`); the largest gap at which it still
//! draws is u, to the probe's resolution.
//!
//! **The needles.** One cell per gap d: a triangle whose left side is
//! vertical at x = x_p + 1 + d, d to the right of the right side of the
//! cell's target pixel p (row p, half a pixel tall, in the middle of the
//! row), its third vertex half a pixel further right. Grown by u, its left
//! side moves to x_p + 1 + d − u (the corners move along that side: the
//! grown triangle reaches no further left), so the target is drawn exactly
//! when d ≤ u. The cells are 5 × 4 pixels: a triangle grown by up to 1 px
//! reaches no other cell's target. Three frames per axis refine the gap:
//! 65 gaps 2^-6 apart from 0 to 1 px, then 64 at 2^-12 in the last step
//! drawn, then 16 at 2^-16 in the last of those; the same transposed
//! measures along y. The scenes state 16 subpixel bits: a rasterizer that
//! snaps coarser moves each needle by less than its grid, and the finding
//! is then that grid's (reported as measured: gaps are as stated).
//!
//! The finding is the largest gap drawn and the smallest not drawn, exact;
//! a gap of 0 (the triangle touching the square's side) must be drawn,
//! and the drawn gaps must be a prefix of the sweep: otherwise it is said
//! so, and nothing is concluded from that axis. What this does not
//! measure: growth at corners beyond the edges' (Minkowski sum against
//! moved edges), underestimation, lines and points.

use serde::Serialize;
use serde_json::{json, Value};

use super::diagnosis::SamplerKind;
use super::infer::draw;
use crate::rasterizer::Rasterizer;
use crate::scene::{parse_case, Limits, Number, Scene};

/// The finest step of the sweep: gaps are multiples of 2^-[`FINE_BITS`].
pub const FINE_BITS: u32 = 16;

/// One refinement of the sweep: how many gaps, and their step in units
/// of 2^-16 px.
const LEVELS: [(u32, u64); 3] = [(65, 1 << 10), (64, 1 << 4), (16, 1)];

/// Cell size in pixels; cells per row of the canvas.
const CELL: (u32, u32) = (5, 4);
const PER_ROW: u32 = 13;

/// What the probe found along one axis.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Reach {
    /// The largest gap (px, exact) at which the pixel is still drawn;
    /// `null` when not even a touching triangle draws it.
    pub largest_drawn: Option<String>,
    /// The smallest gap tried beyond it that is not drawn; `null` when
    /// every gap up to 1 px is drawn.
    pub smallest_missed: Option<String>,
    /// `false` when a gap is drawn after one that is not (the drawn gaps
    /// are not a prefix of the sweep): the reach is then not a number.
    pub monotone: bool,
}

/// The conservative probe's finding, in the profile (`conservative`).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct ConservativeProbe {
    /// Along x (needles right of the pixel) and along y (below it).
    pub x: Reach,
    pub y: Reach,
    /// The uncertainty in words: "2^-9 px (1/512) along x and y", or why
    /// none is concluded.
    pub uncertainty: String,
    /// What it was measured on.
    pub measured_on: String,
}

/// What the needles are, in the words of a profile.
pub const MEASURED_ON: &str = "needles (triangles half a pixel tall) at gaps d from a pixel's closed square, right of it (x) and below it (y), 16 subpixel bits: 65 gaps 2^-6 apart from 0 to 1 px, 64 at 2^-12 and 16 at 2^-16 in the last step drawn; the pixel is drawn while d ≤ u";

/// `k`/2^16 as an exact string.
fn gap_text(k: u64) -> String {
    Number::ratio(k as i64, 1 << FINE_BITS).to_exact_string()
}

/// The needle scene of `gaps` (in 2^-16 px), along x or (transposed) y.
/// Returns the scene and each gap's target pixel.
pub(super) fn needle_scene(gaps: &[u64], along_y: bool) -> (Scene, Vec<(u32, u32)>) {
    let rows = (gaps.len() as u32).div_ceil(PER_ROW);
    let (w, h) = (PER_ROW * CELL.0, rows * CELL.1);
    let unit = 1u64 << FINE_BITS;
    let point = |x: u64, y: u64| -> Value {
        let [x, y] = [x, y].map(|v| json!(Number::ratio(v as i64, unit as i64).to_exact_string()));
        if along_y {
            json!([y, x])
        } else {
            json!([x, y])
        }
    };
    let mut targets = Vec::new();
    let mut triangles = Vec::new();
    for (i, &d) in gaps.iter().enumerate() {
        let (cx, cy) = ((i as u32 % PER_ROW) * CELL.0, (i as u32 / PER_ROW) * CELL.1);
        let (px, py) = (cx + 1, cy + 1);
        targets.push(if along_y { (py, px) } else { (px, py) });
        // In 2^-16 px: the left side at x_p + 1 + d, from y_p + 1/4 to
        // y_p + 3/4; the apex half a pixel right, at mid-height.
        let left = u64::from(px + 1) * unit + d;
        let (top, mid, bottom) = (
            u64::from(py) * unit + unit / 4,
            u64::from(py) * unit + unit / 2,
            u64::from(py) * unit + 3 * unit / 4,
        );
        triangles.push(json!({"triangle": [
            point(left, top), point(left + unit / 2, mid), point(left, bottom)
        ]}));
    }
    let (w, h) = if along_y { (h, w) } else { (w, h) };
    let scene = parse_case(
        &json!({
            "name": format!("probe_conservative_{}", if along_y { "y" } else { "x" }),
            "canvas": {"width": w, "height": h},
            "rules": {"subpixel_bits": FINE_BITS, "fill_rule": "top-left", "cull": "none"},
            "primitives": triangles,
        })
        .to_string(),
        "probe",
        &Limits::default(),
    )
    .unwrap_or_else(|e| panic!("a probe scene is invalid: {e}"));
    (scene, targets)
}

/// Which gaps of `gaps` the candidate draws its target pixel at.
fn drawn(candidate: &dyn Rasterizer, gaps: &[u64], along_y: bool) -> Result<Vec<bool>, String> {
    let (scene, targets) = needle_scene(gaps, along_y);
    let frame = draw(candidate, &scene).map_err(|e| e.to_string())?;
    Ok(targets
        .iter()
        .map(|&(x, y)| frame.samples > 0 && frame.coverage[frame.index(x, y)] > 0)
        .collect())
}

/// The reach along one axis: the three refinements in turn.
fn reach(candidate: &dyn Rasterizer, along_y: bool) -> Result<Reach, String> {
    let mut start = 0u64;
    let mut largest: Option<u64> = None;
    let mut missed: Option<u64> = None;
    for (n, step) in LEVELS {
        // The first level starts at 0; each later one just after the
        // largest gap drawn so far.
        let first = if largest.is_some() { start + step } else { 0 };
        let gaps: Vec<u64> = (0..u64::from(n)).map(|j| first + j * step).collect();
        let hits = drawn(candidate, &gaps, along_y)?;
        let prefix = hits.iter().take_while(|&&h| h).count();
        if hits[prefix..].iter().any(|&h| h) {
            return Ok(Reach {
                largest_drawn: largest.map(gap_text),
                smallest_missed: None,
                monotone: false,
            });
        }
        if prefix == 0 && largest.is_none() {
            break;
        }
        if prefix > 0 {
            largest = Some(gaps[prefix - 1]);
            start = gaps[prefix - 1];
        }
        match gaps.get(prefix) {
            Some(&g) => missed = Some(missed.map_or(g, |m: u64| m.min(g))),
            None => break,
        }
    }
    Ok(Reach {
        largest_drawn: largest.map(gap_text),
        smallest_missed: missed.map(gap_text),
        monotone: true,
    })
}

/// The uncertainty in words, from both axes.
fn words(x: &Reach, y: &Reach) -> String {
    let one = |r: &Reach| -> Result<String, String> {
        if !r.monotone {
            return Err("drawn at a gap beyond one it missed (not monotone)".into());
        }
        match (&r.largest_drawn, &r.smallest_missed) {
            (None, _) => {
                Err("a touching triangle does not draw the pixel: not overestimating".into())
            }
            (Some(d), Some(m)) => Ok(format!("{d} px (drawn at a gap of {d}, not at {m})")),
            (Some(d), None) => Ok(format!("at least {d} px")),
        }
    };
    match (one(x), one(y)) {
        (Ok(a), Ok(b)) if a == b => format!("{a} along x and y"),
        (Ok(a), Ok(b)) => format!("along x {a}; along y {b}"),
        (Err(e), _) => format!("none concluded: along x, {e}"),
        (_, Err(e)) => format!("none concluded: along y, {e}"),
    }
}

/// The conservative probe, for an any-coverage rasterizer, and for one
/// whose sampler is unknown (a conservative rasterizer growing triangles
/// by 1/32 px or more draws the sampler probe's slivers into their
/// neighbours, and is not recognised there): for the latter, kept only
/// where it looks conservative on both axes (a touching needle drawn, the
/// drawn gaps a prefix). `None` for any other (its pixels are decided
/// otherwise), or when it cannot draw the needles.
pub fn probe_conservative(
    candidate: &dyn Rasterizer,
    sampler: SamplerKind,
) -> Option<ConservativeProbe> {
    if !matches!(sampler, SamplerKind::AnyCoverage | SamplerKind::Unknown) {
        return None;
    }
    let x = reach(candidate, false).ok()?;
    let y = reach(candidate, true).ok()?;
    let conservative = |r: &Reach| r.monotone && r.largest_drawn.is_some();
    if sampler == SamplerKind::Unknown && !(conservative(&x) && conservative(&y)) {
        return None;
    }
    Some(ConservativeProbe {
        uncertainty: words(&x, &y),
        x,
        y,
        measured_on: MEASURED_ON.to_owned(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Primitive;

    /// Each needle's left side lies exactly its gap right of its target's
    /// square, in both orientations.
    #[test]
    fn each_needle_lies_its_gap_from_its_target() {
        let gaps = [0u64, 1, 1024, 65536];
        for along_y in [false, true] {
            let (scene, targets) = needle_scene(&gaps, along_y);
            for ((p, &(tx, ty)), &d) in scene.primitives.iter().zip(&targets).zip(&gaps) {
                let Primitive::Triangle(t) = p else { panic!() };
                let near = t
                    .vertices
                    .iter()
                    .map(|v| if along_y { v.y.clone() } else { v.x.clone() })
                    .min()
                    .unwrap();
                let side = Number::from_int(i64::from(if along_y { ty } else { tx }) + 1);
                assert_eq!(&near - &side, Number::ratio(d as i64, 65536));
            }
        }
    }
}
