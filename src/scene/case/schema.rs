//! The schema of a case file: the walk that maps each section and field of
//! the format (name, canvas, rules, primitives and their vertices, effects,
//! expect) onto the scene model, with each field's defaults.
//!
//! A value is checked where it is read, so its error names its path; the
//! range helper and the checks across fields, run once the scene is
//! assembled, are `validate.rs`'s.

use serde_json::Value;

use crate::scene::expect::{Expect, TimePin};
use crate::scene::model::{Canvas, Effects, Scene};
use crate::scene::number::Number;
use crate::scene::primitive::{Line, Polygon, Primitive, Triangle, Vertex};
use crate::scene::rules::{
    limits, Cull, FillRule, Interpolation, LastPixel, LineParameter, LineRule, PolygonFill,
    ProvokingVertex, Rules,
};
use crate::scene::samples::{Antialias, Pattern};
use crate::scene::time::{MotionBlur, TimePattern};

use super::json::{array, boolean, count, fail, kind, named, number, string, Fields, Path, Result};
use super::reader::Reader;
use super::validate::{positive_length, within};

impl Reader<'_> {
    pub(super) fn scene(&self, value: &Value) -> Result<Scene> {
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
                "viewport",
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
        let viewport = self.clip_space(&fields, &canvas)?;
        let has_depth = viewport.is_some()
            || fields
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
            viewport,
        };
        self.check_attribute_counts(&scene, &primitives_path)?;
        self.check_clip_space(&scene, &fields)?;
        self.check_depth_rules(&scene)?;
        self.check_points(&scene)?;
        self.check_combinations(&scene, &fields)?;
        self.check_samples(&scene)?;
        self.check_conservative(&scene)?;
        Ok(scene)
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
            return self.over(
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
        let fields = Fields::new(
            value,
            path,
            &[
                "subpixel_bits",
                "fill_rule",
                "cull",
                "provoking_vertex",
                "clip_xy",
                "clip_z",
                "depth",
                "interpolate_from",
                "depth_format",
                "depth_bias",
                "clip_points",
                "point_bounds",
            ],
        )?;
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
            rules.cull = named(v, &p, Cull::from_name, &Cull::NAMES)?;
        }
        if let Some((v, p)) = fields.get("provoking_vertex") {
            rules.provoking_vertex =
                named(v, &p, ProvokingVertex::from_name, &ProvokingVertex::NAMES)?;
        }
        self.clip_rules(&fields, &mut rules.clip)?;
        self.depth_rules(&fields, &mut rules)?;
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
            return self.over(
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
        if value.get("point").is_some() {
            return self.point(value, path);
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
            Some((v, p)) => named(v, &p, Interpolation::from_name, &Interpolation::NAMES),
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
            Some((v, p)) => named(v, &p, LineRule::from_name, &LineRule::NAMES)?,
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
                positive_length(&w, &p, limits::MAX_LINE_WIDTH, "a line width", "width")?;
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
            Some((v, p)) => named(v, &p, PolygonFill::from_name, &PolygonFill::NAMES)?,
            None => PolygonFill::NonZero,
        };
        Ok(Primitive::Polygon(Polygon {
            vertices,
            contour_ends,
            fill,
        }))
    }

    pub(super) fn vertex(&self, value: &Value, path: &Path) -> Result<Vertex> {
        match value {
            Value::Array(_) => {
                let (x, y) = self.position(value, path)?;
                Ok(Vertex::at(x, y))
            }
            Value::Object(_) => {
                let fields = Fields::new(
                    value,
                    path,
                    &["position", "from", "to", "clip", "z", "w", "attributes"],
                )?;
                let mut vertex = match fields.get("clip") {
                    Some((v, p)) => self.clip_vertex(v, &p, &fields)?,
                    None => self.moving_position(&fields, path)?,
                };
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
        let fields = Fields::new(value, path, &["antialias", "motion_blur", "conservative"])?;
        let antialias = match fields.get("antialias") {
            Some((v, p)) => Some(self.antialias(v, &p)?),
            None => None,
        };
        let motion_blur = match fields.get("motion_blur") {
            Some((v, p)) => Some(self.motion_blur(v, &p)?),
            None => None,
        };
        let conservative = match fields.get("conservative") {
            Some((v, p)) => Some(self.conservative(v, &p)?),
            None => None,
        };
        Ok(Effects {
            antialias,
            motion_blur,
            conservative,
        })
    }

    fn motion_blur(&self, value: &Value, path: &Path) -> Result<MotionBlur> {
        use crate::scene::time::limits as mb;
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
        let (samples, _) = sample_count(&fields, mb::MAX_SAMPLES)?;
        let names: Vec<&str> = TimePattern::ALL.iter().map(|p| p.name()).collect();
        let pattern = pattern(
            &fields,
            TimePattern::from_name,
            &names,
            TimePattern::Stratified,
        )?;
        let seed = seed(&fields)?;
        Ok(MotionBlur {
            shutter,
            samples,
            pattern,
            seed,
        })
    }

    fn antialias(&self, value: &Value, path: &Path) -> Result<Antialias> {
        use crate::scene::samples::limits as aa;
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
        let (samples, samples_path) = sample_count(&fields, aa::MAX_SAMPLES)?;
        let names: Vec<&str> = Pattern::ALL.iter().map(|p| p.name()).collect();
        let pattern = pattern(&fields, Pattern::from_name, &names, Pattern::Standard)?;
        if let Err(why) = pattern.check_count(samples) {
            return fail(&samples_path, why);
        }
        let seed = seed(&fields)?;
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
                "conservative",
            ],
        )?;
        let mut expect = Expect::default();
        if let Some((v, p)) = fields.get("conservative") {
            expect.conservative = Some(self.conservative_promise(v, &p)?);
        }
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
                return fail(
                    &p,
                    format!(
                        "{key} must be ≥ 0, found {}",
                        crate::scene::number::echo_number(&n)
                    ),
                );
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
}

/// `samples` of a sampling effect (antialiasing, motion blur): a count in
/// [1, `max`], and its path.
fn sample_count(fields: &Fields, max: u32) -> Result<(u32, Path)> {
    let (v, samples_path) = fields.require("samples")?;
    let samples = count(v, &samples_path, u64::MAX >> 1)?;
    if samples == 0 || samples > u64::from(max) {
        return fail(
            &samples_path,
            format!("samples {samples} is outside [1, {max}]"),
        );
    }
    Ok((samples as u32, samples_path))
}

/// `pattern` of a sampling effect: one of `names`, or `default`.
fn pattern<T>(
    fields: &Fields,
    parse: fn(&str) -> Option<T>,
    names: &[&str],
    default: T,
) -> Result<T> {
    match fields.get("pattern") {
        Some((v, p)) => named(v, &p, parse, names),
        None => Ok(default),
    }
}

/// `seed` of a sampling effect; 0 when absent.
fn seed(fields: &Fields) -> Result<u64> {
    match fields.get("seed") {
        Some((v, p)) => count(v, &p, u64::MAX),
        None => Ok(0),
    }
}

/// Whether a primitive's JSON gives `z` on any vertex.
fn mentions_depth(primitive: &Value) -> bool {
    if let Some(vertex) = primitive.get("point") {
        return vertex.get("z").is_some();
    }
    ["triangle", "line"].iter().any(|kind| {
        primitive
            .get(kind)
            .and_then(Value::as_array)
            .is_some_and(|vs| vs.iter().any(|v| v.get("z").is_some()))
    })
}
