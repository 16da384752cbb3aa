//! The protocol's messages (SPEC.md §12): the JSON request a scene goes
//! out as, and the response that comes back, read into a [`Frame`]: the
//! covered pixels of each primitive composed in primitive order, summed
//! antialiased coverage, or an EXR file in the golden files' layout
//! (`frame::exr`); a moving scene's extra fields and its answers are
//! `motion.rs`'s (SPEC.md §12.8). Starting, feeding and reaping the
//! processes that speak it is `one_shot.rs`'s and `pool.rs`'.

use std::path::Path;

use serde_json::{json, Value};

use crate::frame::{exr, Frame, Parts};
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::{DepthFormat, LastPixel, LineParameter, Number, Primitive, Scene, Vertex};

use super::hello::Answers;
use super::motion;
use super::values::{exact, float, float_exact, pixel_of, stored_depth, whole_below};

/// The protocol's name and version, sent in every request of v1.
pub const PROTOCOL: &str = "rastercheck-external/1";

/// Version 2 (SPEC.md §12.7): the program's hello, ids in every request
/// and answer.
pub const PROTOCOL_V2: &str = "rastercheck-external/2";

/// A vertex; a moving one (SPEC.md §12.8) also carries `to`, its position
/// at shutter close, while `x` and `y` are its `from`; a clip-space one
/// (§12.10) is `clip` and `attributes` alone.
fn vertex(v: &Vertex, clip_space: bool) -> Value {
    if clip_space {
        let clip = [&v.x, &v.y, &v.z, &v.w];
        return json!({
            "clip": clip.map(float),
            "attributes": v.attributes.iter().map(float).collect::<Vec<_>>(),
            "exact": {
                "clip": clip.map(exact),
                "attributes": v.attributes.iter().map(exact).collect::<Vec<_>>(),
            }
        });
    }
    let mut out = json!({
        "x": float(&v.x),
        "y": float(&v.y),
        "z": float(&v.z),
        "w": float(&v.w),
        "attributes": v.attributes.iter().map(float).collect::<Vec<_>>(),
        "exact": {
            "x": exact(&v.x),
            "y": exact(&v.y),
            "z": exact(&v.z),
            "w": exact(&v.w),
            "attributes": v.attributes.iter().map(exact).collect::<Vec<_>>(),
        }
    });
    if let Some((to, exact_to)) = motion::vertex_to(v) {
        out["to"] = to;
        out["exact"]["to"] = exact_to;
    }
    out
}

/// The request for one scene (SPEC.md §12.1); a moving scene's also says
/// which primitives move and carries `plan.motion` (§12.8).
pub fn request(scene: &Scene, plan: &Plan) -> Value {
    let clip_space = scene.in_clip_space();
    let vertex = |v: &Vertex| vertex(v, clip_space);
    let mut primitives: Vec<Value> = scene
        .primitives
        .iter()
        .map(|p| match p {
            Primitive::Triangle(t) => json!({
                "triangle": t.vertices.iter().map(vertex).collect::<Vec<_>>(),
                "interpolation": t.interpolation.name(),
            }),
            Primitive::Line(l) => json!({
                "line": l.vertices.iter().map(vertex).collect::<Vec<_>>(),
                "rule": l.rule.name(),
                "width": float(&l.width),
                "last_pixel": match l.last_pixel {
                    LastPixel::Include => "include",
                    LastPixel::Exclude => "exclude",
                },
                "parameter": match l.parameter {
                    LineParameter::Major => "major",
                    LineParameter::Projected => "projected",
                },
                "interpolation": l.interpolation.name(),
                "exact": { "width": exact(&l.width) },
            }),
            Primitive::Polygon(polygon) => json!({
                "contours": polygon
                    .contours()
                    .map(|c| c.iter().map(vertex).collect::<Vec<_>>())
                    .collect::<Vec<_>>(),
                "fill": polygon.fill.name(),
            }),
            Primitive::Point(point) => json!({
                "point": vertex(&point.vertices[0]),
                "size": float(&point.size),
                "exact": { "size": exact(&point.size) },
            }),
        })
        .collect();
    let mut plan_out = plan_json(plan);
    if let Some(motion) = &plan.motion {
        for (primitive, &moves) in primitives.iter_mut().zip(&motion.moving) {
            primitive["moves"] = json!(moves);
        }
        plan_out["motion"] = motion::plan_motion(scene, plan, motion);
    }
    let mut out = json!({
        "protocol": PROTOCOL,
        "case": scene.name,
        "canvas": { "width": scene.canvas.width, "height": scene.canvas.height },
        "rules": {
            "subpixel_bits": scene.rules.subpixel_bits,
            "fill_rule": scene.rules.fill_rule.name(),
            "cull": scene.rules.cull.name(),
            "provoking_vertex": scene.rules.provoking_vertex.name(),
        },
        "plan": plan_out,
        "primitives": primitives,
    });
    depth_and_clip(scene, &mut out);
    out
}

