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

use rastercheck::explore::fuzz::{generate, Family};
use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::production::Production;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::reference::conservative::{classify, PixelClass};
use rastercheck::scene::{parse_case, ConservativeMode, Limits, Scene};

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
    // edge; none of row 0 or column 0.
    let frame = draw(&case(
        5,
        CORNER,
        r#""mode": "overestimate", "fully_covered": true"#,
    ));
    assert_eq!(drawn(&frame), square(1, 3, 1, 3));
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
    for (i, class) in classes.drawn.iter().enumerate() {
        let expected = match mode {
            ConservativeMode::Overestimate => *class != PixelClass::Forbidden,
            ConservativeMode::Underestimate => *class == PixelClass::Required,
        };
        let got = frame.coverage[i] > 0;
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
            let drawn = frame.coverage[i] > 0;
            if drawn && !class.admits(got[i]) || !drawn && got[i] {
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

#[test]
fn production_is_exact_on_the_fuzzers_conservative_family() {
    let mut judged = 0;
    for index in 0..1500 {
        let (_, scene) = generate(38, index, Some(Family::Conservative));
        if let Err(why) = agrees(&scene) {
            panic!(
                "scene {index}: {why}\n{}",
                rastercheck::explore::fuzz::case_json(&scene)
            );
        }
        judged += 1;
    }
    assert_eq!(judged, 1500);
}
