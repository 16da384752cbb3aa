//! The hello of protocol v2 (SPEC.md §12.7): the first line a persistent
//! program writes, before it reads anything, declaring its name, version,
//! capabilities and conventions. A case outside the declared capabilities
//! is unsupported, with the declaration as its reason, and is never sent.
//! A program that sends no hello speaks v1 and is asked everything.

use std::sync::Mutex;

use serde_json::{Map, Value};

use super::messages::shorten;
use crate::scene::case::{closest, edit_distance};

use crate::plan::Plan;
use crate::rasterizer::Declaration;
use crate::scene::{
    ClipXy, ClipZ, ConservativeMode, DeclaredRule, FillRule, InterpolateFrom, Interpolation,
    LineRule, Pattern, PointBounds, PointClip, PolygonFill, Primitive, Scene,
};

use super::conservative::{self, DeclaredConservative};
use super::space::{Declared3d, FixedClip, DEPTH_FORMATS};

/// What a program declared in its hello. A list left out declares nothing
/// (everything is asked of it); `None` below means "not declared".
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Hello {
    pub protocol: u64,
    pub name: Option<String>,
    pub version: Option<String>,
    /// `triangles`, `lines`, `polygons`.
    primitives: Option<Vec<String>>,
    line_rules: Option<Vec<String>>,
    fill_rules: Option<Vec<String>>,
    polygon_fills: Option<Vec<String>>,
    interpolation: Option<Vec<String>>,
    sample_patterns: Option<Vec<String>>,
    antialias: Option<bool>,
    max_samples: Option<u64>,
    max_subpixel_bits: Option<u64>,
    exact_coordinates: Option<bool>,
    depth: Option<bool>,
    attributes: Option<bool>,
    /// Moving scenes are sent (SPEC.md §12.8) only when this is `Some(true)`
    /// in a version 2 hello.
    motion: Option<bool>,
    /// Fragments carry no depth and no attributes (SPEC.md §12.9).
    coverage_only: Option<bool>,
    /// Coverage fractions are multiples of 1/(2^bits − 1) (§12.9).
    coverage_bits: Option<u64>,
    /// `"fraction"`: multiples of 1/2^bits, capped at 1 − 1/2^bits (§12.9).
    coverage_fraction: bool,
    /// `conventions.snapping`, `sample_pattern`, `y`, `pixel_centre`
    /// (SPEC.md §2.1, §3.2, §14.2.1).
    declaration: Declaration,
    /// Declared conventions, kept as written; `fill_rule` is judged.
    pub conventions: Option<Value>,
    fill_rule: Option<DeclaredRule>,
    /// Clip space, points, depth formats and polygon offset, and the clip
    /// conventions it follows (SPEC.md §12.10): `space.rs`.
    three_d: Declared3d,
    /// Conservative rasterization (SPEC.md §12.11): `conservative.rs`.
    conservative: Option<DeclaredConservative>,
}

/// How a program's answers are shaped, as its hello declares them
/// (SPEC.md §12.9); a program without a hello gives the default.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Answers {
    /// Its fragments carry no depth and no attributes, whatever the plan
    /// asks; they are then not judged.
    pub coverage_only: bool,
    /// Its coverage fractions are the exact areas as multiples of
    /// 1/(2^bits − 1), judged per primitive within one such step.
    pub coverage_bits: Option<u32>,
    /// The fill rule it follows whatever the case states
    /// (`conventions.fill_rule`): cases are judged under it (SPEC.md §3.1),
    /// or off the ties for `none` (§3.1.1).
    pub fill_rule: Option<DeclaredRule>,
    /// The clip conventions it follows whatever the case states
    /// (SPEC.md §12.10): cases are judged under them (§16.9).
    pub clip: FixedClip,
    /// Its coverage encoding is `"fraction"`: steps of 1/2^bits, saturating.
    pub coverage_fraction: bool,
    /// Its other conventions (snapping, sample positions, y, pixel centre).
    pub declaration: Declaration,
}

impl Answers {
    /// The declared quantization step of coverage fractions; 0 for none.
    pub fn step(&self) -> f64 {
        let steps = |bits: u32| {
            let whole = 2f64.powi(bits as i32);
            if self.coverage_fraction {
                whole
            } else {
                whole - 1.0
            }
        };
        self.coverage_bits.map_or(0.0, |bits| 1.0 / steps(bits))
    }

