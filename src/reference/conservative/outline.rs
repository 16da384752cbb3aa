//! The closed shape each primitive of a conservative scene is, on one
//! integer grid (SPEC.md §19.3, §19.8): a triangle, or the segment or point
//! a degenerate one is; a point's square; a `parallelogram` line's
//! parallelogram; a `rectangle` line's rectangle, whose corners are
//! irrational and whose tests compare squares; a degenerate line's point.
//! Each shape answers whether a closed grid rectangle meets it and whether
//! it holds one, exactly.
//!
//! The grid is the least common multiple of every denominator: the snapped
//! coordinates, the uncertainty u, each point's half size and each line's
//! half width, so that every one of them, and every pixel boundary, is an
//! integer.

use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

use super::geometry::{inside, meets, orient, GridPoint, Rect};
use crate::reference::exact::snap;
use crate::scene::{Conservative, LineRule, Number, Primitive, Scene};

/// A primitive's closed shape on the grid.
#[derive(Clone, Debug)]
pub enum Outline {
    /// The closed convex hull of these points, in order round it: a
    /// triangle (or the segment or point a degenerate one is), a point's
    /// square, a parallelogram line, a degenerate line's point.
    Hull(Vec<GridPoint>),
    /// A `rectangle` line (SPEC.md §4.3): with d = b − a ≠ 0 and q = p − a,
    /// the points with 0 ≤ q·d ≤ |d|² and |q × d| ≤ h·|d|, h the half
    /// width.
    Rectangle {
        a: GridPoint,
        b: GridPoint,
        half_width: IBig,
    },
}

/// A conservative scene's shapes on the grid: the grid's units per pixel,
/// the uncertainty in those units, and each primitive drawn (its index in
/// the scene, its outline). Culled primitives are left out.
pub struct GridScene {
    pub scale: IBig,
    pub u: IBig,
    pub shapes: Vec<(usize, Outline)>,
}

/// The shapes of `scene`'s primitives under `case` (SPEC.md §19.3, §19.8):
/// triangles culled by winding or, when degenerate, by
/// `degenerate_triangles: false`; lines of zero length after snapping
/// culled by `degenerate_lines: false` and otherwise the point they are.
/// The scene holds triangles, points and `rectangle` or `parallelogram`
/// lines only (`Scene::conservative_unjudged`).
pub fn grid_scene(scene: &Scene, case: &Conservative) -> GridScene {
    let bits = scene.rules.subpixel_bits;
    let at = |v: &crate::scene::Vertex| [&v.x, &v.y].map(|c| snapped(c, bits));
    let half = |n: &Number| n.as_rbig() / RBig::from(2u8);
    // Every rational the shapes are built from, first as rationals.
    let rational: Vec<(usize, Rational)> = scene
        .primitives
        .iter()
        .enumerate()
        .filter_map(|(i, p)| {
            let shape = match p {
                Primitive::Triangle(t) => Rational::Hull(t.vertices.iter().map(at).collect()),
                Primitive::Point(p) => {
                    let [x, y] = at(&p.vertices[0]);
                    let h = half(&p.size);
                    Rational::Hull(vec![
                        [&x - &h, &y - &h],
                        [&x + &h, &y - &h],
                        [&x + &h, &y + &h],
                        [&x - &h, &y + &h],
                    ])
                }
                Primitive::Line(l) => {
                    let [a, b] = [at(&l.vertices[0]), at(&l.vertices[1])];
                    if a == b {
                        if !case.degenerate_lines {
                            return None;
                        }
                        Rational::Hull(vec![a])
                    } else if l.rule == LineRule::Rectangle {
                        Rational::Rectangle(Box::new((a, b, half(&l.width))))
                    } else {
                        // The parallelogram: each end swept by the half
                        // width along the minor axis (|dx| ≥ |dy|: x-major).
                        let d = [&b[0] - &a[0], &b[1] - &a[1]];
                        let abs = |q: &RBig| if *q < RBig::ZERO { -q } else { q.clone() };
                        let minor = usize::from(abs(&d[0]) >= abs(&d[1]));
                        let h = half(&l.width);
                        let shift = |p: &[RBig; 2], sign: bool| {
                            let mut q = p.clone();
                            q[minor] = if sign { &q[minor] + &h } else { &q[minor] - &h };
                            q
                        };
                        Rational::Hull(vec![
                            shift(&a, false),
                            shift(&b, false),
                            shift(&b, true),
                            shift(&a, true),
                        ])
                    }
                }
                Primitive::Polygon(_) => return None,
            };
            Some((i, shape))
        })
        .collect();
    let mut denominators: Vec<&UBig> = vec![case.uncertainty.as_rbig().denominator()];
    for (_, shape) in &rational {
        match shape {
            Rational::Hull(points) => {
                denominators.extend(points.iter().flatten().map(RBig::denominator));
            }
            Rational::Rectangle(line) => {
                let (a, b, h) = &**line;
                denominators.extend(a.iter().chain(b).chain([h]).map(RBig::denominator));
            }
        }
    }
    let scale = common_scale(denominators);
    let on_grid =
        |q: &RBig| -> IBig { q.numerator() * (&scale / IBig::from(q.denominator().clone())) };
    let point = |p: &[RBig; 2]| -> GridPoint { [on_grid(&p[0]), on_grid(&p[1])] };
    let mut shapes = Vec::new();
    for (i, shape) in rational {
        let outline = match shape {
            Rational::Hull(points) => {
                let points: Vec<GridPoint> = points.iter().map(point).collect();
                if let Primitive::Triangle(_) = scene.primitives[i] {
                    let area = orient(&points[0], &points[1], &points[2]);
                    if area == IBig::ZERO {
                        if !case.degenerate_triangles {
                            continue;
                        }
                    } else if scene.rules.cull.discards(area.cmp(&IBig::ZERO)) {
                        continue;
                    }
                }
                Outline::Hull(points)
            }
            Rational::Rectangle(line) => Outline::Rectangle {
                a: point(&line.0),
                b: point(&line.1),
                half_width: on_grid(&line.2),
            },
        };
        shapes.push((i, outline));
    }
    GridScene {
        u: on_grid(case.uncertainty.as_rbig()),
        scale,
        shapes,
    }
}

