//! Sample patterns: where the samples of an antialiased scene lie in each
//! pixel (SPEC.md §14.2).
//!
//! A pattern is part of what a case asks for, like its vertices, so it
//! lives in the scene model: the reference and production read the same
//! offsets, and neither decides them. Every offset is an exact multiple of
//! 2^-`position_bits` pixel, as GPUs quantize sample locations
//! (Vulkan's `sampleLocationSubPixelBits`), and the same offsets repeat in
//! every pixel. Seeded patterns come from SplitMix64, written out below so
//! that any program can reproduce them.

/// How the samples of a pattern are placed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pattern {
    /// k × k samples at the centres of a regular grid (N = k²); centres
    /// that are not on the position lattice round to it, ties to even.
    Grid,
    /// Vulkan's and D3D11's standard locations for 1, 2, 4, 8 and 16 samples.
    Standard,
    /// One uniformly random sample in each cell of a k × k grid (N = k²).
    Stratified,
    /// N independent uniformly random samples.
    Random,
    /// N samples, one in each of N columns and each of N rows, the rows
    /// shuffled: a Latin hypercube in two dimensions.
    NRooks,
}

case_names!(Pattern {
    Grid => "grid",
    Standard => "standard",
    Stratified => "stratified",
    Random => "random",
    NRooks => "n-rooks",
});

impl Pattern {
    /// Whether the seed changes the positions.
    pub fn is_seeded(self) -> bool {
        matches!(
            self,
            Pattern::Stratified | Pattern::Random | Pattern::NRooks
        )
    }

    /// Why `samples` is not a valid count for this pattern, if it is not.
    pub fn check_count(self, samples: u32) -> Result<(), String> {
        let square = integer_sqrt(samples).pow(2) == samples;
        match self {
            Pattern::Standard if !matches!(samples, 1 | 2 | 4 | 8 | 16) => Err(format!(
                "the standard pattern has 1, 2, 4, 8 or 16 samples, not {samples}"
            )),
            Pattern::Grid | Pattern::Stratified if !square => Err(format!(
                "a {} pattern has k × k samples (1, 4, 9, 16, …), not {samples}",
                self.name()
            )),
            _ => Ok(()),
        }
    }
}

/// Vulkan `standardSampleLocations` (the same as D3D11's), in 1/16 pixel,
/// y down.
const STANDARD_1: [[u32; 2]; 1] = [[8, 8]];
const STANDARD_2: [[u32; 2]; 2] = [[12, 12], [4, 4]];
const STANDARD_4: [[u32; 2]; 4] = [[6, 2], [14, 6], [2, 10], [10, 14]];
const STANDARD_8: [[u32; 2]; 8] = [
    [9, 5],
    [7, 11],
    [13, 9],
    [5, 3],
    [3, 13],
    [1, 7],
    [11, 15],
    [15, 1],
];
const STANDARD_16: [[u32; 2]; 16] = [
    [9, 9],
    [7, 5],
    [5, 10],
    [12, 7],
    [3, 6],
    [10, 13],
    [13, 11],
    [11, 3],
    [6, 14],
    [8, 1],
    [4, 2],
    [2, 12],
    [0, 8],
    [15, 4],
    [14, 15],
    [1, 0],
];

/// Antialiasing as a case asks for it (`effects.antialias`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Antialias {
    /// Samples per pixel, N.
    pub samples: u32,
    pub pattern: Pattern,
    /// Seed of the `stratified`, `random` and `n-rooks` patterns.
    pub seed: u64,
    /// Production samples only the pixels an edge touches; the others are
    /// wholly covered or wholly empty. The result must not change.
    pub adaptive: bool,
    /// Offsets are multiples of 2^-position_bits pixel.
    pub position_bits: u32,
}

/// Bounds on `effects.antialias`.
pub mod limits {
    /// Largest sample count.
    pub const MAX_SAMPLES: u32 = 256;
    /// The standard patterns lie on the 1/16 grid.
    pub const MIN_POSITION_BITS: u32 = 4;
    /// Offsets as fine as the finest snapping grid.
    pub const MAX_POSITION_BITS: u32 = 16;
    pub const DEFAULT_POSITION_BITS: u32 = 8;
}

