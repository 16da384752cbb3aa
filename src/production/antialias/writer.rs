//! A set-up triangle's covered samples, and their values, written into an
//! antialiased frame.

use super::cover::{cover, At, SampleSink};
use super::sampling::Sampling;
use crate::frame::Frame;
use crate::production::fixed::{EdgeInt, Format};
use crate::production::setup::{Shading, TriangleSetup};

/// Writes the covered samples of a set-up triangle, and their values, into
/// an antialiased frame as primitive `index`.
pub fn write_triangle<E: EdgeInt>(
    setup: &TriangleSetup<E>,
    format: Format,
    offsets: &[[i64; 2]],
    sampling: Sampling,
    index: usize,
    frame: &mut Frame,
) {
    let mut writer = TriangleWriter {
        frame,
        index,
        samples: offsets.len(),
        shading: &setup.shading,
    };
    cover(setup, format, offsets, sampling, &mut writer);
}

/// Writes a triangle's samples, and their values, into a frame.
struct TriangleWriter<'a> {
    frame: &'a mut Frame,
    index: usize,
    samples: usize,
    shading: &'a Shading,
}

impl TriangleWriter<'_> {
    #[inline]
    fn first_slot(&self, x: i64, y: i64) -> usize {
        (y as usize * self.frame.width as usize + x as usize) * self.samples
    }
}

impl<E: EdgeInt> SampleSink<E> for TriangleWriter<'_> {
    #[inline]
    fn sample(&mut self, x: i64, y: i64, s: usize, at: At<E>) {
        let i = self.first_slot(x, y) + s;
        self.frame.hit(i, self.index);
        self.shading.write(self.frame, i, at.values());
    }

    #[inline]
    fn whole(&mut self, x: i64, y: i64, samples: usize, at: impl Fn(usize) -> At<E>) {
        let first = self.first_slot(x, y);
        if let Shading::Values { .. } = self.shading {
            for s in 0..samples {
                self.shading.write(self.frame, first + s, at(s).values());
            }
        }
        let run = first..first + samples;
        for count in &mut self.frame.coverage[run.clone()] {
            *count = count.saturating_add(1);
        }
        self.frame.last[run].fill(self.index as u32 + 1);
    }
}