    /// Whether its coverage encoding saturates at 1 − step (`"fraction"`).
    pub fn saturates(&self) -> bool {
        self.coverage_fraction && self.coverage_bits.is_some()
    }
}

/// The most coverage bits a hello may declare.
const MAX_COVERAGE_BITS: u64 = 24;

/// The protocol versions this rastercheck speaks.
pub const VERSIONS: [u64; 2] = [1, 2];

/// The primitive kinds a hello may list (`points`: SPEC.md §12.10).
const PRIMITIVES: [&str; 4] = ["triangles", "lines", "polygons", "points"];

/// What a key of the hello takes.
#[derive(Clone, Copy, Debug)]
enum Kind {
    /// An object, whose keys are those listed under its path.
    Object,
    /// A string (`null`: not given).
    Text,
    /// `true` or `false`.
    Flag,
    /// A whole number from the first to the second.
    Count(u64, u64),
    /// One of these words.
    Word(&'static [&'static str]),
    /// A list of these words.
    Words(&'static [&'static str]),
    /// A value its own reader checks (`snapping`: a word or a number of
    /// bits, `rasterizer::Declaration::read`).
    Read,
}

/// Every key a hello may hold (SPEC.md §12.7, §12.9), as (the object it
/// sits in, under `$.hello`; the key; what it takes): the one list a new
/// key of the protocol joins, with one line. Any other key is an error
/// naming its JSON path, with the nearest known key when one is close
/// (`conventions` alone may also hold descriptions: [`DESCRIPTIONS`]).
const KEYS: &[(&str, &str, Kind)] = &[
    ("", "protocol", Kind::Count(1, 2)),
    ("", "name", Kind::Text),
    ("", "version", Kind::Text),
    ("", "capabilities", Kind::Object),
    ("", "conventions", Kind::Object),
    ("capabilities", "primitives", Kind::Words(&PRIMITIVES)),
    ("capabilities", "line_rules", Kind::Words(&LineRule::NAMES)),
    ("capabilities", "fill_rules", Kind::Words(&FillRule::NAMES)),
    (
        "capabilities",
        "polygon_fills",
        Kind::Words(&PolygonFill::NAMES),
    ),
    (
        "capabilities",
        "interpolation",
        Kind::Words(&Interpolation::NAMES),
    ),
    (
        "capabilities",
        "sample_patterns",
        Kind::Words(&Pattern::NAMES),
    ),
    ("capabilities", "antialias", Kind::Flag),
    ("capabilities", "max_samples", Kind::Count(0, u64::MAX)),
    (
        "capabilities",
        "max_subpixel_bits",
        Kind::Count(0, u64::MAX),
    ),
    ("capabilities", "exact_coordinates", Kind::Flag),
    ("capabilities", "depth", Kind::Flag),
    ("capabilities", "attributes", Kind::Flag),
    ("capabilities", "motion", Kind::Flag),
    ("capabilities", "coverage_only", Kind::Flag),
    (
        "capabilities",
        "coverage_bits",
        Kind::Count(1, MAX_COVERAGE_BITS),
    ),
    ("conventions", "fill_rule", Kind::Word(&DeclaredRule::NAMES)),
    // Clip space, points, depth formats and polygon offset (§12.10,
    // space.rs).
    ("capabilities", "clip_space", Kind::Flag),
    ("capabilities", "depth_formats", Kind::Words(&DEPTH_FORMATS)),
    ("capabilities", "polygon_offset", Kind::Flag),
    ("conventions", "clip_xy", Kind::Word(&ClipXy::NAMES)),
    ("conventions", "clip_z", Kind::Word(&ClipZ::NAMES)),
    (
        "conventions",
        "interpolate_from",
        Kind::Word(&InterpolateFrom::NAMES),
    ),
    ("conventions", "clip_points", Kind::Word(&PointClip::NAMES)),
    (
        "conventions",
        "point_bounds",
        Kind::Word(&PointBounds::NAMES),
    ),
    // The conventions of SPEC.md §2.1, §3.2 and §14.2.1
    // (`rasterizer::Declaration`) and the coverage encoding of §12.9.
    ("conventions", "snapping", Kind::Read),
    ("conventions", "sample_pattern", Kind::Word(&["standard"])),
    ("conventions", "y", Kind::Word(&["down", "up"])),
    (
        "conventions",
        "pixel_centre",
        Kind::Word(&["half", "integer"]),
    ),
    (
        "capabilities",
        "coverage_encoding",
        Kind::Word(&["unorm", "fraction"]),
    ),
    // Diamond-exit lines drawn with the APIs' latitude (SPEC.md §4.2.1).
    (
        "conventions",
        "diamond_exit",
        Kind::Word(&Declaration::DIAMOND_EXIT),
    ),
    // Conservative rasterization (§12.11, conservative.rs).
    ("capabilities", "conservative", Kind::Object),
    (
        "capabilities.conservative",
        "modes",
        Kind::Words(&ConservativeMode::NAMES),
    ),
    ("capabilities.conservative", "uncertainty", Kind::Read),
    (
        "capabilities.conservative",
        "degenerate_triangles",
        Kind::Flag,
    ),
    ("capabilities.conservative", "degenerate_lines", Kind::Flag),
    ("capabilities.conservative", "points_and_lines", Kind::Flag),
    ("capabilities.conservative", "fully_covered", Kind::Flag),
    ("capabilities.conservative", "depth", Kind::Flag),
];

