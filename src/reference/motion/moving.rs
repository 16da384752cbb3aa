//! Moving triangles and `parallelogram` lines on the integer grid: the
//! polynomials in τ whose signs decide whether one sample is covered, and
//! the exact static decision at one rational instant (SPEC.md §3, §4.4).
//!
//! The decision at an instant is written out again here, from the rules,
//! rather than borrowed from `triangle.rs` and `line.rs`: the tests hold
//! this oracle against the static one at many instants, and two
//! independent readings of §3 and §4.4 that agree are the point.

use dashu_int::ops::UnsignedAbs;
use dashu_int::IBig;
use dashu_ratio::RBig;

use super::measure::{measure, Measure};
use super::quadratic::Quadratic;
use crate::reference::grid::{orient, Point};
use crate::scene::{Cull, FillRule, LineRule, Number, Primitive};

/// Deliberately wrong variants of the oracle, for the tests that show the
/// brute-force comparison catches them. Not for use.
#[doc(hidden)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Mutation {
    #[default]
    None,
    /// Roots of every polynomial without its τ² term, as if edges moved
    /// without turning.
    LinearEdges,
    /// Cull by the winding at shutter open, not at each instant.
    WindingAtOpen,
}

/// A vertex on the grid: at instant τ it is start + τ·velocity.
#[derive(Clone, Debug)]
pub struct Track {
    pub start: Point<IBig>,
    pub velocity: Point<IBig>,
}

/// An instant τ = num/den, den > 0.
struct Instant {
    num: IBig,
    den: IBig,
}

impl Instant {
    fn new(t: &RBig) -> Instant {
        Instant {
            num: t.numerator().clone(),
            den: IBig::from(t.denominator().clone()),
        }
    }

    /// den·p: a fixed point on the same scale as [`Track::at`].
    fn scale(&self, p: &Point<IBig>) -> Point<IBig> {
        [&p[0] * &self.den, &p[1] * &self.den]
    }
}

/// A point whose coordinates are polynomials of degree ≤ 1 in τ.
type PolyPoint = [Quadratic; 2];

impl Track {
    /// The vertex at τ = 0 and τ = 1, on a grid of `scale` units per
    /// pixel: each end snapped to 2^-bits pixel (SPEC.md §15.1), never the
    /// vertex at τ.
    ///
    /// # Panics
    /// When a snapped coordinate is not on the grid.
    fn new(from: [&Number; 2], to: [&Number; 2], bits: u32, scale: &IBig) -> Track {
        let start = from.map(|c| on_grid(&c.snapped(bits), scale));
        let end = to.map(|c| on_grid(&c.snapped(bits), scale));
        Track {
            velocity: [&end[0] - &start[0], &end[1] - &start[1]],
            start,
        }
    }

    fn poly(&self) -> PolyPoint {
        [0, 1].map(|k| Quadratic::linear(self.start[k].clone(), self.velocity[k].clone()))
    }

    /// den·(the vertex at τ = num/den): integers.
    fn at(&self, t: &Instant) -> Point<IBig> {
        [0, 1].map(|k| &self.start[k] * &t.den + &self.velocity[k] * &t.num)
    }
}

fn on_grid(n: &Number, scale: &IBig) -> IBig {
    let den = IBig::from(n.denominator().clone());
    let scaled = n.numerator() * scale;
    assert!(
        &scaled % &den == IBig::ZERO,
        "the grid holds every snapped vertex"
    );
    scaled / den
}

fn constant(p: &Point<IBig>) -> PolyPoint {
    [0, 1].map(|k| Quadratic::linear(p[k].clone(), IBig::ZERO))
}

fn minus(a: &PolyPoint, b: &PolyPoint) -> PolyPoint {
    [a[0].sub(&b[0]), a[1].sub(&b[1])]
}

/// u × w = ux·wy − uy·wx: a quadratic whose τ² coefficient is the cross
/// product of the two velocities.
fn cross(u: &PolyPoint, w: &PolyPoint) -> Quadratic {
    Quadratic::product(&u[0], &w[1]).sub(&Quadratic::product(&u[1], &w[0]))
}

