//! The `parallelogram` line (SPEC.md §4.4, the non-strict wide line) as
//! two triangles of production's triangle path, their shared diagonal owned
//! by one of them whatever the fill rule, drawn at pixel centres or, in an
//! antialiased scene, sampled like any triangle (`antialias::cover`).

use super::shading::LineSink;
use super::step::{Geometry, DIFF_PX_BITS};
use crate::plan::Plan;
use crate::production::antialias;
use crate::production::fixed::{EdgeInt, Fixed, Format, I64_MAX_FRAC_BITS, MAX_FRAC_BITS};
use crate::production::setup::{self, Footprint};
use crate::production::traverse;
use crate::rasterizer::RasterError;
use crate::scene::rules::limits;
use crate::scene::{Canvas, Cull, FillRule, Interpolation, Line, Number, Triangle, Vertex};

// Parallelogram corners lie up to width/2 ≤ 2^9 px beyond the vertex range,
// so a difference of two corners, or of a corner and a sample on the canvas,
// stays below 2^(DIFF_PX_BITS + 1) px. An edge function, two products of such
// differences plus the tie bias, is then below 2^(2(DIFF_PX_BITS + 1 + f) + 1):
// that many bits of magnitude and one of sign. It fits i64 up to
// I64_MAX_FRAC_BITS (the integer the parallelogram picks with
// Format::fits_i64), and i128 at every format.
const fn corner_edge_bits(frac_bits: u32) -> u32 {
    2 * (DIFF_PX_BITS + 1 + frac_bits) + 2
}
const _: () = assert!(limits::MAX_LINE_WIDTH < 1 << DIFF_PX_BITS);
const _: () = assert!(corner_edge_bits(I64_MAX_FRAC_BITS) <= 64);
const _: () = assert!(corner_edge_bits(MAX_FRAC_BITS) <= 128);

/// The parallelogram line as two triangles of production's triangle path.
///
/// Corners A = v0 − h, B = v1 − h, C = v1 + h, D = v0 + h with h = width/2
/// along the minor axis; triangles ABC and ACD. Their outer edges follow the
/// fill rule, classified by direction exactly as §4.3's outward normals do.
/// The diagonal AC goes to ABC when the fill rule gives it to ABC and to ACD
/// otherwise: for the four consistent rules that is what the rule does
/// anyway, and under `all-edges` it keeps the diagonal's samples from being
/// counted twice. So the triangles are disjoint and their union is exactly
/// the parallelogram, corners included (at A, ABC covers a sample exactly
/// when the nudge of §3 points into ABC, ACD never does when it does not
/// own the diagonal, and the nudge lies in the parallelogram's corner).
pub(super) fn parallelogram(
    line: &Line,
    g: &Geometry,
    format: Format,
    rule: FillRule,
    canvas: Canvas,
    sink: &mut LineSink,
) -> Result<(), RasterError> {
    // The corners need width/2 in fixed point. A dyadic half-width finer
    // than the case's format is drawn in a finer one (the endpoints are exact
    // in it too): the first with enough fraction bits, up to the finest.
    // width/2 in units of 2^-f is width in units of 2^-(f − 1).
    let (fine, half) = (format.frac_bits..=MAX_FRAC_BITS)
        .find_map(|frac_bits| {
            let half = Format {
                frac_bits: frac_bits - 1,
            }
            .exact(&line.width)?;
            Some((Format { frac_bits }, half.0))
        })
        .ok_or_else(|| {
            RasterError::Unsupported(format!(
                "a parallelogram line's corners need half its width in fixed point, and width {} \
                 is not a multiple of 2^-{}",
                line.width.to_exact_string(),
                MAX_FRAC_BITS - 1
            ))
        })?;
    let scale = fine.frac_bits - format.frac_bits;
    let g = &Geometry::new([g.v0, g.v1].map(|p| p.map(|c| Fixed(c << scale))));
    if fine.fits_i64() {
        parallelogram_in::<i64>(g, half, fine, rule, canvas, sink);
    } else {
        parallelogram_in::<i128>(g, half, fine, rule, canvas, sink);
    }
    Ok(())
}

