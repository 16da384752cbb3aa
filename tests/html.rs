//! The HTML report and the EXR error maps, end to end: the real binary on
//! the bundled cases with `--report`, the EXR files read back, and the page
//! opened in headless Chromium (a screenshot, and the DOM after load to
//! prove every embedded picture decoded).
//!
//! Without Chromium the browser half is skipped with a message on stderr
//! (`.ci/run` installs it); the file checks still run.

use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

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

/// A dda-f32 foil card with its reference, candidate and diff pictures.
fn has_foil_card_with_pictures(html: &str) -> bool {
    cards(html).iter().any(|card| {
        let head = &card[..card.find('>').unwrap()];
        attribute(head, "data-rasterizer") == Some("dda-f32")
            && attribute(head, "data-verdict") == Some("foil")
            && ["reference", "candidate", "diff"].iter().all(|role| {
                card.contains(&format!(
                    "data-role=\"{role}\" src=\"data:image/png;base64,"
                ))
            })
    })
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
                let layer = &image.layer_data[0];
                let canvas = &case["rules"]["canvas"];
                assert_eq!(
                    (layer.size.width() as u64, layer.size.height() as u64),
                    (canvas[0].as_u64().unwrap(), canvas[1].as_u64().unwrap()),
                    "{file}"
                );
                let channel = |name: &str| -> Vec<f32> {
                    layer
                        .channel_data
                        .list
                        .iter()
                        .find(|c| c.name.to_string() == name)
                        .unwrap_or_else(|| panic!("{file} has no channel {name}"))
                        .sample_data
                        .values_as_f32()
                        .collect()
                };
                let m = &result["metrics"];
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

    // The page is self-contained.
    let page = dir.join("index.html");
    let html = std::fs::read_to_string(&page).expect("index.html is written");
    eprintln!("index.html: {} bytes", html.len());
    let images = html.matches("<img ").count();
    assert!(images > 0);
    assert_eq!(
        html.matches("<img data-role=").count(),
        html.matches(" src=\"data:image/png;base64,").count()
    );
    assert!(
        !html.contains("src=\"http") && !html.contains("<link"),
        "external resources"
    );
    assert!(
        has_foil_card_with_pictures(&html),
        "no dda-f32 foil card with three pictures"
    );

    // Every case link resolves from the report folder.
    let links: Vec<&str> = html
        .split("class=\"case-json\" href=\"")
        .skip(1)
        .map(|rest| &rest[..rest.find('"').unwrap()])
        .collect();
    assert!(!links.is_empty());
    for link in &links {
        assert!(
            dir.join(link).is_file(),
            "case link {link} does not resolve"
        );
    }

    // The EXR error maps agree with the metrics.
    let report: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).unwrap()).unwrap();
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

    let dom = dir.join("dom.html");
    run_chromium(&chromium, &profile, &page, &["--dump-dom".to_owned()], &dom);
    let dom = std::fs::read_to_string(&dom).unwrap();
    let body = &dom[dom.find("<body").expect("a body")..];
    let decoded = attribute(&body[..body.find('>').unwrap()], "data-images")
        .expect("the page's load script ran");
    assert_eq!(
        decoded,
        format!("{images}/{images}"),
        "pictures that decoded / all"
    );
    assert!(
        has_foil_card_with_pictures(&dom),
        "the DOM lacks the foil card"
    );
    eprintln!(
        "chromium: screenshot and DOM in {:.1} s; {decoded} pictures decoded",
        browser.elapsed().as_secs_f64()
    );
    let _ = std::fs::remove_dir_all(&dir);
}