fn signum(v: &IBig) -> i32 {
    match v.cmp(&IBig::ZERO) {
        std::cmp::Ordering::Less => -1,
        std::cmp::Ordering::Equal => 0,
        std::cmp::Ordering::Greater => 1,
    }
}

/// A moving primitive on the grid.
#[derive(Clone, Debug)]
pub enum Moving {
    Triangle([Track; 3]),
    /// A `parallelogram` line; its width as a fraction (num, den) of grid
    /// units.
    Line {
        ends: [Track; 2],
        width: (IBig, IBig),
    },
}

/// What decides coverage besides geometry.
#[derive(Clone, Copy, Debug)]
pub struct Rules {
    pub fill: FillRule,
    pub cull: Cull,
    pub mutation: Mutation,
}

impl Moving {
    /// `primitive` on a grid of `scale` units per pixel (a multiple of
    /// 2^bits).
    ///
    /// # Panics
    /// For polygons and lines of rules other than `parallelogram`, which
    /// cannot move (the reader refuses them, SPEC.md §15.1).
    pub fn new(primitive: &Primitive, bits: u32, scale: &IBig) -> Moving {
        let track = |v: &crate::scene::Vertex| Track::new([&v.x, &v.y], v.end(), bits, scale);
        match primitive {
            Primitive::Triangle(t) => Moving::Triangle([0, 1, 2].map(|i| track(&t.vertices[i]))),
            Primitive::Line(line) if line.rule == LineRule::Parallelogram => Moving::Line {
                ends: [0, 1].map(|i| track(&line.vertices[i])),
                width: (
                    line.width.numerator() * scale,
                    IBig::from(line.width.denominator().clone()),
                ),
            },
            other => panic!(
                "only triangles and parallelogram lines move (SPEC.md §15.1), not this {}",
                other.kind()
            ),
        }
    }

    /// [min, max] per axis of every point the primitive may cover at the
    /// instants between num_0/den and num_1/den (`instants` = [num_0,
    /// num_1]), in units of 1/den of a grid unit: a vertex moves along a
    /// segment, so its positions at the two instants bound it.
    pub fn bounds(&self, instants: [&IBig; 2], den: &IBig) -> [[IBig; 2]; 2] {
        let (tracks, reach): (&[Track], IBig) = match self {
            Moving::Triangle(v) => (v, IBig::ZERO),
            // A parallelogram reaches width/2 beyond its ends' box along the
            // minor axis: at most ⌈width⌉.
            Moving::Line { ends, width } => {
                let w = (&width.0 + &width.1 - IBig::ONE) / &width.1;
                (ends, w * den)
            }
        };
        [0, 1].map(|k| {
            let at = |v: &Track, n: &IBig| &v.start[k] * den + &v.velocity[k] * n;
            let all = tracks.iter().flat_map(|v| instants.map(|n| at(v, n)));
            let lo = all.clone().min().expect("vertices") - &reach;
            let hi = all.max().expect("vertices") + &reach;
            [lo, hi]
        })
    }

    /// The measure of the instants of [lo, hi] at which the primitive
    /// covers sample `p` (grid coordinates).
    pub fn measure(&self, p: &Point<IBig>, span: [&RBig; 2], bits: usize, rules: Rules) -> Measure {
        match self {
            Moving::Triangle(v) => triangle(v, p, span, bits, rules),
            Moving::Line { ends, width } => line(ends, width, p, span, bits, rules),
        }
    }
}

fn prepare(polys: Vec<Quadratic>, mutation: Mutation) -> Vec<Quadratic> {
    match mutation {
        Mutation::LinearEdges => polys.iter().map(Quadratic::without_square).collect(),
        _ => polys,
    }
}

