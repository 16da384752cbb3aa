//! Exact line coverage and interpolation (SPEC.md §4 and §5).
//!
//! Lines are evaluated in big integers throughout: a line visits O(length)
//! samples for `midpoint`, O(length × width) for wide lines, and the
//! squared comparisons of `rectangle` lines have no small bound worth
//! proving. Every decision is the sign of an exact integer expression.
//!
//! What this module does not do: step incrementally. Each column, row or
//! sample is evaluated from the segment's exact equation.

use dashu_int::IBig;
use dashu_ratio::RBig;

use super::exact::{ceil_div, to_f64_round_odd};
use super::grid::{orient, Grid, Point};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::scene::{
    Canvas, FillRule, Interpolation, LastPixel, Line, LineClamp, LineParameter, LineRule,
};

/// Visits every pixel a line covers: `visit(pixel, t)`, where t is the
/// exact interpolation parameter of the sample (SPEC.md §5), clamped to
/// [0, 1] unless `clamp` says otherwise (§5.1: a rasterizer's declared
/// unclamped parameter, which extrapolates before the first end and past
/// the last).
pub fn visit<F: FnMut(usize, RBig)>(
    grid: &Grid,
    canvas: Canvas,
    line: &Line,
    ends: &[Point<IBig>],
    rule: FillRule,
    clamp: LineClamp,
    mut visit: F,
) {
    let (a, b) = (&ends[0], &ends[1]);
    let d = [&b[0] - &a[0], &b[1] - &a[1]];
    if d[0] == IBig::ZERO && d[1] == IBig::ZERO {
        return;
    }
    let abs = |v: &IBig| {
        if *v < IBig::ZERO {
            -v.clone()
        } else {
            v.clone()
        }
    };
    // x-major (0) when |dx| ≥ |dy|, so that |slope| = 1 is x-major.
    let major = usize::from(abs(&d[0]) < abs(&d[1]));
    let parameter = |p: &Point<IBig>| -> RBig {
        let t = match line.parameter {
            LineParameter::Major => {
                RBig::from_parts_signed(&p[major] - &a[major], d[major].clone())
            }
            LineParameter::Projected => {
                let q = [&p[0] - &a[0], &p[1] - &a[1]];
                RBig::from_parts_signed(
                    &q[0] * &d[0] + &q[1] * &d[1],
                    &d[0] * &d[0] + &d[1] * &d[1],
                )
            }
        };
        match clamp {
            LineClamp::Clamped => t.clamp(RBig::ZERO, RBig::ONE),
            LineClamp::Unclamped => t,
        }
    };
    let width = canvas.width as usize;
    match line.rule {
        LineRule::Midpoint => midpoint(grid, canvas, line.last_pixel, a, b, major, |x, y, p| {
            visit(y as usize * width + x as usize, parameter(&p))
        }),
        LineRule::DiamondExit => diamond_exit(grid, canvas, a, b, major, |x, y, p| {
            visit(y as usize * width + x as usize, parameter(&p))
        }),
        LineRule::Rectangle | LineRule::Parallelogram => {
            let region = Region::new(grid, line, a, b, major, rule);
            let half = region.reach(grid);
            let lo = |k: usize| a[k].clone().min(b[k].clone()) - &half;
            let hi = |k: usize| a[k].clone().max(b[k].clone()) + &half;
            let xs = grid.centre_range(&lo(0), &hi(0), canvas.width);
            for y in grid.centre_range(&lo(1), &hi(1), canvas.height) {
                crate::deadline::check();
                for x in xs.clone() {
                    let p = [grid.centre(i64::from(x)), grid.centre(i64::from(y))];
                    if region.covers(&p) {
                        visit(y as usize * width + x as usize, parameter(&p));
                    }
                }
            }
        }
    }
}

