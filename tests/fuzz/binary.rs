//! The binary on a folder of mutated case files: it must exit 0, 1 or 2,
//! never panic, and report every file.

use std::path::Path;
use std::process::Command;

use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, TestRunner};
use serde_json::Value;

use crate::mutations::{mutate, mutation, Mutation};
use crate::{case_texts, fuzz_cases};

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
