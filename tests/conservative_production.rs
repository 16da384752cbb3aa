//! Production's conservative rasterization (SPEC.md §19) against
//! hand-computed answers and against the exact reference's classes.
//!
//! Production draws the extreme a case allows: in overestimation every
//! pixel not forbidden (its square grown by the uncertainty meets the
//! triangle), in underestimation every required one (so grown, it lies
//! inside), and the fully-covered flag where the grown square lies
//! inside. So on every scene its frame is a function of the reference's
//! classes, and these tests hold it to that function exactly, not just
//! to a passing verdict.

use dashu_ratio::RBig;
use rastercheck::explore::fuzz::{generate, Family};
use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::production::Production;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::reference::conservative::{classify, PixelClass};
use rastercheck::scene::{parse_case, ConservativeMode, Limits, Primitive, Scene};

fn scene(json: &str) -> Scene {
    parse_case(json, "t.json", &Limits::default()).unwrap_or_else(|e| panic!("{e}\n{json}"))
}

fn draw(scene: &Scene) -> Frame {
    Production
        .rasterize(scene, &Plan::for_scene(scene))
        .unwrap_or_else(|e| panic!("{e}"))
}

/// A one-triangle conservative case on a `side`² canvas.
fn case(side: u32, vertices: &str, conservative: &str) -> Scene {
    scene(&format!(
        r#"{{ "name": "t", "canvas": {{ "width": {side}, "height": {side} }},
        "rules": {{ "subpixel_bits": 8 }},
        "effects": {{ "conservative": {{ {conservative} }} }},
        "primitives": [ {{ "triangle": {vertices} }} ] }}"#
    ))
}

/// The drawn pixels, as (x, y), row by row.
fn drawn(frame: &Frame) -> Vec<(u32, u32)> {
    let mut out = Vec::new();
    for y in 0..frame.height {
        for x in 0..frame.width {
            if frame.coverage[frame.index(x, y)] > 0 {
                out.push((x, y));
            }
        }
    }
    out
}

fn flagged(frame: &Frame) -> Vec<(u32, u32)> {
    let flags = frame
        .fully_covered
        .as_ref()
        .expect("the flag was asked for");
    drawn(frame)
        .into_iter()
        .filter(|&(x, y)| flags[frame.index(x, y)])
        .collect()
}

fn square(x0: u32, x1: u32, y0: u32, y1: u32) -> Vec<(u32, u32)> {
    (y0..=y1)
        .flat_map(|y| (x0..=x1).map(move |x| (x, y)))
        .collect()
}

/// The triangle x ≥ 2, y ≥ 2, x + y ≤ 6: its right angle on the corner of
/// pixel (1, 1), its hypotenuse through the corner of pixel (3, 3).
const CORNER: &str =
    r#"[ { "position": [2, 2] }, { "position": [4, 2] }, { "position": [2, 4] } ]"#;

#[test]
fn overestimation_draws_pixels_touched_at_one_point() {
    // Every pixel of [1, 3]²: (1, 1) and (3, 3) meet the triangle at a
    // single point, (1, 2), (2, 1) and the rest of the border along an
    // edge; and the four whose corners the vertices (4, 2) and (2, 4)
    // touch: (4, 1), (4, 2), (1, 4), (2, 4). None of row 0 or column 0.
    let frame = draw(&case(
        5,
        CORNER,
        r#""mode": "overestimate", "fully_covered": true"#,
    ));
    let mut expected = square(1, 3, 1, 3);
    expected.extend([(4, 1), (4, 2), (1, 4), (2, 4)]);
    expected.sort_by_key(|&(x, y)| (y, x));
    assert_eq!(drawn(&frame), expected);
    // Only (2, 2) is wholly inside (its far corner on the hypotenuse).
    assert_eq!(flagged(&frame), vec![(2, 2)]);
}

