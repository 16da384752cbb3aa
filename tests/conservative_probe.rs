//! `probe` finds a conservative rasterizer and measures its uncertainty
//! (issue 38): the exact conservative example
//! (`examples/conservative_rasterizer.py --always U`, which grows every
//! triangle by U and declares nothing) is found any-coverage, and the
//! needles of `explore/probe/conservative.rs` give back U exactly, to
//! 2^-16 px, along x and y (for U ≥ 1/32 px the sampler probe calls it
//! unknown, and the needles still find it); a point sampler gets no such
//! finding.

use rastercheck::explore::probe::{self, Profile, Reach, SamplerKind};
use rastercheck::registry;
use rastercheck::scene::Number;

fn probe_of(name: &str) -> Profile {
    // The hello read once first, as a run does (a slow start is waited for).
    rastercheck::adapters::external::preflight(name).unwrap();
    let r = registry::by_name(name).unwrap_or_else(|| panic!("no rasterizer {name}"));
    let p = probe::probe(r.as_ref()).unwrap_or_else(|e| panic!("{name}: {e}"));
    eprintln!("{}", p.describe());
    p
}

/// The example drawing every triangle grown by `u`, declaring nothing.
fn example(u: &str) -> String {
    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/conservative_rasterizer.py"
    );
    format!("external-persistent:python3 {script} --always {u}")
}

fn exact(n: Number) -> String {
    n.to_exact_string()
}

/// Each uncertainty is measured exactly: drawn at a gap of u, not at
/// u + 2^-16, along both axes, and said so in the profile's words.
#[test]
fn the_uncertainty_of_a_conservative_program_is_measured_exactly() {
    for (u, p, q) in [
        ("0", 0, 1 << 20),
        ("1/512", 1, 512),
        ("1/4", 1, 4),
        ("3/4", 3, 4),
    ] {
        let profile = probe_of(&example(u));
        // Grown by 1/32 px or more, the sampler probe's slivers spill into
        // their neighbours: any-coverage is not recognised there, and the
        // needles still measure it.
        let sampler = if q >= 32 {
            SamplerKind::AnyCoverage
        } else {
            SamplerKind::Unknown
        };
        assert_eq!(profile.sampler, sampler, "u = {u}");
        let found = profile
            .conservative
            .expect("an any-coverage rasterizer is measured");
        let want = Number::ratio(p, q);
        let next = &want + &Number::ratio(1, 65536);
        let reach = Reach {
            largest_drawn: Some(exact(want.clone())),
            smallest_missed: Some(exact(next)),
            monotone: true,
        };
        assert_eq!(found.x, reach, "u = {u}, along x");
        assert_eq!(found.y, reach, "u = {u}, along y");
        assert!(
            found
                .uncertainty
                .starts_with(&format!("{} px", exact(want)))
                && found.uncertainty.ends_with("along x and y"),
            "{}",
            found.uncertainty
        );
    }
}

/// A point sampler (production) and the python example (point-sampled,
/// closed edges) get no conservative finding: their pixels are decided at
/// a point.
#[test]
fn a_point_sampler_gets_no_conservative_finding() {
    assert!(probe_of("production").conservative.is_none());
    assert!(probe_of(registry::PYTHON_EXAMPLE).conservative.is_none());
}
