//! `rastercheck bench --quick`: writes BENCH.md and bench.svg with every
//! section and method, under `out/bench/` (the committed files untouched). Never asserts on timing, only that numbers are there
//! (peak heap too), that exact methods have no errors and that seeded errors
//! (motion blur's) fall as they should; the bench's exact time coverage
//! under translation against the reference; and the peak-heap probe against
//! allocations of known size.

use std::path::PathBuf;
use std::process::Command;

use rastercheck::bench::memory;
use rastercheck::scene::Scene;

/// The binary's counting allocator, so that the probe can be tested here.
#[global_allocator]
static ALLOCATOR: memory::Counting = memory::Counting;

/// The peak heap cell of a table row: the column before the note.
fn heap_of(line: &str) -> String {
    let cells: Vec<&str> = line.split(" | ").collect();
    cells
        .len()
        .checked_sub(2)
        .map_or("", |k| cells[k])
        .to_owned()
}

fn has_bytes(cell: &str) -> bool {
    [" B", " KiB", " MiB", " GiB"]
        .iter()
        .any(|unit| cell.ends_with(unit))
}

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

/// Run in a folder holding a committed BENCH.md and bench.svg, with no
/// `--out`: the quick run writes under `out/bench/`, says so, and leaves
/// the committed files as they were.
#[test]
fn quick_bench_writes_the_report_and_the_chart() {
    let dir = std::env::temp_dir().join(format!("rastercheck-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let committed = "committed, not to be overwritten\n";
    for file in ["BENCH.md", "bench.svg"] {
        std::fs::write(dir.join(file), committed).unwrap();
    }
    let out = Command::new(env!("CARGO_BIN_EXE_rastercheck"))
        .args(["bench", "--quick"])
        .current_dir(&dir)
        .output()
        .expect("the binary runs");
    let shown = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(out.status.code(), Some(0), "{shown}");
    for file in ["BENCH.md", "bench.svg"] {
        assert_eq!(
            std::fs::read_to_string(dir.join(file)).unwrap(),
            committed,
            "bench --quick overwrote {file}"
        );
    }
    let written: PathBuf = dir.join("out/bench");
    assert!(
        shown.contains("wrote out/bench/BENCH.md and out/bench/bench.svg"),
        "{shown}"
    );
    let md = std::fs::read_to_string(written.join("BENCH.md")).expect("BENCH.md written");
    let svg = std::fs::read_to_string(written.join("bench.svg")).expect("bench.svg written");

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
        "### motion blur",
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
            assert!(has_bytes(&heap_of(line)), "no peak heap in {line}");
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
        assert!(has_bytes(&heap_of(line)), "no peak heap in {line}");
        assert!(
            svg.contains(&format!(">{method} lines<")),
            "{method} not in the chart"
        );
    }
    assert!(row(&md, "### lines", "production").contains("| 0 of "));
    // A static scene declaring motion blur draws the exact frame, as the
    // same scene drawn in turn with it.
    for section in ["### triangles, L=10", "### triangles, L=50"] {
        for method in [rastercheck::bench::PAIRED, rastercheck::bench::DECLARED] {
            let line = row(&md, section, method);
            assert!(line.contains("| 0 of "), "{line}");
            assert!(line.contains(" µs |") || line.contains(" ns |") || line.contains(" ms |"));
        }
    }
    // Motion blur: every row timed, with an RMS / max time error; the
    // stratified error falls as N grows (seeded: not a timing).
    let motion = "### motion blur";
    let error_of = |line: &str| line.split(" | ").nth(5).unwrap_or("").to_owned();
    let rms_of = |method: &str| -> f64 {
        let line = row(&md, motion, method);
        assert!(line.contains(" µs |") || line.contains(" ns |") || line.contains(" ms |"));
        let error = error_of(line);
        error
            .split(" / ")
            .next()
            .and_then(|r| r.parse().ok())
            .unwrap_or_else(|| panic!("no time error in {line}"))
    };
    let stratified = [4, 16, 64].map(|n| rms_of(&format!("production {n}× stratified")));
    assert!(has_bytes(&heap_of(row(
        &md,
        motion,
        "production 64× stratified"
    ))));
    assert!(
        stratified[0] > stratified[1] && stratified[1] > stratified[2],
        "{stratified:?}"
    );
    assert!(rms_of("production 16× random") > stratified[1]);
    assert!(rms_of(rastercheck::bench::MOTION_BASELINE) > stratified[0]);
    for n in [4, 16, 64] {
        let line = row(&md, motion, &format!("production {n}× stratified"));
        assert!(line.contains("sample test efficiency 0."), "{line}");
    }
    // The tiled method draws production's frame.
    let tiled = row(&md, motion, "production-tiled 64× stratified (2 threads)");
    assert_eq!(
        error_of(tiled),
        error_of(row(&md, motion, "production 64× stratified"))
    );
    assert!(svg.contains(">production 16× stratified motion<"));
    // The plain loop walks the same exact rule.
    assert!(row(&md, "### lines", "midpoint-plain").contains("| 0 of "));
    // Antialiasing: every method timed, with an RMS / max coverage error;
    // adaptive sampling gives exactly the error of full sampling.
    let aa = "### antialiasing";
    let full = row(&md, aa, "production 16× standard");
    let adaptive = row(&md, aa, "production 16× standard, adaptive");
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
        assert!(has_bytes(&heap_of(line)), "no peak heap in {line}");
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
        "declaring motion blur ≤ 1.1× the cost of the same scene without (L=10)",
        "declaring motion blur ≤ 1.1× the cost of the same scene without (L=50)",
    ] {
        let targets = &md[md.find("## Performance targets").unwrap()..];
        let line = targets
            .lines()
            .find(|l| l.starts_with("| ") && l.contains(target))
            .unwrap_or_else(|| panic!("no target {target:?}:\n{md}"));
        assert!(line.contains('×') && (line.contains("| met |") || line.contains("| not met |")));
    }
    for n in [4, 16, 64] {
        let targets = &md[md.find("## Performance targets").unwrap()..];
        let name = format!("`production {n}× stratified` within SPEC's default max_time_rms");
        let line = targets
            .lines()
            .find(|l| l.contains(&name))
            .unwrap_or_else(|| panic!("no target {name:?}:\n{md}"));
        assert!(line.contains("| met |"), "{line}");
    }
    // Peak heap: a column in every table, measured (the binary counts), and
    // said how.
    assert_eq!(
        md.matches("| peak heap | note |").count(),
        md.matches("\n### ").count(),
        "a table without the peak heap column:\n{md}"
    );
    assert!(md.contains("- peak heap: each method run once more, outside every timing"));
    assert!(md.contains("- Peak heap: each method is run once more after its timings"));
    assert!(!md.contains("not measured (no counting allocator"));
    // Every method with a draw call of its own is timed at it, and the
    // frame it draws names the judged frame's owners; the whole call and
    // the adapter's overhead have columns. Then the machine's parallel
    // ceiling beside the tiled target.
    assert!(
        md.contains("| whole call per item | adapter overhead |"),
        "{md}"
    );
    for method in ["production", "production-tiled", "tiny-skia", "euc"] {
        for section in ["### triangles, L=10", "### triangles, L=50"] {
            let line = row(&md, section, method);
            assert!(
                line.contains("the draw call alone")
                    && line.contains("names the whole call's last primitive at every sample"),
                "{line}"
            );
        }
    }
    let targets = &md[md.find("## Performance targets").unwrap()..];
    let tiled = targets
        .lines()
        .find(|l| l.contains("production-tiled ≥ 1.7× production"))
        .unwrap();
    assert!(
        tiled.contains("the machine gave 2 threads ") && tiled.contains("× during this run"),
        "{tiled}"
    );
    // llvmpipe single-threaded: rows and targets where a driver is built
    // in, else one target saying how to get them.
    let drivers: Vec<&str> = rastercheck::bench::DRIVERS
        .iter()
        .map(|(name, _)| *name)
        .filter(|name| {
            cfg!(feature = "lavapipe") && *name == "lavapipe"
                || cfg!(feature = "gl") && *name == "gl"
        })
        .collect();
    if drivers.is_empty() {
        let line = targets
            .lines()
            .find(|l| l.contains("production ≥ 3× llvmpipe single-threaded"))
            .unwrap_or_else(|| panic!("no llvmpipe target:\n{md}"));
        assert!(
            line.contains("| not measured |") && line.contains("--features lavapipe"),
            "{line}"
        );
    } else {
        assert!(md.contains("LP_NUM_THREADS=1"), "{md}");
    }
    for driver in drivers {
        for (section, short) in [
            ("### triangles, L=10", "L=10"),
            ("### triangles, L=50", "L=50"),
        ] {
            let driver_row = row(&md, section, driver);
            assert!(driver_row.contains("LP_NUM_THREADS=1"), "{driver_row}");
            assert!(
                driver_row.contains("the draw call alone")
                    && driver_row.contains("names the whole call's last primitive at every sample"),
                "{driver_row}"
            );
            let name = format!(
                "production ≥ 3× llvmpipe single-threaded, draw only (`{driver}`, {short})"
            );
            let line = targets
                .lines()
                .find(|l| l.contains(&name))
                .unwrap_or_else(|| panic!("no target {name:?}:\n{md}"));
            assert!(
                line.contains("× the draw call")
                    && (line.contains("| met |") || line.contains("| not met |")),
                "{line}"
            );
        }
    }
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert!(svg.contains(">exact<") && svg.contains("time per item") && svg.contains("error ("));
    std::fs::remove_dir_all(&dir).ok();
}

