//! A moving primitive ready to be tested: its path from shutter open to
//! close, its swept bounding box, and one sample's tests at any instant
//! (the fast quadratic road, or exact placing at each instant).

use std::ops::Range;

use super::exact::{edge_owned, sub, triangle_covers, Point, TIME_BITS};
use super::fast::{Fast, Quadratic, FAST_MAX_FRAC_BITS};
use crate::production::fixed::{Format, MAX_FRAC_BITS};
use crate::production::scene_format::place;
use crate::rasterizer::RasterError;
use crate::scene::{Cull, FillRule, LineRule, MotionBlur, Primitive, Scene, Vertex};

/// A moving primitive's vertices: 2^32 times each at shutter open of the
/// case (τ = 0), and its motion to τ = 1, B − A; at instant t the vertex is
/// `from + t·velocity`.
#[derive(Clone, Debug)]
pub(super) struct Path<const K: usize> {
    from: [Point; K],
    velocity: [Point; K],
}

impl<const K: usize> Path<K> {
    /// `ends[i]` holds vertex i snapped at τ = 0 and τ = 1.
    fn new(ends: [[[i64; 2]; 2]; K]) -> Path<K> {
        Path {
            from: ends.map(|[a, _]| a.map(|c| i128::from(c) << TIME_BITS)),
            velocity: ends.map(|[a, b]| [0, 1].map(|k| i128::from(b[k]) - i128::from(a[k]))),
        }
    }

    #[inline]
    fn at(&self, t: i128) -> [Point; K] {
        std::array::from_fn(|i| [0, 1].map(|k| self.from[i][k] + t * self.velocity[i][k]))
    }
}

#[derive(Clone, Debug)]
pub(super) enum Shape {
    /// A triangle in a format of at most [`FAST_MAX_FRAC_BITS`].
    Fast(Box<Fast>),
    /// Any triangle, its positions at each instant compared in 256 bits
    /// where i128 does not hold the products.
    Triangle { path: Path<3>, cull: Cull },
    /// A `parallelogram` line: its two ends, and 2^32 times half its width.
    Parallelogram { path: Path<2>, half: i128 },
}

/// A moving primitive ready to be tested.
#[derive(Clone, Debug)]
pub(super) struct Mover {
    pub(super) shape: Shape,
    /// Fraction bits of its format above the scene's (a parallelogram may
    /// need a finer one for half its width): what a sample is shifted by.
    pub(super) shift: u32,
    /// Its swept bounding box, closed, in its own units of 2^-(f+32) px.
    pub(super) lo: Point,
    pub(super) hi: Point,
    /// The pixels that may hold a sample in the box, clipped to the canvas.
    pub(super) columns: Range<i64>,
    pub(super) rows: Range<i64>,
}

impl Mover {
    pub(super) fn new(
        scene: &Scene,
        primitive: &Primitive,
        format: Format,
        blur: &MotionBlur,
    ) -> Result<Mover, RasterError> {
        let ends = |v: &Vertex, shift: u32| -> [[i64; 2]; 2] {
            let [ex, ey] = v.end();
            [[&v.x, &v.y], [ex, ey]].map(|p| p.map(|c| place(scene, format, c).0 << shift))
        };
        // The shape; its vertices at τ = 0 and 1 and how far beyond them
        // it reaches, for the swept box.
        let (shape, shift, vertices, margin) = match primitive {
            Primitive::Triangle(t) => {
                let vertices = t.vertices.each_ref().map(|v| ends(v, 0));
                let shape = if format.frac_bits <= FAST_MAX_FRAC_BITS {
                    Shape::Fast(Box::new(Fast::new(vertices, scene.rules.cull)))
                } else {
                    Shape::Triangle {
                        path: Path::new(vertices),
                        cull: scene.rules.cull,
                    }
                };
                (shape, 0, vertices.to_vec(), 0)
            }
            Primitive::Line(line) if line.rule == LineRule::Parallelogram => {
                // As `line::parallelogram`: the first format, from the
                // scene's on, in which half the width is exact (width/2 in
                // units of 2^-f is width in units of 2^-(f − 1)).
                let (fine, half) = (format.frac_bits..=MAX_FRAC_BITS)
                    .find_map(|frac_bits| {
                        let half = Format {
                            frac_bits: frac_bits - 1,
                        }
                        .exact(&line.width)?;
                        Some((frac_bits, half.0))
                    })
                    .ok_or_else(|| {
                        RasterError::Unsupported(format!(
                            "a parallelogram line's corners need half its width in fixed \
                             point, and width {} is not a multiple of 2^-{}",
                            line.width.to_exact_string(),
                            MAX_FRAC_BITS - 1
                        ))
                    })?;
                let shift = fine - format.frac_bits;
                let vertices = line.vertices.each_ref().map(|v| ends(v, shift));
                let half = i128::from(half) << TIME_BITS;
                (
                    Shape::Parallelogram {
                        path: Path::new(vertices),
                        half,
                    },
                    shift,
                    vertices.to_vec(),
                    // The corners lie half the width from the ends along
                    // one axis or the other.
                    half,
                )
            }
            Primitive::Line(line) => {
                return Err(RasterError::Unsupported(format!(
                    "only parallelogram lines can move (SPEC.md §15.1); this is a {} line",
                    line.rule.name()
                )))
            }
            Primitive::Polygon(_) => {
                return Err(RasterError::Unsupported(
                    "polygons cannot move (SPEC.md §15.1)".to_owned(),
                ))
            }
            Primitive::Point(_) => {
                return Err(RasterError::Unsupported(
                    "points cannot move (SPEC.md §17)".to_owned(),
                ))
            }
        };
        // The box of every vertex at the shutter's two ends.
        let [open, close] =
            [0, crate::scene::time::limits::TIME_ONE].map(|u| i128::from(blur.instant(u)));
        let points: Vec<Point> = vertices
            .iter()
            .flat_map(|&[a, b]| {
                [open, close].map(|t| {
                    [0, 1].map(|k| {
                        (i128::from(a[k]) << TIME_BITS) + t * (i128::from(b[k]) - i128::from(a[k]))
                    })
                })
            })
            .collect();
        let lo = [0, 1].map(|k| points.iter().map(|p| p[k]).min().unwrap() - margin);
        let hi = [0, 1].map(|k| points.iter().map(|p| p[k]).max().unwrap() + margin);
        // A sample i·one + o with o in [0, one) lies in [lo, hi] only in
        // pixels ⌊lo/one⌋ to ⌊hi/one⌋.
        let one = 1i128 << (format.frac_bits + shift + TIME_BITS);
        let pixels = |k: usize, size: u32| {
            let first = lo[k].div_euclid(one).max(0);
            let last = hi[k].div_euclid(one).min(i128::from(size) - 1);
            (first as i64)..(last as i64 + 1).max(first as i64)
        };
        Ok(Mover {
            shape,
            shift,
            lo,
            hi,
            columns: pixels(0, scene.canvas.width),
            rows: pixels(1, scene.canvas.height),
        })
    }

