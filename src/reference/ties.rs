//! The tie set: every sample that lies exactly on an edge of a primitive
//! (an edge function exactly 0 after snapping, in exact arithmetic), with
//! what each rule could make of it. A rasterizer that declares no tie rule
//! (`fill_rule: "none"`, SPEC.md §3.1.1) is judged exactly everywhere else;
//! at a tie sample any outcome a choice of sides allows is accepted.
//!
//! A primitive holds a sample on one of its edges exactly when some rule
//! covers it and not all four consistent rules do: a sample strictly
//! inside is covered under every rule, and each consistent rule leaves out
//! two of the four edge kinds (top, bottom, left, right), so a sample on an
//! edge is left out by at least one of them; a sample on a vertex may be
//! covered by `all-edges` alone. The set is found that way, with the same
//! traversal and exact arithmetic as the reference's frame, and no float.
//! For polygons `all-edges` is not defined (SPEC.md §14.1): a polygon's
//! samples on a vertex that no consistent rule covers are not in the set.

use std::collections::{BTreeMap, HashMap};

use super::visit::{visit_samples, Arithmetic};
use crate::plan::Plan;
use crate::scene::{FillRule, Scene};

/// One tie sample: the primitives that hold it strictly inside and on an
/// edge, and the counts the consistent rules give it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TieSample {
    /// Primitives that cover it under every rule.
    pub inside: u16,
    /// The last of those (index + 1), 0 when none.
    pub last_inside: u32,
    /// Primitives that hold it on an edge (index + 1, in scene order).
    pub on_edge: Vec<u32>,
    /// The fewest and the most primitives a consistent rule covers it with.
    pub fewest: u16,
    pub most: u16,
}

/// What a candidate made of a tie sample.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TieOutcome {
    /// A choice of sides gives it: covered by every primitive holding it
    /// inside and some of those holding it on an edge, the last of them
    /// its owner. `overdrawn` when more primitives cover it than any
    /// consistent rule allows (both sides of a shared edge), `hole` when
    /// fewer (neither side).
    Allowed { overdrawn: bool, hole: bool },
    /// No choice of sides gives it: judged as any other sample.
    NotAllowed,
}

impl TieSample {
    /// Whether `count` covers with `last` (index + 1, 0 for none) is an
    /// outcome some choice of sides gives.
    pub fn outcome(&self, count: u16, last: u32) -> TieOutcome {
        let most_possible = usize::from(self.inside) + self.on_edge.len();
        let count_ok = count >= self.inside && usize::from(count) <= most_possible;
        // The chosen edge primitives S, |S| = count − inside, and the owner
        // is the latest of the inside ones and S.
        let chosen = usize::from(count.saturating_sub(self.inside));
        let before = |p: u32| self.on_edge.iter().filter(|&&q| q < p).count();
        let owner_ok = if count == 0 {
            last == 0
        } else if last == self.last_inside && last > 0 {
            // S drawn before the last inside primitive.
            before(self.last_inside) >= chosen
        } else {
            // S holds `last`, drawn after every inside primitive, and
            // chosen − 1 others drawn before it.
            chosen > 0
                && last > self.last_inside
                && self.on_edge.contains(&last)
                && before(last) >= chosen - 1
        };
        if count_ok && owner_ok {
            TieOutcome::Allowed {
                overdrawn: count > self.most,
                hole: count < self.fewest,
            }
        } else {
            TieOutcome::NotAllowed
        }
    }
}

/// Every tie sample of a scene, by slot (one per pixel, or N per pixel
/// when the scene antialiases, as in a frame).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TieSet {
    pub samples: BTreeMap<usize, TieSample>,
}

impl TieSet {
    pub fn get(&self, slot: usize) -> Option<&TieSample> {
        self.samples.get(&slot)
    }

    pub fn len(&self) -> usize {
        self.samples.len()
    }

    pub fn is_empty(&self) -> bool {
        self.samples.is_empty()
    }

    /// The tie samples whose every primitive holding them on an edge is
    /// one `keep` names (by index in the scene): for a rasterizer with no
    /// tie rule on those primitives alone (rectangle lines' borders,
    /// SPEC.md §4.3.1), every other sample judged under the fill rule.
    pub fn only_on(self, keep: impl Fn(usize) -> bool) -> TieSet {
        let samples = self
            .samples
            .into_iter()
            .filter(|(_, tie)| tie.on_edge.iter().all(|&p| keep(p as usize - 1)))
            .collect();
        TieSet { samples }
    }
}

