//! Exact triangle coverage and interpolation.
//!
//! Every decision is the sign of an exact integer: vertices are snapped
//! exactly, moved onto one integer grid that also holds every sample point,
//! and tested against each edge with an orientation determinant. The fill
//! rule is applied as D3D11 words it (§3.4.2.1), edge by edge, from where the
//! third vertex lies, not from the winding.
//!
//! Each row of samples is settled by exact division: where each edge's
//! orientation, linear along the row, crosses its threshold (see
//! [`visit`]). What this module does not do: bounding-box blocking, or any
//! float arithmetic; speed is the production rasterizer's job.

use dashu_int::IBig;
use dashu_ratio::RBig;

use super::exact::{ceil_div, floor_div, quotient_to_f64_round_odd, to_f64_round_odd, ExactInt};
use super::grid::{orient, Grid, Point};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::scene::{Canvas, Cull, FillRule, Interpolation, Triangle};

/// Whether the edge a→b of a triangle whose third vertex is c owns the
/// samples on it, by D3D11's definitions: a top edge is horizontal with the
/// triangle below it; a left edge is not horizontal and has the triangle to
/// its right.
fn edge_owns<T: ExactInt>(rule: FillRule, a: &Point<T>, b: &Point<T>, c: &Point<T>) -> bool {
    if a[1] == b[1] {
        let triangle_below = c[1] > a[1];
        return if triangle_below {
            rule.owns_top()
        } else {
            rule.owns_bottom()
        };
    }
    // c lies right of the line through a and b when c.x exceeds the line's x
    // at c.y:  (cx - ax) > (cy - ay)(bx - ax)/(by - ay). Multiplying by
    // (by - ay) keeps the comparison exact and flips it when by < ay.
    let s = c[0]
        .sub(&a[0])
        .mul(&b[1].sub(&a[1]))
        .sub(&c[1].sub(&a[1]).mul(&b[0].sub(&a[0])));
    let triangle_right = s.signum() == b[1].sub(&a[1]).signum();
    if triangle_right {
        rule.owns_left()
    } else {
        rule.owns_right()
    }
}

/// A triangle ready for exact sample tests.
struct Setup<T> {
    v: [Point<T>; 3],
    /// Twice the signed area; positive for clockwise on screen.
    area: T,
    /// Edge i runs from v[i] to v[(i+1)%3]; whether it owns its samples.
    owns: [bool; 3],
}

impl<T: ExactInt> Setup<T> {
    /// `None` for zero-area and culled triangles.
    fn new(v: [Point<T>; 3], rule: FillRule, cull: Cull) -> Option<Setup<T>> {
        let area = orient(&v[0], &v[1], &v[2]);
        let clockwise = match area.signum() {
            0 => return None,
            s => s > 0,
        };
        match cull {
            Cull::Clockwise if clockwise => return None,
            Cull::CounterClockwise if !clockwise => return None,
            _ => {}
        }
        let owns = [0, 1, 2].map(|i| edge_owns(rule, &v[i], &v[(i + 1) % 3], &v[(i + 2) % 3]));
        Some(Setup { v, area, owns })
    }

    /// The three orientations of `p` against the edges when `p` is
    /// covered; `None` otherwise. Value i, for edge v[i]→v[i+1], carries the
    /// area's sign and equals the area times the barycentric weight of the
    /// opposite vertex v[i+2].
    fn covers(&self, p: &Point<T>) -> Option<[T; 3]> {
        let sign = self.area.signum();
        let mut values = [T::zero(), T::zero(), T::zero()];
        for (i, value) in values.iter_mut().enumerate() {
            let e = orient(&self.v[i], &self.v[(i + 1) % 3], p);
            let inward = e.signum() * sign;
            if inward < 0 || (inward == 0 && !self.owns[i]) {
                return None;
            }
            *value = e;
        }
        Some(values)
    }
}

/// What finding a row's span needs beyond [`ExactInt`]: addition, exact
/// floor and ceiling division by a positive divisor, and small constants.
pub trait SpanInt: ExactInt {
    fn add(&self, other: &Self) -> Self;
    fn from_i64(v: i64) -> Self;
    /// ⌊self / d⌋ for d > 0.
    fn floor_div(&self, d: &Self) -> Self;
    /// ⌈self / d⌉ for d > 0.
    fn ceil_div(&self, d: &Self) -> Self;
    /// The value clamped to [lo, hi].
    fn clamp_to(&self, lo: i64, hi: i64) -> i64;
}