/// The objects whose other keys are descriptions for people rather than
/// errors: a string each, reported and not judged (`"arithmetic":
/// "doubles"`). A key there that is one typo from a known key
/// (`fillrule`), or whose value is a word a known key takes, is still an
/// error: it was meant as that key.
const DESCRIPTIONS: [&str; 1] = ["conventions"];

/// Whether a line of output is a hello (an object with a `hello` key).
pub fn is_hello(value: &Value) -> bool {
    value.as_object().is_some_and(|o| o.contains_key("hello"))
}

/// The commands (program and arguments) whose hello the preflight read
/// ([`super::preflight::preflight`]): the run then waits for their hello
/// up to the case's time limit, not [`super::limits::HELLO_WAIT`], since
/// it is known to come (a program slow to start under load would
/// otherwise be taken for version 1 on its first case).
static SEEN: Mutex<Vec<Vec<String>>> = Mutex::new(Vec::new());

/// Remembers that `command` wrote a hello when the preflight started it.
pub(super) fn remember(command: &[String]) {
    let mut seen = SEEN.lock().unwrap_or_else(|e| e.into_inner());
    if !seen.iter().any(|c| c == command) {
        seen.push(command.to_vec());
    }
}

/// Whether `command` wrote a hello when the preflight started it.
pub(super) fn seen(command: &[String]) -> bool {
    SEEN.lock()
        .unwrap_or_else(|e| e.into_inner())
        .iter()
        .any(|c| c == command)
}

/// `key` quoted for a message: at most 80 characters of it.
fn quoted(key: &str) -> String {
    format!("{:?}", shorten(key))
}

/// The message for a word not among `known` at `path`.
fn unknown_word(path: &str, word: &str, known: &[&str]) -> String {
    let hint = match closest(word, known) {
        Some(meant) => format!("did you mean {meant:?}? "),
        None => String::new(),
    };
    format!(
        "{path} is {}; {hint}known: {}",
        quoted(word),
        known.join(", ")
    )
}