impl Antialias {
    /// The offsets of the N samples from the pixel's top-left corner, in
    /// units of 2^-position_bits pixel, each in [0, 2^position_bits).
    pub fn offsets(&self) -> Vec<[u32; 2]> {
        let bits = self.position_bits;
        let one = 1u64 << bits;
        let n = self.samples;
        let mut rng = SplitMix64::new(self.seed);
        match self.pattern {
            Pattern::Standard => {
                let table: &[[u32; 2]] = match n {
                    1 => &STANDARD_1,
                    2 => &STANDARD_2,
                    4 => &STANDARD_4,
                    8 => &STANDARD_8,
                    _ => &STANDARD_16,
                };
                table.iter().map(|p| p.map(|c| c << (bits - 4))).collect()
            }
            Pattern::Grid => {
                let k = u64::from(integer_sqrt(n));
                // The centre of cell i is (2i + 1) / 2k, on the lattice
                // round((2i + 1)·2^bits / 2k), ties to even.
                let centre = |i: u64| round_half_even((2 * i + 1) * one, 2 * k) as u32;
                (0..k * k).map(|s| [centre(s % k), centre(s / k)]).collect()
            }
            Pattern::Stratified => {
                let k = u64::from(integer_sqrt(n));
                (0..k * k)
                    .map(|s| {
                        let x = ((s % k) * one + rng.below_power_of_two(bits)) / k;
                        let y = ((s / k) * one + rng.below_power_of_two(bits)) / k;
                        [x as u32, y as u32]
                    })
                    .collect()
            }
            Pattern::Random => (0..n)
                .map(|_| {
                    let x = rng.below_power_of_two(bits);
                    let y = rng.below_power_of_two(bits);
                    [x as u32, y as u32]
                })
                .collect(),
            Pattern::NRooks => {
                let n = u64::from(n);
                // Fisher–Yates from the top, as SPEC.md writes it.
                let mut rows: Vec<u64> = (0..n).collect();
                for i in (1..n).rev() {
                    let j = rng.next_u64() % (i + 1);
                    rows.swap(i as usize, j as usize);
                }
                (0..n)
                    .map(|i| {
                        let x = (i * one + rng.below_power_of_two(bits)) / n;
                        let y = (rows[i as usize] * one + rng.below_power_of_two(bits)) / n;
                        [x as u32, y as u32]
                    })
                    .collect()
            }
        }
    }
}

/// ⌊√n⌋.
fn integer_sqrt(n: u32) -> u32 {
    let mut r = (n as f64).sqrt() as u32;
    while r * r > n {
        r -= 1;
    }
    while (r + 1) * (r + 1) <= n {
        r += 1;
    }
    r
}

/// p / q rounded to the nearest integer, ties to even.
fn round_half_even(p: u64, q: u64) -> u64 {
    let (quotient, rest) = (p / q, p % q);
    match (2 * rest).cmp(&q) {
        std::cmp::Ordering::Less => quotient,
        std::cmp::Ordering::Greater => quotient + 1,
        std::cmp::Ordering::Equal => quotient + (quotient & 1),
    }
}

/// SplitMix64 (Steele, Lea and Flood 2014): the generator of the seeded
/// patterns.
#[derive(Clone, Debug)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    pub fn new(seed: u64) -> SplitMix64 {
        SplitMix64 { state: seed }
    }

    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform integer in [0, 2^bits): the top `bits` bits of the next
    /// output.
    pub fn below_power_of_two(&mut self, bits: u32) -> u64 {
        self.next_u64() >> (64 - bits)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn aa(samples: u32, pattern: Pattern) -> Antialias {
        Antialias {
            samples,
            pattern,
            seed: 7,
            adaptive: false,
            position_bits: 8,
        }
    }

    #[test]
    fn standard_four_is_vulkans() {
        let offsets = aa(4, Pattern::Standard).offsets();
        let as_f64: Vec<[f64; 2]> = offsets
            .iter()
            .map(|p| p.map(|c| f64::from(c) / 256.0))
            .collect();
        assert_eq!(
            as_f64,
            [
                [0.375, 0.125],
                [0.875, 0.375],
                [0.125, 0.625],
                [0.625, 0.875]
            ]
        );
    }

    #[test]
    fn standard_sixteen_touches_the_border() {
        let offsets = aa(16, Pattern::Standard).offsets();
        assert!(offsets.contains(&[0, 128]));
        assert!(offsets.contains(&[16, 0]));
    }

    #[test]
    fn grid_three_by_three_rounds_to_the_lattice() {
        let offsets = aa(9, Pattern::Grid).offsets();
        // 256/6 = 42.67 → 43, 256/2 = 128, 5·256/6 = 213.3 → 213.
        assert_eq!(offsets[0], [43, 43]);
        assert_eq!(offsets[4], [128, 128]);
        assert_eq!(offsets[8], [213, 213]);
    }

    #[test]
    fn stratified_and_n_rooks_keep_to_their_cells() {
        let s = aa(16, Pattern::Stratified).offsets();
        for (i, p) in s.iter().enumerate() {
            assert_eq!(p[0] / 64, i as u32 % 4);
            assert_eq!(p[1] / 64, i as u32 / 4);
        }
        let r = aa(8, Pattern::NRooks).offsets();
        let mut columns: Vec<u32> = r.iter().map(|p| p[0] / 32).collect();
        let mut rows: Vec<u32> = r.iter().map(|p| p[1] / 32).collect();
        columns.sort();
        rows.sort();
        assert_eq!(columns, (0..8).collect::<Vec<_>>());
        assert_eq!(rows, (0..8).collect::<Vec<_>>());
    }

    #[test]
    fn seeds_are_deterministic_and_matter() {
        let a = aa(16, Pattern::Random).offsets();
        assert_eq!(a, aa(16, Pattern::Random).offsets());
        let mut other = aa(16, Pattern::Random);
        other.seed = 8;
        assert_ne!(a, other.offsets());
    }

    #[test]
    fn counts_are_checked() {
        assert!(Pattern::Standard.check_count(3).is_err());
        assert!(Pattern::Grid.check_count(8).is_err());
        assert!(Pattern::Grid.check_count(9).is_ok());
        assert!(Pattern::Random.check_count(7).is_ok());
    }
}
