//! Exact area coverage (SPEC.md §14.2): for each pixel, the area of
//! primitive ∩ pixel square [x, x+1] × [y, y+1] as a rational, summed over
//! primitives.
//!
//! Every primitive becomes an outline: closed directed contours and a fill
//! (a triangle or a parallelogram line is one contour filled nonzero; a
//! polygon keeps its contours and its fill). The plane is cut into
//! horizontal slabs at every vertex height, every height where two edges
//! cross, and every pixel row boundary. Inside a slab no two edges cross, so
//! the edges through it keep one left-to-right order; sweeping them in that
//! order (sorted at mid-height) accumulates the winding number, and each
//! edge gets a coefficient: +1 where the filled region begins at it, −1
//! where it ends, 0 where the fill does not change. The filled part of the
//! slab is then a set of trapezoids, and its area in pixel column j is
//! Σ coefficient · G(j), where G(j) is the area of column j within the slab
//! to the right of the edge, a piecewise quadratic of the column's bounds,
//! integrated exactly. Everything is in pixel units as `RBig`: the corners of
//! a parallelogram line (half a width from its ends) need not lie on the
//! sample grid.
//!
//! [`primitive_area`] computes a primitive's whole area a second way, with
//! no rows and no columns (the shoelace formula for triangles and
//! parallelograms, the slabs' trapezoids for polygons), so that the sum of
//! the per-pixel areas can be checked against it as an equality of
//! rationals.
//!
//! What this module does not do: `midpoint` and `diamond-exit` lines have no
//! area, and a `rectangle` line's is irrational; the reader refuses them in
//! antialiased scenes, and they count 0 here.

use dashu_int::IBig;
use dashu_ratio::RBig;

use super::exact::snap;
use crate::scene::{Cull, LineRule, Number, PolygonFill, Primitive, Scene};

type Point = [RBig; 2];

/// A primitive's filled region: directed edges of closed contours, and the
/// winding rule that fills them.
struct Outline {
    edges: Vec<(Point, Point)>,
    fill: PolygonFill,
    /// Whether edges meet only at shared vertices (a triangle or a
    /// parallelogram), so no crossing needs to be looked for.
    simple: bool,
}

/// An edge that is not horizontal, from its upper end (smaller y) down.
struct Edge {
    top: Point,
    bottom: Point,
    /// +1 when the contour runs down the screen along it, −1 up.
    direction: i64,
    /// dx/dy.
    slope: RBig,
}

impl Edge {
    fn x_at(&self, y: &RBig) -> RBig {
        &self.top[0] + (y - &self.top[1]) * &self.slope
    }
}

/// The exact area of each pixel covered by the scene's primitives, summed
/// over primitives, row-major. A triangle that is culled or has zero area
/// covers nothing; `midpoint`, `diamond-exit` and `rectangle` lines count 0.
pub fn exact_areas(scene: &Scene) -> Vec<RBig> {
    let (width, height) = (scene.canvas.width as usize, scene.canvas.height as usize);
    let mut areas = vec![RBig::ZERO; width * height];
    for index in 0..scene.primitives.len() {
        crate::deadline::check();
        if let Some(outline) = outline(scene, index) {
            add_pixel_areas(&outline, width, height, &mut areas);
        }
    }
    areas
}

/// The exact area of each pixel covered by primitive `index` alone, for
/// the pixels where it is not 0: (pixel index, area), row-major. Summed
/// over the primitives, these are [`exact_areas`].
pub fn primitive_pixel_areas(scene: &Scene, index: usize) -> Vec<(u32, RBig)> {
    let Some(outline) = outline(scene, index) else {
        return Vec::new();
    };
    let (width, height) = (scene.canvas.width as usize, scene.canvas.height as usize);
    let mut areas = vec![RBig::ZERO; width * height];
    add_pixel_areas(&outline, width, height, &mut areas);
    areas
        .into_iter()
        .enumerate()
        .filter(|(_, a)| *a != RBig::ZERO)
        .map(|(p, a)| (p as u32, a))
        .collect()
}

