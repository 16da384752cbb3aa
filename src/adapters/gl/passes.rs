//! Passes: the scene drawn once per sample slot, each pass in a tile of
//! one framebuffer, side by side.
//!
//! A scene without antialiasing is one pass at the pixel centres. An
//! antialiased one is drawn by **shifted passes** (`gpu::shifts`): for
//! sample slot s, the whole scene moved by the shift that brings slot s's
//! offset onto the pixel centre, where the single-sample driver samples,
//! so that the pass's pixel (x, y) decides slot s of pixel (x, y). The
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

use crate::adapters::gpu::{self, VERTEX_FLOATS};
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::Scene;

/// The subpixel bits Mesa's GL snaps to.
pub(super) const DRIVER_BITS: u32 = 8;

/// One pass: the runs of its stream (vertex indices into the shared
/// buffer) and the window position of its tile's lower-left corner.
pub(super) struct Pass {
    pub origin: (u32, u32),
    pub runs: Vec<gpu::Run>,
}

/// Every pass's stream in one vertex array, and where each pass is drawn.
pub(super) struct Layout {
    pub vertices: Vec<f32>,
    pub passes: Vec<Pass>,
    /// The framebuffer holding every tile.
    pub size: (u32, u32),
}

/// The passes `scene` is drawn in, each in a `tile` (`P × Q`), or why
/// they cannot be drawn exactly: an antialiased scene whose shifts leave
/// the driver's grid, or whose tiles do not fit in `max_side`.
pub(super) fn layout(
    scene: &Scene,
    plan: &Plan,
    bits: u32,
    tile: (u32, u32),
    max_side: u32,
) -> Result<Layout, RasterError> {
    let shifts = match &plan.antialias {
        None => vec![gpu::Placement::at_centres(bits, tile).shift],
        Some(aa) => {
            if bits > DRIVER_BITS {
                return Err(RasterError::Unsupported(format!(
                    "antialiasing by shifted passes with subpixel_bits {bits}: Mesa rounds \
                     vertices to {DRIVER_BITS} bits, ties to even, which a shift does not \
                     commute with"
                )));
            }
            gpu::shifts(aa, DRIVER_BITS).map_err(|why| {
                RasterError::Unsupported(format!("antialiasing by shifted passes: {why}"))
            })?
        }
    };
    let n = shifts.len() as u32;
    let columns = (max_side / tile.0).clamp(1, n);
    let rows = n.div_ceil(columns);
    if u64::from(rows) * u64::from(tile.1) > u64::from(max_side) {
        return Err(RasterError::Unsupported(format!(
            "{n} shifted passes of {}×{} do not fit in the driver's {max_side}×{max_side}",
            tile.0, tile.1
        )));
    }
    let mut layout = Layout {
        vertices: Vec::new(),
        passes: Vec::with_capacity(shifts.len()),
        size: (columns * tile.0, rows * tile.1),
    };
    for (k, shift) in shifts.into_iter().enumerate() {
        let k = k as u32;
        let place = gpu::Placement {
            shift,
            ..gpu::Placement::at_centres(bits, tile)
        };
        let stream = gpu::Stream::new(scene, &place);
        let base = (layout.vertices.len() / VERTEX_FLOATS) as u32;
        layout.vertices.extend(stream.vertices);
        layout.passes.push(Pass {
            origin: ((k % columns) * tile.0, (k / columns) * tile.1),
            runs: stream
                .runs
                .into_iter()
                .map(|run| gpu::Run {
                    first: run.first + base,
                    end: run.end + base,
                    ..run
                })
                .collect(),
        });
    }
    Ok(layout)
}
