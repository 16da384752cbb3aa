//! `rastercheck bench`: time and error of each method, measured in one run on
//! the same seeded workloads, written as BENCH.md and a hand-drawn SVG chart.
//!
//! Timings are medians over interleaved repetitions (every method runs once
//! per round, so drift in the machine's speed hits all methods alike), and
//! the conclusions drawn from them are ratios between methods measured side
//! by side. Errors are counted against the exact reference.

use std::fmt::Write as _;
use std::time::{Duration, Instant};

pub mod memory;

use crate::explore::fuzz::Rng;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::time::limits::TIME_ONE;
use crate::scene::{
    Antialias, Canvas, Cull, Effects, Expect, FillRule, Interpolation, LastPixel, Line,
    LineParameter, LineRule, MotionBlur, Number, Pattern, Primitive, Rules, Scene, TimePattern,
    Triangle, Vertex,
};

/// The seed of every workload: the same scenes on every run.
pub const SEED: u64 = 0x6265_6e63_6821;

/// How big a run is.
#[derive(Clone, Copy, Debug)]
pub struct Options {
    pub quick: bool,
}

/// Sizes of the workloads for one run.
#[derive(Clone, Copy, Debug)]
struct Sizes {
    canvas: u32,
    /// (leg length, triangles)
    triangles: [(u32, usize); 3],
    /// Triangles of each workload the reference is timed on.
    reference_triangles: [usize; 3],
    line_canvas: u32,
    line_lengths: (f64, f64),
    lines: usize,
    /// Lines whose pixel sets are compared one by one.
    lines_compared: usize,
    /// Lines on which production is checked against the reference.
    lines_verified: usize,
    /// Antialiasing: (leg, triangles), and the sample counts swept.
    antialias: (u32, usize),
    antialias_samples: &'static [u32],
    /// Motion blur: (leg, triangles, largest translation in pixels).
    motion: (u32, usize, f64),
    repetitions: usize,
    /// Steps of the parallel-ceiling loop ([`ParallelCeiling`]).
    ceiling_steps: u64,
}

impl Sizes {
    fn for_options(o: Options) -> Sizes {
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
                motion: (50, 400, 25.0),
                repetitions: 5,
                ceiling_steps: 1 << 23,
            }
        }
    }
}

/// One method on one workload.
#[derive(Clone, Debug)]
pub struct Measured {
    pub method: String,
    /// Median time per item (triangle or line); `None` when the method could
    /// not run, with the reason in `note`.
    pub per_item: Option<Duration>,
    /// Items the timing was taken on.
    pub timed_items: usize,
    /// Mismatched samples (triangles) or lines whose pixel set differs
    /// (lines), and out of how many.
    pub errors: Option<(u64, u64)>,
    /// Antialiasing: (RMS over edge pixels, largest) of resolved coverage
    /// minus exact area.
    pub coverage_error: Option<(f64, f64)>,
    pub exact: bool,
    /// Peak heap bytes of one extra, untimed run (see [`memory`]); `None`
    /// when not measured.
    pub peak_heap: Option<u64>,
    /// The same call's median time for the whole frame on the same canvas
    /// with no primitives: its fixed per-frame cost, where measured.
    pub empty_frame: Option<Duration>,
    pub note: String,
}

impl Measured {
    /// A method that could not run on a workload, and why.
    fn not_run(method: &str, why: String) -> Measured {
        Measured {
            method: method.to_owned(),
            per_item: None,
            timed_items: 0,
            errors: None,
            coverage_error: None,
            exact: false,
            peak_heap: None,
            empty_frame: None,
            note: why,
        }
    }

    /// The error as a fraction, for the chart: wrong samples over covered
    /// ones, or the RMS coverage error of an antialiasing method.
    pub fn error_fraction(&self) -> Option<f64> {
        if let Some((rms, _)) = self.coverage_error {
            return Some(rms);
        }
        self.errors
            .map(|(e, of)| if of == 0 { 0.0 } else { e as f64 / of as f64 })
    }
}

/// One workload and every method measured on it.
#[derive(Clone, Debug)]
pub struct Workload {
    pub name: String,
    pub short: String,
    /// The method the "×" column compares every other one with.
    pub baseline: String,
    pub items: usize,
    /// Nominal pixels per item (the triangle's area, the line's length).
    pub pixels_per_item: f64,
    pub error_unit: String,
    pub methods: Vec<Measured>,
    /// Triangle workloads: the machine's parallel ceiling measured in the
    /// same rounds ([`ParallelCeiling::ratio`]).
    pub parallel_ceiling: Option<f64>,
}

impl Workload {
    pub fn method(&self, name: &str) -> Option<&Measured> {
        self.methods.iter().find(|m| m.method == name)
    }

    /// How many times faster `a` is than `b`.
    pub fn ratio(&self, a: &str, b: &str) -> Option<f64> {
        let ta = self.method(a)?.per_item?.as_secs_f64();
        let tb = self.method(b)?.per_item?.as_secs_f64();
        (ta > 0.0).then(|| tb / ta)
    }
}

/// A performance target and what was measured for it.
#[derive(Clone, Debug)]
pub struct Target {
    pub target: String,
    pub measured: String,
    pub met: Option<bool>,
    pub note: String,
}

/// Everything one run measured.
#[derive(Clone, Debug)]
pub struct Report {
    pub quick: bool,
    pub machine: String,
    pub cores: usize,
    pub date: String,
    pub version: String,
    pub repetitions: usize,
    pub workloads: Vec<Workload>,
    pub targets: Vec<Target>,
    pub notes: Vec<String>,
    pub elapsed: Duration,
    /// The machine's load averages (1, 5, 15 min) before and after the
    /// run, where the system reports them: other work sharing the cores.
    pub load: Option<(String, String)>,
    /// Whether peak heap was counted ([`memory::installed`]).
    pub memory_counted: bool,
    /// Where a llvmpipe adapter is compiled in: `LP_NUM_THREADS` during
    /// the run, and whether the bench set it.
    pub lp_num_threads: Option<(String, bool)>,
}

// --- The naive floor --------------------------------------------------------

/// The floor every real rasterizer should beat: for each triangle, every
/// pixel of its bounding box is tested against the three edge functions,
/// each evaluated in full (no incremental stepping), in i64 on 16.8 fixed
/// point, with the top-left rule. Triangles only, coverage only.
#[derive(Clone, Copy, Debug, Default)]
pub struct NaiveBbox;

impl Rasterizer for NaiveBbox {
    fn name(&self) -> &str {
        "naive"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            triangles: true,
            ideal_geometry: false,
            attributes: false,
            depth: false,
            polygons: false,
            antialias: false,
            motion_blur: false,
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        if scene.rules.subpixel_bits != Some(8) || scene.rules.fill_rule != FillRule::TopLeft {
            return Err(RasterError::Unsupported(
                "only 16.8 fixed point under the top-left rule".to_owned(),
            ));
        }
        if plan.interpolates() {
            return Err(RasterError::Unsupported("coverage only".to_owned()));
        }
        let (w, h) = (scene.canvas.width as i64, scene.canvas.height as i64);
        let mut frame = Frame::new(scene.canvas.width, scene.canvas.height, false, 0);
        let fixed = |n: &Number| (n.to_f64_lossy() * 256.0).round_ties_even() as i64;
        for (index, primitive) in scene.primitives.iter().enumerate() {
            let Primitive::Triangle(t) = primitive else {
                return Err(RasterError::Unsupported("triangles only".to_owned()));
            };
            let v = t.vertices.each_ref().map(|p| [fixed(&p.x), fixed(&p.y)]);
            let area = orient(v[0], v[1], v[2]);
            if area == 0 {
                continue;
            }
            let sign = area.signum();
            let owns = [0, 1, 2].map(|i| top_left_owns(v[i], v[(i + 1) % 3], v[(i + 2) % 3]));
            let lo = |a: usize| v.iter().map(|p| p[a]).min().unwrap();
            let hi = |a: usize| v.iter().map(|p| p[a]).max().unwrap();
            // Pixel centres (k + 0.5) within [lo, hi], clamped to the canvas.
            let first = |l: i64| ((l - 128 + 255) >> 8).max(0);
            let last = |h: i64, size: i64| ((h - 128) >> 8).min(size - 1);
            for y in first(lo(1))..=last(hi(1), h) {
                for x in first(lo(0))..=last(hi(0), w) {
                    let p = [x * 256 + 128, y * 256 + 128];
                    let inside = (0..3).all(|i| {
                        let e = orient(v[i], v[(i + 1) % 3], p).signum() * sign;
                        e > 0 || (e == 0 && owns[i])
                    });
                    if inside {
                        let i = frame.index(x as u32, y as u32);
                        frame.hit(i, index);
                    }
                }
            }
        }
        Ok(frame)
    }
}

