//! Homogeneous rasterization of one triangle (an original one or a piece
//! of a clipped one's fan), SPEC.md §16.4: edge functions
//! E_i(s) = det[H_(i+1), H_(i+2), S] and D = det[H_0, H_1, H_2] on the
//! homogeneous screen points of [`project`](super::project), the fill rule's
//! ownership read off each edge's coefficients, and the samples to visit.
//!
//! Set-up is exact and per triangle: each H_i is scaled by a positive
//! rational c_i into an integer vector G_i (in half-pixel units, so that a
//! pixel centre is an integer point too), which multiplies E_i by
//! c_(i+1)·c_(i+2) and D by c_0·c_1·c_2, all positive: signs, coverage and
//! the ratios E_i/D up to the factor c_i the weights carry
//! ([`Piece::scale`]) are unchanged. The per-sample work is then integer
//! dot products: in i128 when every coefficient fits [`SMALL_BITS`], in
//! big integers otherwise.
//!
//! What this file does not do: divide by a w ≤ 0 (never needed: such a
//! vertex stays a homogeneous point), or clip (that is `clipper.rs`).

use dashu_int::ops::{BitTest, UnsignedAbs};
use dashu_int::IBig;
use dashu_ratio::RBig;

use super::project::Projected;
use crate::scene::rules::limits::MAX_CANVAS_SIDE;
use crate::scene::FillRule;

/// The largest coefficient magnitude, in bits, evaluated in i128: with a
/// pixel index below 2^15 on either axis (a canvas side is at most
/// [`MAX_CANVAS_SIDE`] = 2^14), |a·x + b·y + c| < 2^100·(2^15 + 2^15 + 1)
/// < 2^117, far inside i128 with no check needed per sample.
pub const SMALL_BITS: usize = 100;
const _: () = assert!(MAX_CANVAS_SIDE < 1 << 15 && SMALL_BITS + 17 < 127);

/// An edge's σ-signed function of the pixel index (px, py), at the pixel
/// centre: a·px + b·py + c.
type Coefficients<T> = [[T; 3]; 3];

/// The three edges' coefficients, in i128 when they fit.
#[derive(Clone, Debug)]
pub enum Edges {
    Small(Coefficients<i128>),
    Big(Coefficients<IBig>),
}

/// The three σ·E_i at one sample.
#[derive(Clone, Debug)]
pub enum EdgeValues {
    Small([i128; 3]),
    Big([IBig; 3]),
}

impl EdgeValues {
    /// The values as big integers, for the exact value path.
    pub fn big(&self) -> [IBig; 3] {
        match self {
            EdgeValues::Small(v) => v.map(IBig::from),
            EdgeValues::Big(v) => v.clone(),
        }
    }
}

/// One triangle set up for homogeneous rasterization.
#[derive(Clone, Debug)]
pub struct Piece {
    /// σ·E_i(s) = a·px + b·py + c for pixel (px, py), in G's units.
    pub edges: Edges,
    /// 0 for an edge that owns its samples, −1 otherwise: a sample is
    /// covered when every σ·E_i + bias_i ≥ 0.
    pub bias: [i8; 3],
    /// c_i > 0, so that E_i/D = c_i·E'_i/D' in G's units.
    pub scale: [RBig; 3],
    /// |D'| = σ·det[G_0, G_1, G_2] > 0.
    pub det: IBig,
    /// Every vertex has w > 0, and all share one c (so that the weights
    /// E'_i·c/|D'| are the screen-space barycentrics).
    pub in_front: bool,
}

