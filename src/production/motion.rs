//! Motion blur in production (SPEC.md §15.3): every spatial sample of a
//! pixel tested at its N instants against each moving primitive, each test
//! decided exactly in fixed point.
//!
//! Every instant of §15.3 is τ = t/2^32 for an integer t ≤ 2^32. A vertex at
//! τ is (1 − τ)·A + τ·B, A and B its positions snapped at shutter open and
//! close by production's own snapping ([`super::place`]), so 2^32 times it,
//! (2^32 − t)·A + t·B = 2^32·A + t·(B − A), is an integer in units of
//! 2^-(f+32) px at the fixed-point format of f fraction bits: the primitive
//! at τ exactly, snapped at its ends only. A test then decides the sample
//! as the static path decides one (`setup::setup_in`, SPEC.md §3): nothing
//! at zero area, the cull applied to the winding at τ, each edge's cross
//! product with the sample positive, or zero on an edge that owns it by
//! production's [`setup::edge_owned`] on the edge's direction at τ. A moving
//! `parallelogram` line is its two triangles at τ with the minor axis of
//! its direction at τ, as `line::parallelogram` builds them (SPEC.md §4.4).
//!
//! Triangles in formats of up to [`FAST_MAX_FRAC_BITS`] fraction bits (12
//! subpixel bits) take a faster road to the same integers: each edge
//! function at a sample, and twice the area, is a quadratic in τ
//! ([`Quadratic`]), set up once per sample and evaluated exactly at each of
//! its instants, about 3× faster than placing the vertices at every
//! instant. Finer triangles, and parallelograms, place their vertices at
//! each instant and compare products in 256 bits where i128 does not hold
//! them.
//!
//! Static primitives of a moving scene are drawn once, by production's
//! static path at the same spatial samples ([`super::draw_frame`]), and a
//! sample one covers counts as covered at all N instants: the frame's
//! [`SampleTests`] counts the tests of moving primitives alone. A moving
//! primitive is tested only at samples inside its swept bounding box, the
//! box of its positions at shutter open and close, which holds it at every
//! instant between (each vertex moves on a segment).
//!
//! What this module does not do: moving polygons and moving lines of the
//! other rules (the case reader refuses them, SPEC.md §15.1), and values
//! (a moving scene has no depth or attributes).

use std::cmp::Ordering;
use std::ops::Range;

use rayon::prelude::*;

use super::antialias::{Samples, Sampling};
use super::fixed::{Fixed, Format, MAX_FRAC_BITS};
use super::{draw_frame, format_for, place, setup};
use crate::frame::{Frame, SampleTests};
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::rules::limits;
use crate::scene::{Canvas, Cull, FillRule, LineRule, MotionBlur, Primitive, Scene, Vertex};

/// Fraction bits of an instant: τ = t/2^TIME_BITS. The shutter's ends are
/// multiples of 2^-16 and an instant adds (close − open)·u/2^16 with u below
/// 2^16 (`MotionBlur::instant`).
const TIME_BITS: u32 = 2 * crate::scene::time::limits::TIME_BITS;

/// Bits of any difference a test takes, in pixels. A vertex lies within
/// 2^15 px of the origin at both ends of the shutter, so at every instant;
/// a parallelogram's corner at most width/2 ≤ 2^9 px further; a sample on
/// the canvas within 2^14 px. Two such points are less than 2^17 px apart.
const DIFF_PX_BITS: u32 = 17;
const _: () = assert!(2 * (limits::COORD_LIMIT + limits::MAX_LINE_WIDTH / 2) <= 1 << DIFF_PX_BITS);
const _: () = assert!((limits::MAX_CANVAS_SIDE as i64) <= limits::COORD_LIMIT);

/// Bits of such a difference in units of 2^-(f+32) px, f ≤ MAX_FRAC_BITS:
/// 66, held in i128 with room (and so are the positions themselves).
const DIFF_BITS: u32 = DIFF_PX_BITS + MAX_FRAC_BITS + TIME_BITS;
const _: () = assert!(DIFF_BITS <= 126);

