//! The fixed-point format production draws a scene in, and each of the
//! scene's coordinates placed in it (snapped, or exact).

use super::antialias::sampling::Samples;
use super::fixed::{self, Fixed, Format};
use crate::rasterizer::RasterError;
use crate::scene::{Number, Scene};

/// The fixed-point format production draws `scene` in: the snapping grid
/// one bit finer, or the exact coordinates' own, at least as fine as the
/// sample offsets.
pub(crate) fn format_for(scene: &Scene, samples: Option<&Samples>) -> Result<Format, RasterError> {
    let format = match scene.rules.subpixel_bits {
        Some(bits) => Format::snapped(bits),
        None => {
            Format::for_exact(scene.vertices().flat_map(|v| [&v.x, &v.y])).ok_or_else(|| {
                RasterError::Unsupported(format!(
                    "unsnapped coordinates must be multiples of 2^-{} to be held in fixed point",
                    fixed::MAX_FRAC_BITS - 1
                ))
            })?
        }
    };
    // Sample offsets are integers in a format at least position_bits fine.
    Ok(match samples {
        Some(samples) => format.with_samples(samples.plan.position_bits),
        None => format,
    })
}

/// A coordinate in `format`, snapped or exact as the scene's rules say.
pub(crate) fn place(scene: &Scene, format: Format, n: &Number) -> Fixed {
    match scene.rules.subpixel_bits {
        Some(bits) => format.snap(n, bits),
        None => format
            .exact(n)
            .expect("format_for checked every coordinate"),
    }
}
