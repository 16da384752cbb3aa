//! Exact polygon coverage (SPEC.md §14.1).
//!
//! A sample is covered when the winding number of the sample, nudged as the
//! fill rule says, passes the polygon's fill (even-odd or nonzero). The
//! nudged point lies on no edge, so no sample needs a further tie rule: the
//! nudge alone decides samples on edges, at vertices and at crossings, and
//! for a triangle it is exactly the edge ownership of §3.
//!
//! The winding number is counted along the horizontal ray from the nudged
//! point to +x. With the top-left nudge (x + ε, y + ε²), an edge a→b with
//! a.y ≠ b.y crosses that ray when min(a.y, b.y) ≤ p.y < max(a.y, b.y) (the
//! ε² moves the point below a vertex at p.y, so the edge leaving a vertex
//! downward counts and the one arriving from above does not) and its
//! crossing x_c at height p.y satisfies x_c > p.x (ε moves the point right
//! of a crossing at p.x, ε² · slope being negligible against ε). A nudge up
//! (−ε²) makes the first test min < p.y ≤ max; a nudge left (−ε) makes the
//! second x_c ≥ p.x. Horizontal edges never cross the nudged ray.
//!
//! x_c − p.x has the sign of orient(a, b, p) · sign(b.y − a.y): one exact
//! orientation, the expression `exact::I128_COORD_BOUND` is proven for.
//!
//! What this module does not do: interpolate (polygons carry positions
//! only), or treat `all-edges`, which SPEC.md leaves undefined for polygons
//! and the reader refuses; a scene built in code with it is decided as
//! top-left.

use dashu_int::IBig;

use super::exact::ExactInt;
use super::grid::{orient, Grid, Point};
use crate::scene::{Canvas, FillRule, Polygon};

/// Which way the fill rule nudges a sample: right (+ε) or left in x, down
/// (+ε²) or up in y.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Nudge {
    pub right: bool,
    pub down: bool,
}

impl Nudge {
    /// Top-left nudges right and down, bottom-right left and up, and so on:
    /// the nudge moves a sample on an owned edge into the primitive.
    pub fn of(rule: FillRule) -> Nudge {
        match rule {
            FillRule::TopLeft | FillRule::AllEdges => Nudge {
                right: true,
                down: true,
            },
            FillRule::TopRight => Nudge {
                right: false,
                down: true,
            },
            FillRule::BottomLeft => Nudge {
                right: true,
                down: false,
            },
            FillRule::BottomRight => Nudge {
                right: false,
                down: false,
            },
        }
    }

    /// Whether an edge spanning heights [lo, hi] (lo < hi) crosses the
    /// nudged horizontal line through height y.
    fn spans<T: ExactInt>(self, lo: &T, hi: &T, y: &T) -> bool {
        if self.down {
            lo <= y && y < hi
        } else {
            lo < y && y <= hi
        }
    }

    /// Whether a crossing counts for a sample, from `side` =
    /// orient(a, b, p) · sign(b.y − a.y), which has the sign of x_c − p.x.
    fn counts<T: ExactInt>(self, side: &T) -> bool {
        let s = side.signum();
        if self.right {
            s > 0
        } else {
            s >= 0
        }
    }
}

/// One non-horizontal edge of a polygon, ready for sample tests.
struct Edge<T> {
    a: Point<T>,
    b: Point<T>,
    lo: T,
    hi: T,
    /// +1 when the edge runs down the screen (b.y > a.y), −1 when up: its
    /// step of the winding number, and the sign of b.y − a.y.
    direction: i64,
}

/// The directed edges of a polygon's contours as grid points: (from, to).
/// `points` holds the polygon's vertices in order, contour after contour.
pub fn edges<'a, P>(polygon: &Polygon, points: &'a [P]) -> Vec<(&'a P, &'a P)> {
    let mut edges = Vec::new();
    let mut start = 0;
    for &end in &polygon.contour_ends {
        let end = end.min(points.len());
        if end > start {
            let contour = &points[start..end];
            for (i, a) in contour.iter().enumerate() {
                edges.push((a, &contour[(i + 1) % contour.len()]));
            }
        }
        start = start.max(end);
    }
    edges
}

/// Visits every sample (pixel centre) a polygon covers under `rule`:
/// `visit(pixel)`. `to_t` moves grid coordinates into the integer type the
/// proof allows.
pub fn visit<T, F>(
    grid: &Grid,
    canvas: Canvas,
    polygon: &Polygon,
    points: &[Point<IBig>],
    to_t: fn(&IBig) -> T,
    rule: FillRule,
    visit: F,
) where
    T: ExactInt,
    F: FnMut(usize),
{
    visit_nudged(grid, canvas, polygon, points, to_t, Nudge::of(rule), visit)
}

