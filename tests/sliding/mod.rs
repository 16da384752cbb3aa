//! A square sliding sideways, for the motion-blur tests that must not wait
//! for the oracle: under pure translation every spatial sample is inside
//! the square during one interval of the shutter, whose ends are
//! rational, so each pixel's exact time coverage is computed here by hand
//! (SPEC.md §15.2), and so is what an honest sampler returns with the
//! instants of SPEC.md §15.3.

#![allow(dead_code)] // each test crate uses its own subset

use dashu_ratio::RBig;

use rastercheck::frame::{Frame, SampleTests};
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::reference::motion::Certified;
use rastercheck::scene::{parse_case, Limits, Scene};

/// The square [x0, x1] × [y0, y1] at shutter open, moving by (dx, 0) by
/// τ = 1, drawn as two triangles that share a diagonal (so that every
/// sample inside is covered once).
#[derive(Clone, Debug)]
pub struct Slide {
    pub name: &'static str,
    pub canvas: [u32; 2],
    pub x: [i64; 2],
    pub y: [i64; 2],
    pub dx: i64,
    /// N, time samples per spatial sample.
    pub samples: u32,
    pub pattern: &'static str,
    /// M, `effects.antialias.samples` (standard pattern), when antialiased.
    pub antialias: Option<u32>,
    /// In 2^-16 of [0, 1].
    pub shutter: [u32; 2],
    /// Extra `expect` members, JSON without the braces.
    pub expect: String,
}

pub const ONE: u32 = 1 << 16;

impl Slide {
    /// A 4×4 square at x = 2..6, y = 1..5 on a 16×6 canvas, moving 8
    /// pixels right over the whole shutter, 16 stratified instants.
    pub fn new(name: &'static str) -> Slide {
        Slide {
            name,
            canvas: [16, 6],
            x: [2, 6],
            y: [1, 5],
            dx: 8,
            samples: 16,
            pattern: "stratified",
            antialias: None,
            shutter: [0, ONE],
            expect: String::new(),
        }
    }

