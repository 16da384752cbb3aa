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

use super::clipped::{self, Clipped};
use super::line_parameters::LineParameters;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{
    Capabilities, Declaration, PixelCentre, RasterError, Rasterizer, ScreenViewport, Snapping,
    YDirection,
};
use crate::scene::{
    ClipRules, ClipXy, Cull, DeclaredRule, DepthMode, FillRule, LineRule, LineT, Number, Pattern,
    Primitive, Scene,
};

/// The schema of a profile file, written by `probe` and read here.
pub const SCHEMA: &str = "rastercheck-profile/1";

/// What `run --profile` takes from a profile file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Declared {
    pub rasterizer: String,
    /// A fill rule, or `none` (no tie rule, SPEC.md §3.1.1); `None` for an
    /// area method's profile that declares its coverage encoding only.
    pub fill_rule: Option<DeclaredRule>,
    /// Its optional `conventions`: snapping, sample positions, y direction,
    /// pixel centre (SPEC.md §13), declared by hand; `probe` writes none.
    pub conventions: Declaration,
    /// Its optional `coverage_encoding` and `coverage_bits` (SPEC.md §12.9),
    /// as `probe` finds them on an area method.
    pub coverage: Option<CoverageEncoding>,
    pub file: String,
}

/// How an area method's coverage fractions are encoded (SPEC.md §12.9):
/// multiples of 1/(2^bits − 1) (`unorm`), or of 1/2^bits capped at
/// 1 − 1/2^bits (`fraction`: area × 2^bits in a word that saturates).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CoverageEncoding {
    /// `"fraction"` (else `"unorm"`).
    pub fraction: bool,
    pub bits: u32,
}

impl CoverageEncoding {
    /// The most bits a profile may declare, as a hello may.
    pub const MAX_BITS: u32 = 24;

    /// One step of the encoding: 1/2^bits, or 1/(2^bits − 1).
    pub fn step(&self) -> f64 {
        let whole = 2f64.powi(self.bits as i32);
        1.0 / if self.fraction { whole } else { whole - 1.0 }
    }