/// What SPEC.md §12.10 adds to a request, as the case states it: in clip
/// space the viewport and the clip conventions; a depth format other than
/// `exact`; a polygon offset. A scene with none of them is sent as before.
fn depth_and_clip(scene: &Scene, out: &mut Value) {
    let numbers = |pairs: &[(&str, &Number)]| {
        let mut floats = serde_json::Map::new();
        let mut exacts = serde_json::Map::new();
        for (key, n) in pairs {
            let (f, e) = float_exact(n);
            floats.insert((*key).to_owned(), f);
            exacts.insert((*key).to_owned(), e);
        }
        floats.insert("exact".to_owned(), Value::Object(exacts));
        Value::Object(floats)
    };
    if let Some(v) = &scene.viewport {
        out["viewport"] = numbers(&[
            ("x", &v.x),
            ("y", &v.y),
            ("width", &v.width),
            ("height", &v.height),
            ("min_depth", &v.min_depth),
            ("max_depth", &v.max_depth),
        ]);
        let clip = &scene.rules.clip;
        let rules = &mut out["rules"];
        rules["clip_xy"] = json!(clip.xy.name());
        rules["clip_z"] = json!(clip.z.name());
        rules["depth"] = json!(clip.depth.name());
        rules["interpolate_from"] = json!(clip.values.name());
        rules["clip_points"] = json!(clip.points.name());
        rules["point_bounds"] = json!(clip.bounds.name());
    }
    if scene.rules.depth_format != DepthFormat::Exact {
        out["rules"]["depth_format"] = json!(scene.rules.depth_format.name());
    }
    if let Some(bias) = &scene.rules.depth_bias {
        out["rules"]["depth_bias"] = numbers(&[
            ("constant", &bias.constant),
            ("slope", &bias.slope),
            ("clamp", &bias.clamp),
        ]);
    }
}

/// The request of protocol v2 (SPEC.md §12.7): v1's, named
/// `rastercheck-external/2` and carrying the `id` its answer must echo.
pub fn request_v2(scene: &Scene, plan: &Plan, id: &str) -> Value {
    let mut out = request(scene, plan);
    out["protocol"] = json!(PROTOCOL_V2);
    out["id"] = json!(id);
    out
}

/// The plan, with the sample offsets of an antialiased scene as floats and,
/// in `exact`, as fractions.
fn plan_json(plan: &Plan) -> Value {
    let mut out = json!({
        "samples_per_pixel": plan.samples_per_pixel,
        "depth": plan.depth,
        "attributes": plan.attributes,
    });
    if let Some(aa) = &plan.antialias {
        let one = 1i64 << aa.position_bits;
        let offset = |c: u32| Number::ratio(i64::from(c), one);
        out["antialias"] = json!({
            "samples": aa.offsets.len(),
            "position_bits": aa.position_bits,
            "offsets": aa.offsets.iter().map(|p| p.map(|c| float(&offset(c)))).collect::<Vec<_>>(),
            "exact": {
                "offsets": aa.offsets.iter().map(|p| p.map(|c| exact(&offset(c)))).collect::<Vec<_>>(),
            },
        });
    }
    out
}