/// Checks every key of the object at `at` (`""` for the hello itself) and
/// the objects under it against [`KEYS`]: unknown keys, values of the
/// wrong type, unknown words. The message names the JSON path.
fn check_object(object: &Map<String, Value>, at: &str) -> Result<(), String> {
    let path_of = |key: &str| match at {
        "" => format!("$.hello.{}", shorten(key)),
        _ => format!("$.hello.{at}.{}", shorten(key)),
    };
    let known: Vec<&str> = KEYS
        .iter()
        .filter(|(parent, _, _)| *parent == at)
        .map(|(_, key, _)| *key)
        .collect();
    for (key, value) in object {
        let path = path_of(key);
        let Some(&(_, _, kind)) = KEYS.iter().find(|(p, k, _)| *p == at && k == key) else {
            if DESCRIPTIONS.contains(&at) {
                check_description(key, value, at, &path)?;
                continue;
            }
            // A key of another object of the hello, put in the wrong one.
            let elsewhere = || {
                KEYS.iter()
                    .filter(|(parent, _, _)| *parent != at && !parent.is_empty())
                    .find(|(_, k, _)| closest(key, &[k]).is_some())
                    .map(|(parent, k, _)| format!("{parent}.{k}"))
            };
            let hint = match closest(key, &known).map(str::to_owned).or_else(elsewhere) {
                Some(meant) => format!("did you mean {meant:?}?"),
                None => format!("known: {}", known.join(", ")),
            };
            return Err(format!("{path}: unknown key {}; {hint}", quoted(key)));
        };
        match (kind, value) {
            (Kind::Object, Value::Object(inner)) => {
                let inner_at = match at {
                    "" => key.clone(),
                    _ => format!("{at}.{key}"),
                };
                check_object(inner, &inner_at)?;
            }
            (Kind::Object, _) => return Err(format!("{path} must be an object")),
            (Kind::Text, Value::String(_) | Value::Null) => {}
            (Kind::Text, _) => return Err(format!("{path} must be a string")),
            (Kind::Flag, Value::Bool(_)) => {}
            (Kind::Flag, _) => return Err(format!("{path} must be true or false")),
            (Kind::Count(low, high), _) => match value.as_u64() {
                Some(n) if (low..=high).contains(&n) => {}
                Some(_) if high < u64::MAX => {
                    return Err(format!("{path} must be from {low} to {high}"))
                }
                _ => return Err(format!("{path} must be a whole number")),
            },
            (Kind::Word(words), Value::String(word)) => {
                if !words.contains(&word.as_str()) {
                    return Err(unknown_word(&path, word, words));
                }
            }
            (Kind::Word(words), _) => {
                return Err(format!("{path} must be one of {}", words.join(", ")))
            }
            (Kind::Words(words), Value::Array(list)) => {
                for (i, item) in list.iter().enumerate() {
                    let item_path = format!("{path}[{i}]");
                    let word = item
                        .as_str()
                        .ok_or_else(|| format!("{item_path} must be a string"))?;
                    if !words.contains(&word) {
                        return Err(unknown_word(&item_path, word, words));
                    }
                }
            }
            (Kind::Words(_), _) => return Err(format!("{path} must be a list of words")),
            (Kind::Read, _) => {}
        }
    }
    Ok(())
}

/// A key of `conventions` that no entry of [`KEYS`] names: a description
/// (a string), unless it looks meant as a known key.
fn check_description(key: &str, value: &Value, at: &str, path: &str) -> Result<(), String> {
    let known: Vec<(&str, Kind)> = KEYS
        .iter()
        .filter(|(parent, _, _)| *parent == at)
        .map(|(_, key, kind)| (*key, *kind))
        .collect();
    let names: Vec<&str> = known.iter().map(|(k, _)| *k).collect();
    // A typo (two edits at most: `fillrule`), not a description that only
    // resembles a key (`interpolation` beside `interpolate_from`).
    let typo = names
        .iter()
        .map(|name| (edit_distance(key, name), *name))
        .filter(|(d, _)| *d <= 2)
        .min()
        .map(|(_, name)| name);
    let meant = typo.or_else(|| {
        let word = value.as_str()?;
        known.iter().find_map(|(k, kind)| match kind {
            Kind::Word(words) if words.contains(&word) => Some(*k),
            _ => None,
        })
    });
    if let Some(meant) = meant {
        return Err(format!(
            "{path}: unknown key {}; did you mean {meant:?}?",
            quoted(key)
        ));
    }
    if !value.is_string() {
        return Err(format!(
            "{path}: unknown key {}; a description must be a string (known keys: {})",
            quoted(key),
            names.join(", ")
        ));
    }
    Ok(())
}

