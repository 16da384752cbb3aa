//! Declared conventions (`run --profile`, `fuzz --profile`): reading
//! profile files, choosing the rasterizers to run, and wrapping each
//! profiled rasterizer so that it follows its declared fill rule: the
//! harness then judges it against a reference drawn under that rule
//! instead of each case's, as it judges any rasterizer whose rule is fixed
//! (`judge::run_candidate`, SPEC.md §3.1).
//!
//! `explore::probe` writes profiles; the harness only reads what they
//! declare, so a hand-written profile is judged the same way.

use std::path::Path;

use serde_json::Value;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{ClipRules, DeclaredRule, DepthMode, FillRule, Primitive, Scene};

/// The schema of a profile file, written by `probe` and read here.
pub const SCHEMA: &str = "rastercheck-profile/1";

/// What `run --profile` takes from a profile file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Declared {
    pub rasterizer: String,
    /// A fill rule, or `none` (no tie rule, SPEC.md §3.1.1).
    pub fill_rule: DeclaredRule,
    pub file: String,
}

/// Reads a profile file for `run --profile`.
pub fn load_declared(path: &Path) -> Result<Declared, String> {
    let shown = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| format!("{shown}: {e}"))?;
    let value: Value =
        serde_json::from_str(&text).map_err(|e| format!("{shown}: not JSON: {e}"))?;
    let schema = value.get("schema").and_then(Value::as_str);
    if schema != Some(SCHEMA) {
        return Err(format!(
            "{shown}: $.schema: expected {SCHEMA:?}, found {}",
            value
                .get("schema")
                .map_or("nothing".to_owned(), |v| v.to_string())
        ));
    }
    let rasterizer = value
        .get("rasterizer")
        .and_then(Value::as_str)
        .ok_or_else(|| format!("{shown}: $.rasterizer: expected a rasterizer name"))?
        .to_owned();
    let rule = value
        .get("fill_rule")
        .and_then(Value::as_str)
        .ok_or_else(|| {
            // A probe of a rasterizer that is not point-sampled writes no
            // rule (`sampler`, optional: absent in older profiles).
            let sampler = match value.get("sampler").and_then(Value::as_str) {
                Some(s) if s != "point" => {
                    format!(" (its sampler is {s}: not point-sampled, so it has no tie rule)")
                }
                _ => String::new(),
            };
            format!("{shown}: $.fill_rule: the profile declares no fill rule{sampler}")
        })?;
    // A probe that found ties going by slope names the nearest rule and
    // the verdict `inconsistent`: it has no tie rule (SPEC.md §3.1.1).
    let by_slope = value.get("tie_verdict").and_then(Value::as_str) == Some("inconsistent");
    let rule = if by_slope { DeclaredRule::NONE } else { rule };
    let fill_rule = DeclaredRule::from_name(rule).ok_or_else(|| {
        format!(
            "{shown}: $.fill_rule: {rule:?} is not a fill rule a case can state, nor none ({})",
            DeclaredRule::NAMES.join(", ")
        )
    })?;
    Ok(Declared {
        rasterizer,
        fill_rule,
        file: shown,
    })
}

impl Declared {
    /// The line `run` prints about the override.
    pub fn note(&self) -> String {
        if self.fill_rule == DeclaredRule::NoTieRule {
            return format!(
                "profile: {} declares no tie rule (from {}): judged exactly off the ties, its tie samples counted apart",
                self.rasterizer, self.file
            );
        }
        format!(
            "profile: {} is judged under its declared fill rule {} (from {}) instead of each case's",
            self.rasterizer, self.fill_rule, self.file
        )
    }
}

