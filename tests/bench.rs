//! `rastercheck bench --quick`: writes BENCH.md and bench.svg with every
//! section and method. Never asserts on timing, only that numbers are there
//! and that exact methods have no errors.

use std::path::PathBuf;
use std::process::Command;

fn row<'a>(md: &'a str, section: &str, method: &str) -> &'a str {
    let start = md
        .find(section)
        .unwrap_or_else(|| panic!("no section {section:?}:\n{md}"));
    let rest = &md[start..];
    let end = rest[4..].find("\n### ").map_or(rest.len(), |e| e + 4);
    rest[..end]
        .lines()
        .find(|l| l.starts_with(&format!("| `{method}` |")))
        .unwrap_or_else(|| panic!("no row for {method} in {section:?}:\n{md}"))
}

#[test]
fn quick_bench_writes_the_report_and_the_chart() {
    let dir = std::env::temp_dir().join(format!("rastercheck-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out_file: PathBuf = dir.join("BENCH.md");
    let out = Command::new(env!("CARGO_BIN_EXE_rastercheck"))
        .args(["bench", "--quick", "--out"])
        .arg(&out_file)
        .output()
        .expect("the binary runs");
    let shown = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(out.status.code(), Some(0), "{shown}");
    let md = std::fs::read_to_string(&out_file).expect("BENCH.md written");
    let svg = std::fs::read_to_string(dir.join("bench.svg")).expect("bench.svg written");

    for heading in [
        "# rastercheck bench",
        "- machine: ",
        "- date: ",
        "- rastercheck version: ",
        "![accuracy against time](bench.svg)",
        "## Workloads",
        "### triangles, L=10",
        "### triangles, L=50",
        "### lines",
        "## Performance targets",
        "## Notes",
    ] {
        assert!(md.contains(heading), "no {heading:?} in:\n{md}");
    }
    let mut triangle_methods: Vec<String> = rastercheck::bench::triangle_methods()
        .into_iter()
        .map(|(name, _)| name)
        .collect();
    triangle_methods.push("reference".to_owned());
    for section in ["### triangles, L=10", "### triangles, L=50"] {
        for method in &triangle_methods {
            let line = row(&md, section, method);
            assert!(
                line.contains(" µs |") || line.contains(" ns |") || line.contains(" ms |"),
                "no time in {line}"
            );
            assert!(line.contains(" of "), "no error count in {line}");
            if ["production", "production-tiled", "naive", "reference"].contains(&method.as_str()) {
                assert!(
                    line.contains("| 0 of "),
                    "an exact method has errors: {line}"
                );
            }
            assert!(
                svg.contains(&format!(">{method} L=")),
                "{method} not in the chart"
            );
        }
    }
    for method in ["production", "dda-f32", "dda-f64", "midpoint-plain"] {
        let line = row(&md, "### lines", method);
        assert!(line.contains(" µs |") || line.contains(" ns |") || line.contains(" ms |"));
        assert!(
            svg.contains(&format!(">{method} lines<")),
            "{method} not in the chart"
        );
    }
    assert!(row(&md, "### lines", "production").contains("| 0 of "));
    // The plain loop walks the same exact rule.
    assert!(row(&md, "### lines", "midpoint-plain").contains("| 0 of "));
    // Antialiasing: every method timed, with an RMS / max coverage error;
    // adaptive sampling gives exactly the error of full sampling.
    let aa = "### antialiasing";
    let full = row(&md, aa, "production 16× standard");
    let adaptive = row(&md, aa, "production 16× standard, adaptive");
    let error_of = |line: &str| line.split(" | ").nth(5).unwrap_or("").to_owned();
    assert!(
        error_of(full).contains(" / "),
        "no coverage error in {full}"
    );
    assert_eq!(error_of(full), error_of(adaptive));
    // adaptive-resolve's resolve is full sampling's, bit for bit.
    let resolved = row(&md, aa, "adaptive-resolve 16× standard");
    assert_eq!(error_of(full), error_of(resolved));
    for method in [
        "production 1× (aliased)",
        "production 64× stratified",
        "production 64× random",
        "area-f32 (16× standard case)",
    ] {
        let line = row(&md, aa, method);
        assert!(line.contains(" µs |") || line.contains(" ns |") || line.contains(" ms |"));
        assert!(
            svg.contains(&format!(">{method} AA<")),
            "{method} not in the chart"
        );
    }
    for target in [
        "naive on 1250-px",
        "naive on 50-px",
        "dda-f32",
        "within 10×",
        "adaptive 16×",
        "`adaptive-resolve 16× standard`",
        "`production 16× standard, adaptive`",
        "production-tiled ≥ 1.7× production",
        "plain midpoint loop",
    ] {
        let targets = &md[md.find("## Performance targets").unwrap()..];
        let line = targets
            .lines()
            .find(|l| l.starts_with("| ") && l.contains(target))
            .unwrap_or_else(|| panic!("no target {target:?}:\n{md}"));
        assert!(line.contains('×') && (line.contains("| met |") || line.contains("| not met |")));
    }
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert!(svg.contains(">exact<") && svg.contains("time per item") && svg.contains("error ("));
    std::fs::remove_dir_all(&dir).ok();
}