#[test]
fn the_uncertainty_grows_the_pixel_square_on_every_side() {
    // Grown by ½ px, pixel (4, 3)'s square [3.5, 5.5] × [2.5, 4.5] reaches
    // the hypotenuse at (3.5, 2.5); (4, 4)'s stays ½ px away from it
    // diagonally ((3.5, 3.5) has x + y = 7); (0, 2)'s reaches x = 1.5 only.
    let over = |u: &str| {
        draw(&case(
            6,
            CORNER,
            &format!(r#""mode": "overestimate", "uncertainty": "{u}""#),
        ))
    };
    let tight = drawn(&over("0"));
    let grown = drawn(&over("1/2"));
    assert!(!tight.contains(&(4, 3)) && grown.contains(&(4, 3)));
    assert!(!grown.contains(&(4, 4)) && !grown.contains(&(0, 2)));
    assert!(tight.iter().all(|p| grown.contains(p)));
    // Just under: the grown square stops 1/256 px short of the hypotenuse.
    assert!(!drawn(&over("127/256")).contains(&(4, 3)));
}

#[test]
fn underestimation_draws_wholly_covered_pixels() {
    let under = |u: &str| {
        draw(&case(
            6,
            CORNER,
            &format!(r#""mode": "underestimate", "uncertainty": "{u}", "fully_covered": true"#),
        ))
    };
    let tight = under("0");
    assert_eq!(drawn(&tight), vec![(2, 2)]);
    assert_eq!(flagged(&tight), vec![(2, 2)]);
    // Grown by 1/256 px, (2, 2)'s square crosses x = 2: nothing is sure.
    assert!(drawn(&under("1/256")).is_empty());
}

#[test]
fn degenerate_triangles_are_drawn_as_their_segment_or_culled() {
    // Collinear vertices on the line y = x: the segment from (1, 1) to
    // (3, 3) runs through the squares of pixels (1, 1) and (2, 2), and
    // touches those of (0, 0), (3, 3), (1, 0), (0, 1), (2, 1) and (1, 2)
    // at one corner each; (3, 0) and (4, 4) it misses.
    let segment = r#"[ { "position": [1, 1] }, { "position": [2, 2] }, { "position": [3, 3] } ]"#;
    let drawn_with = |degenerate: bool| {
        drawn(&draw(&case(
            5,
            segment,
            &format!(r#""mode": "overestimate", "degenerate_triangles": {degenerate}"#),
        )))
    };
    assert!(drawn_with(false).is_empty());
    let on = drawn_with(true);
    for p in [
        (0, 0),
        (1, 1),
        (2, 2),
        (3, 3),
        (1, 0),
        (0, 1),
        (2, 1),
        (1, 2),
    ] {
        assert!(on.contains(&p), "{p:?} in {on:?}");
    }
    assert!(!on.contains(&(3, 0)) && !on.contains(&(4, 4)), "{on:?}");
    // Underestimation draws nothing of a triangle without area.
    let under = case(
        5,
        segment,
        r#""mode": "underestimate", "degenerate_triangles": true"#,
    );
    assert!(drawn(&draw(&under)).is_empty());
}

/// Production's frame against the reference's classes: overestimation
/// draws exactly the pixels not forbidden, underestimation exactly the
/// required ones, and the flag is exactly the required flags.
fn agrees(scene: &Scene) -> Result<(), String> {
    let classes = match classify(scene) {
        Ok(c) => c,
        Err(e) => return Err(format!("the reference refused: {e}")),
    };
    let frame = draw(scene);
    let mode = scene
        .effects
        .conservative
        .as_ref()
        .expect("conservative")
        .mode;
    // Multisampled (SPEC.md §19.10): a pixel's samples all or none.
    let n = frame.samples.max(1) as usize;
    let covered = |i: usize| {
        let run = &frame.coverage[i * n..(i + 1) * n];
        match (run.iter().all(|&c| c > 0), run.iter().any(|&c| c > 0)) {
            (all, any) if all == any => Ok(all),
            _ => Err(format!(
                "pixel ({}, {}): only some of its samples covered",
                i as u32 % frame.width,
                i as u32 / frame.width
            )),
        }
    };
    for (i, class) in classes.drawn.iter().enumerate() {
        let expected = match mode {
            ConservativeMode::Overestimate => *class != PixelClass::Forbidden,
            ConservativeMode::Underestimate => *class == PixelClass::Required,
        };
        let got = covered(i)?;
        if got != expected {
            return Err(format!(
                "pixel ({}, {}): the reference classes it {}, production {}",
                i as u32 % frame.width,
                i as u32 / frame.width,
                class.name(),
                if got { "draws it" } else { "does not" }
            ));
        }
    }
    if let Some(flags) = &classes.fully_covered {
        let got = frame.fully_covered.as_ref().ok_or("no flag")?;
        for (i, class) in flags.iter().enumerate() {
            let drawn = covered(i)?;
            // One triangle: the flag is exactly the sure one (S_u inside
            // the triangle); several: whatever the last writer's class
            // admits.
            let exact = scene.primitives.len() == 1 && got[i] != (*class == PixelClass::Required);
            if drawn && (exact || !class.admits(got[i])) || !drawn && got[i] {
                return Err(format!(
                    "pixel ({}, {}): flag {} where the reference classes it {}",
                    i as u32 % frame.width,
                    i as u32 / frame.width,
                    got[i],
                    class.name()
                ));
            }
        }
    }
    Ok(())
}

/// A brute force of SPEC.md §19's sets, independent of production and of
/// the reference: each triangle (snapped, in rationals) clipped against
/// the pixel's grown square S_u by the four closed half-planes of its
/// sides (Sutherland–Hodgman; a touch at one point leaves that point);
/// S_u meets the triangle when anything is left. S_u lies inside when its
/// four corners do. Points' squares, parallelogram lines and degenerate
/// lines' points (SPEC.md §19.8) are convex polygons with rational
/// corners and are clipped the same way; a rectangle line's corners are
/// irrational, so a scene with one is `None` (`agrees` holds those).
/// Returns (drawn, flag) per pixel, last writer's flag.
fn brute_force(scene: &Scene) -> Option<(Vec<bool>, Vec<bool>)> {
    let c = scene.effects.conservative.as_ref().expect("conservative");
    let u = c.uncertainty.as_rbig().clone();
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let n = (w * h) as usize;
    let (mut drawn, mut flags) = (vec![false; n], vec![false; n]);
    for primitive in &scene.primitives {
        let v: Vec<[RBig; 2]> = primitive
            .vertices()
            .iter()
            .map(|v| {
                [&v.x, &v.y].map(|n| match scene.rules.subpixel_bits {
                    Some(b) => n.snapped(b).as_rbig().clone(),
                    None => n.as_rbig().clone(),
                })
            })
            .collect();
        let v = match primitive {
            Primitive::Triangle(_) => v,
            Primitive::Point(p) => {
                let s = p.size.as_rbig() / RBig::from(2u8);
                let [x, y] = &v[0];
                vec![
                    [x - &s, y - &s],
                    [x + &s, y - &s],
                    [x + &s, y + &s],
                    [x - &s, y + &s],
                ]
            }
            Primitive::Line(_) if v[0] == v[1] => {
                if !c.degenerate_lines {
                    continue;
                }
                vec![v[0].clone()]
            }
            Primitive::Line(l) if l.rule == rastercheck::scene::LineRule::Parallelogram => {
                let d = [&v[1][0] - &v[0][0], &v[1][1] - &v[0][1]];
                let abs = |q: &RBig| if *q < RBig::ZERO { -q } else { q.clone() };
                let minor = usize::from(abs(&d[0]) >= abs(&d[1]));
                let s = l.width.as_rbig() / RBig::from(2u8);
                let shift = |p: &[RBig; 2], by: &RBig| {
                    let mut q = p.clone();
                    q[minor] = &q[minor] + by;
                    q
                };
                let minus = -&s;
                vec![
                    shift(&v[0], &minus),
                    shift(&v[1], &minus),
                    shift(&v[1], &s),
                    shift(&v[0], &s),
                ]
            }
            _ => return None,
        };
        let area = (1..v.len().saturating_sub(1))
            .map(|i| cross(&v[0], &v[i], &v[i + 1]))
            .fold(RBig::ZERO, |a, b| a + b);
        let triangle = matches!(primitive, Primitive::Triangle(_));
        if triangle && area == RBig::ZERO && !c.degenerate_triangles {
            continue;
        }
        if triangle && scene.rules.cull.discards(area.cmp(&RBig::ZERO)) {
            continue;
        }
        for y in 0..h {
            for x in 0..w {
                let lo = [RBig::from(x) - &u, RBig::from(y) - &u];
                let hi = [RBig::from(x + 1) + &u, RBig::from(y + 1) + &u];
                let inside = area != RBig::ZERO
                    && [&lo[0], &hi[0]].into_iter().all(|cx| {
                        [&lo[1], &hi[1]].into_iter().all(|cy| {
                            let p = [cx.clone(), cy.clone()];
                            (0..v.len()).all(|i| {
                                let s = cross(&v[i], &v[(i + 1) % v.len()], &p);
                                s == RBig::ZERO || (s > RBig::ZERO) == (area > RBig::ZERO)
                            })
                        })
                    });
                let draw = match c.mode {
                    ConservativeMode::Overestimate => meets(v.clone(), &lo, &hi),
                    ConservativeMode::Underestimate => inside,
                };
                if draw {
                    let i = (y * w + x) as usize;
                    drawn[i] = true;
                    flags[i] = inside;
                }
            }
        }
    }
    Some((drawn, flags))
}

fn cross(a: &[RBig; 2], b: &[RBig; 2], p: &[RBig; 2]) -> RBig {
    (&b[0] - &a[0]) * (&p[1] - &a[1]) - (&b[1] - &a[1]) * (&p[0] - &a[0])
}

/// Whether the convex polygon `poly` meets the closed box [lo, hi].
fn meets(mut poly: Vec<[RBig; 2]>, lo: &[RBig; 2], hi: &[RBig; 2]) -> bool {
    for axis in 0..2 {
        for (bound, keep_above) in [(&lo[axis], true), (&hi[axis], false)] {
            let inside = |p: &[RBig; 2]| {
                if keep_above {
                    p[axis] >= *bound
                } else {
                    p[axis] <= *bound
                }
            };
            let mut out = Vec::new();
            for k in 0..poly.len() {
                let (p, q) = (&poly[k], &poly[(k + 1) % poly.len()]);
                if inside(p) {
                    out.push(p.clone());
                }
                if inside(p) != inside(q) {
                    let t = (bound - &p[axis]) / (&q[axis] - &p[axis]);
                    out.push([0, 1].map(|a| &p[a] + &t * (&q[a] - &p[a])));
                }
            }
            poly = out;
            if poly.is_empty() {
                return false;
            }
        }
    }
    true
}

#[test]
fn production_matches_a_brute_force_of_the_sets() {
    let mut forced = 0;
    for index in 0..600 {
        let (_, scene) = generate(35, index, Some(Family::Conservative));
        let frame = draw(&scene);
        let Some((drawn, flags)) = brute_force(&scene) else {
            continue;
        };
        forced += 1;
        // Multisampled (SPEC.md §19.10): a pixel is drawn when any of
        // its samples is (`agrees` holds it to all or none).
        let n = frame.samples.max(1) as usize;
        let got: Vec<bool> = frame
            .coverage
            .chunks(n)
            .map(|run| run.iter().any(|&c| c > 0))
            .collect();
        let text = || rastercheck::explore::fuzz::case_json(&scene);
        assert_eq!(got, drawn, "scene {index}: drawn pixels\n{}", text());
        if let Some(f) = &frame.fully_covered {
            assert_eq!(*f, flags, "scene {index}: flags\n{}", text());
        }
    }
    assert!(forced > 400, "{forced} scenes brute-forced");
}

/// Scenes `0..count` of the fuzzer's conservative family under `seed`,
/// each held to [`agrees`]; panics with the first that differs, as a case
/// file. Returns how many the reference judged.
fn exact_over(seed: u64, count: u64) -> u64 {
    let mut judged = 0;
    for index in 0..count {
        let (_, scene) = generate(seed, index, Some(Family::Conservative));
        if let Err(why) = agrees(&scene) {
            panic!(
                "scene {index} of seed {seed}: {why}\n{}",
                rastercheck::explore::fuzz::case_json(&scene)
            );
        }
        judged += 1;
    }
    judged
}

#[test]
fn production_is_exact_on_the_fuzzers_conservative_family() {
    assert_eq!(exact_over(38, 1500), 1500);
}

/// The family draws multisampled scenes (SPEC.md §19.10), of more than one
/// sample and never with depth (not judged, §19.7), each judged: held to
/// [`agrees`] above, and production's verdict on it a pass.
#[test]
fn the_fuzzers_conservative_family_draws_multisampled_scenes() {
    let (mut multisampled, mut many) = (0, 0);
    for index in 0..1500 {
        let (_, scene) = generate(38, index, Some(Family::Conservative));
        let Some(aa) = &scene.effects.antialias else {
            continue;
        };
        multisampled += 1;
        many += usize::from(aa.samples > 1);
        assert!(!scene.has_depth, "scene {index}");
        assert_eq!(scene.conservative_unjudged(), None, "scene {index}");
        let reference = rastercheck::harness::oracle::run_reference(&scene);
        let run = rastercheck::harness::judge::run_candidate(&scene, &reference, &Production);
        assert!(
            matches!(run.verdict, rastercheck::harness::judge::Verdict::Pass),
            "scene {index}: {:?}\n{}",
            run.verdict,
            rastercheck::explore::fuzz::case_json(&scene)
        );
    }
    assert!(
        multisampled > 150 && many > 100,
        "{multisampled} multisampled, {many} of more than one sample"
    );
}

/// The issue's done-when: 0 differences over at least 10^5 scenes
/// (`CONSERVATIVE_SCENES` to change the count). Minutes, so ignored:
/// `cargo test --release --test conservative_production -- --ignored`.
#[test]
#[ignore]
fn production_is_exact_on_a_hundred_thousand_scenes() {
    let count = std::env::var("CONSERVATIVE_SCENES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(100_000);
    let started = std::time::Instant::now();
    assert_eq!(exact_over(1, count), count);
    eprintln!("{count} scenes, 0 differences, {:.1?}", started.elapsed());
}

/// Every bundled conservative case: production's frame exactly the
/// extreme the classes allow, and its verdict a pass.
#[test]
fn production_is_exact_and_passes_on_every_bundled_case() {
    let mut judged = 0;
    for entry in std::fs::read_dir("cases/conservative").expect("cases/conservative") {
        let path = entry.expect("an entry").path();
        let text = std::fs::read_to_string(&path).expect("a case file");
        let scene = parse_case(&text, &path.display().to_string(), &Limits::default())
            .unwrap_or_else(|e| panic!("{e}"));
        if let Err(why) = agrees(&scene) {
            panic!("{}: {why}", path.display());
        }
        let reference = rastercheck::harness::oracle::run_reference(&scene);
        let run = rastercheck::harness::judge::run_candidate(&scene, &reference, &Production);
        assert!(
            matches!(run.verdict, rastercheck::harness::judge::Verdict::Pass),
            "{}: {:?}",
            path.display(),
            run.verdict
        );
        judged += 1;
    }
    assert!(judged >= 40, "{judged} cases");
}
