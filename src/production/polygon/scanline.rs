//! Scanline polygon fill (SPEC.md §14.1): an edge table sorted by first
//! sample row, an active edge table stepped row by row with an exact
//! integer DDA, and spans between the sorted crossings.
//!
//! Every decision is an integer comparison in the fixed-point format. A fill
//! rule is a nudge of the sample: top-left tests (x + ε, y + ε²). The ε² in
//! y makes an edge active on sample row y when min(a.y, b.y) ≤ y <
//! max(a.y, b.y) (a nudge up: min < y ≤ max); the ε in x puts the sample
//! right of a crossing x_c when x_c ≤ x (a nudge left: x_c < x). ε² · slope
//! is negligible against ε, so the crossing is taken at y itself. Each edge
//! then gives the first sample column right of it, ⌈(x_c − s)/one⌉ or
//! ⌊(x_c − s)/one⌋ + 1 for sample offset s, and the winding number between
//! two consecutive crossings is constant: a span.
//!
//! The winding number is counted from the left (−∞ to the sample) rather
//! than to +x as SPEC.md words it; the two are opposite, since every row
//! crosses closed contours as often downwards as upwards, and both fills
//! depend only on whether it is odd or non-zero.

use crate::frame::Frame;
use crate::scene::{Canvas, FillRule, PolygonFill};

/// A polygon vertex in fixed-point units: [x, y].
pub type Point = [i64; 2];

/// Which way a fill rule nudges a sample: right (+ε) or left in x, down
/// (+ε²) or up in y.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Nudge {
    pub right: bool,
    pub down: bool,
}

impl Nudge {
    /// The nudge of one of the four consistent rules; `all-edges` has none
    /// (SPEC.md leaves it undefined for polygons).
    pub fn of(rule: FillRule) -> Option<Nudge> {
        let (right, down) = match rule {
            FillRule::TopLeft => (true, true),
            FillRule::TopRight => (false, true),
            FillRule::BottomLeft => (true, false),
            FillRule::BottomRight => (false, false),
            FillRule::AllEdges => return None,
        };
        Some(Nudge { right, down })
    }
}

/// Where the samples lie: sample (j, k) at (j·one + offset[0],
/// k·one + offset[1]) fixed-point units, and which frame slot they fill.
#[derive(Clone, Copy, Debug)]
pub struct Samples {
    /// Units per pixel.
    pub one: i64,
    /// The sample's offset from its pixel's top-left corner, in units.
    pub offset: [i64; 2],
    /// The slot of this sample in each pixel's run.
    pub slot: usize,
    pub nudge: Nudge,
}

impl Samples {
    /// The sample rows k whose nudged height lies strictly between y0 < y1:
    /// half-open, not clipped to the canvas.
    pub fn rows(&self, y0: i64, y1: i64) -> (i64, i64) {
        let s = self.offset[1];
        if self.nudge.down {
            // y0 ≤ k·one + s < y1.
            (ceil_div(y0 - s, self.one), ceil_div(y1 - s, self.one))
        } else {
            // y0 < k·one + s ≤ y1.
            (
                (y0 - s).div_euclid(self.one) + 1,
                (y1 - s).div_euclid(self.one) + 1,
            )
        }
    }

    /// Row k clipped to the canvas: the rows of an edge that are drawn.
    pub fn rows_on(&self, y0: i64, y1: i64, canvas: Canvas) -> (i64, i64) {
        let (k0, k1) = self.rows(y0, y1);
        (k0.max(0), k1.min(i64::from(canvas.height)))
    }
}

/// ⌈a / b⌉ for b > 0.
pub fn ceil_div(a: i64, b: i64) -> i64 {
    -(-a).div_euclid(b)
}

/// ⌊a / b⌋ and the remainder in [0, b), for b > 0.
fn div_floor(a: i128, b: i128) -> (i128, i128) {
    (a.div_euclid(b), a.rem_euclid(b))
}