    pub fn json(&self) -> String {
        let ([x0, x1], [y0, y1], dx) = (self.x, self.y, self.dx);
        let v = |x: i64, y: i64| format!("{{\"from\": [{x}, {y}], \"to\": [{}, {y}]}}", x + dx);
        let antialias = self.antialias.map_or(String::new(), |m| {
            format!(", \"antialias\": {{\"samples\": {m}}}")
        });
        let time = |u: u32| format!("{}", f64::from(u) / f64::from(ONE));
        format!(
            r#"{{"name": "{}", "canvas": {{"width": {}, "height": {}}},
  "primitives": [
    {{"triangle": [{}, {}, {}]}},
    {{"triangle": [{}, {}, {}]}}
  ],
  "effects": {{"motion_blur": {{"samples": {}, "pattern": "{}", "shutter": [{}, {}]}}{antialias}}},
  "expect": {{{}}}}}"#,
            self.name,
            self.canvas[0],
            self.canvas[1],
            v(x0, y0),
            v(x1, y0),
            v(x1, y1),
            v(x0, y0),
            v(x1, y1),
            v(x0, y1),
            self.samples,
            self.pattern,
            time(self.shutter[0]),
            time(self.shutter[1]),
            self.expect
        )
    }

    pub fn scene(&self) -> Scene {
        parse_case(&self.json(), "inline.json", &Limits::default())
            .unwrap_or_else(|e| panic!("{e}\n{}", self.json()))
    }

    /// Every spatial sample of pixel (x, y), as exact positions.
    fn samples_of(&self, plan: &Plan, x: u32, y: u32) -> Vec<[RBig; 2]> {
        let (x, y) = (RBig::from(x), RBig::from(y));
        match &plan.antialias {
            None => {
                let half = RBig::from_parts(1.into(), 2u8.into());
                vec![[&x + &half, &y + &half]]
            }
            Some(samples) => {
                let lattice = dashu_int::UBig::ONE << samples.position_bits as usize;
                samples
                    .offsets
                    .iter()
                    .map(|&[ox, oy]| {
                        let at = |o: u32| RBig::from_parts(o.into(), lattice.clone());
                        [&x + at(ox), &y + at(oy)]
                    })
                    .collect()
            }
        }
    }

    /// Whether the square covers the sample (qx, qy) at instant τ: left and
    /// top edges inclusive (the top-left rule), right and bottom exclusive.
    pub fn covers(&self, [qx, qy]: &[RBig; 2], tau: &RBig) -> bool {
        let shift = tau * RBig::from(self.dx);
        let [x0, x1] = self.x.map(|v| RBig::from(v) + &shift);
        let [y0, y1] = self.y.map(RBig::from);
        &x0 <= qx && qx < &x1 && &y0 <= qy && qy < &y1
    }

    /// The shutter as exact instants in [0, 1].
    fn shutter(&self) -> [RBig; 2] {
        self.shutter
            .map(|u| RBig::from_parts(u.into(), dashu_int::UBig::from(ONE)))
    }

    /// The exact time coverage of one spatial sample: the length of the
    /// instants it is inside, over the shutter's.
    fn sample_time(&self, [qx, qy]: &[RBig; 2]) -> RBig {
        let [y0, y1] = self.y.map(RBig::from);
        let [open, close] = self.shutter();
        if !(&y0 <= qy && qy < &y1) {
            return RBig::ZERO;
        }
        // x0 + dx·τ ≤ qx < x1 + dx·τ.
        let (lo, hi) = if self.dx == 0 {
            let inside = &RBig::from(self.x[0]) <= qx && qx < &RBig::from(self.x[1]);
            return if inside { RBig::ONE } else { RBig::ZERO };
        } else {
            let dx = RBig::from(self.dx);
            let a = (qx - RBig::from(self.x[1])) / &dx;
            let b = (qx - RBig::from(self.x[0])) / &dx;
            if self.dx > 0 {
                (a, b)
            } else {
                (b, a)
            }
        };
        let (lo, hi) = (lo.max(open.clone()), hi.min(close.clone()));
        if hi > lo {
            (hi - lo) / (close - open)
        } else {
            RBig::ZERO
        }
    }

    /// Each pixel's exact time coverage, certified exactly (bound 0): what
    /// the oracle must compute for this scene.
    pub fn exact(&self, plan: &Plan) -> Vec<Certified> {
        let [w, h] = self.canvas;
        (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .map(|(x, y)| {
                let samples = self.samples_of(plan, x, y);
                let sum = samples
                    .iter()
                    .fold(RBig::ZERO, |acc, q| acc + self.sample_time(q));
                Certified {
                    value: sum / RBig::from(samples.len()),
                    bound: RBig::ZERO,
                }
            })
            .collect()
    }

    /// The exact values rounded to f64, row-major.
    pub fn exact_f64(&self, plan: &Plan) -> Vec<f64> {
        self.exact(plan)
            .iter()
            .map(|c| c.value.to_f64().value())
            .collect()
    }

    /// What an honest sample method returns: each spatial sample tested at
    /// the pattern's N instants of its pixel (SPEC.md §15.3), covered tests
    /// over M·N, with the tests counted.
    pub fn sampled(&self, scene: &Scene, plan: &Plan) -> Frame {
        let blur = &plan.motion.as_ref().expect("a moving scene").blur;
        let [w, h] = self.canvas;
        let (mut tests, mut covered_all) = (0u64, 0u64);
        let two_32 = RBig::from(1u64 << 32);
        let mut time = Vec::new();
        for y in 0..h {
            for x in 0..w {
                let samples = self.samples_of(plan, x, y);
                let pixel = u64::from(y * w + x);
                let us = blur.pixel_times(pixel, samples.len() as u32);
                let n = blur.samples as usize;
                let covered = us
                    .iter()
                    .enumerate()
                    .filter(|&(j, &u)| {
                        let tau = RBig::from(blur.instant(u)) / &two_32;
                        self.covers(&samples[j / n], &tau)
                    })
                    .count() as u64;
                tests += us.len() as u64;
                covered_all += covered;
                time.push(covered as f64 / us.len() as f64);
            }
        }
        let mut frame = Frame::time_only(scene.canvas.width, scene.canvas.height, time);
        frame.sample_tests = Some(SampleTests {
            tests,
            covered: covered_all,
        });
        frame
    }
}

/// A rasterizer that returns what a function makes of the scene.
pub struct Given<F>(pub &'static str, pub F);

impl<F> Rasterizer for Given<F>
where
    F: Fn(&Scene, &Plan) -> Frame + Send + Sync,
{
    fn name(&self) -> &str {
        self.0
    }
    fn capabilities(&self) -> Capabilities {
        Capabilities::everything()
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        Ok((self.1)(scene, plan))
    }
}
