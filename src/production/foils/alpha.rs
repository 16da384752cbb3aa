//! `foil-alpha256`, `foil-alpha256-as-unorm` and `foil-alpha255`: area
//! methods that store each primitive's coverage of a pixel in one byte, as
//! 2D libraries do (issue 40). The area is `area-f32`'s; what differs is
//! the byte and what the foil says it means (SPEC.md §12.9):
//!
//! - `foil-alpha256` stores area × 256, rounded and capped at 255 (alpha
//!   over 256: a whole pixel is 255/256), and declares that encoding
//!   (`"fraction"`, 8 bits): its fractions are held within 1/256 of the
//!   exact area and its top code stands for a whole pixel;
//! - `foil-alpha256-as-unorm` stores the same bytes and declares the
//!   default encoding (8-bit `unorm`, steps of 1/255), as a library whose
//!   adapter reads alpha/256 as alpha/255 does: every whole pixel it draws
//!   is 255/256, not 1, and it is caught wherever a primitive covers one;
//! - `foil-alpha255` stores area × 255, rounded (alpha over 255, a whole
//!   pixel 255/255), and declares it: the unorm library `probe` must tell
//!   from alpha over 256.
//!
//! **Foils**: not exact (f32 areas), each wrong only where it says it is.
//! Antialiased scenes only, coverage only.

use crate::frame::{Frame, Parts};
use crate::plan::Plan;
use crate::production::antialias::area::{self, AreaF32};
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::Scene;

/// How a byte encodes coverage, and what the foil declares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Alpha {
    /// The byte is area × 256 capped at 255 (else area × 255).
    over_256: bool,
    /// It declares that encoding truly (else the 8-bit unorm default).
    declares: bool,
}

impl Alpha {
    /// `foil-alpha256`: alpha over 256, declared.
    pub const FRACTION: Alpha = Alpha {
        over_256: true,
        declares: true,
    };
    /// `foil-alpha256-as-unorm`: alpha over 256, read as alpha over 255.
    pub const FRACTION_AS_UNORM: Alpha = Alpha {
        over_256: true,
        declares: false,
    };
    /// `foil-alpha255`: alpha over 255, declared.
    pub const UNORM: Alpha = Alpha {
        over_256: false,
        declares: true,
    };

    /// The fraction a byte stands for: area × 256 rounded, capped at 255,
    /// over 256; or area × 255 rounded, over 255.
    pub fn encode(&self, area: f64) -> f64 {
        let area = area.clamp(0.0, 1.0);
        if self.over_256 {
            (area * 256.0).round().min(255.0) / 256.0
        } else {
            (area * 255.0).round() / 255.0
        }
    }

    /// The step and saturation it declares (`Parts::step`,
    /// `Parts::saturates`).
    fn declared(&self) -> (f64, bool) {
        if self.over_256 && self.declares {
            (1.0 / 256.0, true)
        } else {
            (1.0 / 255.0, false)
        }
    }
}

impl Rasterizer for Alpha {
    fn name(&self) -> &str {
        match (self.over_256, self.declares) {
            (true, true) => "foil-alpha256",
            (true, false) => "foil-alpha256-as-unorm",
            (false, _) => "foil-alpha255",
        }
    }

    fn is_foil(&self) -> bool {
        true
    }

    fn capabilities(&self) -> Capabilities {
        AreaF32.capabilities()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        if plan.antialias.is_none() {
            return Err(RasterError::Unsupported(format!(
                "{} answers antialiased scenes only",
                self.name()
            )));
        }
        if plan.interpolates() {
            return Err(RasterError::Unsupported(format!(
                "{} computes coverage only, not depth or attributes",
                self.name()
            )));
        }
        let mut resolved = vec![0.0; scene.canvas.pixel_count()];
        let mut coverage = vec![Vec::new(); scene.primitives.len()];
        area::each_primitive(scene, |index, areas| {
            for (p, &a) in areas.iter().enumerate() {
                let fraction = self.encode(a);
                if fraction != 0.0 {
                    resolved[p] += fraction;
                    coverage[index].push((p as u32, fraction));
                }
            }
        })?;
        let mut frame = Frame::resolved_only(scene.canvas.width, scene.canvas.height, resolved);
        let (step, saturates) = self.declared();
        frame.parts = Some(Parts {
            coverage,
            step,
            saturates,
        });
        frame.coverage_only = true;
        Ok(frame)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_whole_pixel_is_255_over_256_or_one() {
        assert_eq!(Alpha::FRACTION.encode(1.0), 255.0 / 256.0);
        assert_eq!(Alpha::FRACTION_AS_UNORM.encode(1.0), 255.0 / 256.0);
        assert_eq!(Alpha::UNORM.encode(1.0), 1.0);
        assert_eq!(Alpha::FRACTION.encode(0.5), 0.5);
        assert_eq!(Alpha::UNORM.encode(0.5), 128.0 / 255.0);
        assert_eq!(Alpha::FRACTION.encode(0.0), 0.0);
    }
}