/// The midpoint rule: in each column whose centre lies between the ends
/// (rows, for a y-major line), the pixel whose centre is nearest the line,
/// ties to the smaller coordinate. `draw(x, y, sample)`.
fn midpoint<F: FnMut(u32, u32, Point<IBig>)>(
    grid: &Grid,
    canvas: Canvas,
    last_pixel: LastPixel,
    a: &Point<IBig>,
    b: &Point<IBig>,
    major: usize,
    mut draw: F,
) {
    let minor = 1 - major;
    let sizes = [canvas.width, canvas.height];
    let (lo, hi) = (
        a[major].clone().min(b[major].clone()),
        a[major].clone().max(b[major].clone()),
    );
    for i in grid.centre_range(&lo, &hi, sizes[major]) {
        crate::deadline::check();
        let c = grid.centre(i64::from(i));
        if last_pixel == LastPixel::Exclude && c == b[major] {
            continue;
        }
        // The line's minor coordinate at c, in pixels:
        //   (a_minor·d_major + (c - a_major)·d_minor) / (d_major · scale),
        // and the pixel nearest it is ⌈that⌉ - 1.
        let d_major = &b[major] - &a[major];
        let d_minor = &b[minor] - &a[minor];
        let mut num = &a[minor] * &d_major + (&c - &a[major]) * &d_minor;
        let mut den = &d_major * &grid.scale;
        if den < IBig::ZERO {
            num = -num;
            den = -den;
        }
        let j = ceil_div(&num, &den) - IBig::ONE;
        if j < IBig::ZERO || j >= IBig::from(sizes[minor]) {
            continue;
        }
        let j: u32 = (&j).try_into().unwrap();
        let mut pixel = [0u32; 2];
        pixel[major] = i;
        pixel[minor] = j;
        let mut sample = [IBig::ZERO, IBig::ZERO];
        sample[major] = c;
        sample[minor] = grid.centre(i64::from(j));
        draw(pixel[0], pixel[1], sample);
    }
}

/// The diamond-exit rule: a pixel is lit when the segment meets its diamond
/// and v1 does not lie in it. `draw(x, y, sample)`.
///
/// Candidates: a segment through a diamond passes, at the diamond's centre
/// column (row, for y-major), within half a pixel of its centre, because
/// |slope| ≤ 1 along the major axis. So for every column whose centre lies
/// within a pixel of the segment's span, the two rows nearest the line's
/// height there (and one more on each side, to be generous) are tested
/// exactly.
fn diamond_exit<F: FnMut(u32, u32, Point<IBig>)>(
    grid: &Grid,
    canvas: Canvas,
    a: &Point<IBig>,
    b: &Point<IBig>,
    major: usize,
    mut draw: F,
) {
    let minor = 1 - major;
    let sizes = [canvas.width, canvas.height];
    let d = [&b[0] - &a[0], &b[1] - &a[1]];
    let lo = a[major].clone().min(b[major].clone()) - &grid.scale;
    let hi = a[major].clone().max(b[major].clone()) + &grid.scale;
    for i in grid.centre_range(&lo, &hi, sizes[major]) {
        crate::deadline::check();
        let c = grid.centre(i64::from(i));
        // The line's minor coordinate at c, in pixels, rounded down.
        let mut num = &a[minor] * &d[major] + (&c - &a[major]) * &d[minor];
        let mut den = &d[major] * &grid.scale;
        if den < IBig::ZERO {
            num = -num;
            den = -den;
        }
        let near = super::exact::floor_div(&num, &den);
        for j in [
            &near - IBig::from(2u8),
            &near - IBig::ONE,
            near.clone(),
            &near + IBig::ONE,
        ] {
            if j < IBig::ZERO || j >= IBig::from(sizes[minor]) {
                continue;
            }
            let j: u32 = (&j).try_into().unwrap();
            let mut pixel = [0u32; 2];
            pixel[major] = i;
            pixel[minor] = j;
            let centre = [
                grid.centre(i64::from(pixel[0])),
                grid.centre(i64::from(pixel[1])),
            ];
            let diamond = Diamond {
                centre: centre.clone(),
                half: &grid.scale >> 1,
                y_major: major == 1,
            };
            if diamond.meets(a, &d) && !diamond.contains(b) {
                draw(pixel[0], pixel[1], centre);
            }
        }
    }
}

/// A pixel's diamond with D3D11's border conventions (SPEC.md §4.2).
struct Diamond {
    centre: Point<IBig>,
    /// Half a pixel, in grid units.
    half: IBig,
    /// Whether the right corner belongs to it (y-major lines).
    y_major: bool,
}