// ---------------------------------------------------------------------------
// The response.

pub(super) fn parse_response(bytes: &[u8]) -> Result<Value, String> {
    serde_json::from_slice(bytes).map_err(|e| {
        let text = String::from_utf8_lossy(bytes);
        let shown: String = text.chars().take(80).collect();
        if text.trim().is_empty() {
            "printed no response".to_owned()
        } else {
            format!(
                "printed something that is not a JSON response ({e}): {shown:?}{}",
                if text.chars().count() > 80 { "…" } else { "" }
            )
        }
    })
}

/// Turns a response into a frame, checking it against the request, for a
/// program that declared nothing about its answers (version 1).
pub fn frame_from_response(
    response: &Value,
    scene: &Scene,
    plan: &Plan,
) -> Result<Frame, RasterError> {
    frame_from_answer(response, scene, plan, Answers::default())
}

/// [`frame_from_response`] for a program whose hello declared how its
/// answers are shaped (SPEC.md §12.9).
pub fn frame_from_answer(
    response: &Value,
    scene: &Scene,
    plan: &Plan,
    answers: Answers,
) -> Result<Frame, RasterError> {
    let bad = |why: String| RasterError::Failed(format!("bad response: {why}"));
    let Some(object) = response.as_object() else {
        return Err(bad("not a JSON object".to_owned()));
    };
    if let Some(protocol) = object.get("protocol") {
        if protocol.as_str() != Some(PROTOCOL) && protocol.as_str() != Some(PROTOCOL_V2) {
            return Err(bad(format!(
                "$.protocol is {protocol}; this rastercheck speaks {PROTOCOL:?} and {PROTOCOL_V2:?}"
            )));
        }
    }
    if let Some(why) = object.get("unsupported") {
        return Err(RasterError::Unsupported(text_of(why)));
    }
    if let Some(why) = object.get("error") {
        return Err(RasterError::Failed(format!(
            "the program reported an error: {}",
            text_of(why)
        )));
    }
    match (object.get("primitives"), object.get("exr")) {
        (Some(primitives), None) => compose(primitives, scene, plan, answers).map_err(bad),
        (None, Some(path)) => {
            let path = path
                .as_str()
                .ok_or_else(|| bad("$.exr must be a string (a file path)".to_owned()))?;
            if plan.motion.is_some() {
                return Err(bad(
                    "an exr response holds no time coverage; answer moving scenes with fragments or time (SPEC §12.8)"
                        .to_owned(),
                ));
            }
            if plan.antialias.is_some() {
                return Err(bad(
                    "an exr response holds one sample per pixel; answer antialiased scenes with fragments or coverage"
                        .to_owned(),
                ));
            }
            frame_from_exr(Path::new(path), scene, plan).map_err(bad)
        }
        (Some(_), Some(_)) => Err(bad("give either $.primitives or $.exr, not both".to_owned())),
        (None, None) => Err(bad(
            "expected $.primitives, $.exr, $.unsupported or $.error".to_owned(),
        )),
    }
}

fn text_of(value: &Value) -> String {
    // Quoted in the report: at most 80 characters of it (SPEC.md §8).
    match value {
        Value::String(s) => super::messages::shorten(s),
        other => super::messages::shorten(&other.to_string()),
    }
}

