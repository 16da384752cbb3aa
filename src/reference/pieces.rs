//! The values of a screen-space triangle's clipped pieces (SPEC.md §16.9).
//!
//! A driver that clips a screen-space case at its viewport draws each
//! triangle that reaches past it as the pieces clipping leaves, their new
//! vertices carrying the triangle's values there: its depth plane and
//! each attribute's plane (affine on the screen, or affine in 1/w for
//! `perspective`, §5) are the same functions on every piece as on the
//! whole triangle, and a `flat` piece keeps its provoking vertex's values
//! (§16.6). The judge restates such a case with each piece as a polygon,
//! which decides coverage and owners but carries no values; this writes
//! them: at every sample a piece is the last to cover, the whole
//! triangle's exact depth and attributes, its planes extended to the
//! sample. A new vertex snapped off the triangle's edge may put such a
//! sample up to the snapping distance outside the whole triangle, where
//! its edge values are negative and the planes still hold; only a
//! perspective channel can lose its value there (Σ b_i/w_i ≤ 0, a
//! triangle whose w differ by more than its size over that distance),
//! and such a sample keeps the polygon's values.
//!
//! What this does not do: decide coverage (the restated polygons do), or
//! values of lines, points or clip-space pieces (`clip/`).

use dashu_int::IBig;

use super::depth::DepthRules;
use super::grid::{on_grid_sampled, orient, Point};
use super::render::{store, triangle_stored};
use super::triangle::VertexValues;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::scene::{Primitive, Scene};

