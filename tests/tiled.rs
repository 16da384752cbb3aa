//! `production-tiled` writes production's frame exactly: random scenes of
//! triangles, lines of every rule and polygons, with depth, attributes and
//! antialiasing, on canvases several bands tall.

use rastercheck::explore::fuzz::Rng;
use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::production::tiled::{Tiled, BAND};
use rastercheck::production::Production;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::scene::{
    Antialias, Canvas, Cull, Effects, Expect, FillRule, Interpolation, LastPixel, Line,
    LineParameter, LineRule, Number, Pattern, Polygon, PolygonFill, Primitive, Rules, Scene,
    Triangle, Vertex,
};

fn coordinate(rng: &mut Rng, size: u32) -> Number {
    // Mostly on the canvas, some beyond it; dyadic, so that ideal geometry
    // fits production's fixed point.
    let span = i64::from(size) * 256;
    Number::ratio(rng.range(-span / 4, span + span / 4), 256)
}

fn vertex(rng: &mut Rng, canvas: Canvas, attributes: usize) -> Vertex {
    let mut v = Vertex::at(
        coordinate(rng, canvas.width),
        coordinate(rng, canvas.height),
    );
    v.z = Number::ratio(rng.range(0, 1000), 1000);
    v.w = Number::ratio(rng.range(1, 40), 8);
    v.attributes = (0..attributes)
        .map(|_| Number::ratio(rng.range(-500, 500), 7))
        .collect();
    v
}

fn random_scene(rng: &mut Rng, antialiased: bool, polygons: bool) -> Scene {
    let canvas = Canvas {
        width: *rng.pick(&[40, 97, 130]),
        height: *rng.pick(&[BAND - 1, BAND + 1, 2 * BAND + 17, 3 * BAND]),
    };
    let values = !antialiased && rng.chance(1, 2);
    let attributes = if values { rng.below(3) as usize } else { 0 };
    let interpolation = *rng.pick(&[
        Interpolation::Flat,
        Interpolation::Linear,
        Interpolation::Perspective,
    ]);
    let count = rng.range(1, 40) as usize;
    let primitives = (0..count)
        .map(|_| {
            let kind = rng.below(if polygons { 3 } else { 2 });
            match kind {
                0 => Primitive::Triangle(Triangle {
                    vertices: [0, 1, 2].map(|_| vertex(rng, canvas, attributes)),
                    interpolation,
                }),
                1 => {
                    let rule = if antialiased {
                        LineRule::Parallelogram
                    } else {
                        *rng.pick(&LineRule::ALL)
                    };
                    Primitive::Line(Line {
                        vertices: [0, 1].map(|_| vertex(rng, canvas, attributes)),
                        rule,
                        width: Number::ratio(rng.range(1, 64), 8),
                        last_pixel: *rng.pick(&[LastPixel::Include, LastPixel::Exclude]),
                        parameter: *rng.pick(&[LineParameter::Major, LineParameter::Projected]),
                        interpolation,
                    })
                }
                _ => Primitive::Polygon(Polygon {
                    vertices: (0..rng.range(3, 9))
                        .map(|_| vertex(rng, canvas, 0))
                        .collect(),
                    contour_ends: Vec::new(),
                    fill: *rng.pick(&[PolygonFill::EvenOdd, PolygonFill::NonZero]),
                }),
            }
        })
        .map(|p| match p {
            Primitive::Polygon(mut polygon) => {
                polygon.contour_ends = vec![polygon.vertices.len()];
                Primitive::Polygon(polygon)
            }
            p => p,
        })
        .collect();
    let antialias = antialiased.then(|| {
        let pattern = *rng.pick(&Pattern::ALL);
        let samples = *rng.pick(&[1, 2, 4, 8, 16, 64]);
        let samples = if pattern.check_count(samples).is_ok() {
            samples
        } else {
            4
        };
        Antialias {
            samples,
            pattern,
            seed: rng.next_u64(),
            adaptive: rng.chance(1, 2),
            position_bits: *rng.pick(&[4, 8]),
        }
    });
    Scene {
        name: "tiled".to_owned(),
        description: String::new(),
        canvas,
        rules: Rules {
            subpixel_bits: *rng.pick(&[Some(0), Some(4), Some(8), None]),
            fill_rule: *rng.pick(&FillRule::ALL),
            cull: *rng.pick(&[Cull::None, Cull::Clockwise, Cull::CounterClockwise]),
            ..Rules::default()
        },
        primitives,
        effects: Effects {
            antialias,
            motion_blur: None,
            conservative: None,
        },
        expect: Expect::default(),
        attribute_count: attributes,
        has_depth: values,
        viewport: None,
    }
}