    /// The encoding's word, as a hello and a profile write it.
    pub fn word(&self) -> &'static str {
        if self.fraction {
            "fraction"
        } else {
            "unorm"
        }
    }

    /// "8-bit fraction (steps of 1/256, saturating at 255/256)".
    pub fn words(&self) -> String {
        let n = 1u64 << self.bits.min(62);
        if self.fraction {
            format!(
                "{}-bit fraction (steps of 1/{n}, saturating at {}/{n})",
                self.bits,
                n - 1
            )
        } else {
            format!("{}-bit unorm (steps of 1/{})", self.bits, n - 1)
        }
    }

    /// Reads `coverage_encoding` and `coverage_bits` from a profile's
    /// top level: both or neither (`coverage_encoding` alone is an error;
    /// `coverage_bits` alone is `unorm`).
    fn read(value: &Value, shown: &str) -> Result<Option<CoverageEncoding>, String> {
        let encoding = match value.get("coverage_encoding") {
            None | Some(Value::Null) => None,
            Some(Value::String(w)) if w == "unorm" || w == "fraction" => Some(w == "fraction"),
            Some(other) => {
                return Err(format!(
                    "{shown}: $.coverage_encoding is {other}; known: unorm, fraction"
                ))
            }
        };
        let bits = match value.get("coverage_bits") {
            None | Some(Value::Null) => None,
            Some(v) => match v.as_u64() {
                Some(b) if (1..=u64::from(Self::MAX_BITS)).contains(&b) => Some(b as u32),
                _ => {
                    return Err(format!(
                        "{shown}: $.coverage_bits is {v}; expected a whole number from 1 to {}",
                        Self::MAX_BITS
                    ))
                }
            },
        };
        match (encoding, bits) {
            (Some(_), None) => Err(format!(
                "{shown}: $.coverage_encoding needs $.coverage_bits (the k of the encoding)"
            )),
            (fraction, Some(bits)) => Ok(Some(CoverageEncoding {
                fraction: fraction.unwrap_or(false),
                bits,
            })),
            (None, None) => Ok(None),
        }
    }
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
    let coverage = CoverageEncoding::read(&value, &shown)?;
    // A probe of a rasterizer that is not point-sampled writes no rule
    // (`sampler`, optional: absent in older profiles); an area method's
    // profile may then declare its coverage encoding alone.
    let fill_rule = match value.get("fill_rule").and_then(Value::as_str) {
        None if coverage.is_some() => None,
        None => {
            let sampler = match value.get("sampler").and_then(Value::as_str) {
                Some(s) if s != "point" => {
                    format!(" (its sampler is {s}: not point-sampled, so it has no tie rule)")
                }
                _ => String::new(),
            };
            return Err(format!(
                "{shown}: $.fill_rule: the profile declares no fill rule{sampler}"
            ));
        }
        Some(rule) => {
            // A probe that found ties going by slope names the nearest
            // rule and the verdict `inconsistent`: it has no tie rule
            // (SPEC.md §3.1.1).
            let by_slope = value.get("tie_verdict").and_then(Value::as_str) == Some("inconsistent");
            let rule = if by_slope { DeclaredRule::NONE } else { rule };
            Some(DeclaredRule::from_name(rule).ok_or_else(|| {
                format!(
                    "{shown}: $.fill_rule: {rule:?} is not a fill rule a case can state, nor none ({})",
                    DeclaredRule::NAMES.join(", ")
                )
            })?)
        }
    };
    let conventions = match value.get("conventions") {
        None | Some(Value::Null) => Declaration::default(),
        Some(Value::Object(object)) => {
            if let Some(key) = object
                .keys()
                .find(|k| !Declaration::KEYS.contains(&k.as_str()))
            {
                let hint = match crate::scene::case::closest(key, &Declaration::KEYS) {
                    Some(meant) => format!("did you mean {meant:?}? "),
                    None => String::new(),
                };
                return Err(format!(
                    "{shown}: $.conventions.{key}: not a convention a profile declares; {hint}known: {}",
                    Declaration::KEYS.join(", ")
                ));
            }
            Declaration::read(object, "$.conventions").map_err(|e| format!("{shown}: {e}"))?
        }
        Some(_) => return Err(format!("{shown}: $.conventions must be an object")),
    };
    Ok(Declared {
        rasterizer,
        fill_rule,
        conventions,
        coverage,
        file: shown,
    })
}

