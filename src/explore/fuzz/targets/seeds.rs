//! The seed corpus of each target, for `rastercheck fuzz --corpus DIR`.

use std::path::Path;

use super::by_name::TARGETS;
use super::response::{requests, selector, Form};
use crate::explore::fuzz::family::{tape_of_case, Family};
use crate::explore::fuzz::rng::Rng;
use crate::frame::Frame;
use crate::plan::Plan;

/// Seed files of target `name`, as (file name, bytes):
/// - `case_json`: every case file under `cases` (`invalid/` folders too);
/// - `scene_reference_vs_production`: the tapes of the first 8 cases of
///   each family of `rastercheck fuzz --seed 1`;
/// - `protocol_response`: answers to each request built from the
///   reference's frame (fragments, per-primitive coverage, an EXR file),
///   refusals, errors and hellos;
/// - `exact_arithmetic`: constant and SplitMix64 bytes.
///
/// Empty for an unknown name.
pub fn seeds(name: &str, cases: &Path) -> Vec<(String, Vec<u8>)> {
    match name {
        "case_json" => case_files(cases),
        "scene_reference_vs_production" => Family::ALL
            .iter()
            .flat_map(|&family| {
                (0..8).map(move |i| (format!("{}_{i}", family.name()), tape_of_case(1, i, family)))
            })
            .collect(),
        "protocol_response" => answers(),
        "exact_arithmetic" => (0..16u64)
            .map(|k| {
                let mut rng = Rng::new(k);
                let bytes = match k {
                    0 => vec![0; 96],
                    1 => vec![0xff; 96],
                    _ => (0..96).map(|_| rng.next_u64() as u8).collect(),
                };
                (format!("bytes_{k}"), bytes)
            })
            .collect(),
        _ => Vec::new(),
    }
}

fn case_files(cases: &Path) -> Vec<(String, Vec<u8>)> {
    let mut paths = Vec::new();
    let mut folders = vec![cases.to_path_buf()];
    while let Some(folder) = folders.pop() {
        let Ok(entries) = std::fs::read_dir(&folder) else {
            continue;
        };
        for path in entries.flatten().map(|e| e.path()) {
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|e| e == "json") {
                paths.push(path);
            }
        }
    }
    paths.sort();
    paths
        .iter()
        .filter_map(|path| {
            let name = relative_name(cases, path);
            std::fs::read(path).ok().map(|bytes| (name, bytes))
        })
        .collect()
}

/// `triangles/a.json` as `triangles_a.json`.
fn relative_name(root: &Path, path: &Path) -> String {
    path.strip_prefix(root)
        .unwrap_or(path)
        .to_string_lossy()
        .replace(['/', '\\'], "_")
}

/// Answers, right and wrong, to each request of the target.
fn answers() -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    for (r, (scene, plan)) in requests().iter().enumerate() {
        let frame = crate::reference::render(scene, plan);
        let mut seed = |name: &str, form: Form, body: &[u8]| {
            let mut bytes = vec![selector(form, r)];
            bytes.extend_from_slice(body);
            out.push((format!("{}_{name}", scene.name), bytes));
        };
        seed("fragments", Form::Json, fragments(&frame, plan).as_bytes());
        seed(
            "unsupported",
            Form::Json,
            br#"{"unsupported": "no such rule"}"#,
        );
        seed(
            "error",
            Form::Json,
            br#"{"id": "c1", "error": "out of memory"}"#,
        );
        seed(
            "empty",
            Form::Json,
            format!(
                r#"{{"primitives": [{}]}}"#,
                vec!["{\"fragments\": []}"; scene.primitives.len()].join(", ")
            )
            .as_bytes(),
        );
        seed(
            "hello",
            Form::Hello,
            br#"{"hello": {"protocol": 2, "name": "seed", "version": "1", "capabilities": {"primitives": ["triangle"], "antialias": false, "fill_rules": ["top-left"]}}}"#,
        );
        seed("not_hello", Form::Hello, br#"{"primitives": []}"#);
        if plan.antialias.is_some() {
            seed(
                "coverage",
                Form::Json,
                coverage(&frame, scene.primitives.len()).as_bytes(),
            );
        } else {
            let path = std::env::temp_dir()
                .join(format!("rastercheck-seed-{}-{r}.exr", std::process::id()));
            if crate::frame::exr::write(&frame, &path).is_ok() {
                if let Ok(bytes) = std::fs::read(&path) {
                    seed("exr", Form::Exr, &bytes);
                }
                let _ = std::fs::remove_file(&path);
            }
        }
    }
    out
}

