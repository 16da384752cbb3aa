//! What the float-input adapters (tiny-skia, euc, vello_cpu) share: turning
//! a case's exact vertices into the floats a library takes, and the
//! pipeline state they apply themselves (culling).
//!
//! Snapping is done here, exactly, on the scene's [`Number`]s: the nearest
//! multiple of 2^-bits, ties to even (SPEC.md §2). Only the snapped value is
//! rounded to a float, once, correctly (dashu's conversion). An f32 holds
//! every snapped coordinate up to 2^24 subpixels in magnitude (|x| < 2^16
//! pixels at 8 bits, 2^8 pixels at 16 bits); beyond that the library draws
//! a slightly different triangle and the case may differ for that reason.
//! Unsnapped coordinates (`subpixel_bits: null`) go through the same
//! rounding. [`f32_exact`] says whether a triangle's input was exact, so an
//! adapter can report it.

use std::cmp::Ordering;

use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

use crate::rasterizer::{Capabilities, RasterError};
use crate::scene::{Cull, Number, PolygonFill, Primitive, Scene, Triangle};

/// `n` on the case's subpixel grid: the nearest multiple of 2^-bits, ties to
/// even; `n` itself when the case keeps exact coordinates.
pub(crate) fn snapped(n: &Number, bits: Option<u32>) -> RBig {
    let Some(bits) = bits else {
        return n.as_rbig().clone();
    };
    let scaled = n.numerator() << bits as usize;
    let den = IBig::from(n.denominator().clone());
    // Floor division with a non-negative remainder.
    let mut q = &scaled / &den;
    if &q * &den > scaled {
        q -= IBig::ONE;
    }
    let twice_rest = (&scaled - &q * &den) * IBig::from(2u8);
    let up = match twice_rest.cmp(&den) {
        Ordering::Greater => true,
        Ordering::Equal => (&q % IBig::from(2u8)) != IBig::ZERO,
        Ordering::Less => false,
    };
    if up {
        q += IBig::ONE;
    }
    RBig::from_parts(q, UBig::ONE << bits as usize)
}

/// A triangle's snapped screen positions, exact.
pub(crate) fn snapped_triangle(t: &Triangle, bits: Option<u32>) -> [[RBig; 2]; 3] {
    t.vertices
        .each_ref()
        .map(|v| [snapped(&v.x, bits), snapped(&v.y, bits)])
}

/// The nearest f32, ties to even.
pub(crate) fn to_f32(q: &RBig) -> f32 {
    q.to_f32().value()
}

/// The f32 nearest an exact number (a depth, a w, an attribute), unsnapped.
pub(crate) fn f32_of(n: &Number) -> f32 {
    to_f32(n.as_rbig())
}

/// The nearest f64, ties to even.
#[allow(dead_code)] // used by the vello adapter only
pub(crate) fn to_f64(q: &RBig) -> f64 {
    q.to_f64().value()
}

/// Whether every coordinate survives the conversion to f32 unchanged.
#[allow(dead_code)]
pub(crate) fn f32_exact(positions: &[[RBig; 2]; 3]) -> bool {
    positions
        .iter()
        .flatten()
        .all(|c| RBig::try_from(to_f32(c)).is_ok_and(|back| &back == c))
}

/// Whether the case's cull state discards this triangle, decided exactly on
/// the snapped positions (SPEC.md §2: clockwise on screen, y down, is a
/// positive twice-signed area). Culling is pipeline state, not a rasterizer
/// convention, so every adapter applies it itself before the library sees
/// the triangle; a zero-area triangle is never culled here, so the library's
/// own handling of it is what gets measured.
pub(crate) fn culled(positions: &[[RBig; 2]; 3], cull: Cull) -> bool {
    let [a, b, c] = positions;
    let area = (&b[0] - &a[0]) * (&c[1] - &a[1]) - (&b[1] - &a[1]) * (&c[0] - &a[0]);
    match cull {
        Cull::None => false,
        Cull::Clockwise => area > RBig::ZERO,
        Cull::CounterClockwise => area < RBig::ZERO,
    }
}

/// What a path-fill library draws (tiny-skia, vello_cpu): triangles and
/// polygons at their exact or snapped positions, and antialiased
/// coverage; no depth, attributes or motion.
#[allow(dead_code)] // used by the tiny-skia and vello adapters
pub(crate) fn path_fill_capabilities() -> Capabilities {
    Capabilities {
        triangles: true,
        ideal_geometry: true,
        polygons: true,
        antialias: true,
        ..Capabilities::none()
    }
}