impl Diamond {
    /// The four borders as (α, β, strict): α·u + β·v < half (strict) or
    /// ≤ half. Upper-left, upper-right, lower-left, lower-right.
    const BORDERS: [(i8, i8, bool); 4] =
        [(-1, -1, true), (1, -1, true), (-1, 1, false), (1, 1, false)];

    fn right_corner(&self) -> Point<IBig> {
        [&self.centre[0] + &self.half, self.centre[1].clone()]
    }

    fn contains(&self, p: &Point<IBig>) -> bool {
        let (u, v) = (&p[0] - &self.centre[0], &p[1] - &self.centre[1]);
        let inside = Diamond::BORDERS.iter().all(|&(alpha, beta, strict)| {
            let value = IBig::from(alpha) * &u + IBig::from(beta) * &v;
            if strict {
                value < self.half
            } else {
                value <= self.half
            }
        });
        inside || (self.y_major && *p == self.right_corner())
    }

    /// Whether the segment a + s·d, s ∈ [0, 1], meets the diamond.
    fn meets(&self, a: &Point<IBig>, d: &Point<IBig>) -> bool {
        let (u0, v0) = (&a[0] - &self.centre[0], &a[1] - &self.centre[1]);
        // The feasible s form an interval; each bound is (value, open).
        let mut low = (RBig::ZERO, false);
        let mut high = (RBig::ONE, false);
        for &(alpha, beta, strict) in &Diamond::BORDERS {
            let (alpha, beta) = (IBig::from(alpha), IBig::from(beta));
            // e + s·f (<, ≤) half.
            let e = &alpha * &u0 + &beta * &v0;
            let f = &alpha * &d[0] + &beta * &d[1];
            let room = &self.half - &e;
            if f == IBig::ZERO {
                let holds = if strict {
                    room > IBig::ZERO
                } else {
                    room >= IBig::ZERO
                };
                if !holds {
                    return self.y_major && self.passes_right_corner(a, d);
                }
                continue;
            }
            let bound = RBig::from_parts_signed(room, f.clone());
            if f > IBig::ZERO {
                // s < bound (or ≤).
                if bound < high.0 || (bound == high.0 && strict) {
                    high = (bound, strict);
                }
            } else if bound > low.0 || (bound == low.0 && strict) {
                low = (bound, strict);
            }
        }
        let meets = low.0 < high.0 || (low.0 == high.0 && !low.1 && !high.1);
        meets || (self.y_major && self.passes_right_corner(a, d))
    }

    fn passes_right_corner(&self, a: &Point<IBig>, d: &Point<IBig>) -> bool {
        let corner = self.right_corner();
        let b = [&a[0] + &d[0], &a[1] + &d[1]];
        if orient(a, &b, &corner) != IBig::ZERO {
            return false;
        }
        let within = |k: usize| {
            corner[k] >= a[k].clone().min(b[k].clone())
                && corner[k] <= a[k].clone().max(b[k].clone())
        };
        within(0) && within(1)
    }
}

/// A wide line as the intersection of four half-planes, each with its
/// outward normal, so that border samples follow the fill rule.
struct Region {
    a: Point<IBig>,
    d: Point<IBig>,
    /// The width as a fraction of grid units.
    width: (IBig, IBig),
    rule: LineRule,
    major: usize,
    fill: FillRule,
}

impl Region {
    fn new(
        grid: &Grid,
        line: &Line,
        a: &Point<IBig>,
        b: &Point<IBig>,
        major: usize,
        fill: FillRule,
    ) -> Region {
        Region {
            a: a.clone(),
            d: [&b[0] - &a[0], &b[1] - &a[1]],
            width: grid.length(&line.width),
            rule: line.rule,
            major,
            fill,
        }
    }

    /// How far, in grid units, the region reaches beyond the segment's
    /// bounding box on any axis: at most the width (a conservative bound).
    fn reach(&self, _grid: &Grid) -> IBig {
        ceil_div(&self.width.0, &self.width.1)
    }