/// The whole filled area of primitive `index`, in square pixels, unclipped
/// by the canvas and computed without pixels: the shoelace formula for
/// triangles (0 when culled) and parallelogram lines, the slabs'
/// trapezoids for polygons. 0 for an index out of range.
pub fn primitive_area(scene: &Scene, index: usize) -> RBig {
    let Some(outline) = outline(scene, index) else {
        return RBig::ZERO;
    };
    if outline.simple {
        // Twice the signed area: Σ a × b over the edges.
        let twice = outline.edges.iter().fold(RBig::ZERO, |sum, (a, b)| {
            sum + &a[0] * &b[1] - &a[1] * &b[0]
        });
        let area = twice / RBig::from(2u8);
        return if area < RBig::ZERO { -area } else { area };
    }
    let mut total = RBig::ZERO;
    sweep(&outline, slab_heights(&outline, None), |_, y0, y1, slab| {
        let h = y1 - y0;
        for (edge, coefficient) in slab {
            // A trapezoid's area is its height times its mean width.
            let mid = (edge.x_at(y0) + edge.x_at(y1)) / RBig::from(2u8);
            total -= RBig::from(*coefficient) * &h * mid;
        }
    });
    total
}

/// The nearest f64 to an exact area (dashu rounds correctly).
pub fn to_f64_nearest(q: &RBig) -> f64 {
    q.to_f64().value()
}

fn place(scene: &Scene, n: &Number) -> RBig {
    match scene.rules.subpixel_bits {
        Some(bits) => snap(n, bits),
        None => n.as_rbig().clone(),
    }
}

/// The outline of primitive `index`, or `None` when it covers no area.
fn outline(scene: &Scene, index: usize) -> Option<Outline> {
    let primitive = scene.primitives.get(index)?;
    let points: Vec<Point> = primitive
        .vertices()
        .iter()
        .map(|v| [place(scene, &v.x), place(scene, &v.y)])
        .collect();
    let closed = |points: &[Point]| -> Vec<(Point, Point)> {
        (0..points.len())
            .map(|i| (points[i].clone(), points[(i + 1) % points.len()].clone()))
            .collect()
    };
    match primitive {
        Primitive::Triangle(_) => {
            let [a, b, c] = [&points[0], &points[1], &points[2]];
            // Positive for clockwise on screen (SPEC.md §2).
            let twice = (&b[0] - &a[0]) * (&c[1] - &a[1]) - (&b[1] - &a[1]) * (&c[0] - &a[0]);
            let culled = match scene.rules.cull {
                Cull::None => false,
                Cull::Clockwise => twice > RBig::ZERO,
                Cull::CounterClockwise => twice < RBig::ZERO,
            };
            (twice != RBig::ZERO && !culled).then(|| Outline {
                edges: closed(&points),
                fill: PolygonFill::NonZero,
                simple: true,
            })
        }
        Primitive::Line(line) if line.rule == LineRule::Parallelogram => {
            let (a, b) = (&points[0], &points[1]);
            let d = [&b[0] - &a[0], &b[1] - &a[1]];
            if d[0] == RBig::ZERO && d[1] == RBig::ZERO {
                return None;
            }
            // Swept along the minor axis by half the width each way (§4.4).
            let x_major = d[0].abs_cmp(&d[1]) != std::cmp::Ordering::Less;
            let minor = usize::from(x_major);
            let half = line.width.as_rbig() / RBig::from(2u8);
            let shift = |p: &Point, by: &RBig| {
                let mut q = p.clone();
                q[minor] = &q[minor] + by;
                q
            };
            let corners = [
                shift(a, &-half.clone()),
                shift(b, &-half.clone()),
                shift(b, &half),
                shift(a, &half),
            ];
            Some(Outline {
                edges: closed(&corners),
                fill: PolygonFill::NonZero,
                simple: true,
            })
        }
        Primitive::Line(_) | Primitive::Point(_) => None,
        Primitive::Polygon(polygon) => Some(Outline {
            edges: super::polygon::edges(polygon, &points)
                .into_iter()
                .map(|(a, b)| (a.clone(), b.clone()))
                .collect(),
            fill: polygon.fill,
            simple: false,
        }),
    }
}

trait AbsCmp {
    fn abs_cmp(&self, other: &Self) -> std::cmp::Ordering;
}

