//! A screen-space case restated under a driver's own clipping at its
//! viewport (SPEC.md §16.9): where no viewport the device allows holds a
//! case's vertices, an adapter draws it through a smaller one
//! (`Rasterizer::screen_viewport`), and a driver that declares
//! `clip_xy: clip-then-snap` clips each primitive there and snaps the new
//! vertices. The restated case is that: each triangle and each polygon
//! contour clipped exactly at the rectangle (`reference::clip::window`)
//! from its vertices snapped to the case's grid, as the adapter sends them,
//! the new vertices left for the reference to snap to the rasterizer's
//! grid: its own where it is coarser than the case's (SPEC.md §3.2), and
//! where it is finer, too (`clip_scene_on_grid`: the case restated at the
//! driver's bits).
//!
//! A clipped triangle is a convex polygon: it is restated as a polygon of
//! one contour under `nonzero`, one primitive, so it keeps its place (and
//! its id). Its fan's inner edges own each sample once under the tie rule,
//! and SPEC.md §14.1's nudge is the tie rule on its outer edges, so the
//! polygon covers what the driver's clipped triangle covers. A polygon's
//! contours are clipped one by one: the driver clips each fan triangle of
//! the adapter's stencil fan, whose inner edges cancel in the winding
//! count, and its outer edges are the contour's, crossing the rectangle
//! where the contour's do.
//!
//! A polygon carries no values, so the pieces decide coverage and owners
//! only. Their values come from a second restatement, the same case with
//! each clipped triangle left whole ([`Clipped::Whole`]: its vertices
//! where the pieces' old ones are): a piece lies in its triangle's depth
//! and attribute planes, so at each sample a piece covers the reference
//! writes the whole triangle's exact values there, its planes extended to
//! samples a snapped new vertex puts just outside it
//! (`reference::take_whole_values`, SPEC.md §16.9).

use dashu_ratio::RBig;

use crate::plan::Plan;
use crate::rasterizer::ScreenViewport;
use crate::reference::clip::{clip_to_window, Window};
use crate::scene::{Cull, Number, Polygon, PolygonFill, Primitive, Scene, Vertex};

/// Whether a case clipped at a viewport can be restated here: a
/// screen-space case of triangles and polygons (no lines or points, whose
/// clipping this does not restate), static. Its values, where the plan
/// interpolates them, come from the whole triangles (the module's notes).
pub fn applies(scene: &Scene, plan: &Plan) -> bool {
    !scene.in_clip_space()
        && plan.motion.is_none()
        && scene
            .primitives
            .iter()
            .all(|p| matches!(p, Primitive::Triangle(_) | Primitive::Polygon(_)))
}

/// What a triangle clipped at the viewport becomes in a restated case.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Clipped {
    /// Its pieces: one polygon of one contour, in its place (coverage and
    /// owners).
    Pieces,
    /// The whole triangle, its vertices snapped to the case's grid as the
    /// pieces' old vertices are, its values as stated: where the pieces'
    /// values come from.
    Whole,
}

/// `scene` with every primitive that reaches past `viewport` clipped at it
/// (the module's notes); `bits` the case's own subpixel bits, which the
/// adapter snapped the vertices to before the driver clipped them. A
/// primitive wholly inside, one wholly outside (it covers no sample of the
/// canvas the viewport holds), a triangle of zero area and a culled one are
/// kept as they are. Returns the indices of the triangles clipped.
pub fn clip_scene(scene: &mut Scene, viewport: ScreenViewport, bits: Option<u32>) -> Vec<usize> {
    clip_scene_as(scene, viewport, bits, Clipped::Pieces)
}