impl Hello {
    /// Reads `{"hello": {...}}`, checked like a case file: an unknown key
    /// or word, or a value of the wrong type, anywhere in it is an error
    /// naming its JSON path (with "did you mean" when one is close).
    pub fn parse(value: &Value) -> Result<Hello, String> {
        let line = value.as_object().ok_or("$ must be an object")?;
        if let Some(key) = line.keys().find(|k| *k != "hello") {
            return Err(format!(
                "${}: unknown key {} beside the hello; a hello line holds only \"hello\"",
                if key.is_empty() {
                    String::new()
                } else {
                    format!(".{}", shorten(key))
                },
                quoted(key)
            ));
        }
        let hello = value
            .get("hello")
            .and_then(Value::as_object)
            .ok_or("$.hello must be an object")?;
        let protocol = hello
            .get("protocol")
            .and_then(Value::as_u64)
            .ok_or("$.hello.protocol must be a protocol version (2)")?;
        if !VERSIONS.contains(&protocol) {
            return Err(format!(
                "$.hello.protocol is {protocol}; this rastercheck speaks versions 1 and 2"
            ));
        }
        check_object(hello, "")?;
        let text = |key: &str| hello.get(key).and_then(Value::as_str).map(str::to_owned);
        let conventions = hello.get("conventions");
        let caps = hello.get("capabilities");
        let cap = |key: &str| caps.and_then(|c| c.get(key));
        let words = |key: &str| {
            cap(key).and_then(Value::as_array).map(|list| {
                list.iter()
                    .filter_map(Value::as_str)
                    .map(str::to_owned)
                    .collect::<Vec<_>>()
            })
        };
        let flag = |key: &str| cap(key).and_then(Value::as_bool);
        let count = |key: &str| cap(key).and_then(Value::as_u64);
        let mut three_d = Declared3d::parse(
            caps.and_then(Value::as_object),
            conventions.and_then(Value::as_object),
        )?;
        three_d.points = words("primitives").is_some_and(|l| l.iter().any(|w| w == "points"));
        let declaration = match conventions.and_then(Value::as_object) {
            Some(c) => Declaration::read(c, "$.hello.conventions")?,
            None => Declaration::default(),
        };
        if cap("coverage_encoding").and_then(Value::as_str) == Some("fraction")
            && cap("coverage_bits").is_none()
        {
            return Err(
                "$.hello.capabilities.coverage_encoding needs coverage_bits (the k of 1/2^k)"
                    .to_owned(),
            );
        }
        let conservative = cap("conservative")
            .and_then(Value::as_object)
            .map(DeclaredConservative::parse)
            .transpose()?;
        if conservative.as_ref().is_some_and(|c| c.depth) && flag("coverage_only") == Some(true) {
            return Err(format!(
                "{}.depth is true, but capabilities.coverage_only is true: a coverage-only \
                 program gives no depth (SPEC §12.9, §12.11)",
                conservative::PATH
            ));
        }
        Ok(Hello {
            protocol,
            name: text("name"),
            version: text("version"),
            primitives: words("primitives"),
            line_rules: words("line_rules"),
            fill_rules: words("fill_rules"),
            polygon_fills: words("polygon_fills"),
            interpolation: words("interpolation"),
            sample_patterns: words("sample_patterns"),
            antialias: flag("antialias"),
            max_samples: count("max_samples"),
            max_subpixel_bits: count("max_subpixel_bits"),
            exact_coordinates: flag("exact_coordinates"),
            depth: flag("depth"),
            attributes: flag("attributes"),
            motion: flag("motion"),
            coverage_only: flag("coverage_only"),
            coverage_bits: count("coverage_bits"),
            fill_rule: conventions
                .and_then(|c| c.get("fill_rule"))
                .and_then(Value::as_str)
                .and_then(DeclaredRule::from_name),
            coverage_fraction: cap("coverage_encoding").and_then(Value::as_str) == Some("fraction"),
            declaration,
            conventions: conventions.cloned(),
            three_d,
            conservative,
        })
    }