/// [`visit`] with the nudge given directly.
fn visit_nudged<T, F>(
    grid: &Grid,
    canvas: Canvas,
    polygon: &Polygon,
    points: &[Point<IBig>],
    to_t: fn(&IBig) -> T,
    nudge: Nudge,
    mut visit: F,
) where
    T: ExactInt,
    F: FnMut(usize),
{
    if points.is_empty() {
        return;
    }
    let edges: Vec<Edge<T>> = edges(polygon, points)
        .into_iter()
        .filter(|(a, b)| a[1] != b[1])
        .map(|(a, b)| {
            let (a, b) = (a.clone().map(|c| to_t(&c)), b.clone().map(|c| to_t(&c)));
            let down = b[1] > a[1];
            let (lo, hi) = if down {
                (a[1].clone(), b[1].clone())
            } else {
                (b[1].clone(), a[1].clone())
            };
            Edge {
                a,
                b,
                lo,
                hi,
                direction: if down { 1 } else { -1 },
            }
        })
        .collect();
    let lo = |axis: usize| points.iter().map(|p| &p[axis]).min().unwrap();
    let hi = |axis: usize| points.iter().map(|p| &p[axis]).max().unwrap();
    let xs = grid.centre_range(lo(0), hi(0), canvas.width);
    let ys = grid.centre_range(lo(1), hi(1), canvas.height);
    let columns: Vec<T> = xs
        .clone()
        .map(|x| to_t(&grid.centre(i64::from(x))))
        .collect();
    // change[i]: how the winding number steps between column i − 1 and i,
    // counting from the left end of the row, where the nudged ray crosses
    // every edge of the row.
    let mut change = vec![0i64; columns.len() + 1];
    for y in ys {
        crate::deadline::check();
        let py = to_t(&grid.centre(i64::from(y)));
        change.iter_mut().for_each(|c| *c = 0);
        for edge in edges.iter().filter(|e| nudge.spans(&e.lo, &e.hi, &py)) {
            // The crossing counts for a prefix of the columns: x_c − p.x
            // falls as p.x grows. Find where it stops counting.
            let counts = |px: &T| {
                let p = [px.clone(), py.clone()];
                let o = orient(&edge.a, &edge.b, &p);
                let side = if edge.direction > 0 {
                    o
                } else {
                    T::zero().sub(&o)
                };
                nudge.counts(&side)
            };
            let stop = columns.partition_point(counts);
            change[0] += edge.direction;
            change[stop] -= edge.direction;
        }
        let mut winding = 0i64;
        for (i, x) in xs.clone().enumerate() {
            winding += change[i];
            if polygon.fill.fills(winding) {
                visit(y as usize * canvas.width as usize + x as usize);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::grid::on_grid;
    use crate::scene::{parse_case, Limits, Primitive, Scene};

    fn scene(primitive: &str) -> Scene {
        let json = format!(
            r#"{{"name": "t", "canvas": {{"width": 4, "height": 4}}, "primitives": [{primitive}]}}"#
        );
        parse_case(&json, "t.json", &Limits::default()).unwrap()
    }

    /// The pixels the first primitive, a polygon, covers with `nudge`.
    fn covered(scene: &Scene, nudge: Nudge) -> Vec<usize> {
        let on = on_grid(scene);
        let Primitive::Polygon(polygon) = &scene.primitives[0] else {
            panic!("a polygon");
        };
        let mut pixels = Vec::new();
        visit_nudged(
            &on.grid,
            scene.canvas,
            polygon,
            &on.points[0],
            IBig::clone,
            nudge,
            |p| pixels.push(p),
        );
        pixels
    }

    #[test]
    fn the_nudge_decides_samples_on_edges_and_vertices() {
        // A square whose corners are the centres of pixels (1, 1) and
        // (2, 2): every sample it touches lies on its border.
        let s = scene(r#"{"polygon": [[1.5, 1.5], [2.5, 1.5], [2.5, 2.5], [1.5, 2.5]]}"#);
        let right_down = Nudge {
            right: true,
            down: true,
        };
        // Top-left: only the top-left corner's sample (on the top and left
        // edges) is covered.
        assert_eq!(covered(&s, right_down), [4 + 1]);
        // A nudge with the wrong sign in x takes the top-right corner.
        let left_down = Nudge {
            right: false,
            down: true,
        };
        assert_eq!(covered(&s, left_down), [4 + 2]);
        let left_up = Nudge {
            right: false,
            down: false,
        };
        assert_eq!(covered(&s, left_up), [2 * 4 + 2]);
    }

    #[test]
    fn nudges_follow_the_edges_each_rule_owns() {
        for rule in FillRule::CONSISTENT {
            let n = Nudge::of(rule);
            assert_eq!(n.right, rule.owns_left(), "{rule:?}");
            assert_eq!(n.down, rule.owns_top(), "{rule:?}");
        }
    }
}