/// Draws the fragments of each primitive, in primitive order; or, for an
/// antialiased scene answered with per-pixel coverage, sums it. A program
/// that answers coverage only gives no depth and no attributes: its frame
/// has none, and says so (SPEC.md §12.9).
fn compose(
    primitives: &Value,
    scene: &Scene,
    plan: &Plan,
    answers: Answers,
) -> Result<Frame, String> {
    let (width, height) = (scene.canvas.width, scene.canvas.height);
    let list = primitives
        .as_array()
        .ok_or("$.primitives must be an array")?;
    if list.len() != scene.primitives.len() {
        return Err(format!(
            "$.primitives has {} entries; the request has {} primitives",
            list.len(),
            scene.primitives.len()
        ));
    }
    if plan.motion.is_some() {
        return motion::compose(list, scene, plan);
    }
    let with_coverage = list.iter().filter(|e| e.get("coverage").is_some()).count();
    if with_coverage > 0 {
        if plan.antialias.is_none() {
            return Err("coverage entries answer antialiased scenes only; give fragments".into());
        }
        if with_coverage != list.len() {
            return Err("give coverage for every primitive or fragments for every one".into());
        }
        return sum_coverage(list, width, height, answers.step(), answers.saturates());
    }
    // The values a coverage-only program does not give are not judged; the
    // result says so.
    let unjudged = answers.coverage_only && plan.interpolates();
    let given;
    let plan = if unjudged {
        given = Plan {
            depth: false,
            attributes: 0,
            ..plan.clone()
        };
        &given
    } else {
        plan
    };
    let samples = plan.antialias.as_ref().map(|aa| aa.offsets.len() as u32);
    let slot_field = usize::from(samples.is_some());
    let values = usize::from(plan.depth) + plan.attributes;
    let arity = 2 + slot_field + values;
    let mut frame = Frame::for_plan(width, height, plan);
    frame.coverage_only = answers.coverage_only;
    if unjudged {
        frame.method = Some(COVERAGE_ONLY);
    }
    for (p, entry) in list.iter().enumerate() {
        let fragments = entry
            .as_object()
            .and_then(|o| o.get("fragments"))
            .and_then(Value::as_array)
            .ok_or_else(|| format!("$.primitives[{p}] must be an object with a fragments array"))?;
        for (f, fragment) in fragments.iter().enumerate() {
            let at = || format!("$.primitives[{p}].fragments[{f}]");
            let numbers = fragment
                .as_array()
                .filter(|a| a.len() == arity)
                .ok_or_else(|| {
                    format!(
                        "{} must be an array of {arity} numbers: x, y{}{}{}",
                        at(),
                        if samples.is_some() { ", sample" } else { "" },
                        if plan.depth { ", depth" } else { "" },
                        if plan.attributes > 0 {
                            format!(", {} attributes", plan.attributes)
                        } else {
                            String::new()
                        }
                    )
                })?;
            let (x, y) = pixel_of(numbers, (width, height), &at)?;
            let slot = match samples {
                Some(n) => whole_below(&numbers[2], n).ok_or_else(|| {
                    format!(
                        "{}[2]: {} is not a sample index in [0, {n})",
                        at(),
                        numbers[2]
                    )
                })?,
                None => 0,
            };
            let i = frame.index(x, y) + slot as usize;
            frame.hit(i, p);
            for (k, v) in numbers[2 + slot_field..].iter().enumerate() {
                let v = v.as_f64().filter(|v| v.is_finite()).ok_or_else(|| {
                    format!("{}[{}] must be a finite number", at(), k + 2 + slot_field)
                })?;
                match (&mut frame.depth, k) {
                    (Some(depth), 0) => {
                        depth[i] = stored_depth(v, scene.rules.depth_format).ok_or_else(|| {
                            format!(
                                "{}[{}]: {v} is not a {} depth (SPEC §12.10)",
                                at(),
                                2 + slot_field,
                                scene.rules.depth_format.name()
                            )
                        })?
                    }
                    (Some(_), k) => frame.attributes[k - 1][i] = v,
                    (None, k) => frame.attributes[k][i] = v,
                }
            }
        }
    }
    if samples.is_some() {
        frame.resolve();
    }
    Ok(frame)
}

