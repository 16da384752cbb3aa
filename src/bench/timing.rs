//! How the bench takes a time: the median of interleaved rounds, a
//! rasterizer timed inside its own rayon pool ([`OnPool`]), and the
//! machine's parallel ceiling measured in the same rounds
//! ([`ParallelCeiling`]). What is timed, and on which scene, is each
//! workload's file.

use std::time::{Duration, Instant};

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, Prepared, RasterError, Rasterizer};
use crate::scene::Scene;

pub(super) fn median(mut times: Vec<Duration>) -> Duration {
    times.sort();
    times[times.len() / 2]
}

/// A rasterizer run on a dedicated rayon pool: `production-tiled` on two
/// threads, whatever the machine.
pub struct OnPool {
    inner: Box<dyn Rasterizer>,
    pool: rayon::ThreadPool,
}

/// Threads of the tiled method's pool.
pub const TILED_THREADS: usize = 2;

impl OnPool {
    pub fn new(inner: Box<dyn Rasterizer>, threads: usize) -> OnPool {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a rayon pool");
        OnPool { inner, pool }
    }

    /// Rasterizes on the pool, timed there: from the moment a pool thread
    /// starts the job to its end. Handing the job over and waking the
    /// caller afterwards are left out, which on a loaded machine can take
    /// a scheduler time slice each.
    pub fn timed(&self, scene: &Scene, plan: &Plan) -> (Result<Frame, RasterError>, Duration) {
        self.pool.install(|| {
            let started = Instant::now();
            let result = self.inner.rasterize(scene, plan);
            (result, started.elapsed())
        })
    }
}

impl OnPool {
    /// A prepared draw run on the pool, timed there as [`OnPool::timed`].
    pub fn timed_draw(
        &self,
        prepared: &mut (dyn Prepared + '_),
    ) -> (Result<(), RasterError>, Duration) {
        self.pool.install(|| {
            let started = Instant::now();
            let result = prepared.draw();
            (result, started.elapsed())
        })
    }
}

impl Rasterizer for OnPool {
    fn name(&self) -> &str {
        self.inner.name()
    }

    fn capabilities(&self) -> Capabilities {
        self.inner.capabilities()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        self.pool.install(|| self.inner.rasterize(scene, plan))
    }

    /// The inner method's draw call; the bench runs its draws on the pool
    /// ([`OnPool::timed_draw`]).
    fn prepare<'a>(
        &'a self,
        scene: &'a Scene,
        plan: &'a Plan,
    ) -> Option<Result<Box<dyn Prepared + 'a>, RasterError>> {
        self.inner.prepare(scene, plan)
    }
}

/// The machine's parallel ceiling during a run: a perfectly parallel
/// integer loop (a dependent multiply–xorshift chain in registers, no
/// memory traffic) on a pool of [`TILED_THREADS`] threads split into as
/// many equal parts, against the whole loop on a pool of one thread. Each
/// is timed inside its pool, as `production-tiled` is ([`OnPool::timed`]).
/// On an idle machine the ratio is near the thread count; below it, other
/// work took the cores, and the tiled method cannot do better than this.
pub struct ParallelCeiling {
    one: rayon::ThreadPool,
    many: rayon::ThreadPool,
    /// Loop steps in all.
    steps: u64,
    times: [Vec<Duration>; 2],
}

impl ParallelCeiling {
    pub fn new(steps: u64) -> ParallelCeiling {
        let pool = |threads| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a rayon pool")
        };
        ParallelCeiling {
            one: pool(1),
            many: pool(TILED_THREADS),
            steps,
            times: [Vec::new(), Vec::new()],
        }
    }

    /// `steps` steps of the chain from `seed`; its end, so that none is
    /// optimised away.
    fn spin(steps: u64, seed: u64) -> u64 {
        let mut x = std::hint::black_box(seed);
        for _ in 0..steps {
            x = x
                .wrapping_mul(0x5851_f42d_4c95_7f2d)
                .wrapping_add(0x1405_7b7e_f767_814f);
            x ^= x >> 29;
        }
        x
    }

    /// One timing of each: one thread, then the pool.
    pub fn round(&mut self) {
        use rayon::prelude::*;
        let steps = self.steps;
        let one = self.one.install(|| {
            let started = Instant::now();
            std::hint::black_box(Self::spin(steps, 1));
            started.elapsed()
        });
        let parts = TILED_THREADS;
        let many = self.many.install(|| {
            let started = Instant::now();
            let sum: u64 = (0..parts)
                .into_par_iter()
                .with_max_len(1)
                .map(|k| Self::spin(steps / parts as u64, k as u64 + 1))
                .reduce(|| 0, u64::wrapping_add);
            std::hint::black_box(sum);
            started.elapsed()
        });
        self.times[0].push(one);
        self.times[1].push(many);
    }

    /// Median time on one thread over median time on the pool.
    pub fn ratio(&self) -> Option<f64> {
        if self.times[0].is_empty() {
            return None;
        }
        let [one, many] = self.times.clone().map(median);
        (many > Duration::ZERO).then(|| one.as_secs_f64() / many.as_secs_f64())
    }
}
