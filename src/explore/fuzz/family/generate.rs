//! [`generate`]: case `index` of a seed drawn from its own stream, kept
//! only when it is a valid case (SPEC.md §8); the same scenes drawn from a
//! tape of choices for `fuzz/`'s scene target.

use super::antialias::antialias_scene;
use super::clip::clip_scene;
use super::conservative::conservative_scene;
use super::conservative_lines::points_and_lines_scene;
use super::lines::line_scene;
use super::list::Family;
use super::mesh::mesh_scene;
use super::motion::motion_scene;
use super::polygons::polygon_scene;
use super::triangles::triangle_scene;
use crate::explore::fuzz::case_json::valid;
use crate::explore::fuzz::rng::Rng;
use crate::scene::Scene;

/// Case `index` of a run with `seed`: its family (the one asked for, or the
/// families in turn) and its scene.
pub fn generate(seed: u64, index: u64, family: Option<Family>) -> (Family, Scene) {
    let family = family.unwrap_or(Family::ALL[(index % Family::ALL.len() as u64) as usize]);
    let mut scene = generate_with(&mut Rng::for_case(seed, index), family);
    scene.name = format!("fuzz_{}_{seed}_{index}", family.name());
    (family, scene)
}

/// The first valid scene of `family` drawn from `rng`.
fn generate_with(rng: &mut Rng, family: Family) -> Scene {
    loop {
        let scene = match family {
            Family::Triangles => Some(triangle_scene(rng)),
            Family::Lines => Some(line_scene(rng)),
            Family::Meshes => mesh_scene(rng),
            Family::Polygons => Some(polygon_scene(rng)),
            Family::Antialias => Some(antialias_scene(rng)),
            Family::Motion => Some(motion_scene(rng)),
            Family::Clip => Some(clip_scene(rng)),
            Family::Conservative if rng.chance(1, 3) => Some(points_and_lines_scene(rng)),
            Family::Conservative => Some(conservative_scene(rng)),
        };
        if let Some(scene) = scene.filter(|s| valid(s).is_ok()) {
            return scene;
        }
    }
}

/// The scene a tape of choices draws (`fuzz/`'s scene target): the first
/// choice picks the family, the rest are the family's own draws
/// ([`Rng::from_tape`]).
pub fn scene_from_tape(tape: &[u8]) -> (Family, Scene) {
    let mut rng = Rng::from_tape(tape);
    let family = Family::ALL[rng.below(Family::ALL.len() as u64) as usize];
    let mut scene = generate_with(&mut rng, family);
    scene.name = format!("fuzz_{}_tape", family.name());
    (family, scene)
}

