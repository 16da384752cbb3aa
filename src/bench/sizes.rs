//! The sizes of a run's workloads: the full bench, or `--quick`'s small
//! canvas and few items. Only numbers; the scenes themselves are built in
//! `workloads.rs`.

/// How big a run is: the full bench, or `--quick`'s.
#[derive(Clone, Copy, Debug)]
pub struct Options {
    pub quick: bool,
}

/// Sizes of the workloads for one run.
#[derive(Clone, Copy, Debug)]
pub(super) struct Sizes {
    pub(super) canvas: u32,
    /// (leg length, triangles)
    pub(super) triangles: [(u32, usize); 3],
    /// Triangles of each workload the reference is timed on.
    pub(super) reference_triangles: [usize; 3],
    pub(super) line_canvas: u32,
    pub(super) line_lengths: (f64, f64),
    pub(super) lines: usize,
    /// Lines whose pixel sets are compared one by one.
    pub(super) lines_compared: usize,
    /// Lines on which production is checked against the reference.
    pub(super) lines_verified: usize,
    /// Antialiasing: (leg, triangles), and the sample counts swept.
    pub(super) antialias: (u32, usize),
    pub(super) antialias_samples: &'static [u32],
    /// Conservative rasterization: (leg, triangles, triangles the
    /// reference is timed on).
    pub(super) conservative: (u32, usize, usize),
    /// Motion blur: (leg, triangles, largest translation in pixels).
    pub(super) motion: (u32, usize, f64),
    pub(super) repetitions: usize,
    /// Steps of the parallel-ceiling loop
    /// ([`ParallelCeiling`](super::timing::ParallelCeiling)).
    pub(super) ceiling_steps: u64,
}

impl Sizes {
    pub(super) fn for_options(o: Options) -> Sizes {
        if o.quick {
            Sizes {
                canvas: 256,
                triangles: [(10, 1000), (50, 100), (250, 0)],
                reference_triangles: [250, 25, 0],
                line_canvas: 512,
                line_lengths: (250.0, 350.0),
                lines: 500,
                lines_compared: 100,
                lines_verified: 20,
                antialias: (50, 40),
                antialias_samples: &[4, 16, 64],
                conservative: (10, 500, 20),
                motion: (30, 16, 12.0),
                repetitions: 5,
                ceiling_steps: 1 << 20,
            }
        } else {
            Sizes {
                canvas: 1024,
                triangles: [(10, 20_000), (50, 2_000), (250, 200)],
                reference_triangles: [2_000, 200, 20],
                line_canvas: 2048,
                line_lengths: (1000.0, 1400.0),
                lines: 10_000,
                lines_compared: 1_000,
                lines_verified: 100,
                antialias: (50, 400),
                antialias_samples: &[1, 4, 16, 64, 256],
                conservative: (10, 5_000, 100),
                motion: (50, 400, 25.0),
                repetitions: 5,
                ceiling_steps: 1 << 23,
            }
        }
    }
}