/// An edge's first sample column right of its crossing, row after row:
/// q + r/den is (x_c − s)/one plus the rounding bias, held as an integer
/// quotient and remainder and stepped by dx/dy per row.
///
/// Bounds: with coordinates below 2^(15 + f) units in magnitude (f fraction
/// bits, at most 17), den = dy · one < 2^(16 + 2f) ≤ 2^50 and the
/// remainder is below den, so the stepping fits i64; only the first
/// numerator, a product of two coordinate differences, needs i128.
#[derive(Clone, Copy, Debug)]
pub struct Walk {
    column: i64,
    rest: i64,
    column_step: i64,
    rest_step: i64,
    den: i64,
}

impl Walk {
    /// The walk of edge p0→p1 (p0.y < p1.y) from sample row k.
    pub fn new(p0: Point, p1: Point, k: i64, samples: &Samples) -> Walk {
        let one = i128::from(samples.one);
        let [sx, sy] = samples.offset.map(i128::from);
        let dx = i128::from(p1[0] - p0[0]);
        let dy = i128::from(p1[1] - p0[1]);
        debug_assert!(dy > 0);
        let den = dy * one;
        let y = i128::from(k) * one + sy;
        // x_c = p0.x + (y − p0.y)·dx/dy, so
        // (x_c − sx)/one = ((p0.x − sx)·dy + (y − p0.y)·dx) / (dy·one).
        let num = (i128::from(p0[0]) - sx) * dy + (y - i128::from(p0[1])) * dx;
        // Nudged right, the first column with x ≥ x_c: ⌈num/den⌉ =
        // ⌊(num + den − 1)/den⌋. Nudged left, the first with x > x_c:
        // ⌊num/den⌋ + 1 = ⌊(num + den)/den⌋.
        let bias = if samples.nudge.right { den - 1 } else { den };
        let (column, rest) = div_floor(num + bias, den);
        let (column_step, rest_step) = div_floor(dx * one, den);
        let narrow = |v: i128| i64::try_from(v).expect("bounded by the coordinate limit");
        Walk {
            column: narrow(column),
            rest: narrow(rest),
            column_step: narrow(column_step),
            rest_step: narrow(rest_step),
            den: narrow(den),
        }
    }

    /// The first sample column right of the crossing on the current row.
    #[inline]
    pub fn column(&self) -> i64 {
        self.column
    }

    /// Moves to the next sample row.
    #[inline]
    pub fn step(&mut self) {
        self.column += self.column_step;
        self.rest += self.rest_step;
        if self.rest >= self.den {
            self.column += 1;
            self.rest -= self.den;
        }
    }
}

/// An edge of the edge table: its drawn rows and its walk from the first.
#[derive(Clone, Copy, Debug)]
struct Edge {
    first_row: i64,
    end_row: i64,
    /// +1 for an edge heading down (b.y > a.y), −1 for one heading up.
    direction: i32,
    top: Point,
    bottom: Point,
}

/// Writes samples `(x0..x1, row)` of `samples.slot`, clipped to the canvas.
#[inline]
pub fn write_span(frame: &mut Frame, row: i64, x0: i64, x1: i64, samples: &Samples, index: usize) {
    let x0 = x0.max(0);
    let x1 = x1.min(i64::from(frame.width));
    if x0 >= x1 {
        return;
    }
    let n = frame.samples as usize;
    let base = row as usize * frame.width as usize;
    for x in x0 as usize..x1 as usize {
        frame.hit((base + x) * n + samples.slot, index);
    }
}

