//! A screen-space contour clipped exactly at a viewport rectangle
//! (SPEC.md §16.9): a driver without a guard band clips a screen-space
//! case at its viewport when no viewport it allows holds the case. With
//! w = 1 the homogeneous clip of `clipper.rs` against x = ±w, y = ±w is
//! the clip at the rectangle in screen space, so each position is put in
//! the rectangle's normalised coordinates, clipped there in the order
//! SPEC.md §16.3 clips (left, right, top, bottom), and put back: every new
//! vertex an exact rational on the rectangle's side, snapped afterwards
//! like any vertex.

use dashu_ratio::RBig;

use super::clipper::{clip, ClipVertex};

/// A rectangle of the canvas's pixels: its corner and its sides.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Window {
    pub origin: [RBig; 2],
    pub size: [RBig; 2],
}

impl Window {
    /// Whether `p` lies in the closed rectangle.
    pub fn holds(&self, p: &[RBig; 2]) -> bool {
        (0..2).all(|a| p[a] >= self.origin[a] && p[a] <= &self.origin[a] + &self.size[a])
    }
}

/// The part of the closed contour `points` (screen positions, exact) in
/// `window`, the last vertex joined to the first; fewer than three
/// vertices when nothing of it is left. A contour wholly inside comes back
/// as it is.
pub fn clip_to_window(points: &[[RBig; 2]], window: &Window) -> Vec<[RBig; 2]> {
    if points.iter().all(|p| window.holds(p)) {
        return points.to_vec();
    }
    let two = RBig::from(2u8);
    // x ↦ 2(x − x0)/V − 1: the rectangle onto [−1, 1], exactly.
    let ndc = |p: &[RBig; 2]| -> [RBig; 4] {
        let [x, y] =
            [0, 1].map(|a| &two * (&p[a] - &window.origin[a]) / &window.size[a] - RBig::ONE);
        [x, y, RBig::ZERO, RBig::ONE]
    };
    let polygon = points
        .iter()
        .map(|p| ClipVertex {
            c: ndc(p),
            attributes: Vec::new(),
        })
        .collect();
    let side_planes = [false, false, true, true, true, true];
    clip(polygon, side_planes)
        .into_iter()
        .map(|v| [0, 1].map(|a| (&v.c[a] + RBig::ONE) * &window.size[a] / &two + &window.origin[a]))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: i64, y: i64) -> [RBig; 2] {
        [RBig::from(x), RBig::from(y)]
    }

    fn window() -> Window {
        Window {
            origin: [RBig::ZERO, RBig::ZERO],
            size: [RBig::from(64), RBig::from(64)],
        }
    }

    #[test]
    fn a_contour_inside_comes_back_whole() {
        let inside = vec![p(1, 1), p(60, 2), p(3, 50)];
        assert_eq!(clip_to_window(&inside, &window()), inside);
    }

    #[test]
    fn a_long_triangle_is_cut_at_the_sides_exactly() {
        // From x = −32000 to +32000 at y = 10 and 20, apex far below.
        let far = vec![p(-32000, 10), p(32000, 20), p(0, 100_000)];
        let cut = clip_to_window(&far, &window());
        assert!(cut.len() >= 3);
        assert!(cut.iter().all(|q| window().holds(q)));
        // The crossing of the first edge with x = 0: y = 15, exactly.
        assert!(cut.contains(&[RBig::ZERO, RBig::from(15)]));
        // With x = 64: y = 10 + 10·32064/64000, a rational, exactly.
        let y = RBig::from(10) + RBig::from(10 * 32064) / RBig::from(64000);
        assert!(cut.contains(&[RBig::from(64), y]));
    }

    #[test]
    fn a_contour_wholly_outside_leaves_nothing() {
        let outside = vec![p(100, 100), p(200, 100), p(100, 200)];
        assert!(clip_to_window(&outside, &window()).len() < 3);
    }
}