impl Piece {
    /// Sets up a triangle; `None` when D = 0 (it covers nothing).
    pub fn new(h: &[Projected; 3], rule: FillRule) -> Option<Piece> {
        let in_front = h.iter().all(Projected::in_front);
        // T·H = (2X, 2Y, W): half-pixel units, pixel centres (2px+1, 2py+1).
        let two = RBig::from(2);
        let t: [[RBig; 3]; 3] = h
            .each_ref()
            .map(|p| [&p.h[0] * &two, &p.h[1] * &two, p.h[2].clone()]);
        let scale: [RBig; 3] = if in_front {
            let c = lcm_of_denominators(t.iter().flat_map(|v| &v[..2]));
            [c.clone(), c.clone(), c]
        } else {
            t.each_ref().map(|v| lcm_of_denominators(v.iter()))
        };
        let g: [[IBig; 3]; 3] = [0, 1, 2].map(|i| {
            t[i].each_ref().map(|x| {
                let n = x * &scale[i];
                debug_assert!(n.is_int());
                n.numerator().clone()
            })
        });
        // det[G1, G2, S] = sx·a + sy·b + sw·c (cofactors of S's row).
        let cofactors = [0, 1, 2].map(|i| {
            let (p, q) = (&g[(i + 1) % 3], &g[(i + 2) % 3]);
            [
                &p[1] * &q[2] - &p[2] * &q[1],
                &p[2] * &q[0] - &p[0] * &q[2],
                &p[0] * &q[1] - &p[1] * &q[0],
            ]
        });
        // D' = det[G0, G1, G2] = det[G1, G2, G0].
        let det: IBig = (0..3).map(|k| &g[0][k] * &cofactors[0][k]).sum();
        if det == IBig::ZERO {
            return None;
        }
        let sigma = if det > IBig::ZERO {
            IBig::ONE
        } else {
            -IBig::ONE
        };
        // At pixel (px, py) the sample is (2px+1, 2py+1, 1) in T's units:
        // σ·E = 2a·px + 2b·py + (a + b + c), a and b keeping their signs.
        let big: Coefficients<IBig> = cofactors.map(|[a, b, c]| {
            let (a, b, c) = (&sigma * a, &sigma * b, &sigma * c);
            [&a * 2, &b * 2, a + b + c]
        });
        let bias = big
            .each_ref()
            .map(|[a, b, _]| if owns(a, b, rule) { 0 } else { -1 });
        let small = big
            .iter()
            .flatten()
            .all(|x| x.unsigned_abs().bit_len() <= SMALL_BITS);
        let edges = if small {
            Edges::Small(big.map(|e| e.map(|x| i128::try_from(&x).expect("checked to fit"))))
        } else {
            Edges::Big(big)
        };
        Some(Piece {
            edges,
            bias,
            scale,
            det: &sigma * det,
            in_front,
        })
    }

    /// σ·E_i at pixel (px, py)'s centre.
    pub fn at(&self, px: i64, py: i64) -> EdgeValues {
        match &self.edges {
            // |value| < 2^117 (SMALL_BITS): no overflow.
            Edges::Small(e) => {
                EdgeValues::Small(e.map(|[a, b, c]| a * i128::from(px) + b * i128::from(py) + c))
            }
            Edges::Big(e) => EdgeValues::Big(
                e.each_ref()
                    .map(|[a, b, c]| a * IBig::from(px) + b * IBig::from(py) + c),
            ),
        }
    }

    /// Whether the sample with these edge values is covered: every
    /// σ·E_i > 0, or = 0 on an edge that owns it.
    pub fn covers(&self, values: &EdgeValues) -> bool {
        match values {
            EdgeValues::Small(v) => (0..3).all(|i| v[i] + i128::from(self.bias[i]) >= 0),
            EdgeValues::Big(v) => (0..3).all(|i| &v[i] + IBig::from(self.bias[i]) >= IBig::ZERO),
        }
    }
}

/// Whether an edge with σ-signed coefficients a (of s_x) and b (of s_y)
/// owns the samples on it (SPEC.md §16.4): a left edge when a > 0, a right
/// one when a < 0, and when a = 0 a top edge if b > 0 (the triangle below
/// it, y down), a bottom one if b < 0; a = b = 0 owns nothing.
fn owns(a: &IBig, b: &IBig, rule: FillRule) -> bool {
    let zero = IBig::ZERO;
    if *a > zero {
        rule.owns_left()
    } else if *a < zero {
        rule.owns_right()
    } else if *b > zero {
        rule.owns_top()
    } else if *b < zero {
        rule.owns_bottom()
    } else {
        false
    }
}

/// The least common multiple of the numbers' denominators, as a positive
/// rational (an integer).
pub fn lcm_of_denominators<'a>(numbers: impl Iterator<Item = &'a RBig>) -> RBig {
    use dashu_int::ops::Gcd;
    let lcm = numbers.fold(dashu_int::UBig::ONE, |l, n| {
        let d = n.denominator();
        let g = (&l).gcd(d);
        &l / g * d
    });
    RBig::from(lcm)
}

