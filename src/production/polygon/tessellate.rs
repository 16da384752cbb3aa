//! Ear-clipping tessellation of simple polygons into triangles drawn by
//! production's triangle path with culling off.
//!
//! The tie rules are nudges of the sample (SPEC.md §14.1), so a nudged
//! sample lies inside exactly one triangle of a triangulation when it lies
//! inside the polygon, and in none otherwise: the triangles cover exactly
//! the polygon's samples, each once, and agree with the reference.
//!
//! Simple means one contour that does not touch or cross itself, decided
//! exactly (every pair of edges, in i128); anything else is unsupported.
//! Clipping is the textbook O(n²)–O(n³) loop: a strictly convex vertex is
//! an ear when no other vertex lies in its closed triangle; a straight
//! vertex (on the segment of its neighbours) is dropped, which changes no
//! region.

use super::contour::{single_contour, turn};
use super::scanline::Point;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::fixed::{EdgeInt, Fixed, Format};
use crate::production::setup;
use crate::production::traverse::{self, Sink};
use crate::rasterizer::RasterError;
use crate::scene::{Cull, Interpolation, Number, Polygon, Scene, Triangle, Vertex};

/// Whether segments ab and cd share any point, exactly.
fn segments_meet(a: Point, b: Point, c: Point, d: Point) -> bool {
    // Bounding boxes first: cheap, and needed for the collinear case.
    let apart = |k: usize| a[k].max(b[k]) < c[k].min(d[k]) || c[k].max(d[k]) < a[k].min(b[k]);
    if apart(0) || apart(1) {
        return false;
    }
    let (o1, o2) = (turn(a, b, c).signum(), turn(a, b, d).signum());
    let (o3, o4) = (turn(c, d, a).signum(), turn(c, d, b).signum());
    if o1 == 0 && o2 == 0 {
        // Collinear, with overlapping boxes: they overlap.
        return true;
    }
    o1 * o2 <= 0 && o3 * o4 <= 0
}

/// Whether a closed contour without consecutive repeats is simple: no two
/// edges meet except consecutive ones at their shared vertex.
pub fn is_simple(points: &[Point]) -> bool {
    let n = points.len();
    if n < 3 {
        return false;
    }
    let edge = |i: usize| (points[i], points[(i + 1) % n]);
    for i in 0..n {
        let (a, b) = edge(i);
        // The next edge: only a reversal along the line makes them overlap.
        let c = points[(i + 2) % n];
        if turn(a, b, c) == 0 {
            let dot = i128::from(b[0] - a[0]) * i128::from(c[0] - b[0])
                + i128::from(b[1] - a[1]) * i128::from(c[1] - b[1]);
            if dot < 0 {
                return false;
            }
        }
        // Edges not adjacent to edge i (edge n−1 is adjacent to edge 0).
        let last = if i == 0 { n - 1 } else { n };
        for j in i + 2..last {
            let (c, d) = edge(j);
            if segments_meet(a, b, c, d) {
                return false;
            }
        }
    }
    true
}

/// Twice the signed area (positive clockwise on screen). Each term is below
/// 2^(2(15 + f) + 1) ≤ 2^65 and there are at most 4096 of them.
fn signed_area(points: &[Point]) -> i128 {
    let n = points.len();
    (0..n)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            i128::from(a[0]) * i128::from(b[1]) - i128::from(b[0]) * i128::from(a[1])
        })
        .sum()
}

