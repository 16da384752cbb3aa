//! The HTML report and the EXR error maps, end to end: the real binary on
//! the bundled cases with `--report`, the EXR files read back, and the page
//! opened in headless Chromium (a screenshot, and the DOM after load to
//! prove every embedded picture decoded).
//!
//! Without Chromium the browser half is skipped with a message on stderr
//! (`.ci/run` installs it); the file checks still run.

mod common;

use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use common::cli::exr_channel;
use serde_json::Value;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn report_dir() -> PathBuf {
    let dir =
        Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("html-report-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn chromium() -> Option<PathBuf> {
    let on_path = std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .map(|p| p.join("chromium"))
            .find(|p| p.is_file())
    });
    on_path.or_else(|| {
        let fixed = PathBuf::from("/usr/bin/chromium");
        fixed.is_file().then_some(fixed)
    })
}

/// Runs headless Chromium on `page` with `extra` flags, stdout to `out`,
/// killed after two minutes.
fn run_chromium(chromium: &Path, profile: &Path, page: &Path, extra: &[String], out: &Path) {
    let url = format!("file://{}", page.display());
    let mut child = Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--no-first-run",
            "--hide-scrollbars",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(extra)
        .arg(&url)
        .stdin(Stdio::null())
        .stdout(File::create(out).unwrap())
        .stderr(Stdio::null())
        .spawn()
        .expect("chromium starts");
    let deadline = Instant::now() + Duration::from_secs(120);
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            assert!(status.success(), "chromium {extra:?} exited with {status}");
            return;
        }
        if Instant::now() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            panic!("chromium {extra:?} did not finish in two minutes");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// The text of every `<article ...>` element with its content.
fn cards(html: &str) -> Vec<&str> {
    html.split("<article")
        .skip(1)
        .map(|rest| &rest[..rest.find("</article>").expect("articles close")])
        .collect()
}

fn attribute<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let start = tag.find(&format!("{name}=\""))? + name.len() + 2;
    let len = tag[start..].find('"')?;
    Some(&tag[start..start + len])
}

/// A dda-f32 foil card with its reference, candidate and diff pictures,
/// each a PNG file of the report folder `dir` (the page's base).
fn has_foil_card_with_pictures(html: &str, dir: &Path) -> bool {
    cards(html).iter().any(|card| {
        let head = &card[..card.find('>').unwrap()];
        attribute(head, "data-rasterizer") == Some("dda-f32")
            && attribute(head, "data-verdict") == Some("foil")
            && ["reference", "candidate", "diff"].iter().all(|role| {
                let tag = format!("data-role=\"{role}\" src=\"");
                card.find(&tag).is_some_and(|at| {
                    let src = &card[at + tag.len()..];
                    let src = &src[..src.find('"').unwrap()];
                    src.starts_with("images/") && src.ends_with(".png") && dir.join(src).is_file()
                })
            })
    })
}

/// Every case page of the report folder `dir`, by path, with its text.
fn pages(dir: &Path) -> Vec<(PathBuf, String)> {
    let mut found = Vec::new();
    let mut folders = vec![dir.join("pages")];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).unwrap().flatten() {
            let path = entry.path();
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|e| e == "html") {
                let text = std::fs::read_to_string(&path).unwrap();
                found.push((path, text));
            }
        }
    }
    found.sort();
    found
}

/// The value of every `href="..."` in `html` that is not an anchor.
fn links(html: &str) -> Vec<&str> {
    html.split("href=\"")
        .skip(1)
        .map(|rest| &rest[..rest.find('"').unwrap()])
        .filter(|l| !l.starts_with('#') && !l.ends_with('/'))
        .collect()
}

/// A relative URL of the report folder as a file path: no anchor, and
/// percent escapes decoded.
fn url_file(url: &str) -> String {
    let url = url.split('#').next().unwrap();
    let mut out = Vec::new();
    let bytes = url.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            out.push(u8::from_str_radix(&url[i + 1..i + 3], 16).unwrap());
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).unwrap()
}

/// Opens `page` in Chromium and returns its DOM after load, with what the
/// page's script recorded on `<body>`: pictures decoded of all, script
/// errors, and the milliseconds from navigation to the load event.
fn open(chromium: &Path, profile: &Path, page: &Path, out: &Path) -> (String, String, u32, f64) {
    run_chromium(chromium, profile, page, &["--dump-dom".to_owned()], out);
    let dom = std::fs::read_to_string(out).unwrap();
    let body = &dom[dom.find("<body").expect("a body")..];
    let tag = &body[..body.find('>').unwrap()];
    let images = attribute(tag, "data-images")
        .expect("the page's load script ran")
        .to_owned();
    let errors = attribute(tag, "data-errors").unwrap().parse().unwrap();
    let load_ms = attribute(tag, "data-load-ms").unwrap().parse().unwrap();
    (dom.clone(), images, errors, load_ms)
}

