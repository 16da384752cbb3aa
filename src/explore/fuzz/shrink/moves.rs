//! Shrinking passes that move numbers to simpler ones: vertex positions
//! (shared vertices together, then each on its own), the ends of paths, and
//! depth, w and attribute values.

use dashu_int::UBig;
use dashu_ratio::RBig;

use super::state::Shrinker;
use super::values::{key, simpler};
use crate::explore::fuzz::geometry::num;
use crate::explore::fuzz::judge::samples_per_pixel;
use crate::reference::exact::snap;
use crate::scene::rules::limits::MAX_SUBPIXEL_BITS;
use crate::scene::{Canvas, Number, Scene, Vertex};

impl Shrinker<'_> {
    /// How simple a vertex position is: its larger denominator, then how
    /// far it lies outside the canvas, then its distance from the origin
    /// (L1). Every coordinate move makes one vertex's key smaller.
    fn position_key(&self, x: &Number, y: &Number) -> (UBig, Number, Number) {
        let canvas = self.best.canvas;
        let outside = |v: &Number, side: u32| {
            let hi = Number::from_int(side.into());
            if *v < Number::ZERO {
                v.abs()
            } else if *v > hi {
                v - &hi
            } else {
                Number::ZERO
            }
        };
        (
            x.denominator().max(y.denominator()).clone(),
            &outside(x, canvas.width) + &outside(y, canvas.height),
            &x.abs() + &y.abs(),
        )
    }

    /// The centre of the first sample that shows the failure (the canvas's
    /// middle when none does).
    fn focus_sample(&self) -> [Number; 2] {
        let Canvas { width, height } = self.best.canvas;
        let n = samples_per_pixel(&self.best);
        let (px, py) = match self.failure.focus(self.kind).first() {
            Some(&i) => (
                (i / n % width as usize) as i64,
                (i / n / width as usize) as i64,
            ),
            None => (i64::from(width / 2), i64::from(height / 2)),
        };
        [Number::ratio(2 * px + 1, 2), Number::ratio(2 * py + 1, 2)]
    }

    /// Simpler positions for a vertex at `p`, simplest first: one axis at a
    /// time (integers on the canvas nearest it, coarser dyadic grids,
    /// halfway in from far away), then both axes rounded together, then
    /// pulled halfway toward the failing sample (which keeps a vertex on a
    /// line through that sample) and halfway along each edge to a
    /// `partner` (which keeps the edge's line: a line keeps its slope), each
    /// on coarser grids.
    fn position_candidates(&self, p: &[Number; 2], partners: &[[Number; 2]]) -> Vec<[Number; 2]> {
        let finest = self
            .best
            .rules
            .subpixel_bits
            .unwrap_or(MAX_SUBPIXEL_BITS)
            .min(MAX_SUBPIXEL_BITS);
        let Canvas { width, height } = self.best.canvas;
        let [x, y] = p;
        let mut out: Vec<[Number; 2]> = Vec::new();
        out.extend(
            simpler(x, 0, width.into(), finest)
                .into_iter()
                .map(|c| [c, y.clone()]),
        );
        out.extend(
            simpler(y, 0, height.into(), finest)
                .into_iter()
                .map(|c| [x.clone(), c]),
        );
        let [fx, fy] = self.focus_sample();
        let half = |a: &Number, b: &Number| num(&((a.as_rbig() + b.as_rbig()) / RBig::from(2u8)));
        let mut targets = vec![p.clone(), [half(x, &fx), half(y, &fy)]];
        targets.extend(partners.iter().map(|q| [half(x, &q[0]), half(y, &q[1])]));
        for target in &targets {
            for k in 0..=finest {
                out.push(target.each_ref().map(|c| num(&snap(c, k))));
            }
        }
        let current = self.position_key(x, y);
        let mut seen: Vec<[Number; 2]> = Vec::new();
        out.retain(|c| {
            let keep = !seen.contains(c) && self.position_key(&c[0], &c[1]) < current;
            seen.push(c.clone());
            keep
        });
        out
    }

    /// Moves every vertex at one position together (a mesh stays a mesh).
    pub(super) fn move_shared_vertices(&mut self) -> bool {
        let mut progress = false;
        let mut positions: Vec<[Number; 2]> = Vec::new();
        for v in self.best.vertices() {
            let p = [v.x.clone(), v.y.clone()];
            if !positions.contains(&p) {
                positions.push(p);
            }
        }
        for position in positions {
            let at = |v: &Vertex| v.x == position[0] && v.y == position[1];
            let mut partners: Vec<[Number; 2]> = Vec::new();
            for p in &self.best.primitives {
                if p.vertices().iter().any(at) {
                    for v in p.vertices().iter().filter(|v| !at(v)) {
                        let q = [v.x.clone(), v.y.clone()];
                        if !partners.contains(&q) {
                            partners.push(q);
                        }
                    }
                }
            }
            for c in self.position_candidates(&position, &partners) {
                let mut scene = self.best.clone();
                for p in &mut scene.primitives {
                    for v in p.vertices_mut() {
                        if v.x == position[0] && v.y == position[1] {
                            [v.x, v.y] = c.clone();
                        }
                    }
                }
                if self.try_scene(scene) {
                    progress = true;
                    break;
                }
            }
        }
        progress
    }

    /// Moves each vertex on its own. A moving vertex's whole path is
    /// moved first (its `to` by as much as its `from`, which keeps the
    /// velocity) when that makes `to` no less simple, then its `from` alone.
    pub(super) fn move_vertices(&mut self) -> bool {
        let mut progress = false;
        for i in 0..self.best.primitives.len() {
            for j in 0..self.best.primitives[i].vertices().len() {
                let vertices = self.best.primitives[i].vertices();
                let position = [vertices[j].x.clone(), vertices[j].y.clone()];
                let end = vertices[j].to.as_deref().cloned();
                let partners: Vec<[Number; 2]> = (0..vertices.len())
                    .filter(|&k| k != j)
                    .map(|k| [vertices[k].x.clone(), vertices[k].y.clone()])
                    .collect();
                for c in self.position_candidates(&position, &partners) {
                    let mut tries = Vec::new();
                    if let Some([tx, ty]) = &end {
                        let to = [tx + &(&c[0] - &position[0]), ty + &(&c[1] - &position[1])];
                        if self.position_key(&to[0], &to[1]) <= self.position_key(tx, ty) {
                            tries.push(Some(to));
                        }
                    }
                    tries.push(None);
                    let mut moved = false;
                    for to in tries {
                        let mut scene = self.best.clone();
                        let v = &mut scene.primitives[i].vertices_mut()[j];
                        [v.x, v.y] = c.clone();
                        if let (Some(to), Some(end)) = (to, v.to.as_deref_mut()) {
                            *end = to;
                        }
                        if self.try_scene(scene) {
                            moved = true;
                            break;
                        }
                    }
                    if moved {
                        progress = true;
                        break;
                    }
                }
            }
        }
        progress
    }

    /// Moves the ends of paths (`to`) to simpler values: every vertex with
    /// the same path together (a moving edge shared by two triangles stays
    /// shared), the candidates as for positions, with the path's start
    /// among the partners (halfway to it is a shorter path).
    pub(super) fn move_ends(&mut self) -> bool {
        let mut progress = false;
        let mut paths: Vec<[[Number; 2]; 2]> = Vec::new();
        for v in self.best.vertices() {
            if let Some(to) = v.to.as_deref() {
                let path = [[v.x.clone(), v.y.clone()], to.clone()];
                if !paths.contains(&path) {
                    paths.push(path);
                }
            }
        }
        for [from, to] in paths {
            let on = |v: &Vertex| v.x == from[0] && v.y == from[1] && v.to.as_deref() == Some(&to);
            let mut partners = vec![from.clone()];
            for p in &self.best.primitives {
                if p.vertices().iter().any(on) {
                    for v in p.vertices().iter().filter(|v| !on(v)) {
                        let [x, y] = v.end();
                        let q = [x.clone(), y.clone()];
                        if !partners.contains(&q) {
                            partners.push(q);
                        }
                    }
                }
            }
            for c in self.position_candidates(&to, &partners) {
                let mut scene = self.best.clone();
                for p in &mut scene.primitives {
                    for v in p.vertices_mut() {
                        if on(v) {
                            v.to = Some(Box::new(c.clone()));
                        }
                    }
                }
                if self.try_scene(scene) {
                    progress = true;
                    break;
                }
            }
        }
        progress
    }

    /// Simpler depth, w and attribute values, vertex by vertex.
    pub(super) fn simplify_values(&mut self) -> bool {
        let mut progress = false;
        let (zero, one) = (Number::ZERO, Number::ONE);
        for i in 0..self.best.primitives.len() {
            for j in 0..self.best.primitives[i].vertices().len() {
                // Slot 0: z, 1: w, 2..: attributes.
                for slot in 0..2 + self.best.attribute_count {
                    if slot == 0 && !self.best.has_depth {
                        continue;
                    }
                    let get = |s: &Scene| {
                        let v = &s.primitives[i].vertices()[j];
                        match slot {
                            0 => v.z.clone(),
                            1 => v.w.clone(),
                            k => v.attributes[k - 2].clone(),
                        }
                    };
                    let current = get(&self.best);
                    let centre = if slot == 1 { &one } else { &zero };
                    let current_key = key(&current, centre, centre, centre);
                    let candidates = simpler(&current, -4, 4, 0)
                        .into_iter()
                        .filter(|c| key(c, centre, centre, centre) < current_key)
                        .filter(|c| slot != 1 || c.is_positive());
                    for c in candidates.collect::<Vec<_>>() {
                        let mut scene = self.best.clone();
                        let v = &mut scene.primitives[i].vertices_mut()[j];
                        match slot {
                            0 => v.z = c,
                            1 => v.w = c,
                            k => v.attributes[k - 2] = c,
                        }
                        if self.try_scene(scene) {
                            progress = true;
                            break;
                        }
                    }
                }
            }
        }
        progress
    }
}
