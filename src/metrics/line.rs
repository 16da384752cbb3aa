//! Line metrics beyond coverage: a midpoint line lights at most one pixel
//! per step along its major axis.

use crate::frame::Frame;
use dashu_int::ops::Abs;

use crate::reference::exact::snap;
use crate::scene::{LineRule, Number, Primitive, Scene};

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LineMetrics {
    /// Midpoint lines in the case.
    pub lines: u64,
    /// Major-axis steps (columns of an x-major line, rows of a y-major one)
    /// in which the candidate drew more than one pixel of the same line.
    pub crowded_steps: u64,
}

/// `None` when the scene has no midpoint line. A line's pixels are those
/// whose last primitive it is, so a later primitive drawn over it can only
/// hide pixels, never add any. The major axis is that of the snapped
/// endpoints (SPEC.md §4), found with the oracle's own snapping. A pixel
/// is the line's when any of its samples is; a frame without samples
/// (an area method) has no pixels to count, so `None`.
pub fn measure(scene: &Scene, candidate: &Frame) -> Option<LineMetrics> {
    if candidate.samples == 0
        || candidate.sample_count() != candidate.pixel_count() * candidate.samples as usize
    {
        return None;
    }
    let mut m = LineMetrics {
        lines: 0,
        crowded_steps: 0,
    };
    let (w, h) = (candidate.width as usize, candidate.height as usize);
    for (index, primitive) in scene.primitives.iter().enumerate() {
        let Primitive::Line(line) = primitive else {
            continue;
        };
        if line.rule != LineRule::Midpoint {
            continue;
        }
        m.lines += 1;
        let place = |n: &Number| match scene.rules.subpixel_bits {
            Some(bits) => snap(n, bits),
            None => n.as_rbig().clone(),
        };
        let [a, b] = &line.vertices;
        let (dx, dy) = (place(&b.x) - place(&a.x), place(&b.y) - place(&a.y));
        let x_major = dx.abs() >= dy.abs();
        let id = index as u32 + 1;
        let (steps, across) = if x_major { (w, h) } else { (h, w) };
        for step in 0..steps {
            let drawn = (0..across)
                .filter(|&k| {
                    let (x, y) = if x_major { (step, k) } else { (k, step) };
                    let first = candidate.index(x as u32, y as u32);
                    candidate.last[first..first + candidate.samples as usize].contains(&id)
                })
                .count();
            m.crowded_steps += u64::from(drawn > 1);
        }
    }
    (m.lines > 0).then_some(m)
}
