//! The accuracy charts of a report folder (SPEC.md §10): the binary run on
//! bundled antialiased and moving cases writes `plots/*.svg`, `summary.md`
//! links each of them, and a later run removes the charts of an earlier one.

mod common;

use std::path::Path;

use common::cli::{rastercheck, scratch, text};

/// The `plots/` links of a markdown file, in order.
fn linked(md: &str) -> Vec<String> {
    md.split("](plots/")
        .skip(1)
        .map(|rest| rest[..rest.find(')').unwrap()].to_owned())
        .collect()
}

fn files(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn a_report_has_plots_and_the_summary_links_them() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let out = scratch("plots");
    std::fs::create_dir_all(out.join("plots")).unwrap();
    std::fs::write(out.join("plots/stale.svg"), "<svg/>").unwrap();
    // An earlier run's folder: its marker (SPEC §10) says so.
    std::fs::write(out.join(".rastercheck-report"), "").unwrap();
    let report = out.to_str().unwrap();
    let mut args = vec![
        "run",
        "-q",
        "-r",
        "production",
        "-r",
        "mutant:coarse-resolve",
    ];
    let cases = [
        "cases/antialias/count_grid_1.json",
        "cases/antialias/count_grid_16.json",
        "cases/antialias/count_stratified_4.json",
        "cases/antialias/count_stratified_64.json",
        "cases/motion/rotate_triangle_random4.json",
        "cases/motion/rotate_triangle_stratified16.json",
        "cases/motion/rotate_triangle_stratified64.json",
        "cases/triangles",
    ];
    args.extend(cases);
    args.extend(["--report", report]);
    let run = rastercheck(root, &args);
    // The mutant fails: exit 1, and every file written. (It does not draw
    // moving scenes: no time chart of its own.)
    assert_eq!(run.status.code(), Some(1), "{}", text(&run));
    assert_eq!(
        files(&out.join("plots")),
        [
            "aa-error-by-family.svg",
            "aa-error-vs-samples-mutant-coarse-resolve.svg",
            "aa-error-vs-samples-production.svg",
            "interpolation-ulp-by-family.svg",
            "time-error-vs-samples-production.svg",
        ],
        "and not the stale file"
    );
    let summary = std::fs::read_to_string(out.join("summary.md")).unwrap();
    let mut links = linked(&summary);
    assert!(summary.contains("\n## Plots\n"));
    assert!(summary.contains(
        "![Antialiasing error against samples: production](plots/aa-error-vs-samples-production.svg)"
    ));
    links.sort();
    assert_eq!(links, files(&out.join("plots")));
    for name in &links {
        let svg = std::fs::read_to_string(out.join("plots").join(name)).unwrap();
        assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
        assert!(svg.trim_end().ends_with("</svg>"));
    }
    // The sweep: a line for grid and one for stratified, through 2 points each.
    let svg =
        std::fs::read_to_string(out.join("plots/aa-error-vs-samples-production.svg")).unwrap();
    assert!(svg.contains(">grid</text>") && svg.contains(">stratified</text>"));
    assert!(!svg.contains(">random</text>"));
    let _ = std::fs::remove_dir_all(&out);
}
