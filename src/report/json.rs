//! `report.json`: the machine-readable report (schema in SPEC.md §10).
//!
//! Built from the run's outcomes; every other output (JUnit, the markdown
//! summary, the HTML page) is written from this model, so they cannot
//! disagree.

use serde::{Deserialize, Serialize};

use super::interned::{maybe_name, name, Word};
use super::machine::Machine;

use crate::harness::flaky::Flaky;
use crate::harness::golden::GoldenStatus;
use crate::harness::judge::Verdict;
use crate::harness::runner::{CaseOutcome, Problem, Tally};
use crate::metrics::antialias::AntialiasMetrics;
use crate::metrics::ties::TieMetrics;
use crate::metrics::time::TimeMetrics;
use crate::metrics::Metrics;
use crate::rasterizer::Snapping;
use crate::scene::{ClipRules, DeclaredRule, Scene};

pub const SCHEMA: &str = "rastercheck-report/1";

/// Hands over a report's case entries, in order, one at a time (from
/// memory, or read back from disk: `spool.rs`).
pub type Cases<'a> = dyn FnMut(&mut dyn FnMut(&CaseEntry)) -> Result<(), String> + 'a;

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Report {
    #[serde(deserialize_with = "name")]
    pub schema: Word,
    pub tool: Tool,
    /// False while the run is under way, or when it was cut short: cases
    /// with status `not-run` did not run.
    pub complete: bool,
    /// The command line, for reproducing the run.
    pub command: Vec<String>,
    /// The host it ran on and the day (SPEC.md §10); empty in a report
    /// written before it was recorded.
    #[serde(default)]
    pub machine: Machine,
    /// `K/N` when the run was the K-th of N shards of its suite
    /// (`run --shard K/N`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shard: Option<String>,
    /// A merged report's inputs (`rastercheck merge`, SPEC.md §10.3): each
    /// report's file, machine and shard, and the rows it gave.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub sources: Vec<Source>,
    pub rasterizers: Vec<RasterizerInfo>,
    pub limits: LimitsInfo,
    /// Random seeds the run used (none yet: every case is deterministic).
    pub seeds: Vec<u64>,
    pub totals: Totals,
    pub cases: Vec<CaseEntry>,
}

/// One report that went into a merged one.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Source {
    /// Its `report.json`, as named on the command line.
    pub report: String,
    pub machine: Machine,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shard: Option<String>,
    /// The merged report's rasterizer rows its results went into.
    pub rows: Vec<String>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Tool {
    #[serde(deserialize_with = "name")]
    pub name: Word,
    #[serde(deserialize_with = "name")]
    pub version: Word,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RasterizerInfo {
    pub name: String,
    pub foil: bool,
    /// What the program says it is (its hello's name and version), when
    /// it said so during the run.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub declared: Option<String>,
    /// What the API's checker said of a driver adapter's calls over the
    /// run (SPEC.md §10); absent for a rasterizer that calls no driver API.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub api_record: Option<crate::rasterizer::ApiRecord>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct LimitsInfo {
    pub max_canvas_pixels: u64,
    pub max_primitives: usize,
    pub max_samples: u64,
    pub max_case_bytes: u64,
    pub max_case_memory: u64,
    /// Seconds per rasterizer and case; `null` for none.
    pub case_timeout_s: Option<f64>,
}

impl LimitsInfo {
    pub fn of(limits: &crate::scene::Limits) -> LimitsInfo {
        LimitsInfo {
            max_canvas_pixels: limits.max_canvas_pixels,
            max_primitives: limits.max_primitives,
            max_samples: limits.max_samples,
            max_case_bytes: limits.max_case_bytes,
            max_case_memory: limits.max_case_memory,
            case_timeout_s: limits.case_timeout.map(|d| d.as_secs_f64()),
        }
    }
}

#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct Totals {
    pub cases: usize,
    pub unreadable: usize,
    pub reference_failed: usize,
    /// Cases the reference could not finish within `--case-timeout`.
    pub limit_exceeded: usize,
    pub not_run: usize,
    /// Per rasterizer, in the order of `rasterizers`.
    pub verdicts: Vec<RasterizerTotals>,
    pub golden: GoldenTotals,
}

