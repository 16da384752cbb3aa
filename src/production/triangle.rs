//! One triangle drawn into the frame: set up ([`setup`]), then traversed
//! at pixel centres into a [`FrameSink`] ([`traverse`]) or, antialiased,
//! sampled at the plan's offsets ([`antialias::write_triangle`]). Lines
//! (`line/`) and polygons (`polygon/`) have paths of their own; a
//! parallelogram line's two triangles reuse setup, traversal and sampling
//! but not this file.

use super::antialias::{self, Samples};
use super::fixed::{EdgeInt, Fixed, Format};
use super::setup::{self, Footprint, Shading, TriangleSetup};
use super::traverse::{self, Sink};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::scene::{Scene, Triangle};

/// Draws one triangle whose vertices are already in `format` as primitive
/// `index`: its pixel centres, or, `sampled`, its samples at the offsets
/// given in `format`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn draw<E: EdgeInt>(
    scene: &Scene,
    plan: &Plan,
    format: Format,
    sampled: Option<(&Samples, &[[i64; 2]])>,
    index: usize,
    triangle: &Triangle,
    positions: [[Fixed; 2]; 3],
    canvas: crate::scene::Canvas,
    frame: &mut Frame,
) {
    let footprint = match sampled {
        Some(_) => Footprint::Squares,
        None => Footprint::Centres,
    };
    let Some(mut setup) = setup::setup_in::<E>(
        positions,
        triangle,
        format,
        scene.rules.fill_rule,
        scene.rules.cull,
        canvas,
        plan,
        |_, _| None,
        footprint,
    ) else {
        return;
    };
    setup
        .shading
        .set_provoking(scene.rules.provoking_vertex.index(3));
    match sampled {
        Some((samples, offsets)) => {
            antialias::write_triangle(&setup, format, offsets, samples.sampling, index, frame)
        }
        None => {
            let mut sink = FrameSink {
                frame,
                index,
                setup: &setup,
            };
            traverse::traverse(&setup, &mut sink);
        }
    }
}

/// Writes covered pixels, and their interpolated values, into a frame.
struct FrameSink<'a, E> {
    frame: &'a mut Frame,
    index: usize,
    setup: &'a TriangleSetup<E>,
}

impl<E: EdgeInt> Sink for FrameSink<'_, E> {
    #[inline]
    fn ahead(&mut self, y: i64, x0: i64, x1: i64) {
        let row = y as usize * self.frame.width as usize;
        let run = row + x0 as usize..row + x1 as usize;
        traverse::prefetch(&self.frame.coverage[run.clone()]);
        traverse::prefetch(&self.frame.last[run]);
    }

    fn span(&mut self, y: i64, x0: i64, x1: i64) {
        let width = self.frame.width as usize;
        let row = y as usize * width;
        self.frame
            .hit_run(row + x0 as usize, row + x1 as usize, self.index);
        if matches!(self.setup.shading, Shading::None) {
            return;
        }
        // The exact edge values at the span's first pixel, bias removed,
        // then stepped pixel by pixel.
        let mut e = self.setup.edges.map(|edge| edge.at(x0, y) - edge.bias);
        for x in x0..x1 {
            self.setup.shading.write(self.frame, row + x as usize, e);
            for (value, edge) in e.iter_mut().zip(&self.setup.edges) {
                *value = *value + edge.step_x;
            }
        }
    }
}
