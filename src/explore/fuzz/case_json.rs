//! A scene as a case file (SPEC.md §1), every number exact, and whether a
//! scene can be one (`valid`: within SPEC.md's limits and, for polygons,
//! antialiasing and motion, reading back from its own file). Writing only:
//! reading is [`crate::scene::parse_case`].

use crate::scene::rules::limits::{CLIP_LIMIT, COORD_LIMIT, W_LIMIT};
use crate::scene::time::limits::TIME_ONE;
use crate::scene::{
    parse_case, DepthMode, InterpolateFrom, Interpolation, LastPixel, Limits, LineParameter,
    LineRule, Number, PointBounds, PointClip, Primitive, ProvokingVertex, Scene, Vertex,
};

/// Whether a scene is within SPEC.md's limits (§8), as a case file must be.
pub(super) fn valid(scene: &Scene) -> Result<(), String> {
    let side = 1..=crate::scene::rules::limits::MAX_CANVAS_SIDE;
    if !side.contains(&scene.canvas.width) || !side.contains(&scene.canvas.height) {
        return Err("canvas side out of range".to_owned());
    }
    if scene.primitives.is_empty() {
        return Err("no primitives".to_owned());
    }
    if scene.in_clip_space() {
        // Clip coordinates have their own bound, w any sign (SPEC.md §16.1);
        // the viewport and the rules' combinations are the reader's to check.
        let limit = Number::from_int(CLIP_LIMIT);
        for v in scene.vertices() {
            if [&v.x, &v.y, &v.z, &v.w].iter().any(|c| c.abs() > limit) {
                return Err("clip coordinate out of range".to_owned());
            }
        }
        return reads_back(scene);
    }
    let limit = Number::from_int(COORD_LIMIT);
    let (w_lo, w_hi) = (Number::ratio(1, W_LIMIT), Number::from_int(W_LIMIT));
    for v in scene.vertices() {
        if v.x.abs() > limit || v.y.abs() > limit {
            return Err("coordinate out of range".to_owned());
        }
        if v.w < w_lo || v.w > w_hi {
            return Err("w out of range".to_owned());
        }
        if v.attributes.len() != scene.attribute_count {
            return Err("attribute count".to_owned());
        }
    }
    // Polygons, antialiasing and motion have rules of their own (contours
    // of at least 3 vertices, sample counts per pattern, no `all-edges` for
    // polygons, no midpoint lines under antialiasing, only triangles and
    // parallelogram lines move, no values and no sample expectations in a
    // moving scene): the scene must read back from its case file, so that
    // a shrunk counterexample is a case.
    let motion = scene.effects.motion_blur.is_some() || scene.vertices().any(|v| v.to.is_some());
    if scene.has_polygons()
        || scene.effects.antialias.is_some()
        || motion
        || scene.is_conservative()
    {
        return reads_back(scene);
    }
    Ok(())
}

/// Whether the scene reads back from its own case file.
fn reads_back(scene: &Scene) -> Result<(), String> {
    let mut named = scene.clone();
    named.name = "fuzz".to_owned();
    named.description = "fuzz".to_owned();
    parse_case(&case_json(&named), "fuzz", &Limits::default())
        .map(|_| ())
        .map_err(|e| format!("not a valid case: {}", e.message))
}

fn json_number(n: &Number) -> String {
    let s = n.to_exact_string();
    if s.contains('/') {
        format!("\"{s}\"")
    } else {
        s
    }
}

fn json_string(s: &str) -> String {
    serde_json::to_string(s).expect("a string serializes")
}

fn position_json(x: &Number, y: &Number) -> String {
    format!("[{}, {}]", json_number(x), json_number(y))
}

fn vertex_json(scene: &Scene, v: &Vertex) -> String {
    if scene.in_clip_space() {
        let c: Vec<String> = [&v.x, &v.y, &v.z, &v.w].map(json_number).to_vec();
        let mut fields = vec![format!("\"clip\": [{}]", c.join(", "))];
        if !v.attributes.is_empty() {
            let values: Vec<String> = v.attributes.iter().map(json_number).collect();
            fields.push(format!("\"attributes\": [{}]", values.join(", ")));
        }
        return format!("{{ {} }}", fields.join(", "));
    }
    let position = position_json(&v.x, &v.y);
    if !scene.has_depth && v.w == Number::ONE && v.attributes.is_empty() && v.to.is_none() {
        return position;
    }
    let mut fields = match v.to.as_deref() {
        // A moving vertex (or one written with from = to, which is static).
        Some([x, y]) => vec![
            format!("\"from\": {position}"),
            format!("\"to\": {}", position_json(x, y)),
        ],
        None => vec![format!("\"position\": {position}")],
    };
    if scene.has_depth {
        fields.push(format!("\"z\": {}", json_number(&v.z)));
    }
    if v.w != Number::ONE {
        fields.push(format!("\"w\": {}", json_number(&v.w)));
    }
    if !v.attributes.is_empty() {
        let values: Vec<String> = v.attributes.iter().map(json_number).collect();
        fields.push(format!("\"attributes\": [{}]", values.join(", ")));
    }
    format!("{{ {} }}", fields.join(", "))
}

