//! Shrinking passes that take things away: primitives, canvas rows and
//! columns (crop and trim), polygon contours and vertices, and paths (moving
//! vertices made static).

use super::state::Shrinker;
use crate::explore::fuzz::judge::{samples_per_pixel, Kind};
use crate::scene::{
    Canvas, Interpolation, Number, Polygon, PolygonFill, Primitive, Scene, Triangle,
};

impl Shrinker<'_> {
    /// Removes chunks of primitives, halves first, then one at a time.
    pub(super) fn remove_primitives(&mut self) -> bool {
        let mut progress = false;
        let mut chunk = self.best.primitives.len() / 2;
        while chunk >= 1 {
            let mut start = 0;
            while start < self.best.primitives.len() && self.best.primitives.len() > 1 {
                let end = (start + chunk).min(self.best.primitives.len());
                if end - start == self.best.primitives.len() {
                    break;
                }
                let mut scene = self.best.clone();
                scene.primitives.drain(start..end);
                if self.try_scene(scene) {
                    progress = true;
                } else {
                    start += chunk;
                }
            }
            chunk /= 2;
        }
        progress
    }

    /// The canvas `[x0, x0 + w) × [y0, y0 + h)` of the current scene, with
    /// everything translated by (−x0, −y0): a moving vertex's `from` and
    /// `to` together, so that its path keeps its shape (and, moved by whole
    /// pixels, its snapping).
    fn cropped(&self, x0: u32, y0: u32, w: u32, h: u32) -> Scene {
        let mut scene = self.best.clone();
        let (dx, dy) = (Number::from_int(x0.into()), Number::from_int(y0.into()));
        for p in &mut scene.primitives {
            for v in p.vertices_mut() {
                v.x = &v.x - &dx;
                v.y = &v.y - &dy;
                if let Some(to) = v.to.as_deref_mut() {
                    to[0] = &to[0] - &dx;
                    to[1] = &to[1] - &dy;
                }
            }
        }
        scene.canvas = Canvas {
            width: w,
            height: h,
        };
        scene
    }

    /// Crops to the failing samples and a margin around them. A time
    /// failure is a mean over the moving pixels, spread over the primitives'
    /// paths: when the box of all the pixels it names does not do, the
    /// worst pixel's neighbourhood is tried alone.
    pub(super) fn crop(&mut self) -> bool {
        let focus = self.failure.focus(self.kind).to_vec();
        if focus.is_empty() {
            return false;
        }
        if self.crop_to(&focus) {
            return true;
        }
        self.kind == Kind::Time && focus.len() > 1 && self.crop_to(&focus[..1])
    }

    /// Crops to the box of `focus` (sample slots) and a margin around it.
    fn crop_to(&mut self, focus: &[usize]) -> bool {
        let Canvas { width, height } = self.best.canvas;
        let w = width as usize;
        let n = samples_per_pixel(&self.best);
        let xs = focus.iter().map(|i| (i / n % w) as u32);
        let ys = focus.iter().map(|i| (i / n / w) as u32);
        let (x0, x1) = (xs.clone().min().unwrap(), xs.max().unwrap());
        let (y0, y1) = (ys.clone().min().unwrap(), ys.max().unwrap());
        for margin in [0, 1, 2, 4] {
            let (ax, ay) = (x0.saturating_sub(margin), y0.saturating_sub(margin));
            let (bx, by) = ((x1 + margin).min(width - 1), (y1 + margin).min(height - 1));
            let (cw, ch) = (bx - ax + 1, by - ay + 1);
            if (cw, ch) == (width, height) {
                break;
            }
            let scene = self.cropped(ax, ay, cw, ch);
            if self.try_scene(scene) {
                return true;
            }
        }
        false
    }

    /// Trims each side of the canvas: half of it, then a quarter, ... then
    /// one row or column at a time.
    pub(super) fn trim(&mut self) -> bool {
        let mut progress = false;
        for side in 0..4 {
            let extent = |c: Canvas| if side % 2 == 0 { c.width } else { c.height };
            let mut cut = extent(self.best.canvas) / 2;
            while cut >= 1 {
                let Canvas { width, height } = self.best.canvas;
                if extent(self.best.canvas) <= cut {
                    cut /= 2;
                    continue;
                }
                let scene = match side {
                    0 => self.cropped(cut, 0, width - cut, height),
                    1 => self.cropped(0, cut, width, height - cut),
                    2 => self.cropped(0, 0, width - cut, height),
                    _ => self.cropped(0, 0, width, height - cut),
                };
                if self.try_scene(scene) {
                    progress = true;
                } else {
                    cut /= 2;
                }
            }
        }
        progress
    }

    /// Makes moving vertices static, keeping `from` as the position: each
    /// primitive's all at once, then one at a time. Fewer paths each time.
    pub(super) fn freeze_vertices(&mut self) -> bool {
        let mut progress = false;
        for i in 0..self.best.primitives.len() {
            let paths = |s: &Scene| {
                s.primitives[i]
                    .vertices()
                    .iter()
                    .filter(|v| v.to.is_some())
                    .count()
            };
            if paths(&self.best) > 1 {
                let mut scene = self.best.clone();
                for v in scene.primitives[i].vertices_mut() {
                    v.to = None;
                }
                progress |= self.try_scene(scene);
            }
            for j in 0..self.best.primitives[i].vertices().len() {
                if self.best.primitives[i].vertices()[j].to.is_some() {
                    let mut scene = self.best.clone();
                    scene.primitives[i].vertices_mut()[j].to = None;
                    progress |= self.try_scene(scene);
                }
            }
        }
        progress
    }

    /// Removes whole contours of polygons, then single vertices of contours
    /// longer than 3, and sets the fill to nonzero; a polygon of one
    /// triangular contour becomes a triangle when that still fails.
    pub(super) fn remove_contours_and_vertices(&mut self) -> bool {
        let mut progress = false;
        for i in 0..self.best.primitives.len() {
            let mut c = 0;
            while let Primitive::Polygon(p) = &self.best.primitives[i] {
                if c >= p.contour_ends.len() || p.contour_ends.len() == 1 {
                    break;
                }
                let mut scene = self.best.clone();
                if let Primitive::Polygon(q) = &mut scene.primitives[i] {
                    remove_contour(q, c);
                }
                if self.try_scene(scene) {
                    progress = true;
                } else {
                    c += 1;
                }
            }
            let mut k = 0;
            while let Primitive::Polygon(p) = &self.best.primitives[i] {
                if k >= p.vertices.len() {
                    break;
                }
                let mut scene = self.best.clone();
                let removed = match &mut scene.primitives[i] {
                    Primitive::Polygon(q) => remove_vertex(q, k),
                    _ => false,
                };
                if removed && self.try_scene(scene) {
                    progress = true;
                } else {
                    k += 1;
                }
            }
            let mut scene = self.best.clone();
            if let Primitive::Polygon(q) = &mut scene.primitives[i] {
                if q.fill != PolygonFill::NonZero {
                    q.fill = PolygonFill::NonZero;
                    progress |= self.try_scene(scene);
                }
            }
            if let Primitive::Polygon(q) = &self.best.primitives[i] {
                if q.contour_ends == [3] {
                    let mut scene = self.best.clone();
                    let vertices = [
                        q.vertices[0].clone(),
                        q.vertices[1].clone(),
                        q.vertices[2].clone(),
                    ];
                    scene.primitives[i] = Primitive::Triangle(Triangle {
                        vertices,
                        interpolation: Interpolation::Perspective,
                    });
                    progress |= self.try_scene(scene);
                }
            }
        }
        progress
    }
}

