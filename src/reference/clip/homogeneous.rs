//! Homogeneous rasterization of one triangle (SPEC.md §16.4, §16.5): each
//! vertex a point of the projective plane, each sample tested with edge
//! functions that never divide by w, as in Olano and Greer's 2D
//! homogeneous rasterization.
//!
//! A vertex with w > 0 is its snapped screen position (X, Y, 1) with weight
//! 1/w; a vertex with w ≤ 0 is (w·vx + (vw/2)(w + x), w·vy + (vh/2)(w + y), w)
//! unsnapped, with weight 1. Each is then scaled by a positive integer to
//! integer coordinates G_i, and its weight m_i scaled with it, so that every
//! sample test is the sign of an integer and every value one exact quotient.

use dashu_int::IBig;
use dashu_ratio::RBig;

use super::super::triangle::gcd;
use super::clipper::ClipVertex;
use crate::scene::{FillRule, Number, Viewport};

/// A triangle ready for sample tests.
pub struct Homogeneous {
    /// Edge i's coefficients (a, b, c), G_(i+1) × G_(i+2), times σ: the
    /// edge function at a sample S = (2·sx, 2·sy, 2) is a·S_x + b·S_y + c·S_w,
    /// positive inside.
    edges: [[IBig; 3]; 3],
    /// Whether edge i owns the samples on it.
    owns: [bool; 3],
    /// Each vertex's weight m_i, clip z and attributes, for the values.
    vertices: [Weighted; 3],
    /// D = det[G0, G1, G2], times σ (so positive).
    det: IBig,
    /// Whether every vertex has w > 0: the triangle is then bounded on the
    /// screen by its vertices.
    pub bounded: Option<[RBig; 4]>,
}

/// A vertex's weight m_i and its clip z and attributes, exact.
struct Weighted {
    m: RBig,
    z: RBig,
    attributes: Vec<RBig>,
}

/// Where a clip-space vertex lands: its homogeneous screen point and
/// weight (SPEC.md §16.4), before scaling to integers.
pub fn screen_point(v: &ClipVertex, viewport: &Viewport, bits: Option<u32>) -> ([RBig; 3], RBig) {
    let [x, y, _, w] = &v.c;
    let (vx, vy) = (viewport.x.as_rbig(), viewport.y.as_rbig());
    let half_w = viewport.width.as_rbig() / RBig::from(2);
    let half_h = viewport.height.as_rbig() / RBig::from(2);
    if *w > RBig::ZERO {
        let land = |origin: &RBig, half: &RBig, c: &RBig| {
            let exact = origin + half * (c / w + RBig::ONE);
            match bits {
                Some(b) => Number::from_rbig(exact).snapped(b).as_rbig().clone(),
                None => exact,
            }
        };
        (
            [land(vx, &half_w, x), land(vy, &half_h, y), RBig::ONE],
            RBig::ONE / w,
        )
    } else {
        (
            [
                w * vx + &half_w * (w + x),
                w * vy + &half_h * (w + y),
                w.clone(),
            ],
            RBig::ONE,
        )
    }
}

/// The point scaled by the least positive integer that makes it integral,
/// and that integer.
fn integral(p: &[RBig; 3]) -> ([IBig; 3], IBig) {
    let mut l = IBig::ONE;
    for c in p {
        let d = IBig::from(c.denominator().clone());
        l = &l / gcd(&l, &d) * d;
    }
    let g = p
        .clone()
        .map(|c| c.numerator() * (&l / IBig::from(c.denominator().clone())));
    (g, l)
}

fn cross(p: &[IBig; 3], q: &[IBig; 3]) -> [IBig; 3] {
    [
        &p[1] * &q[2] - &p[2] * &q[1],
        &p[2] * &q[0] - &p[0] * &q[2],
        &p[0] * &q[1] - &p[1] * &q[0],
    ]
}

fn dot(p: &[IBig; 3], q: &[IBig; 3]) -> IBig {
    &p[0] * &q[0] + &p[1] * &q[1] + &p[2] * &q[2]
}

/// The sign of D for three clip-space vertices put on the screen: the
/// winding culling reads (positive: clockwise, y down).
pub fn winding(vertices: &[ClipVertex; 3], viewport: &Viewport, bits: Option<u32>) -> i8 {
    let g = vertices
        .each_ref()
        .map(|v| integral(&screen_point(v, viewport, bits).0).0);
    let d = dot(&g[0], &cross(&g[1], &g[2]));
    match d.cmp(&IBig::ZERO) {
        std::cmp::Ordering::Less => -1,
        std::cmp::Ordering::Equal => 0,
        std::cmp::Ordering::Greater => 1,
    }
}

/// Whether an edge whose inward gradient is (a, b) owns its samples: left
/// when a > 0, right when a < 0, else top when b > 0 (the triangle below
/// it, y down) and bottom when b < 0.
fn owns(rule: FillRule, a: &IBig, b: &IBig) -> bool {
    if *a > IBig::ZERO {
        rule.owns_left()
    } else if *a < IBig::ZERO {
        rule.owns_right()
    } else if *b > IBig::ZERO {
        rule.owns_top()
    } else if *b < IBig::ZERO {
        rule.owns_bottom()
    } else {
        false
    }
}