/// The samples a piece may cover, as half-open pixel ranges [[x0, x1],
/// [y0, y1]]: the bounding box of its snapped vertices when all have
/// w > 0, otherwise everything (its covered region may be unbounded);
/// then within `limit` (the canvas, and the viewport rectangle under the
/// guard band).
pub fn region(h: &[Projected; 3], limit: [[i64; 2]; 2]) -> [[i64; 2]; 2] {
    if !h.iter().all(Projected::in_front) {
        return limit;
    }
    let half = RBig::from_parts(1.into(), 2u8.into());
    [0, 1].map(|k| {
        let lo = h.iter().map(|p| &p.h[k]).min().expect("three vertices");
        let hi = h.iter().map(|p| &p.h[k]).max().expect("three vertices");
        // Centres i + 1/2 in [lo, hi]: i from ⌈lo − 1/2⌉ to ⌊hi − 1/2⌋.
        let first = super::project::clamp_i64((lo - &half).ceil());
        let last = super::project::clamp_i64((hi - &half).floor());
        [first.max(limit[k][0]), (last + 1).min(limit[k][1])]
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::production::clip::clipper::ClipVertex;
    use crate::production::clip::project::Mapping;
    use crate::scene::Viewport;

    fn projected(c: [(i64, i64); 4]) -> Projected {
        let v = ClipVertex {
            clip: c.map(|(n, d)| RBig::from(n) / RBig::from(d)),
            attributes: vec![],
        };
        Mapping::new(&Viewport::canvas(16, 16), Some(8), false).project(&v)
    }

    /// The same piece with its coefficients forced into big integers.
    fn big(piece: &Piece) -> Piece {
        let Edges::Small(e) = &piece.edges else {
            return piece.clone();
        };
        Piece {
            edges: Edges::Big(e.map(|row| row.map(IBig::from))),
            ..piece.clone()
        }
    }

    #[test]
    fn the_i128_path_decides_as_big_integers_do() {
        let mut seed = 0x1234_5678_u64;
        let mut next = |lo: i64, hi: i64| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            lo + ((seed >> 33) % (hi - lo + 1) as u64) as i64
        };
        let mut covered = 0;
        for _ in 0..200 {
            let h = [0, 1, 2].map(|_| {
                projected([
                    (next(-40, 40), 16),
                    (next(-40, 40), 16),
                    (0, 1),
                    (next(-16, 32), 16),
                ])
            });
            let Some(piece) = Piece::new(&h, FillRule::TopLeft) else {
                continue;
            };
            assert!(matches!(piece.edges, Edges::Small(_)));
            let slow = big(&piece);
            for py in -2..18 {
                for px in -2..18 {
                    let (a, b) = (piece.at(px, py), slow.at(px, py));
                    assert_eq!(a.big(), b.big());
                    assert_eq!(piece.covers(&a), slow.covers(&b));
                    covered += usize::from(piece.covers(&a));
                }
            }
        }
        assert!(covered > 1000, "{covered}");
    }

    #[test]
    fn huge_coefficients_take_big_integers() {
        // Unsnapped coordinates with three large prime denominators: their
        // common multiple, times a coordinate, squared, is past 2^100.
        let exact = Mapping::new(&Viewport::canvas(16, 16), None, false);
        let at = |x: RBig, y: RBig| {
            exact.project(&ClipVertex {
                clip: [x, y, RBig::ZERO, RBig::ONE],
                attributes: vec![],
            })
        };
        let inv = |q: i64| RBig::ONE / RBig::from(q);
        let one = RBig::ONE;
        let h = [
            at(inv(1_000_000_007) - &one, inv(1_000_000_007) - &one),
            at(&one - inv(998_244_353), inv(998_244_353) - &one),
            at(inv(1_000_000_009), &one - inv(1_000_000_009)),
        ];
        let piece = Piece::new(&h, FillRule::TopLeft).expect("not degenerate");
        assert!(matches!(piece.edges, Edges::Big(_)));
        // About (0, 0), (16, 0), (8, 16).
        assert!(piece.covers(&piece.at(8, 2)));
        assert!(piece.covers(&piece.at(8, 14)));
        assert!(!piece.covers(&piece.at(0, 15)));
        assert!(!piece.covers(&piece.at(15, 15)));
    }

    #[test]
    fn an_edge_owns_by_its_coefficients() {
        let zero = IBig::ZERO;
        let (pos, neg) = (IBig::ONE, -IBig::ONE);
        let rule = FillRule::TopLeft;
        assert!(owns(&pos, &zero, rule)); // left
        assert!(!owns(&neg, &zero, rule)); // right
        assert!(owns(&zero, &pos, rule)); // top
        assert!(!owns(&zero, &neg, rule)); // bottom
        assert!(!owns(&zero, &zero, FillRule::AllEdges));
    }
}
