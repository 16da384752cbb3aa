//! Reading a case file into a [`Scene`], with errors that name the file and
//! the JSON path of the offending value.
//!
//! The file is parsed into a `serde_json::Value` (with `arbitrary_precision`,
//! so every number keeps the text it was written as) and then walked by hand.
//! Walking by hand, rather than deriving `Deserialize`, is what lets every
//! error carry its JSON path, suggest the field that was meant, and read
//! numbers exactly.

use std::fmt;

use serde_json::{Map, Value};

use super::number::Number;
use super::rules::{
    limits, Cull, FillRule, Interpolation, LastPixel, LineParameter, LineRule, PolygonFill, Rules,
};
use super::samples::{Antialias, Pattern};
use super::time::{MotionBlur, TimePattern};
use super::{Canvas, Effects, Expect, Line, Polygon, Primitive, Scene, TimePin, Triangle, Vertex};

/// Resource limits that a run may tighten or relax (SPEC.md, "Limits").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    pub max_canvas_pixels: u64,
    pub max_primitives: usize,
    /// Sample points per case: pixels × spatial samples × time samples
    /// (the last only when something moves). It bounds the frames'
    /// memory and the work of each primitive.
    pub max_samples: u64,
    /// Wall time each rasterizer (the reference, then each candidate) may
    /// spend on one case; `None` for no limit. Not a property of the file:
    /// the reader ignores it, the runner enforces it ([`crate::deadline`]).
    pub case_timeout: Option<std::time::Duration>,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_canvas_pixels: limits::DEFAULT_MAX_CANVAS_PIXELS,
            max_primitives: limits::DEFAULT_MAX_PRIMITIVES,
            max_samples: limits::DEFAULT_MAX_SAMPLES,
            case_timeout: Some(limits::DEFAULT_CASE_TIMEOUT),
        }
    }
}

/// A case that cannot be read: where, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CaseError {
    /// The case file, as given to the loader.
    pub file: String,
    /// JSON path of the offending value (`$.primitives[2].triangle[0]`), or
    /// `line L column C` for a syntax error.
    pub location: String,
    pub message: String,
}

impl fmt::Display for CaseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}: {}", self.file, self.location, self.message)
    }
}

impl std::error::Error for CaseError {}

/// Reads the text of one case file. `file` names it in errors.
pub fn parse_case(text: &str, file: &str, limits: &Limits) -> Result<Scene, CaseError> {
    let value: Value = serde_json::from_str(text).map_err(|e| CaseError {
        file: file.to_owned(),
        location: format!("line {} column {}", e.line(), e.column()),
        message: format!("invalid JSON: {}", strip_position(&e.to_string())),
    })?;
    let reader = Reader { limits };
    reader.scene(&value).map_err(|(path, message)| CaseError {
        file: file.to_owned(),
        location: path.to_string(),
        message,
    })
}

fn strip_position(message: &str) -> &str {
    message.find(" at line ").map_or(message, |i| &message[..i])
}

/// A JSON path under construction, e.g. `$.primitives[3].triangle[1]`.
#[derive(Clone, Debug)]
struct Path(String);

impl Path {
    fn root() -> Path {
        Path("$".to_owned())
    }
    fn key(&self, key: &str) -> Path {
        Path(format!("{}.{key}", self.0))
    }
    fn index(&self, i: usize) -> Path {
        Path(format!("{}[{i}]", self.0))
    }
}

impl fmt::Display for Path {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

type Fail = (Path, String);
type Result<T, E = Fail> = std::result::Result<T, E>;

fn fail<T>(path: &Path, message: impl Into<String>) -> Result<T> {
    Err((path.clone(), message.into()))
}

fn kind(value: &Value) -> &'static str {
    match value {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// An object's fields, checked against the names a section allows.
struct Fields<'a> {
    map: &'a Map<String, Value>,
    path: Path,
}

impl<'a> Fields<'a> {
    fn new(value: &'a Value, path: &Path, allowed: &[&str]) -> Result<Fields<'a>> {
        let Value::Object(map) = value else {
            return fail(path, format!("expected an object, found {}", kind(value)));
        };
        for key in map.keys() {
            if key.starts_with("//") || allowed.contains(&key.as_str()) {
                continue;
            }
            let hint = match closest(key, allowed) {
                Some(name) => format!("; did you mean \"{name}\"?"),
                None => format!("; expected one of {}", allowed.join(", ")),
            };
            return fail(&path.key(key), format!("unknown field \"{key}\"{hint}"));
        }
        Ok(Fields {
            map,
            path: path.clone(),
        })
    }

    fn get(&self, key: &str) -> Option<(&'a Value, Path)> {
        self.map.get(key).map(|v| (v, self.path.key(key)))
    }

    fn require(&self, key: &str) -> Result<(&'a Value, Path)> {
        self.get(key)
            .ok_or_else(|| (self.path.clone(), format!("missing field \"{key}\"")))
    }
}

/// The allowed name nearest to `key`, if it is plausibly a misspelling.
fn closest<'n>(key: &str, allowed: &[&'n str]) -> Option<&'n str> {
    allowed
        .iter()
        .map(|name| (edit_distance(key, name), *name))
        .filter(|(d, name)| *d <= 2.max(name.len() / 3))
        .min()
        .map(|(_, name)| name)
}

fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let above = row[j + 1];
            row[j + 1] = (above + 1)
                .min(row[j] + 1)
                .min(diagonal + usize::from(ca != *cb));
            diagonal = above;
        }
    }
    row[b.len()]
}

fn string<'v>(value: &'v Value, path: &Path) -> Result<&'v str> {
    value.as_str().ok_or_else(|| {
        (
            path.clone(),
            format!("expected a string, found {}", kind(value)),
        )
    })
}

fn array<'v>(value: &'v Value, path: &Path) -> Result<&'v Vec<Value>> {
    value.as_array().ok_or_else(|| {
        (
            path.clone(),
            format!("expected an array, found {}", kind(value)),
        )
    })
}

fn boolean(value: &Value, path: &Path) -> Result<bool> {
    value.as_bool().ok_or_else(|| {
        (
            path.clone(),
            format!("expected true or false, found {}", kind(value)),
        )
    })
}

/// An exact number: a JSON number read as its decimal text, or a string
/// holding a fraction or decimal.
fn number(value: &Value, path: &Path) -> Result<Number> {
    let parsed = match value {
        Value::Number(n) => Number::from_decimal(n.as_str()),
        Value::String(s) => Number::from_string(s),
        other => {
            return fail(
                path,
                format!(
                    "expected a number or a fraction string, found {}",
                    kind(other)
                ),
            )
        }
    };
    parsed.map_err(|e| (path.clone(), e.to_string()))
}

/// A non-negative integer no larger than `max`.
fn count(value: &Value, path: &Path, max: u64) -> Result<u64> {
    let n = number(value, path)?;
    if !n.is_integer() || n < Number::ZERO {
        return fail(path, format!("expected a whole number ≥ 0, found {n}"));
    }
    if n > Number::from_int(max as i64) {
        return fail(path, format!("{n} is larger than the limit {max}"));
    }
    Ok(n.numerator()
        .to_string()
        .parse()
        .expect("a bounded integer"))
}

fn within(n: &Number, path: &Path, low: &Number, high: &Number, what: &str) -> Result<()> {
    if n < low || n > high {
        return fail(
            path,
            format!("{what} {n} is outside the documented range [{low}, {high}]"),
        );
    }
    Ok(())
}

fn named<T>(value: &Value, path: &Path, parse: fn(&str) -> Option<T>, names: &[&str]) -> Result<T> {
    let s = string(value, path)?;
    parse(s).ok_or_else(|| {
        let hint = match closest(s, names) {
            Some(name) => format!("; did you mean \"{name}\"?"),
            None => String::new(),
        };
        (
            path.clone(),
            format!("\"{s}\" is not one of {}{hint}", names.join(", ")),
        )
    })
}

struct Reader<'a> {
    limits: &'a Limits,
}

