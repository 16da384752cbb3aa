//! Convex-polygon span fill: the contour splits at its highest and lowest
//! vertices into two chains, each monotone in y, and on every sample row
//! one edge of each chain is active; the span lies between their two
//! crossings. No edge table, no sorting: the textbook fill for convex
//! polygons (and what GPUs do for triangles in scanline hardware).
//!
//! Exact, with the crossings and the row ranges of the scanline fill
//! ([`super::scanline`]). Convexity is decided exactly: every turn the same
//! way (or straight, never back), and one revolution in all. Anything else,
//! and polygons of several contours, is unsupported.

use super::contour::{nudge, single_contour, turn};
use super::scanline::{write_span, Point, Samples, Walk};
use crate::frame::Frame;
use crate::production::fixed::Format;
use crate::rasterizer::RasterError;
use crate::scene::{Canvas, Polygon, Scene};

/// What the exact test says of a contour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// Every turn the same way or straight, turning once in all.
    Convex,
    /// All vertices on one line: the polygon covers nothing.
    Flat,
    NotConvex,
}

/// Decides exactly whether a closed contour without repeated consecutive
/// vertices is convex.
///
/// All turns the same way (none reversing along a line) make the edge
/// direction rotate monotonically, by less than π per vertex; over the
/// contour it rotates 2πk, k ≥ 1, and the sign of dy changes 2k times.
/// The contour is convex exactly when k = 1. (A pentagram turns one way at
/// every vertex, with k = 2.)
pub fn shape(points: &[Point]) -> Shape {
    let n = points.len();
    if n < 3 {
        return Shape::Flat;
    }
    let at = |i: usize| points[i % n];
    let mut sign = 0i128;
    let mut reverses = false;
    for i in 0..n {
        let (a, b, c) = (at(i), at(i + 1), at(i + 2));
        let t = turn(a, b, c);
        if t == 0 {
            let dot = i128::from(b[0] - a[0]) * i128::from(c[0] - b[0])
                + i128::from(b[1] - a[1]) * i128::from(c[1] - b[1]);
            reverses |= dot < 0;
        } else if sign == 0 {
            sign = t.signum();
        } else if sign != t.signum() {
            return Shape::NotConvex;
        }
    }
    if sign == 0 {
        return Shape::Flat;
    }
    if reverses {
        return Shape::NotConvex;
    }
    let signs: Vec<bool> = (0..n)
        .map(|i| at(i + 1)[1] - at(i)[1])
        .filter(|&dy| dy != 0)
        .map(|dy| dy > 0)
        .collect();
    let changes = (0..signs.len())
        .filter(|&i| signs[i] != signs[(i + 1) % signs.len()])
        .count();
    if changes == 2 {
        Shape::Convex
    } else {
        Shape::NotConvex
    }
}

/// One chain's non-horizontal edges, top to bottom, with their drawn rows.
fn chain(
    points: &[Point],
    start: usize,
    forward: bool,
    samples: &Samples,
    canvas: Canvas,
) -> Vec<(i64, i64, Point, Point)> {
    let n = points.len();
    let bottom = points.iter().map(|p| p[1]).max().expect("three vertices");
    let mut edges = Vec::new();
    let mut i = start;
    while points[i][1] < bottom {
        let j = if forward {
            (i + 1) % n
        } else {
            (i + n - 1) % n
        };
        let (a, b) = (points[i], points[j]);
        if a[1] < b[1] {
            let (k0, k1) = samples.rows_on(a[1], b[1], canvas);
            if k0 < k1 {
                edges.push((k0, k1, a, b));
            }
        }
        i = j;
    }
    edges
}

/// Draws a convex polygon, or says why it cannot.
pub fn draw(
    scene: &Scene,
    format: Format,
    index: usize,
    polygon: &Polygon,
    frame: &mut Frame,
) -> Result<(), RasterError> {
    let points = single_contour(scene, format, polygon, "polygon-convex")?;
    match shape(&points) {
        Shape::Flat => return Ok(()),
        Shape::NotConvex => {
            return Err(RasterError::Unsupported(
                "polygon-convex fills convex polygons only".to_owned(),
            ))
        }
        Shape::Convex => {}
    }
    let half = format.centre(0).0;
    let samples = Samples {
        one: format.one(),
        offset: [half, half],
        slot: 0,
        nudge: nudge(scene)?,
    };
    let top = (0..points.len())
        .min_by_key(|&i| points[i][1])
        .expect("three vertices");
    let chains = [true, false].map(|forward| chain(&points, top, forward, &samples, scene.canvas));
    // Both chains cover the same rows, one active edge each per row.
    let mut walks = chains.each_ref().map(|c| {
        c.first()
            .map(|&(k0, _, a, b)| (0usize, Walk::new(a, b, k0, &samples)))
    });
    let (Some(first), Some(last)) = (
        chains[0].first().map(|e| e.0),
        chains[0].last().map(|e| e.1),
    ) else {
        return Ok(());
    };
    for row in first..last {
        let mut columns = [0i64; 2];
        for (side, edges) in chains.iter().enumerate() {
            let Some((at, walk)) = walks[side].as_mut() else {
                return Ok(());
            };
            // Move to the edge active on this row.
            while edges[*at].1 <= row {
                *at += 1;
                let Some(&(k0, _, a, b)) = edges.get(*at) else {
                    return Ok(());
                };
                *walk = Walk::new(a, b, k0, &samples);
            }
            if edges[*at].0 > row {
                return Err(RasterError::Failed(
                    "a convex chain has no edge on a row".to_owned(),
                ));
            }
            columns[side] = walk.column();
            walk.step();
        }
        let [x0, x1] = [columns[0].min(columns[1]), columns[0].max(columns[1])];
        write_span(frame, row, x0, x1, &samples, index);
    }
    Ok(())
}