/// Fills the polygon of `contours` (each closed, the last vertex joining
/// the first) into slot `samples.slot` of every pixel, as primitive `index`.
pub fn fill(
    contours: &[Vec<Point>],
    fill: PolygonFill,
    samples: &Samples,
    canvas: Canvas,
    frame: &mut Frame,
    index: usize,
) {
    // The edge table: every non-horizontal edge with a drawn row, by its
    // first row.
    let mut table = Vec::new();
    for contour in contours {
        for (i, &a) in contour.iter().enumerate() {
            let b = contour[(i + 1) % contour.len()];
            if a[1] == b[1] {
                continue;
            }
            let (top, bottom, direction) = if a[1] < b[1] { (a, b, 1) } else { (b, a, -1) };
            let (first_row, end_row) = samples.rows_on(top[1], bottom[1], canvas);
            if first_row < end_row {
                table.push(Edge {
                    first_row,
                    end_row,
                    direction,
                    top,
                    bottom,
                });
            }
        }
    }
    table.sort_unstable_by_key(|e| e.first_row);

    let inside = |winding: i32| match fill {
        PolygonFill::EvenOdd => winding & 1 != 0,
        PolygonFill::NonZero => winding != 0,
    };
    // The active edge table: (end row, direction, walk).
    // The active edge table, kept sorted by crossing column: from one row
    // to the next the order changes only where edges cross, so insertion
    // sort restores it in about one pass (a full sort of every row cost a
    // 4096-vertex star half its time).
    let mut active: Vec<ActiveEdge> = Vec::new();
    let mut next = 0;
    let mut row = 0;
    while next < table.len() || !active.is_empty() {
        if active.is_empty() {
            row = table[next].first_row;
        }
        while next < table.len() && table[next].first_row == row {
            let e = &table[next];
            active.push(ActiveEdge {
                end_row: e.end_row,
                direction: e.direction,
                walk: Walk::new(e.top, e.bottom, row, samples),
            });
            next += 1;
        }
        insertion_sort(&mut active);
        let mut winding = 0;
        for (i, edge) in active.iter().enumerate() {
            winding += edge.direction;
            if inside(winding) {
                if let Some(end) = active.get(i + 1) {
                    let (x0, x1) = (edge.walk.column(), end.walk.column());
                    write_span(frame, row, x0, x1, samples, index);
                }
            }
        }
        row += 1;
        active.retain_mut(|edge| {
            edge.walk.step();
            edge.end_row > row
        });
    }
}

/// An edge of the active edge table.
#[derive(Clone, Copy, Debug)]
struct ActiveEdge {
    end_row: i64,
    direction: i32,
    walk: Walk,
}

/// Sorts by crossing column; linear on an already nearly sorted table.
fn insertion_sort(edges: &mut [ActiveEdge]) {
    for i in 1..edges.len() {
        let mut j = i;
        while j > 0 && edges[j - 1].walk.column() > edges[j].walk.column() {
            edges.swap(j - 1, j);
            j -= 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn centre(rule: FillRule) -> Samples {
        // Units of 1/2 pixel: the pixel centre is offset (1, 1).
        Samples {
            one: 2,
            offset: [1, 1],
            slot: 0,
            nudge: Nudge::of(rule).unwrap(),
        }
    }

    #[test]
    fn crossings_on_a_sample_go_by_the_nudge() {
        // A vertical edge through the centres of column 1 (x = 1.5 px).
        let (top, bottom) = ([3, 0], [3, 8]);
        let right = Walk::new(top, bottom, 0, &centre(FillRule::TopLeft));
        let left = Walk::new(top, bottom, 0, &centre(FillRule::TopRight));
        assert_eq!(right.column(), 1, "x_c ≤ x: column 1 lies right of it");
        assert_eq!(left.column(), 2, "x_c < x: column 1 does not");
    }

    #[test]
    fn rows_are_half_open_by_the_nudge() {
        // y from 0.5 px to 2.5 px: both ends on sample rows 0 and 2.
        let down = centre(FillRule::TopLeft);
        let up = centre(FillRule::BottomLeft);
        assert_eq!(down.rows(1, 5), (0, 2));
        assert_eq!(up.rows(1, 5), (1, 3));
    }

    #[test]
    fn the_walk_steps_exactly() {
        // A slope of 1/3: stepping must agree with dividing afresh.
        let samples = centre(FillRule::TopLeft);
        let (top, bottom) = ([-7, -5], [40, 136]);
        let mut walk = Walk::new(top, bottom, 0, &samples);
        for k in 0..60 {
            assert_eq!(walk.column(), Walk::new(top, bottom, k, &samples).column());
            walk.step();
        }
    }
}