impl SpanInt for i128 {
    fn add(&self, other: &Self) -> Self {
        self.checked_add(*other)
            .expect("i128 bound proven by I128_COORD_BOUND")
    }
    fn from_i64(v: i64) -> Self {
        i128::from(v)
    }
    fn floor_div(&self, d: &Self) -> Self {
        self.div_euclid(*d)
    }
    fn ceil_div(&self, d: &Self) -> Self {
        -(-self).div_euclid(*d)
    }
    fn clamp_to(&self, lo: i64, hi: i64) -> i64 {
        (*self).clamp(i128::from(lo), i128::from(hi)) as i64
    }
}

impl SpanInt for IBig {
    fn add(&self, other: &Self) -> Self {
        self + other
    }
    fn from_i64(v: i64) -> Self {
        IBig::from(v)
    }
    fn floor_div(&self, d: &Self) -> Self {
        floor_div(self, d)
    }
    fn ceil_div(&self, d: &Self) -> Self {
        ceil_div(self, d)
    }
    fn clamp_to(&self, lo: i64, hi: i64) -> i64 {
        if *self < IBig::from(lo) {
            lo
        } else if *self > IBig::from(hi) {
            hi
        } else {
            self.try_into().expect("between two i64")
        }
    }
}

/// Visits every covered sample of one triangle under `rule`:
/// `visit(pixel, edge values, twice the area)`. `to_t` moves grid
/// coordinates into the integer type the proof allows.
///
/// Row by row: along a row of sample points each edge's orientation is
/// linear in the column, o(k) = o(0) + k·step, so the columns inside the
/// edge (o·sign > 0, or = 0 where the edge owns its samples) are one
/// half-line whose end is an exact floor or ceiling quotient. The row's
/// span is the intersection of the three; its samples' values are o(0)
/// plus whole steps, exact integers. The span's end samples are tested
/// from scratch as well in debug builds, and the samples just beyond
/// them found outside.
pub fn visit<T, F>(
    grid: &Grid,
    canvas: Canvas,
    tri: &[Point<IBig>],
    to_t: fn(&IBig) -> T,
    rule: FillRule,
    cull: Cull,
    mut visit: F,
) where
    T: SpanInt,
    F: FnMut(usize, &[T; 3], &T),
{
    let v = [0, 1, 2].map(|i| tri[i].clone().map(|c| to_t(&c)));
    let Some(setup) = Setup::new(v, rule, cull) else {
        return;
    };
    let lo = |axis: usize| tri.iter().map(|p| &p[axis]).min().unwrap();
    let hi = |axis: usize| tri.iter().map(|p| &p[axis]).max().unwrap();
    let xs = grid.centre_range(lo(0), hi(0), canvas.width);
    let ys = grid.centre_range(lo(1), hi(1), canvas.height);
    if xs.is_empty() {
        return;
    }
    let columns = i64::from(xs.end - xs.start);
    let spacing = to_t(&grid.scale);
    // Grid::centre in T: i·scale + scale/2.
    let half = to_t(&(&grid.scale >> 1));
    let centre = |i: u32| T::from_i64(i64::from(i)).mul(&spacing).add(&half);
    let x0 = centre(xs.start);
    let sign = setup.area.signum();
    let signed = |t: T| if sign > 0 { t } else { T::zero().sub(&t) };
    // Per edge: the orientation's change from one column to the next,
    // -(by - ay)·spacing, and the least signed orientation inside it.
    let steps = [0, 1, 2].map(|i| setup.v[i][1].sub(&setup.v[(i + 1) % 3][1]).mul(&spacing));
    let least = setup.owns.map(|owns| T::from_i64(i64::from(!owns)));
    let zero = T::zero();
    for y in ys {
        crate::deadline::check();
        let py = centre(y);
        debug_assert!(py == to_t(&grid.centre(i64::from(y))));
        let first = [x0.clone(), py.clone()];
        let start = [0, 1, 2].map(|i| orient(&setup.v[i], &setup.v[(i + 1) % 3], &first));
        // Columns k in [from, to] with signed(start + k·step) ≥ least.
        let (mut from, mut to) = (0i64, columns - 1);
        for i in 0..3 {
            let (b, a) = (signed(start[i].clone()), signed(steps[i].clone()));
            match a.cmp(&zero) {
                std::cmp::Ordering::Equal => {
                    if b < least[i] {
                        to = -1;
                    }
                }
                // k ≥ ⌈(least − b) / a⌉.
                std::cmp::Ordering::Greater => {
                    let k = least[i].sub(&b).ceil_div(&a);
                    from = from.max(k.clamp_to(0, columns));
                }
                // k ≤ ⌊(b − least) / −a⌋.
                std::cmp::Ordering::Less => {
                    let k = b.sub(&least[i]).floor_div(&zero.sub(&a));
                    to = to.min(k.clamp_to(-1, columns - 1));
                }
            }
        }
        if from > to {
            continue;
        }
        let column = |k: i64| {
            let x = to_t(&grid.centre(i64::from(xs.start) + k));
            [x, py.clone()]
        };
        debug_assert!(setup.covers(&column(from)).is_some());
        debug_assert!(setup.covers(&column(to)).is_some());
        debug_assert!(from == 0 || setup.covers(&column(from - 1)).is_none());
        debug_assert!(to == columns - 1 || setup.covers(&column(to + 1)).is_none());
        let mut values = [0, 1, 2].map(|i| {
            let k = T::from_i64(from);
            start[i].add(&steps[i].mul(&k))
        });
        let row = y as usize * canvas.width as usize + xs.start as usize;
        for k in from..=to {
            visit(row + k as usize, &values, &setup.area);
            for (value, step) in values.iter_mut().zip(&steps) {
                *value = value.add(step);
            }
        }
    }
}