impl AbsCmp for RBig {
    fn abs_cmp(&self, other: &RBig) -> std::cmp::Ordering {
        let abs = |q: &RBig| {
            if *q < RBig::ZERO {
                -q.clone()
            } else {
                q.clone()
            }
        };
        abs(self).cmp(&abs(other))
    }
}

/// Every height where the slab structure can change: vertex heights and
/// the heights where two edges cross; with `rows = Some(height)`, also every
/// pixel row boundary, and only heights within [0, height] (the canvas).
/// Sorted, without repeats.
fn slab_heights(outline: &Outline, rows: Option<usize>) -> Vec<RBig> {
    let mut ys: Vec<RBig> = outline
        .edges
        .iter()
        .flat_map(|(a, b)| [a[1].clone(), b[1].clone()])
        .collect();
    if !outline.simple {
        ys.extend(crossing_heights(&outline.edges));
    }
    if let Some(height) = rows {
        let (lo, hi) = match (ys.iter().min(), ys.iter().max()) {
            (Some(lo), Some(hi)) => (lo.clone(), hi.clone()),
            _ => return Vec::new(),
        };
        let (top, bottom) = (RBig::ZERO, RBig::from(height));
        let first = lo.ceil().max(IBig::ZERO);
        let last = hi.floor().min(IBig::from(height));
        let mut r = first;
        while r <= last {
            ys.push(RBig::from(r.clone()));
            r += IBig::ONE;
        }
        ys.retain(|y| *y >= top && *y <= bottom);
    }
    ys.sort();
    ys.dedup();
    ys
}

/// The heights at which two edges meet, other than at their ends (those
/// are vertex heights already); parallel edges never need one.
fn crossing_heights(edges: &[(Point, Point)]) -> Vec<RBig> {
    let cross = |u: &[RBig; 2], v: &[RBig; 2]| &u[0] * &v[1] - &u[1] * &v[0];
    let sub = |a: &Point, b: &Point| [&a[0] - &b[0], &a[1] - &b[1]];
    let bounds = |(a, b): &(Point, Point), k: usize| {
        if a[k] <= b[k] {
            (a[k].clone(), b[k].clone())
        } else {
            (b[k].clone(), a[k].clone())
        }
    };
    // Edges by their top, so that only edges overlapping in y are paired.
    let mut order: Vec<(RBig, RBig, usize)> = edges
        .iter()
        .enumerate()
        .map(|(i, e)| {
            let (lo, hi) = bounds(e, 1);
            (lo, hi, i)
        })
        .collect();
    order.sort();
    let xs: Vec<(RBig, RBig)> = edges.iter().map(|e| bounds(e, 0)).collect();
    let mut heights = Vec::new();
    for (k, (_, hi, i)) in order.iter().enumerate() {
        for (lo2, _, j) in &order[k + 1..] {
            if lo2 > hi {
                break;
            }
            let (e, f) = (&edges[*i], &edges[*j]);
            let (ex, fx) = (&xs[*i], &xs[*j]);
            if ex.1 < fx.0 || fx.1 < ex.0 {
                continue;
            }
            // e: p + s·r, f: q + u·v; they meet where s = (q−p)×v / (r×v)
            // and u = (q−p)×r / (r×v), both in [0, 1].
            let (p, r) = (&e.0, sub(&e.1, &e.0));
            let (q, v) = (&f.0, sub(&f.1, &f.0));
            let denominator = cross(&r, &v);
            if denominator == RBig::ZERO {
                continue;
            }
            let qp = sub(q, p);
            let s = cross(&qp, &v) / &denominator;
            let u = cross(&qp, &r) / &denominator;
            let unit = |t: &RBig| *t >= RBig::ZERO && *t <= RBig::ONE;
            if unit(&s) && unit(&u) {
                heights.push(&p[1] + s * &r[1]);
            }
        }
    }
    heights
}

