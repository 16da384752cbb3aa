//! The result model: one method on one workload ([`Measured`]), a workload
//! and its methods ([`Workload`]), a performance target ([`Target`]) and a
//! whole run ([`Report`]). Plain data: measuring fills it, `targets.rs`
//! judges it, `markdown.rs` and `chart.rs` write it.

use std::time::Duration;

/// One method on one workload.
#[derive(Clone, Debug)]
pub struct Measured {
    pub method: String,
    /// Median time per item (triangle or line) of the method's own work:
    /// its draw call alone where it has one ([`Prepared::draw`], see
    /// `whole_call`), else the whole call. `None` when the method could not
    /// run, with the reason in `note`.
    ///
    /// [`Prepared::draw`]: crate::rasterizer::Prepared::draw
    pub per_item: Option<Duration>,
    /// Where `per_item` is the draw call alone: the median time per item of
    /// the whole call (`Rasterizer::rasterize`: converting the scene,
    /// uploading it, drawing, reading a frame back). The difference is the
    /// adapter's overhead.
    pub whole_call: Option<Duration>,
    /// Where `per_item` is the draw call alone: the set-up of one frame
    /// (converting the scene and, for a driver, uploading it) and the
    /// median read-back of one frame, each timed apart from the draw.
    pub set_up: Option<Duration>,
    pub read_back: Option<Duration>,
    /// Items the timing was taken on.
    pub timed_items: usize,
    /// Mismatched samples (triangles) or lines whose pixel set differs
    /// (lines), and out of how many.
    pub errors: Option<(u64, u64)>,
    /// Antialiasing: (RMS over edge pixels, largest) of resolved coverage
    /// minus exact area.
    pub coverage_error: Option<(f64, f64)>,
    pub exact: bool,
    /// Peak heap bytes of one extra, untimed run (see
    /// [`memory`](super::memory)); `None` when not measured.
    pub peak_heap: Option<u64>,
    pub note: String,
}

impl Measured {
    /// A row timed on its whole call only, nothing of it measured yet.
    pub(super) fn whole(method: &str, per_item: Duration, timed_items: usize) -> Measured {
        Measured {
            per_item: Some(per_item),
            timed_items,
            note: String::new(),
            ..Measured::not_run(method, String::new())
        }
    }

    /// The adapter's overhead per item: the whole call minus the draw.
    pub fn overhead(&self) -> Option<Duration> {
        Some(self.whole_call?.saturating_sub(self.per_item?))
    }

    /// A method that could not run on a workload, and why.
    pub(super) fn not_run(method: &str, why: String) -> Measured {
        Measured {
            method: method.to_owned(),
            per_item: None,
            whole_call: None,
            set_up: None,
            read_back: None,
            timed_items: 0,
            errors: None,
            coverage_error: None,
            exact: false,
            peak_heap: None,
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
    /// same rounds
    /// ([`ParallelCeiling::ratio`](super::timing::ParallelCeiling::ratio)).
    pub parallel_ceiling: Option<f64>,
}

impl Workload {
    pub fn method(&self, name: &str) -> Option<&Measured> {
        self.methods.iter().find(|m| m.method == name)
    }

    /// How many times faster `a` is than `b`, like for like: their draw
    /// calls alone when both have one, else their whole calls.
    pub fn ratio(&self, a: &str, b: &str) -> Option<f64> {
        let (a, b) = (self.method(a)?, self.method(b)?);
        let draws = a.whole_call.is_some() && b.whole_call.is_some();
        let time = |m: &Measured| match draws {
            true => m.per_item,
            false => m.whole_call.or(m.per_item),
        };
        let (ta, tb) = (time(a)?.as_secs_f64(), time(b)?.as_secs_f64());
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
    /// Whether peak heap was counted
    /// ([`memory::installed`](super::memory::installed)).
    pub memory_counted: bool,
    /// Where a llvmpipe adapter is compiled in: `LP_NUM_THREADS` during
    /// the run, and whether the bench set it.
    pub lp_num_threads: Option<(String, bool)>,
}
