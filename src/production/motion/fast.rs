//! The fast road for moving triangles in formats of at most
//! [`FAST_MAX_FRAC_BITS`] fraction bits: each edge function at a sample, and
//! twice the area, a [`Quadratic`] in τ set up once per sample and its sign
//! taken exactly at each instant. The same integers as `exact.rs`'s test,
//! about 3× faster; finer formats and parallelograms take that one.

use std::cmp::Ordering;

use super::exact::{edge_owned, sub, Point, TIME_BITS};
use crate::scene::rules::limits;
use crate::scene::{Cull, FillRule};

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
pub(super) const FAST_MAX_FRAC_BITS: u32 = 13;
const _: () = assert!(100 + 2 * FAST_MAX_FRAC_BITS <= 126);
const _: () = assert!(limits::COORD_LIMIT == 1 << 15 && limits::MAX_CANVAS_SIDE <= 1 << 14);

/// q(τ) = q0 + q1·τ + q2·τ², held as its coefficients: an edge function at
/// one sample, or twice a triangle's area, as a vertex moves linearly. Its
/// sign at τ = t/2^32 is that of 2^64·q(τ) = 2^32·(2^32·q0 + t·q1) + t²·q2,
/// an exact integer.
#[derive(Clone, Copy, Debug)]
pub(super) struct Quadratic([i128; 3]);

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
pub(super) struct Fast {
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
    pub fn new(ends: [[[i64; 2]; 2]; 3], cull: Cull) -> Fast {
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
    pub fn edges_at(&self, q: Point) -> [Quadratic; 3] {
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
    pub fn covers(&self, edges: &[Quadratic; 3], t: i128, rule: FillRule) -> bool {
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

#[cfg(test)]
mod tests {
    use super::*;

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
}