    /// Why the scene asks for something the program declared it does not
    /// do, naming the declaration; `None` when nothing declared refuses it.
    pub fn refuses(&self, scene: &Scene, plan: &Plan) -> Option<String> {
        let lacks = |list: &Option<Vec<String>>, word: &str| {
            list.as_ref().is_some_and(|l| !l.iter().any(|w| w == word))
        };
        let declared =
            |list: &Option<Vec<String>>| list.as_ref().map_or(String::new(), |l| l.join(", "));
        let who = match self.title() {
            Some(title) => format!("the program ({title})"),
            None => "the program".to_owned(),
        };
        for p in &scene.primitives {
            let kind = match p {
                Primitive::Triangle(_) => "triangles",
                Primitive::Line(_) => "lines",
                Primitive::Polygon(_) => "polygons",
                Primitive::Point(_) => "points",
            };
            if kind != "points" && lacks(&self.primitives, kind) {
                return Some(format!(
                    "{who} declares no {kind} (its hello's primitives: [{}])",
                    declared(&self.primitives)
                ));
            }
            if let Primitive::Line(l) = p {
                if lacks(&self.line_rules, l.rule.name()) {
                    return Some(format!(
                        "{who} declares no {} lines (its hello's line_rules: [{}])",
                        l.rule.name(),
                        declared(&self.line_rules)
                    ));
                }
            }
            if let Primitive::Polygon(polygon) = p {
                if lacks(&self.polygon_fills, polygon.fill.name()) {
                    return Some(format!(
                        "{who} declares no {} polygon fill (its hello's polygon_fills: [{}])",
                        polygon.fill.name(),
                        declared(&self.polygon_fills)
                    ));
                }
            }
            if plan.attributes > 0 || plan.depth {
                let mode = p.interpolation().name();
                if lacks(&self.interpolation, mode) {
                    return Some(format!(
                        "{who} declares no {mode} interpolation (its hello's interpolation: [{}])",
                        declared(&self.interpolation)
                    ));
                }
            }
        }
        if let Some(why) = self.three_d.refuses(scene, &who) {
            return Some(why);
        }
        if let Some(why) = conservative::refuses(scene, self.conservative.as_ref(), &who) {
            return Some(why);
        }
        if self.fill_rule == Some(DeclaredRule::Fill(FillRule::AllEdges)) && scene.has_polygons() {
            return Some(format!(
                "{who} follows all-edges whatever the case states (its hello's \
                 conventions.fill_rule), and all-edges is not defined for polygons \
                 (SPEC.md §14.1)"
            ));
        }
        let fill = scene.rules.fill_rule.name();
        if lacks(&self.fill_rules, fill) {
            return Some(format!(
                "{who} declares no {fill} fill rule (its hello's fill_rules: [{}])",
                declared(&self.fill_rules)
            ));
        }
        match scene.rules.subpixel_bits {
            None if self.exact_coordinates == Some(false) => {
                return Some(format!(
                    "{who} declares no exact coordinates (its hello's exact_coordinates: false)"
                ))
            }
            Some(bits)
                if self
                    .max_subpixel_bits
                    .is_some_and(|max| u64::from(bits) > max) =>
            {
                return Some(format!(
                    "the case asks for {bits} subpixel bits; {who} declares at most {} \
                     (its hello's max_subpixel_bits)",
                    self.max_subpixel_bits.unwrap_or(0)
                ))
            }
            _ => {}
        }
        if let Some(aa) = &scene.effects.antialias {
            if self.antialias == Some(false) {
                return Some(format!(
                    "{who} declares no antialiasing (its hello's antialias: false)"
                ));
            }
            if let Some(max) = self.max_samples.filter(|&max| u64::from(aa.samples) > max) {
                return Some(format!(
                    "the case asks for {} samples per pixel; {who} declares at most {max} \
                     (its hello's max_samples)",
                    aa.samples
                ));
            }
            if lacks(&self.sample_patterns, aa.pattern.name()) {
                return Some(format!(
                    "{who} declares no {} sample pattern (its hello's sample_patterns: [{}])",
                    aa.pattern.name(),
                    declared(&self.sample_patterns)
                ));
            }
        }
        if plan.motion.is_some() && (self.protocol < 2 || self.motion != Some(true)) {
            let said = match self.motion {
                Some(flag) => format!("its hello's motion: {flag}"),
                None => "its hello declares no motion".to_owned(),
            };
            return Some(format!(
                "{who} speaks version {} ({said}); {}",
                self.protocol,
                super::motion::NOT_DECLARED
            ));
        }
        if plan.depth && self.depth == Some(false) {
            return Some(format!(
                "{who} declares no depth (its hello's depth: false)"
            ));
        }
        if plan.attributes > 0 && self.attributes == Some(false) {
            return Some(format!(
                "{who} declares no attributes (its hello's attributes: false)"
            ));
        }
        None
    }

