//! Shrinking passes on what a scene declares rather than on its geometry:
//! depth, attributes, w, rules, line options and expectations,
//! `effects.antialias`, `effects.motion_blur`, `effects.conservative`'s
//! flag, degenerate triangles and uncertainty, and `subpixel_bits`.

use super::state::{Edit, Shrinker};
use super::values::coordinates;
use crate::explore::fuzz::judge::Kind;
use crate::reference::exact::snap;
use crate::scene::rules::limits::MAX_SUBPIXEL_BITS;
use crate::scene::time::limits::TIME_ONE;
use crate::scene::{
    Cull, FillRule, Interpolation, LastPixel, LineParameter, Number, Pattern, Primitive, Rules,
    TimePattern,
};

impl Shrinker<'_> {
    /// Drops depth, attributes, w, and every rule, line option and
    /// expectation that is not needed for the failure.
    pub(super) fn simplify_state(&mut self) -> bool {
        let mut edits: Vec<Edit> = Vec::new();
        edits.push(Box::new(|s| {
            let changed = s.has_depth;
            s.has_depth = false;
            for p in &mut s.primitives {
                for v in p.vertices_mut() {
                    v.z = Number::ZERO;
                }
            }
            changed
        }));
        for k in (0..self.best.attribute_count).rev() {
            edits.push(Box::new(move |s| {
                s.attribute_count -= 1;
                for p in &mut s.primitives {
                    for v in p.vertices_mut() {
                        v.attributes.remove(k);
                    }
                }
                true
            }));
        }
        edits.push(Box::new(|s| {
            let mut changed = false;
            for p in &mut s.primitives {
                for v in p.vertices_mut() {
                    changed |= v.w != Number::ONE;
                    v.w = Number::ONE;
                }
            }
            changed
        }));
        for i in 0..self.best.primitives.len() {
            edits.push(Box::new(move |s| {
                let p = &mut s.primitives[i];
                let changed = p.interpolation() != Interpolation::Perspective;
                match p {
                    Primitive::Triangle(t) => t.interpolation = Interpolation::Perspective,
                    Primitive::Line(l) => l.interpolation = Interpolation::Perspective,
                    Primitive::Polygon(_) | Primitive::Point(_) => {}
                }
                changed
            }));
            edits.push(Box::new(move |s| match &mut s.primitives[i] {
                Primitive::Line(l) => {
                    let before = (l.width.clone(), l.last_pixel, l.parameter);
                    l.width = Number::ONE;
                    l.last_pixel = LastPixel::Include;
                    l.parameter = LineParameter::Major;
                    before != (l.width.clone(), l.last_pixel, l.parameter)
                }
                Primitive::Triangle(_) | Primitive::Polygon(_) | Primitive::Point(_) => false,
            }));
            for option in 0..3 {
                edits.push(Box::new(move |s| match &mut s.primitives[i] {
                    Primitive::Line(l) => match option {
                        0 => std::mem::replace(&mut l.width, Number::ONE) != Number::ONE,
                        1 => {
                            std::mem::replace(&mut l.last_pixel, LastPixel::Include)
                                != LastPixel::Include
                        }
                        _ => {
                            std::mem::replace(&mut l.parameter, LineParameter::Major)
                                != LineParameter::Major
                        }
                    },
                    Primitive::Triangle(_) | Primitive::Polygon(_) | Primitive::Point(_) => false,
                }));
            }
        }
        edits.push(Box::new(|s| {
            std::mem::replace(&mut s.rules.fill_rule, FillRule::TopLeft) != FillRule::TopLeft
        }));
        edits.push(Box::new(|s| {
            std::mem::replace(&mut s.rules.cull, Cull::None) != Cull::None
        }));
        // A conservative scene's flag, degenerate triangles and uncertainty
        // (SPEC.md §19), each dropped when the failure does not need it.
        edits.push(Box::new(|s| {
            let c = s.effects.conservative.as_mut();
            c.is_some_and(|c| std::mem::take(&mut c.fully_covered))
        }));
        edits.push(Box::new(|s| {
            let c = s.effects.conservative.as_mut();
            c.is_some_and(|c| std::mem::take(&mut c.degenerate_triangles))
        }));
        edits.push(Box::new(|s| {
            let c = s.effects.conservative.as_mut();
            c.is_some_and(|c| std::mem::replace(&mut c.uncertainty, Number::ZERO) != Number::ZERO)
        }));
        if !matches!(self.kind, Kind::Holes | Kind::Overdraw) {
            edits.push(Box::new(|s| std::mem::take(&mut s.expect.watertight)));
        }
        edits.push(Box::new(|s| {
            std::mem::take(&mut s.expect.max_mismatched_samples) != 0
        }));
        self.try_each(edits)
    }

    /// Drops `effects.antialias`, or else makes it simpler: fewer samples
    /// (each smaller count the pattern allows, smallest first), the
    /// standard or grid pattern, seed 0, not adaptive, 8 position bits.
    pub(super) fn simplify_antialias(&mut self) -> bool {
        let Some(aa) = self.best.effects.antialias.clone() else {
            return false;
        };
        let mut edits: Vec<Edit> = vec![Box::new(|s| s.effects.antialias.take().is_some())];
        // Each edit changes the current best only toward the simplest
        // (fewer samples; standard, else grid), so no two undo each other.
        for n in [1, 2, 3, 4, 8, 9, 16, 64] {
            if n < aa.samples && aa.pattern.check_count(n).is_ok() {
                edits.push(Box::new(move |s| {
                    s.effects.antialias.as_mut().is_some_and(|a| {
                        let fewer = n < a.samples && a.pattern.check_count(n).is_ok();
                        if fewer {
                            a.samples = n;
                        }
                        fewer
                    })
                }));
            }
        }
        for pattern in [Pattern::Standard, Pattern::Grid] {
            if aa.pattern != pattern && pattern.check_count(aa.samples).is_ok() {
                edits.push(Box::new(move |s| {
                    s.effects.antialias.as_mut().is_some_and(|a| {
                        let simpler = a.pattern != pattern
                            && a.pattern != Pattern::Standard
                            && pattern.check_count(a.samples).is_ok();
                        if simpler {
                            a.pattern = pattern;
                            a.seed = 0;
                        }
                        simpler
                    })
                }));
            }
        }
        edits.push(Box::new(|s| {
            s.effects.antialias.as_mut().is_some_and(|a| {
                let before = (a.seed, a.adaptive, a.position_bits);
                if !a.pattern.is_seeded() {
                    a.seed = 0;
                }
                a.adaptive = false;
                a.position_bits = 8;
                before != (a.seed, a.adaptive, a.position_bits)
            })
        }));
        edits.push(Box::new(|s| {
            s.effects
                .antialias
                .as_mut()
                .is_some_and(|a| std::mem::replace(&mut a.seed, 0) != 0)
        }));
        self.try_each(edits)
    }

    /// Makes `effects.motion_blur` simpler: fewer time samples (smallest
    /// first), the whole shutter, the `stratified` pattern, seed 0. Each
    /// edit moves the current best only toward those, so the measure
    /// (N, then how far each field is from its simplest) falls.
    pub(super) fn simplify_motion(&mut self) -> bool {
        let Some(blur) = self.best.effects.motion_blur.clone() else {
            return false;
        };
        let mut edits: Vec<Edit> = Vec::new();
        for n in [1, 2, 4, 8, 16, 32] {
            if n < blur.samples {
                edits.push(Box::new(move |s| {
                    s.effects.motion_blur.as_mut().is_some_and(|b| {
                        let fewer = n < b.samples;
                        if fewer {
                            b.samples = n;
                        }
                        fewer
                    })
                }));
            }
        }
        edits.push(Box::new(|s| {
            s.effects
                .motion_blur
                .as_mut()
                .is_some_and(|b| std::mem::replace(&mut b.shutter, [0, TIME_ONE]) != [0, TIME_ONE])
        }));
        edits.push(Box::new(|s| {
            s.effects.motion_blur.as_mut().is_some_and(|b| {
                std::mem::replace(&mut b.pattern, TimePattern::Stratified)
                    != TimePattern::Stratified
            })
        }));
        edits.push(Box::new(|s| {
            s.effects
                .motion_blur
                .as_mut()
                .is_some_and(|b| std::mem::replace(&mut b.seed, 0) != 0)
        }));
        self.try_each(edits)
    }

    /// Fewer subpixel bits, when snapping still moves a vertex (otherwise
    /// the case keeps its grid, which then does not matter).
    pub(super) fn reduce_bits(&mut self) -> bool {
        let bits = self.best.rules.subpixel_bits;
        let on_grid = |b: Option<u32>| {
            coordinates(&self.best).all(|c| b.is_none_or(|b| &snap(c, b) == c.as_rbig()))
        };
        if bits.is_some() && on_grid(bits) {
            return false;
        }
        let top = bits.map_or(MAX_SUBPIXEL_BITS + 1, |b| b);
        for b in 0..top {
            let mut scene = self.best.clone();
            scene.rules.subpixel_bits = Some(b);
            if self.try_scene(scene) {
                return true;
            }
        }
        false
    }

    /// Puts `subpixel_bits` back to the default 8 when every vertex lies on
    /// both grids (so snapping moves nothing either way) and the failure
    /// stays: a case is easier to read on the usual grid.
    pub(super) fn restore_default_bits(&mut self) {
        let default = Rules::default().subpixel_bits;
        let bits = self.best.rules.subpixel_bits;
        let on = |b: Option<u32>, v: &Number| b.is_none_or(|b| &snap(v, b) == v.as_rbig());
        if bits == default || !coordinates(&self.best).all(|c| on(bits, c) && on(default, c)) {
            return;
        }
        let mut scene = self.best.clone();
        scene.rules.subpixel_bits = default;
        self.try_scene(scene);
    }
}