/// Removes contour `c` of a polygon of several contours.
fn remove_contour(p: &mut Polygon, c: usize) {
    let start = if c == 0 { 0 } else { p.contour_ends[c - 1] };
    let end = p.contour_ends[c];
    p.vertices.drain(start..end);
    p.contour_ends.remove(c);
    for e in &mut p.contour_ends[c..] {
        *e -= end - start;
    }
}

/// Removes vertex `k` of a polygon when its contour keeps 3 or more;
/// `false` when it would not.
fn remove_vertex(p: &mut Polygon, k: usize) -> bool {
    let c = p.contour_ends.partition_point(|&e| e <= k);
    let start = if c == 0 { 0 } else { p.contour_ends[c - 1] };
    if p.contour_ends[c] - start <= 3 {
        return false;
    }
    p.vertices.remove(k);
    for e in &mut p.contour_ends[c..] {
        *e -= 1;
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Vertex;

    #[test]
    fn contours_and_vertices_are_removed_in_place() {
        let v = |k: i64| Vertex::at(Number::from_int(k), Number::from_int(-k));
        let mut p = Polygon {
            vertices: (0..10).map(v).collect(),
            contour_ends: vec![3, 7, 10],
            fill: PolygonFill::EvenOdd,
        };
        // A 3-vertex contour keeps its vertices.
        assert!(!remove_vertex(&mut p, 1));
        assert!(remove_vertex(&mut p, 4));
        assert_eq!(p.contour_ends, vec![3, 6, 9]);
        let xs = |p: &Polygon| p.vertices.iter().map(|v| v.x.clone()).collect::<Vec<_>>();
        let n = |ks: &[i64]| ks.iter().map(|&k| Number::from_int(k)).collect::<Vec<_>>();
        assert_eq!(xs(&p), n(&[0, 1, 2, 3, 5, 6, 7, 8, 9]));
        remove_contour(&mut p, 1);
        assert_eq!(p.contour_ends, vec![3, 6]);
        assert_eq!(xs(&p), n(&[0, 1, 2, 7, 8, 9]));
        remove_contour(&mut p, 0);
        assert_eq!(p.contour_ends, vec![3]);
        assert_eq!(xs(&p), n(&[7, 8, 9]));
    }
}
