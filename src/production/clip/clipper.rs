//! The clipper of SPEC.md §16.3: Sutherland–Hodgman against the planes a
//! case clips before the divide, in exact rationals, and the fan the
//! clipped polygon is drawn as.
//!
//! Exact on purpose: the new vertex P + t·(Q − P), t = d(P)/(d(P) − d(Q)),
//! is the same rational whichever end the edge is walked from, so two
//! triangles that share an edge share its clipped end and a mesh stays
//! watertight. A float or fixed-point t would round differently from
//! either end.

use dashu_ratio::RBig;

use crate::scene::Vertex;

/// A vertex of the polygon being clipped: its clip coordinates
/// (x, y, z, w) and attributes, exact.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ClipVertex {
    pub clip: [RBig; 4],
    pub attributes: Vec<RBig>,
}

impl ClipVertex {
    /// A clip-space vertex of the scene (its x, y, z, w are clip
    /// coordinates, SPEC.md §16.1).
    pub fn of(v: &Vertex) -> ClipVertex {
        ClipVertex {
            clip: [&v.x, &v.y, &v.z, &v.w].map(|n| n.as_rbig().clone()),
            attributes: v.attributes.iter().map(|a| a.as_rbig().clone()).collect(),
        }
    }

    pub fn w(&self) -> &RBig {
        &self.clip[3]
    }
}

/// How the new vertex on an edge P→Q that a plane cuts is computed, from
/// the two ends and their signed distances d(P) > 0 > d(Q) or the other
/// way round. Production's is [`new_vertex`]; tests pass wrong ones to show
/// that their checks catch them.
pub type NewVertex = fn(&ClipVertex, &ClipVertex, &RBig, &RBig) -> ClipVertex;

/// P + t·(Q − P), t = d(P)/(d(P) − d(Q)), in every clip coordinate and
/// every attribute, exactly (SPEC.md §16.3).
pub fn new_vertex(p: &ClipVertex, q: &ClipVertex, dp: &RBig, dq: &RBig) -> ClipVertex {
    let t = dp / (dp - dq);
    let lerp = |a: &RBig, b: &RBig| a + &t * (b - a);
    ClipVertex {
        clip: [0, 1, 2, 3].map(|i| lerp(&p.clip[i], &q.clip[i])),
        attributes: p
            .attributes
            .iter()
            .zip(&q.attributes)
            .map(|(a, b)| lerp(a, b))
            .collect(),
    }
}

/// The six planes' signed distances, in the order SPEC.md §16.3 clips them:
/// near (z), far (w − z), left (w + x), right (w − x), top (w + y), bottom
/// (w − y).
const PLANES: [fn(&[RBig; 4]) -> RBig; 6] = [
    |[_, _, z, _]| z.clone(),
    |[_, _, z, w]| w - z,
    |[x, _, _, w]| w + x,
    |[x, _, _, w]| w - x,
    |[_, y, _, w]| w + y,
    |[_, y, _, w]| w - y,
];

/// The triangle clipped against the planes `clipped` selects (in
/// [`ClipRules::clipped_planes`](crate::scene::ClipRules::clipped_planes)'s
/// order), one after another. Fewer than three vertices left: nothing to
/// draw.
pub fn clip(triangle: Vec<ClipVertex>, clipped: [bool; 6], new: NewVertex) -> Vec<ClipVertex> {
    let mut polygon = triangle;
    for (plane, _) in PLANES.iter().zip(clipped).filter(|(_, on)| *on) {
        if polygon.len() < 3 {
            break;
        }
        polygon = clip_plane(&polygon, *plane, new);
    }
    polygon
}

/// One Sutherland–Hodgman pass: each edge P→Q (the last vertex to the
/// first included) contributes P if d(P) ≥ 0, then the new vertex if d(P)
/// and d(Q) have opposite strict signs.
fn clip_plane(
    polygon: &[ClipVertex],
    distance: fn(&[RBig; 4]) -> RBig,
    new: NewVertex,
) -> Vec<ClipVertex> {
    let d: Vec<RBig> = polygon.iter().map(|v| distance(&v.clip)).collect();
    let zero = RBig::ZERO;
    let mut out = Vec::with_capacity(polygon.len() + 1);
    for i in 0..polygon.len() {
        let j = (i + 1) % polygon.len();
        if d[i] >= zero {
            out.push(polygon[i].clone());
        }
        if (d[i] < zero && d[j] > zero) || (d[i] > zero && d[j] < zero) {
            out.push(new(&polygon[i], &polygon[j], &d[i], &d[j]));
        }
    }
    out
}

/// The fan (v0, v_i, v_i+1), i = 1 … n − 2, of a clipped polygon, by
/// vertex index.
pub fn fan(count: usize) -> impl Iterator<Item = [usize; 3]> {
    (1..count.saturating_sub(1)).map(|i| [0, i, i + 1])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vertex(c: [i64; 4], a: i64) -> ClipVertex {
        ClipVertex {
            clip: c.map(RBig::from),
            attributes: vec![RBig::from(a)],
        }
    }

    #[test]
    fn the_new_vertex_is_the_same_from_either_end() {
        let p = vertex([1, 2, 3, 4], 5);
        let q = vertex([-7, 3, -2, 1], -1);
        let dp = RBig::from(3);
        let dq = RBig::from(-2);
        assert_eq!(new_vertex(&p, &q, &dp, &dq), new_vertex(&q, &p, &dq, &dp));
        // t = 3/5: z = 3 + 3/5·(−5) = 0, on the near plane.
        assert_eq!(new_vertex(&p, &q, &dp, &dq).clip[2], RBig::ZERO);
    }

    #[test]
    fn near_clipping_a_vertex_behind_the_eye_makes_a_quad() {
        let triangle = vec![
            vertex([-1, -1, 1, 2], 0),
            vertex([1, -1, 1, 2], 0),
            vertex([0, 1, -1, -1], 0),
        ];
        let near_only = [true, false, false, false, false, false];
        let quad = clip(triangle, near_only, new_vertex);
        assert_eq!(quad.len(), 4);
        assert!(quad.iter().all(|v| v.clip[2] >= RBig::ZERO));
        assert_eq!(fan(quad.len()).collect::<Vec<_>>(), [[0, 1, 2], [0, 2, 3]]);
    }

    #[test]
    fn a_triangle_wholly_outside_a_plane_leaves_nothing() {
        let triangle = vec![
            vertex([0, 0, -1, 1], 0),
            vertex([1, 0, -2, 1], 0),
            vertex([0, 1, -1, 1], 0),
        ];
        let all = [true; 6];
        assert!(clip(triangle, all, new_vertex).is_empty());
        assert_eq!(fan(0).count(), 0);
    }
}
