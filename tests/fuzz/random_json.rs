//! Random JSON for the reader: number and string texts (extreme, non-finite,
//! too long), known and misspelt keys, and case-shaped objects with random
//! values (triangles, lines and polygons, moving vertices, antialiasing and
//! motion blur, time expectations), and deep nesting.

use proptest::prelude::*;

/// Number texts: ordinary, extreme exponents, too many digits, negative
/// zero, and the limits of the documented ranges a hair either side.
pub(crate) fn number_text() -> impl Strategy<Value = String> {
    prop_oneof![
        3 => (-100i64..100).prop_map(|n| n.to_string()),
        2 => any::<f64>().prop_filter("finite", |f| f.is_finite()).prop_map(|f| format!("{f:e}")),
        1 => prop::sample::select(vec![
            "0", "-0", "-0.0", "1e1000", "1e1001", "-1e-1000", "1e-1001", "1e999999999",
            "1E+999999999999999999999", "1e-99999999999999999999", "32768", "32768.000000000001",
            "-32768", "-32769", "1000000000000", "1000000000000.5", "0.000001", "0.0000009999",
            "1000000", "1000000.000001", "16384", "16385", "16", "17", "1024", "1024.0001",
            "100000", "100001", "18446744073709551616", "9223372036854775808", "0.5e1", "5e-1",
        ]).prop_map(str::to_owned),
        1 => (1usize..1100).prop_map(|n| "9".repeat(n)),
        1 => (1usize..1100).prop_map(|n| format!("0.{}1", "0".repeat(n))),
    ]
}

/// String texts (JSON-quoted): fractions, non-finite spellings, names the
/// reader knows, and arbitrary strings.
pub(crate) fn string_text() -> impl Strategy<Value = String> {
    prop_oneof![
        2 => prop::sample::select(vec![
            "NaN", "-NaN", "Infinity", "-Infinity", "inf", "+inf", " nan ", "1/3", "-7/2", "1/0",
            "0/0", "1/-0", "3/-4", "1.5/2", "1/2/3", "/", "", " ", "1e3/7", "1e1001/3",
            "top-left", "bottom-right", "top-right", "bottom-left", "all-edges", "none", "cw",
            "ccw", "perspective", "linear", "flat", "midpoint", "diamond-exit", "rectangle",
            "parallelogram", "include", "exclude", "major", "projected", "nonzero", "even-odd",
            "grid", "standard", "stratified", "random", "n-rooks", "stratified-shuffled",
            "jittered-xy-t", "box",
        ]).prop_map(|s| serde_json::to_string(s).unwrap()),
        1 => (number_text(), number_text()).prop_map(|(a, b)| format!("\"{a}/{b}\"")),
        1 => number_text().prop_map(|n| format!("\"{n}\"")),
        1 => any::<String>().prop_map(|s| serde_json::to_string(&s).unwrap()),
    ]
}

const KEYS: &[&str] = &[
    "name",
    "description",
    "canvas",
    "width",
    "height",
    "rules",
    "subpixel_bits",
    "fill_rule",
    "cull",
    "primitives",
    "triangle",
    "line",
    "interpolation",
    "rule",
    "last_pixel",
    "parameter",
    "position",
    "z",
    "w",
    "attributes",
    "effects",
    "antialias",
    "motion_blur",
    "expect",
    "max_mismatched_samples",
    "watertight",
    "samples_covered",
    "max_abs_error",
    "max_ulp_error",
    "from",
    "to",
    "polygon",
    "contours",
    "fill",
    "samples",
    "pattern",
    "seed",
    "adaptive",
    "position_bits",
    "shutter",
    "max_time_error",
    "max_time_rms",
    "time_coverage",
    "pixel",
    "value",
    "// comment",
    "//",
    "nmae",
    "",
    "$",
    "\u{0}",
];

fn key_text() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => prop::sample::select(KEYS).prop_map(|k| serde_json::to_string(k).unwrap()),
        1 => any::<String>().prop_map(|s| serde_json::to_string(&s).unwrap()),
    ]
}

