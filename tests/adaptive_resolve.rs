//! `adaptive-resolve` computes production's box resolve of full
//! supersampling bit for bit, without a sample mask: random triangle scenes
//! under every pattern, sample count, fill rule and snapping.

use rastercheck::explore::fuzz::Rng;
use rastercheck::plan::Plan;
use rastercheck::production::adaptive::resolve::AdaptiveResolve;
use rastercheck::production::Production;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::scene::{
    Antialias, Canvas, Cull, Effects, Expect, FillRule, Interpolation, Number, Pattern, Primitive,
    Rules, Scene, Triangle, Vertex,
};

fn scene(rng: &mut Rng, pattern: Pattern, samples: u32, rule: FillRule) -> Scene {
    let canvas = Canvas {
        width: *rng.pick(&[7, 24, 41]),
        height: *rng.pick(&[5, 24, 33]),
    };
    // Coarse coordinates put vertices and edges on pixel borders and
    // sample positions, where the tie rule decides.
    let den = *rng.pick(&[1, 2, 4, 256]);
    let coordinate = |rng: &mut Rng, size: u32| {
        let span = i64::from(size) * den;
        Number::ratio(rng.range(-span / 4, span + span / 4), den)
    };
    let primitives = (0..rng.range(1, 12))
        .map(|_| {
            Primitive::Triangle(Triangle {
                vertices: [0, 1, 2].map(|_| {
                    Vertex::at(
                        coordinate(rng, canvas.width),
                        coordinate(rng, canvas.height),
                    )
                }),
                interpolation: Interpolation::Linear,
            })
        })
        .collect();
    Scene {
        name: "adaptive-resolve".to_owned(),
        description: String::new(),
        canvas,
        rules: Rules {
            subpixel_bits: *rng.pick(&[Some(0), Some(4), Some(8), None]),
            fill_rule: rule,
            cull: *rng.pick(&[Cull::None, Cull::Clockwise]),
            ..Rules::default()
        },
        primitives,
        effects: Effects {
            antialias: Some(Antialias {
                samples,
                pattern,
                seed: rng.next_u64(),
                adaptive: false,
                position_bits: if samples <= 16 { *rng.pick(&[4, 8]) } else { 8 },
            }),
            motion_blur: None,
            conservative: None,
        },
        expect: Expect::default(),
        attribute_count: 0,
        has_depth: false,
        viewport: None,
    }
}

#[test]
fn resolved_equals_full_supersampling_box_resolve() {
    let mut rng = Rng::new(0x7265_736f);
    let mut seen = 0;
    for pattern in Pattern::ALL {
        for samples in [1, 2, 4, 8, 16, 64, 256] {
            if pattern.check_count(samples).is_err() {
                continue;
            }
            for rule in FillRule::ALL {
                for _ in 0..4 {
                    let s = scene(&mut rng, pattern, samples, rule);
                    let plan = Plan::for_scene(&s);
                    let full = Production.rasterize(&s, &plan).unwrap();
                    let resolved = AdaptiveResolve.rasterize(&s, &plan).unwrap();
                    assert_eq!(resolved.samples, 0, "no mask is written");
                    let want = full.box_resolve();
                    let got = resolved.resolved.unwrap();
                    let same = want
                        .iter()
                        .zip(&got)
                        .all(|(a, b)| a.to_bits() == b.to_bits());
                    assert!(same, "{pattern:?} {samples} {rule:?}: {s:#?}");
                    seen += 1;
                }
            }
        }
    }
    assert!(seen > 200);
}

/// The comparison sees a tie decided the other way: the same scene under
/// a rule that owns other edges resolves differently.
#[test]
fn a_wrong_tie_rule_is_caught() {
    let mut rng = Rng::new(1);
    let mut s = scene(&mut rng, Pattern::Grid, 4, FillRule::TopLeft);
    // The left edge x = 5/4 runs through the grid's samples at 1/4 of
    // their pixels; top-left owns them, bottom-right does not.
    s.rules.subpixel_bits = Some(2);
    s.rules.cull = Cull::None;
    s.primitives = vec![Primitive::Triangle(Triangle {
        vertices: [(5, 4), (20, 4), (5, 16)]
            .map(|(x, y)| Vertex::at(Number::ratio(x, 4), Number::ratio(y, 4))),
        interpolation: Interpolation::Linear,
    })];
    s.effects.antialias.as_mut().unwrap().position_bits = 2;
    let plan = Plan::for_scene(&s);
    let want = Production.rasterize(&s, &plan).unwrap().box_resolve();
    let mut wrong = s.clone();
    wrong.rules.fill_rule = FillRule::BottomRight;
    let got = AdaptiveResolve
        .rasterize(&wrong, &plan)
        .unwrap()
        .resolved
        .unwrap();
    assert_ne!(want, got);
    let right = AdaptiveResolve
        .rasterize(&s, &plan)
        .unwrap()
        .resolved
        .unwrap();
    assert_eq!(want, right);
}

#[test]
fn what_it_cannot_draw_is_refused() {
    let mut rng = Rng::new(2);
    let mut s = scene(&mut rng, Pattern::Standard, 4, FillRule::TopLeft);
    s.effects.antialias = None;
    assert!(AdaptiveResolve.rasterize(&s, &Plan::for_scene(&s)).is_err());
}