/// [`parallelogram`] in a format that holds its corners.
fn parallelogram_in<E: EdgeInt>(
    g: &Geometry,
    half: i64,
    format: Format,
    rule: FillRule,
    canvas: Canvas,
    sink: &mut LineSink,
) {
    let minor = 1 - g.major;
    let corner = |p: [i64; 2], sign: i64| {
        let mut q = p;
        q[minor] += sign * half;
        [Fixed(q[0]), Fixed(q[1])]
    };
    let (a, b, c, d) = (
        corner(g.v0, -1),
        corner(g.v1, -1),
        corner(g.v1, 1),
        corner(g.v0, 1),
    );
    let coverage_only = Plan::coverage_only();
    let placeholder = Triangle {
        vertices: [0, 1, 2].map(|_| Vertex::at(Number::ZERO, Number::ZERO)),
        interpolation: Interpolation::Linear,
    };
    let is_diagonal = |p: [Fixed; 2], q: [Fixed; 2]| (p == a && q == c) || (p == c && q == a);
    let footprint = match sink.samples {
        Some(_) => Footprint::Squares,
        None => Footprint::Centres,
    };
    let first = setup::setup_in::<E>(
        [a, b, c],
        &placeholder,
        format,
        rule,
        Cull::None,
        canvas,
        &coverage_only,
        |_, _| None,
        footprint,
    );
    // ACD walks the diagonal the other way round from ABC (both clockwise
    // once set up), so ABC's ownership is that of the reversed edge.
    let second = setup::setup_in::<E>(
        [a, c, d],
        &placeholder,
        format,
        rule,
        Cull::None,
        canvas,
        &coverage_only,
        |p, q| is_diagonal(p, q).then(|| !setup::edge_owned(q, p, rule)),
        footprint,
    );
    match sink.samples {
        None => {
            for triangle in [first, second].iter().flatten() {
                traverse::traverse(triangle, sink);
            }
        }
        Some(samples) => {
            // The corners' format may be finer than the case's: offsets in
            // it for the decisions, the sink's own for the values.
            let offsets = samples.offsets_in(format);
            for triangle in [first, second].iter().flatten() {
                antialias::cover(triangle, format, &offsets, samples.sampling, sink);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::rectangle::owns;
    use super::super::test_support::*;
    use super::*;
    use crate::scene::LineRule;

    /// A convex polygon's coverage under SPEC.md §4.3's border rule, from
    /// scratch: corners in order, each edge's outward normal from the
    /// winding.
    fn brute_polygon(corners: &[[i128; 2]], rule: FillRule, p: [i128; 2]) -> bool {
        let n = corners.len();
        let area: i128 = (0..n)
            .map(|i| {
                let (a, b) = (corners[i], corners[(i + 1) % n]);
                a[0] * b[1] - a[1] * b[0]
            })
            .sum();
        assert!(area != 0);
        (0..n).all(|i| {
            let (a, b) = (corners[i], corners[(i + 1) % n]);
            let e = [b[0] - a[0], b[1] - a[1]];
            // Outward normal: right of the edge for positive area (y down, clockwise).
            let normal = if area > 0 {
                [-e[1], e[0]]
            } else {
                [e[1], -e[0]]
            };
            let side = (p[0] - a[0]) * normal[0] + (p[1] - a[1]) * normal[1];
            let out = -side;
            if out > 0 {
                false
            } else if out < 0 {
                true
            } else {
                let n = [(-normal[0]).signum() as i64, (-normal[1]).signum() as i64];
                owns(rule, n)
            }
        })
    }

    #[test]
    fn parallelogram_is_exactly_the_swept_segment() {
        let mut rng = Rng(4242);
        for frac_bits in [1, 3, 9] {
            let format = Format { frac_bits };
            let one = i128::from(format.one());
            for trial in 0..600 {
                let g = random_geometry(&mut rng, format, 24);
                if g.is_point() {
                    continue;
                }
                // Widths in sixteenths: finer than the format at few bits,
                // drawn then in a finer one.
                let sixteenths = rng.range(1, 64);
                let width = Number::ratio(sixteenths, 16);
                // Brute force on a grid 32 times finer, where half the width
                // is an integer.
                let half = i128::from(sixteenths) * one;
                let rule = FillRule::ALL[trial % 5];
                let line = test_line(LineRule::Parallelogram, width);
                let frame = draw_one::<i64>(&line, &g, format, rule, CANVAS).unwrap();
                let minor = 1 - g.major;
                let v = |p: [i64; 2], s: i128| {
                    let mut q = [32 * i128::from(p[0]), 32 * i128::from(p[1])];
                    q[minor] += s * half;
                    q
                };
                let corners = [v(g.v0, -1), v(g.v1, -1), v(g.v1, 1), v(g.v0, 1)];
                for y in 0..CANVAS.height as i64 {
                    for x in 0..CANVAS.width as i64 {
                        let p = [
                            32 * i128::from(format.centre(x).0),
                            32 * i128::from(format.centre(y).0),
                        ];
                        let want = u16::from(brute_polygon(&corners, rule, p));
                        let got = frame.coverage[(y * 24 + x) as usize];
                        assert_eq!(got, want, "{g:?} {rule:?} width {half} at ({x}, {y})");
                    }
                }
            }
        }
    }

    #[test]
    fn parallelogram_needs_a_representable_half_width() {
        let format = Format { frac_bits: 9 };
        let g = Geometry::new([[Fixed(0), Fixed(0)], [Fixed(4096), Fixed(512)]]);
        let line = test_line(LineRule::Parallelogram, Number::ratio(1, 3));
        let err = draw_one::<i64>(&line, &g, format, FillRule::TopLeft, CANVAS).unwrap_err();
        assert!(matches!(err, RasterError::Unsupported(_)), "{err}");
    }
}
