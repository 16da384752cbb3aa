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
    for row in rastercheck::harness::matrix::default_rows() {
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
            shown.contains("- `tiny-skia` keeps")
                && shown.contains("a different consistent tie rule"),
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
        block.contains(&rastercheck::harness::matrix::today()),
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