/// A shape before the grid is known.
enum Rational {
    Hull(Vec<[RBig; 2]>),
    Rectangle(Box<([RBig; 2], [RBig; 2], RBig)>),
}

impl Outline {
    /// Whether the closed rectangle `r` meets the shape.
    pub fn meets(&self, r: &Rect) -> bool {
        match self {
            Outline::Hull(points) => meets(r, points),
            Outline::Rectangle { a, b, half_width } => rectangle_meets(r, a, b, half_width),
        }
    }

    /// Whether the closed rectangle `r` lies inside the shape.
    pub fn holds(&self, r: &Rect) -> bool {
        match self {
            Outline::Hull(points) => inside(r, points),
            Outline::Rectangle { a, b, half_width } => {
                let d = [&b[0] - &a[0], &b[1] - &a[1]];
                let length2 = &d[0] * &d[0] + &d[1] * &d[1];
                let reach2 = half_width * half_width * &length2;
                r.corners().iter().all(|c| {
                    let q = [&c[0] - &a[0], &c[1] - &a[1]];
                    let along = &q[0] * &d[0] + &q[1] * &d[1];
                    let across = &q[0] * &d[1] - &q[1] * &d[0];
                    along >= IBig::ZERO && along <= length2 && &across * &across <= reach2
                })
            }
        }
    }

    /// A box on the grid holding the shape, [x0, y0, x1, y1]: a rectangle
    /// line's is its segment's grown by its half width (a superset).
    pub fn bounds(&self) -> [IBig; 4] {
        let (points, grow): (Vec<&GridPoint>, IBig) = match self {
            Outline::Hull(points) => (points.iter().collect(), IBig::ZERO),
            Outline::Rectangle { a, b, half_width } => (vec![a, b], half_width.clone()),
        };
        let lo = |k: usize| points.iter().map(|p| &p[k]).min().expect("a point") - &grow;
        let hi = |k: usize| points.iter().map(|p| &p[k]).max().expect("a point") + &grow;
        [lo(0), lo(1), hi(0), hi(1)]
    }
}

