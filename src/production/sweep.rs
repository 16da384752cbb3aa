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
use crate::scene::{Interpolation, Number, Scene, Triangle, Vertex};

/// The bytes of counts and owners one band keeps in the cache: half a
/// typical 512 KiB second-level cache.
const BAND_BYTES: usize = 256 << 10;

/// Pixel rows per band on a canvas `width` pixels wide: at least one, at
/// most what [`BAND_BYTES`] holds (a count and an owner per pixel).
pub(crate) fn band_rows(width: u32) -> i64 {
    let per_row = width.max(1) as usize * (2 + 4);
    (BAND_BYTES / per_row).clamp(1, 64) as i64
}

/// How many rows a band of the sweep takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Band {
    /// As many as the cache holds ([`band_rows`]): for triangles that
    /// overlap, tall ones.
    Cached,
    /// All the rows at once: each triangle drawn whole in scene order, for
    /// small ones scattered over the frame.
    Whole,
}

/// Triangles at least this many pixel rows tall on average are swept in
/// cached bands: the sweep keeps the frame's rows in the cache while every
/// triangle over them is drawn, which pays once triangles overlap (as
/// large ones do); it costs a little per triangle, which small ones,
/// scattered and drawn once each, do not win back. The result is the same
/// either way.
const SWEEP_ROWS: i64 = 16;

/// Coverage-only triangles ready to be swept: their vertices in `format`
/// (each with its primitive's index, in scene order) and the band their
/// height calls for, both decided once, before any draw.
pub(crate) struct Swept {
    format: Format,
    triangles: Vec<(usize, [[Fixed; 2]; 3])>,
    band: Band,
}

impl Swept {
    pub(crate) fn new(format: Format, triangles: Vec<(usize, [[Fixed; 2]; 3])>) -> Swept {
        let band = band_for(&triangles, format);
        Swept {
            format,
            triangles,
            band,
        }
    }

    /// Sweeps the triangles of `scene` into `rows`, in the narrowest
    /// integers that hold the format's edge functions (the sweep moves no
    /// vertex).
    pub(crate) fn draw(&self, scene: &Scene, rows: Rows<'_>) {
        if self.format.fits_i64() {
            sweep::<i64>(scene, self.format, &self.triangles, rows, self.band);
        } else {
            sweep::<i128>(scene, self.format, &self.triangles, rows, self.band);
        }
    }
}

/// The band for `triangles`: [`Band::Cached`] when they are
/// [`SWEEP_ROWS`] tall on average.
fn band_for(triangles: &[(usize, [[Fixed; 2]; 3])], format: Format) -> Band {
    let rows: i64 = triangles
        .iter()
        .map(|(_, v)| {
            let ys = v.map(|p| p[1].0);
            (ys.iter().max().unwrap() - ys.iter().min().unwrap()) / format.one()
        })
        .sum();
    if !triangles.is_empty() && rows >= SWEEP_ROWS * triangles.len() as i64 {
        Band::Cached
    } else {
        Band::Whole
    }
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
/// `format`, in scene order; every one a triangle of `scene`) into
/// `rows`, coverage only, band by band.
fn sweep<E: EdgeInt>(
    scene: &Scene,
    format: Format,
    points: &[(usize, [[Fixed; 2]; 3])],
    rows: Rows<'_>,
    band: Band,
) {
    let height = (rows.coverage.len() / rows.width.max(1)) as i64;
    if height == 0 {
        return;
    }
    let (first_row, end_row) = (rows.rows_from, rows.rows_from + height);
    let band = match band {
        Band::Cached => band_rows(scene.canvas.width),
        Band::Whole => height,
    };
    let bands = (height + band - 1) / band;
    // Each triangle binned by the band of its first row, from its
    // vertices (each bin in scene order), and set up when the sweep gets
    // there, so that its walker is hot when first walked.
    let one = format.one();
    let mut bins: Vec<Vec<(usize, [[Fixed; 2]; 3])>> = (0..bands).map(|_| Vec::new()).collect();
    for &(index, vertices) in points {
        // A row's centre lies within a pixel of the vertices' extent.
        let ys = vertices.map(|v| v[1].0.div_euclid(one));
        let (top, bottom) = (*ys.iter().min().unwrap(), *ys.iter().max().unwrap());
        if bottom + 1 < first_row || top > end_row {
            continue;
        }
        let b = ((top - 1).max(first_row) - first_row) / band;
        if let Some(bin) = bins.get_mut(b as usize) {
            bin.push((index, vertices));
        }
    }
    // Coverage only: set-up never reads a vertex's values, so the scene's
    // primitives (large, and far apart in memory) are not touched again.
    let plan = Plan::coverage_only();
    let unshaded = Triangle {
        vertices: std::array::from_fn(|_| Vertex::at(Number::ZERO, Number::ZERO)),
        interpolation: Interpolation::Linear,
    };
    let mut sink = RowSink { rows, number: 0 };
    let mut active: Vec<(u32, Walker<E>)> = Vec::new();
    let mut next: Vec<(u32, Walker<E>)> = Vec::new();
    for (b, entering) in bins.iter().enumerate() {
        crate::deadline::check();
        let until = (first_row + (b as i64 + 1) * band).min(end_row);
        // The triangles still walking and those starting here, merged in
        // scene order, each walked through the band as it comes (a new
        // one right after its set-up, while it is in the cache); those
        // that go on below are kept.
        next.clear();
        let mut walk = |number: u32, mut walker: Walker<E>, next: &mut Vec<(u32, Walker<E>)>| {
            sink.number = number;
            walker.walk(until, &mut sink);
            if !walker.done() {
                next.push((number, walker));
            }
        };
        let mut walking = active.drain(..).peekable();
        for &(index, vertices) in entering {
            let number = index as u32 + 1;
            while let Some((n, w)) = walking.next_if(|w| w.0 < number) {
                walk(n, w, &mut next);
            }
            let walker = setup::setup_in::<E>(
                vertices,
                &unshaded,
                format,
                scene.rules.fill_rule,
                scene.rules.cull,
                scene.canvas,
                &plan,
                |_, _| None,
                Footprint::Centres,
            )
            .and_then(|setup| Walker::new(&setup, first_row));
            if let Some(walker) = walker {
                walk(number, walker, &mut next);
            }
        }
        for (n, w) in walking {
            walk(n, w, &mut next);
        }
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