/// A moving triangle at sample p: its twice-signed area A(τ) and edge
/// functions E_i(τ) decide coverage wherever none of them is zero. Where
/// E_i vanishes identically (p rides on edge i), the edge's ownership
/// decides: it changes only with the signs of A (the winding), of the
/// edge's dy (turning horizontal) and, for a horizontal edge, of the third
/// vertex's height above it, so those join the list.
fn triangle(
    v: &[Track; 3],
    p: &Point<IBig>,
    span: [&RBig; 2],
    bits: usize,
    rules: Rules,
) -> Measure {
    let at = [0, 1, 2].map(|i| v[i].poly());
    let q = constant(p);
    let area = cross(&minus(&at[1], &at[0]), &minus(&at[2], &at[0]));
    let mut polys = vec![area];
    for i in 0..3 {
        let (a, b, c) = (&at[i], &at[(i + 1) % 3], &at[(i + 2) % 3]);
        let edge = cross(&minus(b, a), &minus(&q, a));
        if edge.is_zero() {
            polys.push(b[1].sub(&a[1]));
            polys.push(c[1].sub(&a[1]));
        } else {
            polys.push(edge);
        }
    }
    let winding_at_open = match rules.mutation {
        Mutation::WindingAtOpen => {
            let t = Instant::new(span[0]);
            let w = [0, 1, 2].map(|i| v[i].at(&t));
            Some(signum(&orient(&w[0], &w[1], &w[2]))).filter(|s| *s != 0)
        }
        _ => None,
    };
    let mut holds = |t: &RBig| {
        let t = Instant::new(t);
        let w = [0, 1, 2].map(|i| v[i].at(&t));
        triangle_covers(&w, &t.scale(p), rules, winding_at_open)
    };
    measure(span, &prepare(polys, rules.mutation), bits, &mut holds)
}

/// SPEC.md §2 and §3 at one instant: zero area covers nothing, cull by
/// the winding (`winding` overrides it for a wrong variant), and a sample
/// on an edge is covered when every edge it lies on owns it.
fn triangle_covers(
    v: &[Point<IBig>; 3],
    p: &Point<IBig>,
    rules: Rules,
    winding: Option<i32>,
) -> bool {
    let sign = signum(&orient(&v[0], &v[1], &v[2]));
    if sign == 0 {
        return false;
    }
    let clockwise = winding.unwrap_or(sign) > 0;
    match rules.cull {
        Cull::Clockwise if clockwise => return false,
        Cull::CounterClockwise if !clockwise => return false,
        _ => {}
    }
    (0..3).all(|i| {
        let (a, b, c) = (&v[i], &v[(i + 1) % 3], &v[(i + 2) % 3]);
        let inward = signum(&orient(a, b, p)) * sign;
        inward > 0 || (inward == 0 && edge_owns(rules.fill, a, b, c, sign))
    })
}

/// D3D11's classification: a horizontal edge is a top edge when the third
/// vertex lies below it (y down); another edge is a left edge when the
/// triangle lies to its right, which is when −A has the sign of the edge's
/// dy (orient(a, b, c) = A for every edge of the triangle).
fn edge_owns(rule: FillRule, a: &Point<IBig>, b: &Point<IBig>, c: &Point<IBig>, area: i32) -> bool {
    if a[1] == b[1] {
        return if c[1] > a[1] {
            rule.owns_top()
        } else {
            rule.owns_bottom()
        };
    }
    if -area == signum(&(&b[1] - &a[1])) {
        rule.owns_left()
    } else {
        rule.owns_right()
    }
}

