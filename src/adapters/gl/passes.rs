//! Passes: the scene drawn once per sample slot, each pass in a tile of
//! one framebuffer, side by side.
//!
//! A scene without antialiasing is one pass at the pixel centres. An
//! antialiased one is drawn by **shifted passes** (`gpu::shifts`): for
//! sample slot s, the whole scene moved by the shift that brings slot s's
//! offset onto the pixel centre, where the single-sample driver samples,
//! so that the pass's pixel (x, y) decides slot s of pixel (x, y). The
//! shift moves the viewport (`gpu/stream.rs`: its corner off the integers,
//! set by `glViewportIndexedf`), so that a driver clipping at it clips
//! every pass at one rectangle of the case (SPEC.md §16.9). The
//! passes are drawn into tiles of `P × Q` texels laid out in a grid in one
//! framebuffer (at most the driver's largest side), each with its own
//! viewport and scissor, so that one clear, one draw and one read-back
//! cover every pass, and the bench times them as one draw.
//!
//! Shifted passes are exact only when the shift commutes with the
//! driver's own snapping: a shift on its 8-bit grid, added to vertices on
//! that grid (`subpixel_bits` ≤ 8). Mesa rounds a finer vertex to 8 bits
//! with ties to even, which a shift by an odd multiple of 1/256 does not
//! commute with, so antialiased cases with more bits are unsupported.
//!
//! A [`Layout`] is what every way of drawing here produces: streams (each
//! a placement of the scene, its runs indexing one shared vertex array),
//! passes (a stream drawn in a tile, over the canvas or scissored to one
//! pixel: `time.rs`'s time passes), and how the tiles are read back.

use dashu_ratio::RBig;

use crate::adapters::gpu::{self, VERTEX_FLOATS};
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::Scene;

/// The subpixel bits Mesa's GL snaps to.
pub(super) const DRIVER_BITS: u32 = 8;

/// One pass: a stream drawn with the viewport on the tile whose lower-left
/// window corner is `origin`, scissored to the canvas or to one pixel.
pub(super) struct Pass {
    pub origin: (u32, u32),
    /// An index into [`Layout::streams`].
    pub stream: usize,
    /// The canvas pixel (x, y down) a time pass is scissored to; `None`:
    /// the whole canvas.
    pub pixel: Option<(u32, u32)>,
}

/// How a drawing's tiles become a frame.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Reading {
    /// Pass s's tile fills sample slot s of every pixel.
    Slots,
    /// One tile's counts over `tests` time tests per pixel: time coverage.
    Time { tests: u32 },
    /// One pass into a target of `samples` samples a pixel (`msaa.rs`):
    /// each (driver sample, slot) of `read` fills that slot of every pixel.
    Samples {
        samples: u32,
        read: Vec<(u32, usize)>,
    },
}

impl Reading {
    /// The samples a pixel of the target has: 0 for a single-sample one.
    pub(super) fn target_samples(&self) -> u32 {
        match self {
            Reading::Samples { samples, .. } => *samples,
            _ => 0,
        }
    }
}

/// Every stream in one vertex array, the passes drawing them, and how
/// they are read back.
pub(super) struct Layout {
    pub vertices: Vec<f32>,
    /// Each stream's runs, indexing `vertices`.
    pub streams: Vec<Vec<gpu::Run>>,
    /// Each stream's viewport corner (`gpu::Stream::viewport_corner`): the
    /// view's, moved by its placement's shift.
    pub corners: Vec<[f32; 2]>,
    pub passes: Vec<Pass>,
    /// The framebuffer holding every tile.
    pub size: (u32, u32),
    pub reading: Reading,
}

impl Layout {
    /// An empty layout over a framebuffer of `size`.
    pub(super) fn new(size: (u32, u32), reading: Reading) -> Layout {
        Layout {
            vertices: Vec::new(),
            streams: Vec::new(),
            corners: Vec::new(),
            passes: Vec::new(),
            size,
            reading,
        }
    }

    /// Appends `stream`'s vertices and its runs, and returns its index.
    pub(super) fn push(&mut self, stream: gpu::Stream) -> usize {
        let base = (self.vertices.len() / VERTEX_FLOATS) as u32;
        self.vertices.extend(stream.vertices);
        self.corners.push(stream.viewport_corner);
        self.streams.push(
            stream
                .runs
                .into_iter()
                .map(|run| gpu::Run {
                    first: run.first + base,
                    end: run.end + base,
                    ..run
                })
                .collect(),
        );
        self.streams.len() - 1
    }

    /// Whether any stream counts a polygon's winding in the stencil.
    pub(super) fn stencils(&self) -> bool {
        self.streams
            .iter()
            .flatten()
            .any(|run| matches!(run.draw, gpu::Draw::Stencil(_)))
    }
}

/// The shift of each sample slot's pass (one zero shift without
/// antialiasing), or why shifted passes would not be exact: vertices
/// finer than the driver's grid, or offsets off it.
pub(super) fn shifts(plan: &Plan, bits: u32) -> Result<Vec<[RBig; 2]>, RasterError> {
    let Some(aa) = &plan.antialias else {
        return Ok(vec![[RBig::ZERO, RBig::ZERO]]);
    };
    if bits > DRIVER_BITS {
        return Err(RasterError::Unsupported(format!(
            "antialiasing by shifted passes with subpixel_bits {bits}: Mesa rounds \
             vertices to {DRIVER_BITS} bits, ties to even, which a shift does not \
             commute with"
        )));
    }
    gpu::shifts(aa, DRIVER_BITS)
        .map_err(|why| RasterError::Unsupported(format!("antialiasing by shifted passes: {why}")))
}

/// The passes `scene` is drawn in, each in a `tile` (`P × Q`) through
/// `view` (`gpu/view.rs`), or why they cannot be drawn exactly: an
/// antialiased scene whose shifts leave the driver's grid, or whose tiles
/// do not fit in `max_side`.
pub(super) fn layout(
    scene: &Scene,
    plan: &Plan,
    bits: u32,
    (tile, view): ((u32, u32), gpu::View),
    max_side: u32,
) -> Result<Layout, RasterError> {
    let shifts = shifts(plan, bits)?;
    let n = shifts.len() as u32;
    let columns = (max_side / tile.0).clamp(1, n);
    let rows = n.div_ceil(columns);
    if u64::from(rows) * u64::from(tile.1) > u64::from(max_side) {
        return Err(RasterError::Unsupported(format!(
            "{n} shifted passes of {}×{} do not fit in the driver's {max_side}×{max_side}",
            tile.0, tile.1
        )));
    }
    let size = (columns * tile.0, rows * tile.1);
    let mut layout = Layout::new(size, Reading::Slots);
    for (k, shift) in shifts.into_iter().enumerate() {
        let k = k as u32;
        let place = gpu::Placement {
            shift,
            ..gpu::Placement::at_centres(bits, view)
        };
        let stream = layout.push(gpu::Stream::new(scene, &place));
        layout.passes.push(Pass {
            origin: ((k % columns) * tile.0, (k / columns) * tile.1),
            stream,
            pixel: None,
        });
    }
    Ok(layout)
}