fn check_exr(dir: &Path, report: &Value) -> usize {
    let mut checked = 0;
    for case in report["cases"].as_array().unwrap() {
        for result in case["results"].as_array().unwrap() {
            let Some(files) = result["files"].as_array() else {
                continue;
            };
            for file in files.iter().filter_map(Value::as_str) {
                assert!(dir.join(file).is_file(), "{file} is listed but missing");
                if !file.ends_with(".exr") {
                    continue;
                }
                let image = exr::prelude::read_all_flat_layers_from_file(dir.join(file))
                    .unwrap_or_else(|e| panic!("{file}: {e}"));
                let canvas = &case["rules"]["canvas"];
                let (w, h) = (canvas[0].as_u64().unwrap(), canvas[1].as_u64().unwrap());
                let samples = case["rules"]["antialias"]["samples"].as_u64().unwrap_or(1);
                let layer_named = |name: &str| {
                    image.layer_data.iter().find(|l| {
                        l.attributes.layer_name.as_ref().map(|n| n.to_string())
                            == Some(name.to_owned())
                    })
                };
                let m = &result["metrics"];
                // Antialiased: the signed resolved error, one value per pixel.
                if let Some(resolved) = layer_named("resolved") {
                    assert_eq!(
                        (resolved.size.width() as u64, resolved.size.height() as u64),
                        (w, h),
                        "{file}"
                    );
                    let largest = resolved.channel_data.list[0]
                        .sample_data
                        .values_as_f32()
                        .map(|v| f64::from(v.abs()))
                        .fold(0.0, f64::max);
                    let expected = m["antialias"]["max_error"].as_f64().unwrap();
                    assert!(
                        (largest - expected).abs() <= expected * 1e-6 + 1e-30,
                        "{file} resolved.error: largest {largest:e}, metrics say {expected:e}"
                    );
                }
                // Moving scenes: exact, candidate and signed error per pixel.
                if let Some(time) = layer_named("time") {
                    assert_eq!(
                        (time.size.width() as u64, time.size.height() as u64),
                        (w, h),
                        "{file}"
                    );
                    let largest = time
                        .channel_data
                        .list
                        .iter()
                        .find(|c| c.name.to_string() == "time.error")
                        .unwrap_or_else(|| panic!("{file} has no time.error"))
                        .sample_data
                        .values_as_f32()
                        .map(|v| f64::from(v.abs()))
                        .fold(0.0, f64::max);
                    let expected = m["time"]["max_error"].as_f64().unwrap();
                    assert!(
                        (largest - expected).abs() <= expected * 1e-6 + 1e-30,
                        "{file} time.error: largest {largest:e}, metrics say {expected:e}"
                    );
                }
                // Per sample: N times wider than the canvas.
                let Some(layer) = layer_named("error") else {
                    assert!(
                        m["coverage"]["samples"] == 0,
                        "{file} has no error layer but a mask"
                    );
                    checked += 1;
                    continue;
                };
                assert_eq!(
                    (layer.size.width() as u64, layer.size.height() as u64),
                    (w * samples, h),
                    "{file}"
                );
                let channel = |name: &str| exr_channel(layer, name, file);
                let coverage = channel("coverage.error");
                let moved = coverage.iter().filter(|&&v| v != 0.0).count() as u64;
                let c = &m["coverage"];
                assert_eq!(
                    moved,
                    c["missing"].as_u64().unwrap() + c["extra"].as_u64().unwrap(),
                    "{file}: coverage.error"
                );
                let owner = channel("owner.error");
                assert!(owner.iter().all(|&v| v == 0.0 || v == 1.0), "{file}");
                let owners = owner.iter().filter(|&&v| v == 1.0).count() as u64;
                assert!(owners >= c["wrong_owner"].as_u64().unwrap(), "{file}");
                for ch in m["channels"].as_array().unwrap() {
                    let metric_name = ch["channel"].as_str().unwrap();
                    let name = format!("{}.error", metric_name.replace(' ', "."));
                    let largest = channel(&name)
                        .iter()
                        .map(|v| f64::from(v.abs()))
                        .fold(0.0, f64::max);
                    let expected = ch["max_abs"].as_f64().unwrap();
                    assert!(
                        (largest - expected).abs() <= expected * 1e-6 + 1e-30,
                        "{file} {name}: largest {largest:e}, metrics say {expected:e}"
                    );
                }
                checked += 1;
            }
        }
    }
    checked
}

