//! One triangle set up for conservative tests: its snapped vertices as
//! integer edge functions, positive inside, and its bounding box; then,
//! per pixel, whether a square centred on the pixel meets the triangle or
//! lies inside it (SPEC.md §19), decided exactly in integers.
//!
//! The classic method: an edge function E(p) = A·x + B·y + C is linear,
//! so over a square of half side s centred at c it ranges over
//! E(c) ± (|A| + |B|)·s. The square meets the edge's closed half-plane
//! when E(c) + (|A| + |B|)·s ≥ 0 and lies in it when E(c) − (|A| + |B|)·s
//! ≥ 0. A square lies inside a triangle exactly when it lies in all three
//! half-planes. It meets a triangle exactly when no axis separates them:
//! for two convex polygons an edge normal of one of them serves when any
//! axis does, so the tests are the three edges and the bounding boxes
//! (the square's own normals). Each comparison is exact (`growth.rs`).
//!
//! A triangle of zero area after snapping is the segment or point its
//! vertices span: a square meets it when the bounding boxes meet and, for
//! a segment, the square meets its line from both sides.

use super::growth::Growth;

/// Which way a triangle's area goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Shape {
    /// Positive area: the three edges, each positive inside.
    Area,
    /// Zero area, the vertices spanning a segment: edge 0 is its line.
    Segment,
    /// Zero area, every vertex the same point.
    Point,
}

/// One edge function in fixed-point units: E(x, y) = a·x + b·y + c, with
/// a and b in units of 1/one px and c in units of 1/one² px².
#[derive(Clone, Copy, Debug)]
struct Edge {
    a: i128,
    b: i128,
    c: i128,
    /// |a| + |b|: what a square of half side s adds to and takes from E
    /// at its centre, per unit of s.
    k: i128,
}

impl Edge {
    /// The edge from `p` to `q`: (q − p) × (r − p) at a point r, positive
    /// on the side a clockwise (on screen, y down) triangle has inside.
    fn through(p: [i128; 2], q: [i128; 2]) -> Edge {
        let a = p[1] - q[1];
        let b = q[0] - p[0];
        let c = -(a * p[0] + b * p[1]);
        Edge {
            a,
            b,
            c,
            k: a.abs() + b.abs(),
        }
    }

    fn flipped(self) -> Edge {
        Edge {
            a: -self.a,
            b: -self.b,
            c: -self.c,
            k: self.k,
        }
    }

    #[inline]
    fn at(&self, x: i128, y: i128) -> i128 {
        self.a * x + self.b * y + self.c
    }
}

/// A triangle ready for per-pixel conservative tests.
#[derive(Clone, Debug)]
pub(crate) struct Setup {
    pub(crate) shape: Shape,
    edges: [Edge; 3],
    /// The bounding box of the vertices, in units: [x_min, y_min, x_max, y_max].
    pub(crate) bounds: [i128; 4],
    /// Units per pixel: 2^f in fixed point, or twice the coordinates'
    /// common denominator.
    one: i128,
}

impl Setup {
    /// The triangle on `vertices` (in units of 1/`one` px, `one` even, so
    /// that pixel centres are whole units) and the sign of (b − a) × (c − a),
    /// what culling reads.
    pub(crate) fn new(v: [[i128; 2]; 3], one: i128) -> (Setup, std::cmp::Ordering) {
        let mut edges = [0, 1, 2].map(|i| Edge::through(v[i], v[(i + 1) % 3]));
        // (b − a) × (c − a) = E₀₁(c): positive when clockwise on screen.
        let cross = edges[0].at(v[2][0], v[2][1]);
        let orientation = cross.cmp(&0);
        if cross < 0 {
            edges = edges.map(Edge::flipped);
        }
        let shape = if cross != 0 {
            Shape::Area
        } else if v[0] == v[1] && v[1] == v[2] {
            Shape::Point
        } else {
            // The line of the two vertices farthest apart: any two distinct
            // ones give the same line; take an edge whose ends differ.
            let line = edges
                .into_iter()
                .find(|e| e.k != 0)
                .expect("two vertices differ");
            edges[0] = line;
            Shape::Segment
        };
        let lo = |k: usize| v.iter().map(|p| p[k]).min().unwrap_or(0);
        let hi = |k: usize| v.iter().map(|p| p[k]).max().unwrap_or(0);
        let setup = Setup {
            shape,
            edges,
            bounds: [lo(0), lo(1), hi(0), hi(1)],
            one,
        };
        (setup, orientation)
    }

    /// The pixel columns (or rows, `axis` 1) whose squares grown by at most
    /// one pixel can meet the bounding box: a superset, the exact tests
    /// decide. Half-open, clipped to `0..size`.
    pub(crate) fn range(&self, axis: usize, size: u32) -> std::ops::Range<i64> {
        let first = self.bounds[axis].div_euclid(self.one) - 2;
        let last = self.bounds[axis + 2].div_euclid(self.one) + 2;
        let clip = |v: i128| v.clamp(0, i128::from(size)) as i64;
        clip(first)..clip(last)
    }

    /// Whether the square of pixel (x, y) grown by the uncertainty meets
    /// the triangle: `half` is the grown half side (½ + u px), `margin`
    /// the uncertainty (u px). Overestimation's test (SPEC.md §19.1).
    pub(crate) fn meets(&self, x: i64, y: i64, half: &Growth, margin: &Growth) -> bool {
        let (x, y) = (i128::from(x), i128::from(y));
        // The bounding boxes: the pixel [x, x + 1] grown by u reaches the
        // vertices' range when its near side is at most u past it.
        let gap = |lo: i128, hi: i128, p: i128| (p * self.one - hi).max(lo - (p + 1) * self.one);
        if !margin.at_most(gap(self.bounds[0], self.bounds[2], x), 1)
            || !margin.at_most(gap(self.bounds[1], self.bounds[3], y), 1)
        {
            return false;
        }
        let (cx, cy) = self.centre(x, y);
        match self.shape {
            Shape::Point => true,
            // The square's range of E, E(c) ± k·s, must hold 0.
            Shape::Segment => {
                let e = self.edges[0];
                let value = e.at(cx, cy);
                half.at_most(value, e.k) && half.at_most(-value, e.k)
            }
            // −E(c) ≤ k·s for every edge.
            Shape::Area => self.edges.iter().all(|e| half.at_most(-e.at(cx, cy), e.k)),
        }
    }

    /// Whether the square of pixel (x, y) grown to half side `half` lies
    /// inside the triangle (closed): E(c) ≥ k·s for every edge.
    /// Underestimation's test, and the fully-covered flag's (SPEC.md §19.2,
    /// §19.4). No square lies inside a triangle of zero area.
    pub(crate) fn holds(&self, x: i64, y: i64, half: &Growth) -> bool {
        if self.shape != Shape::Area {
            return false;
        }
        let (cx, cy) = self.centre(i128::from(x), i128::from(y));
        self.edges.iter().all(|e| half.at_least(e.at(cx, cy), e.k))
    }

    /// The centre of pixel (x, y): (x + ½)·one, whole since `one` is even.
    fn centre(&self, x: i128, y: i128) -> (i128, i128) {
        let half = self.one / 2;
        (x * self.one + half, y * self.one + half)
    }
}