impl Reader<'_> {
    fn scene(&self, value: &Value) -> Result<Scene> {
        let root = Path::root();
        let fields = Fields::new(
            value,
            &root,
            &[
                "name",
                "description",
                "canvas",
                "rules",
                "primitives",
                "effects",
                "expect",
            ],
        )?;
        let (name, name_path) = fields.require("name")?;
        let name = string(name, &name_path)?.to_owned();
        if name.trim().is_empty() {
            return fail(&name_path, "the case name is empty");
        }
        let description = match fields.get("description") {
            Some((v, p)) => string(v, &p)?.to_owned(),
            None => String::new(),
        };
        let (canvas, canvas_path) = fields.require("canvas")?;
        let canvas = self.canvas(canvas, &canvas_path)?;
        let rules = match fields.get("rules") {
            Some((v, p)) => self.rules(v, &p)?,
            None => Rules::default(),
        };
        let (primitives, primitives_path) = fields.require("primitives")?;
        let primitives = self.primitives(primitives, &primitives_path)?;
        let effects = match fields.get("effects") {
            Some((v, p)) => self.effects(v, &p)?,
            None => Effects::default(),
        };
        let expect = match fields.get("expect") {
            Some((v, p)) => self.expect(v, &p)?,
            None => Expect::default(),
        };
        let attribute_count = primitives
            .first()
            .map_or(0, |p| p.vertices()[0].attributes.len());
        let has_depth = fields
            .map
            .get("primitives")
            .and_then(Value::as_array)
            .is_some_and(|ps| ps.iter().any(mentions_depth));
        let scene = Scene {
            name,
            description,
            canvas,
            rules,
            primitives,
            effects,
            expect,
            attribute_count,
            has_depth,
        };
        self.check_attribute_counts(&scene, &primitives_path)?;
        self.check_combinations(&scene, &fields)?;
        self.check_samples(&scene)?;
        Ok(scene)
    }

    /// Pixels × spatial samples × time samples within `max_samples`; time
    /// samples count only when something moves (otherwise no time loop
    /// runs, SPEC.md §15.1).
    fn check_samples(&self, scene: &Scene) -> Result<()> {
        let pixels = u64::from(scene.canvas.width) * u64::from(scene.canvas.height);
        let spatial = scene.effects.antialias.as_ref().map_or(1, |a| a.samples);
        let time = match &scene.effects.motion_blur {
            Some(blur) if scene.moves() => blur.samples,
            _ => 1,
        };
        // At most 2^28 · 2^8 · 2^10: no overflow.
        let total = pixels * u64::from(spatial) * u64::from(time);
        if total <= self.limits.max_samples {
            return Ok(());
        }
        let effects = Path::root().key("effects");
        let (path, factors) = match (spatial, time) {
            (1, 1) => (Path::root().key("canvas"), String::new()),
            (s, 1) => (
                effects.key("antialias").key("samples"),
                format!(" × {s} samples"),
            ),
            (1, t) => (
                effects.key("motion_blur").key("samples"),
                format!(" × {t} time samples"),
            ),
            (s, t) => (
                effects.key("motion_blur").key("samples"),
                format!(" × {s} samples × {t} time samples"),
            ),
        };
        fail(
            &path,
            format!(
                "{pixels} pixels{factors} = {total} sample points exceed the limit of {} (raise it with --max-samples)",
                self.limits.max_samples
            ),
        )
    }

    /// Rules, primitives, effects and expectations that are each valid
    /// alone but not together.
    fn check_combinations(&self, scene: &Scene, fields: &Fields) -> Result<()> {
        let primitives_path = Path::root().key("primitives");
        if scene.rules.fill_rule == FillRule::AllEdges {
            if let Some(i) = scene
                .primitives
                .iter()
                .position(|p| matches!(p, Primitive::Polygon(_)))
            {
                return fail(
                    &primitives_path.index(i),
                    "a polygon needs one of the four consistent tie rules (top-left, top-right, bottom-left, bottom-right), not all-edges",
                );
            }
        }
        let antialias = scene.effects.antialias.is_some();
        if antialias {
            for (i, primitive) in scene.primitives.iter().enumerate() {
                let Primitive::Line(line) = primitive else {
                    continue;
                };
                let why = match line.rule {
                    LineRule::Midpoint | LineRule::DiamondExit => format!(
                        "a {} line chooses whole pixels and has no samples; antialiasing samples triangles, polygons and parallelogram lines",
                        line.rule.name()
                    ),
                    LineRule::Rectangle => "a rectangle line has irrational corners, so its exact area coverage is not a rational number; antialias parallelogram lines".to_owned(),
                    LineRule::Parallelogram => continue,
                };
                return fail(&primitives_path.index(i), why);
            }
        }
        self.check_motion(scene, fields)?;
        if !antialias {
            let e = &scene.expect;
            let given = [
                ("max_coverage_error", e.max_coverage_error.is_some()),
                ("max_coverage_rms", e.max_coverage_rms.is_some()),
                ("area", e.area.is_some()),
            ];
            if let (Some((key, _)), Some((_, expect_path))) =
                (given.iter().find(|(_, g)| *g), fields.get("expect"))
            {
                return fail(
                    &expect_path.key(key),
                    format!(
                        "{key} measures antialiased coverage; the case needs effects.antialias"
                    ),
                );
            }
        }
        Ok(())
    }

    /// Moving primitives need `effects.motion_blur`, move only as triangles
    /// and parallelogram lines, and carry positions only; time expectations
    /// need something that moves (SPEC.md §15).
    fn check_motion(&self, scene: &Scene, fields: &Fields) -> Result<()> {
        let primitives_path = Path::root().key("primitives");
        let moving = scene.primitives.iter().position(Primitive::moves);
        if let Some(i) = moving {
            let path = primitives_path.index(i);
            let primitive = &scene.primitives[i];
            if scene.effects.motion_blur.is_none() {
                return fail(
                    &path,
                    "this primitive moves (a vertex gives from and to), so the case needs effects.motion_blur",
                );
            }
            for (i, primitive) in scene.primitives.iter().enumerate() {
                if !primitive.moves() {
                    continue;
                }
                let why = match primitive {
                    Primitive::Polygon(_) => "a polygon cannot move in this version of rastercheck; move triangles or parallelogram lines",
                    Primitive::Line(line) if line.rule != LineRule::Parallelogram => "only parallelogram lines can move in this version of rastercheck (a midpoint or diamond-exit line chooses whole pixels at each instant, and a rectangle's corners are irrational)",
                    _ => continue,
                };
                return fail(&primitives_path.index(i), why);
            }
            let valued = scene.has_depth
                || scene.attribute_count > 0
                || scene.vertices().any(|v| v.w != Number::ONE);
            if valued {
                return fail(
                    &path.key(primitive.kind()),
                    "a scene in which something moves is judged on time coverage only: z, w and attributes are not supported with motion in this version of rastercheck",
                );
            }
            if let (Some(key), Some((_, expect_path))) = (
                scene.expect.sample_expectations().first(),
                fields.get("expect"),
            ) {
                return fail(
                    &expect_path.key(key),
                    format!("expect.{key} measures samples; a scene in which something moves is judged on time coverage only (max_time_error, max_time_rms, time_coverage)"),
                );
            }
            if scene.rules.subpixel_bits.is_none() {
                return fail(
                    &Path::root().key("rules").key("subpixel_bits"),
                    "moving vertices snap at shutter open and close: a moving scene needs subpixel_bits",
                );
            }
        }
        let e = &scene.expect;
        let given = [
            ("max_time_error", e.max_time_error.is_some()),
            ("max_time_rms", e.max_time_rms.is_some()),
            ("time_coverage", !e.time_coverage.is_empty()),
        ];
        if let (Some((key, _)), Some((_, expect_path))) =
            (given.iter().find(|(_, g)| *g), fields.get("expect"))
        {
            if moving.is_none() {
                return fail(
                    &expect_path.key(key),
                    format!("{key} measures time coverage; the case needs a primitive that moves and effects.motion_blur"),
                );
            }
        }
        for (i, pin) in e.time_coverage.iter().enumerate() {
            let [x, y] = pin.pixel;
            if x >= scene.canvas.width || y >= scene.canvas.height {
                let path = fields.get("expect").map_or(Path::root(), |(_, p)| p);
                return fail(
                    &path.key("time_coverage").index(i).key("pixel"),
                    format!(
                        "pixel ({x}, {y}) is outside the {}×{} canvas",
                        scene.canvas.width, scene.canvas.height
                    ),
                );
            }
        }
        Ok(())
    }

    fn canvas(&self, value: &Value, path: &Path) -> Result<Canvas> {
        let fields = Fields::new(value, path, &["width", "height"])?;
        let side = |key: &str| -> Result<u32> {
            let (v, p) = fields.require(key)?;
            let n = count(v, &p, u64::MAX >> 1)?;
            if n == 0 || n > u64::from(limits::MAX_CANVAS_SIDE) {
                return fail(
                    &p,
                    format!(
                        "canvas {key} {n} is outside [1, {}]",
                        limits::MAX_CANVAS_SIDE
                    ),
                );
            }
            Ok(n as u32)
        };
        let canvas = Canvas {
            width: side("width")?,
            height: side("height")?,
        };
        let pixels = canvas.pixel_count() as u64;
        if pixels > self.limits.max_canvas_pixels {
            return fail(
                path,
                format!(
                    "canvas of {pixels} pixels exceeds the limit of {} (raise it with --max-canvas-pixels)",
                    self.limits.max_canvas_pixels
                ),
            );
        }
        Ok(canvas)
    }

    fn rules(&self, value: &Value, path: &Path) -> Result<Rules> {
        let fields = Fields::new(value, path, &["subpixel_bits", "fill_rule", "cull"])?;
        let mut rules = Rules::default();
        if let Some((v, p)) = fields.get("subpixel_bits") {
            rules.subpixel_bits = match v {
                Value::Null => None,
                _ => {
                    let bits = count(v, &p, u64::MAX >> 1)?;
                    if bits > u64::from(limits::MAX_SUBPIXEL_BITS) {
                        return fail(
                            &p,
                            format!(
                                "subpixel_bits {bits} exceeds the limit of {}",
                                limits::MAX_SUBPIXEL_BITS
                            ),
                        );
                    }
                    Some(bits as u32)
                }
            };
        }
        if let Some((v, p)) = fields.get("fill_rule") {
            let names: Vec<&str> = FillRule::ALL.iter().map(|r| r.name()).collect();
            rules.fill_rule = named(v, &p, FillRule::from_name, &names)?;
        }
        if let Some((v, p)) = fields.get("cull") {
            rules.cull = named(v, &p, Cull::from_name, &["none", "cw", "ccw"])?;
        }
        Ok(rules)
    }

    fn primitives(&self, value: &Value, path: &Path) -> Result<Vec<Primitive>> {
        let items = array(value, path)?;
        if items.is_empty() {
            return fail(
                path,
                "the primitive list is empty; a case draws at least one primitive",
            );
        }
        if items.len() > self.limits.max_primitives {
            return fail(
                path,
                format!(
                    "{} primitives exceed the limit of {} (raise it with --max-primitives)",
                    items.len(),
                    self.limits.max_primitives
                ),
            );
        }
        items
            .iter()
            .enumerate()
            .map(|(i, item)| self.primitive(item, &path.index(i)))
            .collect()
    }

    fn primitive(&self, value: &Value, path: &Path) -> Result<Primitive> {
        if value.get("line").is_some() {
            return self.line(value, path);
        }
        if value.get("polygon").is_some() || value.get("contours").is_some() {
            return self.polygon(value, path);
        }
        let fields = Fields::new(value, path, &["triangle", "interpolation"])?;
        let (vertices, vertices_path) = fields.require("triangle")?;
        let list = array(vertices, &vertices_path)?;
        if list.len() != 3 {
            return fail(
                &vertices_path,
                format!("a triangle has 3 vertices, found {}", list.len()),
            );
        }
        let v = |i: usize| self.vertex(&list[i], &vertices_path.index(i));
        let vertices = [v(0)?, v(1)?, v(2)?];
        let interpolation = self.interpolation(&fields)?;
        Ok(Primitive::Triangle(Triangle {
            vertices,
            interpolation,
        }))
    }

    fn interpolation(&self, fields: &Fields) -> Result<Interpolation> {
        match fields.get("interpolation") {
            Some((v, p)) => named(
                v,
                &p,
                Interpolation::from_name,
                &["perspective", "linear", "flat"],
            ),
            None => Ok(Interpolation::Perspective),
        }
    }

    fn line(&self, value: &Value, path: &Path) -> Result<Primitive> {
        let fields = Fields::new(
            value,
            path,
            &[
                "line",
                "rule",
                "width",
                "last_pixel",
                "parameter",
                "interpolation",
            ],
        )?;
        let (vertices, vertices_path) = fields.require("line")?;
        let list = array(vertices, &vertices_path)?;
        if list.len() != 2 {
            return fail(
                &vertices_path,
                format!("a line has 2 vertices, found {}", list.len()),
            );
        }
        let v = |i: usize| self.vertex(&list[i], &vertices_path.index(i));
        let vertices = [v(0)?, v(1)?];
        let rule = match fields.get("rule") {
            Some((v, p)) => named(
                v,
                &p,
                LineRule::from_name,
                &["midpoint", "rectangle", "parallelogram"],
            )?,
            None => LineRule::Midpoint,
        };
        let width = match fields.get("width") {
            Some((v, p)) => {
                if !rule.is_wide() {
                    return fail(
                        &p,
                        format!(
                            "a {} line has no width; only rectangle and parallelogram lines do",
                            rule.name()
                        ),
                    );
                }
                let w = number(v, &p)?;
                if !w.is_positive() {
                    return fail(&p, format!("a line width must be positive, found {w}"));
                }
                within(
                    &w,
                    &p,
                    &Number::ZERO,
                    &Number::from_int(limits::MAX_LINE_WIDTH),
                    "width",
                )?;
                w
            }
            None => Number::ONE,
        };
        let last_pixel = match fields.get("last_pixel") {
            Some((v, p)) => {
                if rule != LineRule::Midpoint {
                    return fail(&p, "last_pixel applies to midpoint lines only");
                }
                named(v, &p, LastPixel::from_name, &["include", "exclude"])?
            }
            None => LastPixel::Include,
        };
        let parameter = match fields.get("parameter") {
            Some((v, p)) => named(v, &p, LineParameter::from_name, &["major", "projected"])?,
            None => LineParameter::Major,
        };
        let interpolation = self.interpolation(&fields)?;
        Ok(Primitive::Line(Line {
            vertices,
            rule,
            width,
            last_pixel,
            parameter,
            interpolation,
        }))
    }

    /// `{"polygon": [[x, y], ...]}` for one contour, or
    /// `{"contours": [[[x, y], ...], ...]}` for several; `"fill"` is
    /// `nonzero` (the default) or `even-odd`.
    fn polygon(&self, value: &Value, path: &Path) -> Result<Primitive> {
        let fields = Fields::new(value, path, &["polygon", "contours", "fill"])?;
        let contours: Vec<(Vec<Value>, Path)> =
            match (fields.get("polygon"), fields.get("contours")) {
                (Some(_), Some((_, p))) => {
                    return fail(
                        &p,
                        "give either polygon (one contour) or contours (several), not both",
                    )
                }
                (Some((v, p)), None) => vec![(array(v, &p)?.clone(), p)],
                (None, Some((v, p))) => {
                    let list = array(v, &p)?;
                    if list.is_empty() {
                        return fail(&p, "a polygon has at least one contour");
                    }
                    list.iter()
                        .enumerate()
                        .map(|(i, c)| Ok((array(c, &p.index(i))?.clone(), p.index(i))))
                        .collect::<Result<_>>()?
                }
                (None, None) => unreachable!("called for polygon or contours"),
            };
        let mut vertices = Vec::new();
        let mut contour_ends = Vec::new();
        for (list, contour_path) in &contours {
            if list.len() < 3 {
                return fail(
                    contour_path,
                    format!("a contour has at least 3 vertices, found {}", list.len()),
                );
            }
            for (j, item) in list.iter().enumerate() {
                let (x, y) = match item {
                    Value::Array(_) => self.position(item, &contour_path.index(j))?,
                    Value::Object(map) if map.contains_key("from") || map.contains_key("to") => {
                        return fail(
                            &contour_path.index(j),
                            "a polygon cannot move in this version of rastercheck; move triangles or parallelogram lines",
                        );
                    }
                    _ => {
                        return fail(
                            &contour_path.index(j),
                            format!(
                                "a polygon vertex is a position [x, y] (polygons carry no depth or attributes), found {}",
                                kind(item)
                            ),
                        )
                    }
                };
                vertices.push(Vertex::at(x, y));
            }
            if vertices.len() > limits::MAX_POLYGON_VERTICES {
                return fail(
                    contour_path,
                    format!(
                        "the polygon has more than {} vertices",
                        limits::MAX_POLYGON_VERTICES
                    ),
                );
            }
            contour_ends.push(vertices.len());
        }
        let fill = match fields.get("fill") {
            Some((v, p)) => named(v, &p, PolygonFill::from_name, &["nonzero", "even-odd"])?,
            None => PolygonFill::NonZero,
        };
        Ok(Primitive::Polygon(Polygon {
            vertices,
            contour_ends,
            fill,
        }))
    }

    fn vertex(&self, value: &Value, path: &Path) -> Result<Vertex> {
        match value {
            Value::Array(_) => {
                let (x, y) = self.position(value, path)?;
                Ok(Vertex::at(x, y))
            }
            Value::Object(_) => {
                let fields = Fields::new(
                    value,
                    path,
                    &["position", "from", "to", "z", "w", "attributes"],
                )?;
                let mut vertex = self.moving_position(&fields, path)?;
                let value_limit = Number::from_int(limits::VALUE_LIMIT);
                if let Some((v, p)) = fields.get("z") {
                    vertex.z = number(v, &p)?;
                    within(&vertex.z, &p, &-value_limit.clone(), &value_limit, "z")?;
                }
                if let Some((v, p)) = fields.get("w") {
                    let w = number(v, &p)?;
                    if !w.is_positive() {
                        return fail(&p, format!("w must be positive, found {w}; vertices behind the eye must be clipped before rasterization"));
                    }
                    within(
                        &w,
                        &p,
                        &Number::ratio(1, limits::W_LIMIT),
                        &Number::from_int(limits::W_LIMIT),
                        "w",
                    )?;
                    vertex.w = w;
                }
                if let Some((v, p)) = fields.get("attributes") {
                    let items = array(v, &p)?;
                    if items.len() > limits::MAX_ATTRIBUTES {
                        return fail(
                            &p,
                            format!(
                                "{} attributes exceed the limit of {}",
                                items.len(),
                                limits::MAX_ATTRIBUTES
                            ),
                        );
                    }
                    for (i, item) in items.iter().enumerate() {
                        let a = number(item, &p.index(i))?;
                        within(
                            &a,
                            &p.index(i),
                            &-value_limit.clone(),
                            &value_limit,
                            "attribute",
                        )?;
                        vertex.attributes.push(a);
                    }
                }
                Ok(vertex)
            }
            other => fail(
                path,
                format!(
                    "expected a vertex ([x, y] or {{\"position\": [x, y], ...}}), found {}",
                    kind(other)
                ),
            ),
        }
    }

    /// `position`, or `from` and `to` for a moving vertex (SPEC.md §15.1).
    fn moving_position(&self, fields: &Fields, path: &Path) -> Result<Vertex> {
        match (fields.get("position"), fields.get("from"), fields.get("to")) {
            (Some((v, p)), None, None) => {
                let (x, y) = self.position(v, &p)?;
                Ok(Vertex::at(x, y))
            }
            (None, Some((from, from_path)), Some((to, to_path))) => {
                let (x, y) = self.position(from, &from_path)?;
                let (to_x, to_y) = self.position(to, &to_path)?;
                Ok(Vertex {
                    to: Some(Box::new([to_x, to_y])),
                    ..Vertex::at(x, y)
                })
            }
            (Some((_, p)), _, _) => fail(
                &p,
                "a vertex gives either position or from and to (a moving vertex), not both",
            ),
            (None, Some(_), None) => fail(
                &path.key("to"),
                "a moving vertex gives both from and to; this one has no to",
            ),
            (None, None, Some(_)) => fail(
                &path.key("from"),
                "a moving vertex gives both from and to; this one has no from",
            ),
            (None, None, None) => fail(
                &path.key("position"),
                "missing required field (a vertex gives position, or from and to)",
            ),
        }
    }

    fn position(&self, value: &Value, path: &Path) -> Result<(Number, Number)> {
        let items = array(value, path)?;
        if items.len() != 2 {
            return fail(
                path,
                format!("a position is [x, y], found {} values", items.len()),
            );
        }
        let limit = Number::from_int(limits::COORD_LIMIT);
        let x = number(&items[0], &path.index(0))?;
        within(&x, &path.index(0), &-limit.clone(), &limit, "coordinate")?;
        let y = number(&items[1], &path.index(1))?;
        within(&y, &path.index(1), &-limit.clone(), &limit, "coordinate")?;
        Ok((x, y))
    }

    fn effects(&self, value: &Value, path: &Path) -> Result<Effects> {
        let fields = Fields::new(value, path, &["antialias", "motion_blur"])?;
        let antialias = match fields.get("antialias") {
            Some((v, p)) => Some(self.antialias(v, &p)?),
            None => None,
        };
        let motion_blur = match fields.get("motion_blur") {
            Some((v, p)) => Some(self.motion_blur(v, &p)?),
            None => None,
        };
        Ok(Effects {
            antialias,
            motion_blur,
        })
    }

    fn motion_blur(&self, value: &Value, path: &Path) -> Result<MotionBlur> {
        use super::time::limits as mb;
        let fields = Fields::new(value, path, &["shutter", "samples", "pattern", "seed"])?;
        let shutter = match fields.get("shutter") {
            Some((v, p)) => {
                let items = array(v, &p)?;
                if items.len() != 2 {
                    return fail(
                        &p,
                        format!("a shutter is [open, close], found {} values", items.len()),
                    );
                }
                let mut ends = [0u32; 2];
                for (i, item) in items.iter().enumerate() {
                    let t = number(item, &p.index(i))?;
                    within(&t, &p.index(i), &Number::ZERO, &Number::ONE, "shutter time")?;
                    let units = t.as_rbig() * dashu_ratio::RBig::from(mb::TIME_ONE);
                    if units.denominator() != &dashu_int::UBig::ONE {
                        return fail(
                            &p.index(i),
                            format!("shutter time {t} is not a multiple of 2^-{} (1/{}); shutter times are exact in 16-bit fixed point", mb::TIME_BITS, mb::TIME_ONE),
                        );
                    }
                    ends[i] = units.to_f64().value() as u32;
                }
                if ends[0] >= ends[1] {
                    return fail(&p, "the shutter opens before it closes: open < close");
                }
                ends
            }
            None => [0, mb::TIME_ONE],
        };
        let (v, samples_path) = fields.require("samples")?;
        let samples = count(v, &samples_path, u64::MAX >> 1)?;
        if samples == 0 || samples > u64::from(mb::MAX_SAMPLES) {
            return fail(
                &samples_path,
                format!("samples {samples} is outside [1, {}]", mb::MAX_SAMPLES),
            );
        }
        let pattern = match fields.get("pattern") {
            Some((v, p)) => {
                let names: Vec<&str> = TimePattern::ALL.iter().map(|p| p.name()).collect();
                named(v, &p, TimePattern::from_name, &names)?
            }
            None => TimePattern::Stratified,
        };
        let seed = match fields.get("seed") {
            Some((v, p)) => count(v, &p, u64::MAX >> 1)?,
            None => 0,
        };
        Ok(MotionBlur {
            shutter,
            samples: samples as u32,
            pattern,
            seed,
        })
    }

    fn antialias(&self, value: &Value, path: &Path) -> Result<Antialias> {
        use super::samples::limits as aa;
        let fields = Fields::new(
            value,
            path,
            &[
                "samples",
                "pattern",
                "seed",
                "adaptive",
                "resolve",
                "position_bits",
            ],
        )?;
        let (v, samples_path) = fields.require("samples")?;
        let samples = count(v, &samples_path, u64::MAX >> 1)?;
        if samples == 0 || samples > u64::from(aa::MAX_SAMPLES) {
            return fail(
                &samples_path,
                format!("samples {samples} is outside [1, {}]", aa::MAX_SAMPLES),
            );
        }
        let samples = samples as u32;
        let pattern = match fields.get("pattern") {
            Some((v, p)) => {
                let names: Vec<&str> = Pattern::ALL.iter().map(|p| p.name()).collect();
                named(v, &p, Pattern::from_name, &names)?
            }
            None => Pattern::Standard,
        };
        if let Err(why) = pattern.check_count(samples) {
            return fail(&samples_path, why);
        }
        let seed = match fields.get("seed") {
            Some((v, p)) => count(v, &p, u64::MAX >> 1)?,
            None => 0,
        };
        let adaptive = match fields.get("adaptive") {
            Some((v, p)) => boolean(v, &p)?,
            None => false,
        };
        if let Some((v, p)) = fields.get("resolve") {
            named(v, &p, |n| (n == "box").then_some(()), &["box"])?;
        }
        let position_bits = match fields.get("position_bits") {
            Some((v, p)) => {
                let bits = count(v, &p, u64::MAX >> 1)?;
                if bits < u64::from(aa::MIN_POSITION_BITS)
                    || bits > u64::from(aa::MAX_POSITION_BITS)
                {
                    return fail(
                        &p,
                        format!(
                            "position_bits {bits} is outside [{}, {}]",
                            aa::MIN_POSITION_BITS,
                            aa::MAX_POSITION_BITS
                        ),
                    );
                }
                bits as u32
            }
            None => aa::DEFAULT_POSITION_BITS,
        };
        Ok(Antialias {
            samples,
            pattern,
            seed,
            adaptive,
            position_bits,
        })
    }

    fn expect(&self, value: &Value, path: &Path) -> Result<Expect> {
        let fields = Fields::new(
            value,
            path,
            &[
                "max_mismatched_samples",
                "watertight",
                "samples_covered",
                "max_abs_error",
                "max_ulp_error",
                "max_coverage_error",
                "max_coverage_rms",
                "area",
                "max_time_error",
                "max_time_rms",
                "time_coverage",
            ],
        )?;
        let mut expect = Expect::default();
        if let Some((v, p)) = fields.get("max_mismatched_samples") {
            expect.max_mismatched_samples = count(v, &p, u64::MAX >> 1)?;
        }
        if let Some((v, p)) = fields.get("watertight") {
            expect.watertight = boolean(v, &p)?;
        }
        if let Some((v, p)) = fields.get("samples_covered") {
            expect.samples_covered = Some(count(v, &p, u64::MAX >> 1)?);
        }
        let tolerance = |key: &str| -> Result<Option<f64>> {
            let Some((v, p)) = fields.get(key) else {
                return Ok(None);
            };
            let n = number(v, &p)?;
            if n < Number::ZERO {
                return fail(&p, format!("{key} must be ≥ 0, found {n}"));
            }
            within(
                &n,
                &p,
                &Number::ZERO,
                &Number::from_int(limits::VALUE_LIMIT),
                key,
            )?;
            Ok(Some(n.to_f64_lossy()))
        };
        expect.max_abs_error = tolerance("max_abs_error")?;
        expect.max_ulp_error = tolerance("max_ulp_error")?;
        expect.max_coverage_error = tolerance("max_coverage_error")?;
        expect.max_coverage_rms = tolerance("max_coverage_rms")?;
        expect.max_time_error = tolerance("max_time_error")?;
        expect.max_time_rms = tolerance("max_time_rms")?;
        if let Some((v, p)) = fields.get("time_coverage") {
            for (i, item) in array(v, &p)?.iter().enumerate() {
                let item_path = p.index(i);
                let pin = Fields::new(item, &item_path, &["pixel", "value"])?;
                let (pixel, pixel_path) = pin.require("pixel")?;
                let xy = array(pixel, &pixel_path)?;
                if xy.len() != 2 {
                    return fail(
                        &pixel_path,
                        format!("a pixel is [x, y], found {} values", xy.len()),
                    );
                }
                let x = count(&xy[0], &pixel_path.index(0), u64::from(u32::MAX))? as u32;
                let y = count(&xy[1], &pixel_path.index(1), u64::from(u32::MAX))? as u32;
                let (value, value_path) = pin.require("value")?;
                let value = number(value, &value_path)?;
                if value < Number::ZERO {
                    return fail(
                        &value_path,
                        format!("a time coverage is ≥ 0, found {value}"),
                    );
                }
                expect.time_coverage.push(TimePin {
                    pixel: [x, y],
                    value,
                });
            }
        }
        if let Some((v, p)) = fields.get("area") {
            let area = number(v, &p)?;
            if area < Number::ZERO {
                return fail(&p, format!("an area is ≥ 0, found {area}"));
            }
            expect.area = Some(area);
        }
        Ok(expect)
    }

    /// Every vertex of a case carries the same number of attributes, so that
    /// every pixel of the frame has the same channels.
    fn check_attribute_counts(&self, scene: &Scene, path: &Path) -> Result<()> {
        for (i, primitive) in scene.primitives.iter().enumerate() {
            let kind = primitive.kind();
            for (j, v) in primitive.vertices().iter().enumerate() {
                if v.attributes.len() != scene.attribute_count {
                    return fail(
                        &path.index(i).key(kind).index(j).key("attributes"),
                        format!(
                            "this vertex has {} attributes but the first vertex of the case has {}; every vertex carries the same number",
                            v.attributes.len(),
                            scene.attribute_count
                        ),
                    );
                }
            }
        }
        Ok(())
    }
}