/// [`clip_scene`], each clipped triangle restated `as_` its pieces or whole
/// (polygons are clipped either way).
pub fn clip_scene_as(
    scene: &mut Scene,
    viewport: ScreenViewport,
    bits: Option<u32>,
    as_: Clipped,
) -> Vec<usize> {
    let window = Window {
        origin: viewport.origin.map(RBig::from),
        size: viewport.size.map(RBig::from),
    };
    let snapped = |v: &Vertex| {
        [&v.x, &v.y].map(|c| match bits {
            Some(b) => c.snapped(b).as_rbig().clone(),
            None => c.as_rbig().clone(),
        })
    };
    let cull = scene.rules.cull;
    let mut triangles = Vec::new();
    for (index, primitive) in scene.primitives.iter_mut().enumerate() {
        let clipped = match primitive {
            Primitive::Triangle(t) => {
                let points: Vec<[RBig; 2]> = t.vertices.iter().map(snapped).collect();
                if culled(&points, cull) {
                    continue;
                }
                let piece = clip_to_window(&points, &window);
                if piece.len() < 3 || piece == points {
                    continue;
                }
                triangles.push(index);
                if as_ == Clipped::Whole {
                    for (v, [x, y]) in t.vertices.iter_mut().zip(points) {
                        v.x = Number::from_rbig(x);
                        v.y = Number::from_rbig(y);
                    }
                    continue;
                }
                polygon(vec![piece])
            }
            Primitive::Polygon(p) => {
                let contours: Vec<Vec<[RBig; 2]>> = p
                    .contours()
                    .map(|c| c.iter().map(snapped).collect())
                    .collect();
                let pieces: Vec<Vec<[RBig; 2]>> = contours
                    .iter()
                    .map(|c| clip_to_window(c, &window))
                    .filter(|piece| piece.len() >= 3)
                    .collect();
                if pieces.is_empty() || pieces == contours {
                    continue;
                }
                Polygon {
                    fill: p.fill,
                    ..polygon(pieces)
                }
            }
            _ => continue,
        };
        *primitive = Primitive::Polygon(clipped);
    }
    scene.expect.area = None;
    triangles
}

/// [`clip_scene`] for a driver that snaps the new vertices to `finer`
/// bits where the case states fewer, `bits` (SPEC.md §16.9): the adapter
/// sends the case's vertices on the case's grid, which lies on the finer
/// one, and the driver clips them and snaps the new vertices to its own.
/// So every vertex is snapped to the case's grid first, the scene clipped,
/// and the restated case stated at `finer` bits, at which the old vertices
/// stay where they are and the new ones snap as the driver's do. Otherwise
/// (no finer grid) [`clip_scene`]. Each clipped triangle is restated `as_`
/// its pieces or whole; returns their indices.
pub fn clip_scene_on_grid(
    scene: &mut Scene,
    viewport: ScreenViewport,
    bits: Option<u32>,
    finer: Option<u32>,
    as_: Clipped,
) -> Vec<usize> {
    let Some((bits, finer)) = bits.zip(finer).filter(|(bits, finer)| finer > bits) else {
        return clip_scene_as(scene, viewport, bits, as_);
    };
    for v in scene.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
        v.x = v.x.snapped(bits);
        v.y = v.y.snapped(bits);
    }
    let clipped = clip_scene_as(scene, viewport, Some(bits), as_);
    scene.rules.subpixel_bits = Some(finer);
    clipped
}

/// Whether a triangle of these (snapped) vertices draws nothing: zero
/// area, or culled by its winding (twice its signed area positive for
/// clockwise on screen, y down, as the reference's triangles).
fn culled(v: &[[RBig; 2]], cull: Cull) -> bool {
    let area = (&v[1][0] - &v[0][0]) * (&v[2][1] - &v[0][1])
        - (&v[1][1] - &v[0][1]) * (&v[2][0] - &v[0][0]);
    let clockwise = area > RBig::ZERO;
    area == RBig::ZERO
        || matches!(
            (cull, clockwise),
            (Cull::Clockwise, true) | (Cull::CounterClockwise, false)
        )
}

