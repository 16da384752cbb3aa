//! The protocol's requests (SPEC.md §12): the JSON a scene goes out as,
//! written straight to the program's stdin as it is serialized
//! ([`Request::write_to`]): one primitive's JSON at a time, and a moving
//! scene's per-pixel instants one pixel at a time, so that a request is
//! never whole in memory (issue 36: a 2048² case at 16 instants was built
//! three times, as vectors, a `Value` and text, and took 9 GB). A moving
//! scene's extra fields are `motion.rs`'s (SPEC.md §12.8); the answer that
//! comes back is `answer.rs`'s. Starting, feeding and reaping the
//! processes that speak it is `one_shot.rs`'s and `pool.rs`'.

use std::io::{self, BufWriter, Write};

use serde::ser::{Serialize, SerializeMap, SerializeSeq, Serializer};
use serde_json::{json, Value};

use crate::plan::Plan;
use crate::scene::{DepthFormat, LastPixel, LineParameter, Number, Primitive, Scene, Vertex};

use super::motion::{self, Times};
use super::values::{exact, float, float_exact};

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

/// One primitive as a request carries it; `moves` for a moving scene
/// (SPEC.md §12.8).
fn primitive(p: &Primitive, clip_space: bool, moves: Option<bool>) -> Value {
    let vertex = |v: &Vertex| vertex(v, clip_space);
    let mut out = match p {
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
    };
    if let Some(moves) = moves {
        out["moves"] = json!(moves);
    }
    out
}

/// The request for one scene (SPEC.md §12.1) but for its parts written as
/// they go (`primitives`, and a moving scene's `plan.motion.times`), which
/// are placeholders here; a moving scene's also carries `plan.motion`
/// (§12.8).
fn head(scene: &Scene, plan: &Plan) -> Value {
    let mut plan_out = plan_json(plan);
    if let Some(motion) = &plan.motion {
        plan_out["motion"] = motion::plan_motion(plan, motion);
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
        "primitives": null,
    });
    depth_and_clip(scene, &mut out);
    if let Some(case) = &scene.effects.conservative {
        out["rules"]["conservative"] = super::conservative::request_rules(case);
    }
    out
}

/// A request ready to be written to a program: the scene and plan it
/// carries (owned, so that the thread that feeds a persistent program's
/// stdin can write it while the case waits for the answer), and its id
/// under version 2 (SPEC.md §12.7).
pub struct Request {
    scene: Scene,
    plan: Plan,
    id: Option<String>,
}

impl Request {
    /// A version 1 request.
    pub fn v1(scene: &Scene, plan: &Plan) -> Request {
        Request {
            scene: scene.clone(),
            plan: plan.clone(),
            id: None,
        }
    }

    /// A version 2 request (SPEC.md §12.7): v1's, named
    /// `rastercheck-external/2` and carrying the `id` its answer must echo.
    pub fn v2(scene: &Scene, plan: &Plan, id: &str) -> Request {
        Request {
            id: Some(id.to_owned()),
            ..Request::v1(scene, plan)
        }
    }

    /// Writes the request as one JSON line, serialized as it goes: what is
    /// in memory at once is one primitive's JSON, or one pixel's instants,
    /// and the buffer.
    pub fn write_to(&self, out: &mut dyn Write) -> io::Result<()> {
        let mut out = BufWriter::with_capacity(1 << 16, out);
        serde_json::to_writer(&mut out, &Body(self)).map_err(io::Error::from)?;
        out.write_all(b"\n")?;
        out.flush()
    }

    /// The request's line as bytes (a one-shot program's request, which is
    /// never a moving scene's; tests).
    pub fn to_vec(&self) -> Vec<u8> {
        let mut bytes = Vec::new();
        self.write_to(&mut bytes)
            .expect("writing to memory succeeds");
        bytes
    }
}

/// What goes to a persistent program's stdin: a request, or a fixed line
/// (the goodbye).
pub enum Outgoing {
    Request(Box<Request>),
    Line(&'static [u8]),
}

impl Outgoing {
    /// Writes it and flushes.
    pub fn write_to(&self, out: &mut dyn Write) -> io::Result<()> {
        match self {
            Outgoing::Request(request) => request.write_to(out),
            Outgoing::Line(line) => out.write_all(line).and_then(|()| out.flush()),
        }
    }
}

/// The request's JSON: its head's keys in their order (sorted, as a
/// `Value` writes them), with `primitives` and `plan` written by
/// [`Primitives`] and [`PlanOut`].
struct Body<'a>(&'a Request);

impl Serialize for Body<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let Request { scene, plan, id } = self.0;
        let mut head = head(scene, plan);
        if let Some(id) = id {
            head["protocol"] = json!(PROTOCOL_V2);
            head["id"] = json!(id);
        }
        let Value::Object(head) = head else {
            unreachable!("a request is an object")
        };
        let mut map = serializer.serialize_map(Some(head.len()))?;
        for (key, value) in &head {
            match key.as_str() {
                "primitives" => map.serialize_entry(key, &Primitives(self.0))?,
                "plan" => map.serialize_entry(key, &PlanOut(self.0, value))?,
                _ => map.serialize_entry(key, value)?,
            }
        }
        map.end()
    }
}

/// `primitives`, one at a time.
struct Primitives<'a>(&'a Request);

impl Serialize for Primitives<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let Request { scene, plan, .. } = self.0;
        let clip_space = scene.in_clip_space();
        let mut seq = serializer.serialize_seq(Some(scene.primitives.len()))?;
        for (i, p) in scene.primitives.iter().enumerate() {
            let moves = plan.motion.as_ref().map(|m| m.moving[i]);
            seq.serialize_element(&primitive(p, clip_space, moves))?;
        }
        seq.end()
    }
}

/// `plan`, with a moving scene's `motion.times` written by [`Times`].
struct PlanOut<'a>(&'a Request, &'a Value);

impl Serialize for PlanOut<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let (Request { scene, plan, .. }, Value::Object(head)) = (self.0, self.1) else {
            unreachable!("a plan is an object")
        };
        let mut map = serializer.serialize_map(Some(head.len()))?;
        for (key, value) in head {
            match (key.as_str(), &plan.motion, value) {
                ("motion", Some(motion), Value::Object(fields)) => map.serialize_entry(
                    key,
                    &MotionOut(
                        Times {
                            scene,
                            plan,
                            motion,
                        },
                        fields,
                    ),
                )?,
                _ => map.serialize_entry(key, value)?,
            }
        }
        map.end()
    }
}

/// `plan.motion`, its `times` written by [`Times`].
struct MotionOut<'a>(Times<'a>, &'a serde_json::Map<String, Value>);

impl Serialize for MotionOut<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.1.len()))?;
        for (key, value) in self.1 {
            if key == "times" {
                map.serialize_entry(key, &self.0)?;
            } else {
                map.serialize_entry(key, value)?;
            }
        }
        map.end()
    }
}

/// The request for one scene as a `Value` (tests, and callers that want
/// to look at one; a program is sent [`Request::write_to`]'s text).
pub fn request(scene: &Scene, plan: &Plan) -> Value {
    serde_json::from_slice(&Request::v1(scene, plan).to_vec()).expect("a request parses")
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

/// The request of protocol v2 (SPEC.md §12.7) as a `Value`: v1's, named
/// `rastercheck-external/2` and carrying the `id` its answer must echo.
pub fn request_v2(scene: &Scene, plan: &Plan, id: &str) -> Value {
    serde_json::from_slice(&Request::v2(scene, plan, id).to_vec()).expect("a request parses")
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