fn primitive_json(scene: &Scene, p: &Primitive) -> String {
    let vertices: Vec<String> = p.vertices().iter().map(|v| vertex_json(scene, v)).collect();
    let mut fields = match p {
        Primitive::Triangle(_) => vec![format!("\"triangle\": [{}]", vertices.join(", "))],
        Primitive::Point(point) => {
            let mut f = vec![format!("\"point\": {}", vertices[0])];
            if point.size != Number::ONE {
                f.push(format!("\"size\": {}", json_number(&point.size)));
            }
            f
        }
        Primitive::Polygon(polygon) => {
            let contours: Vec<String> = polygon
                .contours()
                .map(|c| {
                    let vs: Vec<String> = c.iter().map(|v| vertex_json(scene, v)).collect();
                    format!("[{}]", vs.join(", "))
                })
                .collect();
            vec![
                format!("\"contours\": [{}]", contours.join(", ")),
                format!("\"fill\": \"{}\"", polygon.fill.name()),
            ]
        }
        Primitive::Line(l) => {
            let mut f = vec![
                format!("\"line\": [{}]", vertices.join(", ")),
                format!("\"rule\": \"{}\"", l.rule.name()),
            ];
            if l.rule.is_wide() && l.width != Number::ONE {
                f.push(format!("\"width\": {}", json_number(&l.width)));
            }
            if l.rule == LineRule::Midpoint && l.last_pixel == LastPixel::Exclude {
                f.push("\"last_pixel\": \"exclude\"".to_owned());
            }
            if l.parameter == LineParameter::Projected {
                f.push("\"parameter\": \"projected\"".to_owned());
            }
            f
        }
    };
    // A polygon and a point take no interpolation.
    if !matches!(p, Primitive::Polygon(_) | Primitive::Point(_))
        && p.interpolation() != Interpolation::Perspective
    {
        fields.push(format!(
            "\"interpolation\": \"{}\"",
            p.interpolation().name()
        ));
    }
    format!("{{ {} }}", fields.join(", "))
}