/// The profiles of `run --profile`, and the rasterizers to run: `names`,
/// or the profiles' rasterizers when none are named (production when
/// there are no profiles either). Every profiled rasterizer must be run,
/// and have one profile; `called` is the name a `-r` argument is reported
/// under (NAME for a program named with `-r NAME=external…`).
pub fn for_run(
    files: &[std::path::PathBuf],
    names: &[String],
    called: fn(&str) -> &str,
) -> Result<(Vec<Declared>, Vec<String>), String> {
    let mut declared: Vec<Declared> = Vec::new();
    for file in files {
        let d = load_declared(file)?;
        if let Some(other) = declared.iter().find(|o| o.rasterizer == d.rasterizer) {
            return Err(format!(
                "{} and {} are both profiles of {}; give one per rasterizer",
                other.file, d.file, d.rasterizer
            ));
        }
        declared.push(d);
    }
    let names = if !names.is_empty() {
        names.to_vec()
    } else if declared.is_empty() {
        vec!["production".to_owned()]
    } else {
        declared.iter().map(|d| d.rasterizer.clone()).collect()
    };
    if let Some(d) = declared
        .iter()
        .find(|d| !names.iter().any(|n| called(n) == d.rasterizer))
    {
        return Err(format!(
            "{} is a profile of {}, which this run does not check (add -r '{}')",
            d.file, d.rasterizer, d.rasterizer
        ));
    }
    Ok((declared, names))
}

/// A rasterizer that follows the fill rule its profile declares, whatever
/// a case states: judged under it ([`Rasterizer::fixed_fill_rule`], SPEC.md
/// §3.1). `fuzz --profile` searches with it.
pub struct Profiled {
    pub inner: Box<dyn Rasterizer>,
    pub rule: DeclaredRule,
}

impl Rasterizer for Profiled {
    fn name(&self) -> &str {
        self.inner.name()
    }
    fn capabilities(&self) -> Capabilities {
        self.inner.capabilities()
    }
    fn is_foil(&self) -> bool {
        self.inner.is_foil()
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        self.inner.rasterize(scene, plan)
    }
    fn declared(&self) -> Option<String> {
        self.inner.declared()
    }
    fn fixed_fill_rule(&self) -> Option<FillRule> {
        self.rule.fill_rule()
    }
    fn no_tie_rule(&self) -> bool {
        self.rule == DeclaredRule::NoTieRule
    }
}

/// Why a case cannot be judged under `rule`: `all-edges` is not defined for
/// polygons (SPEC.md §14.1), so a polygon case is unsupported under it
/// rather than judged under another rule.
pub fn cannot_judge_under(scene: &Scene, rule: FillRule) -> Option<String> {
    (rule == FillRule::AllEdges && scene.has_polygons()).then(|| {
        format!(
            "it is judged under its own {rule} rule instead of the case's {}, and all-edges is not defined for polygons (SPEC.md §14.1)",
            scene.rules.fill_rule
        )
    })
}

/// The conventions a rasterizer is judged under instead of a case's, when
/// it follows its own (SPEC.md §3.1, §16): its fixed fill rule where the
/// case states another, and for a clip-space case under depth clip its
/// fixed `clip_xy` and `clip_z` where the case states others (under
/// depth clamp `clip_z` means nothing; `clip_xy` still does), its fixed
/// `interpolate_from`, and for a clip-space case with points its fixed
/// `clip_points` and `point_bounds`. `clip_xy`, `clip_z` and `interpolate_from` shape
/// triangles only (a point is kept or popped by its centre, and its
/// values are its one vertex's, SPEC.md §17.2): a case of points alone is
/// judged under the driver's own `clip_points` and `point_bounds` and
/// nothing else.
///
/// Its fixed subpixel bits ([`Rasterizer::fixed_subpixel_bits`]) where the
/// case states more bits or none (SPEC.md §3.2): a case at fewer bits is
/// drawn as stated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OwnConventions {
    pub fill_rule: Option<FillRule>,
    /// It declares no tie rule (SPEC.md §3.1.1): judged under the case's
    /// rule off the ties, which the judge then asks the reference for.
    pub no_tie_rule: bool,
    pub clip: Option<ClipRules>,
    pub subpixel_bits: Option<u32>,
}