    /// Whether an edge with outward normal n owns the samples on it.
    fn owns(&self, n: [IBig; 2]) -> bool {
        if n[0] == IBig::ZERO {
            if n[1] < IBig::ZERO {
                self.fill.owns_top()
            } else {
                self.fill.owns_bottom()
            }
        } else if n[0] < IBig::ZERO {
            self.fill.owns_left()
        } else {
            self.fill.owns_right()
        }
    }

    /// Each border as (signed distance-like value ≥ 0 inside, outward
    /// normal); the sample is covered when every value is positive, or
    /// zero on an owned border.
    fn covers(&self, p: &Point<IBig>) -> bool {
        let (a, d) = (&self.a, &self.d);
        let q = [&p[0] - &a[0], &p[1] - &a[1]];
        let zero = || IBig::ZERO;
        let (w_num, w_den) = &self.width;
        // Side borders: |q × d| against half the width, scaled to integers.
        let cross = orient(&[zero(), zero()], d, &q);
        let side_normal = |sign: i8| -> [IBig; 2] {
            // The gradient of q × d is (-dy, dx): outward on the positive side.
            let n = [-d[1].clone(), d[0].clone()];
            if sign > 0 {
                n
            } else {
                n.map(|c| -c)
            }
        };
        let (ends, side_slack): ([(IBig, [IBig; 2]); 2], [IBig; 2]) = match self.rule {
            LineRule::Rectangle => {
                let along = &q[0] * &d[0] + &q[1] * &d[1];
                let length2 = &d[0] * &d[0] + &d[1] * &d[1];
                // 4·cross²·w_den² ≤ w_num²·|d|²: one condition for both sides,
                // split by the sign of cross to know which border is touched.
                let slack =
                    w_num * w_num * &length2 - IBig::from(4u8) * &cross * &cross * w_den * w_den;
                let (plus, minus) = if cross >= IBig::ZERO {
                    (slack.clone(), IBig::ONE)
                } else {
                    (IBig::ONE, slack)
                };
                (
                    [
                        (along.clone(), d.clone().map(|c| -c)),
                        (length2 - along, d.clone()),
                    ],
                    [plus, minus],
                )
            }
            LineRule::Parallelogram => {
                let m = self.major;
                let step = q[m].clone() * d[m].signum();
                let span = d[m].clone() * d[m].signum();
                let mut start_normal = [IBig::ZERO, IBig::ZERO];
                start_normal[m] = -d[m].signum();
                let mut end_normal = [IBig::ZERO, IBig::ZERO];
                end_normal[m] = d[m].signum();
                // 2·|cross|·w_den ≤ w_num·|d_major|.
                let limit = w_num * &span;
                let twice = IBig::from(2u8) * &cross * w_den;
                (
                    [(step.clone(), start_normal), (span - step, end_normal)],
                    [&limit - &twice, &limit + &twice],
                )
            }
            LineRule::Midpoint | LineRule::DiamondExit => {
                unreachable!("thin lines are not regions")
            }
        };
        let borders = [
            (ends[0].0.clone(), ends[0].1.clone()),
            (ends[1].0.clone(), ends[1].1.clone()),
            (side_slack[0].clone(), side_normal(1)),
            (side_slack[1].clone(), side_normal(-1)),
        ];
        borders
            .into_iter()
            .all(|(value, normal)| value > IBig::ZERO || (value == IBig::ZERO && self.owns(normal)))
    }
}

/// The exact depth at a sample with parameter t, (1 − t)·z0 + t·z1.
pub fn depth(line: &Line, t: &RBig) -> RBig {
    let [v0, v1] = &line.vertices;
    (RBig::ONE - t) * v0.z.as_rbig() + t * v1.z.as_rbig()
}

