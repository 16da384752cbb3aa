//! The brute force: the static reference at K exact instants, the
//! tolerance from the number of changes, and the disagreements with the
//! certified oracle.

use crate::scenes::r;
use dashu_ratio::RBig;
use rastercheck::plan::Plan;
use rastercheck::reference;
use rastercheck::reference::motion::{self, Certified, Mutation};
use rastercheck::scene::{Number, Primitive, Scene};

/// The spatial samples of a pixel, as offsets in pixels from its corner.
pub fn offsets(scene: &Scene) -> Vec<[RBig; 2]> {
    match Plan::for_scene(scene).antialias {
        Some(samples) => samples
            .offsets
            .iter()
            .map(|o| o.map(|c| r(i64::from(c), 1 << samples.position_bits)))
            .collect(),
        None => vec![[r(1, 2), r(1, 2)]],
    }
}

/// The K stratified instants open + (close − open)(j + ½)/K.
pub fn instants(scene: &Scene, k: usize) -> Vec<RBig> {
    let [open, close] = shutter(scene);
    (0..k)
        .map(|j| &open + (&close - &open) * r(2 * j as i64 + 1, 2 * k as i64))
        .collect()
}

pub fn shutter(scene: &Scene) -> [RBig; 2] {
    let blur = scene.effects.motion_blur.as_ref().expect("motion blur");
    blur.shutter.map(|u| r(i64::from(u), 1 << 16))
}

/// Brute force: each sample slot's coverage count at each instant, from
/// the static reference on the static scene at that instant
/// (`Scene::at_instant`). `coverage_under` is the visit `reference::render`
/// counts coverage with, without the exact areas an antialiased render
/// also computes.
pub fn brute_samples(scene: &Scene, instants: &[RBig]) -> Vec<Vec<u16>> {
    instants
        .iter()
        .map(|t| {
            let at = scene.at_instant(&Number::from_rbig(t.clone()));
            reference::coverage_under(&at, &Plan::for_scene(&at), scene.rules.fill_rule)
        })
        .collect()
}

/// Each pixel's mean over instants and spatial samples.
pub fn brute_pixels(samples: &[Vec<u16>], m: usize) -> Vec<RBig> {
    let pixels = samples[0].len() / m;
    (0..pixels)
        .map(|p| {
            let sum: u64 = samples
                .iter()
                .flat_map(|at| &at[p * m..(p + 1) * m])
                .map(|&c| u64::from(c))
                .sum();
            r(sum as i64, (samples.len() * m) as i64)
        })
        .collect()
}

/// C of the module doc, summed over the moving primitives.
pub fn changes(scene: &Scene) -> i64 {
    scene
        .primitives
        .iter()
        .filter(|p| p.moves())
        .map(|p| match p {
            Primitive::Triangle(_) => 8,
            _ => 16,
        })
        .sum()
}

/// Pixels where |brute − value| > C/(2K) + bound, described.
pub fn disagreements(
    scene: &Scene,
    certified: &[Certified],
    brute: &[RBig],
    k: usize,
) -> Vec<String> {
    let tolerance = r(changes(scene), 2 * k as i64);
    certified
        .iter()
        .zip(brute)
        .enumerate()
        .filter(|(_, (c, b))| {
            let error = &c.value - *b;
            let error = if error < RBig::ZERO { -error } else { error };
            error > &tolerance + &c.bound
        })
        .map(|(p, (c, b))| {
            let w = scene.canvas.width as usize;
            format!(
                "({}, {}): certified {} (±{:e}), brute {}",
                p % w,
                p / w,
                c.value.to_f64().value(),
                c.bound.to_f64().value(),
                b.to_f64().value()
            )
        })
        .collect()
}

pub fn coverage(scene: &Scene) -> Vec<Certified> {
    motion::time_coverage(scene, &Plan::for_scene(scene))
}

pub fn mutated(scene: &Scene, mutation: Mutation) -> Vec<Certified> {
    motion::time_coverage_with(scene, &Plan::for_scene(scene), mutation)
}