impl Totals {
    /// No case yet, for `rasterizers`.
    pub fn of(rasterizers: &[RasterizerInfo]) -> Totals {
        Totals {
            verdicts: rasterizers
                .iter()
                .map(|r| RasterizerTotals {
                    rasterizer: r.name.clone(),
                    tally: Tally::default(),
                })
                .collect(),
            ..Totals::default()
        }
    }

    /// Counts one more case.
    pub fn add(&mut self, case: &CaseEntry) {
        self.cases += 1;
        match case.status {
            "unreadable" => self.unreadable += 1,
            "reference-failed" => self.reference_failed += 1,
            "limit-exceeded" => self.limit_exceeded += 1,
            "not-run" => self.not_run += 1,
            _ => {}
        }
        match case.golden {
            Some("match") => self.golden.matching += 1,
            Some("differ") => self.golden.differing += 1,
            Some("missing") => self.golden.missing += 1,
            _ => {}
        }
        for (result, totals) in case.results.iter().zip(self.verdicts.iter_mut()) {
            let tally = &mut totals.tally;
            match result.verdict {
                "pass" => tally.pass += 1,
                "fail" => tally.fail += 1,
                "foil" => tally.foil += 1,
                "unsupported" => tally.unsupported += 1,
                "flaky" => tally.flaky += 1,
                _ => tally.error += 1,
            }
            tally.own_rule += usize::from(
                result.judged_fill_rule.is_some()
                    || result.judged_clip.is_some()
                    || result.judged_subpixel_bits.is_some()
                    || result.judged_snapping.is_some()
                    || result.judged_sample_pattern.is_some()
                    || result.judged_y.is_some()
                    || result.judged_pixel_centre.is_some()
                    || result.judged_line_parameter.is_some()
                    || result.judged_line_border.is_some()
                    || result
                        .conservative
                        .as_ref()
                        .is_some_and(|c| c.case_states.is_some()),
            );
        }
    }
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RasterizerTotals {
    pub rasterizer: String,
    #[serde(flatten)]
    pub tally: Tally,
}

#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct GoldenTotals {
    pub matching: usize,
    pub differing: usize,
    pub missing: usize,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct CaseEntry {
    pub id: String,
    pub path: String,
    /// The first segment of the id.
    pub family: String,
    /// `ran`, `unreadable`, `reference-failed`, `limit-exceeded` or
    /// `not-run`.
    #[serde(deserialize_with = "name")]
    pub status: Word,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rules: Option<RulesInfo>,
    /// `match`, `differ` or `missing`.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[serde(default, deserialize_with = "maybe_name")]
    pub golden: Option<Word>,
    /// The case file's bytes hashed (`fnv1a64:` and 16 hex digits), so
    /// that reports merged by case id can tell two different files behind
    /// one id; absent when the file could not be read.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hash: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub golden_detail: Option<String>,
    pub reference_ms: f64,
    /// The case's HTML page, relative to the report folder, when it has
    /// one (failures, departures, results with some error).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub page: Option<String>,
    pub results: Vec<ResultEntry>,
}

/// A clip-space case's `clip_xy`, `clip_z` and `depth`.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ClipInfo {
    #[serde(deserialize_with = "name")]
    pub clip_xy: Word,
    #[serde(deserialize_with = "name")]
    pub clip_z: Word,
    #[serde(deserialize_with = "name")]
    pub depth: Word,
    #[serde(deserialize_with = "name")]
    pub interpolate_from: Word,
    /// What the side planes do to points (SPEC.md §17).
    #[serde(deserialize_with = "name")]
    pub clip_points: Word,
    /// What limits a kept point's square (SPEC.md §17.2).
    #[serde(deserialize_with = "name")]
    pub point_bounds: Word,
    /// The viewport a screen-space case was judged clipped at, `[x, y,
    /// width, height]` in the canvas's pixels (SPEC.md §16.9): the
    /// rasterizer's, where no viewport it allows holds the case.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub viewport: Option<[i64; 4]>,
    /// With `viewport`, for a case with depth or attributes:
    /// `"whole-triangle"`, the values of a clipped triangle's pieces judged
    /// as its whole planes (SPEC.md §16.9).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[serde(deserialize_with = "maybe_name")]
    pub piece_values: Option<Word>,
}