#[test]
fn the_html_report_opens_in_a_browser_with_every_picture() {
    let dir = report_dir();
    let started = Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_rastercheck"))
        .args([
            "run",
            "cases",
            "-r",
            "production",
            "-r",
            "dda-f32",
            "--quiet",
            "--report",
        ])
        .arg(&dir)
        .current_dir(ROOT)
        .output()
        .expect("the binary runs");
    assert!(
        out.status.success(),
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    eprintln!(
        "run with --report: {:.1} s",
        started.elapsed().as_secs_f64()
    );

    // The index is light: no picture embedded, nothing from the network,
    // and every link resolves in the report folder.
    let page = dir.join("index.html");
    let html = std::fs::read_to_string(&page).expect("index.html is written");
    eprintln!("index.html: {} bytes", html.len());
    assert!(html.len() < 1 << 20, "index.html has {} bytes", html.len());
    assert!(
        !html.contains("data:image"),
        "a picture embedded in the index"
    );
    assert!(
        !html.contains("src=\"http") && !html.contains("<link"),
        "external resources"
    );
    let index_links = links(&html);
    assert!(index_links.iter().any(|l| l.starts_with("pages/")));
    for link in &index_links {
        assert!(
            dir.join(url_file(link)).is_file(),
            "{link} does not resolve"
        );
    }

    // The case pages: the foil's cards with their pictures, and links that
    // resolve against the report folder (each page's `<base>`).
    let pages = pages(&dir);
    assert!(!pages.is_empty(), "no case pages");
    let foil_page = pages
        .iter()
        .find(|(_, text)| has_foil_card_with_pictures(text, &dir))
        .expect("no dda-f32 foil card with three pictures");
    let mut case_links = 0;
    for (path, text) in &pages {
        let depth = path.strip_prefix(&dir).unwrap().components().count() - 1;
        assert!(
            text.contains(&format!("<base href=\"{}\">", "../".repeat(depth))),
            "{}: no base at the report folder",
            path.display()
        );
        for link in links(text) {
            assert!(
                dir.join(url_file(link)).is_file(),
                "{}: {link} does not resolve",
                path.display()
            );
            case_links += usize::from(link.ends_with(".json"));
        }
    }
    assert!(case_links > 0, "no case file linked");
    let report: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).unwrap()).unwrap();
    for case in report["cases"].as_array().unwrap() {
        if let Some(page) = case["page"].as_str() {
            assert!(dir.join(page).is_file(), "{page}");
        }
    }

    // The EXR error maps agree with the metrics.
    let maps = check_exr(&dir, &report);
    assert!(maps > 0, "no EXR error maps");
    let foils = report["totals"]["verdicts"][1]["foil"].as_u64().unwrap();
    assert!(
        maps as u64 >= foils,
        "{maps} maps for {foils} foil departures"
    );

    let Some(chromium) = chromium() else {
        eprintln!("skipped: chromium not found; .ci/run installs it (the browser half of this test did not run)");
        return;
    };
    let profile = dir.join("chromium-profile");
    let shot = dir.join("shot.png");
    let browser = Instant::now();
    run_chromium(
        &chromium,
        &profile,
        &page,
        &[
            format!("--screenshot={}", shot.display()),
            "--window-size=1400,3000".to_owned(),
        ],
        &dir.join("screenshot.log"),
    );
    let picture = image::open(&shot)
        .expect("the screenshot decodes")
        .to_rgb8();
    assert_eq!(picture.dimensions(), (1400, 3000));
    let mut colours: Vec<[u8; 3]> = picture.pixels().map(|p| p.0).collect();
    colours.sort_unstable();
    colours.dedup();
    assert!(colours.len() > 20, "the screenshot looks blank");

    let (dom, decoded, errors, load_ms) = open(&chromium, &profile, &page, &dir.join("dom.html"));
    let images = html.matches("<img ").count();
    assert_eq!(
        decoded,
        format!("{images}/{images}"),
        "index pictures decoded / all"
    );
    assert_eq!(errors, 0, "script errors on the index");
    assert!(load_ms < 1000.0, "the index took {load_ms} ms to load");
    assert!(dom.contains("Failures first"), "the DOM lacks the failures");
    // The plots: SVG files beside the index, each decoded (counted above),
    // and linked from summary.md too.
    let plots = html.matches("data-role=\"plot\"").count();
    assert!(plots >= 3, "{plots} plots on the index");
    assert_eq!(dom.matches("data-role=\"plot\"").count(), plots);
    let summary = std::fs::read_to_string(dir.join("summary.md")).unwrap();
    assert_eq!(summary.matches("](plots/").count(), plots, "{summary}");
    assert!(
        dom.contains("<h2>Families</h2>"),
        "the DOM lacks the summary"
    );

    let (dom, decoded, errors, _) = open(&chromium, &profile, &foil_page.0, &dir.join("page.html"));
    let images = foil_page.1.matches("<img ").count();
    assert_eq!(
        decoded,
        format!("{images}/{images}"),
        "case page pictures decoded / all"
    );
    assert_eq!(errors, 0, "script errors on a case page");
    assert!(
        has_foil_card_with_pictures(&dom, &dir),
        "the DOM lacks the foil card"
    );
    eprintln!(
        "chromium: screenshot and DOMs in {:.1} s; the index loaded in {load_ms:.0} ms",
        browser.elapsed().as_secs_f64()
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A 16-sample triangle and an 8-sample quadrilateral of two triangles,
/// each judged for production, the coarse-resolve mutant (8 and 16 samples
/// resolve to other than quarters, so rounding down shows) and the
/// shifted-samples mutant (its mask differs).
const AA_CASES: [(&str, &str); 2] = [
    (
        "triangle16",
        r#"{"name": "triangle16", "canvas": {"width": 12, "height": 9},
  "primitives": [{"triangle": [[0.5, 0.25], [11.75, 1.5], [2.25, 8.5]]}],
  "effects": {"antialias": {"samples": 16, "position_bits": 4}},
  "expect": {"max_coverage_error": 0.25, "max_coverage_rms": 0.1}}"#,
    ),
    (
        "quad8",
        r#"{"name": "quad8", "canvas": {"width": 8, "height": 8},
  "primitives": [{"triangle": [[0.5, 0.25], [7.75, 1], [7, 7.5]]},
                 {"triangle": [[0.5, 0.25], [7, 7.5], [1, 7]]}],
  "effects": {"antialias": {"samples": 8}},
  "expect": {"max_coverage_error": 0.5, "watertight": true, "area": "1407/32"}}"#,
    ),
];

