//! A conservative scene drawn (SPEC.md §19): every triangle placed in
//! fixed point as production places any, set up (`triangle.rs`), and each
//! pixel of its box tested. Overestimation draws every pixel whose square,
//! grown by the case's uncertainty, meets the triangle: the most the case
//! allows. Underestimation draws every pixel whose square, so grown, lies
//! inside it: the least the case requires. The fully-covered flag, where
//! asked for, is true where the grown square lies inside the triangle (a
//! flag it is sure of), and the last triangle to draw a pixel leaves its
//! flag there.
//!
//! Multisampled (SPEC.md §19.10), a drawn pixel covers every sample of it.
//!
//! What it does not do: motion, clip space, polygons, lines,
//! points, depth and attributes under conservative rasterization (the
//! scene says why, `Scene::conservative_unjudged`); coordinates that are
//! not snapped whose common denominator exceeds 2^24.
//!
//! Coordinates are placed as production places any (snapped, or exact in
//! fixed point); unsnapped ones that are not dyadic are held exactly in
//! units of a half of their common denominator's reciprocal instead.

use super::growth::Growth;
use super::triangle::{Setup, Shape};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::scene_format::{format_for, place};
use crate::rasterizer::RasterError;
use crate::scene::{ConservativeMode, ConservativeSupport, Number, Primitive, Scene};

/// The largest common denominator of unsnapped coordinates that are not
/// dyadic this path holds: coordinates below 2^15 px times twice it stay
/// below 2^41 units, edge functions below 2^85.
const MAX_DENOMINATOR: u64 = 1 << 24;

/// What production draws conservatively: both modes and the flag, each
/// under the case's own uncertainty and properties.
pub fn support() -> ConservativeSupport {
    ConservativeSupport {
        overestimate: true,
        underestimate: true,
        fully_covered: true,
        ..ConservativeSupport::default()
    }
}

/// Production's frame of a conservative scene.
pub fn rasterize(scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    let Some(case) = scene.effects.conservative.as_ref() else {
        return Err(RasterError::Failed(
            "production's conservative path was given a scene that is not conservative".to_owned(),
        ));
    };
    if let Some(why) = scene.conservative_unjudged() {
        return Err(RasterError::Unsupported(why));
    }
    let placed = placed(scene)?;
    let half = Growth::half_side(&case.uncertainty, placed.one);
    let margin = Growth::margin(&case.uncertainty, placed.one);
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let mut frame = Frame::for_plan(w, h, plan);
    let mut flags = case.fully_covered.then(|| vec![false; frame.pixel_count()]);
    // Multisampled (SPEC.md §19.10): a drawn pixel covers all its samples.
    let samples = frame.samples.max(1) as usize;
    for (index, primitive) in scene.primitives.iter().enumerate() {
        let Primitive::Triangle(_) = primitive else {
            return Err(RasterError::Unsupported(
                "production draws triangles only under conservative rasterization".to_owned(),
            ));
        };
        let (setup, orientation) = Setup::new(placed.vertices[index], placed.one);
        if setup.shape != Shape::Area && !case.degenerate_triangles {
            continue;
        }
        if scene.rules.cull.discards(orientation) {
            continue;
        }
        for y in setup.range(1, h) {
            for x in setup.range(0, w) {
                let drawn = match case.mode {
                    ConservativeMode::Overestimate => setup.meets(x, y, &half, &margin),
                    ConservativeMode::Underestimate => setup.holds(x, y, &half),
                };
                if !drawn {
                    continue;
                }
                let i = frame.index(x as u32, y as u32);
                frame.hit_run(i, i + samples, index);
                if let Some(flags) = &mut flags {
                    flags[i / samples] = setup.holds(x, y, &half);
                }
            }
        }
    }
    frame.fully_covered = flags;
    if frame.resolved.is_some() {
        frame.resolved = Some(frame.box_resolve());
    }
    frame.coverage_only = true;
    Ok(frame)
}

/// A scene's triangles in integer units of 1/`one` px.
struct PlacedScene {
    one: i128,
    /// Per primitive, its three vertices (nothing for others: refused).
    vertices: Vec<[[i128; 2]; 3]>,
}

/// Every triangle's vertices in integers: production's fixed point where
/// it holds them, else units of 1/(2D) px for D the coordinates' common
/// denominator.
fn placed(scene: &Scene) -> Result<PlacedScene, RasterError> {
    let triangles = || {
        scene.primitives.iter().filter_map(|p| match p {
            Primitive::Triangle(t) => Some(t),
            _ => None,
        })
    };
    if let Ok(format) = format_for(scene, None) {
        let vertices = triangles()
            .map(|t| {
                t.vertices
                    .each_ref()
                    .map(|v| [&v.x, &v.y].map(|n| i128::from(place(scene, format, n).0)))
            })
            .collect();
        return Ok(PlacedScene {
            one: 1 << format.frac_bits,
            vertices,
        });
    }
    let mut d: u64 = 1;
    for n in scene.vertices().flat_map(|v| [&v.x, &v.y]) {
        let q = u64::try_from(n.denominator()).ok();
        d = q
            .and_then(|q| {
                let lcm = d / gcd(d, q) * q;
                (lcm <= MAX_DENOMINATOR).then_some(lcm)
            })
            .ok_or_else(|| {
                RasterError::Unsupported(format!(
                    "unsnapped coordinates whose common denominator exceeds 2^24 are not held by production's conservative path ({})",
                    n.to_exact_string()
                ))
            })?;
    }
    let one = 2 * i128::from(d);
    let units = |n: &Number| {
        let p = i128::try_from(n.numerator()).expect("coordinates are bounded by COORD_LIMIT");
        let q = i128::try_from(n.denominator()).expect("q divides d");
        p * (one / q)
    };
    let vertices = triangles()
        .map(|t| t.vertices.each_ref().map(|v| [units(&v.x), units(&v.y)]))
        .collect();
    Ok(PlacedScene { one, vertices })
}

fn gcd(a: u64, b: u64) -> u64 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}
