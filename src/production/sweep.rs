//! Coverage-only triangles swept band by band: production's fast road for
//! the commonest scene, and the tiled method's work on each thread.
//!
//! Drawing triangle by triangle, a frame larger than the cache is fetched
//! from memory once per triangle that covers a pixel: large triangles
//! overlap many times, small ones scatter. The sweep instead walks the
//! rows a band at a time (a few rows whose counts and owners fit the
//! cache), and in each band every triangle that reaches it, in scene
//! order, each from where its walk stopped in the band above
//! ([`Walker`]). Bands are disjoint, and within one the triangles keep
//! scene order, so every sample gets the same count and the same last
//! primitive as drawing triangle by triangle; each triangle is still set
//! up once, and its edges' crossings are stepped row by row as in
//! `traverse.rs`.

use super::fixed::{EdgeInt, Fixed, Format};
use super::setup::{self, Footprint};
use super::traverse::{self, Sink, Walker};
use crate::frame::cover_run;
use crate::plan::Plan;
use crate::scene::{Primitive, Scene};

/// The bytes of counts and owners one band keeps in the cache: half a
/// typical 512 KiB second-level cache.
const BAND_BYTES: usize = 256 << 10;

/// Pixel rows per band on a canvas `width` pixels wide: at least one, at
/// most what [`BAND_BYTES`] holds (a count and an owner per pixel).
pub(crate) fn band_rows(width: u32) -> i64 {
    let per_row = width.max(1) as usize * (2 + 4);
    (BAND_BYTES / per_row).clamp(1, 64) as i64
}

/// The frame's counts and owners for rows `rows_from..` (as many as the
/// slices hold), `width` pixels wide.
pub(crate) struct Rows<'a> {
    pub coverage: &'a mut [u16],
    pub last: &'a mut [u32],
    pub width: usize,
    pub rows_from: i64,
}

/// Draws the triangles `points` holds (primitive index and vertices in
/// `format`, in scene order; every primitive a triangle) into `rows`,
/// coverage only, band by band.
pub(crate) fn sweep<E: EdgeInt>(
    scene: &Scene,
    format: Format,
    points: &[(usize, [[Fixed; 2]; 3])],
    rows: Rows<'_>,
) {
    let height = (rows.coverage.len() / rows.width.max(1)) as i64;
    if height == 0 {
        return;
    }
    let (first_row, end_row) = (rows.rows_from, rows.rows_from + height);
    let band = band_rows(scene.canvas.width);
    let bands = (height + band - 1) / band;
    // Each triangle set up once, in scene order, and binned by the band
    // of its first row: each bin in scene order.
    let plan = Plan::coverage_only();
    let mut walkers: Vec<(u32, Walker<E>)> = Vec::with_capacity(points.len());
    let mut bins: Vec<Vec<u32>> = (0..bands).map(|_| Vec::new()).collect();
    for (k, &(index, vertices)) in points.iter().enumerate() {
        if k % 256 == 0 {
            crate::deadline::check();
        }
        // Rows wholly above or below these rows: nothing to set up. A
        // row's centre lies within a pixel of the vertices' extent.
        let one = format.one();
        let ys = vertices.map(|v| v[1].0.div_euclid(one));
        let (top, bottom) = (ys.iter().min().unwrap(), ys.iter().max().unwrap());
        if bottom + 1 < first_row || *top > end_row {
            continue;
        }
        let Primitive::Triangle(triangle) = &scene.primitives[index] else {
            unreachable!("the sweep draws triangles only");
        };
        let Some(setup) = setup::setup_in::<E>(
            vertices,
            triangle,
            format,
            scene.rules.fill_rule,
            scene.rules.cull,
            scene.canvas,
            &plan,
            |_, _| None,
            Footprint::Centres,
        ) else {
            continue;
        };
        if setup.bounds.y1 <= first_row || setup.bounds.y0 >= end_row {
            continue;
        }
        let Some(walker) = Walker::new(&setup, first_row) else {
            continue;
        };
        let b = ((walker.row() - first_row) / band) as usize;
        if b < bins.len() {
            bins[b].push(walkers.len() as u32);
            walkers.push((index as u32 + 1, walker));
        }
    }
    // The walkers stay where they are; the bands pass their places round.
    let mut sink = RowSink { rows, number: 0 };
    let mut active: Vec<u32> = Vec::new();
    let mut next: Vec<u32> = Vec::new();
    for (b, entering) in bins.iter().enumerate() {
        crate::deadline::check();
        let until = (first_row + (b as i64 + 1) * band).min(end_row);
        // The triangles still walking and those starting here, merged in
        // scene order (the order of their places).
        next.clear();
        let mut entering = entering.iter().copied().peekable();
        for &walking in &active {
            while let Some(new) = entering.next_if(|&new| new < walking) {
                next.push(new);
            }
            next.push(walking);
        }
        next.extend(entering);
        next.retain(|&k| {
            let (number, walker) = &mut walkers[k as usize];
            sink.number = *number;
            walker.walk(until, &mut sink);
            !walker.done()
        });
        std::mem::swap(&mut active, &mut next);
    }
}

/// Writes spans into a [`Rows`], as `Frame::hit_run` does.
struct RowSink<'a> {
    rows: Rows<'a>,
    /// The primitive being walked, 1-based.
    number: u32,
}

impl Sink for RowSink<'_> {
    #[inline]
    fn span(&mut self, y: i64, x0: i64, x1: i64) {
        let row = (y - self.rows.rows_from) as usize * self.rows.width;
        let run = row + x0 as usize..row + x1 as usize;
        cover_run(
            &mut self.rows.coverage[run.clone()],
            &mut self.rows.last[run],
            self.number,
        );
    }

    #[inline]
    fn ahead(&mut self, y: i64, x0: i64, x1: i64) {
        let row = (y - self.rows.rows_from) as usize * self.rows.width;
        let run = row + x0 as usize..row + x1 as usize;
        traverse::prefetch(&self.rows.coverage[run.clone()]);
        traverse::prefetch(&self.rows.last[run]);
    }
}
