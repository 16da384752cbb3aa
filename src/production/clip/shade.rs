//! Depth and attributes at a covered sample of a clip-space triangle
//! (SPEC.md §16.5), and the per-sample depth test of `clip_z: per-sample`.
//!
//! With the σ-signed edge values E_i of [`Piece`] (G's units) and the
//! weights K_i = c_i·k_i:
//! - z_ndc = Σ E_i·K_i·z_i / |D'|, the per-sample test 0 ≤ z_ndc ≤ 1
//!   exact in integers;
//! - perspective a = Σ E_i·K_i·a_i / Σ E_i·K_i, whose denominator is a sum
//!   of non-negative terms at a covered sample (every E_i ≥ 0, K_i > 0);
//! - flat: the original triangle's provoking vertex's values.
//!
//! A piece whose vertices all have w > 0 is a screen-space triangle with
//! depth z_f and the same w (§16.7), and is shaded by the screen-space
//! path's own f32 set-up ([`Shading`]), so that it gives the very values
//! a screen-space triangle would. Any other piece takes the exact path:
//! each value an exact quotient of integers, rounded once to f64.

use dashu_int::ops::UnsignedAbs;
use dashu_int::IBig;
use dashu_ratio::RBig;

use super::clipper::ClipVertex;
use super::homogeneous::{lcm_of_denominators, EdgeValues, Piece};
use super::project::{Mapping, Projected};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::depth;
use crate::production::setup::{self, Shading};
use crate::scene::{DepthBias, DepthFormat, Interpolation, Number, Triangle, Vertex};

/// How a piece's values are found at a covered sample.
#[derive(Clone, Debug)]
pub struct Values {
    /// z_ndc = Σ E_i·depth[i] / depth_over, integers.
    depth: [IBig; 3],
    depth_over: IBig,
    /// `depth: clamp`: the depth range, exact and as f64.
    clamp: Option<[RBig; 2]>,
    /// Σ E_i·weight[i] (K_i times a common denominator): positive where
    /// the piece's plane lies in front of the eye, and the denominator of
    /// the exact path's perspective values.
    weight: [IBig; 3],
    /// The piece's polygon offset (SPEC.md §18.2), added before the clamp.
    offset: f64,
    how: How,
}

#[derive(Clone, Debug)]
enum How {
    /// The screen-space path's shading (all w > 0, i128 edge values).
    Screen(Shading),
    /// Exact quotients of integers.
    Exact { attributes: Vec<Attribute> },
    /// Coverage only.
    None,
}

#[derive(Clone, Debug)]
enum Attribute {
    Flat(f64),
    /// Σ E_i·numerator[i] / (Σ E_i·weight[i]) · ratio.
    Perspective {
        numerator: [IBig; 3],
        ratio: RBig,
    },
}