/// Whether a primitive's JSON gives `z` on any vertex.
fn mentions_depth(primitive: &Value) -> bool {
    ["triangle", "line"].iter().any(|kind| {
        primitive
            .get(kind)
            .and_then(Value::as_array)
            .is_some_and(|vs| vs.iter().any(|v| v.get("z").is_some()))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> std::result::Result<Scene, CaseError> {
        parse_case(text, "test.json", &Limits::default())
    }

    const MINIMAL: &str = r#"{"name": "t", "canvas": {"width": 4, "height": 4},
        "primitives": [{"triangle": [[0, 0], [4, 0], [0, "4/3"]]}]}"#;

    #[test]
    fn minimal_case_reads_with_defaults() {
        let scene = parse(MINIMAL).unwrap();
        assert_eq!(scene.rules, Rules::default());
        assert_eq!(scene.attribute_count, 0);
        assert!(!scene.has_depth);
        let (_, t) = scene.triangles().next().unwrap();
        assert_eq!(t.vertices[2].y, Number::ratio(4, 3));
    }

    #[test]
    fn errors_name_the_json_path() {
        let e = parse(
            r#"{"name": "t", "canvas": {"width": 4, "height": 4},
            "primitives": [{"triangle": [[0, 0], [4, 0], [0, 40000]]}]}"#,
        )
        .unwrap_err();
        assert_eq!(e.location, "$.primitives[0].triangle[2][1]");
        assert!(e.message.contains("outside the documented range"), "{e}");
    }

    #[test]
    fn unknown_fields_suggest_the_right_one() {
        let e = parse(r#"{"name": "t", "canvas": {"width": 4, "hieght": 4}, "primitives": []}"#)
            .unwrap_err();
        assert_eq!(e.location, "$.canvas.hieght");
        assert!(e.message.contains("did you mean \"height\""), "{e}");
    }

    #[test]
    fn syntax_errors_give_line_and_column() {
        let e = parse("{\"name\": \"t\",\n \"canvas\": }").unwrap_err();
        assert_eq!(e.location, "line 2 column 12");
    }

    #[test]
    fn numbers_are_read_exactly() {
        let text = MINIMAL.replace("\"4/3\"", "0.1");
        let scene = parse(&text).unwrap();
        let (_, t) = scene.triangles().next().unwrap();
        assert_eq!(t.vertices[2].y, Number::ratio(1, 10));
    }
}