/// How many pixels' exact time coverage (`bench::translation_time_coverage`)
/// strays from the reference's static coverage averaged over K instants
/// (midpoints of K equal parts of the shutter) by more than P/K: each
/// primitive covers a centre over one interval of the shutter, whose length
/// K midpoints measure within 1/K.
fn riemann_disagreements(scene: &Scene, exact: &[f64]) -> usize {
    use rastercheck::scene::Number;
    const K: i64 = 64;
    let [open, close] = scene
        .effects
        .motion_blur
        .as_ref()
        .unwrap()
        .shutter
        .map(i64::from);
    let mut sums = vec![0u32; exact.len()];
    for j in 0..K {
        // open + (close − open)·(j + ½)/K, in units of 2^-16 / 2K.
        let tau = Number::ratio(open * 2 * K + (close - open) * (2 * j + 1), (2 * K) << 16);
        let at = scene.at_instant(&tau);
        let counts = rastercheck::reference::coverage_under(
            &at,
            &rastercheck::plan::Plan::for_scene(&at),
            scene.rules.fill_rule,
        );
        for (sum, c) in sums.iter_mut().zip(counts) {
            *sum += u32::from(c);
        }
    }
    let tolerance = scene.primitives.len() as f64 / K as f64 + 1e-12;
    sums.iter()
        .zip(exact)
        .filter(|(&sum, &e)| (f64::from(sum) / K as f64 - e).abs() > tolerance)
        .count()
}