// A product of two differences needs 2·DIFF_BITS = 132 bits at the finest
// format: it fits i128 (below 2^127) only when f ≤ 14 (2(17 + f + 32) ≤ 126).
// A cross product's sign is the comparison of its two products, so no
// difference of products is ever formed: each product is taken in i128
// where `checked_mul` says it fits, in 256 bits otherwise, and every format
// of the case reader is drawn.
const _: () = assert!(2 * DIFF_BITS < 255);

/// A point: 2^32 times a position at an instant, in units of 2^-(f+32) px,
/// or on the fast path ([`Fast`]) a position in units of 2^-f px.
type Point = [i128; 2];

#[inline]
fn sub(a: Point, b: Point) -> Point {
    [a[0] - b[0], a[1] - b[1]]
}

/// a·b exactly, as the high (signed) and low halves of its 256-bit two's
/// complement form: the pairs compare as the products do.
fn wide_product(a: i128, b: i128) -> (i128, u128) {
    const LOW: u128 = u64::MAX as u128;
    let (x, y) = (a.unsigned_abs(), b.unsigned_abs());
    let (x1, x0) = (x >> 64, x & LOW);
    let (y1, y0) = (y >> 64, y & LOW);
    let (p00, p01, p10, p11) = (x0 * y0, x0 * y1, x1 * y0, x1 * y1);
    let mid = (p00 >> 64) + (p01 & LOW) + (p10 & LOW);
    let low = (p00 & LOW) | (mid << 64);
    // |a|, |b| ≤ 2^127, so |a·b| ≤ 2^254 and the high half is below 2^127.
    let high = (p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64)) as i128;
    match ((a < 0) != (b < 0), low) {
        (false, _) => (high, low),
        // −(h·2^128 + l) = (−h − 1)·2^128 + (2^128 − l) for l > 0.
        (true, 0) => (-high, 0),
        (true, _) => (-high - 1, low.wrapping_neg()),
    }
}

/// The sign of the cross product u × v = u.x·v.y − u.y·v.x, as the
/// comparison of its two products.
#[inline]
fn cross_sign(u: Point, v: Point) -> Ordering {
    match (u[0].checked_mul(v[1]), u[1].checked_mul(v[0])) {
        (Some(p), Some(q)) => p.cmp(&q),
        _ => wide_product(u[0], v[1]).cmp(&wide_product(u[1], v[0])),
    }
}

/// Whether the edge a→b of a clockwise triangle owns the samples on it:
/// production's own rule, which reads only the signs of the edge's
/// direction.
fn edge_owned(a: Point, b: Point, rule: FillRule) -> bool {
    let sign = |k: usize| Fixed((b[k] - a[k]).signum() as i64);
    setup::edge_owned([Fixed(0), Fixed(0)], [sign(0), sign(1)], rule)
}

/// Whether the triangle `p` (one instant's vertices, in the case's order)
/// covers the sample `q`, as the static setup decides: nothing at zero area
/// or when the winding is culled; then, walked clockwise, every edge's
/// cross product with the sample is positive, or zero on an edge that
/// `owned(a, b)` gives the sample.
#[inline]
fn triangle_covers(
    p: [Point; 3],
    q: Point,
    cull: Cull,
    owned: impl Fn(Point, Point) -> bool,
) -> bool {
    let clockwise = match cross_sign(sub(p[1], p[0]), sub(p[2], p[0])) {
        Ordering::Equal => return false,
        o => o == Ordering::Greater,
    };
    match cull {
        Cull::Clockwise if clockwise => return false,
        Cull::CounterClockwise if !clockwise => return false,
        _ => {}
    }
    let order = if clockwise { p } else { [p[0], p[2], p[1]] };
    (0..3).all(|i| {
        let (a, b) = (order[i], order[(i + 1) % 3]);
        match cross_sign(sub(b, a), sub(q, a)) {
            Ordering::Greater => true,
            Ordering::Equal => owned(a, b),
            Ordering::Less => false,
        }
    })
}

