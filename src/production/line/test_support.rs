//! What the line tests share: a deterministic generator, a small canvas,
//! random segments, and one line drawn through [`draw`] into a
//! frame of its own.

use super::draw::draw;
use super::step::Geometry;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::fixed::{EdgeInt, Fixed, Format};
use crate::rasterizer::RasterError;
use crate::scene::{
    Canvas, FillRule, Interpolation, LastPixel, Line, LineParameter, LineRule, Number, Vertex,
};

/// A tiny deterministic generator (xorshift), so the tests need no
/// dependency.
pub(super) struct Rng(pub u64);
impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }
}

pub(super) const CANVAS: Canvas = Canvas {
    width: 24,
    height: 20,
};

pub(super) fn random_geometry(rng: &mut Rng, format: Format, spread: i64) -> Geometry {
    let one = format.one();
    let mut p = || rng.range(-2 * one, spread * one);
    let ends = [[Fixed(p()), Fixed(p())], [Fixed(p()), Fixed(p())]];
    Geometry::new(ends)
}

pub(super) fn frame_for(canvas: Canvas) -> Frame {
    Frame::new(canvas.width, canvas.height, false, 0)
}

pub(super) fn test_line(rule: LineRule, width: Number) -> Line {
    Line {
        vertices: [
            Vertex::at(Number::ZERO, Number::ZERO),
            Vertex::at(Number::ZERO, Number::ZERO),
        ],
        rule,
        width,
        last_pixel: LastPixel::Include,
        parameter: LineParameter::Major,
        interpolation: Interpolation::Perspective,
    }
}

pub(super) fn draw_one<E: EdgeInt>(
    line: &Line,
    g: &Geometry,
    format: Format,
    rule: FillRule,
    canvas: Canvas,
) -> Result<Frame, RasterError> {
    let mut frame = frame_for(canvas);
    let plan = Plan::coverage_only();
    let ends = [
        [Fixed(g.v0[0]), Fixed(g.v0[1])],
        [Fixed(g.v1[0]), Fixed(g.v1[1])],
    ];
    draw::<E>(
        line,
        ends,
        format,
        rule,
        canvas,
        &plan,
        None,
        0,
        crate::scene::ProvokingVertex::First,
        &mut frame,
    )?;
    Ok(frame)
}
