//! A polygon's contours in fixed point, as every polygon method takes them:
//! the fill rule's nudge, snapped vertices, a single contour without
//! repeats, and the turn of three points.

use super::scanline::{Nudge, Point};
use crate::production::fixed::Format;
use crate::rasterizer::RasterError;
use crate::scene::{Number, Polygon, Scene};

/// The nudge of the scene's fill rule.
pub(super) fn nudge(scene: &Scene) -> Result<Nudge, RasterError> {
    Nudge::of(scene.rules.fill_rule).ok_or_else(|| {
        RasterError::Unsupported("all-edges is not defined for polygons (SPEC.md §14.1)".to_owned())
    })
}

/// A coordinate in `format`, snapped as the scene says, or held exactly
/// when the scene keeps exact coordinates (as production does for
/// triangles).
fn place(scene: &Scene, format: Format, n: &Number) -> Result<i64, RasterError> {
    match scene.rules.subpixel_bits {
        Some(bits) => Ok(format.snap(n, bits).0),
        None => format.exact(n).map(|f| f.0).ok_or_else(|| {
            RasterError::Unsupported(format!(
                "the coordinate {} is not a multiple of 2^-{}",
                n.to_exact_string(),
                format.frac_bits
            ))
        }),
    }
}

/// Every contour's vertices, snapped, in `format`.
pub(super) fn snapped(
    scene: &Scene,
    format: Format,
    polygon: &Polygon,
) -> Result<Vec<Vec<Point>>, RasterError> {
    polygon
        .contours()
        .map(|contour| {
            contour
                .iter()
                .map(|v| Ok([place(scene, format, &v.x)?, place(scene, format, &v.y)?]))
                .collect()
        })
        .collect()
}

/// The one contour of a polygon, snapped and without repeats, for the
/// methods that fill a single contour; `method` names the one that refuses
/// several.
pub(super) fn single_contour(
    scene: &Scene,
    format: Format,
    polygon: &Polygon,
    method: &str,
) -> Result<Vec<Point>, RasterError> {
    let contours = snapped(scene, format, polygon)?;
    match contours.as_slice() {
        [contour] => Ok(without_repeats(contour)),
        _ => Err(RasterError::Unsupported(format!(
            "{method} fills one contour, not {}",
            contours.len()
        ))),
    }
}

/// The vertices of a closed contour without consecutive repeats (the
/// last vertex counts as followed by the first): a repeated vertex adds a
/// zero-length edge, which changes no winding number.
fn without_repeats(contour: &[Point]) -> Vec<Point> {
    let mut points: Vec<Point> = Vec::with_capacity(contour.len());
    for &p in contour {
        if points.last() != Some(&p) {
            points.push(p);
        }
    }
    while points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
    points
}

/// (b − a) × (c − b): positive when a, b, c turn clockwise on screen (y
/// down). Differences are below 2^(16 + f) ≤ 2^33, so products fit i128.
pub(super) fn turn(a: Point, b: Point, c: Point) -> i128 {
    let d = |u: i64, v: i64| i128::from(u) - i128::from(v);
    d(b[0], a[0]) * d(c[1], b[1]) - d(b[1], a[1]) * d(c[0], b[0])
}
