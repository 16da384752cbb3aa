//! Random numbers for the fuzzer: SplitMix64 ([`Rng`]), one stream per case
//! so that case `i` of a seed is regenerated without the ones before it, and
//! sines by a fixed polynomial, the same bits on every machine. No clock
//! here: the search's `clock_seed` is the only one.

/// SplitMix64 (Steele, Lea and Flood, OOPSLA 2014): a small, fast,
/// well-mixed generator whose stream depends only on its seed.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    /// The stream of case `index` of a run with `seed`.
    pub fn for_case(seed: u64, index: u64) -> Rng {
        let mut mix = Rng(seed ^ index.wrapping_mul(0xD1B5_4A32_D192_ED03));
        Rng(mix.next_u64())
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, n), n > 0.
    pub fn below(&mut self, n: u64) -> u64 {
        ((u128::from(self.next_u64()) * u128::from(n)) >> 64) as u64
    }

    /// Uniform in [lo, hi), lo < hi.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.below((hi - lo) as u64) as i64
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// True with probability `num / den`.
    pub fn chance(&mut self, num: u64, den: u64) -> bool {
        self.below(den) < num
    }

    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len() as u64) as usize]
    }
}

/// sin and cos by a fixed Taylor polynomial: the same bits on every machine
/// (only IEEE +, −, ×, ÷ and remainder), unlike the platform's libm.
pub(super) fn sin_cos(angle: f64) -> (f64, f64) {
    let pi = std::f64::consts::PI;
    let mut x = angle % std::f64::consts::TAU;
    if x > pi {
        x -= std::f64::consts::TAU;
    } else if x < -pi {
        x += std::f64::consts::TAU;
    }
    let (mut s, mut c) = (0.0, 0.0);
    let (mut ts, mut tc) = (x, 1.0);
    for k in 0..16 {
        s += ts;
        c += tc;
        let k = f64::from(k);
        ts *= -x * x / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
        tc *= -x * x / ((2.0 * k + 1.0) * (2.0 * k + 2.0));
    }
    (s, c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sines_are_close_to_libm() {
        for k in -50..50 {
            let a = f64::from(k) * 0.37;
            let (s, c) = sin_cos(a);
            assert!((s - a.sin()).abs() < 1e-12 && (c - a.cos()).abs() < 1e-12);
        }
    }
}