/// `Unsupported` when the scene holds a line: none of these libraries has
/// an aliased line rule equal to one of SPEC.md §4's.
pub(crate) fn triangles_only(scene: &Scene, library: &str) -> Result<(), RasterError> {
    match scene
        .primitives
        .iter()
        .find(|p| matches!(p, Primitive::Line(_) | Primitive::Point(_)))
    {
        Some(Primitive::Line(l)) => Err(RasterError::Unsupported(format!(
            "{library} has no line rule equal to `{}` (SPEC.md §4); only triangles are drawn",
            l.rule.name()
        ))),
        Some(Primitive::Point(_)) => Err(RasterError::Unsupported(format!(
            "{library} has no point primitive (SPEC.md §17); only triangles and paths are drawn"
        ))),
        _ => Ok(()),
    }
}

/// `Unsupported` when the plan asks for depth or attributes, for libraries
/// that fill shapes with one colour and interpolate nothing.
pub(crate) fn coverage_only(plan: &crate::plan::Plan, library: &str) -> Result<(), RasterError> {
    if plan.depth || plan.attributes > 0 {
        return Err(RasterError::Unsupported(format!(
            "{library} fills paths with a paint and interpolates no per-vertex depth or attributes"
        )));
    }
    Ok(())
}

/// `Unsupported` unless the plan samples each pixel once, at its centre.
pub(crate) fn single_sample(plan: &crate::plan::Plan, library: &str) -> Result<(), RasterError> {
    if plan.samples_per_pixel != 1 {
        return Err(RasterError::Unsupported(format!(
            "the {library} adapter draws one sample per pixel; {} samples were asked for",
            plan.samples_per_pixel
        )));
    }
    Ok(())
}

/// A primitive as a path fill: its contours, snapped exactly, and the fill
/// rule that decides its inside.
#[allow(dead_code)] // used by the tiny-skia and vello adapters
pub(crate) struct FillPath {
    pub contours: Vec<Vec<[RBig; 2]>>,
    pub even_odd: bool,
}

/// Every primitive of the scene as a path fill, in scene order; `None` for a
/// triangle the case's cull state discards. Triangles fill with the
/// non-zero rule (either winding then fills), polygons with their own.
/// Lines are refused: see [`triangles_only`].
#[allow(dead_code)] // used by the tiny-skia and vello adapters
pub(crate) fn fill_paths(
    scene: &Scene,
    library: &str,
) -> Result<Vec<Option<FillPath>>, RasterError> {
    triangles_only(scene, library)?;
    let bits = scene.rules.subpixel_bits;
    Ok(scene
        .primitives
        .iter()
        .map(|p| match p {
            Primitive::Triangle(t) => {
                let exact = snapped_triangle(t, bits);
                (!culled(&exact, scene.rules.cull)).then(|| FillPath {
                    contours: vec![exact.to_vec()],
                    even_odd: false,
                })
            }
            Primitive::Polygon(polygon) => Some(FillPath {
                contours: polygon
                    .contours()
                    .map(|c| {
                        c.iter()
                            .map(|v| [snapped(&v.x, bits), snapped(&v.y, bits)])
                            .collect()
                    })
                    .collect(),
                even_odd: polygon.fill == PolygonFill::EvenOdd,
            }),
            Primitive::Line(_) | Primitive::Point(_) => unreachable!("refused by triangles_only"),
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn n(s: &str) -> Number {
        Number::from_string(s).unwrap()
    }

    #[test]
    fn snapping_rounds_to_nearest_ties_to_even() {
        let cases = [
            ("1/3", 8, "85/256"),
            ("0.5", 0, "0"),
            ("1.5", 0, "2"),
            ("-0.5", 0, "0"),
            ("-1.5", 0, "-2"),
            ("-2.5", 0, "-2"),
            ("3/512", 8, "1/128"),
            ("5/512", 8, "1/128"),
            ("7/512", 8, "1/64"),
        ];
        for (value, bits, want) in cases {
            assert_eq!(
                snapped(&n(value), Some(bits)),
                n(want).as_rbig().clone(),
                "{value} at {bits} bits"
            );
        }
        assert_eq!(snapped(&n("1/3"), None), n("1/3").as_rbig().clone());
    }

    #[test]
    fn f32_holds_24_bits_of_subpixels() {
        let at = |x: &str| {
            let p = [snapped(&n(x), Some(16)), RBig::ZERO];
            [p.clone(), p.clone(), p]
        };
        assert!(f32_exact(&at("255.99998474121094"))); // 2^24 - 1 subpixels
        assert!(!f32_exact(&at("32767.99998474121094"))); // 2^31 - 1 subpixels
    }
}