#[test]
fn antialiased_cases_show_resolved_coverage_and_error_maps() {
    let dir = report_dir().with_extension("aa");
    let cases = dir.join("cases/aa");
    std::fs::create_dir_all(&cases).unwrap();
    for (name, json) in AA_CASES {
        std::fs::write(cases.join(format!("{name}.json")), json).unwrap();
    }
    let out = Command::new(env!("CARGO_BIN_EXE_rastercheck"))
        .args([
            "run",
            "cases",
            "-r",
            "production",
            "-r",
            "mutant:coarse-resolve",
            "-r",
            "mutant:shifted-samples",
            "--quiet",
            "--report",
            "report",
        ])
        .current_dir(&dir)
        .output()
        .expect("the binary runs");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(out.status.code(), Some(1), "{text}");
    let report_dir = dir.join("report");
    let report: Value =
        serde_json::from_str(&std::fs::read_to_string(report_dir.join("report.json")).unwrap())
            .unwrap();
    for case in report["cases"].as_array().unwrap() {
        assert_eq!(case["status"], "ran", "{case}");
        let rules = &case["rules"]["antialias"];
        assert!(rules["samples"].as_u64().unwrap() >= 4, "{case}");
        let [production, mutant, shifted] = [0, 1, 2].map(|k| &case["results"][k]);
        assert_eq!(production["verdict"], "pass", "{production}");
        assert_eq!(mutant["verdict"], "fail", "{mutant}");
        let aa = &production["metrics"]["antialias"];
        assert_eq!(aa["piglit_violations"], 0);
        assert!(aa["edge_pixels"].as_u64().unwrap() > 0, "{aa}");
        assert!(
            mutant["reasons"]
                .as_array()
                .unwrap()
                .iter()
                .any(|r| r.as_str().unwrap().contains("box resolve")),
            "{mutant}"
        );
        // Pictures and maps for the failure: greyscale, signed error, samples.
        let files: Vec<&str> = mutant["files"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f.as_str().unwrap())
            .collect();
        for suffix in [
            "/reference.png",
            "/mutant-coarse-resolve.png",
            ".diff.png",
            ".exr",
        ] {
            assert!(
                files.iter().any(|f| f.ends_with(suffix)),
                "{suffix} in {files:?}"
            );
        }
        // Its samples are right: no samples picture.
        assert!(!files.iter().any(|f| f.ends_with(".samples.png")));
        assert_eq!(shifted["verdict"], "fail", "{shifted}");
        let samples = shifted["files"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|f| f.as_str())
            .find(|f| f.ends_with("/mutant-shifted-samples.samples.png"))
            .expect("a samples picture for a mask that differs");
        let samples = image::open(report_dir.join(samples)).unwrap().to_rgb8();
        let magenta = rastercheck::report::png::MISSING;
        let red = rastercheck::report::png::EXTRA;
        assert!(samples.pixels().any(|p| p.0 == magenta || p.0 == red));
        let diff = files.iter().find(|f| f.ends_with(".diff.png")).unwrap();
        let diff = image::open(report_dir.join(diff)).unwrap().to_rgb8();
        // Rounding down: too little coverage, blue; never red.
        assert!(diff.pixels().any(|p| p.0[2] > 200 && p.0[0] < 100));
        assert!(!diff.pixels().any(|p| p.0[0] > 200 && p.0[1] < 100));
        let reference = files
            .iter()
            .find(|f| f.ends_with("/reference.png"))
            .unwrap();
        let reference = image::open(report_dir.join(reference)).unwrap().to_rgb8();
        let greys = reference
            .pixels()
            .filter(|p| p.0[0] == p.0[1] && p.0[1] == p.0[2] && (60..200).contains(&p.0[0]))
            .count();
        assert!(greys > 0, "the exact area shows partial pixels in grey");
    }
    assert!(check_exr(&report_dir, &report) >= 4);

    // Passing antialiased results get a card too, drawn from the frames, on
    // their case's page.
    let html: String = pages(&report_dir).into_iter().map(|(_, t)| t).collect();
    let aa_cards: Vec<&str> = cards(&html)
        .into_iter()
        .filter(|c| c.contains("<h4>resolved coverage</h4>"))
        .collect();
    assert_eq!(aa_cards.len(), 6, "{} cards", cards(&html).len());
    for card in aa_cards {
        let shifted = card.contains("data-rasterizer=\"mutant:shifted-samples\"");
        assert_eq!(card.contains("data-role=\"samples\""), shifted);
        for role in ["reference", "candidate", "diff"] {
            assert!(
                card.contains(&format!(
                    "data-role=\"{role}\" src=\"data:image/png;base64,"
                )),
                "{role}"
            );
        }
        assert!(card.contains("edge RMS"));
    }
    let summary = std::fs::read_to_string(report_dir.join("summary.md")).unwrap();
    assert!(
        summary.contains("## Worst antialiasing errors"),
        "{summary}"
    );
    let junit = std::fs::read_to_string(report_dir.join("junit.xml")).unwrap();
    assert!(
        junit.contains("box resolve of their own samples"),
        "{junit}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `diff`'s page opens in Chromium: production against a mutant on the
/// triangles, and every case the mutant newly fails is a row of the page's
/// DOM after load.
#[test]
fn the_diff_page_opens_in_a_browser() {
    let dir = report_dir().with_extension("diff");
    std::fs::create_dir_all(&dir).unwrap();
    let triangles = Path::new(ROOT).join("cases/triangles");
    for (name, rasterizer) in [("old", "production"), ("new", "mutant:no-perspective")] {
        let out = Command::new(env!("CARGO_BIN_EXE_rastercheck"))
            .args(["run", "-q", "-r", rasterizer, "--report"])
            .arg(dir.join(name))
            .arg(&triangles)
            .output()
            .expect("the binary runs");
        assert!(out.status.code().is_some_and(|c| c <= 1), "{out:?}");
    }
    let out = Command::new(env!("CARGO_BIN_EXE_rastercheck"))
        .arg("diff")
        .args([dir.join("old"), dir.join("new")])
        .arg("--out")
        .arg(dir.join("diff"))
        .output()
        .expect("the binary runs");
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    let json: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("diff/diff.json")).unwrap())
            .unwrap();
    let newly: Vec<String> = json["newly_failing"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["case"].as_str().unwrap().to_owned())
        .collect();
    assert!(!newly.is_empty());
    let page = dir.join("diff/diff.html");
    let html = std::fs::read_to_string(&page).unwrap();
    assert!(!html.contains("src=\"http") && !html.contains("<link"));

    let Some(chromium) = chromium() else {
        eprintln!("skipped: chromium not found; .ci/run installs it (the browser half of this test did not run)");
        return;
    };
    let dom = dir.join("dom.html");
    run_chromium(
        &chromium,
        &dir.join("chromium-profile"),
        &page,
        &["--dump-dom".to_owned()],
        &dom,
    );
    let dom = std::fs::read_to_string(&dom).unwrap();
    assert!(dom.contains("regression"), "{dom}");
    for case in &newly {
        assert!(dom.contains(case.as_str()), "{case} is not on the page");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