/// A triangle's exact per-vertex values, prepared for interpolation.
///
/// Each channel's three values are put over one common denominator, so a
/// sample's value is one quotient of integer sums of the edge values,
/// rounded once without any gcd (antialiased scenes evaluate it at every
/// sample of every pixel).
pub struct VertexValues {
    z: Combination,
    attributes: Vec<Channel>,
    /// Σ e'_i (1/w_i) as a combination, for perspective channels.
    inv_w: Combination,
}

/// Σ b_i v_i as integers: (Σ e'_i num_i) / (area · den), where e'_i is the
/// edge value opposite vertex i (area · b_i).
struct Combination {
    num: [IBig; 3],
    den: IBig,
}

impl Combination {
    fn new(values: &[RBig; 3]) -> Combination {
        let den = values.iter().fold(IBig::ONE, |l, v| {
            let d = IBig::from(v.denominator().clone());
            let g = gcd(&l, &d);
            &l / g * d
        });
        let num = values
            .clone()
            .map(|v| v.numerator() * (&den / IBig::from(v.denominator().clone())));
        Combination { num, den }
    }

    /// Σ e'_i num_i.
    fn sum(&self, weights: &[&IBig; 3]) -> IBig {
        weights[0] * &self.num[0] + weights[1] * &self.num[1] + weights[2] * &self.num[2]
    }
}

/// The greatest common divisor, non-negative.
pub(super) fn gcd(a: &IBig, b: &IBig) -> IBig {
    let (mut a, mut b) = (a.clone(), b.clone());
    while b != IBig::ZERO {
        let r = &a % &b;
        a = b;
        b = r;
    }
    if a < IBig::ZERO {
        -a
    } else {
        a
    }
}

enum Channel {
    /// The provoking vertex's value, rounded once.
    Flat(f64),
    Linear(Combination),
    /// Σ e'_i a_i/w_i over the combination of 1/w_i.
    Perspective(Combination),
}

impl VertexValues {
    /// `provoking`: the vertex whose values a flat triangle takes (SPEC.md §16.6).
    pub fn new(t: &Triangle, provoking: usize) -> VertexValues {
        let v = &t.vertices;
        let count = v[0].attributes.len();
        let inv_w: [RBig; 3] = [0, 1, 2].map(|i| RBig::ONE / v[i].w.as_rbig());
        let attributes = (0..count)
            .map(|k| {
                let values = [0, 1, 2].map(|i| v[i].attributes[k].as_rbig().clone());
                match t.interpolation {
                    Interpolation::Flat => Channel::Flat(to_f64_round_odd(&values[provoking])),
                    Interpolation::Linear => Channel::Linear(Combination::new(&values)),
                    Interpolation::Perspective => {
                        let over_w = [0, 1, 2].map(|i| &values[i] * &inv_w[i]);
                        Channel::Perspective(Combination::new(&over_w))
                    }
                }
            })
            .collect();
        VertexValues {
            z: Combination::new(&[0, 1, 2].map(|i| v[i].z.as_rbig().clone())),
            attributes,
            inv_w: Combination::new(&inv_w),
        }
    }

    /// The exact depth at a covered sample (for the depth formats of
    /// SPEC.md §18, which judge it before rounding).
    pub fn depth(&self, e: &[IBig; 3], area: &IBig) -> RBig {
        let weights = [&e[1], &e[2], &e[0]];
        RBig::from_parts_signed(self.z.sum(&weights), area * &self.z.den)
    }

    /// Whether its perspective channels have a value at the sample of
    /// these edge values: Σ b_i/w_i > 0 there (the sum carries the area's
    /// sign), as it is inside a triangle whose w are all positive, and no
    /// longer need be where its planes are extended beyond its edges
    /// (`pieces.rs`). Without a perspective channel, always.
    pub fn defined_at(&self, e: &[IBig; 3], area: &IBig) -> bool {
        if !self
            .attributes
            .iter()
            .any(|c| matches!(c, Channel::Perspective(_)))
        {
            return true;
        }
        let q = self.inv_w.sum(&[&e[1], &e[2], &e[0]]);
        q != IBig::ZERO && (q > IBig::ZERO) == (*area > IBig::ZERO)
    }

