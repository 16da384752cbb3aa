//! The `midpoint` rule (SPEC.md §4.1), one line at a time: the incremental
//! walk that calls back for each pixel (with values, or for the foils), and
//! the coverage-only line written straight into the frame. A scene of many
//! coverage-only midpoint lines on a large canvas goes band by band instead
//! (`bands.rs`).

use super::step::{major_range, Geometry, Slope};
use crate::frame::Frame;
use crate::production::fixed::Format;
use crate::scene::{Canvas, LastPixel};

/// Calls `visit(x, y)` for each pixel of a `midpoint` line on the canvas.
///
/// Along the major axis u, the pixel is ⌈v(c)⌉ − 1 on the minor axis v,
/// with v(c) = a_v + (c − a_u)·dv/du measured in pixels: in units that is
/// ⌊(N − 1)/D⌋ with N = a_v·du + (c − a_u)·dv and D = du·one (du > 0). The
/// first is one exact i128 division; each next centre adds dv·one to N,
/// which moves the remainder by at most D, so one comparison steps it.
/// The walk starts from the endpoint with the smaller major coordinate,
/// and depends only on the segment's points: v1→v0 draws what v0→v1 does.
pub(crate) fn midpoint(
    g: &Geometry,
    format: Format,
    last_pixel: LastPixel,
    canvas: Canvas,
    mut visit: impl FnMut(i64, i64),
) {
    let (u, v) = (g.major, 1 - g.major);
    let (first, end) = major_range(g, format, last_pixel, canvas);
    if first >= end {
        return;
    }
    let minor_size = i64::from(if v == 0 { canvas.width } else { canvas.height });
    // ⌈N/D⌉ − 1 = ⌊(N − 1)/D⌋.
    let mut steps = Slope::new(g, format, first).steps(-1);
    for m in first..end {
        let minor = steps.minor;
        if (0..minor_size).contains(&minor) {
            if u == 0 {
                visit(m, minor);
            } else {
                visit(minor, m);
            }
        }
        steps.advance();
    }
}

/// Draws a coverage-only `midpoint` line as primitive `index`: each pixel
/// written in place, as `Frame::hit` does.
pub(super) fn midpoint_coverage(
    g: &Geometry,
    format: Format,
    last_pixel: LastPixel,
    canvas: Canvas,
    index: usize,
    frame: &mut Frame,
) {
    let width = frame.width as usize;
    let id = index as u32 + 1;
    let (coverage, last) = (&mut frame.coverage, &mut frame.last);
    midpoint(g, format, last_pixel, canvas, |x, y| {
        let i = y as usize * width + x as usize;
        coverage[i] = coverage[i].saturating_add(1);
        last[i] = id;
    });
}

#[cfg(test)]
mod tests {
    use super::super::test_support::*;
    use super::*;
    use crate::production::fixed::Fixed;

    fn pixels_of(g: &Geometry, format: Format, last: LastPixel, canvas: Canvas) -> Vec<(i64, i64)> {
        let mut out = Vec::new();
        midpoint(g, format, last, canvas, |x, y| out.push((x, y)));
        out.sort();
        out
    }

    /// SPEC.md §4.1 written out directly, each pixel from scratch, i128.
    fn brute_midpoint(
        g: &Geometry,
        format: Format,
        last: LastPixel,
        canvas: Canvas,
    ) -> Vec<(i64, i64)> {
        let (u, v) = (g.major, 1 - g.major);
        let one = i128::from(format.one());
        let sizes = [i64::from(canvas.width), i64::from(canvas.height)];
        let mut out = Vec::new();
        for i in -2..sizes[u] + 2 {
            let c = i128::from(i) * one + one / 2;
            let (p, q) = (i128::from(g.v0[u]), i128::from(g.v1[u]));
            if c < p.min(q) || c > p.max(q) {
                continue;
            }
            if last == LastPixel::Exclude && c == q {
                continue;
            }
            // v(c)/one = (v0·du + (c − u0)·dv) / (du·one); ceil − 1.
            let (mut n, mut den) = (
                i128::from(g.v0[v]) * (q - p) + (c - p) * i128::from(g.d[v]),
                (q - p) * one,
            );
            if den < 0 {
                n = -n;
                den = -den;
            }
            let ceil = if n >= 0 {
                (n + den - 1) / den
            } else {
                -((-n) / den)
            };
            let j = (ceil - 1) as i64;
            if i < 0 || i >= sizes[u] || j < 0 || j >= sizes[v] {
                continue;
            }
            out.push(if u == 0 { (i, j) } else { (j, i) });
        }
        out.sort();
        out
    }