    /// How the program's answers are shaped.
    pub fn answers(&self) -> Answers {
        Answers {
            coverage_only: self.coverage_only == Some(true),
            coverage_bits: self.coverage_bits.map(|b| b as u32),
            fill_rule: self.fill_rule,
            clip: self.three_d.fixed,
            coverage_fraction: self.coverage_fraction,
            declaration: self.declaration,
        }
    }

    /// Its conservative declaration (SPEC.md §12.11), when it makes one.
    pub fn conservative(&self) -> Option<&DeclaredConservative> {
        self.conservative.as_ref()
    }

    /// The program as its hello names it: `name version`, or `None`; each
    /// cut to 80 characters (SPEC.md §8), since it is quoted in every
    /// refusal and report.
    pub fn title(&self) -> Option<String> {
        let name = shorten(self.name.as_deref()?);
        Some(match &self.version {
            Some(v) => format!("{name} {}", shorten(v)),
            None => name,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn reads_a_hello_and_refuses_by_it() {
        let hello = Hello::parse(&json!({"hello": {
            "protocol": 2, "name": "toy", "version": "1.0",
            "capabilities": {"primitives": ["triangles"], "fill_rules": ["top-left"]},
        }}))
        .unwrap();
        assert_eq!(hello.title().as_deref(), Some("toy 1.0"));
        assert!(Hello::parse(&json!({"hello": {"protocol": 3}})).is_err());
        assert!(Hello::parse(&json!({"hello": {"protocol": 2,
            "capabilities": {"primitives": ["spheres"]}}}))
        .unwrap_err()
        .contains("$.hello.capabilities.primitives[0]"));
        assert!(is_hello(&json!({"hello": {}})));
        assert!(!is_hello(&json!({"id": "1"})));
    }

    #[test]
    fn a_description_that_only_resembles_a_key_is_a_description() {
        // The C example's own hello: `interpolation` is a description,
        // not `interpolate_from` misspelt (five edits away).
        let hello = Hello::parse(&json!({"hello": {"protocol": 2,
            "conventions": {"interpolation": "doubles", "arithmetic": "exact"}}}));
        assert!(hello.is_ok(), "{hello:?}");
    }

    fn error_of(hello: Value) -> String {
        Hello::parse(&json!({ "hello": hello })).unwrap_err()
    }

    /// Every mistake of issue 40 is an error naming its path, with the key
    /// or word meant when one is close.
    #[test]
    fn a_hello_is_checked_like_a_case_file() {
        let cases = [
            (
                json!({"protocol": 2, "primitive": ["triangles"]}),
                "$.hello.primitive: unknown key \"primitive\"; did you mean \"capabilities.primitives\"?",
            ),
            (
                json!({"protocol": 2, "capabilities": {"primitive": ["triangles"]}}),
                "$.hello.capabilities.primitive: unknown key \"primitive\"; did you mean \"primitives\"?",
            ),
            (
                json!({"protocol": 2, "capabilities": {"coverage_bit": 8}}),
                "$.hello.capabilities.coverage_bit: unknown key \"coverage_bit\"; did you mean \"coverage_bits\"?",
            ),
            (
                json!({"protocol": 2, "conventions": {"fillrule": "top-left"}}),
                "$.hello.conventions.fillrule: unknown key \"fillrule\"; did you mean \"fill_rule\"?",
            ),
            (
                json!({"protocol": 2, "conventions": {"rule": "bottom-right"}}),
                "$.hello.conventions.rule: unknown key \"rule\"; did you mean \"fill_rule\"?",
            ),
            (
                json!({"protocol": 2, "conventions": {"ties": 3}}),
                "$.hello.conventions.ties: unknown key \"ties\"; a description must be a string",
            ),
            (
                json!({"protocol": 2, "capabilities": {"primitives": ["triangle"]}}),
                "$.hello.capabilities.primitives[0] is \"triangle\"; did you mean \"triangles\"? known: triangles,",
            ),
            (
                json!({"protocol": 2, "capabilities": {"line_rules": ["diamond"]}}),
                "$.hello.capabilities.line_rules[0] is \"diamond\"",
            ),
            (
                json!({"protocol": 2, "conventions": {"fill_rule": "top_left"}}),
                "$.hello.conventions.fill_rule is \"top_left\"; did you mean \"top-left\"?",
            ),
            (
                json!({"protocol": 2, "capabilities": {"antialias": "yes"}}),
                "$.hello.capabilities.antialias must be true or false",
            ),
            (
                json!({"protocol": 2, "capabilities": {"max_samples": -1}}),
                "$.hello.capabilities.max_samples must be a whole number",
            ),
            (
                json!({"protocol": 2, "capabilities": {"coverage_bits": 30}}),
                "$.hello.capabilities.coverage_bits must be from 1 to 24",
            ),
            (
                json!({"protocol": 2, "capabilities": []}),
                "$.hello.capabilities must be an object",
            ),
            (json!({"protocol": 2, "name": 7}), "$.hello.name must be a string"),
            // Conservative rasterization (§12.11).
            (
                json!({"protocol": 2, "capabilities": {"conservative": {"mode": ["overestimate"]}}}),
                "$.hello.capabilities.conservative.mode: unknown key \"mode\"; did you mean \"modes\"?",
            ),
            (
                json!({"protocol": 2, "capabilities": {"conservative": {"modes": ["overestimates"]}}}),
                "$.hello.capabilities.conservative.modes[0] is \"overestimates\"; did you mean \"overestimate\"?",
            ),
            (
                json!({"protocol": 2, "capabilities": {"conservative": {"fully_covered": "yes"}}}),
                "$.hello.capabilities.conservative.fully_covered must be true or false",
            ),
            (
                json!({"protocol": 2, "capabilities": {"conservative": {"uncertainty": "1/0"}}}),
                "$.hello.capabilities.conservative.uncertainty:",
            ),
            (
                json!({"protocol": 2, "capabilities": {"conservative": true}}),
                "$.hello.capabilities.conservative must be an object",
            ),
            (
                json!({"protocol": 2, "capabilities": {"coverage_only": true,
                                                       "conservative": {"depth": true}}}),
                "$.hello.capabilities.conservative.depth is true, but capabilities.coverage_only is true",
            ),
        ];
        for (hello, expected) in cases {
            let error = error_of(hello.clone());
            assert!(error.starts_with(expected), "{hello}: {error}");
        }
        let line = json!({"hello": {"protocol": 2}, "id": "1"});
        assert!(Hello::parse(&line)
            .unwrap_err()
            .starts_with("$.id: unknown key"));
        // A 2 MB key is quoted short.
        let long = "k".repeat(2 << 20);
        let error = error_of(json!({"protocol": 2, long: 1}));
        assert!(error.len() < 400, "{}", error.len());
    }

    /// What SPEC.md documents is accepted, descriptions in `conventions`
    /// included, and `points` is a word (a case with points is refused by
    /// the adapter's capabilities while requests cannot carry them).
    #[test]
    fn every_documented_key_is_accepted() {
        let hello = Hello::parse(&json!({"hello": {
            "protocol": 2, "name": "all", "version": null,
            "capabilities": {
                "primitives": ["triangles", "lines", "polygons", "points"],
                "line_rules": LineRule::NAMES, "fill_rules": FillRule::NAMES,
                "polygon_fills": PolygonFill::NAMES,
                "interpolation": Interpolation::NAMES,
                "sample_patterns": Pattern::NAMES,
                "antialias": true, "max_samples": 16, "max_subpixel_bits": 8,
                "exact_coordinates": false, "depth": true, "attributes": true,
                "motion": true, "coverage_only": false, "coverage_bits": 8,
            },
            "conventions": {"fill_rule": "top-left", "arithmetic": "doubles",
                            "interpolation": "doubles", "ties": "inclusive"},
        }}))
        .unwrap();
        assert_eq!(hello.fill_rule, Some(DeclaredRule::Fill(FillRule::TopLeft)));
        assert_eq!(hello.answers().coverage_bits, Some(8));
    }

    /// A name of 2 MB is quoted at 80 characters.
    #[test]
    fn a_long_name_is_quoted_short() {
        let hello = Hello::parse(&json!({"hello": {
            "protocol": 2, "name": "n".repeat(2 << 20), "version": "v".repeat(1000),
        }}))
        .unwrap();
        let title = hello.title().unwrap();
        assert!(title.len() < 250, "{}", title.len());
        assert!(title.contains("… (2097152 bytes)"), "{title}");
    }
}