/// A response listing each sample's last primitive as its fragment.
fn fragments(frame: &Frame, plan: &Plan) -> String {
    let count = frame.last.iter().copied().max().unwrap_or(0) as usize;
    let mut lists = vec![Vec::new(); count.max(1)];
    let per_pixel = frame.samples.max(1) as usize;
    for y in 0..frame.height {
        for x in 0..frame.width {
            for s in 0..per_pixel {
                let i = frame.index(x, y) + s;
                let Some(p) = (frame.last[i] as usize).checked_sub(1) else {
                    continue;
                };
                let mut numbers = vec![x.to_string(), y.to_string()];
                if plan.antialias.is_some() {
                    numbers.push(s.to_string());
                }
                if let Some(depth) = &frame.depth {
                    numbers.push(depth[i].to_string());
                }
                numbers.extend(frame.attributes.iter().map(|a| a[i].to_string()));
                lists[p].push(format!("[{}]", numbers.join(", ")));
            }
        }
    }
    let entries: Vec<String> = lists
        .iter()
        .map(|l| format!(r#"{{"fragments": [{}]}}"#, l.join(", ")))
        .collect();
    format!(r#"{{"primitives": [{}]}}"#, entries.join(", "))
}

/// A per-primitive coverage answer: each pixel's resolved coverage given
/// to the last primitive there.
fn coverage(frame: &Frame, primitives: usize) -> String {
    let mut lists = vec![Vec::new(); primitives];
    let per_pixel = frame.samples.max(1) as usize;
    for y in 0..frame.height {
        for x in 0..frame.width {
            let i = frame.index(x, y);
            let slots = &frame.last[i..i + per_pixel];
            let covered = slots.iter().filter(|&&l| l > 0).count();
            if let Some(&p) = slots.iter().max().filter(|&&p| p > 0) {
                let fraction = covered as f64 / per_pixel as f64;
                lists[p as usize - 1].push(format!("[{x}, {y}, {fraction}]"));
            }
        }
    }
    let entries: Vec<String> = lists
        .iter()
        .map(|l| format!(r#"{{"coverage": [{}]}}"#, l.join(", ")))
        .collect();
    format!(r#"{{"primitives": [{}]}}"#, entries.join(", "))
}

/// Writes every target's seeds under `dir/<target>/`; the files written.
pub fn write_corpus(dir: &Path, cases: &Path) -> Result<usize, String> {
    let mut written = 0;
    for name in TARGETS {
        let folder = dir.join(name);
        std::fs::create_dir_all(&folder).map_err(|e| format!("{}: {e}", folder.display()))?;
        for (file, bytes) in seeds(name, cases) {
            let path = folder.join(file);
            std::fs::write(&path, bytes).map_err(|e| format!("{}: {e}", path.display()))?;
            written += 1;
        }
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::explore::fuzz::targets::by_name::run;

    /// Every seed of every target runs clean: the corpus a campaign starts
    /// from holds no finding.
    #[test]
    fn every_seed_runs_clean() {
        for name in TARGETS {
            let seeds = seeds(name, std::path::Path::new("cases"));
            assert!(seeds.len() >= 8, "{name}: {} seeds", seeds.len());
            for (file, data) in &seeds {
                let ran = std::panic::catch_unwind(|| run(name, data));
                assert!(matches!(ran, Ok(true)), "{name} on seed {file}");
            }
        }
    }
}