    /// Writes exact depth and attributes at a covered sample. `e[i]` is the
    /// edge value of edge v[i]→v[i+1], which is the area-weighted barycentric
    /// weight of the opposite vertex v[i+2].
    pub fn write(&self, frame: &mut Frame, pixel: usize, plan: &Plan, e: &[IBig; 3], area: &IBig) {
        // Area times the barycentric weight of vertex i: e[(i+1)%3].
        let weights = [&e[1], &e[2], &e[0]];
        let linear =
            |c: &Combination| quotient_to_f64_round_odd(&c.sum(&weights), &(area * &c.den));
        if let Some(depth) = frame.depth.as_mut() {
            depth[pixel] = linear(&self.z);
        }
        if plan.attributes == 0 {
            return;
        }
        // Perspective: (Σ b_i a_i / w_i) / (Σ b_i / w_i); the area cancels:
        // (Σ e'_i P_i / D_p) / (Σ e'_i Q_i / D_q).
        let mut inv_w_sum = None;
        for (k, channel) in self.attributes.iter().enumerate() {
            frame.attributes[k][pixel] = match channel {
                Channel::Flat(value) => *value,
                Channel::Linear(c) => linear(c),
                Channel::Perspective(c) => {
                    let q = inv_w_sum.get_or_insert_with(|| self.inv_w.sum(&weights));
                    quotient_to_f64_round_odd(&(c.sum(&weights) * &self.inv_w.den), &(&*q * &c.den))
                }
            };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Number, Vertex};

    /// The interpolation formulas of SPEC.md §5 in `RBig`, term by term.
    fn by_formula(t: &Triangle, e: &[IBig; 3], area: &IBig) -> (RBig, Vec<RBig>) {
        let b: [RBig; 3] =
            [0, 1, 2].map(|i| RBig::from_parts_signed(e[(i + 1) % 3].clone(), area.clone()));
        let v = &t.vertices;
        let linear = |f: &dyn Fn(usize) -> RBig| &b[0] * f(0) + &b[1] * f(1) + &b[2] * f(2);
        let z = linear(&|i| v[i].z.as_rbig().clone());
        let attributes = (0..v[0].attributes.len())
            .map(|k| match t.interpolation {
                Interpolation::Flat => v[0].attributes[k].as_rbig().clone(),
                Interpolation::Linear => linear(&|i| v[i].attributes[k].as_rbig().clone()),
                Interpolation::Perspective => {
                    linear(&|i| v[i].attributes[k].as_rbig() / v[i].w.as_rbig())
                        / linear(&|i| RBig::ONE / v[i].w.as_rbig())
                }
            })
            .collect();
        (z, attributes)
    }

    #[test]
    fn integer_combinations_round_like_the_rational_formulas() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = |m: i64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % (2 * m as u64)) as i64 - m
        };
        for round in 0..3000 {
            let mut vertex = || {
                let mut v = Vertex::at(Number::ZERO, Number::ZERO);
                v.z = Number::ratio(next(1 << 40), next(1000).abs() + 1);
                v.w = Number::ratio(next(1000).abs() + 1, next(1000).abs() + 1);
                v.attributes = vec![
                    Number::ratio(next(1 << 50), next(1 << 20).abs() + 1),
                    Number::ratio(next(7), 3),
                ];
                v
            };
            let t = Triangle {
                vertices: [vertex(), vertex(), vertex()],
                interpolation: [
                    Interpolation::Perspective,
                    Interpolation::Linear,
                    Interpolation::Flat,
                ][round % 3],
            };
            let area = IBig::from(next(1 << 40));
            if area == IBig::ZERO {
                continue;
            }
            // Edge values carry the area's sign and sum to it.
            let (e0, e1) = (next(1 << 20).abs(), next(1 << 20).abs());
            let scale = if area > IBig::ZERO { 1 } else { -1 };
            let e = [
                IBig::from(e0 * scale),
                IBig::from(e1 * scale),
                &area - IBig::from((e0 + e1) * scale),
            ];
            let plan = Plan {
                samples_per_pixel: 1,
                antialias: None,
                depth: true,
                attributes: 2,
                motion: None,
            };
            let mut frame = Frame::new(1, 1, true, 2);
            VertexValues::new(&t, 0).write(&mut frame, 0, &plan, &e, &area);
            let (z, attributes) = by_formula(&t, &e, &area);
            assert_eq!(frame.depth.as_ref().unwrap()[0], to_f64_round_odd(&z));
            for (channel, exact) in frame.attributes.iter().zip(&attributes) {
                assert_eq!(channel[0], to_f64_round_odd(exact));
            }
        }
    }
}