/// The bench's exact time coverage under translation is the static rules'
/// coverage integrated over the shutter: on seeded scenes of translating
/// triangles (every fill rule and cull, shutters inside [0, 1], edges that
/// slide along rows of centres), against the reference at 64 instants. The
/// time-reversed motion's values, a plausible slip, are caught.
#[test]
fn translation_time_coverage_is_the_reference_over_the_shutter() {
    use rastercheck::scene::{Cull, FillRule, TimePattern};
    let mut caught = 0;
    for k in 0..24u64 {
        let mut s = rastercheck::bench::motion_scene(24, 8, 3, 6.0, 1, TimePattern::Random, k);
        s.rules.fill_rule = FillRule::ALL[k as usize % 5];
        s.rules.cull = [Cull::None, Cull::Clockwise, Cull::CounterClockwise][k as usize % 3];
        // Both windings, for the cull to keep one.
        s.primitives[2].vertices_mut().swap(1, 2);
        if k % 4 == 3 {
            s.effects.motion_blur.as_mut().unwrap().shutter = [1 << 13, 3 << 14];
        }
        if k % 2 == 1 {
            // The first triangle slides along the row of centres y = 4.5
            // with a horizontal edge on it: its centres ride that edge, and
            // the fill rule decides them all shutter long.
            use rastercheck::scene::Number;
            let p = |x: i64, y2: i64| [Number::from_int(x), Number::ratio(y2, 2)];
            // Above the edge (a bottom edge) or below it (a top edge).
            let third = if k % 4 == 1 { 4 } else { 14 };
            let corners = [p(2, 9), p(10, 9), p(6, third)];
            let vertices = s.primitives[0].vertices_mut();
            for (v, [x, y]) in vertices.iter_mut().zip(corners) {
                let to = [&x + &Number::from_int(5), y.clone()];
                v.x = x;
                v.y = y;
                v.to = Some(Box::new(to));
            }
        }
        let exact = rastercheck::bench::translation_time_coverage(&s).expect("translations");
        assert!(
            exact.iter().any(|&e| e > 0.0 && e < 1.0),
            "scene {k} moves over centres"
        );
        assert_eq!(riemann_disagreements(&s, &exact), 0, "scene {k}: {s:#?}");
        let mut reversed = s.clone();
        for v in reversed
            .primitives
            .iter_mut()
            .flat_map(|p| p.vertices_mut())
        {
            let [x, y] = *v.to.take().unwrap();
            let from = [
                std::mem::replace(&mut v.x, x),
                std::mem::replace(&mut v.y, y),
            ];
            v.to = Some(Box::new(from));
        }
        let wrong = rastercheck::bench::translation_time_coverage(&reversed).unwrap();
        caught += riemann_disagreements(&s, &wrong);
    }
    assert!(caught > 0, "time-reversed values went unnoticed");
}