/// Calls `slab(row, y0, y1, edges)` for each slab between consecutive
/// `heights` with the edges through it that bound the filled region, each
/// with its coefficient (+1: the fill begins at it, going right; −1: it
/// ends). `row` is ⌊y0⌋.
fn sweep<F>(outline: &Outline, heights: Vec<RBig>, mut slab: F)
where
    F: FnMut(i64, &RBig, &RBig, &[(&Edge, i8)]),
{
    let mut edges: Vec<Edge> = outline
        .edges
        .iter()
        .filter(|(a, b)| a[1] != b[1])
        .map(|(a, b)| {
            let (top, bottom, direction) = if a[1] < b[1] {
                (a.clone(), b.clone(), 1)
            } else {
                (b.clone(), a.clone(), -1)
            };
            let slope = (&bottom[0] - &top[0]) / (&bottom[1] - &top[1]);
            Edge {
                top,
                bottom,
                direction,
                slope,
            }
        })
        .collect();
    edges.sort_by(|e, f| e.top[1].cmp(&f.top[1]));
    let mut next = 0;
    let mut active: Vec<usize> = Vec::new();
    let two = RBig::from(2u8);
    for pair in heights.windows(2) {
        crate::deadline::check();
        let (y0, y1) = (&pair[0], &pair[1]);
        while next < edges.len() && edges[next].top[1] <= *y0 {
            active.push(next);
            next += 1;
        }
        active.retain(|&i| edges[i].bottom[1] > *y0);
        // Every active edge spans the whole slab: its ends are heights.
        let middle = (y0 + y1) / &two;
        let mut through: Vec<(RBig, &Edge)> = active
            .iter()
            .map(|&i| (edges[i].x_at(&middle), &edges[i]))
            .collect();
        through.sort_by(|a, b| a.0.cmp(&b.0));
        let mut winding = 0i64;
        let mut bounding: Vec<(&Edge, i8)> = Vec::new();
        for (_, edge) in through {
            let before = outline.fill.fills(winding);
            winding += edge.direction;
            let after = outline.fill.fills(winding);
            if before != after {
                bounding.push((edge, if after { 1 } else { -1 }));
            }
        }
        if !bounding.is_empty() {
            let row: i64 = (&y0.floor()).try_into().unwrap_or(i64::MAX);
            slab(row, y0, y1, &bounding);
        }
    }
}

/// Adds the area of `outline` in each pixel of a width × height canvas.
fn add_pixel_areas(outline: &Outline, width: usize, height: usize, areas: &mut [RBig]) {
    add_pixel_areas_of(outline, width, height, areas, |_, _| true)
}

/// [`add_pixel_areas`] with only the slab edges `keep(slab, edge)` (the
/// tests' deliberately wrong variants drop one).
fn add_pixel_areas_of<K>(
    outline: &Outline,
    width: usize,
    height: usize,
    areas: &mut [RBig],
    mut keep: K,
) where
    K: FnMut(usize, usize) -> bool,
{
    let mut slab_index = 0;
    // Per row: columns from which a slab's edge adds coefficient · h to
    // every column to its right (the part of the slab right of the edge
    // that fills whole columns).
    let mut tails: Vec<(usize, i64, RBig)> = Vec::new();
    let heights = slab_heights(outline, Some(height));
    sweep(outline, heights, |row, y0, y1, slab| {
        if row < 0 || row >= height as i64 {
            return;
        }
        let row = row as usize;
        let h = y1 - y0;
        slab_index += 1;
        for (k, (edge, coefficient)) in slab.iter().enumerate() {
            if !keep(slab_index - 1, k) {
                continue;
            }
            let (xa, xb) = (edge.x_at(y0), edge.x_at(y1));
            let (lo, hi) = if xa <= xb { (xa, xb) } else { (xb, xa) };
            let right_of = RightOf {
                lo: &lo,
                hi: &hi,
                h: &h,
            };
            let first = lo.floor();
            let full: IBig = hi.ceil();
            let sign = RBig::from(*coefficient);
            // Columns the edge passes through, partly right of it.
            let mut j = first.clone().max(IBig::ZERO);
            while j < full && j < IBig::from(width) {
                let c = RBig::from(j.clone());
                let column = right_of.left_of(&(&c + RBig::ONE)) - right_of.left_of(&c);
                let x: usize = (&j).try_into().unwrap();
                areas[row * width + x] += &sign * column;
                j += IBig::ONE;
            }
            // Columns wholly right of it.
            let from: i64 = (&full.max(IBig::ZERO)).try_into().unwrap_or(i64::MAX);
            if from < width as i64 {
                tails.push((row, from, &sign * &h));
            }
        }
    });
    tails.sort_by_key(|t| (t.0, t.1));
    let mut k = 0;
    while k < tails.len() {
        let row = tails[k].0;
        let mut running = RBig::ZERO;
        while k < tails.len() && tails[k].0 == row {
            let from = tails[k].1 as usize;
            running += &tails[k].2;
            k += 1;
            let to = if k < tails.len() && tails[k].0 == row {
                tails[k].1 as usize
            } else {
                width
            };
            if running != RBig::ZERO {
                for x in from..to {
                    areas[row * width + x] += &running;
                }
            }
        }
    }
}