fn orient(a: [i64; 2], b: [i64; 2], p: [i64; 2]) -> i64 {
    (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
}

/// Top-left ownership of edge a→b of a triangle whose third vertex is c
/// (y down): a top edge is horizontal with the triangle below; a left edge
/// is not horizontal and has the triangle to its right.
fn top_left_owns(a: [i64; 2], b: [i64; 2], c: [i64; 2]) -> bool {
    if a[1] == b[1] {
        return c[1] > a[1];
    }
    let s = (c[0] - a[0]) * (b[1] - a[1]) - (c[1] - a[1]) * (b[0] - a[0]);
    s.signum() == (b[1] - a[1]).signum()
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
}

/// The plain midpoint loop a line rasterizer is first written as: 16.9
/// fixed point, the major axis stepped pixel by pixel from the endpoint
/// with the smaller major coordinate, the minor pixel from a remainder
/// updated by adding, each pixel bounds-checked and written with
/// `Frame::hit`. Midpoint lines with their last pixel, 16.8 snapping,
/// coverage only: the rule production's midpoint walk implements.
#[derive(Clone, Copy, Debug, Default)]
pub struct PlainMidpoint;

impl Rasterizer for PlainMidpoint {
    fn name(&self) -> &str {
        "midpoint-plain"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            triangles: false,
            ideal_geometry: false,
            attributes: false,
            depth: false,
            polygons: false,
            antialias: false,
            motion_blur: false,
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let unsupported = |why: &str| Err(RasterError::Unsupported(why.to_owned()));
        if scene.rules.subpixel_bits != Some(8) || plan.interpolates() {
            return unsupported("16.8 fixed point, coverage only");
        }
        let (w, h) = (scene.canvas.width as i64, scene.canvas.height as i64);
        let mut frame = Frame::new(scene.canvas.width, scene.canvas.height, false, 0);
        let fixed = |n: &Number| (n.to_f64_lossy() * 256.0).round_ties_even() as i64;
        for (index, primitive) in scene.primitives.iter().enumerate() {
            let Primitive::Line(line) = primitive else {
                return unsupported("lines only");
            };
            if line.rule != LineRule::Midpoint || line.last_pixel != LastPixel::Include {
                return unsupported("midpoint lines with their last pixel");
            }
            // 16.9 fixed point: pixel centres k·512 + 256 are integers.
            let [a, b] = line
                .vertices
                .each_ref()
                .map(|v| [2 * fixed(&v.x), 2 * fixed(&v.y)]);
            let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
            if dx == 0 && dy == 0 {
                continue;
            }
            // u: the major axis (x on a diagonal), v: the minor one.
            let (u, v) = if dx.abs() >= dy.abs() { (0, 1) } else { (1, 0) };
            let (a, b) = if b[u] < a[u] { (b, a) } else { (a, b) };
            let (du, dv) = (b[u] - a[u], b[v] - a[v]);
            // Centres within [a_u, b_u], clipped to the canvas.
            let size = if u == 0 { w } else { h };
            let first = (a[u] - 256 + 511).div_euclid(512).max(0);
            let last = (b[u] - 256).div_euclid(512).min(size - 1);
            if first > last {
                continue;
            }
            // The minor pixel at centre c is ⌈v(c)⌉ − 1 = ⌊(N − 1)/D⌋,
            // N = a_v·du + (c − a_u)·dv, D = 512·du: one division, then a
            // remainder stepped by adding.
            let den = 512 * du;
            let c = first * 512 + 256;
            let num = a[v] * du + (c - a[u]) * dv - 1;
            let (mut m, mut rest) = (num.div_euclid(den), num.rem_euclid(den));
            let minor_size = if u == 0 { h } else { w };
            for k in first..=last {
                if (0..minor_size).contains(&m) {
                    let (x, y) = if u == 0 { (k, m) } else { (m, k) };
                    let i = frame.index(x as u32, y as u32);
                    frame.hit(i, index);
                }
                rest += 512 * dv;
                if rest >= den {
                    rest -= den;
                    m += 1;
                } else if rest < 0 {
                    rest += den;
                    m -= 1;
                }
            }
        }
        Ok(frame)
    }
}

// --- Workloads ----------------------------------------------------------------

fn on_grid(v: f64) -> Number {
    Number::ratio((v * 256.0).round() as i64, 256)
}

fn scene(name: &str, canvas: u32, primitives: Vec<Primitive>) -> Scene {
    Scene {
        name: name.to_owned(),
        description: String::new(),
        canvas: Canvas {
            width: canvas,
            height: canvas,
        },
        rules: Rules::default(),
        primitives,
        effects: Effects::default(),
        expect: Expect::default(),
        attribute_count: 0,
        has_depth: false,
    }
}

/// Right triangles with legs `leg`, randomly rotated, wholly inside the
/// canvas (one pixel of margin).
pub fn triangle_scene(canvas: u32, leg: u32, count: usize, seed: u64) -> Scene {
    let mut rng = Rng::new(seed ^ u64::from(leg));
    let l = f64::from(leg);
    let size = f64::from(canvas);
    let primitives = (0..count)
        .map(|_| {
            let theta = rng.uniform(0.0, std::f64::consts::TAU);
            let (s, c) = theta.sin_cos();
            let offsets = [(0.0, 0.0), (l * c, l * s), (-l * s, l * c)];
            let min_x = offsets.iter().map(|o| o.0).fold(f64::MAX, f64::min);
            let max_x = offsets.iter().map(|o| o.0).fold(f64::MIN, f64::max);
            let min_y = offsets.iter().map(|o| o.1).fold(f64::MAX, f64::min);
            let max_y = offsets.iter().map(|o| o.1).fold(f64::MIN, f64::max);
            let ox = rng.uniform(1.0 - min_x, size - 1.0 - max_x);
            let oy = rng.uniform(1.0 - min_y, size - 1.0 - max_y);
            Primitive::Triangle(Triangle {
                vertices: offsets.map(|(dx, dy)| Vertex::at(on_grid(ox + dx), on_grid(oy + dy))),
                interpolation: Interpolation::Linear,
            })
        })
        .collect();
    scene(&format!("triangles L={leg}"), canvas, primitives)
}

/// Midpoint lines of random direction and length in `lengths`, wholly
/// inside the canvas.
pub fn line_scene(canvas: u32, lengths: (f64, f64), count: usize, seed: u64) -> Scene {
    let mut rng = Rng::new(seed ^ 0x4c49_4e45);
    let size = f64::from(canvas);
    let primitives = (0..count)
        .map(|_| {
            let len = rng.uniform(lengths.0, lengths.1);
            let theta = rng.uniform(0.0, std::f64::consts::TAU);
            let (dx, dy) = (len * theta.cos(), len * theta.sin());
            let x0 = rng.uniform(1.0 - dx.min(0.0), size - 1.0 - dx.max(0.0));
            let y0 = rng.uniform(1.0 - dy.min(0.0), size - 1.0 - dy.max(0.0));
            Primitive::Line(Line {
                vertices: [
                    Vertex::at(on_grid(x0), on_grid(y0)),
                    Vertex::at(on_grid(x0 + dx), on_grid(y0 + dy)),
                ],
                rule: LineRule::Midpoint,
                width: Number::ONE,
                last_pixel: LastPixel::Include,
                parameter: LineParameter::Major,
                interpolation: Interpolation::Linear,
            })
        })
        .collect();
    scene("lines", canvas, primitives)
}

// --- Measuring ----------------------------------------------------------------

fn median(mut times: Vec<Duration>) -> Duration {
    times.sort();
    times[times.len() / 2]
}

fn subset(s: &Scene, n: usize) -> Scene {
    let mut out = s.clone();
    out.primitives.truncate(n);
    out
}

fn mismatched(reference: &Frame, frame: &Frame) -> u64 {
    reference
        .coverage
        .iter()
        .zip(&frame.coverage)
        .zip(reference.last.iter().zip(&frame.last))
        .filter(|((r, c), (rl, cl))| r != c || rl != cl)
        .count() as u64
}

/// The triangle methods, in table order: (name, rasterizer).
pub fn triangle_methods() -> Vec<(String, Box<dyn Rasterizer>)> {
    let mut out: Vec<(String, Box<dyn Rasterizer>)> = vec![
        (
            "production".to_owned(),
            Box::new(crate::production::Production),
        ),
        (
            "production-tiled".to_owned(),
            Box::new(OnPool::new(
                Box::new(crate::production::tiled::Tiled),
                TILED_THREADS,
            )),
        ),
        ("naive".to_owned(), Box::new(NaiveBbox)),
    ];
    let mut names = vec!["float-f32", "float-f64"];
    if cfg!(feature = "tiny-skia") {
        names.push("tiny-skia");
    }
    if cfg!(feature = "euc") {
        names.push("euc");
    }
    if cfg!(feature = "lavapipe") {
        names.push("lavapipe");
    }
    if cfg!(feature = "gl") {
        names.push("gl");
    }
    for name in names {
        if let Some(r) = crate::harness::suite::rasterizer(name) {
            out.push((name.to_owned(), r));
        }
    }
    out
}

/// Methods whose coverage is exact by construction.
fn is_exact(name: &str) -> bool {
    matches!(
        name,
        "production" | "production-tiled" | "naive" | "reference"
    )
}

/// The row of a static scene that declares motion blur, and of the same
/// scene without, drawn in turn with it.
pub const DECLARED: &str = "production, motion blur declared";
pub const PAIRED: &str = "production, paired";

/// `s` declaring 16 stratified instants over the whole shutter, with
/// nothing moving: a static scene (SPEC.md §15.1).
fn with_motion_declared(s: &Scene) -> Scene {
    let mut declared = s.clone();
    declared.effects.motion_blur = Some(MotionBlur {
        shutter: [0, TIME_ONE],
        samples: 16,
        pattern: TimePattern::Stratified,
        seed: SEED,
    });
    declared
}

/// The same static scene, drawn by production without and with motion
/// blur declared: each round draws them in turn through the same call, in
/// the orders ABBA ABBA (BAAB BAAB in odd rounds), so that each takes every
/// place as often. A draw's time depends on where it falls: drawn right
/// after the row `production`, the same scene took 10–20% longer than that
/// row (a large frame allocated after another's is freed comes from a
/// different place in the allocator), and a plain alternation still left a
/// few percent in favour of the later place.
struct Declared {
    scenes: [Scene; 2],
    plans: [Plan; 2],
    /// Draw times, and Plan::for_scene's: plain, then declared.
    draws: [Vec<Duration>; 2],
    planning: [Vec<Duration>; 2],
    frames: [Result<Frame, String>; 2],
}

impl Declared {
    fn new(s: &Scene) -> Declared {
        let scenes = [s.clone(), with_motion_declared(s)];
        Declared {
            plans: [Plan::for_scene(&scenes[0]), Plan::for_scene(&scenes[1])],
            scenes,
            draws: [Vec::new(), Vec::new()],
            planning: [Vec::new(), Vec::new()],
            frames: [Err(String::new()), Err(String::new())],
        }
    }

    fn round(&mut self, rep: usize, production: &dyn Rasterizer) {
        let order = if rep.is_multiple_of(2) {
            [0, 1, 1, 0, 0, 1, 1, 0]
        } else {
            [1, 0, 0, 1, 1, 0, 0, 1]
        };
        for (i, k) in order.into_iter().enumerate() {
            let started = Instant::now();
            let frame = production.rasterize(&self.scenes[k], &self.plans[k]);
            self.draws[k].push(started.elapsed());
            if rep == 0 && i < 2 {
                self.frames[k] = frame.map_err(|e| e.to_string());
            }
        }
        for k in [0, 1] {
            let started = Instant::now();
            let plan = Plan::for_scene(&self.scenes[k]);
            self.planning[k].push(started.elapsed());
            std::hint::black_box(plan);
        }
    }

    /// Each scene's peak heap, drawn once more outside every timing.
    fn peaks(&self, production: &dyn Rasterizer) -> [Option<u64>; 2] {
        [0, 1].map(|k| memory::peak(|| production.rasterize(&self.scenes[k], &self.plans[k])).1)
    }

    /// The two rows.
    fn rows(
        self,
        exact: &Frame,
        covered: u64,
        count: usize,
        peaks: [Option<u64>; 2],
    ) -> Vec<Measured> {
        let [plain_planning, declared_planning] = self.planning.map(median);
        [PAIRED, DECLARED]
            .iter()
            .zip(self.draws)
            .zip(self.frames)
            .zip(peaks)
            .enumerate()
            .map(|(k, (((name, draws), frame), peak_heap))| Measured {
                method: (*name).to_owned(),
                per_item: frame.is_ok().then(|| median(draws) / count as u32),
                timed_items: count,
                errors: frame.as_ref().ok().map(|f| (mismatched(exact, f), covered)),
                coverage_error: None,
                exact: true,
                peak_heap,
                empty_frame: None,
                note: match (frame, k) {
                    (Err(why), _) => why,
                    (Ok(_), 0) => format!("production on this scene, drawn in turn with `{DECLARED}`"),
                    (Ok(_), _) => format!(
                        "this scene with effects.motion_blur declared, nothing moving: its plan has \
                         no time loop (planning, outside every timing: {} with the declaration, {} \
                         without)",
                        time_text(declared_planning),
                        time_text(plain_planning)
                    ),
                },
            })
            .collect()
    }
}

/// Whether a method is llvmpipe behind a GPU API: warmed up before the
/// rounds (its device, context and pipelines are created on first use) and
/// also timed on an empty canvas, for its marginal cost.
fn is_driver(name: &str) -> bool {
    DRIVERS.iter().any(|(n, _)| *n == name)
}

/// The llvmpipe methods, by adapter name, with what each goes through.
pub const DRIVERS: [(&str, &str); 2] = [
    ("lavapipe", "lavapipe (Vulkan) through wgpu"),
    ("gl", "Mesa's OpenGL through EGL surfaceless"),
];

/// The name of a driver's marginal row.
pub fn marginal_name(driver: &str) -> String {
    format!("{driver}, marginal")
}

/// The time per item above a method's fixed per-frame cost:
/// (its frame − the same call on an empty canvas) / items, in seconds.
/// `None` when not measured or not above the noise (≤ 0).
pub fn marginal_per_item(m: &Measured) -> Option<f64> {
    let full = m.per_item?.as_secs_f64();
    let empty = m.empty_frame?.as_secs_f64() / m.timed_items.max(1) as f64;
    (full > empty).then_some(full - empty)
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

fn measure_triangles(
    leg: u32,
    count: usize,
    reference_count: usize,
    sizes: &Sizes,
    notes: &mut Vec<String>,
) -> Workload {
    let s = triangle_scene(sizes.canvas, leg, count, SEED);
    let plan = Plan::for_scene(&s);
    // The exact frame, computed once, outside every timing: the reference
    // row's peak heap is this call's.
    let (exact, reference_peak) = memory::peak(|| crate::reference::render(&s, &plan));
    let covered: u64 = exact.coverage.iter().map(|&c| u64::from(c)).sum();
    let methods = triangle_methods();
    // The tiled method is timed inside its pool (OnPool::timed).
    let tiled_at = methods
        .iter()
        .position(|(name, _)| name == "production-tiled")
        .unwrap_or(usize::MAX);
    let tiled = (tiled_at != usize::MAX)
        .then(|| OnPool::new(Box::new(crate::production::tiled::Tiled), TILED_THREADS));
    let draw = |k: usize, r: &dyn Rasterizer, scene: &Scene| match tiled
        .as_ref()
        .filter(|_| k == tiled_at)
    {
        Some(pool) => pool.timed(scene, &plan),
        None => {
            let started = Instant::now();
            let result = r.rasterize(scene, &plan);
            (result, started.elapsed())
        }
    };
    // The fixed per-frame cost of production and the drivers: the same
    // call on the same canvas with no triangles.
    let empty = subset(&s, 0);
    let with_empty = |name: &str| name == "production" || is_driver(name);
    let mut empty_times: Vec<Vec<Duration>> = vec![Vec::new(); methods.len()];
    let mut ceiling = ParallelCeiling::new(sizes.ceiling_steps);
    // Drivers create their device and pipelines on first use: once here,
    // untimed.
    for (_, r) in methods.iter().filter(|(name, _)| is_driver(name)) {
        std::hint::black_box(r.rasterize(&s, &plan).ok());
    }
    let mut times: Vec<Vec<Duration>> = vec![Vec::new(); methods.len()];
    let mut frames: Vec<Result<Frame, String>> = vec![Err(String::new()); methods.len()];
    let reference_scene = subset(&s, reference_count);
    let mut reference_times = Vec::new();
    let mut declared = Declared::new(&s);
    for rep in 0..sizes.repetitions {
        for (k, (name, r)) in methods.iter().enumerate() {
            if rep > 0 && frames[k].is_err() {
                continue;
            }
            let (result, elapsed) = draw(k, r.as_ref(), &s);
            times[k].push(elapsed);
            if rep == 0 {
                frames[k] = result.map_err(|e| e.to_string());
            }
            if with_empty(name) && frames[k].is_ok() {
                let (result, elapsed) = draw(k, r.as_ref(), &empty);
                empty_times[k].push(elapsed);
                std::hint::black_box(result.ok());
            }
            if name == "production" {
                declared.round(rep, r.as_ref());
            }
            if k == tiled_at {
                ceiling.round();
            }
        }
        let started = Instant::now();
        let frame = crate::reference::render(&reference_scene, &plan);
        reference_times.push(started.elapsed());
        std::hint::black_box(frame);
    }
    // Peak heap: each method once more, outside every timing.
    let peaks: Vec<Option<u64>> = methods
        .iter()
        .enumerate()
        .map(|(k, (_, r))| {
            frames[k]
                .is_ok()
                .then(|| memory::peak(|| draw(k, r.as_ref(), &s)).1)
                .flatten()
        })
        .collect();
    let declared_peaks = methods
        .iter()
        .find(|(name, _)| name == "production")
        .map_or([None, None], |(_, r)| declared.peaks(r.as_ref()));
    let mut measured: Vec<Measured> = Vec::new();
    for (k, (((name, _), times), frame)) in methods.iter().zip(times).zip(frames).enumerate() {
        let empty_frame = (!empty_times[k].is_empty()).then(|| median(empty_times[k].clone()));
        let row = match frame {
            Ok(frame) => Measured {
                method: name.clone(),
                per_item: Some(median(times) / count as u32),
                timed_items: count,
                errors: Some((mismatched(&exact, &frame), covered)),
                coverage_error: None,
                exact: is_exact(name),
                peak_heap: peaks[k],
                empty_frame,
                note: match empty_frame {
                    Some(e) if is_driver(name) => format!(
                        "LP_NUM_THREADS={}; the whole call: vertex stream, upload, draw, \
                         read-back of the targets into a frame ({} per frame on an empty canvas)",
                        lp_num_threads().unwrap_or_else(|| "unset".to_owned()),
                        time_text(e)
                    ),
                    Some(e) => format!("{} per frame on an empty canvas", time_text(e)),
                    None => String::new(),
                },
            },
            Err(why) => Measured {
                exact: is_exact(name),
                ..Measured::not_run(name, why)
            },
        };
        let marginal = is_driver(name)
            .then(|| marginal_per_item(&row).zip(row.empty_frame))
            .flatten()
            .map(|(t, e)| Measured {
                method: marginal_name(name),
                per_item: Some(Duration::from_secs_f64(t)),
                timed_items: count,
                errors: row.errors,
                coverage_error: None,
                exact: false,
                peak_heap: None,
                empty_frame: None,
                note: format!(
                    "`{name}`'s time minus its {} on the same canvas with no triangles \
                     (clearing and reading back the targets, filling the frame), per triangle",
                    time_text(e)
                ),
            });
        measured.push(row);
        measured.extend(marginal);
    }
    measured.extend(declared.rows(&exact, covered, count, declared_peaks));
    measured.push(Measured {
        method: "reference".to_owned(),
        per_item: Some(median(reference_times) / reference_count as u32),
        timed_items: reference_count,
        errors: Some((0, covered)),
        coverage_error: None,
        exact: true,
        peak_heap: reference_peak,
        empty_frame: None,
        note: if reference_count < count {
            format!(
                "timed on the first {reference_count} of the {count} triangles; \
                 peak heap on all {count}"
            )
        } else {
            String::new()
        },
    });
    if reference_count < count {
        notes.push(format!(
            "L={leg}: the reference is timed on the first {reference_count} triangles; \
             its frame for all {count} is the exact answer every error is counted against"
        ));
    }
    Workload {
        name: format!(
            "triangles, L={leg} ({} px each), {}² canvas",
            leg * leg / 2,
            sizes.canvas
        ),
        short: format!("L={leg}"),
        baseline: "production".to_owned(),
        items: count,
        pixels_per_item: f64::from(leg * leg) / 2.0,
        error_unit: "samples".to_owned(),
        methods: measured,
        parallel_ceiling: ceiling.ratio(),
    }
}

/// The pixels one line lights, in a frame holding it alone.
fn lit(frame: &Frame) -> Vec<usize> {
    frame
        .coverage
        .iter()
        .enumerate()
        .filter(|(_, &c)| c > 0)
        .map(|(i, _)| i)
        .collect()
}

fn measure_lines(sizes: &Sizes, notes: &mut Vec<String>) -> Workload {
    let s = line_scene(sizes.line_canvas, sizes.line_lengths, sizes.lines, SEED);
    let plan = Plan::for_scene(&s);
    let names = ["production", "dda-f32", "dda-f64", "midpoint-plain"];
    let methods: Vec<Box<dyn Rasterizer>> = names
        .iter()
        .map(|&n| match n {
            "midpoint-plain" => Box::new(PlainMidpoint),
            n => crate::harness::suite::rasterizer(n).expect("a built-in rasterizer"),
        })
        .collect();
    let mut times: Vec<Vec<Duration>> = vec![Vec::new(); methods.len()];
    for _ in 0..sizes.repetitions {
        for (k, r) in methods.iter().enumerate() {
            let started = Instant::now();
            let frame = r.rasterize(&s, &plan);
            times[k].push(started.elapsed());
            std::hint::black_box(frame.expect("lines draw"));
        }
    }
    // Peak heap: each method once more, outside every timing.
    let peaks: Vec<Option<u64>> = methods
        .iter()
        .map(|r| memory::peak(|| r.rasterize(&s, &plan)).1)
        .collect();
    // Pixel sets, line by line: each line alone in the full canvas, so that
    // the float methods round exactly as in the timed run.
    let alone = |i: usize| {
        let mut one = s.clone();
        one.primitives = vec![s.primitives[i].clone()];
        one
    };
    let compared = sizes.lines_compared.min(sizes.lines);
    let mut differ = vec![0u64; names.len()];
    let mut disagree_with_reference = 0;
    for i in 0..compared {
        let one = alone(i);
        let sets: Vec<Vec<usize>> = methods
            .iter()
            .map(|r| lit(&r.rasterize(&one, &plan).expect("lines draw")))
            .collect();
        for k in 1..names.len() {
            differ[k] += u64::from(sets[k] != sets[0]);
        }
        if i < sizes.lines_verified {
            let exact = lit(&crate::reference::render(&one, &plan));
            disagree_with_reference += u64::from(exact != sets[0]);
        }
    }
    differ[0] = disagree_with_reference;
    notes.push(format!(
        "Lines: the exact rule is production's midpoint; it drew the reference's pixel set \
         on {} of the {} lines checked against the reference. Pixel sets are compared \
         on the first {compared} of the {} lines, each drawn alone.",
        sizes.lines_verified.min(compared) as u64 - disagree_with_reference,
        sizes.lines_verified.min(compared),
        sizes.lines
    ));
    let measured = names
        .iter()
        .zip(times)
        .enumerate()
        .map(|(k, (name, times))| Measured {
            method: (*name).to_owned(),
            per_item: Some(median(times) / sizes.lines as u32),
            timed_items: sizes.lines,
            errors: Some(if k == 0 {
                (differ[0], sizes.lines_verified.min(compared) as u64)
            } else {
                (differ[k], compared as u64)
            }),
            coverage_error: None,
            exact: k == 0,
            peak_heap: peaks[k],
            empty_frame: None,
            note: if k == 0 {
                "error against the reference".to_owned()
            } else {
                "error against the exact midpoint rule".to_owned()
            },
        })
        .collect();
    Workload {
        name: format!(
            "lines, {}–{} px, {}² canvas",
            sizes.line_lengths.0, sizes.line_lengths.1, sizes.line_canvas
        ),
        short: "lines".to_owned(),
        baseline: "production".to_owned(),
        items: sizes.lines,
        pixels_per_item: (sizes.line_lengths.0 + sizes.line_lengths.1) / 2.0,
        error_unit: "lines".to_owned(),
        methods: measured,
        parallel_ceiling: None,
    }
}

/// One antialiasing method of the bench: a production pattern, or a
/// measured method of its own.
struct AaMethod {
    name: String,
    antialias: Option<Antialias>,
    rasterizer: Box<dyn Rasterizer>,
}

fn aa_methods(counts: &[u32]) -> Vec<AaMethod> {
    let production = || -> Box<dyn Rasterizer> { Box::new(crate::production::Production) };
    let with = |samples: u32, pattern: Pattern, adaptive: bool| Antialias {
        samples,
        pattern,
        seed: SEED,
        adaptive,
        position_bits: 8,
    };
    let mut out = vec![AaMethod {
        name: "production 1× (aliased)".to_owned(),
        antialias: None,
        rasterizer: production(),
    }];
    for pattern in [
        Pattern::Standard,
        Pattern::Grid,
        Pattern::Stratified,
        Pattern::Random,
        Pattern::NRooks,
    ] {
        for &n in counts {
            if pattern.check_count(n).is_err() || (pattern == Pattern::Standard && n > 16) {
                continue;
            }
            out.push(AaMethod {
                name: format!("production {n}× {}", pattern.name()),
                antialias: Some(with(n, pattern, false)),
                rasterizer: production(),
            });
        }
    }
    out.push(AaMethod {
        name: "production 16× standard, adaptive".to_owned(),
        antialias: Some(with(16, Pattern::Standard, true)),
        rasterizer: production(),
    });
    out.push(AaMethod {
        name: "adaptive-resolve 16× standard".to_owned(),
        antialias: Some(with(16, Pattern::Standard, true)),
        rasterizer: Box::new(crate::production::antialias::resolve::AdaptiveResolve),
    });
    for name in ["adaptive-refine", "area-f32", "tiny-skia", "vello-cpu"] {
        if let Some(r) = crate::harness::suite::rasterizer(name) {
            out.push(AaMethod {
                name: format!("{name} (16× standard case)"),
                antialias: Some(with(16, Pattern::Standard, false)),
                rasterizer: r,
            });
        }
    }
    out
}

/// (RMS over edge pixels, largest |error|) of resolved coverage against
/// exact areas; an aliased frame's coverage counts stand for its resolve.
fn coverage_error(exact: &[f64], frame: &Frame) -> (f64, f64) {
    let resolved = frame
        .resolved
        .clone()
        .unwrap_or_else(|| frame.box_resolve());
    let (mut sum, mut n, mut max) = (0.0, 0usize, 0.0f64);
    for (&e, &r) in exact.iter().zip(&resolved) {
        let edge = (e > 0.0 && e < 1.0) || (r > 0.0 && r < 1.0) || r != e;
        if edge {
            sum += (r - e) * (r - e);
            n += 1;
            max = max.max((r - e).abs());
        }
    }
    ((sum / n.max(1) as f64).sqrt(), max)
}

fn measure_antialias(sizes: &Sizes, notes: &mut Vec<String>) -> Workload {
    let (leg, count) = sizes.antialias;
    let base = triangle_scene(sizes.canvas, leg, count, SEED ^ 0x4141);
    let mut aa_scene = base.clone();
    aa_scene.effects.antialias = Some(Antialias {
        samples: 1,
        pattern: Pattern::Standard,
        seed: 0,
        adaptive: false,
        position_bits: 8,
    });
    let exact: Vec<f64> = crate::reference::exact_areas(&aa_scene)
        .iter()
        .map(|a| a.to_f64().value())
        .collect();
    let methods = aa_methods(sizes.antialias_samples);
    let scenes: Vec<(Scene, Plan)> = methods
        .iter()
        .map(|m| {
            let mut s = base.clone();
            s.effects.antialias = m.antialias.clone();
            let plan = Plan::for_scene(&s);
            (s, plan)
        })
        .collect();
    let mut times: Vec<Vec<Duration>> = vec![Vec::new(); methods.len()];
    let mut results: Vec<Result<(f64, f64), String>> = vec![Err(String::new()); methods.len()];
    for rep in 0..sizes.repetitions {
        for (k, m) in methods.iter().enumerate() {
            if rep > 0 && results[k].is_err() {
                continue;
            }
            let (s, plan) = &scenes[k];
            let started = Instant::now();
            let result = m.rasterizer.rasterize(s, plan);
            times[k].push(started.elapsed());
            if rep == 0 {
                results[k] = result
                    .map(|frame| coverage_error(&exact, &frame))
                    .map_err(|e| e.to_string());
            }
        }
    }
    // Peak heap: each method once more, outside every timing.
    let peaks: Vec<Option<u64>> = methods
        .iter()
        .zip(&scenes)
        .zip(&results)
        .map(|((m, (s, plan)), result)| {
            result
                .is_ok()
                .then(|| memory::peak(|| m.rasterizer.rasterize(s, plan)).1)
                .flatten()
        })
        .collect();
    let measured = methods
        .iter()
        .zip(times)
        .zip(results)
        .zip(peaks)
        .map(|(((m, times), result), peak_heap)| match result {
            Ok(error) => Measured {
                method: m.name.clone(),
                per_item: Some(median(times) / count as u32),
                timed_items: count,
                errors: None,
                coverage_error: Some(error),
                exact: false,
                peak_heap,
                empty_frame: None,
                note: String::new(),
            },
            Err(why) => Measured::not_run(&m.name, why),
        })
        .collect();
    notes.push(format!(
        "Antialiasing: errors are resolved coverage minus the exact area of each pixel \
         (the reference's rational areas, summed over overlapping triangles), RMS over edge \
         pixels and largest; the aliased 1× row resolves each pixel to its centre's coverage. \
         Seeded patterns use seed {SEED:#x}, the same offsets in every pixel."
    ));
    Workload {
        name: format!(
            "antialiasing, L={leg} ({} px each), {}² canvas",
            leg * leg / 2,
            sizes.canvas
        ),
        short: "AA".to_owned(),
        baseline: "production 1× (aliased)".to_owned(),
        items: count,
        pixels_per_item: f64::from(leg * leg) / 2.0,
        error_unit: "coverage, RMS over edge pixels / max".to_owned(),
        methods: measured,
        parallel_ceiling: None,
    }
}

// --- Motion blur ----------------------------------------------------------------

/// The triangles of [`triangle_scene`], each translated over the shutter by
/// `reach`/2 to `reach` px in a random direction (on the 2^-8 grid, so that
/// snapping leaves the motion as it is), sampled at `samples` instants of
/// `pattern` per pixel centre.
pub fn motion_scene(
    canvas: u32,
    leg: u32,
    count: usize,
    reach: f64,
    samples: u32,
    pattern: TimePattern,
    seed: u64,
) -> Scene {
    let mut s = triangle_scene(canvas, leg, count, seed);
    let mut rng = Rng::new(seed ^ 0x4d4f_5645);
    for p in &mut s.primitives {
        let theta = rng.uniform(0.0, std::f64::consts::TAU);
        let length = rng.uniform(reach / 2.0, reach);
        let d = [on_grid(length * theta.cos()), on_grid(length * theta.sin())];
        for v in p.vertices_mut() {
            v.to = Some(Box::new([&v.x + &d[0], &v.y + &d[1]]));
        }
    }
    s.name = format!("moving triangles L={leg}");
    s.effects.motion_blur = Some(MotionBlur {
        shutter: [0, TIME_ONE],
        samples,
        pattern,
        seed,
    });
    s
}

/// Coordinates [`translation_time_coverage`] takes, in units of
/// 2^-(subpixel_bits + 1) px: below 2^24, so that every cross product
/// below is under 2^51 and a comparison of two of their quotients under
/// 2^102, in i128.
const TRANSLATION_UNITS_BITS: u32 = 24;

/// The exact time coverage of each pixel centre (row-major) of a scene of
/// triangles that move by pure translation (SPEC.md §15.2), rounded to f64
/// once per triangle: no reference needed. A translation keeps every edge's
/// direction and the winding, so each edge function at the centre q is
/// linear in τ, E(τ) = α − τ·β with α = d × (q − a) and β = d × v (d the
/// edge, a its start, v the motion), and the covered instants are one
/// interval with rational ends: the shutter cut by τ < α/β where β > 0
/// and τ > α/β where β < 0. An edge with β = 0 keeps its value: it covers
/// always, never, or (a centre riding on it, α = 0) as the fill rule says.
/// Culled and zero-area triangles cover nothing. `None` when the scene
/// antialiases, has a primitive that is not a translating (or static)
/// triangle, or coordinates beyond 2^(24 − subpixel_bits − 1) px.
pub fn translation_time_coverage(scene: &Scene) -> Option<Vec<f64>> {
    let blur = scene.effects.motion_blur.as_ref()?;
    let bits = scene.rules.subpixel_bits?;
    if scene.effects.antialias.is_some() {
        return None;
    }
    let units = |n: &Number| -> Option<i128> {
        let snapped = n.snapped(bits);
        let scaled = snapped.numerator() << (bits as usize + 1);
        let den = dashu_int::IBig::from(snapped.denominator().clone());
        let u: i128 = (&(scaled / den)).try_into().ok()?;
        (u.abs() < 1 << TRANSLATION_UNITS_BITS).then_some(u)
    };
    let (width, height) = (scene.canvas.width as i128, scene.canvas.height as i128);
    let one = 1i128 << (bits + 1);
    let [open, close] = blur.shutter.map(i128::from);
    let mut out = vec![0.0; scene.canvas.pixel_count()];
    for p in &scene.primitives {
        let Primitive::Triangle(t) = p else {
            return None;
        };
        let mut from = [[0i128; 2]; 3];
        let mut to = [[0i128; 2]; 3];
        for (i, v) in t.vertices.iter().enumerate() {
            let [ex, ey] = v.end();
            from[i] = [units(&v.x)?, units(&v.y)?];
            to[i] = [units(ex)?, units(ey)?];
        }
        let motion = [to[0][0] - from[0][0], to[0][1] - from[0][1]];
        if (0..3).any(|i| [to[i][0] - from[i][0], to[i][1] - from[i][1]] != motion) {
            return None;
        }
        let cross = |u: [i128; 2], w: [i128; 2]| u[0] * w[1] - u[1] * w[0];
        let sub = |u: [i128; 2], w: [i128; 2]| [u[0] - w[0], u[1] - w[1]];
        let area = cross(sub(from[1], from[0]), sub(from[2], from[0]));
        let culled = match scene.rules.cull {
            Cull::Clockwise => area > 0,
            Cull::CounterClockwise => area < 0,
            Cull::None => false,
        };
        if area == 0 || culled {
            continue;
        }
        // Clockwise on screen: every edge function positive inside.
        let v = if area > 0 {
            from
        } else {
            [from[0], from[2], from[1]]
        };
        let edges: Vec<([i128; 2], [i128; 2], bool)> = (0..3)
            .map(|i| {
                let (a, b) = (v[i], v[(i + 1) % 3]);
                let d = sub(b, a);
                // §3: heading east on screen, a clockwise triangle lies
                // below (a top edge); heading north, to the east (a left
                // edge).
                let rule = scene.rules.fill_rule;
                let owned = match (d[1].signum(), d[0] > 0) {
                    (0, true) => rule.owns_top(),
                    (0, false) => rule.owns_bottom(),
                    (-1, _) => rule.owns_left(),
                    _ => rule.owns_right(),
                };
                (a, d, owned)
            })
            .collect();
        // Centres in the box swept between open and close, on the canvas.
        let ends = |k: usize| {
            let at = |c: i128, tau: i128| c * TIME_ONE as i128 + motion[k] * tau;
            let all = v.iter().flat_map(|p| [at(p[k], open), at(p[k], close)]);
            let (lo, hi) = all.fold((i128::MAX, i128::MIN), |(l, h), c| (l.min(c), h.max(c)));
            let scale = one * i128::from(TIME_ONE);
            // Centres i·one + one/2 in [lo, hi] (scaled by 2^16), and
            // perhaps one more before: each is decided exactly below.
            let first = (lo - scale / 2).div_euclid(scale);
            let last = (hi - scale / 2).div_euclid(scale);
            (first.max(0), last)
        };
        let ((x0, x1), (y0, y1)) = (ends(0), ends(1));
        for y in y0..=y1.min(height - 1) {
            for x in x0..=x1.min(width - 1) {
                let q = [x * one + one / 2, y * one + one / 2];
                // The interval (lo, hi), each a rational n/m with m > 0, τ
                // in [0, 1].
                let mut lo = (open, i128::from(TIME_ONE));
                let mut hi = (close, i128::from(TIME_ONE));
                let less = |a: (i128, i128), b: (i128, i128)| a.0 * b.1 < b.0 * a.1;
                let mut empty = false;
                for &(a, d, owned) in &edges {
                    let alpha = cross(d, sub(q, a));
                    let beta = cross(d, motion);
                    match beta.signum() {
                        0 => empty |= alpha < 0 || (alpha == 0 && !owned),
                        1 if less((alpha, beta), hi) => hi = (alpha, beta),
                        -1 if less(lo, (-alpha, -beta)) => lo = (-alpha, -beta),
                        _ => {}
                    }
                }
                if !empty && less(lo, hi) {
                    // (hi − lo)/(close − open), as one f64 quotient.
                    let num = hi.0 * lo.1 - lo.0 * hi.1;
                    let den = hi.1 * lo.1;
                    let span = (close - open) as f64 / f64::from(TIME_ONE);
                    out[(y * width + x) as usize] += num as f64 / den as f64 / span;
                }
            }
        }
    }
    Some(out)
}

/// (RMS over moving pixels, largest |error|) of a time coverage against
/// the exact one (SPEC.md §15.4): moving pixels are those whose exact
/// value is not a whole number or whose candidate value is not exact.
pub fn time_error(exact: &[f64], time: &[f64]) -> (f64, f64) {
    let (mut sum, mut n, mut max) = (0.0, 0usize, 0.0f64);
    for (&e, &t) in exact.iter().zip(time) {
        if e.fract() != 0.0 || t != e {
            sum += (t - e) * (t - e);
            n += 1;
            max = max.max((t - e).abs());
        }
    }
    ((sum / n.max(1) as f64).sqrt(), max)
}

/// One motion row: its name, its time pattern and N (none: the static frame
/// at shutter open), and the threads it runs on.
type MotionMethod = (String, Option<(TimePattern, u32)>, usize);

fn motion_methods() -> Vec<MotionMethod> {
    let mut out = vec![(MOTION_BASELINE.to_owned(), None, 1)];
    for n in [4, 16, 64] {
        out.push((
            format!("production {n}× stratified"),
            Some((TimePattern::Stratified, n)),
            1,
        ));
    }
    out.push((
        "production 16× random".to_owned(),
        Some((TimePattern::Random, 16)),
        1,
    ));
    out.push((
        format!("production-tiled 64× stratified ({TILED_THREADS} threads)"),
        Some((TimePattern::Stratified, 64)),
        TILED_THREADS,
    ));
    out
}

/// The motion workload's baseline: its triangles drawn once at shutter
/// open, as if nothing moved.
pub const MOTION_BASELINE: &str = "production, static at shutter open";

fn measure_motion(sizes: &Sizes, notes: &mut Vec<String>) -> Workload {
    let (leg, count, reach) = sizes.motion;
    let seed = SEED ^ 0x4d42;
    let methods = motion_methods();
    let scenes: Vec<(Scene, Plan)> = methods
        .iter()
        .map(|(_, time, _)| {
            let (pattern, n) = time.unwrap_or((TimePattern::Stratified, 1));
            let mut s = motion_scene(sizes.canvas, leg, count, reach, n, pattern, seed);
            if time.is_none() {
                s.effects.motion_blur = None;
                for v in s.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
                    v.to = None;
                }
            }
            let plan = Plan::for_scene(&s);
            (s, plan)
        })
        .collect();
    let exact = translation_time_coverage(&scenes[1].0).expect("pure translations");
    let pools: Vec<OnPool> = methods
        .iter()
        .map(|(name, _, threads)| {
            let inner: Box<dyn Rasterizer> = if name.starts_with("production-tiled") {
                Box::new(crate::production::tiled::Tiled)
            } else {
                Box::new(crate::production::Production)
            };
            OnPool::new(inner, *threads)
        })
        .collect();
    let mut times: Vec<Vec<Duration>> = vec![Vec::new(); methods.len()];
    let mut frames: Vec<Option<Result<Frame, String>>> = vec![None; methods.len()];
    for rep in 0..sizes.repetitions {
        for (k, pool) in pools.iter().enumerate() {
            let (s, plan) = &scenes[k];
            let (result, elapsed) = pool.timed(s, plan);
            times[k].push(elapsed);
            if rep == 0 {
                frames[k] = Some(result.map_err(|e| e.to_string()));
            }
        }
    }
    // Peak heap: each method once more, outside every timing.
    let peaks: Vec<Option<u64>> = pools
        .iter()
        .zip(&scenes)
        .map(|(pool, (s, plan))| memory::peak(|| pool.timed(s, plan)).1)
        .collect();
    let measured = methods
        .iter()
        .zip(times)
        .zip(frames)
        .zip(peaks)
        .map(
            |((((name, _, _), times), frame), peak_heap)| match frame.expect("drawn") {
                Ok(frame) => {
                    let time = frame.time.clone().unwrap_or_else(|| frame.box_resolve());
                    let note = match frame.sample_tests {
                        Some(tests) => format!(
                            "sample test efficiency {} ({} of {} tests covered)",
                            significant(tests.efficiency()),
                            tests.covered,
                            tests.tests
                        ),
                        None => "the error of ignoring motion".to_owned(),
                    };
                    Measured {
                        method: name.clone(),
                        per_item: Some(median(times) / count as u32),
                        timed_items: count,
                        errors: None,
                        coverage_error: Some(time_error(&exact, &time)),
                        exact: false,
                        peak_heap,
                        empty_frame: None,
                        note,
                    }
                }
                Err(why) => Measured::not_run(name, why),
            },
        )
        .collect();
    notes.push(format!(
        "Motion blur: {count} triangles (legs {leg} px) each translated by {}–{reach} px over \
         the shutter; errors are time coverage minus the exact value at each pixel centre \
         (`bench::translation_time_coverage`: under translation each edge crosses a centre \
         at one rational instant), RMS over moving pixels and largest. Production rows run \
         on a pool of one thread, the tiled row on {TILED_THREADS}. Sample test efficiency: \
         covered tests of moving triangles over all their tests (a triangle is tested only \
         at centres in the box it sweeps).",
        reach / 2.0
    ));
    Workload {
        name: format!(
            "motion blur, L={leg} ({} px each), {}² canvas",
            leg * leg / 2,
            sizes.canvas
        ),
        short: "motion".to_owned(),
        baseline: MOTION_BASELINE.to_owned(),
        items: count,
        pixels_per_item: f64::from(leg * leg) / 2.0,
        error_unit: "time coverage, RMS over moving pixels / max".to_owned(),
        methods: measured,
        parallel_ceiling: None,
    }
}

fn targets(workloads: &[Workload], quick: bool, lp: Option<&(String, bool)>) -> Vec<Target> {
    let mut out = Vec::new();
    let find = |short: &str| workloads.iter().find(|w| w.short == short);
    let shown = |r: Option<f64>| r.map_or("not measured".to_owned(), |r| format!("{r:.2}×"));
    let scale = if quick {
        " (quick run: small workloads; run the full bench for the record)"
    } else {
        ""
    };
    for (short, need, px) in [("L=50", 2.5, 1250), ("L=10", 1.5, 50)] {
        let r = find(short).and_then(|w| w.ratio("production", "naive"));
        out.push(Target {
            target: format!("production ≥ {need}× naive on {px}-px triangles ({short})"),
            measured: shown(r),
            met: r.map(|r| r >= need),
            note: format!(
                "{}{scale}",
                if short == "L=10" {
                    "small triangles: per-triangle setup (exact snapping of rational vertices, edge setup) dominates both"
                } else {
                    "mid-size triangles: traversal dominates; naive tests every bounding-box pixel in full"
                }
            ),
        });
    }
    for w in workloads.iter().filter(|w| w.short.starts_with("L=")) {
        // The cost of the declaration: declared time over plain time.
        let r = w.ratio(PAIRED, DECLARED);
        out.push(Target {
            target: format!(
                "a static scene declaring motion blur ≤ 1.1× the cost of the same scene without ({})",
                w.short
            ),
            measured: r.map_or("not measured".to_owned(), |r| format!("{r:.2}× the cost")),
            met: r.map(|r| r <= 1.1),
            note: format!(
                "nothing moves, so the plan has no time loop and production draws the static scene (SPEC.md §15.1); `{PAIRED}` and `{DECLARED}` are drawn in turn, each with its own plan{scale}"
            ),
        });
    }
    if let Some(w) = find("motion") {
        for m in w.methods.iter().filter(|m| m.note.contains("efficiency")) {
            let Some(n) = m
                .method
                .split('×')
                .next()
                .and_then(|h| h.rsplit(' ').next())
                .and_then(|n| n.parse::<f64>().ok())
            else {
                continue;
            };
            let bound = 0.75 / n.sqrt();
            let rms = m.coverage_error.map(|e| e.0);
            out.push(Target {
                target: format!(
                    "motion: `{}` within SPEC's default max_time_rms 0.75·N^-1/2 = {bound:.3}",
                    m.method
                ),
                measured: rms.map_or("not measured".to_owned(), |r| {
                    format!("RMS {} ({:.2}× the bound)", significant(r), r / bound)
                }),
                met: rms.map(|r| r <= bound),
                note: format!(
                    "against exact time coverage of translating triangles (SPEC.md §15.4){scale}"
                ),
            });
        }
    }
    for w in workloads.iter().filter(|w| w.short.starts_with("L=")) {
        let r = w.ratio("production", "euc");
        if w.method("euc").is_none() {
            continue;
        }
        out.push(Target {
            target: format!("production ≥ 3× euc ({})", w.short),
            measured: shown(r),
            met: r.map(|r| r >= 3.0),
            note: format!(
                "euc is timed through its adapter (scene conversion and read-back included){scale}"
            ),
        });
    }
    out.extend(llvmpipe_targets(workloads, lp, scale));
    if let Some(w) = find("AA") {
        const RESOLVE: &str = "adaptive-resolve 16× standard";
        const MASK: &str = "production 16× standard, adaptive";
        let cost = |method: &str| w.ratio("production 1× (aliased)", method);
        for (method, note) in [
            (
                RESOLVE,
                "adaptive-resolve writes no sample mask: interior pixels add 16 untested, edge pixels count their covered samples (the box resolve of full sampling, bit for bit)".to_owned(),
            ),
            (
                MASK,
                format!(
                    "production's adaptive sampling writing the full 16-slot mask: interior pixels are filled without sampling, but every covered pixel still writes 16 coverage counts and 16 owners, into a frame 16× the size of the 1× one (see its peak heap){}",
                    match cost(RESOLVE) {
                        Some(r) if r <= 3.0 => format!("; `{RESOLVE}`, the same resolved coverage without the mask, meets the target ({r:.2}× the cost)"),
                        _ => String::new(),
                    }
                ),
            ),
        ] {
            let r = cost(method);
            out.push(Target {
                target: format!("adaptive 16× AA ≤ 3× the cost of 1× (1250-px triangles): `{method}`"),
                measured: r.map_or("not measured".to_owned(), |r| format!("{r:.2}× the cost")),
                met: r.map(|r| r <= 3.0),
                note: format!("{note}{scale}"),
            });
        }
    }
    if let Some(w) = find("lines") {
        let r = w.ratio("production", "dda-f32");
        out.push(Target {
            target: "lines: production midpoint ≥ 2× dda-f32".to_owned(),
            measured: shown(r),
            met: r.map(|r| r >= 2.0),
            note: format!("both write the same frame (coverage and last primitive per pixel); memory traffic bounds both{scale}"),
        });
        let r = w.ratio("production", "midpoint-plain");
        out.push(Target {
            target: "lines: production midpoint ≥ 1.3× a plain midpoint loop".to_owned(),
            measured: shown(r),
            met: r.map(|r| r >= 1.3),
            note: format!("the plain loop (bench.rs `PlainMidpoint`) steps the same exact rule pixel by pixel, bounds-checking and writing each pixel; production draws coverage-only midpoint scenes whose frame exceeds 4 MiB band by band (768 KiB bands, rows padded against 4K aliasing) with resumable walkers, x-major lines in row runs, and smaller frames line by line (production/line.rs `midpoint_lines`){scale}"),
        });
    }
    // The tiled method on the largest triangle workload measured.
    if let Some(w) = workloads
        .iter()
        .filter(|w| w.short.starts_with("L="))
        .max_by_key(|w| w.pixels_per_item as u64)
    {
        let r = w.ratio("production-tiled", "production");
        let ceiling = match (w.parallel_ceiling, r) {
            (Some(c), Some(r)) => format!(
                "the machine gave {TILED_THREADS} threads {c:.2}× during this run (a perfectly \
                 parallel integer loop, no memory traffic, timed in the same rounds: \
                 `bench::ParallelCeiling`), so the tiled method reached {:.0}% of what the \
                 machine allowed{}. ",
                100.0 * r / c,
                if r >= 1.7 {
                    ""
                } else if c < 1.7 {
                    ": the machine itself gave less than the target (other work on the cores), \
                     so this run cannot tell; rerun on an idle machine"
                } else {
                    ": the cores were free, so the shortfall is the method's own (binning \
                     and allocating the frame run on one thread; a triangle is set up again \
                     in each band it spans)"
                }
            ),
            _ => String::new(),
        };
        out.push(Target {
            target: format!(
                "production-tiled ≥ 1.7× production ({}, {TILED_THREADS} threads)",
                w.short
            ),
            measured: shown(r),
            met: r.map(|r| r >= 1.7),
            note: format!(
                "{ceiling}{}-row bands drawn in parallel on a dedicated rayon pool of {TILED_THREADS} threads, primitives binned and drawn in order in each (the frame is production's); placing vertices, binning and per-band setup are timed, handing the job to the pool is not (OnPool::timed){scale}",
                crate::production::tiled::BAND
            ),
        });
    }
    for w in workloads.iter().filter(|w| w.short.starts_with("L=")) {
        // Within 10×: production is at most 10× faster.
        let r = w.ratio("production", "reference");
        out.push(Target {
            target: format!("reference within 10× of production ({})", w.short),
            measured: r.map_or("not measured".to_owned(), |r| {
                format!("production {r:.2}× faster")
            }),
            met: r.map(|r| r <= 10.0),
            note: format!("the reference finds each row's covered span by exact integer division of the three edge functions and steps exact values along it; production is timed single-threaded{scale}"),
        });
    }
    out
}

/// The command that measures the llvmpipe rows.
pub const LLVMPIPE_COMMAND: &str = "cargo run --release --features lavapipe,gl -- bench";

/// Production against llvmpipe single-threaded, per triangle workload and
/// driver compiled in; without any, one row saying how to measure them.
fn llvmpipe_targets(
    workloads: &[Workload],
    lp: Option<&(String, bool)>,
    scale: &str,
) -> Vec<Target> {
    let mut out = Vec::new();
    let threads = match lp {
        Some((v, true)) => format!("LP_NUM_THREADS={v} (set by the bench)"),
        Some((v, false)) => format!(
            "LP_NUM_THREADS={v} (set before the run{})",
            if v == "1" {
                ""
            } else {
                ": not single-threaded, so this is not the target's comparison"
            }
        ),
        None => "LP_NUM_THREADS not set".to_owned(),
    };
    for w in workloads.iter().filter(|w| w.short.starts_with("L=")) {
        let Some(production) = w.method("production") else {
            continue;
        };
        for (driver, through) in DRIVERS {
            let Some(d) = w.method(driver) else {
                continue;
            };
            let full = w.ratio("production", driver);
            let marginal = marginal_per_item(production)
                .zip(marginal_per_item(d))
                .map(|(p, d)| d / p);
            let measured = match (full, marginal) {
                (Some(f), Some(m)) => format!("{f:.2}× the whole call, {m:.2}× marginal"),
                (Some(f), None) => {
                    format!("{f:.2}× the whole call; marginal cost not above the noise")
                }
                _ => "not measured".to_owned(),
            };
            let empty = |m: &Measured| m.empty_frame.map_or("—".to_owned(), time_text);
            let limit = match (full, marginal) {
                (Some(f), Some(m)) if f >= 3.0 && m < 3.0 => format!(
                    "Not met: only the whole call reaches 3×, through llvmpipe's fixed \
                     per-frame cost; above it, per triangle, production is {m:.2}× llvmpipe. "
                ),
                (Some(f), Some(m)) if f < 3.0 => format!(
                    "Not met: production is {f:.2}× llvmpipe on the whole call and {m:.2}× per \
                     triangle above the fixed cost, and llvmpipe's time includes the vertex \
                     stream the adapter builds on the CPU (exact snapping, then f32). "
                ),
                _ => String::new(),
            };
            let note = if d.per_item.is_none() {
                format!("`{driver}` did not draw: {}", d.note)
            } else {
                format!(
                    "{limit}llvmpipe through {through}, {threads}. Met when production is ≥ 3× on \
                     both measures: the whole call (for `{driver}`: building the vertex \
                     stream with exact snapping, uploading it, drawing, copying the targets \
                     back and filling a frame; for production: drawing into a new frame), and \
                     the marginal cost per triangle, each method's time minus its time on the \
                     same canvas with no triangles ({} for `{driver}`, {} for production), \
                     which leaves out the fixed per-frame clearing and read-back. The device \
                     and pipelines were created before the first timing{scale}",
                    empty(d),
                    empty(production)
                )
            };
            out.push(Target {
                target: format!(
                    "production ≥ 3× llvmpipe single-threaded (`{driver}`, {})",
                    w.short
                ),
                measured,
                met: full.zip(marginal).map(|(f, m)| f >= 3.0 && m >= 3.0),
                note,
            });
        }
    }
    if out.is_empty() {
        out.push(Target {
            target: "production ≥ 3× llvmpipe single-threaded".to_owned(),
            measured: "not measured".to_owned(),
            met: None,
            note: format!(
                "this binary was built without the Mesa adapters; the llvmpipe rows need \
                 `--features lavapipe` (and `gl`): `{LLVMPIPE_COMMAND}`, with Mesa's \
                 packages installed (Debian: mesa-vulkan-drivers libvulkan1 libegl1 \
                 libegl-mesa0 libgl1-mesa-dri; `.ci/run` installs them)"
            ),
        });
    }
    out
}

/// The value of `LP_NUM_THREADS`, if set.
pub fn lp_num_threads() -> Option<String> {
    std::env::var("LP_NUM_THREADS").ok()
}

/// Where a llvmpipe adapter is compiled in: sets `LP_NUM_THREADS=1` (one
/// rasterizer thread; the calling thread bins and waits) unless the user
/// set it, before any driver starts (llvmpipe reads it when its screen is
/// created). Returns (its value, whether the bench set it).
fn pin_llvmpipe_threads() -> Option<(String, bool)> {
    if !cfg!(any(feature = "lavapipe", feature = "gl")) {
        return None;
    }
    match lp_num_threads() {
        Some(v) => Some((v, false)),
        None => {
            // Before any driver is loaded, on the one thread running the
            // bench: nothing reads the environment concurrently.
            std::env::set_var("LP_NUM_THREADS", "1");
            Some(("1".to_owned(), true))
        }
    }
}

fn machine() -> (String, usize) {
    let info = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
    let model = info
        .lines()
        .find(|l| l.starts_with("model name"))
        .and_then(|l| l.split_once(':'))
        .map_or("unknown CPU".to_owned(), |(_, m)| m.trim().to_owned());
    let cores = info.lines().filter(|l| l.starts_with("processor")).count();
    let cores = if cores > 0 {
        cores
    } else {
        std::thread::available_parallelism().map_or(1, |n| n.get())
    };
    (model, cores)
}

/// The 1, 5 and 15 min load averages, where the system reports them.
fn load_average() -> Option<String> {
    let text = std::fs::read_to_string("/proc/loadavg").ok()?;
    let fields: Vec<&str> = text.split_whitespace().take(3).collect();
    (fields.len() == 3).then(|| fields.join(" "))
}

/// Runs every workload.
pub fn run(options: Options, progress: &mut dyn FnMut(&str)) -> Report {
    let lp_num_threads = pin_llvmpipe_threads();
    let memory_counted = memory::installed();
    let load_before = load_average();
    let started = Instant::now();
    let sizes = Sizes::for_options(options);
    let mut notes = Vec::new();
    let mut workloads = Vec::new();
    for (k, &(leg, count)) in sizes.triangles.iter().enumerate() {
        if count == 0 {
            notes.push(format!(
                "L={leg} is left out of the quick run (it does not fit a small canvas)."
            ));
            continue;
        }
        progress(&format!("triangles L={leg}: {count} triangles"));
        workloads.push(measure_triangles(
            leg,
            count,
            sizes.reference_triangles[k],
            &sizes,
            &mut notes,
        ));
    }
    progress(&format!("lines: {} lines", sizes.lines));
    workloads.push(measure_lines(&sizes, &mut notes));
    progress(&format!(
        "antialiasing: {} triangles, L={}",
        sizes.antialias.1, sizes.antialias.0
    ));
    workloads.push(measure_antialias(&sizes, &mut notes));
    let (leg, count, _) = sizes.motion;
    progress(&format!("motion blur: {count} moving triangles, L={leg}"));
    workloads.push(measure_motion(&sizes, &mut notes));
    let (machine, cores) = machine();
    let targets = targets(&workloads, options.quick, lp_num_threads.as_ref());
    Report {
        quick: options.quick,
        machine,
        cores,
        date: crate::harness::matrix::today(),
        version: env!("CARGO_PKG_VERSION").to_owned(),
        repetitions: sizes.repetitions,
        workloads,
        targets,
        notes,
        elapsed: started.elapsed(),
        load: load_before.zip(load_average()),
        memory_counted,
        lp_num_threads,
    }
}

// --- Writing ------------------------------------------------------------------

fn time_text(d: Duration) -> String {
    let s = d.as_secs_f64();
    if s >= 1e-3 {
        format!("{:.3} ms", s * 1e3)
    } else if s >= 1e-6 {
        format!("{:.3} µs", s * 1e6)
    } else {
        format!("{:.1} ns", s * 1e9)
    }
}

/// Three significant digits.
fn significant(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let digits = (2 - v.abs().log10().floor() as i32).max(0) as usize;
    format!("{v:.digits$}")
}

impl Report {
    pub fn to_markdown(&self, svg_name: &str) -> String {
        let mut md = String::new();
        let _ = writeln!(md, "# rastercheck bench\n");
        let command = match (self.quick, self.lp_num_threads.is_some()) {
            (true, _) => "`rastercheck bench --quick`".to_owned(),
            (false, true) => format!("`{LLVMPIPE_COMMAND}`"),
            (false, false) => format!(
                "`cargo run --release -- bench` (with the llvmpipe rows: `{LLVMPIPE_COMMAND}`)"
            ),
        };
        let _ = writeln!(
            md,
            "Written by {command}. Every number below was measured in this one run, on the \
             same seeded workloads (seed {SEED:#x}), one thread (but `production-tiled`, on a \
             pool of {TILED_THREADS}).\n"
        );
        let _ = writeln!(md, "- machine: {} ({} cores)", self.machine, self.cores);
        let _ = writeln!(md, "- date: {}", self.date);
        let _ = writeln!(md, "- rastercheck version: {}", self.version);
        let _ = writeln!(
            md,
            "- timing: median of {} interleaved repetitions per method; run took {:.1} s",
            self.repetitions,
            self.elapsed.as_secs_f64()
        );
        if let Some((before, after)) = &self.load {
            let _ = writeln!(
                md,
                "- load average (1, 5, 15 min): {before} before the run, {after} after; \
                 above 0 it is other work sharing the {} cores, which the two-thread \
                 method feels most",
                self.cores
            );
        }
        match &self.lp_num_threads {
            Some((v, by_bench)) => {
                let _ = writeln!(
                    md,
                    "- llvmpipe rows (`lavapipe`, `gl`): LP_NUM_THREADS={v}, {}",
                    if *by_bench {
                        "set by the bench (one rasterizer thread; the calling thread bins and waits)"
                    } else {
                        "as set before the run"
                    }
                );
            }
            None => {
                let _ = writeln!(
                    md,
                    "- llvmpipe rows: not in this build (`{LLVMPIPE_COMMAND}` adds them)"
                );
            }
        }
        let _ = writeln!(
            md,
            "- peak heap: {}",
            if self.memory_counted {
                "each method run once more, outside every timing, with a counting allocator \
                 (see the notes)"
            } else {
                "not measured (no counting allocator in this program)"
            }
        );
        if self.quick {
            let _ = writeln!(
                md,
                "- **quick run**: small canvas, few items; timings are indicative only"
            );
        }
        let _ = writeln!(md);
        let _ = writeln!(md, "![accuracy against time]({svg_name})\n");
        let _ = writeln!(md, "## Workloads\n");
        for w in &self.workloads {
            let _ = writeln!(md, "### {} ({} items)\n", w.name, w.items);
            let per_second = if w.short == "lines" {
                "Mlines/s"
            } else {
                "Mtri/s"
            };
            let _ = writeln!(
                md,
                "| method | time per item | {per_second} | Mpix/s | × `{}` | error ({}) | peak heap | note |",
                w.baseline, w.error_unit
            );
            let _ = writeln!(md, "|---|---|---|---|---|---|---|---|");
            for m in &w.methods {
                let (time, rate, mpix) = match m.per_item {
                    Some(d) if d.as_nanos() > 0 => {
                        let s = d.as_secs_f64();
                        (
                            time_text(d),
                            significant(1e-6 / s),
                            significant(w.pixels_per_item * 1e-6 / s),
                        )
                    }
                    _ => ("—".to_owned(), "—".to_owned(), "—".to_owned()),
                };
                let ratio = w
                    .ratio(&m.method, &w.baseline)
                    .map_or("—".to_owned(), |r| format!("{r:.2}"));
                let error = match (m.errors, m.coverage_error) {
                    (_, Some((rms, max))) => {
                        format!("{} / {}", significant(rms), significant(max))
                    }
                    (Some((0, of)), None) => format!("0 of {of} (exact)"),
                    (Some((e, of)), None) => {
                        format!("{e} of {of} ({:.3}%)", 100.0 * e as f64 / of.max(1) as f64)
                    }
                    (None, None) => "—".to_owned(),
                };
                let heap = match (m.peak_heap, m.per_item) {
                    (Some(b), _) => memory::bytes_text(b),
                    (None, Some(_)) if !self.memory_counted => "not measured".to_owned(),
                    (None, _) => "—".to_owned(),
                };
                let _ = writeln!(
                    md,
                    "| `{}` | {time} | {rate} | {mpix} | {ratio} | {error} | {heap} | {} |",
                    m.method, m.note
                );
            }
            let _ = writeln!(md);
        }
        let _ = writeln!(
            md,
            "“×” is the method's speed relative to the workload's baseline measured side by side \
             (above 1: faster). Mpix/s counts nominal pixels (a triangle's area L²/2, a line's \
             mean length). Triangle errors are samples whose coverage count or last primitive \
             differs from the exact reference's frame for the whole workload, out of the \
             reference's covered samples (counted with multiplicity).\n"
        );
        let _ = writeln!(md, "## Performance targets\n");
        let _ = writeln!(md, "| target | measured | status | note |");
        let _ = writeln!(md, "|---|---|---|---|");
        for t in &self.targets {
            let status = match t.met {
                Some(true) => "met",
                Some(false) => "not met",
                None => "not measured",
            };
            let _ = writeln!(
                md,
                "| {} | {} | {status} | {} |",
                t.target, t.measured, t.note
            );
        }
        let _ = writeln!(md, "\n## Notes\n");
        for n in &self.notes {
            let _ = writeln!(md, "- {n}");
        }
        let _ = writeln!(
            md,
            "- Adapters (tiny-skia, euc, and lavapipe and gl where built in) are timed through \
             rastercheck's adapters: converting the scene and reading their pixels back into a \
             frame is included. The llvmpipe adapters create their device (or EGL context) and \
             pipelines once per process, on an untimed first draw; every timed call still \
             builds the vertex stream, uploads it, allocates and clears the targets, draws, \
             copies them back and fills a frame. Their `, marginal` rows subtract the same \
             call on the same canvas with no triangles."
        );
        let _ = writeln!(
            md,
            "- Peak heap: each method is run once more after its timings, never inside one, \
             with a counting global allocator on (`bench::memory`): the most heap it held \
             above the level at the call's start, on every thread it used, the frame it \
             returns included. Counted: every allocation through Rust's allocator (for the \
             llvmpipe adapters, wgpu's and the adapter's own: the vertex stream, the bytes \
             copied out of the driver's read-back buffers, the frame). Not counted: memory Mesa's C code allocates itself \
             (render targets, JIT-compiled shaders, bins, its threads' heap), stacks, and pages \
             kept by the allocator after a free. The reference's figure is for its exact frame \
             of the whole workload."
        );
        if let Some(c) = self
            .workloads
            .iter()
            .filter_map(|w| w.parallel_ceiling.map(|c| (w, c)))
            .map(|(w, c)| format!("{} {c:.2}×", w.short))
            .reduce(|a, b| format!("{a}, {b}"))
        {
            let _ = writeln!(
                md,
                "- Parallel ceiling: a perfectly parallel integer loop (no memory traffic) on \
                 the tiled method's pool of {TILED_THREADS} threads against one thread, timed \
                 in the rounds of each triangle workload: {c}. Near {TILED_THREADS}× the \
                 cores were free; below, other work shared them."
            );
        }
        let _ = writeln!(
            md,
            "- Only ratios measured side by side in this run are claims; absolute times \
             depend on the machine."
        );
        md
    }

    /// A log–log chart of error against time per item, one point per method
    /// per workload, the Pareto front of each workload marked.
    pub fn to_svg(&self) -> String {
        const W: f64 = 820.0;
        const H: f64 = 520.0;
        const LEFT: f64 = 80.0;
        const RIGHT: f64 = 160.0;
        const TOP: f64 = 40.0;
        const BOTTOM: f64 = 60.0;
        const COLOURS: [&str; 5] = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"];
        let points: Vec<(usize, &Measured, f64, f64)> = self
            .workloads
            .iter()
            .enumerate()
            .flat_map(|(k, w)| {
                w.methods.iter().filter_map(move |m| {
                    Some((k, m, m.per_item?.as_secs_f64(), m.error_fraction()?))
                })
            })
            .filter(|p| p.2 > 0.0)
            .collect();
        let lt = |v: f64| v.log10();
        let (mut t0, mut t1) = points.iter().fold((f64::MAX, f64::MIN), |(a, b), p| {
            (a.min(lt(p.2)), b.max(lt(p.2)))
        });
        if points.is_empty() {
            (t0, t1) = (-9.0, -3.0);
        }
        t0 = t0.floor();
        t1 = t1.ceil().max(t0 + 1.0);
        let nonzero: Vec<f64> = points.iter().map(|p| p.3).filter(|&e| e > 0.0).collect();
        let mut e0 = nonzero.iter().fold(f64::MAX, |a, &e| a.min(lt(e)));
        let mut e1 = nonzero.iter().fold(f64::MIN, |a, &e| a.max(lt(e)));
        if nonzero.is_empty() {
            (e0, e1) = (-4.0, 0.0);
        }
        e0 = e0.floor();
        e1 = e1.ceil().max(e0 + 1.0);
        let plot_h = H - TOP - BOTTOM;
        let floor_y = TOP + plot_h; // zero errors
        let x_of = |t: f64| LEFT + (lt(t) - t0) / (t1 - t0) * (W - LEFT - RIGHT);
        let y_of = |e: f64| {
            if e <= 0.0 {
                floor_y
            } else {
                TOP + (e1 - lt(e)) / (e1 - e0) * (plot_h - 40.0)
            }
        };
        let mut svg = String::new();
        let _ = writeln!(
            svg,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" viewBox="0 0 {W} {H}" font-family="sans-serif" font-size="11">"#
        );
        let _ = writeln!(svg, r#"<rect width="{W}" height="{H}" fill="white"/>"#);
        let _ = writeln!(
            svg,
            r#"<text x="{}" y="20" text-anchor="middle" font-size="14">Error against time per item (log–log); filled: Pareto front of its workload</text>"#,
            W / 2.0
        );
        // Axes and grid.
        let right = W - RIGHT;
        let _ = writeln!(
            svg,
            r##"<line x1="{LEFT}" y1="{TOP}" x2="{LEFT}" y2="{floor_y}" stroke="#000"/><line x1="{LEFT}" y1="{floor_y}" x2="{right}" y2="{floor_y}" stroke="#000"/>"##
        );
        for d in (t0 as i32)..=(t1 as i32) {
            let x = x_of(10f64.powi(d));
            let _ = writeln!(
                svg,
                r##"<line x1="{x:.1}" y1="{TOP}" x2="{x:.1}" y2="{floor_y}" stroke="#ddd"/><text x="{x:.1}" y="{:.1}" text-anchor="middle">{}</text>"##,
                floor_y + 16.0,
                time_text(Duration::from_secs_f64(10f64.powi(d)))
            );
        }
        for d in (e0 as i32)..=(e1 as i32) {
            let y = y_of(10f64.powi(d));
            let _ = writeln!(
                svg,
                r##"<line x1="{LEFT}" y1="{y:.1}" x2="{right}" y2="{y:.1}" stroke="#ddd"/><text x="{:.1}" y="{:.1}" text-anchor="end">1e{d}</text>"##,
                LEFT - 6.0,
                y + 4.0
            );
        }
        let _ = writeln!(
            svg,
            r##"<line x1="{LEFT}" y1="{floor_y}" x2="{right}" y2="{floor_y}" stroke="#000" stroke-width="2"/><text x="{:.1}" y="{:.1}" text-anchor="end" font-weight="bold">exact</text>"##,
            LEFT - 6.0,
            floor_y + 4.0
        );
        let _ = writeln!(
            svg,
            r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">time per item (triangle or line), log scale</text>"#,
            (LEFT + right) / 2.0,
            H - 16.0
        );
        let _ = writeln!(
            svg,
            r#"<text transform="translate(18 {:.1}) rotate(-90)" text-anchor="middle">error (mismatched sample or line fraction), log scale</text>"#,
            (TOP + floor_y) / 2.0
        );
        // Points, Pareto fronts, legend.
        for (k, w) in self.workloads.iter().enumerate() {
            let colour = COLOURS[k % COLOURS.len()];
            let mine: Vec<&(usize, &Measured, f64, f64)> =
                points.iter().filter(|p| p.0 == k).collect();
            let mut front: Vec<(f64, f64)> = mine
                .iter()
                .filter(|p| {
                    !mine
                        .iter()
                        .any(|q| q.2 <= p.2 && q.3 <= p.3 && (q.2 < p.2 || q.3 < p.3))
                })
                .map(|p| (p.2, p.3))
                .collect();
            front.sort_by(|a, b| a.0.total_cmp(&b.0));
            if front.len() > 1 {
                let path: Vec<String> = front
                    .iter()
                    .map(|&(t, e)| format!("{:.1},{:.1}", x_of(t), y_of(e)))
                    .collect();
                let _ = writeln!(
                    svg,
                    r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-dasharray="4 3"/>"#,
                    path.join(" ")
                );
            }
            for p in &mine {
                let on_front = front.contains(&(p.2, p.3));
                let (x, y) = (x_of(p.2), y_of(p.3));
                let fill = if on_front { colour } else { "white" };
                let _ = writeln!(
                    svg,
                    r#"<circle cx="{x:.1}" cy="{y:.1}" r="4" fill="{fill}" stroke="{colour}" stroke-width="1.5"/><text x="{:.1}" y="{:.1}" fill="{colour}" transform="rotate(-30 {:.1} {:.1})">{} {}</text>"#,
                    x + 6.0,
                    y - 4.0,
                    x + 6.0,
                    y - 4.0,
                    p.1.method,
                    w.short
                );
            }
            let ly = TOP + 20.0 + 18.0 * k as f64;
            let _ = writeln!(
                svg,
                r#"<circle cx="{:.1}" cy="{ly:.1}" r="4" fill="{colour}"/><text x="{:.1}" y="{:.1}">{}</text>"#,
                right + 20.0,
                right + 30.0,
                ly + 4.0,
                w.short
            );
        }
        let _ = writeln!(svg, "</svg>");
        svg
    }
}
