//! The baseline file's model: round trips, checks, tolerance overrides;
//! and the helpers `compare.rs`'s tests build baselines with.

use std::collections::BTreeMap;

use super::entry::{Entry, Value};
use super::file::{Baseline, SelectionInfo, SCHEMA};
use super::observe::Observed;
use super::tolerance::{Tolerance, Tolerances};

pub(super) fn entry(case: &str, verdict: &str, metrics: &[(&str, f64)]) -> Entry {
    Entry {
        case: case.into(),
        rasterizer: "r".into(),
        verdict: verdict.into(),
        metrics: metrics
            .iter()
            .map(|(k, v)| ((*k).to_owned(), Value(*v)))
            .collect(),
    }
}

pub(super) fn baseline(entries: Vec<Entry>) -> Baseline {
    Baseline::new(
        vec!["baseline".into()],
        SelectionInfo::default(),
        &Observed {
            entries,
            problems: BTreeMap::new(),
        },
    )
}

#[test]
fn the_file_round_trips_and_is_checked() {
    let b = baseline(vec![entry(
        "a",
        "foil",
        &[
            ("coverage.extra", 2.0),
            ("depth.rms", 1.5e-7),
            ("depth.max_abs", f64::INFINITY),
        ],
    )]);
    let text = b.to_json();
    assert!(text.contains("\"coverage.extra\": 2,"), "{text}");
    assert!(text.contains("\"depth.max_abs\": \"inf\""), "{text}");
    assert_eq!(Baseline::parse(&text).unwrap(), b);
    assert_eq!(b.to_json(), Baseline::parse(&text).unwrap().to_json());

    let bad = text.replace("\"relative\": 0.01", "\"relative\": -1");
    assert!(Baseline::parse(&bad).unwrap_err().contains("relative"));
    let bad = text.replace(SCHEMA, "rastercheck-baseline/9");
    assert!(Baseline::parse(&bad)
        .unwrap_err()
        .contains("rastercheck-baseline/9"));
    let bad = text.replace("\"foil\"", "\"fine\"");
    assert!(Baseline::parse(&bad)
        .unwrap_err()
        .contains("unknown verdict"));
    assert!(Baseline::parse("{").unwrap_err().contains(SCHEMA));
}

#[test]
fn overrides_apply_by_name_then_kind() {
    let mut t = Tolerances::default();
    t.overrides.insert(
        "rms".into(),
        Tolerance {
            relative: 1.0,
            absolute: 0.0,
        },
    );
    t.overrides.insert(
        "depth.rms".into(),
        Tolerance {
            relative: 2.0,
            absolute: 0.0,
        },
    );
    assert_eq!(t.for_metric("attribute 0.rms").relative, 1.0);
    assert_eq!(t.for_metric("depth.rms").relative, 2.0);
    assert_eq!(t.for_metric("depth.max_abs").relative, 0.01);
    assert_eq!(t.for_metric("coverage.missing").relative, 0.0);
}
