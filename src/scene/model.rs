//! The scene: one case's canvas, rules, primitives, effects and
//! expectations, and what can be asked of it as a whole.

use super::clip::Viewport;
use super::conservative::Conservative;
use super::expect::Expect;
use super::number::Number;
use super::primitive::{Primitive, Triangle, Vertex};
use super::rules::{FillRule, Interpolation, ProvokingVertex, Rules};
use super::samples::Antialias;
use super::time::MotionBlur;

/// One case: a canvas, rules, primitives, effects and expectations.
#[derive(Clone, Debug)]
pub struct Scene {
    pub name: String,
    pub description: String,
    pub canvas: Canvas,
    pub rules: Rules,
    pub primitives: Vec<Primitive>,
    pub effects: Effects,
    pub expect: Expect,
    /// Attributes every vertex carries (the same count for all vertices).
    pub attribute_count: usize,
    /// Whether any vertex gives `z`, or the scene is in clip space; only
    /// then is depth interpolated.
    pub has_depth: bool,
    /// `Some` when every vertex is in clip space (SPEC.md §16): its x, y,
    /// z and w are homogeneous clip coordinates, mapped onto the canvas by
    /// this viewport after clipping. `None`: screen space, as in §2.
    pub viewport: Option<Viewport>,
}

/// The pixel grid. Pixel (x, y) covers [x, x+1) × [y, y+1), y pointing down.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Canvas {
    pub width: u32,
    pub height: u32,
}

impl Canvas {
    pub fn pixel_count(&self) -> usize {
        self.width as usize * self.height as usize
    }
}

/// Effects a case turns on; a scene pays only for those it names.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Effects {
    /// Several samples per pixel and a resolved coverage per pixel.
    pub antialias: Option<Antialias>,
    /// A shutter interval and time samples (SPEC.md §15); it changes
    /// nothing unless some primitive moves.
    pub motion_blur: Option<MotionBlur>,
    /// Conservative rasterization (SPEC.md §19): the mode, its uncertainty
    /// and the API properties; it replaces the fill rule for triangles.
    pub conservative: Option<Conservative>,
}

impl Scene {
    /// The same scene under another fill rule.
    pub fn with_fill_rule(&self, rule: FillRule) -> Scene {
        let mut s = self.clone();
        s.rules.fill_rule = rule;
        s
    }

    /// The triangles, each with its index among all primitives.
    pub fn triangles(&self) -> impl Iterator<Item = (usize, &Triangle)> {
        self.primitives
            .iter()
            .enumerate()
            .filter_map(|(i, p)| match p {
                Primitive::Triangle(t) => Some((i, t)),
                _ => None,
            })
    }

    /// Whether any primitive is a polygon.
    pub fn has_polygons(&self) -> bool {
        self.primitives
            .iter()
            .any(|p| matches!(p, Primitive::Polygon(_)))
    }

    /// Whether any primitive is a point (SPEC.md §17).
    pub fn has_points(&self) -> bool {
        self.primitives
            .iter()
            .any(|p| matches!(p, Primitive::Point(_)))
    }

    /// Whether the scene is drawn conservatively (SPEC.md §19).
    pub fn is_conservative(&self) -> bool {
        self.effects.conservative.is_some()
    }

    /// Why a conservative scene is not judged in this version, if it is
    /// not (SPEC.md §19.7): motion, clip space, polygons, attributes at
    /// conservative pixels, the depth of points and lines or of multisampled
    /// scenes, and lines without an area. Every candidate's verdict on it is `unsupported`
    /// with this reason; `None` for a scene that is not conservative.
    pub fn conservative_unjudged(&self) -> Option<String> {
        self.effects.conservative.as_ref()?;
        let clash = if self.effects.motion_blur.is_some() {
            Some("effects.motion_blur")
        } else if self.in_clip_space() {
            Some("clip space")
        } else if self.has_polygons() {
            Some("polygons")
        } else {
            None
        };
        if let Some(what) = clash {
            return Some(format!(
                "conservative rasterization with {what} is not judged in this version (SPEC.md §19.7)"
            ));
        }
        if self.has_depth && self.has_points_or_lines() {
            return Some("the depth of conservatively drawn points and lines is not judged in this version (SPEC.md §19.7)".to_owned());
        }
        if self.has_depth && self.effects.antialias.is_some() {
            return Some("the depth of a multisampled conservative scene is not judged in this version (SPEC.md §19.7)".to_owned());
        }
        if self.attribute_count > 0 {
            return Some("attributes at conservatively drawn pixels are not judged in this version (SPEC.md §19.7)".to_owned());
        }
        self.conservative_lines_unjudged()
    }

    /// Whether any primitive moves: only then is there a time loop.
    pub fn moves(&self) -> bool {
        self.primitives.iter().any(Primitive::moves)
    }

    /// The static scene this one is at instant τ ∈ [0, 1] (SPEC.md §15.1):
    /// every vertex at (1 − τ)·snap(from) + τ·snap(to), exactly. Its
    /// positions are already snapped, so its `subpixel_bits` is null; motion
    /// blur and expectations are dropped. Brute force for tests: the static
    /// rules at one instant.
    ///
    /// # Panics
    /// When the scene has no `subpixel_bits` (a moving scene always has).
    pub fn at_instant(&self, instant: &Number) -> Scene {
        let bits = self
            .rules
            .subpixel_bits
            .expect("a moving scene has subpixel_bits");
        let mut scene = self.clone();
        let tau = instant.as_rbig();
        let one_minus = &dashu_ratio::RBig::ONE - tau;
        for vertex in scene.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
            let [x1, y1] = vertex.end().map(|c| c.snapped(bits).as_rbig().clone());
            let [x0, y0] = [&vertex.x, &vertex.y].map(|c| c.snapped(bits).as_rbig().clone());
            vertex.x = Number::from_rbig(&one_minus * x0 + tau * x1);
            vertex.y = Number::from_rbig(&one_minus * y0 + tau * y1);
            vertex.to = None;
        }
        scene.rules.subpixel_bits = None;
        scene.effects.motion_blur = None;
        scene.expect = Expect::default();
        scene
    }

    /// Whether the vertices are in clip space (SPEC.md §16).
    pub fn in_clip_space(&self) -> bool {
        self.viewport.is_some()
    }

    /// Whether the scene's flat values come from the last vertex
    /// (`provoking_vertex: last`, SPEC.md §16.6) on some primitive where
    /// that shows: a `flat` triangle or line carrying attributes. A
    /// rasterizer that can only take the first vertex's values must refuse
    /// exactly these scenes (`rasterizer::refuse_last_provoking`); every
    /// other scene draws the same under either rule.
    pub fn needs_last_provoking_vertex(&self) -> bool {
        self.rules.provoking_vertex == ProvokingVertex::Last
            && self.attribute_count > 0
            && self.primitives.iter().any(|p| match p {
                Primitive::Triangle(t) => t.interpolation == Interpolation::Flat,
                Primitive::Line(l) => l.interpolation == Interpolation::Flat,
                Primitive::Polygon(_) | Primitive::Point(_) => false,
            })
    }

    /// Every vertex of every primitive.
    pub fn vertices(&self) -> impl Iterator<Item = &Vertex> {
        self.primitives.iter().flat_map(|p| p.vertices())
    }
}