/// Whether the closed rectangle `r` meets the rectangle line on a→b of
/// half width h. Separating axes: x and y (r's normals), d and d⊥ (the
/// line's). On d the line spans [d·a, d·b]; on n = (d_y, −d_x) it spans
/// n·a ± h·|d|; on x it spans its ends' range grown by h·|d_y|/|d|, on y
/// by h·|d_x|/|d|. Each irrational reach is compared squared: v ≤ h·|d|
/// iff v ≤ 0 or v² ≤ h²·|d|².
fn rectangle_meets(r: &Rect, a: &GridPoint, b: &GridPoint, h: &IBig) -> bool {
    let d = [&b[0] - &a[0], &b[1] - &a[1]];
    let length2 = &d[0] * &d[0] + &d[1] * &d[1];
    let corners = r.corners();
    let span = |n: &GridPoint| {
        let values: Vec<IBig> = corners
            .iter()
            .map(|c| &n[0] * &c[0] + &n[1] * &c[1])
            .collect();
        let lo = values.iter().min().expect("four corners").clone();
        let hi = values.iter().max().expect("four corners").clone();
        (lo, hi)
    };
    // gap·√scale2 ≤ √reach2: the gap is not positive, or its square,
    // times scale2, is at most reach2.
    let within = |gap: IBig, reach2: &IBig, scale2: &IBig| {
        gap <= IBig::ZERO || &gap * &gap * scale2 <= *reach2
    };
    let h2 = h * h;
    // d: the line's projection is exact.
    let (rl, rh) = span(&d);
    let da = &d[0] * &a[0] + &d[1] * &a[1];
    if !(da <= rh && rl <= &da + &length2) {
        return false;
    }
    // n: n·a ± h·|d|.
    let n = [d[1].clone(), -&d[0]];
    let (rl, rh) = span(&n);
    let na = &n[0] * &a[0] + &n[1] * &a[1];
    let reach2 = &h2 * &length2;
    if !within(&rl - &na, &reach2, &IBig::ONE) || !within(&na - &rh, &reach2, &IBig::ONE) {
        return false;
    }
    // x and y: the ends' range grown by h·|d_other|/|d|: gap·|d| ≤ h·|d_other|.
    let sides = [(&r.x0, &r.x1, 0usize), (&r.y0, &r.y1, 1usize)];
    sides.into_iter().all(|(r0, r1, k)| {
        let lo = a[k].clone().min(b[k].clone());
        let hi = a[k].clone().max(b[k].clone());
        let other = &d[1 - k];
        let reach2 = &h2 * other * other;
        within(r0 - &hi, &reach2, &length2) && within(&lo - r1, &reach2, &length2)
    })
}

/// A coordinate where the rasterizer puts it: snapped to 2^-bits, or as
/// given.
pub(super) fn snapped(c: &Number, bits: Option<u32>) -> RBig {
    match bits {
        Some(bits) => snap(c, bits),
        None => c.as_rbig().clone(),
    }
}

/// The least common multiple of every denominator (and 1).
pub(super) fn common_scale(denominators: Vec<&UBig>) -> IBig {
    let mut scale = UBig::ONE;
    for d in denominators {
        let g = gcd(&scale, d);
        scale = &scale / &g * d;
    }
    scale.into()
}

fn gcd(a: &UBig, b: &UBig) -> UBig {
    let (mut a, mut b) = (a.clone(), b.clone());
    while b != UBig::ZERO {
        let r = &a % &b;
        a = b;
        b = r;
    }
    a
}

#[cfg(test)]
mod tests {
    use super::super::geometry::{p, rect};
    use super::*;

    #[test]
    fn a_diagonal_rectangle_reaches_its_irrational_corners_and_no_further() {
        // (0,0)→(10,10), half width 5·√2: its corners are (5,−5), (15,5),
        // (5,15), (−5,5). h is not on the grid, so scale by 2: (0,0)→(20,20),
        // h² = 200, h = 10√2, corners (10,−10), (30,10), (10,30), (−10,10).
        let line = Outline::Rectangle {
            a: p(0, 0),
            b: p(20, 20),
            half_width: IBig::from(14),
        };
        // h = 14 < 10√2 ≈ 14.14: the corner (10, −10) is just outside.
        assert!(!line.meets(&rect(9, -12, 11, -10)));
        assert!(line.meets(&rect(9, -12, 11, -9)));
        let line = Outline::Rectangle {
            a: p(0, 0),
            b: p(20, 20),
            half_width: IBig::from(15),
        };
        assert!(line.meets(&rect(9, -12, 11, -10)));
        // Past the end cap along d: x + y > 40 everywhere in the square.
        assert!(!line.meets(&rect(21, 20, 22, 21)));
        assert!(line.meets(&rect(20, 20, 22, 21)));
    }

    #[test]
    fn a_rectangle_holds_what_lies_inside_it() {
        let line = Outline::Rectangle {
            a: p(0, 10),
            b: p(40, 10),
            half_width: IBig::from(10),
        };
        assert!(line.holds(&rect(0, 0, 40, 20)));
        assert!(!line.holds(&rect(0, 0, 41, 20)));
        assert!(!line.holds(&rect(0, -1, 40, 20)));
    }
}