/// The finest format whose triangles take the fast test ([`Quadratic`]).
///
/// At format f a vertex lies within 2^15 px of the origin and a sample on
/// the canvas in [0, 2^14] px, so in units of 2^-f an edge D or a vertex to
/// a sample R is below 2^(16+f) per axis, a velocity V below 2^(16+f) and a
/// difference of velocities W below 2^(17+f); a cross product |u × w| is at
/// most 2·|u|·|w|. An edge function's coefficients (below) are then under
/// 2^(33+2f), 2^(35+2f) and 2^(34+2f), twice the area's under 2^(33+2f),
/// 2^(35+2f) and 2^(35+2f), and with t ≤ 2^32 each scaled value
/// 2^64·q0 + 2^32·t·q1 + t²·q2 is below 2^(64+2f)·(2^33 + 2^35 + 2^35),
/// under 2^(100+2f): in i128 for f ≤ 13.
const FAST_MAX_FRAC_BITS: u32 = 13;
const _: () = assert!(100 + 2 * FAST_MAX_FRAC_BITS <= 126);
const _: () = assert!(limits::COORD_LIMIT == 1 << 15 && limits::MAX_CANVAS_SIDE <= 1 << 14);

/// q(τ) = q0 + q1·τ + q2·τ², held as its coefficients: an edge function at
/// one sample, or twice a triangle's area, as a vertex moves linearly. Its
/// sign at τ = t/2^32 is that of 2^64·q(τ) = 2^32·(2^32·q0 + t·q1) + t²·q2,
/// an exact integer.
#[derive(Clone, Copy, Debug)]
struct Quadratic([i128; 3]);

impl Quadratic {
    #[inline]
    fn sign_at(&self, t: i128, t2: i128) -> Ordering {
        let [q0, q1, q2] = self.0;
        ((((q0 << TIME_BITS) + t * q1) << TIME_BITS) + t2 * q2).cmp(&0)
    }
}

/// The cross product u × w in i128 (the fast path's small values).
#[inline]
fn cross(u: Point, w: Point) -> i128 {
    u[0] * w[1] - u[1] * w[0]
}

/// A moving triangle in a format of at most [`FAST_MAX_FRAC_BITS`]: each
/// edge function at a sample is a [`Quadratic`] in τ whose τ² coefficient
/// does not depend on the sample, so a sample's three quadratics are set up
/// once for its N instants, and a test evaluates them.
#[derive(Clone, Debug)]
struct Fast {
    /// Each vertex at τ = 0 (units of 2^-f) and its motion to τ = 1.
    a: [Point; 3],
    v: [Point; 3],
    /// Twice the area, and its sign when that never changes (the area is
    /// then constant: a translation, say).
    area: Quadratic,
    fixed: Option<Ordering>,
    /// −W × V of each edge i → i + 1 (vertices in the case's order).
    c2: [i128; 3],
    cull: Cull,
}

impl Fast {
    fn new(ends: [[[i64; 2]; 2]; 3], cull: Cull) -> Fast {
        let a = ends.map(|[a, _]| a.map(i128::from));
        let v = ends.map(|[a, b]| [0, 1].map(|k| i128::from(b[k]) - i128::from(a[k])));
        let (d1, d2) = (sub(a[1], a[0]), sub(a[2], a[0]));
        let (w1, w2) = (sub(v[1], v[0]), sub(v[2], v[0]));
        let area = Quadratic([cross(d1, d2), cross(d1, w2) + cross(w1, d2), cross(w1, w2)]);
        let fixed = (area.0[1] == 0 && area.0[2] == 0).then(|| area.0[0].cmp(&0));
        let c2 = [0, 1, 2].map(|i| -cross(sub(v[(i + 1) % 3], v[i]), v[i]));
        Fast {
            a,
            v,
            area,
            fixed,
            c2,
            cull,
        }
    }

    /// The edge functions i → i + 1 at the sample q (units of 2^-f):
    /// (D + τW) × (R − τV) = D × R + τ·(W × R − D × V) − τ²·(W × V), with
    /// D and W the edge and its motion, R = q − a_i and V = v_i.
    fn edges_at(&self, q: Point) -> [Quadratic; 3] {
        [0, 1, 2].map(|i| {
            let j = (i + 1) % 3;
            let (d, w) = (sub(self.a[j], self.a[i]), sub(self.v[j], self.v[i]));
            let r = sub(q, self.a[i]);
            Quadratic([cross(d, r), cross(w, r) - cross(d, self.v[i]), self.c2[i]])
        })
    }

