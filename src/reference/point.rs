//! Points (SPEC.md §17): the square [X − h, X + h] × [Y − h, Y + h] of side
//! `size` around the snapped centre (X, Y), each of its four edges owning
//! the samples on it as a polygon's edge does under the fill rule (§3).
//!
//! Every decision is a comparison of exact rationals: a pixel centre c
//! against X − h and X + h, closed or open as the rule says. The square is
//! the product of a column interval and a row interval, so the columns and
//! the rows are decided apart and every pixel of both is visited.
//!
//! A clip-space point (§17.2) is placed by `clip/point.rs` and drawn here.
//!
//! Not here: antialiasing and motion, which the reader refuses for points.

use dashu_int::IBig;
use dashu_ratio::RBig;

use super::exact::snap;
use super::values::Values;
use crate::scene::{Canvas, FillRule, Point, Scene};

/// A point's square on the screen, exact.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Square {
    /// (X, Y): the snapped centre (exact when the scene does not snap).
    pub centre: [RBig; 2],
    /// h = size/2, never snapped.
    pub half: RBig,
}

impl Square {
    pub fn new(centre: [RBig; 2], size: &crate::scene::Number) -> Square {
        Square {
            centre,
            half: size.as_rbig() / RBig::from(2u8),
        }
    }

    /// Whether the sample coordinate `s` lies in [c − h, c + h] with the
    /// low end closed when `low_owned` and the high end closed when
    /// `high_owned` (each open otherwise).
    fn within(&self, s: &RBig, axis: usize, low_owned: bool, high_owned: bool) -> bool {
        let low = &self.centre[axis] - &self.half;
        let high = &self.centre[axis] + &self.half;
        let above_low = if low_owned { *s >= low } else { *s > low };
        let below_high = if high_owned { *s <= high } else { *s < high };
        above_low && below_high
    }

    /// The pixel columns (axis 0) or rows (axis 1) of `0..size` whose
    /// centre the square's interval holds under `rule`: the left and top
    /// edges are its low ends, the right and bottom edges its high ends.
    pub fn covered(&self, axis: usize, rule: FillRule, size: u32) -> Vec<u32> {
        let (low_owned, high_owned) = if axis == 0 {
            (rule.owns_left(), rule.owns_right())
        } else {
            (rule.owns_top(), rule.owns_bottom())
        };
        // Candidates: every pixel whose centre is within one pixel of the
        // interval (a superset; each is then decided exactly).
        let first = (&self.centre[axis] - &self.half - RBig::ONE).floor();
        let last = (&self.centre[axis] + &self.half + RBig::ONE).ceil();
        let first = first.max(IBig::ZERO);
        let last = last.min(IBig::from(size) - IBig::ONE);
        if first > last {
            return Vec::new();
        }
        let first: u32 = (&first).try_into().expect("within the canvas");
        let last: u32 = (&last).try_into().expect("within the canvas");
        let half_pixel = RBig::from_parts(IBig::ONE, 2u8.into());
        (first..=last)
            .filter(|&i| {
                let centre = RBig::from(i) + &half_pixel;
                self.within(&centre, axis, low_owned, high_owned)
            })
            .collect()
    }
}

/// Visits every pixel of `canvas` whose centre the square covers under
/// `rule`, row by row: `visit(pixel index)`.
pub fn visit<F: FnMut(usize)>(square: &Square, rule: FillRule, canvas: Canvas, mut visit: F) {
    let columns = square.covered(0, rule, canvas.width);
    for row in square.covered(1, rule, canvas.height) {
        crate::deadline::check();
        for &column in &columns {
            visit(row as usize * canvas.width as usize + column as usize);
        }
    }
}

/// A screen-space point's square: its position snapped to the scene's
/// `subpixel_bits` (§2), or exact.
pub fn screen_square(scene: &Scene, point: &Point) -> Square {
    let v = &point.vertices[0];
    let place = |n: &crate::scene::Number| match scene.rules.subpixel_bits {
        Some(bits) => snap(n, bits),
        None => n.as_rbig().clone(),
    };
    Square::new([place(&v.x), place(&v.y)], &point.size)
}

/// A screen-space point's exact values: its vertex's z and attributes.
pub fn screen_values(point: &Point) -> Values {
    let v = &point.vertices[0];
    let depth = v.z.as_rbig().clone();
    // A point is never offset (SPEC.md §18.2).
    Values {
        depth_interval: [depth.clone(), depth.clone()],
        depth,
        attributes: v.attributes.iter().map(|a| a.as_rbig().clone()).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Number;

    fn q(s: &str) -> RBig {
        Number::from_string(s).unwrap().as_rbig().clone()
    }

    #[test]
    fn a_square_through_pixel_centres_owns_them_as_the_rule_says() {
        // Centre 2, size 1: the edges 1.5 and 2.5 are pixel centres 1 and 2.
        let square = Square::new([q("2"), q("2")], &Number::ONE);
        assert_eq!(square.covered(0, FillRule::TopLeft, 8), vec![1]);
        assert_eq!(square.covered(0, FillRule::BottomRight, 8), vec![2]);
        assert_eq!(square.covered(0, FillRule::AllEdges, 8), vec![1, 2]);
        assert_eq!(square.covered(1, FillRule::TopRight, 8), vec![1]);
        assert_eq!(square.covered(1, FillRule::BottomLeft, 8), vec![2]);
    }

    #[test]
    fn the_canvas_limits_a_square() {
        let square = Square::new([q("0"), q("0")], &Number::from_int(4));
        assert_eq!(square.covered(0, FillRule::TopLeft, 8), vec![0, 1]);
        assert_eq!(square.covered(1, FillRule::TopLeft, 1), vec![0]);
    }
}
