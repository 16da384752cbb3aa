//! Production's points (SPEC.md §17): the pixels whose centre lies in the
//! square of side `size` around the snapped centre, each side open or
//! closed as the fill rule owns it, the vertex's depth and attributes
//! written in f32 at every one.
//!
//! The square is a rectangle of whole pixels, so nothing is tested per
//! sample: the set-up finds the first and last pixel column and row, and
//! the rectangle between them is filled.
//!
//! - Screen space is fixed point: the centre X in the scene's format (units
//!   of 2^-f pixel, |X| ≤ 2^(15+f) ≤ 2^32), half the side rounded down and
//!   up to units (h·2^f ≤ 512·2^17 = 2^26), and a pixel centre
//!   c = i·2^f + 2^(f−1). Everything stays below 2^34: i64.
//! - Clip space (`clip/point.rs`) has its centre from the clip path's
//!   projection (`clip/project.rs`: divide, viewport, snap), an exact
//!   rational, and finds its spans from the exact sides once per point
//!   ([`exact_span`]), as the clip path's set-up does for a triangle.
//!
//! Not here: antialiasing and motion, which the reader refuses for points.

use std::ops::Range;

use dashu_int::IBig;
use dashu_ratio::RBig;

use super::fixed::{Fixed, Format, MAX_FRAC_BITS};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::scene::rules::limits::{COORD_LIMIT, MAX_POINT_SIZE};
use crate::scene::{Canvas, FillRule, Number, Point, Vertex};

// The bounds the module doc states: a centre plus or minus half the side,
// in units, fits in i64 with room to spare.
const _: () = assert!((COORD_LIMIT << MAX_FRAC_BITS) + (MAX_POINT_SIZE << MAX_FRAC_BITS) < 1 << 40);

/// Which ends of a square's interval own their samples on one axis.
#[derive(Clone, Copy, Debug)]
pub(super) struct Ends {
    pub(super) low: bool,
    pub(super) high: bool,
}

impl Ends {
    /// Left and right edges on x (axis 0), top and bottom edges on y.
    pub(super) fn of(rule: FillRule, axis: usize) -> Ends {
        if axis == 0 {
            Ends {
                low: rule.owns_left(),
                high: rule.owns_right(),
            }
        } else {
            Ends {
                low: rule.owns_top(),
                high: rule.owns_bottom(),
            }
        }
    }
}

/// Half a point's side in units of 2^-f pixel, rounded down and up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Half {
    floor: i64,
    ceil: i64,
}

impl Half {
    /// h·2^f = size·2^(f−1) = p·2^(f−1)/q, with size = p/q > 0.
    fn new(size: &Number, format: Format) -> Half {
        let scaled = size.numerator() << (format.frac_bits as usize - 1);
        let q = IBig::from(size.denominator().clone());
        // p > 0: truncation is the floor.
        let floor = &scaled / &q;
        let exact = &floor * &q == scaled;
        let floor: i64 = (&floor)
            .try_into()
            .expect("size ≤ 1024: at most 2^26 units");
        Half {
            floor,
            ceil: floor + i64::from(!exact),
        }
    }
}

/// The pixels of `0..side` whose centre c (units) has d = c − x within
/// [−h, h], each end open or closed as `ends` says. For an integer d:
/// d ≥ −h ⟺ d ≥ −⌊h⌋; d > −h ⟺ d ≥ 1 − ⌈h⌉; d ≤ h ⟺ d ≤ ⌊h⌋;
/// d < h ⟺ d ≤ ⌈h⌉ − 1. Then c = i·one + one/2 gives i between two
/// Euclidean quotients.
fn span(x: Fixed, half: Half, ends: Ends, format: Format, side: u32) -> Range<i64> {
    let one = format.one();
    let low = if ends.low { -half.floor } else { 1 - half.ceil };
    let high = if ends.high { half.floor } else { half.ceil - 1 };
    // i·one ≥ x + low − one/2 and i·one ≤ x + high − one/2.
    let first = -(-(x.0 + low - one / 2)).div_euclid(one);
    let last = (x.0 + high - one / 2).div_euclid(one);
    clamped(first, last, side)
}

