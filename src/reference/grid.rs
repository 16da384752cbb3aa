//! The common integer grid of a scene: every snapped vertex and every sample
//! point is an integer multiple of 1/`scale` pixel, so every geometric test
//! is a sign of an integer expression.
//!
//! Antialiased scenes put their samples on the grid too: the scale is then
//! also a multiple of 2^position_bits, and sample s of every pixel is tested
//! as the pixel centre of the scene moved by (½ − offset_s)
//! ([`OnGrid::translated`]). A translation changes no orientation, no edge
//! ownership and no edge value, so one pixel-centre traversal serves every
//! sample.

use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

use super::exact::{ceil_div, fits_fast_path, floor_div, snap, ExactInt};
use crate::scene::{Number, Scene};

pub type Point<T> = [T; 2];

#[derive(Clone, Debug)]
pub struct Grid {
    pub scale: IBig,
}

impl Grid {
    /// `2^(bits+1)` for snapped scenes (pixel centres lie on odd multiples of
    /// 2^-(bits+1)); otherwise the least common multiple of 2 and every
    /// coordinate's denominator. With samples at multiples of
    /// 2^-position_bits, 2^position_bits divides the scale as well:
    /// `2^max(bits+1, position_bits)`, or the lcm with it.
    fn for_scene(
        scene: &Scene,
        positions: &[Vec<Point<RBig>>],
        position_bits: Option<u32>,
    ) -> Grid {
        let sample_bits = position_bits.unwrap_or(0).max(1) as usize;
        if let Some(bits) = scene.rules.subpixel_bits {
            return Grid {
                scale: IBig::ONE << (bits as usize + 1).max(sample_bits),
            };
        }
        // 2^sample_bits (at least 2) divides the scale.
        let mut scale = UBig::ONE << sample_bits;
        for p in positions.iter().flatten().flatten() {
            let d = p.denominator();
            let g = gcd(&scale, d);
            scale = &scale / &g * d;
        }
        Grid {
            scale: scale.into(),
        }
    }

    fn to_grid(&self, q: &RBig) -> IBig {
        let den = IBig::from(q.denominator().clone());
        q.numerator() * (&self.scale / den)
    }

    /// Grid coordinate of the centre of pixel column (or row) `i`.
    pub fn centre(&self, i: i64) -> IBig {
        IBig::from(i) * &self.scale + (&self.scale >> 1)
    }

    /// Pixel columns (or rows) whose centre lies within [lo, hi], clipped
    /// to [0, size).
    pub fn centre_range(&self, lo: &IBig, hi: &IBig, size: u32) -> std::ops::Range<u32> {
        let half = &self.scale >> 1;
        let first = ceil_div(&(lo - &half), &self.scale).max(IBig::ZERO);
        let last = floor_div(&(hi - &half), &self.scale).min(IBig::from(size) - IBig::ONE);
        if first > last {
            return 0..0;
        }
        let first: u32 = (&first).try_into().unwrap();
        let last: u32 = (&last).try_into().unwrap();
        first..last + 1
    }

    /// A length in pixels, as a fraction (numerator, denominator) of grid units.
    pub fn length(&self, n: &Number) -> (IBig, IBig) {
        (
            n.numerator() * &self.scale,
            IBig::from(n.denominator().clone()),
        )
    }
}

pub(super) fn gcd(a: &UBig, b: &UBig) -> UBig {
    let (mut a, mut b) = (a.clone(), b.clone());
    while b != UBig::ZERO {
        let r = &a % &b;
        a = b;
        b = r;
    }
    a
}

/// A scene's primitives on its grid.
pub struct OnGrid {
    pub grid: Grid,
    /// The snapped vertices of each primitive, in scene order.
    pub points: Vec<Vec<Point<IBig>>>,
    /// Whether every coordinate, samples included, fits the i128 path.
    pub fits_i128: bool,
}

/// The scene on the grid of its pixel centres.
pub fn on_grid(scene: &Scene) -> OnGrid {
    on_grid_sampled(scene, None)
}

/// The scene on a grid that also holds every multiple of
/// 2^-`position_bits` pixel, when given.
pub fn on_grid_sampled(scene: &Scene, position_bits: Option<u32>) -> OnGrid {
    let place = |n: &Number| match scene.rules.subpixel_bits {
        Some(bits) => snap(n, bits),
        None => n.as_rbig().clone(),
    };
    let positions: Vec<Vec<Point<RBig>>> = scene
        .primitives
        .iter()
        .map(|p| {
            p.vertices()
                .iter()
                .map(|v| [place(&v.x), place(&v.y)])
                .collect()
        })
        .collect();
    let grid = Grid::for_scene(scene, &positions, position_bits);
    let points: Vec<Vec<Point<IBig>>> = positions
        .iter()
        .map(|ps| {
            ps.iter()
                .map(|p| p.clone().map(|c| grid.to_grid(&c)))
                .collect()
        })
        .collect();
    let fits_i128 = fits(&grid, scene, &points);
    OnGrid {
        grid,
        points,
        fits_i128,
    }
}