/// A polygon of these contours under `nonzero`, its vertices positions
/// only.
fn polygon(contours: Vec<Vec<[RBig; 2]>>) -> Polygon {
    let mut vertices = Vec::new();
    let mut contour_ends = Vec::new();
    for contour in contours {
        for [x, y] in contour {
            vertices.push(Vertex::at(Number::from_rbig(x), Number::from_rbig(y)));
        }
        contour_ends.push(vertices.len());
    }
    Polygon {
        vertices,
        contour_ends,
        fill: PolygonFill::NonZero,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::{render_judged, take_whole_values, Arithmetic};
    use crate::scene::{parse_case, Limits};

    /// A far triangle with depth and a perspective attribute, reaching
    /// from x = −30000 across a 16 × 8 canvas, under a small one inside.
    fn far() -> Scene {
        let json = r#"{"name": "far", "canvas": {"width": 16, "height": 8},
            "rules": {"subpixel_bits": 8, "cull": "none"},
            "primitives": [
              {"triangle": [{"position": [-30000, 3.3], "z": 0.125, "w": 4, "attributes": [1000]},
                            {"position": [20.25, -1.5], "z": 0.75, "w": 0.5, "attributes": [-3]},
                            {"position": [18, 9.75], "z": 1, "w": 1, "attributes": ["1/3"]}]},
              {"triangle": [{"position": [1, 1], "z": 0.5, "attributes": [7]},
                            {"position": [6, 1], "z": 0.5, "attributes": [7]},
                            {"position": [1, 6], "z": 0.5, "attributes": [7]}]}
            ]}"#;
        parse_case(json, "far.json", &Limits::default()).unwrap()
    }

    const CANVAS: ScreenViewport = ScreenViewport {
        origin: [0, 0],
        size: [16, 8],
    };

    #[test]
    fn a_clipped_triangle_is_restated_as_its_pieces_or_whole_at_one_index() {
        let scene = far();
        let (mut pieces, mut whole) = (scene.clone(), scene.clone());
        assert_eq!(clip_scene(&mut pieces, CANVAS, Some(8)), vec![0]);
        assert_eq!(
            clip_scene_as(&mut whole, CANVAS, Some(8), Clipped::Whole),
            vec![0]
        );
        // The triangle inside stays; the far one is a polygon of
        // positions, or itself with its vertices snapped as sent.
        let shown = |p: &Primitive| format!("{p:?}");
        assert_eq!(shown(&pieces.primitives[1]), shown(&scene.primitives[1]));
        assert!(matches!(&pieces.primitives[0], Primitive::Polygon(p)
            if p.vertices.len() >= 3 && p.vertices.iter().all(|v| v.attributes.is_empty())));
        let (Primitive::Triangle(stated), Primitive::Triangle(kept)) =
            (&scene.primitives[0], &whole.primitives[0])
        else {
            panic!("the far triangle is not kept whole");
        };
        for (s, k) in stated.vertices.iter().zip(&kept.vertices) {
            assert_eq!((s.x.snapped(8), s.y.snapped(8)), (k.x.clone(), k.y.clone()));
            assert_eq!((&s.z, &s.w, &s.attributes), (&k.z, &k.w, &k.attributes));
        }
        assert_ne!(stated.vertices[0].y, kept.vertices[0].y, "3.3 snapped");
    }

    /// The restated frame takes coverage and owners from the pieces and
    /// values from the whole triangle: wherever the pieces and the whole
    /// triangle cover a sample alike, the frames agree exactly, depth and
    /// attribute; without the whole triangle's values the pieces' are 0.
    #[test]
    fn the_pieces_take_the_whole_triangles_values() {
        let scene = far();
        let (mut pieces, mut whole) = (scene.clone(), scene.clone());
        let clipped = clip_scene(&mut pieces, CANVAS, Some(8));
        clip_scene_as(&mut whole, CANVAS, Some(8), Clipped::Whole);
        let plan = Plan::for_scene(&scene);
        let (want, _) = render_judged(&whole, &plan, Arithmetic::Auto);
        let (mut got, _) = render_judged(&pieces, &plan, Arithmetic::Auto);
        let alike: Vec<usize> = (0..got.last.len())
            .filter(|&s| got.last[s] == 1 && want.last[s] == 1)
            .collect();
        assert!(alike.len() > 60, "{}", alike.len());
        assert!(alike.iter().all(|&s| got.attributes[0][s] == 0.0));
        take_whole_values(&mut got, None, &whole, &clipped, &plan);
        for &s in &alike {
            assert_eq!(got.attributes[0][s], want.attributes[0][s], "slot {s}");
            assert_eq!(
                got.depth.as_ref().unwrap()[s],
                want.depth.as_ref().unwrap()[s]
            );
        }
        // The triangle inside keeps its own values.
        let inside = got.index(2, 2);
        assert_eq!((got.last[inside], got.attributes[0][inside]), (2, 7.0));
    }
}
