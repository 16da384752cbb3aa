//! The seeded scenes the bench draws: random right triangles, midpoint
//! lines and translating triangles, every vertex on the 2^-8 grid, the
//! same scenes on every run ([`SEED`]).

use crate::explore::fuzz::Rng;
use crate::scene::time::limits::TIME_ONE;
use crate::scene::{
    Canvas, Effects, Expect, Interpolation, LastPixel, Line, LineParameter, LineRule, MotionBlur,
    Number, Primitive, Rules, Scene, TimePattern, Triangle, Vertex,
};

/// The seed of every workload: the same scenes on every run.
pub const SEED: u64 = 0x6265_6e63_6821;

fn on_grid(v: f64) -> Number {
    Number::ratio((v * 256.0).round() as i64, 256)
}

fn scene(name: &str, canvas: u32, primitives: Vec<Primitive>) -> Scene {
    Scene {
        name: name.to_owned(),
        description: String::new(),
        canvas: Canvas {
            width: canvas,
            height: canvas,
        },
        rules: Rules::default(),
        primitives,
        effects: Effects::default(),
        expect: Expect::default(),
        attribute_count: 0,
        has_depth: false,
        viewport: None,
    }
}

/// Right triangles with legs `leg`, randomly rotated, wholly inside the
/// canvas (one pixel of margin).
pub fn triangle_scene(canvas: u32, leg: u32, count: usize, seed: u64) -> Scene {
    let mut rng = Rng::new(seed ^ u64::from(leg));
    let l = f64::from(leg);
    let size = f64::from(canvas);
    let primitives = (0..count)
        .map(|_| {
            let theta = rng.uniform(0.0, std::f64::consts::TAU);
            let (s, c) = theta.sin_cos();
            let offsets = [(0.0, 0.0), (l * c, l * s), (-l * s, l * c)];
            let min_x = offsets.iter().map(|o| o.0).fold(f64::MAX, f64::min);
            let max_x = offsets.iter().map(|o| o.0).fold(f64::MIN, f64::max);
            let min_y = offsets.iter().map(|o| o.1).fold(f64::MAX, f64::min);
            let max_y = offsets.iter().map(|o| o.1).fold(f64::MIN, f64::max);
            let ox = rng.uniform(1.0 - min_x, size - 1.0 - max_x);
            let oy = rng.uniform(1.0 - min_y, size - 1.0 - max_y);
            Primitive::Triangle(Triangle {
                vertices: offsets.map(|(dx, dy)| Vertex::at(on_grid(ox + dx), on_grid(oy + dy))),
                interpolation: Interpolation::Linear,
            })
        })
        .collect();
    scene(&format!("triangles L={leg}"), canvas, primitives)
}

/// Midpoint lines of random direction and length in `lengths`, wholly
/// inside the canvas.
pub fn line_scene(canvas: u32, lengths: (f64, f64), count: usize, seed: u64) -> Scene {
    let mut rng = Rng::new(seed ^ 0x4c49_4e45);
    let size = f64::from(canvas);
    let primitives = (0..count)
        .map(|_| {
            let len = rng.uniform(lengths.0, lengths.1);
            let theta = rng.uniform(0.0, std::f64::consts::TAU);
            let (dx, dy) = (len * theta.cos(), len * theta.sin());
            let x0 = rng.uniform(1.0 - dx.min(0.0), size - 1.0 - dx.max(0.0));
            let y0 = rng.uniform(1.0 - dy.min(0.0), size - 1.0 - dy.max(0.0));
            Primitive::Line(Line {
                vertices: [
                    Vertex::at(on_grid(x0), on_grid(y0)),
                    Vertex::at(on_grid(x0 + dx), on_grid(y0 + dy)),
                ],
                rule: LineRule::Midpoint,
                width: Number::ONE,
                last_pixel: LastPixel::Include,
                parameter: LineParameter::Major,
                interpolation: Interpolation::Linear,
            })
        })
        .collect();
    scene("lines", canvas, primitives)
}

/// The triangles of [`triangle_scene`], each translated over the shutter by
/// `reach`/2 to `reach` px in a random direction (on the 2^-8 grid, so that
/// snapping leaves the motion as it is), sampled at `samples` instants of
/// `pattern` per pixel centre.
pub fn motion_scene(
    canvas: u32,
    leg: u32,
    count: usize,
    reach: f64,
    samples: u32,
    pattern: TimePattern,
    seed: u64,
) -> Scene {
    let mut s = triangle_scene(canvas, leg, count, seed);
    let mut rng = Rng::new(seed ^ 0x4d4f_5645);
    for p in &mut s.primitives {
        let theta = rng.uniform(0.0, std::f64::consts::TAU);
        let length = rng.uniform(reach / 2.0, reach);
        let d = [on_grid(length * theta.cos()), on_grid(length * theta.sin())];
        for v in p.vertices_mut() {
            v.to = Some(Box::new([&v.x + &d[0], &v.y + &d[1]]));
        }
    }
    s.name = format!("moving triangles L={leg}");
    s.effects.motion_blur = Some(MotionBlur {
        shutter: [0, TIME_ONE],
        samples,
        pattern,
        seed,
    });
    s
}
