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
//! where the contour's do. Only coverage survives this restatement, so a
//! case whose plan interpolates values is not restated (`applies`).

use dashu_ratio::RBig;

use crate::plan::Plan;
use crate::rasterizer::ScreenViewport;
use crate::reference::clip::{clip_to_window, Window};
use crate::scene::{Cull, Number, Polygon, PolygonFill, Primitive, Scene, Vertex};

/// Whether a case clipped at a viewport can be restated here: a
/// screen-space case of triangles and polygons (no lines or points, whose
/// clipping this does not restate), static, whose plan interpolates
/// nothing (a polygon carries no values).
pub fn applies(scene: &Scene, plan: &Plan) -> bool {
    !scene.in_clip_space()
        && !plan.interpolates()
        && plan.motion.is_none()
        && scene
            .primitives
            .iter()
            .all(|p| matches!(p, Primitive::Triangle(_) | Primitive::Polygon(_)))
}

/// `scene` with every primitive that reaches past `viewport` clipped at it
/// (the module's notes); `bits` the case's own subpixel bits, which the
/// adapter snapped the vertices to before the driver clipped them. A
/// primitive wholly inside, one wholly outside (it covers no sample of the
/// canvas the viewport holds), a triangle of zero area and a culled one are
/// kept as they are.
pub fn clip_scene(scene: &mut Scene, viewport: ScreenViewport, bits: Option<u32>) {
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
    for primitive in &mut scene.primitives {
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
}

/// [`clip_scene`] for a driver that snaps the new vertices to `finer`
/// bits where the case states fewer, `bits` (SPEC.md §16.9): the adapter
/// sends the case's vertices on the case's grid, which lies on the finer
/// one, and the driver clips them and snaps the new vertices to its own.
/// So every vertex is snapped to the case's grid first, the scene clipped,
/// and the restated case stated at `finer` bits, at which the old vertices
/// stay where they are and the new ones snap as the driver's do. Otherwise
/// (no finer grid) [`clip_scene`].
pub fn clip_scene_on_grid(
    scene: &mut Scene,
    viewport: ScreenViewport,
    bits: Option<u32>,
    finer: Option<u32>,
) {
    let Some((bits, finer)) = bits.zip(finer).filter(|(bits, finer)| finer > bits) else {
        return clip_scene(scene, viewport, bits);
    };
    for v in scene.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
        v.x = v.x.snapped(bits);
        v.y = v.y.snapped(bits);
    }
    clip_scene(scene, viewport, Some(bits));
    scene.rules.subpixel_bits = Some(finer);
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