/// A scene as a case file (SPEC.md §1), every number exact.
pub fn case_json(scene: &Scene) -> String {
    let bits = scene
        .rules
        .subpixel_bits
        .map_or("null".to_owned(), |b| b.to_string());
    let primitives: Vec<String> = scene
        .primitives
        .iter()
        .map(|p| format!("    {}", primitive_json(scene, p)))
        .collect();
    let e = &scene.expect;
    let mut expect = Vec::new();
    if e.max_mismatched_samples != 0 {
        expect.push(format!(
            "\"max_mismatched_samples\": {}",
            e.max_mismatched_samples
        ));
    }
    if e.watertight {
        expect.push("\"watertight\": true".to_owned());
    }
    if let Some(n) = e.samples_covered {
        expect.push(format!("\"samples_covered\": {n}"));
    }
    if let Some(x) = e.max_abs_error {
        expect.push(format!("\"max_abs_error\": {x:e}"));
    }
    if let Some(x) = e.max_ulp_error {
        expect.push(format!("\"max_ulp_error\": {x:e}"));
    }
    if let Some(x) = e.max_coverage_error {
        expect.push(format!("\"max_coverage_error\": {x:e}"));
    }
    if let Some(x) = e.max_coverage_rms {
        expect.push(format!("\"max_coverage_rms\": {x:e}"));
    }
    if let Some(a) = &e.area {
        expect.push(format!("\"area\": \"{}\"", a.to_exact_string()));
    }
    if let Some(x) = e.max_time_error {
        expect.push(format!("\"max_time_error\": {x:e}"));
    }
    if let Some(x) = e.max_time_rms {
        expect.push(format!("\"max_time_rms\": {x:e}"));
    }
    if !e.time_coverage.is_empty() {
        let pins: Vec<String> = e
            .time_coverage
            .iter()
            .map(|pin| {
                format!(
                    "{{ \"pixel\": [{}, {}], \"value\": {} }}",
                    pin.pixel[0],
                    pin.pixel[1],
                    json_number(&pin.value)
                )
            })
            .collect();
        expect.push(format!("\"time_coverage\": [{}]", pins.join(", ")));
    }
    let mut effects = Vec::new();
    if let Some(a) = &scene.effects.antialias {
        effects.push(format!(
            "\"antialias\": {{ \"samples\": {}, \"pattern\": \"{}\", \"seed\": {}, \"adaptive\": {}, \"position_bits\": {} }}",
            a.samples,
            a.pattern.name(),
            a.seed,
            a.adaptive,
            a.position_bits
        ));
    }
    if let Some(b) = &scene.effects.motion_blur {
        let [open, close] = b
            .shutter
            .map(|t| json_number(&Number::ratio(t.into(), TIME_ONE.into())));
        effects.push(format!(
            "\"motion_blur\": {{ \"shutter\": [{open}, {close}], \"samples\": {}, \"pattern\": \"{}\", \"seed\": {} }}",
            b.samples,
            b.pattern.name(),
            b.seed
        ));
    }
    if let Some(c) = &scene.effects.conservative {
        effects.push(format!(
            "\"conservative\": {{ \"mode\": \"{}\", \"uncertainty\": {}, \"fully_covered\": {}, \"degenerate_triangles\": {}, \"degenerate_lines\": {}, \"points_and_lines\": {} }}",
            c.mode.name(),
            json_number(&c.uncertainty),
            c.fully_covered,
            c.degenerate_triangles,
            c.degenerate_lines,
            c.points_and_lines
        ));
    }
    let effects = if effects.is_empty() {
        String::new()
    } else {
        format!("  \"effects\": {{ {} }},\n", effects.join(", "))
    };
    let mut rules = vec![
        format!("\"subpixel_bits\": {bits}"),
        format!("\"fill_rule\": \"{}\"", scene.rules.fill_rule.name()),
        format!("\"cull\": \"{}\"", scene.rules.cull.name()),
    ];
    if scene.rules.provoking_vertex != ProvokingVertex::First {
        rules.push(format!(
            "\"provoking_vertex\": \"{}\"",
            scene.rules.provoking_vertex.name()
        ));
    }
    if scene.rules.depth_format != crate::scene::depth::DepthFormat::Exact {
        rules.push(format!(
            "\"depth_format\": \"{}\"",
            scene.rules.depth_format.name()
        ));
    }
    if let Some(b) = &scene.rules.depth_bias {
        rules.push(format!(
            "\"depth_bias\": {{ \"constant\": {}, \"slope\": {}, \"clamp\": {} }}",
            json_number(&b.constant),
            json_number(&b.slope),
            json_number(&b.clamp)
        ));
    }
    let mut viewport = String::new();
    if let Some(v) = &scene.viewport {
        let clip = scene.rules.clip;
        rules.push(format!("\"clip_xy\": \"{}\"", clip.xy.name()));
        if clip.depth == DepthMode::Clip {
            rules.push(format!("\"clip_z\": \"{}\"", clip.z.name()));
        }
        rules.push(format!("\"depth\": \"{}\"", clip.depth.name()));
        if clip.values != InterpolateFrom::Snapped {
            rules.push(format!("\"interpolate_from\": \"{}\"", clip.values.name()));
        }
        if clip.points != PointClip::Pop {
            rules.push(format!("\"clip_points\": \"{}\"", clip.points.name()));
        }
        if clip.bounds != PointBounds::Canvas {
            rules.push(format!("\"point_bounds\": \"{}\"", clip.bounds.name()));
        }
        viewport = format!(
            "  \"viewport\": {{ \"x\": {}, \"y\": {}, \"width\": {}, \"height\": {}, \"min_depth\": {}, \"max_depth\": {} }},\n",
            json_number(&v.x),
            json_number(&v.y),
            json_number(&v.width),
            json_number(&v.height),
            json_number(&v.min_depth),
            json_number(&v.max_depth)
        );
    }
    format!(
        "{{\n  \"name\": {},\n  \"description\": {},\n  \"canvas\": {{ \"width\": {}, \"height\": {} }},\n  \"rules\": {{ {} }},\n{viewport}{effects}  \"primitives\": [\n{}\n  ],\n  \"expect\": {{ {} }}\n}}\n",
        json_string(&scene.name),
        json_string(&scene.description),
        scene.canvas.width,
        scene.canvas.height,
        rules.join(", "),
        primitives.join(",\n"),
        expect.join(", "),
    )
}
