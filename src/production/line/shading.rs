//! What a line writes: its values interpolated in f32 along the line
//! parameter of SPEC.md §5 ([`LineShading`], never triangle barycentrics),
//! and the sink every rule hands its pixels or samples to ([`LineSink`]),
//! which counts them in the frame and writes their values. No coverage is
//! decided here.

use super::step::{length2, Geometry};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::antialias::{self, SampleSink, Samples};
use crate::production::fixed::{EdgeInt, Format};
use crate::production::traverse::Sink;
use crate::scene::{Interpolation, Line, LineParameter};

/// Per-line values for f32 interpolation along the line parameter.
#[derive(Clone, Debug)]
pub(crate) struct LineShading {
    interpolation: Interpolation,
    parameter: LineParameter,
    v0: [i64; 2],
    d: [i64; 2],
    major: usize,
    /// 1 / |d_major| for `major`, 1 / |d|² for `projected`.
    inv_denominator: f64,
    depth: Option<[f32; 2]>,
    /// Per attribute: a/w at each end for perspective, a otherwise.
    attributes: Vec<[f32; 2]>,
    inv_w: [f32; 2],
    /// The end (0 or 1) whose values a `flat` line takes (SPEC.md §16.6).
    provoking: usize,
}

impl LineShading {
    /// A line's shading; a `flat` line takes end `provoking`'s values.
    pub fn new(line: &Line, g: &Geometry, plan: &Plan, provoking: usize) -> LineShading {
        let vs = &line.vertices;
        let inv_w = [0, 1].map(|i| 1.0 / vs[i].w.to_f64_lossy());
        let interpolation = line.interpolation;
        let attributes = (0..plan.attributes)
            .map(|k| {
                [0, 1].map(|i| {
                    let a = vs[i].attributes[k].to_f64_lossy();
                    let a = if interpolation == Interpolation::Perspective {
                        a * inv_w[i]
                    } else {
                        a
                    };
                    a as f32
                })
            })
            .collect();
        let denominator = match line.parameter {
            LineParameter::Major => g.d[g.major].abs() as f64,
            LineParameter::Projected => length2(g) as f64,
        };
        LineShading {
            interpolation,
            parameter: line.parameter,
            v0: g.v0,
            d: g.d,
            major: g.major,
            inv_denominator: 1.0 / denominator,
            depth: plan
                .depth
                .then(|| [0, 1].map(|i| vs[i].z.to_f64_lossy() as f32)),
            attributes,
            inv_w: inv_w.map(|w| w as f32),
            provoking,
        }
    }

    /// The weights (1 − t, t) of the ends at the sample `p` (fixed point),
    /// t clamped to [0, 1]. Each weight is its own exact integer over the
    /// exact denominator, rounded once, so neither loses precision near an
    /// end.
    pub fn weights(&self, p: [i64; 2]) -> [f32; 2] {
        let q = [i128::from(p[0] - self.v0[0]), i128::from(p[1] - self.v0[1])];
        let d = [i128::from(self.d[0]), i128::from(self.d[1])];
        let (along, whole) = match self.parameter {
            LineParameter::Major => {
                let sign = d[self.major].signum();
                (q[self.major] * sign, d[self.major] * sign)
            }
            LineParameter::Projected => (q[0] * d[0] + q[1] * d[1], d[0] * d[0] + d[1] * d[1]),
        };
        if along <= 0 {
            [1.0, 0.0]
        } else if along >= whole {
            [0.0, 1.0]
        } else {
            [
                ((whole - along) as f64 * self.inv_denominator) as f32,
                (along as f64 * self.inv_denominator) as f32,
            ]
        }
    }

    /// Writes depth and attributes for sample `i` with the ends' weights.
    pub fn write(&self, frame: &mut Frame, i: usize, [s, t]: [f32; 2]) {
        if let (Some([z0, z1]), Some(out)) = (self.depth, frame.depth.as_mut()) {
            out[i] = f64::from(s * z0 + t * z1);
        }
        let perspective_w = match self.interpolation {
            Interpolation::Perspective => s * self.inv_w[0] + t * self.inv_w[1],
            _ => 1.0,
        };
        for (channel, [a0, a1]) in frame.attributes.iter_mut().zip(&self.attributes) {
            let value = match self.interpolation {
                Interpolation::Flat => [*a0, *a1][self.provoking],
                Interpolation::Linear => s * a0 + t * a1,
                Interpolation::Perspective => (s * a0 + t * a1) / perspective_w,
            };
            channel[i] = f64::from(value);
        }
    }
}

/// Writes a line's pixels, and their values, into the frame.
pub(super) struct LineSink<'a> {
    pub frame: &'a mut Frame,
    pub index: usize,
    pub shading: Option<&'a LineShading>,
    pub format: Format,
    /// Antialiased scenes: the samples, and their offsets in `format`.
    pub samples: Option<&'a Samples<'a>>,
    pub offsets: Vec<[i64; 2]>,
}

impl LineSink<'_> {
    /// Sample `s` of pixel (x, y) of an antialiased frame is covered.
    #[inline]
    fn sample(&mut self, x: i64, y: i64, s: usize) {
        let n = self.offsets.len();
        let i = (y as usize * self.frame.width as usize + x as usize) * n + s;
        self.frame.hit(i, self.index);
        if let Some(shading) = self.shading {
            let one = self.format.one();
            let [ox, oy] = self.offsets[s];
            let p = [x * one + ox, y * one + oy];
            shading.write(self.frame, i, shading.weights(p));
        }
    }

    #[inline]
    pub fn pixel(&mut self, x: i64, y: i64) {
        let i = y as usize * self.frame.width as usize + x as usize;
        self.frame.hit(i, self.index);
        if let Some(shading) = self.shading {
            let p = [self.format.centre(x).0, self.format.centre(y).0];
            shading.write(self.frame, i, shading.weights(p));
        }
    }
}

impl<E: EdgeInt> SampleSink<E> for LineSink<'_> {
    #[inline]
    fn sample(&mut self, x: i64, y: i64, s: usize, _: antialias::At<E>) {
        LineSink::sample(self, x, y, s);
    }
}

impl Sink for LineSink<'_> {
    fn span(&mut self, y: i64, x0: i64, x1: i64) {
        for x in x0..x1 {
            self.pixel(x, y);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_support::*;
    use super::*;
    use crate::production::fixed::Fixed;
    use crate::scene::{LineRule, Number};

    #[test]
    fn weights_are_clamped_and_exact_at_the_ends() {
        let g = Geometry::new([[Fixed(0), Fixed(0)], [Fixed(8), Fixed(2)]]);
        let mut line = test_line(LineRule::Midpoint, Number::ONE);
        let plan = Plan {
            samples_per_pixel: 1,
            antialias: None,
            depth: true,
            attributes: 0,
            motion: None,
        };
        let shading = LineShading::new(&line, &g, &plan, 0);
        assert_eq!(shading.weights([-3, 5]), [1.0, 0.0]);
        assert_eq!(shading.weights([8, 0]), [0.0, 1.0]);
        assert_eq!(shading.weights([2, 100]), [0.75, 0.25]);
        line.parameter = LineParameter::Projected;
        let shading = LineShading::new(&line, &g, &plan, 0);
        // (2, 100)·(8, 2) = 216 > 68: clamped.
        assert_eq!(shading.weights([2, 100]), [0.0, 1.0]);
        assert_eq!(shading.weights([4, 1]), [0.5, 0.5]);
    }
}
