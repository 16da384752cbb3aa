//! Random numbers for the fuzzer: SplitMix64 ([`Rng`]), one stream per case
//! so that case `i` of a seed is regenerated without the ones before it, and
//! sines by a fixed polynomial, the same bits on every machine. No clock
//! here: the search's `clock_seed` is the only one.
//!
//! An [`Rng`] can also read its choices from a **tape** of bytes, as
//! libFuzzer's targets do (`fuzz/`, [`super::targets`]): each choice in
//! `[0, n)` takes the fewest whole bytes that can hold `n - 1`, big-endian,
//! reduced mod `n`. When the tape runs out the stream goes on with
//! SplitMix64 seeded from the tape, so every tape gives a scene. A stream
//! can **record** its choices in that encoding, so that the tape of a
//! generated case reads back as the same case: the seed corpus of the
//! scene target is made that way.

use std::sync::Arc;

/// SplitMix64 (Steele, Lea and Flood, OOPSLA 2014): a small, fast,
/// well-mixed generator whose stream depends only on its seed; or a tape of
/// choices (module docs).
#[derive(Clone, Debug)]
pub struct Rng {
    state: u64,
    tape: Option<(Arc<[u8]>, usize)>,
    record: Option<Vec<u8>>,
}

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng {
            state: seed,
            tape: None,
            record: None,
        }
    }

    /// The stream of case `index` of a run with `seed`.
    pub fn for_case(seed: u64, index: u64) -> Rng {
        let mut mix = Rng::new(seed ^ index.wrapping_mul(0xD1B5_4A32_D192_ED03));
        Rng::new(mix.next_u64())
    }

    /// Choices read from `tape`, then SplitMix64 seeded from it (FNV-1a).
    pub fn from_tape(tape: &[u8]) -> Rng {
        Rng {
            state: fnv1a(tape),
            tape: Some((tape.into(), 0)),
            record: None,
        }
    }

    /// This stream, writing down every choice it makes as tape bytes.
    pub fn recording(self) -> Rng {
        Rng {
            record: Some(Vec::new()),
            ..self
        }
    }

    /// The tape of the choices made since [`Rng::recording`].
    pub fn recorded(&self) -> &[u8] {
        self.record.as_deref().unwrap_or_default()
    }

    fn split_mix(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// `width` bytes of the tape, big-endian; `None` once it has run out
    /// (and from then on).
    fn read_tape(&mut self, width: usize) -> Option<u64> {
        let (tape, at) = self.tape.as_mut()?;
        let bytes = tape.get(*at..*at + width);
        let Some(bytes) = bytes else {
            self.tape = None;
            return None;
        };
        *at += width;
        Some(bytes.iter().fold(0, |v, &b| (v << 8) | u64::from(b)))
    }

    /// A choice in [0, 2^(8 × width)) (all of u64 for width 8).
    fn choice(&mut self, width: usize, from_stream: impl FnOnce(&mut Rng) -> u64) -> u64 {
        let v = match self.read_tape(width) {
            Some(v) => v,
            None => from_stream(self),
        };
        if let Some(record) = &mut self.record {
            record.extend_from_slice(&v.to_be_bytes()[8 - width..]);
        }
        v
    }

    pub fn next_u64(&mut self) -> u64 {
        self.choice(8, Rng::split_mix)
    }

    /// Uniform in [0, n), n > 0.
    pub fn below(&mut self, n: u64) -> u64 {
        debug_assert!(n > 0);
        if n <= 1 {
            return 0;
        }
        let width = (64 - (n - 1).leading_zeros()).div_ceil(8) as usize;
        let v = self.choice(width, |rng| {
            ((u128::from(rng.split_mix()) * u128::from(n)) >> 64) as u64
        });
        v % n
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

/// The 64-bit FNV-1a hash of `bytes`: a tape's fallback seed, and the
/// tag of the case file a crash input becomes.
pub(super) fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325_u64, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
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

    /// The stream is the one it always was: SplitMix64's published first
    /// output for seed 0, and `below` by multiply-high.
    #[test]
    fn the_stream_is_unchanged() {
        assert_eq!(Rng::new(0).next_u64(), 0xE220_A839_7B1D_CDAF);
        let mut a = Rng::new(9);
        let mut b = Rng::new(9);
        let x = a.below(1000);
        assert_eq!(x, ((u128::from(b.next_u64()) * 1000) >> 64) as u64);
    }

    /// A recorded stream reads back from its tape as the same choices, and a
    /// tape that runs out goes on without stopping.
    #[test]
    fn tapes_replay_recorded_choices() {
        let draw = |rng: &mut Rng| -> Vec<u64> {
            (1..300u64)
                .map(|i| match i % 4 {
                    0 => rng.next_u64(),
                    1 => rng.below(i),
                    2 => rng.below(1 << (i % 40)),
                    _ => rng.range(-5, 70_000) as u64,
                })
                .collect()
        };
        let mut rng = Rng::for_case(5, 3).recording();
        let draws = draw(&mut rng);
        let mut replay = Rng::from_tape(rng.recorded());
        let again = draw(&mut replay);
        assert_eq!(draws, again);
        assert!(replay.tape.is_some());
        let mut short = Rng::from_tape(&[7, 1]);
        assert_eq!(short.below(256), 7);
        assert!(
            short.below(300) < 300,
            "one byte left is too few for 300: the stream goes on"
        );
        assert!(short.tape.is_none());
        assert!((0..100).map(|_| short.below(10)).any(|v| v != 0));
    }
}