/// Triangulates a simple contour by ear clipping. `None` only if no ear is
/// found, which the two-ears theorem rules out for simple polygons.
pub fn triangulate(points: &[Point]) -> Option<Vec<[Point; 3]>> {
    let n = points.len();
    let orientation = signed_area(points).signum();
    if n < 3 || orientation == 0 {
        return Some(Vec::new());
    }
    let mut next: Vec<usize> = (0..n).map(|i| (i + 1) % n).collect();
    let mut prev: Vec<usize> = (0..n).map(|i| (i + n - 1) % n).collect();
    let mut triangles = Vec::with_capacity(n - 2);
    let mut remaining = n;
    let mut i = 0;
    let mut stalled = 0;
    while remaining > 3 {
        let (p, q) = (prev[i], next[i]);
        let t = turn(points[p], points[i], points[q]).signum() * orientation;
        let clip = t == 0 || (t > 0 && is_ear(points, &next, p, i, q, orientation));
        if clip {
            if t != 0 {
                triangles.push([points[p], points[i], points[q]]);
            }
            next[p] = q;
            prev[q] = p;
            remaining -= 1;
            stalled = 0;
            i = p;
        } else {
            stalled += 1;
            if stalled > remaining {
                return None;
            }
            i = q;
        }
    }
    let (p, q) = (prev[i], next[i]);
    triangles.push([points[p], points[i], points[q]]);
    Some(triangles)
}

/// Whether no remaining vertex but p, i, q lies in the closed triangle
/// p, i, q (turning the polygon's way).
fn is_ear(
    points: &[Point],
    next: &[usize],
    p: usize,
    i: usize,
    q: usize,
    orientation: i128,
) -> bool {
    let (a, b, c) = (points[p], points[i], points[q]);
    let mut v = next[q];
    while v != p {
        let x = points[v];
        let inside = turn(a, b, x).signum() * orientation >= 0
            && turn(b, c, x).signum() * orientation >= 0
            && turn(c, a, x).signum() * orientation >= 0;
        if inside {
            return false;
        }
        v = next[v];
    }
    true
}

/// Draws a simple polygon as triangles, or says why it cannot.
pub fn draw(
    scene: &Scene,
    format: Format,
    index: usize,
    polygon: &Polygon,
    frame: &mut Frame,
) -> Result<(), RasterError> {
    let points = single_contour(scene, format, polygon, "polygon-tessellate")?;
    let flat = (0..points.len()).all(|i| {
        let n = points.len();
        turn(points[i], points[(i + 1) % n], points[(i + 2) % n]) == 0
    });
    if flat {
        // All vertices on one line: no nudged sample is inside.
        return Ok(());
    }
    if !is_simple(&points) {
        return Err(RasterError::Unsupported(
            "polygon-tessellate fills simple polygons only (one contour that neither touches nor crosses itself)"
                .to_owned(),
        ));
    }
    let triangles = triangulate(&points).ok_or_else(|| {
        RasterError::Failed("ear clipping found no ear in a simple polygon".to_owned())
    })?;
    // Production's triangle set-up and traversal, culling off, coverage
    // only.
    let plan = Plan::coverage_only();
    let corner = || Vertex::at(Number::ZERO, Number::ZERO);
    let triangle = Triangle {
        vertices: [corner(), corner(), corner()],
        interpolation: Interpolation::Linear,
    };
    let mut sink = Coverage { frame, index };
    for t in triangles {
        let positions = t.map(|p| p.map(Fixed));
        if format.fits_i64() {
            sink.triangle::<i64>(positions, &triangle, format, scene, &plan);
        } else {
            sink.triangle::<i128>(positions, &triangle, format, scene, &plan);
        }
    }
    Ok(())
}

/// Writes the pixels traversal covers, coverage only.
struct Coverage<'a> {
    frame: &'a mut Frame,
    index: usize,
}

impl Coverage<'_> {
    fn triangle<E: EdgeInt>(
        &mut self,
        positions: [[Fixed; 2]; 3],
        triangle: &Triangle,
        format: Format,
        scene: &Scene,
        plan: &Plan,
    ) {
        if let Some(setup) = setup::setup::<E>(
            positions,
            triangle,
            format,
            scene.rules.fill_rule,
            Cull::None,
            scene.canvas,
            plan,
        ) {
            traverse::traverse(&setup, self);
        }
    }
}

impl Sink for Coverage<'_> {
    fn span(&mut self, y: i64, x0: i64, x1: i64) {
        let row = y as usize * self.frame.width as usize;
        self.frame
            .hit_run(row + x0 as usize, row + x1 as usize, self.index);
    }
}