/// The pixels of `0..side` whose centre i + ½ lies in [x − h, x + h] with
/// exact rational ends: i ≥ ⌈x − h − ½⌉ (closed) or ⌊x − h − ½⌋ + 1
/// (open), and i ≤ ⌊x + h − ½⌋ (closed) or ⌈x + h − ½⌉ − 1 (open).
pub(super) fn exact_span(x: &RBig, half: &RBig, ends: Ends, side: u32) -> Range<i64> {
    let pixel_half = RBig::from_parts(IBig::ONE, 2u8.into());
    let low = x - half - &pixel_half;
    let high = x + half - &pixel_half;
    let first = if ends.low {
        low.ceil()
    } else {
        low.floor() + IBig::ONE
    };
    let last = if ends.high {
        high.floor()
    } else {
        high.ceil() - IBig::ONE
    };
    let clamp = |n: IBig| {
        let limit = IBig::from(i64::from(side) + 1);
        i64::try_from(n.clamp(-limit.clone(), limit)).expect("clamped")
    };
    clamped(clamp(first), clamp(last), side)
}

/// first..=last limited to the canvas side 0..side; empty (and within it)
/// when they do not meet.
fn clamped(first: i64, last: i64, side: u32) -> Range<i64> {
    let side = i64::from(side);
    let first = first.clamp(0, side);
    let end = (last + 1).clamp(first, side);
    first..end
}

/// What a covered pixel gets: depth and attributes in f32, or nothing
/// when the plan interpolates nothing.
pub(super) struct Values {
    pub(super) depth: Option<f32>,
    pub(super) attributes: Vec<f32>,
}

impl Values {
    fn write(&self, frame: &mut Frame, i: usize) {
        if let (Some(z), Some(out)) = (self.depth, frame.depth.as_mut()) {
            out[i] = f64::from(z);
        }
        for (channel, a) in frame.attributes.iter_mut().zip(&self.attributes) {
            channel[i] = f64::from(*a);
        }
    }
}

pub(super) fn attributes(vertex: &Vertex, plan: &Plan) -> Vec<f32> {
    (0..plan.attributes)
        .map(|k| vertex.attributes[k].to_f64_lossy() as f32)
        .collect()
}

/// Fills the rectangle `columns` × `rows` of `frame` (of `canvas`'s size).
pub(super) fn fill(
    frame: &mut Frame,
    canvas: Canvas,
    columns: Range<i64>,
    rows: Range<i64>,
    index: usize,
    values: &Values,
) {
    let width = canvas.width as usize;
    for row in rows {
        let start = row as usize * width;
        let (from, to) = (start + columns.start as usize, start + columns.end as usize);
        frame.hit_run(from, to, index);
        for i in from..to {
            values.write(frame, i);
        }
    }
}

/// Draws a screen-space point whose snapped centre is `centre` in
/// `format`, primitive `index`, into `frame` of `canvas`'s size.
#[allow(clippy::too_many_arguments)]
pub(crate) fn draw(
    point: &Point,
    centre: [Fixed; 2],
    format: Format,
    rule: FillRule,
    plan: &Plan,
    canvas: Canvas,
    index: usize,
    frame: &mut Frame,
) {
    let half = Half::new(&point.size, format);
    let columns = span(centre[0], half, Ends::of(rule, 0), format, canvas.width);
    let rows = span(centre[1], half, Ends::of(rule, 1), format, canvas.height);
    let vertex = &point.vertices[0];
    let values = Values {
        depth: plan.depth.then(|| vertex.z.to_f64_lossy() as f32),
        attributes: attributes(vertex, plan),
    };
    fill(frame, canvas, columns, rows, index, &values);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spans_open_and_close_their_ends_on_pixel_centres() {
        // 4 subpixel bits: f = 5, one = 32. Centre 2 px, size 1: the sides
        // 1.5 and 2.5 are the centres of pixels 1 and 2.
        let format = Format::snapped(4);
        let half = Half::new(&Number::ONE, format);
        assert_eq!(
            half,
            Half {
                floor: 16,
                ceil: 16
            }
        );
        let x = Fixed(64);
        let ends = |low, high| Ends { low, high };
        assert_eq!(span(x, half, ends(true, false), format, 8), 1..2);
        assert_eq!(span(x, half, ends(false, true), format, 8), 2..3);
        assert_eq!(span(x, half, ends(true, true), format, 8), 1..3);
        let x = RBig::from(2u8);
        let h = RBig::from_parts(IBig::ONE, 2u8.into());
        assert_eq!(exact_span(&x, &h, ends(true, false), 8), 1..2);
        assert_eq!(exact_span(&x, &h, ends(false, true), 8), 2..3);
        assert_eq!(exact_span(&x, &h, ends(true, true), 8), 1..3);
        // Size 1/3 rounds h = 1/6 px = 5.33 units both ways.
        let third = Half::new(&Number::from_string("1/3").unwrap(), format);
        assert_eq!(third, Half { floor: 5, ceil: 6 });
    }
}
