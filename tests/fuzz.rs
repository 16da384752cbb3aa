//! Robustness of the case reader and the binary against hostile input.
//!
//! - `parse_case` is fed arbitrary strings, random JSON (extreme numbers,
//!   non-finite strings, deep nesting, case-shaped objects with random
//!   values: triangles, lines and polygons, moving vertices, antialiasing
//!   and motion blur, time expectations) and mutations of the real case
//!   files under `cases/`, the moving ones included (byte flips,
//!   truncations, duplicated keys, swapped types, extreme numbers). It must
//!   never panic, and every error must name a location: a JSON path
//!   (`$...`) or `line L column C`. Cases that read are drawn by the
//!   reference and production, which must not panic either (moving scenes
//!   too, when small enough for the certified oracle to stay fast).
//! - The binary runs a folder of mutated case files and must exit 0, 1 or
//!   2, never panic, and report every file.
//!
//! `RASTERCHECK_FUZZ_CASES` scales the work (default 1000): each proptest
//! property runs that many inputs, and the binary gets a tenth as many files
//! (at least 200). `RASTERCHECK_FUZZ_SEED` changes the binary test's
//! mutations (default fixed). For example:
//! `RASTERCHECK_FUZZ_CASES=20000 cargo test --release --test fuzz`.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::process::Command;

use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, TestRunner};
use rastercheck::plan::Plan;
use rastercheck::production::Production;
use rastercheck::rasterizer::{RasterError, Rasterizer};
use rastercheck::reference;
use rastercheck::scene::{parse_case, Limits, Scene};
use serde_json::Value;

fn fuzz_cases() -> u32 {
    std::env::var("RASTERCHECK_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1000)
}

fn config() -> Config {
    Config {
        cases: fuzz_cases(),
        failure_persistence: None,
        ..Config::default()
    }
}

/// Every case file under `cases/`, valid and invalid, as text.
fn case_texts() -> Vec<String> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "json") {
                out.push(path);
            }
        }
    }
    let mut paths = Vec::new();
    walk(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("cases"),
        &mut paths,
    );
    paths.sort();
    assert!(paths.len() > 50, "expected the case files under cases/");
    paths
        .iter()
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect()
}

/// Whether an error location is a JSON path or a line and column.
fn names_a_location(location: &str) -> bool {
    if location.starts_with('$') {
        return true;
    }
    let words: Vec<&str> = location.split(' ').collect();
    matches!(words.as_slice(), ["line", l, "column", c]
        if l.parse::<u64>().is_ok() && c.parse::<u64>().is_ok())
}

thread_local! {
    /// What [`check`] drew on this thread: scenes, and scenes in which
    /// something moves.
    static DRAWN: std::cell::Cell<[u64; 2]> = const { std::cell::Cell::new([0, 0]) };
}

/// Whether a moving scene is too much work for a property test: the
/// oracle certifies each spatial sample of each moving primitive (about
/// 10 µs each), and production tests each at N instants.
fn too_slow(scene: &Scene, plan: &Plan) -> bool {
    let Some(motion) = &plan.motion else {
        return false;
    };
    let moving = motion.moving.iter().filter(|m| **m).count() as u64;
    let samples = scene.canvas.pixel_count() as u64 * u64::from(plan.samples_per_pixel) * moving;
    samples > 4096 || samples * u64::from(motion.blur.samples) > 1 << 20
}

/// Reads `text`; asserts the reader neither panics nor returns an error
/// without a location; draws what reads (on small canvases) with the
/// reference and production, which must not panic.
fn check(text: &str) -> Result<(), TestCaseError> {
    let limits = Limits {
        max_canvas_pixels: 64 * 64,
        max_primitives: 2000,
        ..Limits::default()
    };
    let result = catch_unwind(|| parse_case(text, "fuzz.json", &limits));
    prop_assert!(result.is_ok(), "the reader panicked on {:?}", text);
    match result.unwrap() {
        Err(e) => {
            prop_assert_eq!(&e.file, "fuzz.json");
            prop_assert!(
                names_a_location(&e.location),
                "no location in {:?} for {:?}",
                e.to_string(),
                text
            );
            prop_assert!(!e.message.is_empty());
        }
        Ok(scene) => {
            let plan = Plan::for_scene(&scene);
            if too_slow(&scene, &plan) {
                return Ok(());
            }
            DRAWN.with(|d| {
                let [all, moving] = d.get();
                d.set([all + 1, moving + u64::from(plan.motion.is_some())]);
            });
            let drawn = catch_unwind(AssertUnwindSafe(|| reference::render(&scene, &plan)));
            prop_assert!(drawn.is_ok(), "the reference panicked on {:?}", text);
            let drawn = catch_unwind(AssertUnwindSafe(|| Production.rasterize(&scene, &plan)));
            prop_assert!(drawn.is_ok(), "production panicked on {:?}", text);
            if let Err(RasterError::Failed(why)) = drawn.unwrap() {
                prop_assert!(false, "production broke ({}) on {:?}", why, text);
            }
        }
    }
    Ok(())
}