/// The tie set of `scene` drawn with `plan` (the scene's own).
pub fn tie_set(scene: &Scene, plan: &Plan) -> TieSet {
    // Bit k set: covered under rule k of `RULES`.
    const RULES: [FillRule; 5] = [
        FillRule::TopLeft,
        FillRule::BottomRight,
        FillRule::TopRight,
        FillRule::BottomLeft,
        FillRule::AllEdges,
    ];
    const CONSISTENT: u8 = 0b1111;
    let mut covered: HashMap<(usize, usize), u8> = HashMap::new();
    let slots = scene.canvas.pixel_count() * plan.samples_per_pixel as usize;
    let mut counts = vec![[0u16; 4]; slots];
    for (k, &rule) in RULES.iter().enumerate() {
        if rule == FillRule::AllEdges && scene.has_polygons() {
            continue;
        }
        visit_samples(
            scene,
            plan.antialias.as_ref(),
            rule,
            Arithmetic::Auto,
            false,
            |primitive, slot, _| {
                *covered.entry((slot, primitive)).or_default() |= 1 << k;
                if k < 4 {
                    counts[slot][k] = counts[slot][k].saturating_add(1);
                }
            },
        );
    }
    let mut set = TieSet::default();
    for (&(slot, _), &rules) in &covered {
        if rules & CONSISTENT != CONSISTENT {
            let c = counts[slot];
            set.samples.entry(slot).or_insert_with(|| TieSample {
                inside: 0,
                last_inside: 0,
                on_edge: Vec::new(),
                fewest: c.iter().copied().min().unwrap_or(0),
                most: c.iter().copied().max().unwrap_or(0),
            });
        }
    }
    for (&(slot, primitive), &rules) in &covered {
        let Some(tie) = set.samples.get_mut(&slot) else {
            continue;
        };
        let index = u32::try_from(primitive + 1).unwrap_or(u32::MAX);
        if rules & CONSISTENT == CONSISTENT {
            tie.inside = tie.inside.saturating_add(1);
            tie.last_inside = tie.last_inside.max(index);
        } else {
            tie.on_edge.push(index);
        }
    }
    for tie in set.samples.values_mut() {
        tie.on_edge.sort_unstable();
    }
    set
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{parse_case, Limits};

    fn scene(triangles: &str) -> Scene {
        let text = format!(
            r#"{{"name": "t", "canvas": {{"width": 4, "height": 4}},
                "rules": {{"subpixel_bits": 8, "fill_rule": "top-left", "cull": "none"}},
                "primitives": [{triangles}]}}"#
        );
        parse_case(&text, "t.json", &Limits::default()).expect("a valid case")
    }

    fn tri(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> String {
        format!(
            r#"{{"triangle": [[{}, {}], [{}, {}], [{}, {}]]}}"#,
            a.0, a.1, b.0, b.1, c.0, c.1
        )
    }

    #[test]
    fn a_shared_diagonal_through_centres_is_tied_and_either_side_is_allowed() {
        // The diagonal from (0, 0) to (4, 4) passes through the centres
        // (0.5, 0.5), ..., (3.5, 3.5).
        let a = tri((0.0, 0.0), (4.0, 0.0), (4.0, 4.0));
        let b = tri((0.0, 0.0), (4.0, 4.0), (0.0, 4.0));
        let s = scene(&format!("{a}, {b}"));
        let set = tie_set(&s, &Plan::for_scene(&s));
        let diagonal: Vec<usize> = (0..4).map(|i| i * 4 + i).collect();
        assert_eq!(set.samples.keys().copied().collect::<Vec<_>>(), diagonal);
        let tie = set.get(5).expect("a tie");
        assert_eq!((tie.inside, tie.on_edge.clone()), (0, vec![1, 2]));
        assert_eq!((tie.fewest, tie.most), (1, 1));
        let ok = TieOutcome::Allowed {
            overdrawn: false,
            hole: false,
        };
        assert_eq!(tie.outcome(1, 1), ok);
        assert_eq!(tie.outcome(1, 2), ok);
        assert_eq!(
            tie.outcome(2, 2),
            TieOutcome::Allowed {
                overdrawn: true,
                hole: false
            }
        );
        assert_eq!(
            tie.outcome(0, 0),
            TieOutcome::Allowed {
                overdrawn: false,
                hole: true
            }
        );
        // Twice, but with the first drawn as the last: no choice gives it.
        assert_eq!(tie.outcome(2, 1), TieOutcome::NotAllowed);
        assert_eq!(tie.outcome(3, 2), TieOutcome::NotAllowed);
    }

    #[test]
    fn a_lone_edge_is_neither_hole_nor_overdraw() {
        let s = scene(&tri((0.5, 0.0), (4.0, 0.0), (0.5, 4.0)));
        let set = tie_set(&s, &Plan::for_scene(&s));
        // The vertical edge x = 0.5 holds the centres of column 0.
        let tie = set.get(4).expect("a tie on the left edge");
        assert_eq!((tie.fewest, tie.most), (0, 1));
        for (count, last) in [(0, 0), (1, 1)] {
            assert_eq!(
                tie.outcome(count, last),
                TieOutcome::Allowed {
                    overdrawn: false,
                    hole: false
                }
            );
        }
        // No sample off the edges is a tie.
        assert!(set.get(5).is_none());
    }
}
