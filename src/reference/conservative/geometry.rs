//! Exact tests between a pixel's square (grown by the uncertainty) and a
//! snapped triangle, on one integer grid (SPEC.md §19.1): whether they
//! meet, and whether the square lies inside. Every decision is the sign of
//! an integer; closed sets throughout (touching counts).

use dashu_int::IBig;

/// A point on the integer grid.
pub type GridPoint = [IBig; 2];

/// An axis-aligned closed rectangle on the grid, [x0, x1] × [y0, y1].
#[derive(Clone, Debug)]
pub struct Rect {
    pub x0: IBig,
    pub y0: IBig,
    pub x1: IBig,
    pub y1: IBig,
}

impl Rect {
    pub fn corners(&self) -> [GridPoint; 4] {
        [
            [self.x0.clone(), self.y0.clone()],
            [self.x1.clone(), self.y0.clone()],
            [self.x1.clone(), self.y1.clone()],
            [self.x0.clone(), self.y1.clone()],
        ]
    }
}

/// (b − a) × (p − a): positive when p is clockwise of a→b on screen (y
/// down), zero on the line.
pub fn orient(a: &GridPoint, b: &GridPoint, p: &GridPoint) -> IBig {
    (&b[0] - &a[0]) * (&p[1] - &a[1]) - (&b[1] - &a[1]) * (&p[0] - &a[0])
}

/// The closed interval of n · p over `points`.
fn projection<'a>(n: &GridPoint, points: impl Iterator<Item = &'a GridPoint>) -> (IBig, IBig) {
    let mut lo: Option<IBig> = None;
    let mut hi: Option<IBig> = None;
    for p in points {
        let v = &n[0] * &p[0] + &n[1] * &p[1];
        if lo.as_ref().is_none_or(|l| v < *l) {
            lo = Some(v.clone());
        }
        if hi.as_ref().is_none_or(|h| v > *h) {
            hi = Some(v);
        }
    }
    (lo.expect("a point"), hi.expect("a point"))
}

/// Whether the closed rectangle `r` meets the closed convex hull of
/// `vertices`, given in order round it (a triangle, or the segment or point
/// a degenerate one is; a point's square; a parallelogram line).
/// Two compact convex polygons are disjoint exactly when a line parallel
/// to an edge of one separates them strictly, so the axes tried are x, y
/// and each non-zero edge's normal: they meet iff every axis's closed
/// projections overlap.
pub fn meets(r: &Rect, vertices: &[GridPoint]) -> bool {
    let corners = r.corners();
    let mut axes: Vec<GridPoint> = vec![[IBig::ONE, IBig::ZERO], [IBig::ZERO, IBig::ONE]];
    let n = vertices.len();
    for i in 0..n {
        let (a, b) = (&vertices[i], &vertices[(i + 1) % n]);
        let d = [&b[0] - &a[0], &b[1] - &a[1]];
        if d[0] != IBig::ZERO || d[1] != IBig::ZERO {
            axes.push([d[1].clone(), -&d[0]]);
        }
    }
    axes.iter().all(|n| {
        let (tl, th) = projection(n, vertices.iter());
        let (rl, rh) = projection(n, corners.iter());
        tl <= rh && rl <= th
    })
}

/// Whether the closed rectangle `r` lies inside the closed convex polygon
/// `vertices` (in order round it): every corner on the inner side of (or
/// on) every edge. A polygon of zero area contains no rectangle of
/// positive size.
pub fn inside(r: &Rect, vertices: &[GridPoint]) -> bool {
    let n = vertices.len();
    if n < 3 {
        return false;
    }
    // Twice the signed area, as a fan from the first vertex.
    let area = (1..n - 1)
        .map(|i| orient(&vertices[0], &vertices[i], &vertices[i + 1]))
        .fold(IBig::ZERO, |sum, o| sum + o);
    if area == IBig::ZERO {
        return false;
    }
    let positive = area > IBig::ZERO;
    r.corners().iter().all(|p| {
        (0..n).all(|i| {
            let o = orient(&vertices[i], &vertices[(i + 1) % n], p);
            if positive {
                o >= IBig::ZERO
            } else {
                o <= IBig::ZERO
            }
        })
    })
}

/// A grid point from integers, for tests.
#[cfg(test)]
pub(super) fn p(x: i64, y: i64) -> GridPoint {
    [IBig::from(x), IBig::from(y)]
}

/// A rectangle from integers, for tests.
#[cfg(test)]
pub(super) fn rect(x0: i64, y0: i64, x1: i64, y1: i64) -> Rect {
    Rect {
        x0: x0.into(),
        y0: y0.into(),
        x1: x1.into(),
        y1: y1.into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn touching_at_a_corner_meets_and_a_gap_does_not() {
        let t = [p(10, 10), p(20, 10), p(10, 20)];
        assert!(meets(&rect(0, 0, 10, 10), &t));
        assert!(!meets(&rect(0, 0, 9, 9), &t));
        // Across the hypotenuse: the corner (16, 16) is past x + y = 30.
        assert!(!meets(&rect(16, 16, 20, 20), &t));
        assert!(meets(&rect(15, 15, 20, 20), &t));
    }

    #[test]
    fn a_segment_and_a_point_meet_what_they_touch() {
        let segment = [p(0, 0), p(10, 10), p(5, 5)];
        assert!(!meets(&rect(5, 0, 6, 4), &segment));
        assert!(meets(&rect(4, 0, 6, 4), &segment));
        let point = [p(3, 3), p(3, 3), p(3, 3)];
        assert!(!meets(&rect(3, 0, 4, 2), &point));
        assert!(meets(&rect(3, 3, 4, 4), &point));
    }

    #[test]
    fn inside_is_closed() {
        let t = [p(0, 0), p(10, 0), p(0, 10)];
        assert!(inside(&rect(0, 0, 5, 5), &t));
        assert!(!inside(&rect(0, 0, 5, 6), &t));
        assert!(!inside(&rect(0, 0, 1, 1), &[p(0, 0), p(10, 0), p(20, 0)]));
    }
}