/// Arbitrary JSON text, nested.
pub(crate) fn json_text() -> impl Strategy<Value = String> {
    let leaf = prop_oneof![
        Just("null".to_owned()),
        Just("true".to_owned()),
        Just("false".to_owned()),
        number_text(),
        string_text(),
    ];
    leaf.prop_recursive(6, 64, 8, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..8).prop_map(|v| format!("[{}]", v.join(","))),
            prop::collection::vec((key_text(), inner), 0..8).prop_map(|fields| {
                let fields: Vec<String> = fields.iter().map(|(k, v)| format!("{k}:{v}")).collect();
                format!("{{{}}}", fields.join(","))
            }),
        ]
    })
}

/// A value that is plausible for a count or a coordinate, or any JSON.
fn any_value() -> BoxedStrategy<String> {
    prop_oneof![
        4 => (0u32..17).prop_map(|n| n.to_string()),
        3 => number_text(),
        1 => string_text(),
        1 => json_text(),
    ]
    .boxed()
}

/// `good` nearly always, else any value: fields that read more often than
/// not, so that the reader's later checks (and the rasterizers) are
/// reached with the bad values still in the mix.
fn mostly(good: impl Strategy<Value = String> + 'static) -> BoxedStrategy<String> {
    prop_oneof![30 => good, 1 => any_value()].boxed()
}

/// One of `names`, JSON-quoted, or now and then any string.
fn name_of(names: &'static [&'static str]) -> BoxedStrategy<String> {
    prop_oneof![
        10 => prop::sample::select(names).prop_map(|n| serde_json::to_string(n).unwrap()),
        1 => string_text(),
    ]
    .boxed()
}

/// One of `texts` as they are (JSON already).
fn one_of(texts: &'static [&'static str]) -> BoxedStrategy<String> {
    prop::sample::select(texts).prop_map(str::to_owned).boxed()
}

/// `"key":value` with probability `p`.
fn field(
    key: &'static str,
    value: impl Strategy<Value = String> + 'static,
    p: f64,
) -> BoxedStrategy<Option<String>> {
    prop::option::weighted(
        p,
        value.prop_map(move |v| format!("{}:{v}", serde_json::to_string(key).unwrap())),
    )
    .boxed()
}

/// An object of the fields that are present.
fn object(fields: Vec<BoxedStrategy<Option<String>>>) -> BoxedStrategy<String> {
    fields
        .prop_map(|f| {
            format!(
                "{{{}}}",
                f.into_iter().flatten().collect::<Vec<_>>().join(",")
            )
        })
        .boxed()
}

fn list(
    item: impl Strategy<Value = String> + 'static,
    size: std::ops::Range<usize>,
) -> BoxedStrategy<String> {
    prop::collection::vec(item, size)
        .prop_map(|v| format!("[{}]", v.join(",")))
        .boxed()
}

/// A coordinate near a tiny canvas (half pixels and fractions: ties), or
/// any value.
fn coordinate() -> BoxedStrategy<String> {
    prop_oneof![
        20 => (-8i32..24).prop_map(|n| (f64::from(n) / 2.0).to_string()),
        4 => (-40i64..40, 1i64..9).prop_map(|(a, b)| format!("\"{a}/{b}\"")),
        1 => any_value(),
    ]
    .boxed()
}

fn point() -> BoxedStrategy<String> {
    mostly((coordinate(), coordinate()).prop_map(|(x, y)| format!("[{x},{y}]")))
}

/// A vertex: a position, a moving vertex (`from` and `to`, now and then
/// with a field that may not go with them), an object with `position`,
/// `z`, `w` and `attributes`, half a moving vertex, or any JSON.
fn vertex() -> BoxedStrategy<String> {
    prop_oneof![
        10 => point(),
        10 => object(vec![
            field("from", point(), 0.99),
            field("to", point(), 0.99),
            field("position", point(), 0.02),
            field("z", any_value(), 0.02),
            field("w", any_value(), 0.02),
            field("attributes", list(any_value(), 0..3), 0.02),
        ]),
        2 => object(vec![
            field("position", point(), 0.95),
            field("z", any_value(), 0.3),
            field("w", any_value(), 0.3),
            field("attributes", list(any_value(), 0..4), 0.3),
        ]),
        1 => json_text(),
    ]
    .boxed()
}

