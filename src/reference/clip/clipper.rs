//! Clipping in homogeneous coordinates, before any divide (SPEC.md §16.3):
//! Sutherland–Hodgman against the planes a case clips, in the order near,
//! far, left, right, top, bottom, every new vertex an exact rational.

use dashu_ratio::RBig;

use crate::scene::Vertex;

/// A vertex of a polygon being clipped: clip coordinates (x, y, z, w) and
/// attributes, exact.
#[derive(Clone, Debug, PartialEq)]
pub struct ClipVertex {
    pub c: [RBig; 4],
    pub attributes: Vec<RBig>,
}

impl ClipVertex {
    pub fn of(v: &Vertex) -> ClipVertex {
        ClipVertex {
            c: [&v.x, &v.y, &v.z, &v.w].map(|n| n.as_rbig().clone()),
            attributes: v.attributes.iter().map(|a| a.as_rbig().clone()).collect(),
        }
    }

    /// P + t·(Q − P), in every coordinate and attribute.
    fn towards(&self, q: &ClipVertex, t: &RBig) -> ClipVertex {
        let mix = |p: &RBig, q: &RBig| p + t * (q - p);
        ClipVertex {
            c: [0, 1, 2, 3].map(|i| mix(&self.c[i], &q.c[i])),
            attributes: self
                .attributes
                .iter()
                .zip(&q.attributes)
                .map(|(p, q)| mix(p, q))
                .collect(),
        }
    }
}

/// The signed distance of plane `plane` (0 near, 1 far, 2 left, 3 right,
/// 4 top, 5 bottom): non-negative inside the clip volume.
pub fn distance(plane: usize, c: &[RBig; 4]) -> RBig {
    let [x, y, z, w] = c;
    match plane {
        0 => z.clone(),
        1 => w - z,
        2 => w + x,
        3 => w - x,
        4 => w + y,
        5 => w - y,
        _ => unreachable!("six planes"),
    }
}

/// One Sutherland–Hodgman pass: each edge P→Q (the last vertex to the
/// first included) keeps P when d(P) ≥ 0, then adds the crossing when d(P)
/// and d(Q) have opposite strict signs. t = d(P)/(d(P) − d(Q)) makes the
/// crossing the same rational from either end.
pub fn clip_against(polygon: &[ClipVertex], plane: usize) -> Vec<ClipVertex> {
    let n = polygon.len();
    let d: Vec<RBig> = polygon.iter().map(|v| distance(plane, &v.c)).collect();
    let mut out = Vec::with_capacity(n + 1);
    for i in 0..n {
        let j = (i + 1) % n;
        let (dp, dq) = (&d[i], &d[j]);
        if *dp >= RBig::ZERO {
            out.push(polygon[i].clone());
        }
        let crosses =
            (*dp < RBig::ZERO && *dq > RBig::ZERO) || (*dp > RBig::ZERO && *dq < RBig::ZERO);
        if crosses {
            let t = dp / (dp - dq);
            out.push(polygon[i].towards(&polygon[j], &t));
        }
    }
    out
}

/// The polygon left of `polygon` after every plane `planes` selects
/// (`ClipRules::clipped_planes`), in order; fewer than three vertices when
/// nothing is left.
pub fn clip(polygon: Vec<ClipVertex>, planes: [bool; 6]) -> Vec<ClipVertex> {
    let mut polygon = polygon;
    for (plane, _) in planes.iter().enumerate().filter(|(_, on)| **on) {
        if polygon.len() < 3 {
            break;
        }
        polygon = clip_against(&polygon, plane);
    }
    polygon
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(c: [i64; 4]) -> ClipVertex {
        ClipVertex {
            c: c.map(RBig::from),
            attributes: vec![RBig::from(c[0])],
        }
    }

    #[test]
    fn a_crossing_is_the_same_from_either_end() {
        let p = v([-3, 1, -2, 5]);
        let q = v([7, -4, 9, 2]);
        for plane in 0..6 {
            let a = clip_against(&[p.clone(), q.clone(), v([0, 0, 1, 1])], plane);
            let b = clip_against(&[q.clone(), p.clone(), v([0, 0, 1, 1])], plane);
            for x in &a {
                if *x != p && *x != q && x.c != v([0, 0, 1, 1]).c {
                    assert!(b.contains(x), "plane {plane}: {x:?} not in {b:?}");
                }
            }
        }
    }

    #[test]
    fn near_plane_cuts_a_triangle_into_a_quadrilateral() {
        // One vertex behind the near plane (z < 0): two crossings replace it.
        let tri = vec![v([0, 0, -1, 1]), v([1, 0, 1, 1]), v([0, 1, 1, 1])];
        let out = clip(tri, [true, false, false, false, false, false]);
        assert_eq!(out.len(), 4);
        for p in &out {
            assert!(distance(0, &p.c) >= RBig::ZERO);
        }
        assert_eq!(out[0].c[2], RBig::ZERO);
    }
}
