//! Shifted passes: any sample pattern drawn as one single-sample pass per
//! sample slot, the scene shifted so that the slot's offset falls on the
//! pixel centre, which is where a single-sample driver samples.
//!
//! Slot s of every pixel lies at offset o_s from the pixel's top-left
//! corner. Moving the whole scene by c − o_s (c = (½, ½), the centre)
//! moves the point (x, y) + o_s of pixel (x, y) onto that pixel's centre,
//! so the pass's pixel (x, y) decides exactly slot s of pixel (x, y),
//! interpolating its depth and attributes there too. This is the
//! accumulation-buffer method. It is exact when the shift lies on the
//! driver's subpixel grid: a snapped vertex plus the shift is then on the
//! grid, so the driver's snapping and the shift commute, and its tie rule
//! sees the same geometry, translated. Reports name such results
//! "shifted passes", apart from native multisampling.

use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

use crate::plan::SamplePlan;

/// The shift of each sample slot's pass, in pixels, or why the pattern
/// cannot be drawn exactly by a driver that snaps to `driver_bits`: an
/// offset off its subpixel grid.
#[cfg_attr(not(feature = "vulkan"), allow(dead_code))]
pub(crate) fn shifts(aa: &SamplePlan, driver_bits: u32) -> Result<Vec<[RBig; 2]>, String> {
    let unit = 1u64 << aa.position_bits;
    aa.offsets
        .iter()
        .map(|offset| {
            offset
                .map(|o| {
                    let half = unit / 2;
                    let shift =
                        RBig::from_parts(IBig::from(half as i64 - i64::from(o)), UBig::from(unit));
                    on_grid(&shift, driver_bits).then_some(shift)
                })
                .into_iter()
                .collect::<Option<Vec<_>>>()
                .map(|s| [s[0].clone(), s[1].clone()])
                .ok_or_else(|| {
                    format!(
                        "sample offset ({}, {})/2^{} is off the driver's grid of 1/2^{} pixel: \
                         shifted passes would move the scene off it",
                        offset[0], offset[1], aa.position_bits, driver_bits
                    )
                })
        })
        .collect()
}

/// Whether `q` is a multiple of 2^-bits.
fn on_grid(q: &RBig, bits: u32) -> bool {
    (q * RBig::from(UBig::ONE << bits as usize)).is_int()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plan(offsets: Vec<[u32; 2]>, position_bits: u32) -> SamplePlan {
        SamplePlan {
            offsets,
            position_bits,
            adaptive: false,
        }
    }

    #[test]
    fn a_slot_at_the_centre_needs_no_shift_and_others_move_onto_it() {
        let shifts = shifts(&plan(vec![[128, 128], [96, 32]], 8), 8).unwrap();
        assert_eq!(shifts[0], [RBig::ZERO, RBig::ZERO]);
        // (0.375, 0.125) moves by (0.125, 0.375) onto (0.5, 0.5).
        assert_eq!(
            shifts[1],
            [
                RBig::from_parts(1.into(), 8u8.into()),
                RBig::from_parts(3.into(), 8u8.into())
            ]
        );
    }

    #[test]
    fn offsets_off_the_driver_grid_are_refused() {
        assert!(shifts(&plan(vec![[1, 0]], 16), 8).is_err());
        assert!(shifts(&plan(vec![[256, 0]], 16), 8).is_ok());
        assert!(shifts(&plan(vec![[15, 3]], 4), 8).is_ok());
    }
}