fn same(scene: &Scene) -> Result<(), String> {
    let plan = Plan::for_scene(scene);
    let tiled = Tiled.rasterize(scene, &plan);
    let production = Production.rasterize(scene, &plan);
    match (tiled, production) {
        (Ok(t), Ok(p)) => {
            if t != p {
                let differ = t
                    .coverage
                    .iter()
                    .zip(&p.coverage)
                    .zip(t.last.iter().zip(&p.last))
                    .position(|((a, b), (c, d))| a != b || c != d);
                return Err(format!("frames differ (first differing slot {differ:?})"));
            }
            Ok(())
        }
        (Err(t), Err(p)) if t.to_string() == p.to_string() => Ok(()),
        (t, p) => Err(format!(
            "tiled {:?}, production {:?}",
            t.map(|_| ()),
            p.map(|_| ())
        )),
    }
}

fn check(antialiased: bool, polygons: bool, seed: u64, rounds: u64) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    for i in 0..rounds {
        let mut rng = Rng::for_case(seed, i);
        let scene = random_scene(&mut rng, antialiased, polygons);
        if let Err(why) = pool.install(|| same(&scene)) {
            panic!("scene {i} of seed {seed:#x}: {why}\n{scene:#?}");
        }
    }
}

#[test]
fn triangles_and_lines_of_every_rule_match_production() {
    check(false, false, 0x7469_6c65, 150);
}

#[test]
fn antialiased_scenes_match_production() {
    check(true, false, 0x6161_7469, 80);
}

#[test]
fn scenes_with_polygons_match_production() {
    check(false, true, 0x706f_6c79, 30);
    check(true, true, 0x706f_6c7a, 20);
}

#[test]
fn the_bench_workloads_match_production() {
    for leg in [10, 50, 250] {
        let scene = rastercheck::bench::triangle_scene(512, leg, 300, 7);
        same(&scene).unwrap();
    }
    let lines = rastercheck::bench::line_scene(512, (100.0, 300.0), 300, 7);
    same(&lines).unwrap();
}

/// A band that dropped the primitives straddling its top is caught: the
/// comparison is sample by sample.
#[test]
fn a_frame_missing_one_band_row_is_caught() {
    let scene = rastercheck::bench::triangle_scene(256, 50, 40, 3);
    let plan = Plan::for_scene(&scene);
    let mut frame: Frame = Tiled.rasterize(&scene, &plan).unwrap();
    let width = frame.width as usize;
    // The first band's top row that something covers.
    let row = (1..frame.height / BAND)
        .map(|b| (b * BAND) as usize * width)
        .find(|&row| frame.coverage[row..row + width].iter().any(|&c| c > 0))
        .expect("a covered band top");
    frame.coverage[row..row + width].fill(0);
    assert_ne!(frame, Production.rasterize(&scene, &plan).unwrap());
}

/// Timings for development (`cargo test --release --test tiled -- --ignored
/// --nocapture`); asserts nothing about them.
#[test]
#[ignore]
fn timing() {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    for (leg, count) in [(10, 20_000), (50, 2_000), (250, 200)] {
        let scene = rastercheck::bench::triangle_scene(1024, leg, count, 0x6265_6e63_6821);
        let plan = Plan::for_scene(&scene);
        let one = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        let mut best = [f64::MAX; 3];
        for _ in 0..7 {
            let t = std::time::Instant::now();
            std::hint::black_box(one.install(|| Tiled.rasterize(&scene, &plan).unwrap()));
            best[2] = best[2].min(t.elapsed().as_secs_f64());
            let t = std::time::Instant::now();
            std::hint::black_box(Production.rasterize(&scene, &plan).unwrap());
            best[0] = best[0].min(t.elapsed().as_secs_f64());
            let t = std::time::Instant::now();
            std::hint::black_box(pool.install(|| Tiled.rasterize(&scene, &plan).unwrap()));
            best[1] = best[1].min(t.elapsed().as_secs_f64());
        }
        println!(
            "L={leg}: production {:.3} ms, tiled {:.3} ms ({:.3} ms on one thread), {:.2}×",
            best[0] * 1e3,
            best[1] * 1e3,
            best[2] * 1e3,
            best[0] / best[1]
        );
    }
}

/// Line timings for development, like [`timing`].
#[test]
#[ignore]
fn line_timing() {
    use rastercheck::bench::PlainMidpoint;
    let scene = rastercheck::bench::line_scene(2048, (1000.0, 1400.0), 3000, 0x6265_6e63_6821);
    let plan = Plan::for_scene(&scene);
    let mut best = [f64::MAX; 2];
    for _ in 0..7 {
        let t = std::time::Instant::now();
        std::hint::black_box(Production.rasterize(&scene, &plan).unwrap());
        best[0] = best[0].min(t.elapsed().as_secs_f64());
        let t = std::time::Instant::now();
        std::hint::black_box(PlainMidpoint.rasterize(&scene, &plan).unwrap());
        best[1] = best[1].min(t.elapsed().as_secs_f64());
    }
    println!(
        "lines: production {:.3} ms, plain {:.3} ms, {:.2}×",
        best[0] * 1e3,
        best[1] * 1e3,
        best[1] / best[0]
    );
}
