//! The classic foil: draw the outline with midpoint lines, then flood-fill
//! (4-connected) from seed pixels, filling the outline pixels too.
//!
//! A pixel is seeded when the fill has not reached it yet and its centre and
//! its eight neighbours' centres are inside by an f64 point-in-polygon test
//! (deep inside: a pixel barely inside may lie outside the outline's loop).
//! Parts too thin to hold a deep pixel get their outline only; a seed
//! outside the outline's loop, or a gap in it, floods what lies beyond. The outline covers every pixel
//! an edge runs through from the pixel of one vertex to the next, so thin
//! parts, slivers and edges are covered whether or not a sample is inside:
//! the fill departs from the exact rule, and that is what it is kept to
//! show. It is reported, never counted as a failure.

use super::contour::snapped;
use super::scanline::Point;
use crate::frame::Frame;
use crate::production::fixed::Format;
use crate::rasterizer::RasterError;
use crate::scene::{Polygon, PolygonFill, Scene};

const EMPTY: u8 = 0;
const OUTLINE: u8 = 1;
const FILLED: u8 = 2;

/// Integer midpoint (Bresenham) line from pixel a to pixel b, both ends
/// included, calling `plot` for each pixel.
fn midpoint_line(a: [i64; 2], b: [i64; 2], mut plot: impl FnMut(i64, i64)) {
    let (dx, dy) = ((b[0] - a[0]).abs(), -(b[1] - a[1]).abs());
    let (sx, sy) = ((b[0] - a[0]).signum(), (b[1] - a[1]).signum());
    let [mut x, mut y] = a;
    let mut error = dx + dy;
    loop {
        plot(x, y);
        if [x, y] == b {
            return;
        }
        let twice = 2 * error;
        if twice >= dy {
            error += dy;
            x += sx;
        }
        if twice <= dx {
            error += dx;
            y += sy;
        }
    }
}

/// Which of the centres (x + ½, py), x in x0..x0 + count, are inside by
/// an f64 winding number: the crossings of the row, sorted, counted from
/// the left.
fn row_inside(
    contours: &[Vec<[f64; 2]>],
    py: f64,
    x0: i64,
    count: i64,
    inside: impl Fn(i32) -> bool,
    out: &mut Vec<bool>,
) {
    let mut crossings: Vec<(f64, i32)> = Vec::new();
    for contour in contours {
        for (i, a) in contour.iter().enumerate() {
            let b = contour[(i + 1) % contour.len()];
            if (a[1] <= py) != (b[1] <= py) {
                let x = a[0] + (py - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
                crossings.push((x, if b[1] > a[1] { 1 } else { -1 }));
            }
        }
    }
    crossings.sort_by(|p, q| p.0.total_cmp(&q.0));
    let (mut next, mut winding) = (0, 0);
    for x in x0..x0 + count {
        let px = x as f64 + 0.5;
        while next < crossings.len() && crossings[next].0 < px {
            winding += crossings[next].1;
            next += 1;
        }
        out.push(inside(winding));
    }
}

/// Draws a polygon by outline and flood fill.
pub fn draw(
    scene: &Scene,
    format: Format,
    index: usize,
    polygon: &Polygon,
    frame: &mut Frame,
) -> Result<(), RasterError> {
    let contours: Vec<Vec<Point>> = snapped(scene, format, polygon)?;
    let (width, height) = (i64::from(frame.width), i64::from(frame.height));
    let one = format.one() as f64;
    let pixels: Vec<Vec<[f64; 2]>> = contours
        .iter()
        .map(|c| c.iter().map(|p| p.map(|v| v as f64 / one)).collect())
        .collect();
    let mut state = vec![EMPTY; frame.pixel_count()];
    let at = |x: i64, y: i64| (y * width + x) as usize;
    for contour in &pixels {
        for (i, a) in contour.iter().enumerate() {
            let b = contour[(i + 1) % contour.len()];
            let pixel = |p: [f64; 2]| p.map(|v| v.floor() as i64);
            midpoint_line(pixel(*a), pixel(b), |x, y| {
                if (0..width).contains(&x) && (0..height).contains(&y) {
                    state[at(x, y)] = OUTLINE;
                }
            });
        }
    }
    // Seeds within the polygon's bounding box only.
    let (lo, hi) = pixels.iter().flatten().fold(
        ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
        |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            )
        },
    );
    let range =
        |l: f64, h: f64, size: i64| (l.floor().max(0.0) as i64, (h.ceil() as i64 + 1).min(size));
    let (x0, x1) = range(lo[0], hi[0], width);
    let (y0, y1) = range(lo[1], hi[1], height);
    let inside = |w: i32| match polygon.fill {
        PolygonFill::EvenOdd => w & 1 != 0,
        PolygonFill::NonZero => w != 0,
    };
    // Centres inside by the f64 test, over the box and a margin of one.
    let (bx, by) = (x0 - 1, y0 - 1);
    let box_width = (x1 - x0 + 2).max(0);
    let box_height = (y1 - y0 + 2).max(0);
    let mut centre_inside = Vec::with_capacity((box_width * box_height) as usize);
    for y in by..by + box_height {
        row_inside(
            &pixels,
            y as f64 + 0.5,
            bx,
            box_width,
            inside,
            &mut centre_inside,
        );
    }
    // A seed is deep inside: its centre and its eight neighbours' are
    // inside. A pixel whose centre is barely inside may lie outside the
    // outline's loop, and a fill from it would flood the canvas.
    let deep = |x: i64, y: i64| {
        (-1..=1).all(|dy| {
            (-1..=1).all(|dx| centre_inside[((y + dy - by) * box_width + x + dx - bx) as usize])
        })
    };
    let mut stack = Vec::new();
    for y in y0..y1 {
        for x in x0..x1 {
            if state[at(x, y)] != EMPTY || !deep(x, y) {
                continue;
            }
            state[at(x, y)] = FILLED;
            stack.push((x, y));
            while let Some((x, y)) = stack.pop() {
                for (nx, ny) in [(x - 1, y), (x + 1, y), (x, y - 1), (x, y + 1)] {
                    if (0..width).contains(&nx)
                        && (0..height).contains(&ny)
                        && state[at(nx, ny)] == EMPTY
                    {
                        state[at(nx, ny)] = FILLED;
                        stack.push((nx, ny));
                    }
                }
            }
        }
    }
    for (i, &s) in state.iter().enumerate() {
        if s != EMPTY {
            frame.hit(i, index);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn midpoint_lines_are_eight_connected_and_end_at_both_ends() {
        for (a, b) in [
            ([0, 0], [7, 3]),
            ([5, 9], [1, 0]),
            ([2, 2], [2, -4]),
            ([0, 0], [-6, 6]),
        ] {
            let mut pixels = Vec::new();
            midpoint_line(a, b, |x, y| pixels.push([x, y]));
            assert_eq!(pixels.first(), Some(&a));
            assert_eq!(pixels.last(), Some(&b));
            let steps = (b[0] - a[0]).abs().max((b[1] - a[1]).abs());
            assert_eq!(pixels.len() as i64, steps + 1, "{a:?} to {b:?}: {pixels:?}");
        }
    }
}
