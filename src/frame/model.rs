//! The frame: what a rasterizer returns for one scene, its slots and
//! channels, and how it is built, hit and resolved.

use super::cover::cover_run;
use super::parts::Parts;
use super::sample_tests::SampleTests;
use crate::plan::Plan;

/// A rasterizer's output for one scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    /// Samples per pixel: the length of each pixel's run of slots. 0 for a
    /// frame that holds only resolved coverage (an area method has no
    /// samples).
    pub samples: u32,
    /// How many primitives cover each sample, pixels row-major from the
    /// top-left, each pixel's samples together.
    pub coverage: Vec<u16>,
    /// Index + 1 of the last primitive (in scene order) that covered each
    /// sample; 0 where none did.
    pub last: Vec<u32>,
    /// Depth of the last primitive at each sample, when the plan asks for it;
    /// 0 where uncovered.
    pub depth: Option<Vec<f64>>,
    /// One channel per attribute, each holding the last primitive's value at
    /// every sample; 0 where uncovered.
    pub attributes: Vec<Vec<f64>>,
    /// Antialiased scenes: each pixel's coverage, the sum over primitives of
    /// the fraction of the pixel each covers (box resolve). The reference
    /// gives the exact area.
    pub resolved: Option<Vec<f64>>,
    /// Scenes in which something moves: each pixel's time coverage, the
    /// mean over its spatial samples of the sum over primitives of the
    /// fraction of the shutter each covers the sample. Such a frame has no
    /// sample slots.
    pub time: Option<Vec<f64>>,
    /// What a sample method spent on its time loop, when it counts it.
    pub sample_tests: Option<SampleTests>,
    /// How the rasterizer drew this frame, when it has several ways and
    /// says which (a GPU adapter: "native MSAA", "shifted passes", "time
    /// passes"); reports show it beside the verdict.
    pub method: Option<&'static str>,
    /// An area method's coverage of each pixel by each primitive, when it
    /// gives it (an external program answering `coverage`, SPEC.md §12.9):
    /// judged primitive by primitive against the exact areas (§14.3).
    pub parts: Option<Parts>,
    /// An area method that gives no coverage per primitive (`area-f32`,
    /// `vello-cpu`): its resolved value claims each pixel's exact area
    /// within this step, 0 for the default step (SPEC.md §14.4). `None`
    /// for a sample method, resolved or not, and a frame that gives parts.
    pub area_step: Option<f64>,
    /// The rasterizer answers coverage only: whatever the plan asks, the
    /// frame has no depth and no attributes, and they are not judged
    /// (SPEC.md §12.9).
    pub coverage_only: bool,
    /// A conservative scene whose case asks for it (SPEC.md §19.4): each
    /// pixel's fully-covered flag (`FullyCoveredEXT`, D3D's inner
    /// coverage), the flag of the last fragment written there; false where
    /// nothing is drawn.
    pub fully_covered: Option<Vec<bool>>,
}

impl Frame {
    /// An empty single-sample frame with room for depth and attributes.
    pub fn new(width: u32, height: u32, depth: bool, attributes: usize) -> Frame {
        Frame::with_samples(width, height, 1, depth, attributes)
    }

    /// The bytes [`Frame::for_plan`] allocates for a canvas and a plan,
    /// computed before anything is allocated: what one rasterizer's answer
    /// to the case holds (the runner bounds a case's memory with it,
    /// `--max-case-memory`).
    pub fn estimated_bytes(width: u32, height: u32, plan: &Plan) -> u64 {
        let pixels = u64::from(width) * u64::from(height);
        if plan.motion.is_some() {
            return pixels * 8;
        }
        let samples = pixels * u64::from(plan.samples_per_pixel);
        // coverage (u16) and last (u32) per sample, then f64 channels.
        let channels = u64::from(plan.depth) + plan.attributes as u64;
        let resolved = if plan.antialias.is_some() {
            pixels * 8
        } else {
            0
        };
        samples * (2 + 4 + 8 * channels) + resolved
    }

    /// A frame of no pixels, standing in for one whose memory was given
    /// back once its case was judged and written.
    pub fn released() -> Frame {
        Frame::with_samples(0, 0, 0, false, 0)
    }