/// The tape from which [`scene_from_tape`] draws case `index` of `seed` in
/// `family`: a seed for the scene target's corpus.
pub fn tape_of_case(seed: u64, index: u64, family: Family) -> Vec<u8> {
    let at = Family::ALL.iter().position(|&f| f == family).unwrap_or(0);
    let mut tape = vec![at as u8];
    let mut rng = Rng::for_case(seed, index).recording();
    generate_with(&mut rng, family);
    tape.extend_from_slice(rng.recorded());
    tape
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::explore::fuzz::case_json::case_json;
    use crate::scene::time::limits::TIME_ONE;
    use crate::scene::{LineRule, Pattern, Primitive, TimePattern};

    #[test]
    fn generation_is_deterministic() {
        for i in 0..30 {
            let (_, a) = generate(7, i, None);
            let (_, b) = generate(7, i, None);
            assert_eq!(case_json(&a), case_json(&b));
        }
    }

    #[test]
    fn a_case_of_a_search_naming_no_family_is_the_same_case_of_its_family() {
        // What makes `--family F --first-case I --cases 1` (a finding's
        // reproduction) draw case I of a search that named no family, in
        // this version and in one with more families.
        for i in 0..2 * Family::ALL.len() as u64 {
            let (family, unnamed) = generate(11, i, None);
            let (named_family, named) = generate(11, i, Some(family));
            assert_eq!(named_family, family);
            assert_eq!(case_json(&unnamed), case_json(&named), "case {i}");
        }
    }

    #[test]
    fn tapes_draw_the_cases_they_were_recorded_from() {
        for family in Family::ALL {
            for i in 0..8 {
                let (_, mut scene) = generate(21, i, Some(family));
                let (drawn, mut again) = scene_from_tape(&tape_of_case(21, i, family));
                assert_eq!(drawn, family);
                (scene.name, again.name) = (String::new(), String::new());
                assert_eq!(case_json(&scene), case_json(&again));
            }
        }
        // Any bytes draw a valid scene, the empty tape included.
        for tape in [&[][..], &[255; 3], &[3, 0, 0, 0, 0, 9]] {
            let (_, scene) = scene_from_tape(tape);
            assert!(valid(&scene).is_ok());
        }
    }

    #[test]
    fn generated_scenes_read_back_as_written() {
        for i in 0..60 {
            let (_, scene) = generate(11, i, None);
            let text = case_json(&scene);
            let back = crate::scene::parse_case(&text, "t", &Default::default())
                .unwrap_or_else(|e| panic!("{e}\n{text}"));
            assert_eq!(case_json(&back), text);
        }
    }

    #[test]
    fn polygon_and_antialias_families_read_back_and_vary() {
        let (mut contours, mut fills, mut patterns) = (0, Vec::new(), Vec::new());
        let (mut adaptive, mut lines) = (false, false);
        for i in 0..150 {
            for family in [Family::Polygons, Family::Antialias] {
                let (_, scene) = generate(3, i, Some(family));
                let text = case_json(&scene);
                let back = crate::scene::parse_case(&text, "t", &Default::default())
                    .unwrap_or_else(|e| panic!("{e}\n{text}"));
                assert_eq!(case_json(&back), text);
                for p in &scene.primitives {
                    match p {
                        Primitive::Polygon(q) => {
                            contours = contours.max(q.contour_ends.len());
                            if !fills.contains(&q.fill) {
                                fills.push(q.fill);
                            }
                        }
                        Primitive::Line(l) => lines |= l.rule == LineRule::Parallelogram,
                        Primitive::Triangle(_) | Primitive::Point(_) => {}
                    }
                }
                if let Some(a) = &scene.effects.antialias {
                    assert_eq!(family, Family::Antialias);
                    adaptive |= a.adaptive;
                    if !patterns.contains(&a.pattern) {
                        patterns.push(a.pattern);
                    }
                }
            }
        }
        assert_eq!(contours, 3);
        assert_eq!(fills.len(), 2);
        assert_eq!(patterns.len(), Pattern::ALL.len());
        assert!(adaptive && lines);
    }

    #[test]
    fn motion_family_reads_back_and_varies() {
        let (mut patterns, mut culls, mut shutters) = (Vec::new(), Vec::new(), 0);
        let (mut lines, mut antialiased, mut still, mut frozen_written) = (0, 0, 0, 0);
        let (mut counts, mut moving) = (Vec::new(), 0);
        for i in 0..300 {
            let (family, scene) = generate(5, i, Some(Family::Motion));
            assert_eq!(family, Family::Motion);
            let text = case_json(&scene);
            let back = crate::scene::parse_case(&text, "t", &Default::default())
                .unwrap_or_else(|e| panic!("{e}\n{text}"));
            assert_eq!(case_json(&back), text);
            let blur = scene.effects.motion_blur.as_ref().expect("motion blur");
            let spatial = scene.effects.antialias.as_ref().map_or(1, |a| a.samples);
            assert!(spatial * blur.samples <= 64, "{text}");
            assert!(
                scene.canvas.pixel_count() * spatial as usize <= 256,
                "{text}"
            );
            for (name, list) in [
                (blur.pattern.name(), &mut patterns),
                (scene.rules.cull.name(), &mut culls),
            ] {
                if !list.contains(&name) {
                    list.push(name);
                }
            }
            if !counts.contains(&blur.samples) {
                counts.push(blur.samples);
            }
            shutters += usize::from(blur.shutter != [0, TIME_ONE]);
            antialiased += usize::from(scene.effects.antialias.is_some());
            lines += scene
                .primitives
                .iter()
                .filter(|p| p.moves() && matches!(p, Primitive::Line(_)))
                .count();
            still += scene.primitives.iter().filter(|p| !p.moves()).count();
            frozen_written += scene
                .vertices()
                .filter(|v| v.to.is_some() && !v.moves())
                .count();
            moving += usize::from(scene.moves());
        }
        assert!(moving > 290, "{moving}");
        assert_eq!(patterns.len(), TimePattern::ALL.len());
        assert_eq!(culls.len(), 3);
        assert!(counts.contains(&1) && counts.contains(&64), "{counts:?}");
        assert!(
            shutters > 30 && antialiased > 30 && lines > 30,
            "{shutters} {antialiased} {lines}"
        );
        assert!(
            still > 30 && frozen_written > 10,
            "{still} {frozen_written}"
        );
    }
}
