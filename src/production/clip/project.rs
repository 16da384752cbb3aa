//! From clip coordinates to the homogeneous screen points that
//! rasterization tests (SPEC.md §16.1, §16.4): the divide, the viewport and
//! the snap for a vertex in front of the eye (w > 0), and the undivided
//! homogeneous point for one on or behind it (w ≤ 0), which is never
//! divided.
//!
//! Per-primitive set-up, so exact rationals: a snapped coordinate is the
//! exact x_f rounded once, to nearest-even, as every position is (§2).

use dashu_ratio::RBig;

use super::clipper::ClipVertex;
use crate::scene::{Number, Viewport};

/// A vertex as rasterization sees it: the homogeneous screen point H and
/// the weight k > 0 its clip z and attributes are scaled by (§16.4).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Projected {
    /// (X, Y, 1) with (X, Y) the snapped (x_f, y_f) when w > 0; the exact
    /// (w·vx + (vw/2)(w + x), w·vy + (vh/2)(w + y), w) when w ≤ 0.
    pub h: [RBig; 3],
    /// 1/w when w > 0, 1 otherwise.
    pub k: RBig,
}

impl Projected {
    /// Whether the vertex is in front of the eye, divided and snapped (a
    /// vertex with w ≤ 0 has H's third coordinate w ≤ 0, never 1).
    pub fn in_front(&self) -> bool {
        self.h[2] == RBig::ONE
    }
}

/// The viewport as exact rationals.
#[derive(Clone, Debug)]
pub struct Mapping {
    pub x: RBig,
    pub y: RBig,
    pub width: RBig,
    pub height: RBig,
    pub min_depth: RBig,
    pub max_depth: RBig,
    /// `subpixel_bits`: `None` keeps x_f and y_f exact.
    pub bits: Option<u32>,
    /// `depth: clamp` or `interpolate_from: unsnapped`: each sample's
    /// depth is clamped to the depth range.
    pub clamp: bool,
}

impl Mapping {
    pub fn new(viewport: &Viewport, bits: Option<u32>, clamp: bool) -> Mapping {
        let r = |n: &Number| n.as_rbig().clone();
        Mapping {
            x: r(&viewport.x),
            y: r(&viewport.y),
            width: r(&viewport.width),
            height: r(&viewport.height),
            min_depth: r(&viewport.min_depth),
            max_depth: r(&viewport.max_depth),
            bits,
            clamp,
        }
    }

    /// The vertex's homogeneous screen point and weight.
    pub fn project(&self, v: &ClipVertex) -> Projected {
        let [x, y, _, w] = &v.clip;
        let half = RBig::from_parts(1.into(), 2u8.into());
        if *w > RBig::ZERO {
            let screen = |origin: &RBig, size: &RBig, c: &RBig| {
                self.snap(origin + size * (c / w + RBig::ONE) * &half)
            };
            Projected {
                h: [
                    screen(&self.x, &self.width, x),
                    screen(&self.y, &self.height, y),
                    RBig::ONE,
                ],
                k: RBig::ONE / w,
            }
        } else {
            let point = |origin: &RBig, size: &RBig, c: &RBig| w * origin + size * &half * (w + c);
            Projected {
                h: [
                    point(&self.x, &self.width, x),
                    point(&self.y, &self.height, y),
                    w.clone(),
                ],
                k: RBig::ONE,
            }
        }
    }

    /// x_f or y_f on the snapping grid, or exact without one.
    fn snap(&self, value: RBig) -> RBig {
        match self.bits {
            Some(bits) => Number::from_rbig(value).snapped(bits).as_rbig().clone(),
            None => value,
        }
    }

    /// Depth z_f = min_depth + (max_depth − min_depth)·z_ndc (§16.1).
    pub fn depth(&self, z_ndc: &RBig) -> RBig {
        &self.min_depth + (&self.max_depth - &self.min_depth) * z_ndc
    }

    /// The depth range, low end first: what `depth: clamp` clamps to.
    pub fn depth_range(&self) -> [RBig; 2] {
        if self.min_depth <= self.max_depth {
            [self.min_depth.clone(), self.max_depth.clone()]
        } else {
            [self.max_depth.clone(), self.min_depth.clone()]
        }
    }

    /// The pixels whose centres lie in the viewport rectangle
    /// [x, x + width) × [y, y + height), half-open: pixel i's centre
    /// i + 1/2 ≥ x from i = ⌈x − 1/2⌉ on, and < x + width up to
    /// ⌈x + width − 1/2⌉ excluded.
    pub fn pixel_rectangle(&self) -> [[i64; 2]; 2] {
        let half = RBig::from_parts(1.into(), 2u8.into());
        let range = |origin: &RBig, size: &RBig| {
            [origin - &half, origin + size - &half].map(|e| clamp_i64(e.ceil()))
        };
        [range(&self.x, &self.width), range(&self.y, &self.height)]
    }
}

/// An integer clamped into i64 (pixel indices far off the canvas stay far
/// off it).
pub fn clamp_i64(n: dashu_int::IBig) -> i64 {
    const FAR: i64 = 1 << 40;
    i64::try_from(&n).map_or(if n > dashu_int::IBig::ZERO { FAR } else { -FAR }, |v| {
        v.clamp(-FAR, FAR)
    })
}