/// The probe reports the most heap held at once above the call's start, on
/// any thread, the returned value included: two 1 MiB buffers one after the
/// other read 1 MiB (a total of allocations, the plausible slip, reads 2),
/// two at once 2 MiB, and freeing what existed before reads about 0, not a
/// negative or a wrapped number. Other tests allocate on their own threads
/// meanwhile, hence the slack.
#[test]
fn peak_heap_is_the_most_held_at_once() {
    use std::hint::black_box;
    const MIB: u64 = 1 << 20;
    const SLACK: u64 = 256 << 10;
    let near = |got: Option<u64>, want: u64| {
        let got = got.expect("the counting allocator is installed");
        assert!(got.abs_diff(want) <= SLACK, "{got} bytes, not about {want}");
    };
    assert!(memory::installed());
    let buffer = || black_box(vec![1u8; MIB as usize]);
    near(memory::peak(|| buffer().len()).1, MIB);
    near(
        memory::peak(|| {
            for _ in 0..2 {
                black_box(buffer());
            }
        })
        .1,
        MIB,
    );
    near(memory::peak(|| buffer().len() + buffer().len()).1, 2 * MIB);
    near(
        memory::peak(|| std::thread::scope(|s| s.spawn(|| buffer().len()).join().unwrap())).1,
        MIB,
    );
    let (kept, returned) = memory::peak(buffer);
    near(returned, MIB);
    near(memory::peak(move || drop(kept)).1, 0);
    // A probe inside another is not measured; the outer one still is.
    let (inner, outer) = memory::peak(|| memory::peak(|| buffer().len()).1);
    assert_eq!(inner, None);
    near(outer, MIB);
}