    /// An empty frame with room for what the plan asks for.
    pub fn for_plan(width: u32, height: u32, plan: &Plan) -> Frame {
        if plan.motion.is_some() {
            let n = width as usize * height as usize;
            return Frame::time_only(width, height, vec![0.0; n]);
        }
        let mut frame = Frame::with_samples(
            width,
            height,
            plan.samples_per_pixel,
            plan.depth,
            plan.attributes,
        );
        if plan.antialias.is_some() {
            frame.resolved = Some(vec![0.0; frame.pixel_count()]);
        }
        frame
    }

    fn with_samples(
        width: u32,
        height: u32,
        samples: u32,
        depth: bool,
        attributes: usize,
    ) -> Frame {
        let n = width as usize * height as usize * samples as usize;
        Frame {
            width,
            height,
            samples,
            coverage: vec![0; n],
            last: vec![0; n],
            depth: depth.then(|| vec![0.0; n]),
            // Not `vec![vec![0.0; n]; attributes]`: its template channel
            // is allocated even when there are no attributes.
            attributes: (0..attributes).map(|_| vec![0.0; n]).collect(),
            resolved: None,
            time: None,
            sample_tests: None,
            method: None,
            parts: None,
            area_step: None,
            coverage_only: false,
            fully_covered: None,
        }
    }

    /// A frame of a scene in which something moves: time coverage only.
    pub fn time_only(width: u32, height: u32, time: Vec<f64>) -> Frame {
        assert_eq!(time.len(), width as usize * height as usize);
        Frame {
            time: Some(time),
            ..Frame::with_samples(width, height, 0, false, 0)
        }
    }

    /// A frame of resolved coverage only, from a method without samples.
    pub fn resolved_only(width: u32, height: u32, resolved: Vec<f64>) -> Frame {
        assert_eq!(resolved.len(), width as usize * height as usize);
        Frame {
            resolved: Some(resolved),
            ..Frame::with_samples(width, height, 0, false, 0)
        }
    }

    pub fn pixel_count(&self) -> usize {
        self.width as usize * self.height as usize
    }

    pub fn sample_count(&self) -> usize {
        self.coverage.len()
    }

    /// The slot of pixel (x, y)'s first sample.
    pub fn index(&self, x: u32, y: u32) -> usize {
        (y as usize * self.width as usize + x as usize) * self.samples as usize
    }

    /// Samples covered at least once.
    pub fn covered_samples(&self) -> u64 {
        self.coverage.iter().filter(|&&c| c > 0).count() as u64
    }

    /// Records that primitive `primitive` (0-based) covers sample `i`.
    #[inline]
    pub fn hit(&mut self, i: usize, primitive: usize) {
        self.coverage[i] = self.coverage[i].saturating_add(1);
        self.last[i] = primitive as u32 + 1;
    }

    /// Records that primitive `primitive` (0-based) covers samples
    /// `from..to`: [`Frame::hit`] a run at a time ([`cover_run`]).
    #[inline]
    pub fn hit_run(&mut self, from: usize, to: usize, primitive: usize) {
        cover_run(
            &mut self.coverage[from..to],
            &mut self.last[from..to],
            primitive as u32 + 1,
        );
    }

    /// The box resolve of the samples: each pixel's coverage counts summed
    /// and divided by the sample count: a quotient of two small integers,
    /// rounded once.
    pub fn box_resolve(&self) -> Vec<f64> {
        let n = self.samples.max(1) as usize;
        self.coverage
            .chunks(n)
            .map(|run| run.iter().map(|&c| u32::from(c)).sum::<u32>() as f64 / n as f64)
            .collect()
    }

    /// Empties every channel, keeping the frame's shape and its memory.
    pub fn clear(&mut self) {
        self.coverage.fill(0);
        self.last.fill(0);
        for channel in self.depth.iter_mut().chain(&mut self.attributes) {
            channel.fill(0.0);
        }
        for channel in self.resolved.iter_mut().chain(&mut self.time) {
            channel.fill(0.0);
        }
        if let Some(flags) = &mut self.fully_covered {
            flags.fill(false);
        }
        self.sample_tests = None;
    }

    /// Fills `resolved` with the box resolve of the samples.
    pub fn resolve(&mut self) {
        self.resolved = Some(self.box_resolve());
    }
}