/// The part of a slab of height h right of an edge that runs from x = lo
/// to x = hi across it (in either direction).
struct RightOf<'a> {
    lo: &'a RBig,
    hi: &'a RBig,
    h: &'a RBig,
}

impl RightOf<'_> {
    /// Its area left of x = c:
    /// 0 for c ≤ lo; h (c − lo)² / (2 (hi − lo)) for lo ≤ c ≤ hi (a
    /// triangle); h (c − (lo + hi)/2) for c ≥ hi.
    fn left_of(&self, c: &RBig) -> RBig {
        let two = RBig::from(2u8);
        if c <= self.lo {
            RBig::ZERO
        } else if c >= self.hi {
            self.h * (c - (self.lo + self.hi) / &two)
        } else {
            let run = c - self.lo;
            self.h * &run * &run / (two * (self.hi - self.lo))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{parse_case, Limits};

    fn scene(primitives: &str, size: u32) -> Scene {
        let json = format!(
            r#"{{"name": "t", "canvas": {{"width": {size}, "height": {size}}},
                "rules": {{"subpixel_bits": null}}, "primitives": [{primitives}]}}"#
        );
        parse_case(&json, "t.json", &Limits::default()).unwrap()
    }

    fn q(n: i64, d: i64) -> RBig {
        RBig::from_parts_signed(n.into(), d.into())
    }

    #[test]
    fn a_half_square_triangle_splits_its_diagonal_pixels_in_halves() {
        let s = scene(r#"{"triangle": [[0, 0], [2, 0], [0, 2]]}"#, 2);
        let areas = exact_areas(&s);
        assert_eq!(areas, [RBig::ONE, q(1, 2), q(1, 2), RBig::ZERO]);
        assert_eq!(primitive_area(&s, 0), RBig::from(2u8));
    }

    #[test]
    fn a_pixel_cut_by_a_shallow_edge_gets_its_trapezoid() {
        // The edge from (0, 1/4) to (4, 3/4): in column 0 the region below
        // it has height 1 − (1/4 + 5/16)/2... measured against a hand sum.
        let s = scene(
            r#"{"polygon": [[0, "1/4"], [4, "3/4"], [4, 1], [0, 1]]}"#,
            4,
        );
        let areas = exact_areas(&s);
        // Column j: 1 − (mean height of the edge over [j, j+1]).
        let expected: Vec<RBig> = (0..4)
            .map(|j| RBig::ONE - (q(1, 4) + q(2 * j + 1, 16)))
            .collect();
        assert_eq!(&areas[..4], &expected[..]);
    }

    #[test]
    fn dropping_one_trapezoid_edge_breaks_the_self_check() {
        let s = scene(r#"{"triangle": [[0.5, 0.25], [3.75, 1], [1, 3.5]]}"#, 4);
        let outline = outline(&s, 0).unwrap();
        let total = |areas: &[RBig]| areas.iter().fold(RBig::ZERO, |sum, a| sum + a);
        let whole = primitive_area(&s, 0);
        let mut right = vec![RBig::ZERO; 16];
        add_pixel_areas(&outline, 4, 4, &mut right);
        assert_eq!(total(&right), whole);
        for (slab, edge) in [(0, 0), (2, 1), (3, 1)] {
            let mut wrong = vec![RBig::ZERO; 16];
            add_pixel_areas_of(&outline, 4, 4, &mut wrong, |s, k| (s, k) != (slab, edge));
            assert_ne!(total(&wrong), whole, "slab {slab}, edge {edge}");
        }
    }
}