impl OwnConventions {
    /// What `candidate` is judged under on `scene`; the default (nothing)
    /// when it follows the case.
    pub fn of(candidate: &dyn Rasterizer, scene: &Scene) -> OwnConventions {
        let fill_rule = candidate
            .fixed_fill_rule()
            .filter(|&rule| rule != scene.rules.fill_rule);
        let stated = scene.rules.clip;
        let mut clip = stated;
        let triangles = scene
            .primitives
            .iter()
            .any(|p| matches!(p, Primitive::Triangle(_)));
        if scene.in_clip_space() && triangles {
            if let Some((xy, z)) = candidate.fixed_clip_rules() {
                clip.xy = xy;
                if stated.depth == DepthMode::Clip {
                    clip.z = z;
                }
            }
            if let Some(values) = candidate.fixed_interpolate_from() {
                clip.values = values;
            }
        }
        if scene.in_clip_space() {
            if let Some(points) = candidate.fixed_point_clip().filter(|_| scene.has_points()) {
                clip.points = points;
            }
            if let Some(bounds) = candidate
                .fixed_point_bounds()
                .filter(|_| scene.has_points())
            {
                clip.bounds = bounds;
            }
        }
        let clip = (clip != stated).then_some(clip);
        let subpixel_bits = candidate
            .fixed_subpixel_bits()
            .filter(|&own| scene.rules.subpixel_bits.is_none_or(|bits| bits > own));
        OwnConventions {
            fill_rule,
            no_tie_rule: candidate.no_tie_rule(),
            clip,
            subpixel_bits,
        }
    }

    /// Whether the case is restated (the tie set of a rasterizer with no
    /// tie rule restates nothing).
    pub fn any(&self) -> bool {
        self.fill_rule.is_some() || self.clip.is_some() || self.subpixel_bits.is_some()
    }

    /// The case restated under these conventions. The pins
    /// `samples_covered` and `time_coverage` (whose riding samples fall by
    /// the tie rule) describe the case's own, so they are dropped; so is
    /// `area` (the exact area of the snapped primitives) when the bits
    /// change.
    pub fn restate(&self, scene: &Scene) -> Scene {
        let mut s = scene.clone();
        if let Some(rule) = self.fill_rule {
            s.rules.fill_rule = rule;
        }
        if let Some(clip) = self.clip {
            s.rules.clip = clip;
        }
        if let Some(bits) = self.subpixel_bits {
            s.rules.subpixel_bits = Some(bits);
            s.expect.area = None;
        }
        s.expect.samples_covered = None;
        s.expect.time_coverage.clear();
        s
    }

    /// In words, for a failure of the reference under them.
    pub fn describe(&self) -> String {
        let mut words = Vec::new();
        if let Some(rule) = self.fill_rule {
            words.push(format!("the {rule} rule"));
        }
        if self.no_tie_rule {
            words.push("no tie rule".to_owned());
        }
        if let Some(clip) = self.clip {
            words.push(clip.words());
        }
        if let Some(bits) = self.subpixel_bits {
            words.push(format!("{bits} subpixel bits"));
        }
        words.join(" and ")
    }
}

/// The candidates of `run --profile`, each one a profile names wrapped in
/// [`Profiled`]: judged under the profile's fill rule by the same path as a
/// rasterizer whose rule is fixed (`judge::run_candidate`, SPEC.md §3.1).
pub fn apply(
    candidates: Vec<Box<dyn Rasterizer>>,
    declared: &[Declared],
) -> Vec<Box<dyn Rasterizer>> {
    candidates
        .into_iter()
        .map(
            |candidate| match declared.iter().find(|d| d.rasterizer == candidate.name()) {
                Some(d) => Box::new(Profiled {
                    inner: candidate,
                    rule: d.fill_rule,
                }) as Box<dyn Rasterizer>,
                None => candidate,
            },
        )
        .collect()
}