/// Writes into `frame` (the reference's frame of a case restated with
/// pieces in place of clipped triangles), and into `allowed` (the depths
/// its format allows, `render_judged`'s second half), the values of each
/// primitive of `pieces` at every slot it was the last to cover, taken
/// from `whole`: the same case restated with the triangles unclipped, the
/// same primitives in the same places, its vertices where the pieces' old
/// ones are. `plan` is the restated case's. Nothing happens where the plan
/// interpolates nothing, or for an index that is not a triangle of `whole`
/// of non-zero area.
pub fn take_whole_values(
    frame: &mut Frame,
    mut allowed: Option<&mut Vec<[f64; 2]>>,
    whole: &Scene,
    pieces: &[usize],
    plan: &Plan,
) {
    if !plan.interpolates() || plan.motion.is_some() || whole.in_clip_space() {
        return;
    }
    let on = on_grid_sampled(whole, plan.antialias.as_ref().map(|a| a.position_bits));
    let provoking = whole.rules.provoking_vertex.index(3);
    let mut prepared: Vec<Option<(VertexValues, IBig)>> =
        (0..whole.primitives.len()).map(|_| None).collect();
    for &index in pieces {
        let (Some(Primitive::Triangle(t)), Some(v)) =
            (whole.primitives.get(index), on.points.get(index))
        else {
            continue;
        };
        let area = orient(&v[0], &v[1], &v[2]);
        if area != IBig::ZERO {
            prepared[index] = Some((VertexValues::new(t, provoking), area));
        }
    }
    if prepared.iter().all(Option::is_none) {
        return;
    }
    let rules = DepthRules::new(whole).filter(|_| plan.depth);
    // Sample s of pixel (x, y) lies at the pixel's centre less the shift
    // that brings it there (`OnGrid::sample_shift`): (x + offset_s) on the
    // grid; without antialiasing, at the centre.
    let shifts: Vec<Point<IBig>> = match &plan.antialias {
        Some(samples) => samples
            .offsets
            .iter()
            .map(|&offset| on.sample_shift(offset, samples.position_bits))
            .collect(),
        None => vec![[IBig::ZERO, IBig::ZERO]],
    };
    let n = shifts.len();
    let width = frame.width as usize;
    for slot in 0..frame.last.len() {
        let Some(index) = (frame.last[slot] as usize).checked_sub(1) else {
            continue;
        };
        let Some((values, area)) = prepared.get(index).and_then(Option::as_ref) else {
            continue;
        };
        let (pixel, s) = (slot / n, slot % n);
        let centre = [pixel % width, pixel / width].map(|c| on.grid.centre(c as i64));
        let p = [&centre[0] - &shifts[s][0], &centre[1] - &shifts[s][1]];
        let v = &on.points[index];
        let e = [0, 1, 2].map(|i| orient(&v[i], &v[(i + 1) % 3], &p));
        if !values.defined_at(&e, area) {
            continue;
        }
        values.write(frame, slot, plan, &e, area);
        if let Some(rules) = &rules {
            let stored = triangle_stored(rules, index, values, &e, area);
            store(frame, allowed.as_deref_mut(), slot, stored);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::render_judged;
    use crate::reference::Arithmetic;
    use crate::scene::{parse_case, Limits, Number, Polygon, PolygonFill, Vertex};

    /// A triangle with depth and two perspective attributes over another,
    /// its vertex at x = −40 past a viewport whose side is x = 0; and the
    /// same with, in its place, its piece right of x = 0, every vertex on
    /// the 8-bit grid.
    fn scenes(antialias: &str) -> (Scene, Scene) {
        let v = |x: &str, y: &str, z: &str, w: &str, a: &str, b: &str| {
            format!(r#"{{"position": [{x}, {y}], "z": {z}, "w": {w}, "attributes": [{a}, {b}]}}"#)
        };
        let head = |primitive: String| {
            format!(
                r#"{{"name": "p", "canvas": {{"width": 16, "height": 16}},
                    "rules": {{"subpixel_bits": 8, "cull": "none"}}, {antialias}
                    "primitives": [{{"triangle": [{}, {}, {}], "interpolation": "linear"}}, {primitive}]}}"#,
                v("0", "0", "0", "1", "1", "2"),
                v("16", "0", "0", "1", "1", "2"),
                v("0", "16", "0", "1", "1", "2"),
            )
        };
        // Edges from (−40, 8): to (16, 1) it meets x = 0 at y = 3; to
        // (16, 15) at y = 13 (slopes −1/8 and 1/8).
        let whole = format!(
            r#"{{"triangle": [{}, {}, {}]}}"#,
            v("-40", "8", "0.25", "4", "1", "-3"),
            v("16", "1", "0.5", "0.5", "2", "7"),
            v("16", "15", "1", "1", "\"1/3\"", "5"),
        );
        let whole = parse_case(&head(whole), "p.json", &Limits::default()).unwrap();
        // No case file mixes polygons with attributes: the piece is put in
        // the triangle's place here, as the judge's restatement does.
        let mut pieces = whole.clone();
        pieces.primitives[1] = polygon(&[[0, 3], [16, 1], [16, 15], [0, 13]]);
        (whole, pieces)
    }

    /// A polygon of one contour under `nonzero`, its vertices positions.
    fn polygon(points: &[[i64; 2]]) -> Primitive {
        Primitive::Polygon(Polygon {
            vertices: points
                .iter()
                .map(|&[x, y]| Vertex::at(Number::ratio(x, 1), Number::ratio(y, 1)))
                .collect(),
            contour_ends: vec![points.len()],
            fill: PolygonFill::NonZero,
        })
    }

    #[test]
    fn a_piece_takes_its_whole_triangles_values_at_every_sample_it_covers() {
        for antialias in ["", r#""effects": {"antialias": {"samples": 4}},"#] {
            let (whole, pieces) = scenes(antialias);
            let plan = Plan::for_scene(&whole);
            assert!(plan.interpolates());
            let (want, _) = render_judged(&whole, &plan, Arithmetic::Auto);
            let (mut got, _) = render_judged(&pieces, &plan, Arithmetic::Auto);
            // The piece is the whole triangle inside the canvas: the same
            // samples, the same owners; without values, none of its own.
            assert_eq!(got.coverage, want.coverage);
            assert_eq!(got.last, want.last);
            let owned: Vec<usize> = (0..got.last.len()).filter(|&s| got.last[s] == 2).collect();
            assert!(owned.len() > 100, "{antialias}: {}", owned.len());
            assert!(owned.iter().all(|&s| got.attributes[0][s] == 0.0));
            take_whole_values(&mut got, None, &whole, &[1], &plan);
            assert_eq!(got, want, "{antialias}");
        }
    }

    #[test]
    fn depth_formats_and_offsets_are_the_whole_triangles() {
        let (mut whole, mut pieces) = scenes("");
        for s in [&mut whole, &mut pieces] {
            s.rules.depth_format = crate::scene::DepthFormat::Unorm16;
            s.rules.depth_bias = Some(crate::scene::DepthBias {
                constant: crate::scene::Number::ratio(2, 1),
                slope: crate::scene::Number::ratio(1, 1),
                clamp: crate::scene::Number::ZERO,
            });
        }
        let plan = Plan::for_scene(&whole);
        let (want, want_allowed) = render_judged(&whole, &plan, Arithmetic::Auto);
        let (mut got, mut allowed) = render_judged(&pieces, &plan, Arithmetic::Auto);
        assert_ne!(allowed, want_allowed);
        take_whole_values(&mut got, allowed.as_mut(), &whole, &[1], &plan);
        assert_eq!((got, allowed), (want, want_allowed));
    }

    #[test]
    fn samples_a_piece_covers_outside_its_triangle_extend_the_planes() {
        // The piece reaches 1/2 px left of the whole triangle's edge
        // x = 4: the sample column x = 3.5 is the piece's alone, and its
        // linear attribute is the plane's value there, 3.5.
        let text = |primitive: &str| {
            format!(
                r#"{{"name": "p", "canvas": {{"width": 8, "height": 8}},
                    "rules": {{"subpixel_bits": 8, "cull": "none"}},
                    "primitives": [{primitive}]}}"#
            )
        };
        let whole = parse_case(
            &text(
                r#"{"triangle": [{"position": [4, 0], "attributes": [4]}, {"position": [8, 0], "attributes": [8]}, {"position": [4, 8], "attributes": [4]}], "interpolation": "linear"}"#,
            ),
            "w.json",
            &Limits::default(),
        )
        .unwrap();
        let mut piece = whole.clone();
        piece.primitives[0] = polygon(&[[3, 0], [8, 0], [3, 8]]);
        let plan = Plan::for_scene(&whole);
        let (mut got, _) = render_judged(&piece, &plan, Arithmetic::Auto);
        take_whole_values(&mut got, None, &whole, &[0], &plan);
        let slot = got.index(3, 1);
        assert_eq!(got.last[slot], 1);
        assert_eq!(got.attributes[0][slot], 3.5);
    }
}