impl Declared {
    /// The line `run` prints about the override.
    pub fn note(&self) -> String {
        if self.fill_rule == Some(DeclaredRule::NoTieRule) {
            return format!(
                "profile: {} declares no tie rule (from {}): judged exactly off the ties, its tie samples counted apart",
                self.rasterizer, self.file
            );
        }
        let c = &self.conventions;
        let mut more = Vec::new();
        if let Some(snapping) = c.snapping {
            more.push(snapping.words());
        }
        if let Some(pattern) = c.sample_pattern {
            more.push(format!("its {} sample positions", pattern.name()));
        }
        if c.y == Some(YDirection::Up) {
            more.push("y up".to_owned());
        }
        if c.pixel_centre == Some(PixelCentre::Integer) {
            more.push("samples at whole coordinates".to_owned());
        }
        if c.diamond_exit_latitude == Some(true) {
            more.push("the APIs' latitude for diamond-exit lines".to_owned());
        }
        if let Some(coverage) = self.coverage {
            more.push(format!("coverage as {}", coverage.words()));
        }
        let more = if more.is_empty() {
            String::new()
        } else {
            format!(" and {}", more.join(", "))
        };
        let Some(rule) = self.fill_rule else {
            return format!(
                "profile: {} is judged under its declared {} (from {})",
                self.rasterizer,
                more.trim_start_matches(" and "),
                self.file
            );
        };
        format!(
            "profile: {} is judged under its declared fill rule {rule}{more} (from {}) instead of each case's",
            self.rasterizer, self.file
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
    /// `None`: its own rule (or each case's), as without a profile.
    pub rule: Option<DeclaredRule>,
    /// The profile's other conventions; each one it leaves out is the
    /// rasterizer's own declaration, if any.
    pub conventions: Declaration,
    /// The coverage encoding its area answers are judged under, in place
    /// of the one they carry (SPEC.md §12.9); `None` keeps theirs.
    pub coverage: Option<CoverageEncoding>,
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
        let mut frame = self.inner.rasterize(scene, plan)?;
        if let (Some(c), Some(parts)) = (self.coverage, frame.parts.as_mut()) {
            parts.step = c.step();
            parts.saturates = c.fraction;
        }
        Ok(frame)
    }
    fn declared(&self) -> Option<String> {
        self.inner.declared()
    }
    fn api_record(&self) -> Option<crate::rasterizer::ApiRecord> {
        self.inner.api_record()
    }
    fn conservative(&self) -> Option<crate::scene::ConservativeSupport> {
        self.inner.conservative()
    }
    fn conservative_for(&self, scene: &Scene) -> Option<crate::scene::ConservativeSupport> {
        self.inner.conservative_for(scene)
    }
    fn diamond_exit_latitude(&self) -> bool {
        self.conventions
            .diamond_exit_latitude
            .unwrap_or_else(|| self.inner.diamond_exit_latitude())
    }
    fn fixed_line_parameter(&self, rule: LineRule) -> Option<LineT> {
        self.inner.fixed_line_parameter(rule)
    }
    fn rectangle_border_no_tie_rule(&self) -> bool {
        self.inner.rectangle_border_no_tie_rule()
    }
    fn fixed_clip_rules(&self) -> Option<(crate::scene::ClipXy, crate::scene::ClipZ)> {
        self.inner.fixed_clip_rules()
    }
    fn screen_viewport(&self, scene: &Scene, plan: &Plan) -> Option<ScreenViewport> {
        self.inner.screen_viewport(scene, plan)
    }
    fn fixed_fill_rule(&self) -> Option<FillRule> {
        match self.rule {
            Some(rule) => rule.fill_rule(),
            None => self.inner.fixed_fill_rule(),
        }
    }
    fn no_tie_rule(&self) -> bool {
        match self.rule {
            Some(rule) => rule == DeclaredRule::NoTieRule,
            None => self.inner.no_tie_rule(),
        }
    }
    fn fixed_subpixel_bits(&self) -> Option<u32> {
        match self.conventions.snapping {
            Some(Snapping::Bits(bits)) => Some(bits),
            Some(_) => None,
            None => self.inner.fixed_subpixel_bits(),
        }
    }
    fn fixed_snapping(&self) -> Option<Snapping> {
        self.conventions
            .snapping
            .or_else(|| self.inner.fixed_snapping())
    }
    fn fixed_sample_pattern(&self) -> Option<Pattern> {
        self.conventions
            .sample_pattern
            .or_else(|| self.inner.fixed_sample_pattern())
    }
    fn fixed_y_direction(&self) -> Option<YDirection> {
        self.conventions
            .y
            .or_else(|| self.inner.fixed_y_direction())
    }
    fn fixed_pixel_centre(&self) -> Option<PixelCentre> {
        self.conventions
            .pixel_centre
            .or_else(|| self.inner.fixed_pixel_centre())
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

/// Whether the fill rule decides which samples on `primitive`'s border it
/// covers: triangles, polygons, points (SPEC.md §3, §14.1, §17.1) and
/// rectangle and parallelogram lines (§4.3, §4.4); midpoint and
/// diamond-exit lines choose pixels by their own rules (§4.1, §4.2).
fn uses_fill_rule(primitive: &Primitive) -> bool {
    match primitive {
        Primitive::Line(line) => !matches!(line.rule, LineRule::Midpoint | LineRule::DiamondExit),
        Primitive::Triangle(_) | Primitive::Polygon(_) | Primitive::Point(_) => true,
    }
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
/// Its fixed snapping ([`Rasterizer::fixed_snapping`], SPEC.md §3.2): its
/// subpixel bits where the case states more bits or none (a case at fewer
/// bits is drawn as stated), no snapping where the case snaps, truncation
/// to whole pixels always. Its fixed sample positions where an antialiased
/// case states others (§14.2.1); its y direction and pixel centre where
/// they are not SPEC's (§2.1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OwnConventions {
    /// The fill rule judged, in SPEC's y-down terms (a y-up rasterizer's
    /// own words mirrored).
    pub fill_rule: Option<FillRule>,
    /// It declares no tie rule (SPEC.md §3.1.1): judged under the case's
    /// rule off the ties, which the judge then asks the reference for.
    pub no_tie_rule: bool,
    pub clip: Option<ClipRules>,
    /// Its own subpixel bits ([`Snapping::Bits`]).
    pub subpixel_bits: Option<u32>,
    /// Its own snapping when it is not a number of bits:
    /// [`Snapping::None`] or [`Snapping::Truncate`].
    pub snapping: Option<Snapping>,
    /// Its own sample positions, for an antialiased case stating others.
    pub sample_pattern: Option<Pattern>,
    /// Its y axis points up: the case's cull and fill rule are read
    /// mirrored.
    pub y_up: bool,
    /// Its samples lie at whole coordinates: the case is judged moved by
    /// (½, ½).
    pub integer_centre: bool,
    /// It draws diamond-exit lines with its API's latitude and the case
    /// has some (screen space, not antialiased): they are judged under
    /// the latitude against the exact fragments (SPEC.md §4.2.1), which
    /// restates nothing.
    pub line_latitude: bool,
    /// Its own line parameter (SPEC.md §5.1), for each line rule of the
    /// case whose lines it restates: values are taken at it.
    pub line_parameter: Option<LineParameters>,
    /// It declares no tie rule on a rectangle line's border and the case
    /// has rectangle lines (SPEC.md §4.3.1): their border samples are
    /// judged off the ties, which restates nothing.
    pub rectangle_border_ties: bool,
    /// A screen-space case its viewport cannot hold, judged clipped at that
    /// viewport under its own `clip-then-snap` (SPEC.md §16.9): the
    /// rectangle ([`Rasterizer::screen_viewport`]).
    pub viewport: Option<ScreenViewport>,
    /// With `viewport`: its own subpixel bits where the case states fewer,
    /// at which it snaps the new vertices (`clipped::clip_scene_on_grid`).
    pub viewport_bits: Option<u32>,
    /// With `viewport`, for a case whose plan interpolates depth or
    /// attributes: the clipped triangles' values are judged as the whole
    /// triangles' planes at the samples their pieces cover
    /// ([`OwnConventions::whole_values`], SPEC.md §16.9).
    pub viewport_values: bool,
}

impl OwnConventions {
    /// What `candidate` is judged under on `scene`; the default (nothing)
    /// when it follows the case.
    pub fn of(candidate: &dyn Rasterizer, scene: &Scene) -> OwnConventions {
        let y_up = candidate.fixed_y_direction() == Some(YDirection::Up);
        // Only where a fill rule decides a sample: not for a case of
        // midpoint or diamond-exit lines alone (SPEC.md §3, §4, §17.1).
        let fill_rule = candidate
            .fixed_fill_rule()
            .map(|rule| if y_up { mirrored(rule) } else { rule })
            .or_else(|| y_up.then(|| mirrored(scene.rules.fill_rule)))
            .filter(|&rule| rule != scene.rules.fill_rule)
            .filter(|_| scene.primitives.iter().any(uses_fill_rule));
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
        let case_bits = scene.rules.subpixel_bits;
        let (subpixel_bits, snapping) = match candidate.fixed_snapping() {
            Some(Snapping::Bits(own)) => (
                Some(own).filter(|&own| case_bits.is_none_or(|bits| bits > own)),
                None,
            ),
            Some(Snapping::None) => (None, case_bits.map(|_| Snapping::None)),
            Some(Snapping::Truncate) => (None, Some(Snapping::Truncate)),
            None => (None, None),
        };
        let sample_pattern = match (candidate.fixed_sample_pattern(), &scene.effects.antialias) {
            (Some(own), Some(aa)) if own != aa.pattern => Some(own),
            _ => None,
        };
        OwnConventions {
            fill_rule,
            no_tie_rule: candidate.no_tie_rule(),
            clip,
            subpixel_bits,
            snapping,
            sample_pattern,
            y_up,
            integer_centre: candidate.fixed_pixel_centre() == Some(PixelCentre::Integer),
            line_latitude: candidate.diamond_exit_latitude()
                && !scene.in_clip_space()
                && scene.effects.antialias.is_none()
                && scene
                    .primitives
                    .iter()
                    .any(|p| matches!(p, Primitive::Line(l) if l.rule == LineRule::DiamondExit)),
            line_parameter: LineParameters::of(candidate, scene),
            rectangle_border_ties: candidate.rectangle_border_no_tie_rule()
                && scene
                    .primitives
                    .iter()
                    .any(|p| matches!(p, Primitive::Line(l) if l.rule == LineRule::Rectangle)),
            viewport: None,
            viewport_bits: None,
            viewport_values: false,
        }
    }

    /// These and, for a screen-space case that `candidate` draws through a
    /// viewport too small to hold it and clips at (its declared `clip_xy`
    /// is `clip-then-snap`), that viewport: the case is then judged clipped
    /// there (`clipped.rs`, SPEC.md §16.9), its clipping reported as the
    /// candidate's own (`clip_xy clip-then-snap`); where its plan
    /// interpolates, its clipped triangles' values are the whole
    /// triangles' (`viewport_values`). A case `clipped.rs` cannot restate
    /// (lines, points, motion) is judged as stated.
    pub fn with_viewport(mut self, candidate: &dyn Rasterizer, scene: &Scene, plan: &Plan) -> Self {
        let clips = matches!(
            candidate.fixed_clip_rules(),
            Some((ClipXy::ClipThenSnap, _))
        );
        if !clips || !clipped::applies(scene, plan) {
            return self;
        }
        if let Some(viewport) = candidate.screen_viewport(scene, plan) {
            self.viewport = Some(viewport);
            self.viewport_bits = match (candidate.fixed_snapping(), scene.rules.subpixel_bits) {
                (Some(Snapping::Bits(own)), Some(bits)) if own > bits => Some(own),
                _ => None,
            };
            self.clip = Some(ClipRules {
                xy: ClipXy::ClipThenSnap,
                ..self.clip.unwrap_or(scene.rules.clip)
            });
            self.viewport_values = plan.interpolates();
        }
        self
    }

    /// Whether the case is restated (the tie set of a rasterizer with no
    /// tie rule restates nothing).
    pub fn any(&self) -> bool {
        self.fill_rule.is_some()
            || self.clip.is_some()
            || self.subpixel_bits.is_some()
            || self.snapping.is_some()
            || self.sample_pattern.is_some()
            || self.y_up
            || self.integer_centre
            || self.line_parameter.is_some()
            || self.viewport.is_some()
    }

    /// Why `scene` cannot be judged under these conventions, if it cannot
    /// (SPEC.md §2.1, §3.2, §14.1, §14.2.1): the case is then unsupported
    /// with this reason, never judged under other conventions.
    pub fn cannot_judge(&self, scene: &Scene) -> Option<String> {
        if let Some(own) = self.line_parameter.filter(|own| own.clamp().is_none()) {
            return Some(format!(
                "its own line parameters ({}) clamp t on some of the case's lines and not on others, which no case can state (SPEC.md §5.1)",
                own.words()
            ));
        }
        if let Some(why) = self
            .fill_rule
            .and_then(|rule| cannot_judge_under(scene, rule))
        {
            return Some(why);
        }
        if let (Some(own), Some(aa)) = (self.sample_pattern, &scene.effects.antialias) {
            if let Err(why) = own.check_count(aa.samples) {
                return Some(format!(
                    "its own sample positions are the {} pattern, and the case asks for {} samples: {why} (SPEC.md §14.2.1)",
                    own.name(),
                    aa.samples
                ));
            }
        }
        if self.snapping == Some(Snapping::Truncate) && scene.in_clip_space() {
            return Some(
                "it truncates vertices to whole pixels, which SPEC.md §3.2 defines for screen-space cases only".to_owned(),
            );
        }
        if self.y_up {
            let mirrored_rules = scene
                .primitives
                .iter()
                .any(|p| matches!(p, Primitive::Line(_) | Primitive::Point(_)));
            let why = if scene.in_clip_space() {
                Some("a clip-space case's y direction is its viewport's, which an adapter turns round")
            } else if mirrored_rules {
                Some("a line's or a point's rule read with y up is no rule a case can state")
            } else if scene.effects.antialias.is_some() {
                Some("sample positions read with y up are no pattern a case can state")
            } else {
                None
            };
            if let Some(why) = why {
                return Some(format!("its y axis points up: {why} (SPEC.md §2.1)"));
            }
        }
        if self.integer_centre && scene.in_clip_space() {
            return Some(
                "its samples lie at whole coordinates, which SPEC.md §2.1 restates for screen-space cases only".to_owned(),
            );
        }
        None
    }

    /// The case restated under these conventions. The pins
    /// `samples_covered` and `time_coverage` (whose riding samples fall by
    /// the tie rule) describe the case's own, so they are dropped; so is
    /// `area` (the exact area of the snapped primitives) when the vertices
    /// move (other bits, no snapping, truncation, another pixel centre).
    pub fn restate(&self, scene: &Scene) -> Scene {
        self.restate_as(scene, Clipped::Pieces).0
    }

    /// Where the values of the pieces of the case restated come from, when
    /// it is restated clipped at a viewport and its plan interpolates
    /// (`viewport_values`): the case restated alike with each clipped
    /// triangle whole, and the indices of those triangles, for
    /// `reference::take_whole_values` (SPEC.md §16.9). `None` otherwise,
    /// or when no triangle is clipped.
    pub fn whole_values(&self, scene: &Scene) -> Option<(Scene, Vec<usize>)> {
        if self.viewport.is_none() || !self.viewport_values {
            return None;
        }
        Some(self.restate_as(scene, Clipped::Whole)).filter(|(_, pieces)| !pieces.is_empty())
    }

    /// [`OwnConventions::restate`], each triangle clipped at the viewport
    /// restated `as_` its pieces or whole; with their indices.
    fn restate_as(&self, scene: &Scene, as_: Clipped) -> (Scene, Vec<usize>) {
        let mut s = scene.clone();
        let mut clipped = Vec::new();
        if let Some(viewport) = self.viewport {
            // First, from the positions the adapter sent: the case's own.
            let bits = scene.rules.subpixel_bits;
            clipped = clipped::clip_scene_on_grid(&mut s, viewport, bits, self.viewport_bits, as_);
        }
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
        match self.snapping {
            Some(Snapping::None) => {
                s.rules.subpixel_bits = None;
                s.expect.area = None;
            }
            Some(Snapping::Truncate) => {
                s.rules.subpixel_bits = None;
                s.expect.area = None;
                each_coordinate(&mut s, |c| *c = floor(c));
            }
            _ => {}
        }
        if let (Some(pattern), Some(aa)) = (self.sample_pattern, s.effects.antialias.as_mut()) {
            aa.pattern = pattern;
        }
        if let Some(own) = self.line_parameter {
            for p in &mut s.primitives {
                if let Primitive::Line(line) = p {
                    if let Some(t) = own.get(line.rule) {
                        line.parameter = t.parameter;
                    }
                }
            }
            if let Some(clamp) = own.clamp() {
                s.rules.line_clamp = clamp;
            }
        }
        if self.y_up {
            s.rules.cull = match s.rules.cull {
                Cull::Clockwise => Cull::CounterClockwise,
                Cull::CounterClockwise => Cull::Clockwise,
                Cull::None => Cull::None,
            };
        }
        if self.integer_centre {
            // Snapped first, on the grid the case states (or the one just
            // restated), then moved: ½ is exact, and a coarse grid's ties
            // fall as they would have.
            let half = Number::ratio(1, 2);
            let bits = s.rules.subpixel_bits.take();
            each_coordinate(&mut s, |c| {
                let snapped = bits.map_or_else(|| c.clone(), |b| c.snapped(b));
                *c = &snapped + &half;
            });
            s.expect.area = None;
        }
        s.expect.samples_covered = None;
        s.expect.time_coverage.clear();
        (s, clipped)
    }

    /// How a case clipped at a viewport with values is judged, in words
    /// (`viewport_values`): the console's and [`OwnConventions::describe`]'s.
    pub const WHOLE_VALUES: &'static str =
        "the values of a clipped triangle's pieces from its whole planes";

    /// In words, for a failure of the reference under them.
    pub fn describe(&self) -> String {
        let mut words = Vec::new();
        if let Some(rule) = self.fill_rule {
            words.push(format!("the {rule} rule"));
        }
        if self.no_tie_rule {
            words.push("no tie rule".to_owned());
        }
        match (self.viewport, self.clip) {
            (Some(viewport), _) => {
                words.push(format!("clip_xy clip-then-snap at {}", viewport.words()));
                if self.viewport_values {
                    words.push(Self::WHOLE_VALUES.to_owned());
                }
            }
            (None, Some(clip)) => words.push(clip.words()),
            (None, None) => {}
        }
        if let Some(bits) = self.subpixel_bits {
            words.push(format!("{bits} subpixel bits"));
        }
        if let Some(snapping) = self.snapping {
            words.push(snapping.words());
        }
        if let Some(pattern) = self.sample_pattern {
            words.push(format!("its {} sample positions", pattern.name()));
        }
        if self.y_up {
            words.push("y up".to_owned());
        }
        if self.integer_centre {
            words.push("samples at whole coordinates".to_owned());
        }
        if self.line_latitude {
            words.push("the latitude for diamond-exit lines".to_owned());
        }
        if let Some(own) = self.line_parameter {
            words.push(format!("its {} line parameter", own.words()));
        }
        if self.rectangle_border_ties {
            words.push("no tie rule on rectangle lines' borders".to_owned());
        }
        words.join(" and ")
    }
}

/// A fill rule read with y up, in SPEC's y-down terms: top and bottom
/// change places (SPEC.md §2.1).
pub fn mirrored(rule: FillRule) -> FillRule {
    match rule {
        FillRule::TopLeft => FillRule::BottomLeft,
        FillRule::BottomLeft => FillRule::TopLeft,
        FillRule::TopRight => FillRule::BottomRight,
        FillRule::BottomRight => FillRule::TopRight,
        FillRule::AllEdges => FillRule::AllEdges,
    }
}

/// Every x and y of every vertex, at both ends of a moving one.
fn each_coordinate(scene: &mut Scene, mut f: impl FnMut(&mut Number)) {
    for v in scene.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
        f(&mut v.x);
        f(&mut v.y);
        if let Some(to) = v.to.as_mut() {
            for c in to.iter_mut() {
                f(c);
            }
        }
    }
}

/// ⌊c⌋, exactly: truncation to a whole pixel towards −∞ (SPEC.md §3.2).
fn floor(c: &Number) -> Number {
    Number::from_rbig(dashu_ratio::RBig::from(c.as_rbig().floor()))
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
                    conventions: d.conventions,
                    coverage: d.coverage,
                }) as Box<dyn Rasterizer>,
                None => candidate,
            },
        )
        .collect()
}
