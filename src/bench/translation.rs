//! The exact time coverage of triangles that move by pure translation,
//! computed here without the reference: each edge crosses a pixel centre at
//! one rational instant. The bench's motion errors are counted against it;
//! it handles nothing but translating (or static) triangles.

use crate::scene::time::limits::TIME_ONE;
use crate::scene::{Cull, Number, Primitive, Scene};

/// Coordinates [`translation_time_coverage`] takes, in units of
/// 2^-(subpixel_bits + 1) px: below 2^24, so that every cross product
/// below is under 2^51 and a comparison of two of their quotients under
/// 2^102, in i128.
const TRANSLATION_UNITS_BITS: u32 = 24;

/// The exact time coverage of each pixel centre (row-major) of a scene of
/// triangles that move by pure translation (SPEC.md §15.2), rounded to f64
/// once per triangle: no reference needed. A translation keeps every edge's
/// direction and the winding, so each edge function at the centre q is
/// linear in τ, E(τ) = α − τ·β with α = d × (q − a) and β = d × v (d the
/// edge, a its start, v the motion), and the covered instants are one
/// interval with rational ends: the shutter cut by τ < α/β where β > 0
/// and τ > α/β where β < 0. An edge with β = 0 keeps its value: it covers
/// always, never, or (a centre riding on it, α = 0) as the fill rule says.
/// Culled and zero-area triangles cover nothing. `None` when the scene
/// antialiases, has a primitive that is not a translating (or static)
/// triangle, or coordinates beyond 2^(24 − subpixel_bits − 1) px.
pub fn translation_time_coverage(scene: &Scene) -> Option<Vec<f64>> {
    let blur = scene.effects.motion_blur.as_ref()?;
    let bits = scene.rules.subpixel_bits?;
    if scene.effects.antialias.is_some() {
        return None;
    }
    let units = |n: &Number| -> Option<i128> {
        let snapped = n.snapped(bits);
        let scaled = snapped.numerator() << (bits as usize + 1);
        let den = dashu_int::IBig::from(snapped.denominator().clone());
        let u: i128 = (&(scaled / den)).try_into().ok()?;
        (u.abs() < 1 << TRANSLATION_UNITS_BITS).then_some(u)
    };
    let (width, height) = (scene.canvas.width as i128, scene.canvas.height as i128);
    let one = 1i128 << (bits + 1);
    let [open, close] = blur.shutter.map(i128::from);
    let mut out = vec![0.0; scene.canvas.pixel_count()];
    for p in &scene.primitives {
        let Primitive::Triangle(t) = p else {
            return None;
        };
        let mut from = [[0i128; 2]; 3];
        let mut to = [[0i128; 2]; 3];
        for (i, v) in t.vertices.iter().enumerate() {
            let [ex, ey] = v.end();
            from[i] = [units(&v.x)?, units(&v.y)?];
            to[i] = [units(ex)?, units(ey)?];
        }
        let motion = [to[0][0] - from[0][0], to[0][1] - from[0][1]];
        if (0..3).any(|i| [to[i][0] - from[i][0], to[i][1] - from[i][1]] != motion) {
            return None;
        }
        let cross = |u: [i128; 2], w: [i128; 2]| u[0] * w[1] - u[1] * w[0];
        let sub = |u: [i128; 2], w: [i128; 2]| [u[0] - w[0], u[1] - w[1]];
        let area = cross(sub(from[1], from[0]), sub(from[2], from[0]));
        let culled = match scene.rules.cull {
            Cull::Clockwise => area > 0,
            Cull::CounterClockwise => area < 0,
            Cull::None => false,
        };
        if area == 0 || culled {
            continue;
        }
        // Clockwise on screen: every edge function positive inside.
        let v = if area > 0 {
            from
        } else {
            [from[0], from[2], from[1]]
        };
        let edges: Vec<([i128; 2], [i128; 2], bool)> = (0..3)
            .map(|i| {
                let (a, b) = (v[i], v[(i + 1) % 3]);
                let d = sub(b, a);
                // §3: heading east on screen, a clockwise triangle lies
                // below (a top edge); heading north, to the east (a left
                // edge).
                let rule = scene.rules.fill_rule;
                let owned = match (d[1].signum(), d[0] > 0) {
                    (0, true) => rule.owns_top(),
                    (0, false) => rule.owns_bottom(),
                    (-1, _) => rule.owns_left(),
                    _ => rule.owns_right(),
                };
                (a, d, owned)
            })
            .collect();
        // Centres in the box swept between open and close, on the canvas.
        let ends = |k: usize| {
            let at = |c: i128, tau: i128| c * TIME_ONE as i128 + motion[k] * tau;
            let all = v.iter().flat_map(|p| [at(p[k], open), at(p[k], close)]);
            let (lo, hi) = all.fold((i128::MAX, i128::MIN), |(l, h), c| (l.min(c), h.max(c)));
            let scale = one * i128::from(TIME_ONE);
            // Centres i·one + one/2 in [lo, hi] (scaled by 2^16), and
            // perhaps one more before: each is decided exactly below.
            let first = (lo - scale / 2).div_euclid(scale);
            let last = (hi - scale / 2).div_euclid(scale);
            (first.max(0), last)
        };
        let ((x0, x1), (y0, y1)) = (ends(0), ends(1));
        for y in y0..=y1.min(height - 1) {
            for x in x0..=x1.min(width - 1) {
                let q = [x * one + one / 2, y * one + one / 2];
                // The interval (lo, hi), each a rational n/m with m > 0, τ
                // in [0, 1].
                let mut lo = (open, i128::from(TIME_ONE));
                let mut hi = (close, i128::from(TIME_ONE));
                let less = |a: (i128, i128), b: (i128, i128)| a.0 * b.1 < b.0 * a.1;
                let mut empty = false;
                for &(a, d, owned) in &edges {
                    let alpha = cross(d, sub(q, a));
                    let beta = cross(d, motion);
                    match beta.signum() {
                        0 => empty |= alpha < 0 || (alpha == 0 && !owned),
                        1 if less((alpha, beta), hi) => hi = (alpha, beta),
                        -1 if less(lo, (-alpha, -beta)) => lo = (-alpha, -beta),
                        _ => {}
                    }
                }
                if !empty && less(lo, hi) {
                    // (hi − lo)/(close − open), as one f64 quotient.
                    let num = hi.0 * lo.1 - lo.0 * hi.1;
                    let den = hi.1 * lo.1;
                    let span = (close - open) as f64 / f64::from(TIME_ONE);
                    out[(y * width + x) as usize] += num as f64 / den as f64 / span;
                }
            }
        }
    }
    Some(out)
}