impl Homogeneous {
    /// `None` when D = 0: the triangle covers nothing.
    pub fn new(
        vertices: &[ClipVertex; 3],
        viewport: &Viewport,
        bits: Option<u32>,
        rule: FillRule,
    ) -> Option<Homogeneous> {
        let mut g: Vec<[IBig; 3]> = Vec::with_capacity(3);
        let mut weighted = Vec::with_capacity(3);
        let mut screen = Vec::with_capacity(3);
        for v in vertices {
            let (h, k) = screen_point(v, viewport, bits);
            let (gi, l) = integral(&h);
            g.push(gi);
            screen.push(h);
            weighted.push(Weighted {
                m: k * RBig::from(l),
                z: v.c[2].clone(),
                attributes: v.attributes.clone(),
            });
        }
        let g: [[IBig; 3]; 3] = g.try_into().expect("three");
        let mut edges = [0, 1, 2].map(|i| cross(&g[(i + 1) % 3], &g[(i + 2) % 3]));
        let mut det = dot(&g[0], &edges[0]);
        if det == IBig::ZERO {
            return None;
        }
        if det < IBig::ZERO {
            det = -det;
            for e in &mut edges {
                for c in e.iter_mut() {
                    *c = -&*c;
                }
            }
        }
        let owns = [0, 1, 2].map(|i| owns(rule, &edges[i][0], &edges[i][1]));
        let bounded = (vertices.iter().all(|v| v.c[3] > RBig::ZERO)).then(|| {
            let xs = screen.iter().map(|h| h[0].clone());
            let ys = screen.iter().map(|h| h[1].clone());
            [
                xs.clone().min().expect("three"),
                xs.max().expect("three"),
                ys.clone().min().expect("three"),
                ys.max().expect("three"),
            ]
        });
        Some(Homogeneous {
            edges,
            owns,
            vertices: weighted.try_into().ok().expect("three"),
            det,
            bounded,
        })
    }

    /// The edge values at pixel centre (px, py) when the triangle covers it
    /// (each ≥ 0, positive inside), `None` otherwise.
    pub fn covers(&self, px: i64, py: i64) -> Option<[IBig; 3]> {
        let values = self.edge_values(px, py);
        for (i, e) in values.iter().enumerate() {
            if *e < IBig::ZERO || (*e == IBig::ZERO && !self.owns[i]) {
                return None;
            }
        }
        Some(values)
    }

    /// The σ-signed edge values at pixel centre (px, py), covered or not:
    /// what the values of another triangle's covered sample are
    /// interpolated with under `interpolate_from: unsnapped` (SPEC.md
    /// §16.5).
    pub fn edge_values(&self, px: i64, py: i64) -> [IBig; 3] {
        let s = [
            IBig::from(2 * px + 1),
            IBig::from(2 * py + 1),
            IBig::from(2),
        ];
        [0, 1, 2].map(|i| dot(&self.edges[i], &s))
    }

    /// z_ndc at a covered sample: Σ E_i·m_i·z_i / D. The edge values are
    /// those of S scaled by 2, so D is scaled by 2 as well.
    pub fn depth(&self, e: &[IBig; 3]) -> RBig {
        let num = self.sum(e, |v| &v.m * &v.z);
        num / RBig::from(&self.det * IBig::from(2))
    }

    /// The gradient (∂z_ndc/∂x, ∂z_ndc/∂y) on the screen of the plane
    /// z_ndc(s) = Σ E_i(s)·m_i·z_i / D of [`Homogeneous::depth`]: E_i at
    /// S = (2·sx, 2·sy, 2) grows by 2·a_i per unit of sx (2·b_i of sy), and
    /// `depth` divides by 2·D.
    pub fn depth_gradient(&self) -> [RBig; 2] {
        [0, 1].map(|k| {
            let num = self
                .vertices
                .iter()
                .zip(&self.edges)
                .map(|(v, e)| &v.m * &v.z * RBig::from(e[k].clone()))
                .fold(RBig::ZERO, |a, b| a + b);
            num / RBig::from(self.det.clone())
        })
    }

    /// A perspective attribute: Σ E_i·m_i·a_i / Σ E_i·m_i.
    pub fn perspective(&self, e: &[IBig; 3], k: usize) -> RBig {
        self.sum(e, |v| &v.m * &v.attributes[k]) / self.weight(e)
    }

    /// Σ E_i·m_i: positive wherever the triangle's plane lies in front of
    /// the eye, and so at every sample it covers.
    pub fn weight(&self, e: &[IBig; 3]) -> RBig {
        self.sum(e, |v| v.m.clone())
    }

    fn sum(&self, e: &[IBig; 3], f: impl Fn(&Weighted) -> RBig) -> RBig {
        self.vertices
            .iter()
            .zip(e)
            .map(|(v, e)| f(v) * RBig::from(e.clone()))
            .fold(RBig::ZERO, |a, b| a + b)
    }
}
