//! The hello of protocol v2 (SPEC.md §12.7): the first line a persistent
//! program writes, before it reads anything, declaring its name, version,
//! capabilities and conventions. A case outside the declared capabilities
//! is unsupported, with the declaration as its reason, and is never sent.
//! A program that sends no hello speaks v1 and is asked everything.

use serde_json::Value;

use crate::plan::Plan;
use crate::scene::{DeclaredRule, FillRule, Interpolation, LineRule, Primitive, Scene};

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
    /// Declared conventions, kept as written; `fill_rule` is judged.
    pub conventions: Option<Value>,
    fill_rule: Option<DeclaredRule>,
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
}

impl Answers {
    /// The declared quantization step of coverage fractions; 0 for none.
    pub fn step(&self) -> f64 {
        self.coverage_bits
            .map_or(0.0, |bits| 1.0 / (2f64.powi(bits as i32) - 1.0))
    }
}

/// The most coverage bits a hello may declare.
const MAX_COVERAGE_BITS: u64 = 24;

/// The protocol versions this rastercheck speaks.
pub const VERSIONS: [u64; 2] = [1, 2];

const PRIMITIVES: [&str; 3] = ["triangles", "lines", "polygons"];

/// Whether a line of output is a hello (an object with a `hello` key).
pub fn is_hello(value: &Value) -> bool {
    value.as_object().is_some_and(|o| o.contains_key("hello"))
}

impl Hello {
    /// Reads `{"hello": {...}}`; the message names the JSON path.
    pub fn parse(value: &Value) -> Result<Hello, String> {
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
        let text = |key: &str| -> Result<Option<String>, String> {
            match hello.get(key) {
                None | Some(Value::Null) => Ok(None),
                Some(Value::String(s)) => Ok(Some(s.clone())),
                Some(_) => Err(format!("$.hello.{key} must be a string")),
            }
        };
        let mut out = Hello {
            protocol,
            name: text("name")?,
            version: text("version")?,
            conventions: hello.get("conventions").cloned(),
            ..Hello::default()
        };
        if let Some(conventions) = &out.conventions {
            let conventions = conventions
                .as_object()
                .ok_or("$.hello.conventions must be an object")?;
            out.fill_rule = match conventions.get("fill_rule") {
                None => None,
                Some(rule) => Some(rule.as_str().and_then(DeclaredRule::from_name).ok_or_else(
                    || {
                        format!(
                            "$.hello.conventions.fill_rule is {rule}; known: {}",
                            DeclaredRule::NAMES.join(", ")
                        )
                    },
                )?),
            };
        }
        let Some(caps) = hello.get("capabilities") else {
            return Ok(out);
        };
        let caps = caps
            .as_object()
            .ok_or("$.hello.capabilities must be an object")?;
        let words = |key: &str, known: &[&str]| -> Result<Option<Vec<String>>, String> {
            let Some(v) = caps.get(key) else {
                return Ok(None);
            };
            let list = v
                .as_array()
                .ok_or_else(|| format!("$.hello.capabilities.{key} must be a list of words"))?;
            list.iter()
                .enumerate()
                .map(|(i, w)| {
                    let w = w.as_str().ok_or_else(|| {
                        format!("$.hello.capabilities.{key}[{i}] must be a string")
                    })?;
                    if known.contains(&w) {
                        Ok(w.to_owned())
                    } else {
                        Err(format!(
                            "$.hello.capabilities.{key}[{i}] is {w:?}; known: {}",
                            known.join(", ")
                        ))
                    }
                })
                .collect::<Result<Vec<_>, _>>()
                .map(Some)
        };
        let flag = |key: &str| -> Result<Option<bool>, String> {
            match caps.get(key) {
                None => Ok(None),
                Some(Value::Bool(b)) => Ok(Some(*b)),
                Some(_) => Err(format!("$.hello.capabilities.{key} must be true or false")),
            }
        };
        let count = |key: &str| -> Result<Option<u64>, String> {
            match caps.get(key) {
                None => Ok(None),
                Some(v) => v
                    .as_u64()
                    .map(Some)
                    .ok_or_else(|| format!("$.hello.capabilities.{key} must be a whole number")),
            }
        };
        use crate::scene::{Pattern, PolygonFill};
        out.primitives = words("primitives", &PRIMITIVES)?;
        out.line_rules = words("line_rules", &LineRule::NAMES)?;
        out.fill_rules = words("fill_rules", &FillRule::NAMES)?;
        out.polygon_fills = words("polygon_fills", &PolygonFill::NAMES)?;
        out.interpolation = words("interpolation", &Interpolation::NAMES)?;
        out.sample_patterns = words("sample_patterns", &Pattern::NAMES)?;
        out.antialias = flag("antialias")?;
        out.max_samples = count("max_samples")?;
        out.max_subpixel_bits = count("max_subpixel_bits")?;
        out.exact_coordinates = flag("exact_coordinates")?;
        out.depth = flag("depth")?;
        out.attributes = flag("attributes")?;
        out.coverage_only = flag("coverage_only")?;
        out.coverage_bits = count("coverage_bits")?;
        if out
            .coverage_bits
            .is_some_and(|b| !(1..=MAX_COVERAGE_BITS).contains(&b))
        {
            return Err(format!(
                "$.hello.capabilities.coverage_bits must be from 1 to {MAX_COVERAGE_BITS}"
            ));
        }
        out.motion = flag("motion")?;
        Ok(out)
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
            if lacks(&self.primitives, kind) {
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
        }
    }

    /// The program as its hello names it: `name version`, or `None`.
    pub fn title(&self) -> Option<String> {
        let name = self.name.as_deref()?;
        Some(match &self.version {
            Some(v) => format!("{name} {v}"),
            None => name.to_owned(),
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
}