    #[test]
    fn midpoint_matches_the_rule_in_every_octant() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        for frac_bits in [1, 2, 3, 5, 9, 17] {
            let format = Format { frac_bits };
            for _ in 0..3000 {
                let g = random_geometry(&mut rng, format, 26);
                if g.is_point() {
                    continue;
                }
                for last in [LastPixel::Include, LastPixel::Exclude] {
                    assert_eq!(
                        pixels_of(&g, format, last, CANVAS),
                        brute_midpoint(&g, format, last, CANVAS),
                        "{g:?} at {frac_bits} bits, {last:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn midpoint_is_symmetric_under_reversal() {
        let mut rng = Rng(12345);
        for frac_bits in [1, 4, 9] {
            let format = Format { frac_bits };
            for _ in 0..2000 {
                let g = random_geometry(&mut rng, format, 26);
                if g.is_point() {
                    continue;
                }
                let back = Geometry::new([
                    [Fixed(g.v1[0]), Fixed(g.v1[1])],
                    [Fixed(g.v0[0]), Fixed(g.v0[1])],
                ]);
                assert_eq!(
                    pixels_of(&g, format, LastPixel::Include, CANVAS),
                    pixels_of(&back, format, LastPixel::Include, CANVAS),
                    "{g:?}"
                );
            }
        }
    }

    #[test]
    fn midpoint_ties_go_up_and_left() {
        let format = Format { frac_bits: 1 }; // units of half a pixel
        let at = |x: i64, y: i64| [Fixed(x), Fixed(y)];
        // From (0.5, 1) to (4.5, 1): y(c) = 1 everywhere, row 0.
        let g = Geometry::new([at(1, 2), at(9, 2)]);
        assert_eq!(
            pixels_of(&g, format, LastPixel::Include, CANVAS),
            vec![(0, 0), (1, 0), (2, 0), (3, 0), (4, 0)]
        );
        // Vertical at x = 2: column 1.
        let g = Geometry::new([at(4, 1), at(4, 7)]);
        assert_eq!(
            pixels_of(&g, format, LastPixel::Include, CANVAS),
            vec![(1, 0), (1, 1), (1, 2), (1, 3)]
        );
        assert_eq!(
            pixels_of(&g, format, LastPixel::Exclude, CANVAS),
            vec![(1, 0), (1, 1), (1, 2)]
        );
    }

    #[test]
    fn strips_with_last_pixel_excluded_share_no_joint() {
        let format = Format { frac_bits: 9 };
        let mut rng = Rng(777);
        let centre = |rng: &mut Rng| {
            let mut c = || format.centre(rng.range(0, 19));
            [c(), c()]
        };
        for _ in 0..300 {
            // Joints at pixel centres, where an included last pixel would be
            // drawn by both lines meeting there.
            let points: Vec<[Fixed; 2]> = (0..5).map(|_| centre(&mut rng)).collect();
            for pair in points.windows(2) {
                let g = Geometry::new([pair[0], pair[1]]);
                if g.is_point() {
                    continue;
                }
                let drawn = pixels_of(&g, format, LastPixel::Exclude, CANVAS);
                let pixel = |p: [Fixed; 2]| (p[0].0 >> 9, p[1].0 >> 9);
                assert!(
                    !drawn.contains(&pixel(pair[1])),
                    "{pair:?} drew its last pixel"
                );
                assert!(
                    drawn.contains(&pixel(pair[0])),
                    "{pair:?} missed its first pixel"
                );
            }
        }
    }

    #[test]
    fn midpoint_clips_far_lines_cheaply() {
        let format = Format { frac_bits: 9 };
        let one = format.one();
        let g = Geometry::new([
            [Fixed(-32768 * one), Fixed(-32768 * one)],
            [Fixed(32768 * one), Fixed(32768 * one)],
        ]);
        let pixels = pixels_of(&g, format, LastPixel::Include, CANVAS);
        // The diagonal y = x: pixel centres (i + ½) have y(c) = i + ½.
        assert_eq!(pixels, (0..20).map(|i| (i, i)).collect::<Vec<_>>());
    }
}