/// The method a coverage-only frame of a scene with values names: what the
/// reports show beside its verdict.
pub const COVERAGE_ONLY: &str = "coverage only: depth and attributes not judged";

/// An area method's answer (SPEC.md §12.2): each primitive's covered
/// fraction of the pixels it touches, summed into a frame without samples,
/// and kept per primitive to be judged per primitive (§12.9); `step` is the
/// quantization the program declared (0 for none).
fn sum_coverage(
    list: &[Value],
    width: u32,
    height: u32,
    step: f64,
    saturates: bool,
) -> Result<Frame, String> {
    let mut resolved = vec![0.0; width as usize * height as usize];
    let mut parts = Parts {
        coverage: Vec::with_capacity(list.len()),
        step,
        saturates,
    };
    for (p, entry) in list.iter().enumerate() {
        let mut given = Vec::new();
        let items = entry
            .get("coverage")
            .and_then(Value::as_array)
            .ok_or_else(|| format!("$.primitives[{p}].coverage must be an array"))?;
        for (k, item) in items.iter().enumerate() {
            let at = || format!("$.primitives[{p}].coverage[{k}]");
            let triple = item
                .as_array()
                .filter(|a| a.len() == 3)
                .ok_or_else(|| format!("{} must be [x, y, fraction]", at()))?;
            let (x, y) = pixel_of(triple, (width, height), &at)?;
            let c = triple[2]
                .as_f64()
                .filter(|c| (0.0..=1.0).contains(c))
                .ok_or_else(|| format!("{}[2]: {} is not a fraction in [0, 1]", at(), triple[2]))?;
            let pixel = y * width + x;
            resolved[pixel as usize] += c;
            given.push((pixel, c));
        }
        parts.coverage.push(given);
    }
    Ok(Frame {
        parts: Some(parts),
        ..Frame::resolved_only(width, height, resolved)
    })
}

/// Reads a frame from an EXR file with the channels of a golden file
/// (`frame::exr`).
fn frame_from_exr(path: &Path, scene: &Scene, plan: &Plan) -> Result<Frame, String> {
    let (width, height) = (scene.canvas.width, scene.canvas.height);
    let ((w, h), mut channels) = exr::read(path, (width as usize, height as usize))?;
    if (w, h) != (width as usize, height as usize) {
        return Err(format!(
            "{}: the image is {w}×{h}; the canvas is {width}×{height}",
            path.display()
        ));
    }
    let mut take = |name: &str| {
        channels
            .iter()
            .position(|(n, _)| n == name)
            .map(|at| channels.swap_remove(at).1)
            .ok_or_else(|| format!("{}: no channel {name}", path.display()))
    };
    let coverage = take("coverage")?;
    let primitive = take("primitive")?;
    let mut frame = Frame::new(width, height, plan.depth, plan.attributes);
    let count = scene.primitives.len() as f32;
    for (i, (&c, &p)) in coverage.iter().zip(&primitive).enumerate() {
        let (x, y) = (i % w, i / w);
        if !(c.fract() == 0.0 && (0.0..=f32::from(u16::MAX)).contains(&c)) {
            return Err(format!("coverage at pixel ({x}, {y}) is {c}, not a count"));
        }
        if !(p.fract() == 0.0 && (0.0..=count).contains(&p)) || (p == 0.0) != (c == 0.0) {
            return Err(format!(
                "primitive at pixel ({x}, {y}) is {p} with coverage {c}: it must be index + 1 \
                 of a primitive where coverage > 0, and 0 where coverage is 0"
            ));
        }
        frame.coverage[i] = c as u16;
        frame.last[i] = p as u32;
    }
    if let Some(depth) = &mut frame.depth {
        *depth = take("depth")?.into_iter().map(f64::from).collect();
    }
    for k in 0..plan.attributes {
        frame.attributes[k] = take(&format!("attribute.{k}"))?
            .into_iter()
            .map(f64::from)
            .collect();
    }
    Ok(frame)
}