/// A vertex that mostly stays put (polygons cannot move).
fn still_vertex() -> BoxedStrategy<String> {
    prop_oneof![20 => point(), 1 => vertex()].boxed()
}

const FILL_RULES: &[&str] = &[
    "top-left",
    "top-right",
    "bottom-left",
    "bottom-right",
    "all-edges",
];
const CULLS: &[&str] = &["none", "cw", "ccw"];
const LINE_RULES: &[&str] = &[
    "parallelogram",
    "parallelogram",
    "parallelogram",
    "midpoint",
    "diamond-exit",
    "rectangle",
];
const POLYGON_FILLS: &[&str] = &["nonzero", "even-odd"];
const AA_PATTERNS: &[&str] = &["grid", "standard", "stratified", "random", "n-rooks"];
const TIME_PATTERNS: &[&str] = &[
    "random",
    "stratified",
    "stratified-shuffled",
    "jittered-xy-t",
];

fn primitive() -> BoxedStrategy<String> {
    let corners = || prop_oneof![20 => list(vertex(), 3..4), 1 => list(vertex(), 0..6)];
    let ends = || prop_oneof![20 => list(vertex(), 2..3), 1 => list(vertex(), 0..4)];
    let contour = || prop_oneof![10 => list(still_vertex(), 3..7), 1 => list(still_vertex(), 0..4)];
    prop_oneof![
        12 => object(vec![
            field("triangle", corners(), 0.98),
            field("interpolation", name_of(&["perspective", "linear", "flat"]), 0.1),
        ]),
        8 => object(vec![
            field("line", ends(), 0.98),
            field("rule", name_of(LINE_RULES), 0.9),
            field("width", mostly(one_of(&["1", "0.5", "2", "1.5", "\"1/4\"", "\"1/3\"", "0", "-1"])), 0.3),
            field("last_pixel", name_of(&["include", "exclude"]), 0.1),
            field("parameter", name_of(&["major", "projected"]), 0.1),
        ]),
        2 => object(vec![
            field("polygon", contour(), 0.98),
            field("fill", name_of(POLYGON_FILLS), 0.5),
        ]),
        2 => object(vec![
            field("contours", prop_oneof![10 => list(contour(), 1..3), 1 => list(contour(), 0..4)], 0.98),
            field("fill", name_of(POLYGON_FILLS), 0.5),
        ]),
        1 => json_text(),
    ]
    .boxed()
}

/// `effects`: `antialias` (samples, pattern, seed, adaptive, resolve,
/// position bits) and `motion_blur` (shutter, samples, pattern, seed),
/// each field present or not, good or bad.
fn effects() -> BoxedStrategy<String> {
    let antialias = object(vec![
        field(
            "samples",
            mostly(one_of(&["1", "2", "3", "4", "4", "9", "0", "257"])),
            0.95,
        ),
        field("pattern", name_of(AA_PATTERNS), 0.7),
        field(
            "seed",
            mostly((0u64..1000).prop_map(|n| n.to_string())),
            0.3,
        ),
        field("adaptive", mostly(one_of(&["true", "false"])), 0.3),
        field("resolve", name_of(&["box"]), 0.1),
        field(
            "position_bits",
            mostly((3u32..18).prop_map(|n| n.to_string())),
            0.3,
        ),
    ]);
    let shutter = prop_oneof![
        8 => one_of(&[
            "[0,1]", "[0,0.5]", "[\"1/4\",\"3/4\"]", "[0.5,1]", "[\"1/65536\",1]",
            "[0,\"1/65536\"]", "[0.25,0.375]",
        ]),
        1 => one_of(&[
            "[1,0]", "[0.5,0.5]", "[\"1/3\",1]", "[0]", "[0,1,1]", "[-1,1]", "[0,2]", "{}",
            "[\"1/131072\",1]",
        ]),
        1 => (any_value(), any_value()).prop_map(|(a, b)| format!("[{a},{b}]")),
    ];
    let motion_blur = object(vec![
        field("shutter", shutter, 0.5),
        field(
            "samples",
            mostly(one_of(&["1", "2", "3", "4", "8", "16", "0", "1025"])),
            0.95,
        ),
        field("pattern", name_of(TIME_PATTERNS), 0.7),
        field(
            "seed",
            mostly(prop_oneof![
                4 => (0u64..1000).prop_map(|n| n.to_string()),
                1 => any::<u64>().prop_map(|n| n.to_string()),
                1 => Just("-1".to_owned()),
            ]),
            0.5,
        ),
    ]);
    object(vec![
        field("antialias", antialias, 0.25),
        field("motion_blur", motion_blur, 0.9),
    ])
}

