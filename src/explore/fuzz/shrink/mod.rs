//! Greedy shrinking of a failing scene to a small one that fails the same
//! check: the loop over passes, the evaluation budget, and the simplicity
//! keys that make every accepted step smaller. The passes live beside it:
//! `cut.rs` (fewer things), `settings.rs` (simpler declarations) and
//! `moves.rs` (simpler numbers).

mod cut;
mod moves;
mod settings;

use std::time::{Duration, Instant};

use dashu_int::UBig;
use dashu_ratio::RBig;

use super::geometry::num;
use super::judge::{evaluate, Failure, Kind, Outcome};
use crate::rasterizer::Rasterizer;
use crate::reference::exact::snap;
use crate::scene::rules::limits::MAX_SUBPIXEL_BITS;
use crate::scene::{Number, Scene};

/// Most candidate evaluations one shrink may spend.
pub const SHRINK_BUDGET: u64 = 20_000;

/// A shrunk counterexample.
#[derive(Clone, Debug)]
pub struct Shrunk {
    pub scene: Scene,
    pub failure: Failure,
    /// Candidate evaluations spent.
    pub evaluations: u64,
    /// Rounds of passes, the last of which made no progress.
    pub rounds: u32,
    pub elapsed: Duration,
}

/// One proposed change to a scene; `false` when it would change nothing.
type Edit = Box<dyn Fn(&mut Scene) -> bool>;

struct Shrinker<'a> {
    candidate: &'a dyn Rasterizer,
    kind: Kind,
    best: Scene,
    failure: Failure,
    evaluations: u64,
}

/// Shrinks `scene`, on which `candidate` fails with `failure`, to a small
/// scene that still fails the check `kind`.
pub fn shrink(scene: &Scene, failure: Failure, kind: Kind, candidate: &dyn Rasterizer) -> Shrunk {
    let started = Instant::now();
    let mut s = Shrinker {
        candidate,
        kind,
        best: scene.clone(),
        failure,
        evaluations: 0,
    };
    let mut rounds = 0;
    loop {
        rounds += 1;
        let mut progress = false;
        progress |= s.remove_primitives();
        progress |= s.crop();
        progress |= s.trim();
        progress |= s.simplify_state();
        progress |= s.simplify_antialias();
        progress |= s.simplify_motion();
        progress |= s.freeze_vertices();
        progress |= s.remove_contours_and_vertices();
        progress |= s.move_shared_vertices();
        progress |= s.move_vertices();
        progress |= s.move_ends();
        progress |= s.simplify_values();
        // Coarser snapping is tried once nothing else helps: by then the
        // vertices are as simple as they get, and often on the grid already.
        if !progress {
            progress = s.reduce_bits();
        }
        if !progress || s.exhausted() {
            break;
        }
    }
    s.restore_default_bits();
    Shrunk {
        scene: s.best,
        failure: s.failure,
        evaluations: s.evaluations,
        rounds,
        elapsed: started.elapsed(),
    }
}

/// A simplicity key for a number: smaller denominator first, then closer to
/// `[lo, hi]`, then closer to `centre`. Every accepted move makes some key
/// smaller, and keys of bounded denominator are well-ordered, so shrinking
/// ends.
fn key(v: &Number, lo: &Number, hi: &Number, centre: &Number) -> (UBig, Number, Number) {
    let outside = if v < lo {
        lo - v
    } else if v > hi {
        v - hi
    } else {
        Number::ZERO
    };
    (v.denominator().clone(), outside, (v - centre).abs())
}

/// Simpler values to try for `v`, in order: integers in `[lo, hi]` nearest
/// `v` first, coarser dyadic roundings of `v`, and `v` pulled halfway in
/// from far outside `[lo, hi]`.
fn simpler(v: &Number, lo: i64, hi: i64, finest: u32) -> Vec<Number> {
    let mut out: Vec<Number> = Vec::new();
    let f = v.to_f64_lossy();
    let mut ints: Vec<i64> = (lo..=hi).collect();
    ints.sort_by(|a, b| {
        ((*a as f64) - f)
            .abs()
            .total_cmp(&((*b as f64) - f).abs())
            .then(a.cmp(b))
    });
    out.extend(ints.into_iter().take(12).map(Number::from_int));
    for k in 0..=finest.min(MAX_SUBPIXEL_BITS) {
        out.push(num(&snap(v, k)));
    }
    let (lo_n, hi_n) = (Number::from_int(lo), Number::from_int(hi));
    let edge = if *v < lo_n {
        Some(lo_n)
    } else if *v > hi_n {
        Some(hi_n)
    } else {
        None
    };
    if let Some(edge) = edge {
        let half = num(&((v.as_rbig() + edge.as_rbig()) / RBig::from(2u8)));
        out.push(num(&snap(&half, 0)));
    }
    let mut seen: Vec<Number> = Vec::new();
    out.retain(|c| {
        let fresh = c != v && !seen.contains(c);
        seen.push(c.clone());
        fresh
    });
    out
}

/// Every coordinate of every vertex: its position (`from`) and, for a
/// moving vertex, its `to`.
fn coordinates(scene: &Scene) -> impl Iterator<Item = &Number> {
    scene.vertices().flat_map(|v| {
        [&v.x, &v.y]
            .into_iter()
            .chain(v.to.iter().flat_map(|to| to.iter()))
    })
}

impl Shrinker<'_> {
    fn exhausted(&self) -> bool {
        self.evaluations >= SHRINK_BUDGET
    }

    /// Keeps `scene` when it still fails the same check.
    fn try_scene(&mut self, scene: Scene) -> bool {
        if self.exhausted() {
            return false;
        }
        self.evaluations += 1;
        match evaluate(&scene, self.candidate) {
            Outcome::Fail(f) if f.kinds.contains(&self.kind) => {
                self.best = scene;
                self.failure = f;
                true
            }
            _ => false,
        }
    }

    /// Tries each of `edits` on the current best scene in turn, keeping
    /// each that still fails.
    fn try_each(&mut self, edits: Vec<Edit>) -> bool {
        let mut progress = false;
        for edit in edits {
            let mut scene = self.best.clone();
            if edit(&mut scene) {
                progress |= self.try_scene(scene);
            }
        }
        progress
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn simpler_values_are_simpler() {
        let v = Number::ratio(12345, 4096);
        let c = simpler(&v, 0, 4, 8);
        assert_eq!(c[0], Number::from_int(3));
        assert!(c.contains(&Number::ratio(772, 256)));
        let far = simpler(&Number::from_int(20000), 0, 4, 8);
        assert!(far.contains(&Number::from_int(10002)));
    }
}