    /// [`triangle_covers`] from the quadratics: the winding at τ (zero
    /// area covers nothing; the cull), then each edge walked clockwise, an
    /// edge of a counter-clockwise triangle reversed (its function negated,
    /// its direction turned round).
    #[inline]
    fn covers(&self, edges: &[Quadratic; 3], t: i128, rule: FillRule) -> bool {
        let t2 = t * t;
        let clockwise = match self.fixed.unwrap_or_else(|| self.area.sign_at(t, t2)) {
            Ordering::Equal => return false,
            o => o == Ordering::Greater,
        };
        match self.cull {
            Cull::Clockwise if clockwise => return false,
            Cull::CounterClockwise if !clockwise => return false,
            _ => {}
        }
        (0..3).all(|i| {
            let sign = edges[i].sign_at(t, t2);
            match if clockwise { sign } else { sign.reverse() } {
                Ordering::Greater => true,
                Ordering::Less => false,
                Ordering::Equal => {
                    // 2^32 times the edge's direction at τ, walked clockwise.
                    let j = (i + 1) % 3;
                    let d = [0, 1].map(|k| {
                        ((self.a[j][k] - self.a[i][k]) << TIME_BITS)
                            + t * (self.v[j][k] - self.v[i][k])
                    });
                    let d = if clockwise { d } else { d.map(|c| -c) };
                    edge_owned([0, 0], d, rule)
                }
            }
        })
    }
}

/// A moving primitive's vertices: 2^32 times each at shutter open of the
/// case (τ = 0), and its motion to τ = 1, B − A; at instant t the vertex is
/// `from + t·velocity`.
#[derive(Clone, Debug)]
struct Path<const K: usize> {
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
enum Shape {
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
struct Mover {
    shape: Shape,
    /// Fraction bits of its format above the scene's (a parallelogram may
    /// need a finer one for half its width): what a sample is shifted by.
    shift: u32,
    /// Its swept bounding box, closed, in its own units of 2^-(f+32) px.
    lo: Point,
    hi: Point,
    /// The pixels that may hold a sample in the box, clipped to the canvas.
    columns: Range<i64>,
    rows: Range<i64>,
}

impl Mover {
    fn new(
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
    fn sample(&self, q: [i64; 2]) -> Point {
        q.map(|c| i128::from(c) << self.shift)
    }

    /// Whether the sample (this primitive's format) lies in the swept
    /// bounding box: elsewhere the primitive covers it at no instant of the
    /// shutter.
    #[inline]
    fn sweeps(&self, q: Point) -> bool {
        (0..2).all(|k| self.lo[k] <= q[k] << TIME_BITS && q[k] << TIME_BITS <= self.hi[k])
    }

    /// The sample `q` (this primitive's format) set up for its tests.
    fn probe(&self, q: Point) -> Probe<'_> {
        match &self.shape {
            Shape::Fast(fast) => Probe::Fast(fast, fast.edges_at(q)),
            _ => Probe::Exact(self, q.map(|c| c << TIME_BITS)),
        }
    }