/// `expect`: the sample expectations (which a moving scene refuses) now
/// and then, and the time ones: bounds and pins of pixels.
fn expect() -> BoxedStrategy<String> {
    let pin = object(vec![
        field(
            "pixel",
            mostly((0u32..5, 0u32..5).prop_map(|(x, y)| format!("[{x},{y}]"))),
            0.95,
        ),
        field(
            "value",
            mostly(one_of(&["0", "0.5", "1", "\"1/3\"", "2", "-0.5"])),
            0.95,
        ),
    ]);
    object(vec![
        field("max_mismatched_samples", any_value(), 0.03),
        field("watertight", mostly(one_of(&["true", "false"])), 0.03),
        field("samples_covered", any_value(), 0.03),
        field("max_abs_error", any_value(), 0.03),
        field("max_ulp_error", any_value(), 0.03),
        field("max_coverage_error", any_value(), 0.03),
        field("area", any_value(), 0.03),
        field(
            "max_time_error",
            mostly(one_of(&["0.5", "1", "0.25", "0", "-1"])),
            0.3,
        ),
        field(
            "max_time_rms",
            mostly(one_of(&["0.5", "0.2", "1", "0"])),
            0.3,
        ),
        field("time_coverage", list(pin, 0..3), 0.3),
    ])
}

/// A case-shaped object whose values are plausible or random JSON, so the
/// reader gets past its first checks: tiny canvases (the drawn cases stay
/// fast), triangles, lines and polygons whose vertices may move, effects
/// and expectations, every field sometimes missing or wrong.
pub(crate) fn case_shaped() -> impl Strategy<Value = String> {
    let side = || mostly((1u32..7).prop_map(|n| n.to_string()));
    let rules = object(vec![
        field(
            "subpixel_bits",
            mostly(
                prop_oneof![6 => (0u32..17).prop_map(|n| n.to_string()), 1 => Just("null".to_owned())],
            ),
            0.95,
        ),
        field("fill_rule", name_of(FILL_RULES), 0.8),
        field("cull", name_of(CULLS), 0.6),
    ]);
    object(vec![
        field(
            "name",
            prop_oneof![8 => Just("\"shaped\"".to_owned()), 1 => string_text()],
            0.99,
        ),
        field("description", string_text(), 0.1),
        field(
            "canvas",
            object(vec![
                field("width", side(), 0.99),
                field("height", side(), 0.99),
            ]),
            0.99,
        ),
        field("rules", rules, 0.95),
        field(
            "primitives",
            prop_oneof![10 => list(primitive(), 1..4), 1 => list(primitive(), 0..6)],
            0.99,
        ),
        field("effects", effects(), 0.9),
        field("expect", expect(), 0.6),
    ])
}

/// Nesting far beyond serde_json's recursion limit, bare or inside a case.
pub(crate) fn deep_nesting() -> impl Strategy<Value = String> {
    (1usize..3000, any::<bool>(), any::<bool>(), any::<bool>()).prop_map(
        |(depth, objects, closed, in_case)| {
            let (open, close) = if objects {
                (r#"{"a":"#, "}")
            } else {
                ("[", "]")
            };
            let mut s = open.repeat(depth);
            s.push('1');
            if closed {
                s.push_str(&close.repeat(depth));
            }
            if in_case {
                format!(r#"{{"name":"deep","canvas":{{"width":4,"height":4}},"primitives":[{{"triangle":[{s},[0,0],[1,1]]}}]}}"#)
            } else {
                s
            }
        },
    )
}