    /// A sample given in the scene's format, in this primitive's format.
    #[inline]
    pub(super) fn sample(&self, q: [i64; 2]) -> Point {
        q.map(|c| i128::from(c) << self.shift)
    }

    /// Whether the sample (this primitive's format) lies in the swept
    /// bounding box: elsewhere the primitive covers it at no instant of the
    /// shutter.
    #[inline]
    pub(super) fn sweeps(&self, q: Point) -> bool {
        (0..2).all(|k| self.lo[k] <= q[k] << TIME_BITS && q[k] << TIME_BITS <= self.hi[k])
    }

    /// The sample `q` (this primitive's format) set up for its tests.
    pub(super) fn probe(&self, q: Point) -> Probe<'_> {
        match &self.shape {
            Shape::Fast(fast) => Probe::Fast(fast, fast.edges_at(q)),
            _ => Probe::Exact(self, q.map(|c| c << TIME_BITS)),
        }
    }

    /// Whether the primitive covers the sample `q` (units of 2^-(f+32)) at
    /// instant t/2^32, from its positions at t.
    pub(super) fn covers(&self, q: Point, t: i128, rule: FillRule) -> bool {
        match &self.shape {
            Shape::Fast(_) => unreachable!("fast triangles are probed"),
            Shape::Triangle { path, cull } => {
                triangle_covers(path.at(t), q, *cull, |a, b| edge_owned(a, b, rule))
            }
            Shape::Parallelogram { path, half } => {
                let [v0, v1] = path.at(t);
                let d = sub(v1, v0);
                if d == [0, 0] {
                    return false;
                }
                // x-major when |dx| ≥ |dy|: the corners lie along y.
                let minor = usize::from(d[0].abs() >= d[1].abs());
                let corner = |p: Point, sign: i128| {
                    let mut c = p;
                    c[minor] += sign * half;
                    c
                };
                let (a, b, c, e) = (corner(v0, -1), corner(v1, -1), corner(v1, 1), corner(v0, 1));
                // ABC or ACE. They share only the diagonal AC, and a sample
                // is covered once whichever covers it, so the static path's
                // care to give the diagonal to one of them (it counts
                // coverage per triangle) changes nothing here.
                let owned = |p: Point, q: Point| edge_owned(p, q, rule);
                triangle_covers([a, b, c], q, Cull::None, owned)
                    || triangle_covers([a, c, e], q, Cull::None, owned)
            }
        }
    }
}

/// One sample of one moving primitive, ready for its N tests.
pub(super) enum Probe<'a> {
    Fast(&'a Fast, [Quadratic; 3]),
    /// The sample in units of 2^-(f+32).
    Exact(&'a Mover, Point),
}

impl Probe<'_> {
    /// Whether the primitive covers the sample at instant t/2^32: one test.
    #[inline]
    pub(super) fn covers(&self, t: i128, rule: FillRule) -> bool {
        match self {
            Probe::Fast(fast, edges) => fast.covers(edges, t, rule),
            Probe::Exact(mover, q) => mover.covers(*q, t, rule),
        }
    }
}