/// A moving parallelogram line at sample p. Its major axis is that of its
/// direction d(τ) at each instant, so the span is first cut where
/// |dx| = |dy| (roots of dx − dy and dx + dy, linear: rational). Inside a
/// piece the major axis m is fixed and coverage changes only with the
/// signs of dx and dy (the direction of each border's normal), of the
/// sample's position past either end along m, and of the two side
/// conditions w·|d_m| ∓ 2·(d × (p − a)) (SPEC.md §4.4, compared as
/// integers): each side is one of w·d_m ± 2·cross up to sign.
fn line(
    ends: &[Track; 2],
    width: &(IBig, IBig),
    p: &Point<IBig>,
    span: [&RBig; 2],
    bits: usize,
    rules: Rules,
) -> Measure {
    let [a, b] = [ends[0].poly(), ends[1].poly()];
    let d = minus(&b, &a);
    let q = minus(&constant(p), &a);
    let side = cross(&d, &q).scaled(&(IBig::from(2u8) * &width.1));
    let mut cuts: Vec<RBig> = [d[0].sub(&d[1]), d[0].add(&d[1])]
        .iter()
        .flat_map(|f| f.roots(0))
        .filter_map(|root| match root {
            super::quadratic::Root::At(t) if span[0] < &t && &t < span[1] => Some(t),
            _ => None,
        })
        .collect();
    cuts.sort();
    cuts.dedup();
    let mut bounds = vec![span[0].clone()];
    bounds.extend(cuts);
    bounds.push(span[1].clone());
    let mut total = Measure::default();
    for piece in bounds.windows(2) {
        let middle = Instant::new(&((&piece[0] + &piece[1]) / RBig::from(2u8)));
        let dm = [0, 1].map(|k| &ends[1].at(&middle)[k] - &ends[0].at(&middle)[k]);
        let m = major(&dm);
        let along = d[m].scaled(&width.0);
        let polys = vec![
            d[0].clone(),
            d[1].clone(),
            q[m].clone(),
            b[m].sub(&constant(p)[m]),
            along.add(&side),
            along.sub(&side),
        ];
        let mut holds = |t: &RBig| {
            let t = Instant::new(t);
            let w = (&width.0 * &t.den, width.1.clone());
            line_covers(
                &ends[0].at(&t),
                &ends[1].at(&t),
                &t.scale(p),
                &w,
                rules.fill,
            )
        };
        let piece = [&piece[0], &piece[1]];
        total.add(measure(
            piece,
            &prepare(polys, rules.mutation),
            bits,
            &mut holds,
        ));
    }
    total
}

/// SPEC.md §4.4 at one instant: between the ends along the major axis and
/// within width/2 of the segment along the minor one; a sample on a
/// border is covered when every border it lies on is owned, each border
/// classified by its outward normal (§4.3). `width` is (num, den) of grid
/// units on the points' scale.
fn line_covers(
    a: &Point<IBig>,
    b: &Point<IBig>,
    p: &Point<IBig>,
    width: &(IBig, IBig),
    fill: FillRule,
) -> bool {
    let d = [&b[0] - &a[0], &b[1] - &a[1]];
    if d[0] == IBig::ZERO && d[1] == IBig::ZERO {
        return false;
    }
    let m = major(&d);
    let sigma = IBig::from(signum(&d[m]));
    let q = [&p[0] - &a[0], &p[1] - &a[1]];
    let step = &q[m] * &sigma;
    let span = &d[m] * &sigma;
    let axis = |s: &IBig| {
        let mut n = [IBig::ZERO, IBig::ZERO];
        n[m] = s.clone();
        n
    };
    let cross = &d[0] * &q[1] - &d[1] * &q[0];
    let limit = &width.0 * &span;
    let twice = IBig::from(2u8) * &cross * &width.1;
    let borders = [
        (step.clone(), axis(&-&sigma)),
        (&span - &step, axis(&sigma)),
        (&limit - &twice, [-d[1].clone(), d[0].clone()]),
        (&limit + &twice, [d[1].clone(), -d[0].clone()]),
    ];
    borders
        .iter()
        .all(|(value, normal)| *value > IBig::ZERO || (*value == IBig::ZERO && owns(fill, normal)))
}

/// The major axis of direction d: x (0) when |dx| ≥ |dy|, so that
/// |slope| = 1 is x-major (SPEC.md §4).
fn major(d: &Point<IBig>) -> usize {
    usize::from((&d[0]).unsigned_abs() < (&d[1]).unsigned_abs())
}

/// Whether a border with outward normal n owns the samples on it: a top
/// border (n straight up) or bottom one, else a left or right one.
fn owns(fill: FillRule, n: &Point<IBig>) -> bool {
    if n[0] == IBig::ZERO {
        if n[1] < IBig::ZERO {
            fill.owns_top()
        } else {
            fill.owns_bottom()
        }
    } else if n[0] < IBig::ZERO {
        fill.owns_left()
    } else {
        fill.owns_right()
    }
}
