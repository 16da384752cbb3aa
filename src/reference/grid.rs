//! The common integer grid of a scene: every snapped vertex and every sample
//! point is an integer multiple of 1/`scale` pixel, so every geometric test
//! is a sign of an integer expression.

use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

use super::exact::{ceil_div, fits_fast_path, floor_div, snap, ExactInt};
use crate::scene::{Number, Scene};

pub type Point<T> = [T; 2];

pub struct Grid {
    pub scale: IBig,
}

impl Grid {
    /// `2^(bits+1)` for snapped scenes (pixel centres lie on odd multiples of
    /// 2^-(bits+1)); otherwise the least common multiple of 2 and every
    /// coordinate's denominator.
    fn for_scene(scene: &Scene, positions: &[Vec<Point<RBig>>]) -> Grid {
        if let Some(bits) = scene.rules.subpixel_bits {
            return Grid {
                scale: IBig::ONE << (bits as usize + 1),
            };
        }
        let mut scale = UBig::from(2u8);
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

fn gcd(a: &UBig, b: &UBig) -> UBig {
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

pub fn on_grid(scene: &Scene) -> OnGrid {
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
    let grid = Grid::for_scene(scene, &positions);
    let points: Vec<Vec<Point<IBig>>> = positions
        .iter()
        .map(|ps| {
            ps.iter()
                .map(|p| p.clone().map(|c| grid.to_grid(&c)))
                .collect()
        })
        .collect();
    let far_corner = grid.centre(i64::from(scene.canvas.width.max(scene.canvas.height)));
    let fits_i128 =
        fits_fast_path(&far_corner) && points.iter().flatten().flatten().all(fits_fast_path);
    OnGrid {
        grid,
        points,
        fits_i128,
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