impl ClipInfo {
    fn of(clip: &ClipRules) -> ClipInfo {
        ClipInfo {
            clip_xy: clip.xy.name(),
            clip_z: clip.z.name(),
            depth: clip.depth.name(),
            interpolate_from: clip.values.name(),
            clip_points: clip.points.name(),
            point_bounds: clip.bounds.name(),
            viewport: None,
            piece_values: None,
        }
    }
}

/// A case's `rules.depth_format` and `rules.depth_bias`, the bias's
/// numbers as the exact fractions the case gives.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct DepthInfo {
    #[serde(deserialize_with = "name")]
    pub depth_format: Word,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub depth_bias: Option<DepthBiasInfo>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct DepthBiasInfo {
    pub constant: String,
    pub slope: String,
    pub clamp: String,
}

impl DepthInfo {
    fn of(scene: &Scene) -> Option<DepthInfo> {
        scene.depth_rules_need_attachment().then(|| DepthInfo {
            depth_format: scene.rules.depth_format.name(),
            depth_bias: scene.rules.depth_bias.as_ref().map(|b| DepthBiasInfo {
                constant: b.constant.to_exact_string(),
                slope: b.slope.to_exact_string(),
                clamp: b.clamp.to_exact_string(),
            }),
        })
    }
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RulesInfo {
    pub canvas: [u32; 2],
    pub subpixel_bits: Option<u32>,
    #[serde(deserialize_with = "name")]
    pub fill_rule: Word,
    #[serde(deserialize_with = "name")]
    pub cull: Word,
    #[serde(deserialize_with = "name")]
    pub provoking_vertex: Word,
    /// Clip-space cases only: their clip rules (SPEC.md §16).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub clip: Option<ClipInfo>,
    /// Cases with a depth format or polygon offset only (SPEC.md §18).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub depth: Option<DepthInfo>,
    pub primitives: usize,
    /// Antialiased cases only: `effects.antialias` as the case gives it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub antialias: Option<AntialiasRules>,
    /// Cases that declare `effects.motion_blur` only, as the case gives it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub motion_blur: Option<MotionBlurRules>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct MotionBlurRules {
    /// [open, close] in [0, 1].
    pub shutter: [f64; 2],
    pub samples: u32,
    #[serde(deserialize_with = "name")]
    pub pattern: Word,
    pub seed: u64,
    /// Primitives that move; 0: the scene is drawn as a static one.
    pub moving: usize,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct AntialiasRules {
    pub samples: u32,
    #[serde(deserialize_with = "name")]
    pub pattern: Word,
    pub seed: u64,
    pub adaptive: bool,
    pub position_bits: u32,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ResultEntry {
    pub rasterizer: String,
    /// `pass`, `fail`, `foil` (a foil's departure), `unsupported`,
    /// `error`, or `flaky` (its repetitions under `run --repeat` drew
    /// different frames; `flaky` says how).
    #[serde(deserialize_with = "name")]
    pub verdict: Word,
    pub reasons: Vec<String>,
    /// A flaky result's repetitions: each one's outcome, and where its
    /// frame differed from the first's (channel, first pixel and sample,
    /// values, counts).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub flaky: Option<Flaky>,
    pub time_ms: f64,
    /// How the rasterizer drew it, when it says (a GPU adapter: "native
    /// MSAA", "shifted passes", "time passes").
    #[serde(skip_serializing_if = "Option::is_none")]
    #[serde(default, deserialize_with = "maybe_name")]
    pub method: Option<Word>,
    /// The fill rule it was judged under, when that is its own and not the
    /// case's (`rules.fill_rule`): a rasterizer that cannot follow the
    /// case's rule, or a profile's; `none` for one that declares no tie
    /// rule (SPEC.md §3.1.1), judged off the ties.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[serde(default, deserialize_with = "maybe_name")]
    pub judged_fill_rule: Option<Word>,
    /// With no tie rule: its tie samples, and the overdraw and holes they
    /// got, counted apart (never a failure).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ties: Option<TieMetrics>,
    /// Diamond-exit lines judged under the latitude its API allows
    /// (SPEC.md §4.2.1): the fragments and lines that used it, counted.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub line_latitude: Option<crate::metrics::LatitudeMetrics>,
    /// A conservative case (SPEC.md §19): required, allowed band and
    /// forbidden pixels against the candidate's, "drawn in the allowed
    /// band" counted apart, and the fully-covered flag.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub conservative: Option<crate::metrics::ConservativeMetrics>,
    /// The clip conventions it was judged under, when they are its own and
    /// not the case's (`rules.clip`, SPEC.md §16).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub judged_clip: Option<ClipInfo>,
    /// The subpixel bits it was judged at, when they are its own and not
    /// the case's (`rules.subpixel_bits`, SPEC.md §3.2).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub judged_subpixel_bits: Option<u32>,
    /// Its own snapping when it is not a number of bits: `"none"` or
    /// `"truncate"` (SPEC.md §3.2).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[serde(default, deserialize_with = "maybe_name")]
    pub judged_snapping: Option<Word>,
    /// The sample pattern it was judged at, when that is its own and not
    /// the case's (`rules.antialias.pattern`, SPEC.md §14.2.1).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[serde(default, deserialize_with = "maybe_name")]
    pub judged_sample_pattern: Option<Word>,
    /// `"up"` when it was judged with its y axis up (SPEC.md §2.1).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[serde(default, deserialize_with = "maybe_name")]
    pub judged_y: Option<Word>,
    /// `"integer"` when it was judged with its samples at whole
    /// coordinates (SPEC.md §2.1).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[serde(default, deserialize_with = "maybe_name")]
    pub judged_pixel_centre: Option<Word>,
    /// The line parameter it was judged under, when that is its own and
    /// not the case's lines' (SPEC.md §5.1): `major`, `projected`,
    /// `major-unclamped`, `projected-unclamped`, or `per-rule` where its
    /// line rules declare different ones.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[serde(default, deserialize_with = "maybe_name")]
    pub judged_line_parameter: Option<Word>,
    /// `"none"` when it declares no tie rule on rectangle lines' borders
    /// and the case has rectangle lines (SPEC.md §4.3.1): those border
    /// samples are judged off the ties, counted in `ties`.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[serde(default, deserialize_with = "maybe_name")]
    pub judged_line_border: Option<Word>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub metrics: Option<MetricsEntry>,
    /// Files written for this result, relative to the report folder.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub files: Vec<String>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct MetricsEntry {
    pub coverage: CoverageEntry,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub watertight: Option<WatertightEntry>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lines: Option<LinesEntry>,
    pub channels: Vec<ChannelEntry>,
    /// Antialiased cases only: resolved coverage against the exact area,
    /// per pixel (SPEC.md §14.3), as the metric records it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub antialias: Option<AntialiasMetrics>,
    /// Scenes in which something moves only: time coverage against the
    /// exact time coverage, per pixel (SPEC.md §15.4), as the metric
    /// records it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub time: Option<TimeMetrics>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct CoverageEntry {
    pub samples: u64,
    pub reference_covered: u64,
    pub candidate_covered: u64,
    pub missing: u64,
    pub extra: u64,
    pub wrong_owner: u64,
    pub mismatched: u64,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct WatertightEntry {
    pub interior: u64,
    pub holes: u64,
    pub overdraw: u64,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct LinesEntry {
    pub lines: u64,
    pub crowded_steps: u64,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ChannelEntry {
    pub channel: String,
    pub samples: u64,
    pub max_abs: f64,
    pub max_ulp: f64,
    pub rms: f64,
    pub allowed_abs: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub allowed_ulp: Option<f64>,
    /// Depth under a depth format (SPEC.md §18): the samples off its grid
    /// and outside the allowed set (the distances above are from that set).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub depth_set: Option<DepthSetEntry>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct DepthSetEntry {
    #[serde(deserialize_with = "name")]
    pub format: Word,
    pub off_grid: u64,
    pub outside: u64,
}

impl MetricsEntry {
    pub fn from_metrics(m: &Metrics) -> MetricsEntry {
        let c = &m.coverage;
        MetricsEntry {
            coverage: CoverageEntry {
                samples: c.samples,
                reference_covered: c.reference_covered,
                candidate_covered: c.candidate_covered,
                missing: c.missing,
                extra: c.extra,
                wrong_owner: c.wrong_owner,
                mismatched: c.mismatched(),
            },
            watertight: m.watertight.as_ref().map(|w| WatertightEntry {
                interior: w.interior,
                holes: w.holes,
                overdraw: w.overdraw,
            }),
            lines: m.lines.as_ref().map(|l| LinesEntry {
                lines: l.lines,
                crowded_steps: l.crowded_steps,
            }),
            channels: m
                .channels
                .iter()
                .map(|ch| ChannelEntry {
                    channel: ch.channel.clone(),
                    samples: ch.samples,
                    max_abs: ch.max_abs,
                    max_ulp: ch.max_ulp,
                    rms: ch.rms,
                    allowed_abs: ch.allowed_abs,
                    allowed_ulp: ch.allowed_ulp,
                    depth_set: ch.depth_set.as_ref().map(|d| DepthSetEntry {
                        format: d.format,
                        off_grid: d.off_grid,
                        outside: d.outside,
                    }),
                })
                .collect(),
            antialias: m.antialias.clone(),
            time: m.time.clone(),
        }
    }
}

fn rules_info(scene: &Scene) -> RulesInfo {
    RulesInfo {
        canvas: [scene.canvas.width, scene.canvas.height],
        subpixel_bits: scene.rules.subpixel_bits,
        fill_rule: scene.rules.fill_rule.name(),
        cull: scene.rules.cull.name(),
        provoking_vertex: scene.rules.provoking_vertex.name(),
        clip: scene
            .in_clip_space()
            .then(|| ClipInfo::of(&scene.rules.clip)),
        depth: DepthInfo::of(scene),
        primitives: scene.primitives.len(),
        antialias: scene.effects.antialias.as_ref().map(|a| AntialiasRules {
            samples: a.samples,
            pattern: a.pattern.name(),
            seed: a.seed,
            adaptive: a.adaptive,
            position_bits: a.position_bits,
        }),
        motion_blur: scene.effects.motion_blur.as_ref().map(|m| {
            let one = f64::from(crate::scene::time::limits::TIME_ONE);
            MotionBlurRules {
                shutter: m.shutter.map(|u| f64::from(u) / one),
                samples: m.samples,
                pattern: m.pattern.name(),
                seed: m.seed,
                moving: scene.primitives.iter().filter(|p| p.moves()).count(),
            }
        }),
    }
}

fn millis(d: std::time::Duration) -> f64 {
    d.as_secs_f64() * 1000.0
}

impl CaseEntry {
    /// A case that has not run (yet).
    pub fn not_run(file: &crate::harness::discover::CaseFile) -> CaseEntry {
        CaseEntry {
            id: file.id.clone(),
            path: file.path.display().to_string(),
            family: family(&file.id),
            status: "not-run",
            error: None,
            name: None,
            description: None,
            rules: None,
            golden: None,
            hash: None,
            golden_detail: None,
            reference_ms: 0.0,
            page: None,
            results: Vec::new(),
        }
    }

    /// The entry for a finished case; `foil[k]` tells whether candidate k
    /// is a foil.
    pub fn from_outcome(outcome: &CaseOutcome, foil: &[bool]) -> CaseEntry {
        let mut entry = CaseEntry::not_run(&outcome.file);
        entry.status = match &outcome.problem {
            None => "ran",
            Some(Problem::Unreadable(_)) => "unreadable",
            Some(Problem::ReferenceFailed(_)) => "reference-failed",
            Some(Problem::LimitExceeded(_)) => "limit-exceeded",
            Some(Problem::Interrupted) => return entry,
        };
        entry.error = outcome.problem.as_ref().map(Problem::message);
        entry.hash = outcome.hash.clone();
        if let Some(scene) = &outcome.scene {
            entry.name = Some(scene.name.clone());
            entry.description = Some(scene.description.clone());
            entry.rules = Some(rules_info(scene));
        }
        (entry.golden, entry.golden_detail) = match &outcome.golden {
            None => (None, None),
            Some(GoldenStatus::Matches) => (Some("match"), None),
            Some(GoldenStatus::Missing(path)) => {
                (Some("missing"), Some(path.display().to_string()))
            }
            Some(GoldenStatus::Differs(why)) => (Some("differ"), Some(why.clone())),
        };
        entry.reference_ms = millis(outcome.reference_time());
        entry.results = outcome
            .candidates
            .iter()
            .zip(foil)
            .map(|(run, &is_foil)| ResultEntry {
                rasterizer: run.rasterizer.clone(),
                verdict: run.verdict.recorded_name(is_foil),
                reasons: match &run.verdict {
                    Verdict::Pass => Vec::new(),
                    Verdict::Fail(reasons) => reasons.clone(),
                    Verdict::Unsupported(why) | Verdict::Error(why) => vec![why.clone()],
                    Verdict::Flaky(flaky) => vec![format!("flaky: {}", flaky.summary())],
                },
                flaky: match &run.verdict {
                    Verdict::Flaky(flaky) => Some((**flaky).clone()),
                    _ => None,
                },
                time_ms: millis(run.elapsed),
                method: run.method,
                judged_fill_rule: match run.judged.no_tie_rule {
                    true => Some(DeclaredRule::NONE),
                    false => run.judged.fill_rule.map(|r| r.name()),
                },
                ties: run.metrics.as_ref().and_then(|m| m.ties.clone()),
                line_latitude: run.metrics.as_ref().and_then(|m| m.latitude.clone()),
                conservative: run.metrics.as_ref().and_then(|m| m.conservative.clone()),
                judged_clip: run.judged.clip.map(|c| ClipInfo {
                    viewport: run
                        .judged
                        .viewport
                        .map(|v| [v.origin[0], v.origin[1], v.size[0].into(), v.size[1].into()]),
                    piece_values: run.judged.viewport_values.then_some("whole-triangle"),
                    ..ClipInfo::of(&c)
                }),
                judged_subpixel_bits: run.judged.subpixel_bits,
                judged_snapping: run.judged.snapping.map(|s| match s {
                    Snapping::Truncate => "truncate",
                    _ => "none",
                }),
                judged_sample_pattern: run.judged.sample_pattern.map(|p| p.name()),
                judged_y: run.judged.y_up.then_some("up"),
                judged_pixel_centre: run.judged.integer_centre.then_some("integer"),
                judged_line_parameter: run.judged.line_parameter.map(|p| p.name()),
                judged_line_border: run.judged.rectangle_border_ties.then_some("none"),
                metrics: run.metrics.as_ref().map(MetricsEntry::from_metrics),
                files: Vec::new(),
            })
            .collect();
        entry
    }
}

#[cfg(test)]
impl ResultEntry {
    /// A result for tests: `rasterizer`'s `verdict`, with no reasons,
    /// time, conventions, metrics or files; a test sets what it needs
    /// with `..ResultEntry::bare(…)`.
    pub fn bare(rasterizer: &str, verdict: Word) -> ResultEntry {
        ResultEntry {
            rasterizer: rasterizer.to_owned(),
            verdict,
            reasons: Vec::new(),
            flaky: None,
            time_ms: 0.0,
            method: None,
            judged_fill_rule: None,
            ties: None,
            line_latitude: None,
            conservative: None,
            judged_clip: None,
            judged_subpixel_bits: None,
            judged_snapping: None,
            judged_sample_pattern: None,
            judged_y: None,
            judged_pixel_centre: None,
            judged_line_parameter: None,
            judged_line_border: None,
            metrics: None,
            files: Vec::new(),
        }
    }
}

#[cfg(test)]
impl Report {
    /// An empty report of `run` by production under the default limits,
    /// for tests to fill.
    pub fn of_production_run() -> Report {
        Report::new(
            vec!["run".into()],
            vec![RasterizerInfo {
                name: "production".into(),
                foil: false,
                declared: None,
                api_record: None,
            }],
            LimitsInfo::of(&crate::scene::Limits::default()),
        )
    }
}

/// The family of a case id: its first path segment.
pub fn family(id: &str) -> String {
    match id.split_once('/') {
        Some((family, _)) => family.to_owned(),
        None => "(top)".to_owned(),
    }
}

impl Report {
    pub fn new(
        command: Vec<String>,
        rasterizers: Vec<RasterizerInfo>,
        limits: LimitsInfo,
    ) -> Report {
        Report {
            schema: SCHEMA,
            tool: Tool {
                name: "rastercheck",
                version: env!("CARGO_PKG_VERSION"),
            },
            complete: false,
            command,
            machine: Machine::here(),
            shard: None,
            sources: Vec::new(),
            rasterizers,
            limits,
            seeds: Vec::new(),
            totals: Totals::default(),
            cases: Vec::new(),
        }
    }

    /// Recounts the totals from the case entries.
    pub fn tally(&mut self) {
        let mut totals = Totals::of(&self.rasterizers);
        for case in &self.cases {
            totals.add(case);
        }
        self.totals = totals;
    }

    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("the report serializes")
    }
}
