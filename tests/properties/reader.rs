//! The reader at the edges of the range: every number slot at its limits
//! and beyond, and the count limits of whole objects.

use proptest::prelude::*;
use rastercheck::scene::{parse_case, Limits};

// --- The reader at the edges of the range ---------------------------------

/// What a slot of the template case holds, which decides its range.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Slot {
    Side,
    Bits,
    Coord,
    Value,
    W,
    Width,
    Tolerance,
}

/// The template's slots: JSON path, kind, and in-range default.
fn slots() -> Vec<(String, Slot, &'static str)> {
    let mut s = vec![
        ("$.canvas.width".to_owned(), Slot::Side, "8"),
        ("$.canvas.height".to_owned(), Slot::Side, "8"),
        ("$.rules.subpixel_bits".to_owned(), Slot::Bits, "8"),
    ];
    let defaults = [["0", "0"], ["8", "0"], ["0", "8"]];
    for (i, d) in defaults.iter().enumerate() {
        let v = format!("$.primitives[0].triangle[{i}]");
        s.push((format!("{v}.position[0]"), Slot::Coord, d[0]));
        s.push((format!("{v}.position[1]"), Slot::Coord, d[1]));
        s.push((format!("{v}.z"), Slot::Value, "0.5"));
        s.push((format!("{v}.w"), Slot::W, "1"));
        s.push((format!("{v}.attributes[0]"), Slot::Value, "-3"));
    }
    for i in 0..2 {
        s.push((
            format!("$.primitives[1].line[{i}].position[0]"),
            Slot::Coord,
            "1",
        ));
        s.push((
            format!("$.primitives[1].line[{i}].position[1]"),
            Slot::Coord,
            "2",
        ));
    }
    s.push(("$.primitives[1].width".to_owned(), Slot::Width, "2"));
    s.push((
        "$.expect.max_abs_error".to_owned(),
        Slot::Tolerance,
        "0.001",
    ));
    s
}

/// The template case with `texts` in its slots (in `slots()` order).
fn template(texts: &[String]) -> String {
    let mut t = texts.iter();
    let mut n = || t.next().unwrap().clone();
    let canvas = format!(r#"{{"width": {}, "height": {}}}"#, n(), n());
    let rules = format!(r#"{{"subpixel_bits": {}, "fill_rule": "top-left"}}"#, n());
    let vertices: Vec<String> = (0..3)
        .map(|_| {
            format!(
                r#"{{"position": [{}, {}], "z": {}, "w": {}, "attributes": [{}, 1]}}"#,
                n(),
                n(),
                n(),
                n(),
                n()
            )
        })
        .collect();
    let ends: Vec<String> = (0..2)
        .map(|_| {
            format!(
                r#"{{"position": [{}, {}], "attributes": [0, 0]}}"#,
                n(),
                n()
            )
        })
        .collect();
    let line = format!("[{}]", ends.join(", "));
    format!(
        r#"{{"name": "range", "canvas": {canvas}, "rules": {rules},
  "primitives": [{{"triangle": [{}]}},
    {{"line": {line}, "rule": "rectangle", "width": {}, "interpolation": "linear"}}],
  "expect": {{"max_abs_error": {}}}}}"#,
        vertices.join(", "),
        n(),
        n()
    )
}

/// Exact text for `base + sign · step/den`, as a JSON number or fraction
/// string.
fn offset_text(base: i128, step: i128, den: i128, as_fraction: bool) -> String {
    let n = base * den + step;
    if as_fraction {
        format!("\"{n}/{den}\"")
    } else if den == 1 {
        format!("{n}")
    } else {
        // den is a power of ten here.
        let digits = den.to_string().len() - 1;
        let (sign, m) = if n < 0 { ("-", -n) } else { ("", n) };
        let int = m / den;
        let frac = m % den;
        format!("{sign}{int}.{frac:0digits$}")
    }
}