    /// Whether the primitive covers the sample `q` (units of 2^-(f+32)) at
    /// instant t/2^32, from its positions at t.
    fn covers(&self, q: Point, t: i128, rule: FillRule) -> bool {
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
enum Probe<'a> {
    Fast(&'a Fast, [Quadratic; 3]),
    /// The sample in units of 2^-(f+32).
    Exact(&'a Mover, Point),
}

impl Probe<'_> {
    /// Whether the primitive covers the sample at instant t/2^32: one test.
    #[inline]
    fn covers(&self, t: i128, rule: FillRule) -> bool {
        match self {
            Probe::Fast(fast, edges) => fast.covers(edges, t, rule),
            Probe::Exact(mover, q) => mover.covers(*q, t, rule),
        }
    }
}

/// A moving scene ready to be sampled in time: its frame, and each test's
/// decision on its own for tests of production.
#[derive(Clone, Debug)]
pub struct Sampler {
    canvas: Canvas,
    blur: MotionBlur,
    format: Format,
    rule: FillRule,
    /// Each spatial sample's offset from its pixel's top-left corner in
    /// `format`: the plan's antialiasing offsets, or the pixel centre.
    offsets: Vec<[i64; 2]>,
    movers: Vec<Mover>,
    /// How many static primitives cover each spatial sample (sample s of
    /// pixel p at p·M + s), drawn once; `None` when every primitive moves.
    statics: Option<Vec<u16>>,
}

/// Production's frame of a scene in which something moves (`plan.motion`):
/// each pixel's time coverage, and the sample tests spent on moving
/// primitives.
pub fn rasterize(scene: &Scene, plan: &Plan, sampling: Sampling) -> Result<Frame, RasterError> {
    Ok(Sampler::new(scene, plan, sampling)?.frame())
}

impl Sampler {
    /// Sets up every moving primitive and draws the static ones. `sampling`
    /// decides the static primitives' antialiased samples, as in production's
    /// static path.
    pub fn new(scene: &Scene, plan: &Plan, sampling: Sampling) -> Result<Sampler, RasterError> {
        let motion = plan.motion.as_ref().ok_or_else(|| {
            RasterError::Failed("the time loop needs a plan with motion".to_owned())
        })?;
        if motion.moving.len() != scene.primitives.len() {
            return Err(RasterError::Failed(
                "the plan's moving primitives are not the scene's".to_owned(),
            ));
        }
        if scene.rules.subpixel_bits.is_none() {
            return Err(RasterError::Unsupported(
                "moving vertices snap at shutter open and close: a moving scene needs \
                 subpixel_bits"
                    .to_owned(),
            ));
        }
        let samples = plan
            .antialias
            .as_ref()
            .map(|plan| Samples { plan, sampling });
        let format = format_for(scene, samples.as_ref())?;
        let offsets = match &samples {
            Some(samples) => samples.offsets_in(format),
            None => vec![[format.one() / 2; 2]],
        };
        let movers = scene
            .primitives
            .iter()
            .zip(&motion.moving)
            .filter(|(_, &moving)| moving)
            .map(|(p, _)| Mover::new(scene, p, format, &motion.blur))
            .collect::<Result<Vec<_>, _>>()?;
        let statics = if motion.moving.iter().all(|&m| m) {
            None
        } else {
            let once = Plan {
                motion: None,
                ..plan.clone()
            };
            let frame = draw_frame(scene, &once, sampling, |i| !motion.moving[i])?;
            debug_assert_eq!(frame.samples as usize, offsets.len());
            Some(frame.coverage)
        };
        Ok(Sampler {
            canvas: scene.canvas,
            blur: motion.blur.clone(),
            format,
            rule: scene.rules.fill_rule,
            offsets,
            movers,
            statics,
        })
    }

    /// M: spatial samples per pixel.
    pub fn spatial_samples(&self) -> usize {
        self.offsets.len()
    }

    /// N: time samples per spatial sample.
    pub fn time_samples(&self) -> usize {
        self.blur.samples as usize
    }

    fn pixel_index(&self, x: i64, y: i64) -> usize {
        y as usize * self.canvas.width as usize + x as usize
    }

    /// Static primitives covering spatial sample `s` of pixel `p`.
    fn statics(&self, p: usize, s: usize) -> u32 {
        self.statics
            .as_ref()
            .map_or(0, |c| u32::from(c[p * self.offsets.len() + s]))
    }

    /// Spatial sample `s` of pixel (x, y) in the scene's format.
    fn sample_at(&self, x: i64, y: i64, s: usize) -> [i64; 2] {
        let one = self.format.one();
        let [ox, oy] = self.offsets[s];
        [x * one + ox, y * one + oy]
    }

    /// The pixel's u (SPEC.md §15.3), slot s·N + k for instant k of
    /// spatial sample s; its instant is `blur.instant(u)`/2^32.
    fn times(&self, x: i64, y: i64) -> Vec<u32> {
        let p = self.pixel_index(x, y) as u64;
        self.blur.pixel_times(p, self.offsets.len() as u32)
    }

    /// How many primitives cover spatial sample `s` of pixel (x, y) at the
    /// instant `instant`/2^32 (at most 2^32, any instant, inside the shutter
    /// or not): each moving primitive tested there, with no bounding box,
    /// plus the static ones. One test of the time loop, open to tests of
    /// production against the static rules at that instant.
    pub fn coverage_at(&self, x: u32, y: u32, s: usize, instant: u64) -> u32 {
        assert!(instant <= 1 << TIME_BITS, "an instant in [0, 1]");
        let (x, y) = (i64::from(x), i64::from(y));
        let q = self.sample_at(x, y, s);
        let moving = self
            .movers
            .iter()
            .filter(|m| m.probe(m.sample(q)).covers(i128::from(instant), self.rule))
            .count();
        moving as u32 + self.statics(self.pixel_index(x, y), s)
    }

    /// Pixel (x, y)'s tests as the time loop makes them: slot j = s·N + k
    /// holds how many primitives cover spatial sample s at the pixel's j-th
    /// instant, static ones included. The frame's time coverage of the
    /// pixel is their sum over M·N.
    pub fn slot_counts(&self, x: u32, y: u32) -> Vec<u32> {
        let (x, y) = (i64::from(x), i64::from(y));
        let n = self.time_samples();
        let p = self.pixel_index(x, y);
        let mut slots: Vec<u32> = (0..self.offsets.len() * n)
            .map(|j| self.statics(p, j / n))
            .collect();
        let movers: Vec<&Mover> = self.movers.iter().collect();
        self.test_pixel(x, y, &movers, &mut SampleTests::default(), |j| {
            slots[j] += 1
        });
        slots
    }

    /// Runs the tests of pixel (x, y) against `movers` (those whose rows
    /// hold it), counting them in `tests`; `hit(j)` for each covered one,
    /// j its slot.
    fn test_pixel(
        &self,
        x: i64,
        y: i64,
        movers: &[&Mover],
        tests: &mut SampleTests,
        mut hit: impl FnMut(usize),
    ) {
        let n = self.time_samples();
        let mut times: Option<Vec<u32>> = None;
        for mover in movers.iter().filter(|m| m.columns.contains(&x)) {
            for s in 0..self.offsets.len() {
                let q = mover.sample(self.sample_at(x, y, s));
                if !mover.sweeps(q) {
                    continue;
                }
                let times = times.get_or_insert_with(|| self.times(x, y));
                let probe = mover.probe(q);
                for (k, &u) in times[s * n..(s + 1) * n].iter().enumerate() {
                    tests.tests += 1;
                    if probe.covers(i128::from(self.blur.instant(u)), self.rule) {
                        tests.covered += 1;
                        hit(s * n + k);
                    }
                }
            }
        }
    }

    /// The frame: each pixel's time coverage, (N·static hits + covered
    /// tests)/(M·N), one exact quotient of integers rounded once, rows in
    /// parallel on the current rayon pool.
    pub fn frame(&self) -> Frame {
        let (width, height) = (self.canvas.width, self.canvas.height);
        let (m, n) = (self.offsets.len() as u64, self.time_samples() as u64);
        let mut time = vec![0.0; self.canvas.pixel_count()];
        let tests = time
            .par_chunks_mut(width.max(1) as usize)
            .enumerate()
            .map(|(y, row)| {
                let y = y as i64;
                let movers: Vec<&Mover> =
                    self.movers.iter().filter(|m| m.rows.contains(&y)).collect();
                let mut tests = SampleTests::default();
                for (x, value) in row.iter_mut().enumerate() {
                    let x = x as i64;
                    let p = self.pixel_index(x, y);
                    let still: u64 = (0..m as usize).map(|s| u64::from(self.statics(p, s))).sum();
                    let mut covered = 0u64;
                    self.test_pixel(x, y, &movers, &mut tests, |_| covered += 1);
                    *value = (still * n + covered) as f64 / (m * n) as f64;
                }
                tests
            })
            .reduce(SampleTests::default, |a, b| SampleTests {
                tests: a.tests + b.tests,
                covered: a.covered + b.covered,
            });
        let mut frame = Frame::time_only(width, height, time);
        frame.sample_tests = Some(tests);
        frame
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wide_products_order_as_the_products() {
        let values = [
            0i128,
            1,
            -1,
            3,
            -7,
            1 << 63,
            -(1 << 64) + 5,
            (1 << 100) + 12345,
            -(1 << 110),
            i128::MAX,
            i128::MIN + 1,
            i128::MIN,
        ];
        for &a in &values {
            for &b in &values {
                if let Some(p) = a.checked_mul(b) {
                    let low = p as u128;
                    let high = if p < 0 { -1 } else { 0 };
                    assert_eq!(wide_product(a, b), (high, low), "{a}·{b}");
                }
                for &c in &values {
                    for &d in &values {
                        let want = match (a.checked_mul(b), c.checked_mul(d)) {
                            (Some(p), Some(q)) => p.cmp(&q),
                            _ => continue,
                        };
                        assert_eq!(wide_product(a, b).cmp(&wide_product(c, d)), want);
                    }
                }
            }
        }
        // Beyond i128: 2^127 · 2^127 = 2^254, and its negation.
        assert_eq!(wide_product(i128::MIN, i128::MIN), (1 << 126, 0));
        // 2^127·(2^127 − 1) = (2^126 − 1)·2^128 + 2^127, negated.
        assert_eq!(wide_product(i128::MIN, i128::MAX), (-(1 << 126), 1 << 127));
        assert!(wide_product(1 << 100, 1 << 30) > wide_product((1 << 100) - 1, 1 << 30));
        assert!(wide_product(-(1 << 100), 1 << 30) < wide_product(-(1 << 100) + 1, 1 << 30));
    }

    /// The fast path's bound, tried at its corners: at FAST_MAX_FRAC_BITS,
    /// vertices at the coordinate limits moving from one limit to the
    /// other, samples at the canvas's corners and t up to 2^32, every
    /// intermediate of every quadratic's evaluation is computed with
    /// checked arithmetic and fits.
    #[test]
    fn fast_quadratics_fit_at_their_finest_format() {
        let f = FAST_MAX_FRAC_BITS;
        let limit = limits::COORD_LIMIT << f;
        let side = i64::from(limits::MAX_CANVAS_SIDE) << f;
        let corners = [-limit, limit];
        let checked = |q: &Quadratic, t: i128| -> Option<i128> {
            let [q0, q1, q2] = q.0;
            let inner = q0
                .checked_mul(1 << TIME_BITS)?
                .checked_add(t.checked_mul(q1)?)?;
            inner
                .checked_mul(1 << TIME_BITS)?
                .checked_add((t * t).checked_mul(q2)?)
        };
        let mut tried = 0;
        for bits in 0..1u32 << 12 {
            let c = |k: u32| corners[(bits >> k & 1) as usize];
            let ends = [0, 4, 8].map(|k| [[c(k), c(k + 1)], [c(k + 2), c(k + 3)]]);
            let fast = Fast::new(ends, Cull::None);
            for q in [[0, 0], [side, 0], [0, side], [side, side]] {
                let edges = fast.edges_at(q.map(i128::from));
                for t in [0, 1 << 31, (1 << 32) - 1, 1 << 32] {
                    for quadratic in edges.iter().chain([&fast.area]) {
                        assert!(checked(quadratic, t).is_some(), "{ends:?} {q:?} {t}");
                        tried += 1;
                    }
                }
            }
        }
        assert_eq!(tried, 4096 * 4 * 4 * 4);
    }

    /// The sign of a cross product beyond i128 (at 16 subpixel bits and
    /// coordinates near the limit) agrees with an exact big-integer one.
    #[test]
    fn cross_signs_beyond_i128_are_exact() {
        use dashu_int::IBig;
        let mut state = 0x1234_5678_9abc_def0u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let bound = 1i128 << DIFF_BITS;
        let mut wide = 0;
        for round in 0..20_000 {
            let mut draw = || {
                let r = (i128::from(next()) << 64 | i128::from(next())).rem_euclid(2 * bound);
                r - bound
            };
            let mut u = [draw(), draw()];
            let v = [draw(), draw()];
            if round % 3 == 0 {
                // Parallel, or nearly: the two products tie or differ by little.
                u = [v[0] * 3 / 5, v[1] * 3 / 5 + i128::from(round % 2)];
            }
            let big = |a: i128| IBig::from(a);
            let exact = (big(u[0]) * big(v[1]) - big(u[1]) * big(v[0])).cmp(&IBig::ZERO);
            assert_eq!(cross_sign(u, v), exact, "{u:?} × {v:?}");
            wide += usize::from(u[0].checked_mul(v[1]).is_none());
        }
        assert!(wide > 1000, "{wide} products beyond i128");
    }
}