/// Whether every vertex and every pixel centre of the canvas lies within
/// `exact::I128_COORD_BOUND`.
fn fits(grid: &Grid, scene: &Scene, points: &[Vec<Point<IBig>>]) -> bool {
    let far_corner = grid.centre(i64::from(scene.canvas.width.max(scene.canvas.height)));
    fits_fast_path(&far_corner) && points.iter().flatten().flatten().all(fits_fast_path)
}

impl OnGrid {
    /// Every vertex moved by `t` grid units. Testing the pixel centre c
    /// against the moved primitives is testing c − t against the originals:
    /// orient(a + t, b + t, c) = orient(a, b, c − t), and which edge owns a
    /// sample depends only on differences of vertices. The i128 proof is
    /// redone for the moved vertices (they may grow by |t|).
    pub fn translated(&self, scene: &Scene, t: &Point<IBig>) -> OnGrid {
        let points: Vec<Vec<Point<IBig>>> = self
            .points
            .iter()
            .map(|ps| ps.iter().map(|p| [&p[0] + &t[0], &p[1] + &t[1]]).collect())
            .collect();
        OnGrid {
            grid: self.grid.clone(),
            fits_i128: fits(&self.grid, scene, &points),
            points,
        }
    }

    /// The translation that brings sample `offset` (in units of
    /// 2^-position_bits pixel from the pixel's top-left corner) onto the
    /// pixel centre: (½ − offset) pixel, in grid units. The grid must come
    /// from [`on_grid_sampled`] with the same `position_bits`.
    pub fn sample_shift(&self, offset: [u32; 2], position_bits: u32) -> Point<IBig> {
        let unit = &self.grid.scale >> position_bits as usize;
        let half = &self.grid.scale >> 1;
        offset.map(|o| &half - IBig::from(o) * &unit)
    }
}

pub fn to_i128(v: &IBig) -> i128 {
    v.try_into().expect("checked by fits_fast_path")
}

/// (bx - ax)(py - ay) - (by - ay)(px - ax): positive when p lies clockwise
/// of a→b on screen (y down).
pub fn orient<T: ExactInt>(a: &Point<T>, b: &Point<T>, p: &Point<T>) -> T {
    let left = b[0].sub(&a[0]).mul(&p[1].sub(&a[1]));
    let right = b[1].sub(&a[1]).mul(&p[0].sub(&a[0]));
    left.sub(&right)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{parse_case, Limits};

    #[test]
    fn sample_grids_hold_the_offsets_and_shifts_redo_the_i128_proof() {
        // y = 2^-45 sets the grid to 2^45 per pixel; x = 2^15 − 1/4 then
        // lies 2^43 below the i128 bound of 2^60.
        let json = r#"{"name": "t", "canvas": {"width": 4, "height": 4},
            "rules": {"subpixel_bits": null},
            "primitives": [{"triangle": [["32767.75", "1/35184372088832"], [0, 0], [0, 1]]}],
            "effects": {"antialias": {"samples": 4}}}"#;
        let scene = parse_case(json, "t.json", &Limits::default()).unwrap();
        let on = on_grid_sampled(&scene, Some(8));
        assert_eq!(on.grid.scale, IBig::ONE << 45);
        assert!(on.fits_i128);
        // Offset 3/8 moves the vertex right by 1/8 pixel (2^42): still in.
        let shift = on.sample_shift([96, 32], 8);
        assert_eq!(shift[0], IBig::ONE << 42);
        assert!(on.translated(&scene, &shift).fits_i128);
        // Offset 1/8 moves it by 3/8 pixel (3·2^42): past 2^60.
        let shift = on.sample_shift([32, 160], 8);
        assert!(!on.translated(&scene, &shift).fits_i128);
        // Pixel centres of unsampled scenes keep the grid of old.
        assert_eq!(on_grid(&scene).grid.scale, IBig::ONE << 45);
        let snapped = parse_case(
            &json.replace(r#""subpixel_bits": null"#, r#""subpixel_bits": 4"#),
            "t.json",
            &Limits::default(),
        )
        .unwrap();
        assert_eq!(on_grid(&snapped).grid.scale, IBig::from(32u8));
        assert_eq!(
            on_grid_sampled(&snapped, Some(8)).grid.scale,
            IBig::from(256u16)
        );
    }
}