/// Writes exact depth and attributes at a sample with parameter t; a flat
/// line takes vertex `provoking`'s values (SPEC.md §16.6).
pub fn write(
    line: &Line,
    provoking: usize,
    frame: &mut Frame,
    pixel: usize,
    plan: &Plan,
    t: &RBig,
) {
    let [v0, v1] = &line.vertices;
    let s = RBig::ONE - t;
    let mix = |a: &RBig, b: &RBig| &s * a + t * b;
    if let Some(depth) = frame.depth.as_mut() {
        depth[pixel] = to_f64_round_odd(&mix(v0.z.as_rbig(), v1.z.as_rbig()));
    }
    if plan.attributes == 0 {
        return;
    }
    let inv_w = [RBig::ONE / v0.w.as_rbig(), RBig::ONE / v1.w.as_rbig()];
    for k in 0..plan.attributes {
        let (a0, a1) = (v0.attributes[k].as_rbig(), v1.attributes[k].as_rbig());
        let exact = match line.interpolation {
            Interpolation::Flat => line.vertices[provoking].attributes[k].as_rbig().clone(),
            Interpolation::Linear => mix(a0, a1),
            Interpolation::Perspective => {
                // An unclamped t (SPEC.md §5.1) far past an end can reach
                // the line's vanishing point, where 1/w interpolates to 0
                // or below and the formula has no value: there t is taken
                // at the nearer end, as clamped.
                let w = mix(&inv_w[0], &inv_w[1]);
                if w > RBig::ZERO {
                    mix(&(a0 * &inv_w[0]), &(a1 * &inv_w[1])) / w
                } else if *t < RBig::ZERO {
                    a0.clone()
                } else {
                    a1.clone()
                }
            }
        };
        frame.attributes[k][pixel] = to_f64_round_odd(&exact);
    }
}

#[cfg(test)]
mod tests {
    use crate::plan::Plan;
    use crate::scene::{parse_case, Limits};

    /// The pixels a one-line case lights, as (x, y).
    fn lit(line: &str) -> Vec<(usize, usize)> {
        let json = format!(
            r#"{{"name": "t", "canvas": {{"width": 6, "height": 6}}, "primitives": [{line}]}}"#
        );
        let scene = parse_case(&json, "t.json", &Limits::default()).unwrap();
        let frame = crate::reference::render::render(&scene, &Plan::for_scene(&scene));
        (0..36)
            .filter(|&i| frame.coverage[i] > 0)
            .map(|i| (i % 6, i / 6))
            .collect()
    }

    #[test]
    fn diamond_exit_leaves_out_the_diamond_the_line_ends_in() {
        let pixels = lit(r#"{"line": [[0.5, 0.5], [4.5, 0.5]], "rule": "diamond-exit"}"#);
        assert_eq!(pixels, [(0, 0), (1, 0), (2, 0), (3, 0)]);
    }

    #[test]
    fn diamond_exit_owns_bottom_corners_not_top_ones() {
        // Along y = 1: the bottom corners of row 0 (included), the top
        // corners of row 1 (excluded).
        let pixels = lit(r#"{"line": [[0.5, 1], [4.5, 1]], "rule": "diamond-exit"}"#);
        assert_eq!(pixels, [(0, 0), (1, 0), (2, 0), (3, 0)]);
    }

    #[test]
    fn diamond_exit_owns_right_corners_for_y_major_lines_only() {
        // Along x = 1, y-major: the right corners of column 0 (included for
        // y-major lines), the left corners of column 1 (excluded).
        let pixels = lit(r#"{"line": [[1, 0.5], [1, 4.5]], "rule": "diamond-exit"}"#);
        assert_eq!(pixels, [(0, 0), (0, 1), (0, 2), (0, 3)]);
        // An x-major line through a right corner alone lights nothing there.
        let pixels = lit(r#"{"line": [[1, 2.5], [2, 2.5]], "rule": "diamond-exit"}"#);
        assert_eq!(pixels, [(1, 2)]);
    }

    #[test]
    fn midpoint_ties_go_up_and_left() {
        // Slope 1/2 from a centre: at x = 1.5 the line is at y = 1, between rows.
        assert_eq!(
            lit(r#"{"line": [[0.5, 0.5], [2.5, 1.5]]}"#),
            [(0, 0), (1, 0), (2, 1)]
        );
        // Slope 2: at y = 1.5 the line is at x = 1, between columns.
        assert_eq!(
            lit(r#"{"line": [[0.5, 0.5], [1.5, 2.5]]}"#),
            [(0, 0), (0, 1), (1, 2)]
        );
    }
}