/// A value for a slot of kind `slot` and whether it is in range: the limits
/// themselves, a hair inside or outside them, far outside, the wrong sign,
/// non-finite strings, and numbers too long to read.
fn slot_value(slot: Slot) -> impl Strategy<Value = (String, bool)> {
    let (lo, hi, lo_open): (i128, i128, bool) = match slot {
        Slot::Side => (1, 16384, false),
        Slot::Bits => (0, 16, false),
        Slot::Coord => (-32768, 32768, false),
        Slot::Value => (-1_000_000_000_000, 1_000_000_000_000, false),
        // w ≥ 10^-6: scaled by the denominator below.
        Slot::W => (0, 1_000_000, false),
        Slot::Width => (0, 1024, true),
        Slot::Tolerance => (0, 1_000_000_000_000, false),
    };
    let integral = matches!(slot, Slot::Side | Slot::Bits);
    let dens: Vec<i128> = if integral {
        vec![1]
    } else {
        vec![1, 10, 1_000_000, 1 << 40, 3, 1_000_000_000_000]
    };
    (
        prop::sample::select(dens),
        0u8..8,
        any::<bool>(),
        1i128..1000,
    )
        .prop_map(move |(den, pick, as_fraction, far)| {
            let frac = as_fraction || ![1, 10, 1_000_000, 1_000_000_000_000].contains(&den);
            match pick {
                // The limits themselves (open at 0 for widths, at 10^-6 for w).
                0 => match slot {
                    Slot::W => (
                        offset_text(0, den / 1_000_000, den, frac),
                        den % 1_000_000 == 0,
                    ),
                    _ => (offset_text(lo, 0, den, frac), !lo_open),
                },
                1 => (offset_text(hi, 0, den, frac), true),
                // A hair outside.
                2 => match slot {
                    Slot::W => (offset_text(0, den / 1_000_000 - 1, den, frac), false),
                    _ => (offset_text(lo, -1, den, frac), false),
                },
                3 => (offset_text(hi, 1, den, frac), false),
                // Far outside.
                4 => (offset_text(hi * far, 1, den, frac), false),
                5 => (offset_text(-hi * far - 1, 0, 1, false), false),
                6 => (prop_oneof_text(far as usize, slot), false),
                // A hair inside.
                _ => match slot {
                    Slot::W | Slot::Side | Slot::Bits => (
                        offset_text(hi, -1, den, frac),
                        hi * den > lo * den + if slot == Slot::W { den / 1_000_000 } else { 0 },
                    ),
                    _ => (offset_text(lo, 1, den, frac), true),
                },
            }
        })
}

/// Texts that are never numbers in range: non-finite strings, zero
/// denominators, too many digits, too large exponents; for integer slots,
/// fractions.
fn prop_oneof_text(k: usize, slot: Slot) -> String {
    let texts = [
        "\"NaN\"".to_owned(),
        "\"-Infinity\"".to_owned(),
        "\"inf\"".to_owned(),
        "\"1/0\"".to_owned(),
        format!("1{}", "0".repeat(1000)),
        "1e1001".to_owned(),
        "1e-1001".to_owned(),
        "\"1e999999999\"".to_owned(),
        "true".to_owned(),
        "[1]".to_owned(),
    ];
    match slot {
        Slot::Side | Slot::Bits if k % 3 < 1 => "\"3/2\"".to_owned(),
        _ => texts[k % texts.len()].clone(),
    }
}

proptest! {
    /// Every number slot of a case, at its documented limits, a hair either
    /// side and far beyond: in range it reads, out of range the reader
    /// returns an error naming that slot's JSON path (never a panic).
    #[test]
    fn the_reader_accepts_the_range_and_names_the_path_beyond_it(
        (index, (text, valid)) in (0..slots().len()).prop_flat_map(|i| (Just(i), slot_value(slots()[i].1)))
    ) {
        let slots = slots();
        let mut texts: Vec<String> = slots.iter().map(|s| s.2.to_owned()).collect();
        texts[index] = text.clone();
        let case = template(&texts);
        let result = std::panic::catch_unwind(|| parse_case(&case, "range.json", &Limits::default()));
        prop_assert!(result.is_ok(), "the reader panicked on {}", case);
        match result.unwrap() {
            Ok(_) => prop_assert!(valid, "{} = {} was accepted", slots[index].0, text),
            Err(e) => {
                prop_assert!(!valid, "{} = {} was refused: {}", slots[index].0, text, e);
                prop_assert_eq!(&e.location, &slots[index].0, "{} = {}: {}", slots[index].0, text, e);
            }
        }
    }
}

/// The limits that belong to a whole object rather than one number.
#[test]
fn the_reader_names_the_object_that_breaks_a_count_limit() {
    let parse = |text: &str| parse_case(text, "limits.json", &Limits::default());
    let triangle = r#"{"triangle": [[0, 0], [1, 0], [0, 1]]}"#;
    let case = |canvas: &str, primitives: &str| {
        format!(r#"{{"name": "n", "canvas": {canvas}, "primitives": [{primitives}]}}"#)
    };
    let e = parse(&case(r#"{"width": 16384, "height": 1025}"#, triangle)).unwrap_err();
    assert_eq!(e.location, "$.canvas", "{e}");
    assert!(parse(&case(r#"{"width": 16384, "height": 1024}"#, triangle)).is_ok());
    let vertex = |n: usize| {
        format!(
            r#"{{"position": [0, 0], "attributes": [{}]}}"#,
            vec!["1"; n].join(", ")
        )
    };
    let with_attributes = |n: usize| format!(r#"{{"triangle": [{v}, {v}, {v}]}}"#, v = vertex(n));
    assert!(parse(&case(r#"{"width": 4, "height": 4}"#, &with_attributes(16))).is_ok());
    let e = parse(&case(r#"{"width": 4, "height": 4}"#, &with_attributes(17))).unwrap_err();
    assert_eq!(e.location, "$.primitives[0].triangle[0].attributes", "{e}");
    let many = vec![triangle; 100_001].join(",");
    let e = parse(&case(r#"{"width": 4, "height": 4}"#, &many)).unwrap_err();
    assert_eq!(e.location, "$.primitives", "{e}");
}
