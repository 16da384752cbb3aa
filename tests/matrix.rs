//! The conformance matrix: a table with the default rows, findings computed
//! from the results, and a README block rewritten between its markers only.

mod common;

use common::{rastercheck, text};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn the_matrix_has_every_default_row_and_findings() {
    let out = rastercheck(&root(), &["matrix", "cases"]);
    let shown = text(&out);
    assert_eq!(out.status.code(), Some(0), "{shown}");
    assert!(shown.contains("| rasterizer | triangles ("), "{shown}");
    for row in rastercheck::registry::matrix_default_rows() {
        let line = shown
            .lines()
            .find(|l| l.starts_with(&format!("| `{row}`")))
            .unwrap_or_else(|| panic!("no row for {row}:\n{shown}"));
        // Either counts or the reason it is not available; never dropped.
        assert!(
            line.contains(" pass ") || line.contains(" exact ") || line.contains("not available: "),
            "{line}"
        );
    }
    let triangles = std::fs::read_dir(root().join("cases/triangles"))
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .is_ok_and(|e| e.path().extension().is_some_and(|x| x == "json"))
        })
        .count();
    assert!(
        shown.contains(&format!("| `production` | {triangles} pass · 0 fail")),
        "{shown}"
    );
    assert!(shown.contains("**Findings**"), "{shown}");
    if cfg!(feature = "euc") {
        let euc = shown
            .lines()
            .find(|l| l.starts_with("- `euc` is not watertight"))
            .unwrap_or_else(|| panic!("no finding on euc's overdraw:\n{shown}"));
        assert!(euc.contains("overdrawn samples"), "{euc}");
        assert!(euc.contains("closed edges"), "{euc}");
    }
    if cfg!(feature = "tiny-skia") {
        assert!(
            // Its ties go bottom-right on most slopes, top-left on ±3/2, ±3.
            shown.contains("- `tiny-skia` keeps")
                && shown.contains("with no consistent tie rule: bottom-right on most slopes"),
            "{shown}"
        );
    }
    if !cfg!(feature = "lavapipe") {
        assert!(
            shown.contains("| `lavapipe` | not available: not compiled"),
            "{shown}"
        );
    }
}

#[test]
fn a_rasterizer_that_cannot_start_is_a_row_that_says_why() {
    let out = rastercheck(
        &root(),
        &[
            "matrix",
            "cases/triangles/shared_edge_diagonal.json",
            "-r",
            "production",
            "-r",
            "external:/no/such/program",
        ],
    );
    let shown = text(&out);
    assert_eq!(out.status.code(), Some(0), "{shown}");
    assert!(
        shown.contains("| `external:/no/such/program` | not available: "),
        "{shown}"
    );
    assert!(
        shown.contains("| `production` | 1 pass · 0 fail"),
        "{shown}"
    );
    let unknown = rastercheck(&root(), &["matrix", "cases", "-r", "no-such-rasterizer"]);
    assert_eq!(unknown.status.code(), Some(2), "{}", text(&unknown));
}

/// `matrix` of `case` under production and the flipped-ties mutant, its
/// table written into `readme`.
fn write_readme(dir: &Path, case: &Path, readme: &Path) -> std::process::Output {
    rastercheck(
        dir,
        &[
            "matrix",
            case.to_str().unwrap(),
            "-r",
            "production",
            "-r",
            "mutant:flipped-ties",
            "--write-readme",
            readme.to_str().unwrap(),
        ],
    )
}

#[test]
fn write_readme_replaces_only_the_marked_block() {
    let dir = common::cli::scratch("matrix");
    let readme = dir.join("README.md");
    let before = "# title\n\nintro\n\n<!-- matrix:begin -->\nold table\n<!-- matrix:end -->\n\n## Adding a case\ntail\n";
    std::fs::write(&readme, before).unwrap();
    let case = root().join("cases/triangles/shared_edge_diagonal.json");
    let out = write_readme(&dir, &case, &readme);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let after = std::fs::read_to_string(&readme).unwrap();
    let begin = after.find("<!-- matrix:begin -->").unwrap() + "<!-- matrix:begin -->".len();
    let end = after.find("<!-- matrix:end -->").unwrap();
    assert_eq!(
        &after[..begin],
        &before[..before.find("<!-- matrix:begin -->").unwrap() + 21]
    );
    assert_eq!(
        &after[end..],
        &before[before.find("<!-- matrix:end -->").unwrap()..]
    );
    let block = &after[begin..end];
    assert!(!block.contains("old table"));
    assert!(
        block.contains(&format!("rastercheck {}", env!("CARGO_PKG_VERSION"))),
        "{block}"
    );
    assert!(
        block.contains(&rastercheck::harness::today::today()),
        "{block}"
    );
    assert!(block.contains("| `mutant:flipped-ties` |"), "{block}");
    assert!(
        block.contains("gives 8 tie samples to the other triangle"),
        "{block}"
    );
    // Writing twice gives the same file.
    let again = write_readme(&dir, &case, &readme);
    assert!(again.status.success());
    assert_eq!(std::fs::read_to_string(&readme).unwrap(), after);
    // A file without markers is refused and left alone.
    std::fs::write(&readme, "no markers\n").unwrap();
    let refused = rastercheck(
        &dir,
        &[
            "matrix",
            case.to_str().unwrap(),
            "-r",
            "production",
            "--write-readme",
            readme.to_str().unwrap(),
        ],
    );
    assert_eq!(refused.status.code(), Some(2), "{}", text(&refused));
    assert_eq!(std::fs::read_to_string(&readme).unwrap(), "no markers\n");
}