// --- Random JSON -----------------------------------------------------------

/// Number texts: ordinary, extreme exponents, too many digits, negative
/// zero, and the limits of the documented ranges a hair either side.
fn number_text() -> impl Strategy<Value = String> {
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
fn string_text() -> impl Strategy<Value = String> {
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
fn json_text() -> impl Strategy<Value = String> {
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
fn case_shaped() -> impl Strategy<Value = String> {
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
fn deep_nesting() -> impl Strategy<Value = String> {
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

// --- Mutations of the real case files --------------------------------------

#[derive(Clone, Debug)]
enum Mutation {
    FlipByte(usize, u8),
    InsertByte(usize, u8),
    DeleteRange(usize, usize),
    Truncate(usize),
    DuplicateRange(usize, usize),
    /// Replace the k-th JSON value (in document order) by another of a
    /// different type, or by an extreme number.
    Replace(usize, String),
    /// Add a second copy of the k-th object's first key, with a new value.
    DuplicateKey(usize, String),
    /// Remove the k-th object's or array's k-th entry.
    Remove(usize, usize),
    /// Move the k-th number (in document order) by a small amount, keeping
    /// the case readable more often than not.
    Nudge(usize, String),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let replacement = prop_oneof![
        3 => number_text(),
        2 => string_text(),
        1 => json_text(),
        1 => Just("null".to_owned()),
        1 => Just("[]".to_owned()),
        1 => Just("{}".to_owned()),
        1 => Just("true".to_owned()),
    ];
    prop_oneof![
        2 => (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Mutation::FlipByte(i, b)),
        1 => (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Mutation::InsertByte(i, b)),
        1 => (any::<usize>(), 1usize..64).prop_map(|(i, n)| Mutation::DeleteRange(i, n)),
        1 => any::<usize>().prop_map(Mutation::Truncate),
        1 => (any::<usize>(), 1usize..256).prop_map(|(i, n)| Mutation::DuplicateRange(i, n)),
        6 => (any::<usize>(), replacement.clone()).prop_map(|(k, v)| Mutation::Replace(k, v)),
        2 => (any::<usize>(), replacement).prop_map(|(k, v)| Mutation::DuplicateKey(k, v)),
        2 => (any::<usize>(), any::<usize>()).prop_map(|(k, i)| Mutation::Remove(k, i)),
        4 => (any::<usize>(), prop::sample::select(vec!["1", "-1", "0.5", "-0.5", "1/3", "-1/256", "1/65536", "8", "-8"]))
            .prop_map(|(k, d)| Mutation::Nudge(k, d.to_owned())),
    ]
}

/// A marker string that stands for raw JSON text while a `Value` is
/// serialized, so that replacements keep their exact spelling (numbers
/// with huge exponents, duplicate keys).
const MARK: &str = "\u{1}RAW\u{1}";

fn marked() -> String {
    serde_json::to_string(MARK).unwrap()
}

/// The k-th value of `v` in document order (k modulo the count).
fn nth_value(v: &mut Value, k: usize) -> &mut Value {
    fn count(v: &Value) -> usize {
        1 + match v {
            Value::Array(a) => a.iter().map(count).sum(),
            Value::Object(o) => o.values().map(count).sum(),
            _ => 0,
        }
    }
    fn find(v: &mut Value, k: usize) -> &mut Value {
        if k == 0 {
            return v;
        }
        let mut k = k - 1;
        let children: Vec<&mut Value> = match v {
            Value::Array(a) => a.iter_mut().collect(),
            Value::Object(o) => o.values_mut().collect(),
            _ => unreachable!("k is below the count"),
        };
        for child in children {
            let n = count(child);
            if k < n {
                return find(child, k);
            }
            k -= n;
        }
        unreachable!("k is below the count")
    }
    let k = k % count(v);
    find(v, k)
}

/// Applies a mutation. Text mutations may split a multi-byte character;
/// the bytes are then read lossily, as a file of bad UTF-8 would not reach
/// the reader anyway.
fn mutate(text: &str, m: &Mutation) -> String {
    let bytes = text.as_bytes();
    let at = |i: usize| i % (bytes.len() + 1);
    let lossy = |b: Vec<u8>| String::from_utf8_lossy(&b).into_owned();
    match m {
        Mutation::FlipByte(i, b) => {
            let mut b2 = bytes.to_vec();
            if !b2.is_empty() {
                let i = i % b2.len();
                b2[i] ^= b.max(&1);
            }
            lossy(b2)
        }
        Mutation::InsertByte(i, b) => {
            let mut b2 = bytes.to_vec();
            b2.insert(at(*i), *b);
            lossy(b2)
        }
        Mutation::DeleteRange(i, n) => {
            let start = at(*i);
            let end = (start + n).min(bytes.len());
            lossy([&bytes[..start], &bytes[end..]].concat())
        }
        Mutation::Truncate(i) => lossy(bytes[..at(*i)].to_vec()),
        Mutation::DuplicateRange(i, n) => {
            let start = at(*i);
            let end = (start + n).min(bytes.len());
            lossy([&bytes[..end], &bytes[start..]].concat())
        }
        Mutation::Replace(k, raw) => with_value(text, |v| {
            *nth_value(v, *k) = Value::String(MARK.to_owned());
            Some(raw.clone())
        }),
        Mutation::DuplicateKey(k, raw) => with_value(text, |v| {
            let Value::Object(o) = nth_value(v, *k) else {
                return None;
            };
            let key = o.keys().next()?.clone();
            // serde_json's map keeps one entry per key: write the duplicate
            // as raw text right after the first.
            let first = o
                .insert(key.clone(), Value::String(MARK.to_owned()))
                .unwrap();
            Some(format!(
                "{}, {}: {raw}",
                first,
                serde_json::to_string(&key).unwrap()
            ))
        }),
        Mutation::Nudge(k, delta) => with_value(text, |v| {
            let mut numbers = Vec::new();
            collect_numbers(v, &mut numbers);
            if numbers.is_empty() {
                return None;
            }
            let n = numbers.swap_remove(k % numbers.len());
            let old = n.to_string();
            *n = Value::String(MARK.to_owned());
            // The sum is exact; write it as a fraction string when the
            // delta is one, as the decimal text otherwise.
            Some(match rastercheck::scene::Number::from_decimal(&old) {
                Ok(x) => {
                    let d = rastercheck::scene::Number::from_string(delta).unwrap();
                    let sum = &x + &d;
                    let s = sum.to_exact_string();
                    if s.contains('/') {
                        format!("\"{s}\"")
                    } else {
                        s
                    }
                }
                Err(_) => old,
            })
        }),
        Mutation::Remove(k, i) => with_value(text, |v| {
            match nth_value(v, *k) {
                Value::Array(a) if !a.is_empty() => {
                    let i = i % a.len();
                    a.remove(i);
                }
                Value::Object(o) if !o.is_empty() => {
                    let key = o.keys().nth(i % o.len()).unwrap().clone();
                    o.remove(&key);
                }
                _ => {}
            }
            None
        }),
    }
}

fn collect_numbers<'v>(v: &'v mut Value, out: &mut Vec<&'v mut Value>) {
    match v {
        Value::Number(_) => out.push(v),
        Value::Array(a) => a.iter_mut().for_each(|c| collect_numbers(c, out)),
        Value::Object(o) => o.values_mut().for_each(|c| collect_numbers(c, out)),
        _ => {}
    }
}

/// Parses `text` as JSON, lets `edit` change it (placing `MARK` where raw
/// text goes), and writes it back. Text that is not JSON is returned as is.
fn with_value(text: &str, edit: impl FnOnce(&mut Value) -> Option<String>) -> String {
    let Ok(mut v) = serde_json::from_str::<Value>(text) else {
        return text.to_owned();
    };
    let raw = edit(&mut v);
    let out = serde_json::to_string_pretty(&v).unwrap();
    match raw {
        Some(raw) => out.replacen(&marked(), &raw, 1),
        None => out,
    }
}

fn mutated_case(texts: Vec<String>) -> impl Strategy<Value = String> {
    (
        prop::sample::select(texts),
        prop::collection::vec(mutation(), 1..4),
    )
        .prop_map(|(text, mutations)| mutations.iter().fold(text, |t, m| mutate(&t, m)))
}

/// Runs a property on a thread with a large stack: generating and
/// shrinking proptest's recursive JSON strategy nests deeply (the reader
/// itself stops at serde_json's recursion limit of 128 and is fine on the
/// default stack, which `deep_nesting` checks).
/// Returns how many read cases were drawn, and how many of those move.
fn run<S: Strategy<Value = String>>(
    name: &str,
    strategy: impl FnOnce() -> S + Send + 'static,
) -> [u64; 2] {
    let name = name.to_owned();
    std::thread::Builder::new()
        .stack_size(256 << 20)
        .spawn(move || {
            let mut runner = TestRunner::new(config());
            let result = runner.run(&strategy(), |text| check(&text));
            if let Err(e) = result {
                panic!("{name}: {e}");
            }
            DRAWN.with(|d| d.get())
        })
        .unwrap()
        .join()
        .unwrap()
}

#[test]
fn the_reader_survives_arbitrary_strings() {
    run("arbitrary strings", || {
        prop_oneof![
            any::<String>(),
            "[\\[\\]{}\":,0-9eE.+\\- a-z/]{0,200}",
            prop::collection::vec(any::<u8>(), 0..300)
                .prop_map(|b| String::from_utf8_lossy(&b).into_owned()),
        ]
    });
}

#[test]
fn the_reader_survives_random_json() {
    let [drawn, moving] = run(
        "random JSON",
        || prop_oneof![1 => json_text(), 2 => case_shaped(), 1 => deep_nesting()],
    );
    eprintln!("random JSON: {drawn} cases drawn, {moving} of them moving");
    // Case-shaped input reaches the rasterizers, moving scenes included
    // (about 1 in 25 case-shaped inputs reads; 2 in 3 of those move).
    if fuzz_cases() >= 1000 {
        assert!(moving >= 3, "{drawn} drawn, {moving} moving");
    }
}

#[test]
fn the_reader_survives_mutated_case_files() {
    let texts = case_texts();
    let moving_files = texts.iter().filter(|t| t.contains("\"from\"")).count();
    assert!(moving_files >= 20, "the motion cases are among them");
    let [drawn, moving] = run("mutated case files", || mutated_case(texts));
    eprintln!("mutated case files: {drawn} cases drawn, {moving} of them moving");
    if fuzz_cases() >= 1000 {
        assert!(moving >= 3, "{drawn} drawn, {moving} moving");
    }
}

// --- The binary --------------------------------------------------------------

/// A small deterministic generator for the binary test (proptest's runner
/// is for properties; here we want one folder of files).
struct XorShift(u64);

impl XorShift {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
}

#[test]
fn the_binary_survives_a_folder_of_mutated_cases() {
    let files = (fuzz_cases() as usize / 10).max(200);
    let seed: u64 = std::env::var("RASTERCHECK_FUZZ_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0x5eed_cafe_f00d);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("fuzz-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let cases = dir.join("cases").join("fuzz");
    std::fs::create_dir_all(&cases).unwrap();

    let texts = case_texts();
    let strategy = (
        prop::sample::select(texts),
        prop::collection::vec(mutation(), 1..4),
    );
    let mut runner = TestRunner::new_with_rng(
        Config::default(),
        proptest::test_runner::TestRng::from_seed(proptest::test_runner::RngAlgorithm::ChaCha, &{
            let mut rng = XorShift(seed | 1);
            let mut bytes = [0u8; 32];
            for chunk in bytes.chunks_mut(8) {
                chunk.copy_from_slice(&rng.next().to_le_bytes());
            }
            bytes
        }),
    );
    for i in 0..files {
        let (text, mut mutations) = strategy.new_tree(&mut runner).unwrap().current();
        // Half the files get only nudged numbers, so that most of them
        // still read and run through every stage.
        if i % 2 == 0 {
            mutations.retain(|m| matches!(m, Mutation::Nudge(..)));
        }
        let mut text = mutations.iter().fold(text, |t, m| mutate(&t, m));
        // Give each readable case its own name: duplicate names are bad
        // input of their own (tested in tests/cli.rs).
        if let Ok(Value::Object(mut o)) = serde_json::from_str::<Value>(&text) {
            if o.get("name").is_some_and(Value::is_string) {
                o.insert("name".to_owned(), Value::String(format!("fuzz {i}")));
                text = serde_json::to_string_pretty(&Value::Object(o)).unwrap();
            }
        }
        std::fs::write(cases.join(format!("{i:05}.json")), text).unwrap();
    }

    let out = Command::new(env!("CARGO_BIN_EXE_rastercheck"))
        .current_dir(&dir)
        .args([
            "run",
            "cases",
            "-q",
            "-r",
            "production",
            "-r",
            "dda-f32",
            "-r",
            "float-f64",
            "--max-canvas-pixels",
            "65536",
            "--report",
            "report",
        ])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let all = format!("{stdout}\n{stderr}");
    let tail: String = {
        let lines: Vec<&str> = all.lines().collect();
        lines[lines.len().saturating_sub(40)..].join("\n")
    };
    assert!(
        matches!(out.status.code(), Some(0..=2)),
        "exit status {:?} (seed {seed}, files in {}):\n{tail}",
        out.status,
        dir.display()
    );
    assert!(
        !all.contains("panicked"),
        "a panic (seed {seed}, files in {}):\n{}",
        dir.display(),
        all.lines()
            .filter(|l| l.contains("panicked"))
            .take(10)
            .collect::<Vec<_>>()
            .join("\n")
    );
    assert!(
        stdout.contains(&format!("\n{files} case files, ")),
        "the summary does not count {files} files (seed {seed}):\n{tail}"
    );
    let report: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("report/report.json")).unwrap())
            .unwrap();
    assert_eq!(report["complete"], true);
    assert_eq!(report["cases"].as_array().unwrap().len(), files);
    let _ = std::fs::remove_dir_all(&dir);
}