impl Values {
    /// Sets up the values of `piece`, whose vertices are `vertices`
    /// (projected as `h`); `flat` holds the original triangle's provoking
    /// vertex's attributes. `extrapolated`: the values are also read at
    /// samples outside the piece (the unsnapped piece of `interpolate_from:
    /// unsnapped`, read wherever its snapped twin covers), where the
    /// screen path's f32 set-up, bounded inside a triangle, is not: such a
    /// piece takes the exact path.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        piece: &Piece,
        h: &[Projected; 3],
        vertices: [&ClipVertex; 3],
        interpolation: Interpolation,
        flat: &[RBig],
        plan: &Plan,
        mapping: &Mapping,
        extrapolated: bool,
    ) -> Values {
        let weights: [RBig; 3] = [0, 1, 2].map(|i| &piece.scale[i] * &h[i].k);
        let (depth, q) = integers(&[0, 1, 2].map(|i| &weights[i] * &vertices[i].clip[2]));
        let clamp = mapping.clamp.then(|| mapping.depth_range());
        let (weight, q_weight) = integers(&weights);
        let how = if !plan.interpolates() {
            How::None
        } else if piece.in_front
            && !extrapolated
            && matches!(piece.edges, super::homogeneous::Edges::Small(_))
        {
            How::Screen(screen_shading(
                piece,
                vertices,
                interpolation,
                flat,
                plan,
                mapping,
            ))
        } else {
            let attributes = (0..plan.attributes)
                .map(|j| match interpolation {
                    Interpolation::Perspective => {
                        let (numerator, q_j) =
                            integers(&[0, 1, 2].map(|i| &weights[i] * &vertices[i].attributes[j]));
                        Attribute::Perspective {
                            numerator,
                            ratio: RBig::from(q_weight.clone()) / RBig::from(q_j),
                        }
                    }
                    _ => Attribute::Flat(flat[j].to_f64().value()),
                })
                .collect();
            How::Exact { attributes }
        };
        Values {
            depth,
            depth_over: IBig::from(q) * &piece.det,
            clamp,
            weight,
            offset: 0.0,
            how,
        }
    }

    /// Whether the piece's plane lies in front of the eye at the sample
    /// whose edge values are `e`: Σ E_i·K_i > 0 (at a sample the piece
    /// covers it always does).
    pub fn in_front(&self, e: &EdgeValues) -> bool {
        dot(&e.big(), &self.weight) > IBig::ZERO
    }

    /// These values with the piece's polygon offset under `bias`
    /// (SPEC.md §18.2): its plane's gradient exact, from the depth at three
    /// pixel centres, and its largest |z_f| at a vertex (every w > 0
    /// under an offset, the reader's rule).
    pub fn with_offset(
        mut self,
        bias: &DepthBias,
        format: DepthFormat,
        piece: &Piece,
        vertices: [&ClipVertex; 3],
        mapping: &Mapping,
    ) -> Values {
        let z_f = |px, py| {
            let z_ndc = quotient(
                dot(&piece.at(px, py).big(), &self.depth),
                self.depth_over.clone(),
            );
            mapping.depth(&z_ndc)
        };
        let origin = z_f(0, 0);
        let gradient = [z_f(1, 0), z_f(0, 1)].map(|z| (z - &origin).to_f64().value());
        let largest = vertices
            .iter()
            .map(|v| {
                mapping
                    .depth(&(&v.clip[2] / &v.clip[3]))
                    .to_f64()
                    .value()
                    .abs()
            })
            .fold(0.0, f64::max);
        self.offset = depth::offset(bias, format, gradient, largest);
        self
    }

    /// Whether the sample's exact z_ndc lies in [0, 1] (`clip_z:
    /// per-sample`): 0 ≤ Σ E_i·depth[i] ≤ depth_over.
    pub fn depth_inside(&self, e: &EdgeValues) -> bool {
        let n = dot(&e.big(), &self.depth);
        n >= IBig::ZERO && n <= self.depth_over
    }

    /// Writes depth and attributes at slot `i`.
    pub fn write(&self, frame: &mut Frame, i: usize, e: &EdgeValues, mapping: &Mapping) {
        match (&self.how, e) {
            (How::None, _) => return,
            (How::Screen(shading), EdgeValues::Small(v)) => shading.write::<i128>(frame, i, *v),
            (How::Screen(_), EdgeValues::Big(_)) => {
                unreachable!("the screen path is chosen for i128 edges only")
            }
            (How::Exact { attributes }, e) => {
                let e = e.big();
                if let Some(out) = frame.depth.as_mut() {
                    let z_ndc = quotient(dot(&e, &self.depth), self.depth_over.clone());
                    out[i] = mapping.depth(&z_ndc).to_f64().value();
                }
                let over = dot(&e, &self.weight);
                for (channel, a) in frame.attributes.iter_mut().zip(attributes) {
                    channel[i] = match a {
                        Attribute::Flat(v) => *v,
                        Attribute::Perspective { numerator, ratio } => {
                            let value = quotient(dot(&e, numerator), over.clone()) * ratio;
                            value.to_f64().value()
                        }
                    };
                }
            }
        }
        if let (true, Some(out)) = (self.offset != 0.0, frame.depth.as_mut()) {
            out[i] += self.offset;
        }
        if let (Some([lo, hi]), Some(out)) = (&self.clamp, frame.depth.as_mut()) {
            let (lo, hi) = (lo.to_f64().value(), hi.to_f64().value());
            out[i] = out[i].clamp(lo, hi);
        }
    }
}

/// The screen-space path's shading of a piece with every w > 0: the
/// triangle of depth z_f = depth(z/w), the same w and attributes (or,
/// `flat`, the provoking vertex's at every vertex), through
/// [`setup::shading`] with weights E_i·c/|D'| (c the pieces' common
/// scale), exactly the screen path's λ up to a power of two when the
/// coordinates are dyadic.
fn screen_shading(
    piece: &Piece,
    vertices: [&ClipVertex; 3],
    interpolation: Interpolation,
    flat: &[RBig],
    plan: &Plan,
    mapping: &Mapping,
) -> Shading {
    let vertex = |v: &ClipVertex| {
        let w = v.w();
        let attributes = match interpolation {
            Interpolation::Flat => flat,
            _ => &v.attributes[..],
        };
        Vertex {
            z: Number::from_rbig(mapping.depth(&(&v.clip[2] / w))),
            w: Number::from_rbig(w.clone()),
            attributes: attributes.iter().cloned().map(Number::from_rbig).collect(),
            ..Vertex::at(Number::ZERO, Number::ZERO)
        }
    };
    let triangle = Triangle {
        vertices: vertices.map(vertex),
        interpolation,
    };
    // |D'| / c: twice the area in G's units, divided by the common scale.
    let area = RBig::from(piece.det.clone()) / &piece.scale[0];
    let area = match i128::try_from(area.numerator()) {
        Ok(a) => a as f64,
        Err(_) => area.to_f64().value(),
    };
    setup::shading(&triangle, [0, 1, 2], plan, area)
}

/// The rationals times the least common multiple q of their denominators:
/// integers n_i with r_i = n_i / q.
fn integers(r: &[RBig; 3]) -> ([IBig; 3], dashu_int::UBig) {
    let q = lcm_of_denominators(r.iter());
    let n = r.each_ref().map(|x| {
        let scaled = x * &q;
        debug_assert!(scaled.is_int());
        scaled.numerator().clone()
    });
    (n, q.numerator().unsigned_abs())
}

fn dot(e: &[IBig; 3], n: &[IBig; 3]) -> IBig {
    (0..3).map(|i| &e[i] * &n[i]).sum()
}

/// n / d for d > 0.
fn quotient(n: IBig, d: IBig) -> RBig {
    debug_assert!(d > IBig::ZERO);
    RBig::from_parts(n, d.unsigned_abs())
}