/// Every row the matrix can build without a GPU feature (the defaults, the
/// mutants with a tie rule of their own and area-f32): what the matrix
/// says about its sampler and tie rule is what probe says, and no finding
/// names a rule or a sampler that probe did not find.
#[test]
fn matrix_and_probe_agree_on_every_row() {
    use rastercheck::explore::matrix;
    use rastercheck::explore::probe::{self, SamplerKind};
    use rastercheck::harness::discover;
    use rastercheck::registry;

    let mut names: Vec<String> = rastercheck::registry::matrix_default_rows()
        .into_iter()
        .filter(|n| matches!(matrix::rasterizer(n), Some(Ok(_))))
        .collect();
    names.extend(["mutant:flipped-ties", "mutant:closed-edges", "area-f32"].map(str::to_owned));
    for foil in rastercheck::production::foils::SAMPLER_FOILS {
        assert!(
            names.iter().any(|n| n == foil),
            "{foil} is not a default row"
        );
    }
    let found = discover::discover(&[root().join("cases/triangles")]);
    let limits = rastercheck::scene::Limits::default();
    let m = matrix::build(&found.cases, &limits, &names, None);
    let shown = m.to_markdown();
    let findings: Vec<&str> = shown.lines().filter(|l| l.starts_with("- ")).collect();
    for (name, row) in names.iter().zip(&m.rows) {
        assert!(row.available.is_ok(), "{name}: {:?}", row.available);
        let r = registry::by_name(name).unwrap();
        let p = probe::probe(r.as_ref()).unwrap_or_else(|e| panic!("{name}: {e}"));
        let d = match &row.diagnosis {
            Some(Ok(d)) => d,
            other => panic!("{name}: no diagnosis in the matrix: {other:?}"),
        };
        // The same decision...
        assert_eq!(d.sampler.kind, p.sampler, "{name}");
        assert_eq!(d.fill_rule, p.fill_rule, "{name}");
        assert_eq!(d.fill_rule_consistent, p.fill_rule_consistent, "{name}");
        assert_eq!(d.sample_position, p.sample_position, "{name}");
        // ...said in the findings...
        let quoted = format!("`{}`", row.name);
        let probe_line = findings
            .iter()
            .find(|l| {
                l.starts_with("- Probe: ")
                    && (l.contains(&format!("{quoted},")) || l.contains(&format!("{quoted}:")))
            })
            .unwrap_or_else(|| panic!("no probe finding for {quoted}:\n{shown}"));
        assert!(
            probe_line.ends_with(&format!("{}.", d.summary())),
            "{probe_line}"
        );
        // ...and nothing else said about its rule or sampler.
        for line in findings
            .iter()
            .filter(|l| l.starts_with(&format!("- {quoted} ")))
        {
            let rule = p.fill_rule.as_deref();
            let claims = [
                ("closed edges", rule == Some("all-edges")),
                ("open edges", rule == Some("none")),
                ("(any-coverage)", p.sampler == SamplerKind::AnyCoverage),
                ("(area sampler)", p.sampler == SamplerKind::Area),
                (
                    "different consistent tie rule",
                    rule.is_some_and(|r| r != "top-left") && p.fill_rule_consistent,
                ),
                ("top-left ties", rule == Some("top-left")),
            ];
            for (claim, probe_says) in claims {
                assert!(
                    !line.contains(claim) || probe_says,
                    "{name}: the matrix says {claim:?}, probe says {:?} / {:?}:\n{line}",
                    p.sampler,
                    rule
                );
            }
            // A rule named in any of the ways the findings name one.
            for named in probe::RULE_NAMES {
                let says = [
                    format!("the {named} tie rule"),
                    format!("than top-left: {named}"),
                    format!("({named},"),
                ];
                if says.iter().any(|s| line.contains(s.as_str())) {
                    assert_eq!(rule, Some(named), "{name}: {line}");
                }
            }
        }
    }
}
