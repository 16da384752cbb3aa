//! What a program declares about clip space, points and depth formats
//! (SPEC.md §12.10): the hello's `clip_space`, `points` (a word of
//! `primitives`), `depth_formats` and `polygon_offset`, and the clip
//! conventions it follows whatever a case states. Unlike the capabilities
//! of §12.7, these are asked for: a case that needs one is sent only to a
//! program whose hello declares it, since a program written before §12.10
//! would misread the request. Everything else about such a case (its
//! request fields, the depth its answer gives) is `protocol.rs`'.

use serde_json::{Map, Value};

use crate::scene::{
    ClipXy, ClipZ, DepthFormat, InterpolateFrom, PointBounds, PointClip, Primitive, Scene,
};

/// A hello's declarations about clip space, points and depth formats
/// (SPEC.md §12.10); `None`/empty: not declared.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Declared3d {
    /// `capabilities.clip_space`.
    pub clip_space: Option<bool>,
    /// `points` is a word of `capabilities.primitives`.
    pub points: bool,
    /// `capabilities.depth_formats`: the formats other than `exact` it
    /// stores depth in.
    pub depth_formats: Option<Vec<DepthFormat>>,
    /// `capabilities.polygon_offset`.
    pub polygon_offset: Option<bool>,
    /// The clip conventions of `conventions` it follows whatever a case
    /// states.
    pub fixed: FixedClip,
}

/// The clip conventions a program follows whatever a case states
/// (`conventions.clip_xy`, `clip_z`, `interpolate_from`, `clip_points`,
/// `point_bounds`): a case stating others is judged under these
/// (SPEC.md §16.9), as a driver's are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FixedClip {
    pub xy: Option<ClipXy>,
    pub z: Option<ClipZ>,
    pub values: Option<InterpolateFrom>,
    pub points: Option<PointClip>,
    pub bounds: Option<PointBounds>,
}

impl FixedClip {
    /// `clip_xy` and `clip_z` as `Rasterizer::fixed_clip_rules` gives
    /// them: a hello declares both or neither (`Declared3d::parse`).
    pub fn rules(&self) -> Option<(ClipXy, ClipZ)> {
        self.xy.zip(self.z)
    }
}

/// The words of `capabilities.depth_formats`: the stored formats (`exact`
/// is every program's, and is not listed).
pub const DEPTH_FORMATS: [&str; 3] = ["unorm16", "unorm24", "float32"];

/// Reads a convention word at `$.hello.conventions.KEY`.
fn convention<T>(
    conventions: &Map<String, Value>,
    key: &str,
    from_name: fn(&str) -> Option<T>,
    names: &[&str],
) -> Result<Option<T>, String> {
    match conventions.get(key) {
        None => Ok(None),
        Some(word) => word.as_str().and_then(from_name).map(Some).ok_or_else(|| {
            format!(
                "$.hello.conventions.{key} is {word}; known: {}",
                names.join(", ")
            )
        }),
    }
}

impl Declared3d {
    /// Reads the declarations from a hello's `capabilities` and
    /// `conventions` (either may be absent); `points`, a word of the
    /// hello's `primitives`, is set by the caller that reads that list.
    /// The message names the JSON path.
    pub fn parse(
        capabilities: Option<&Map<String, Value>>,
        conventions: Option<&Map<String, Value>>,
    ) -> Result<Declared3d, String> {
        let mut out = Declared3d::default();
        if let Some(caps) = capabilities {
            let flag = |key: &str| match caps.get(key) {
                None => Ok(None),
                Some(Value::Bool(b)) => Ok(Some(*b)),
                Some(_) => Err(format!("$.hello.capabilities.{key} must be true or false")),
            };
            out.clip_space = flag("clip_space")?;
            out.polygon_offset = flag("polygon_offset")?;
            if let Some(list) = caps.get("depth_formats") {
                let list = list
                    .as_array()
                    .ok_or("$.hello.capabilities.depth_formats must be a list of words")?;
                let formats = list
                    .iter()
                    .enumerate()
                    .map(|(i, w)| {
                        w.as_str()
                            .filter(|w| DEPTH_FORMATS.contains(w))
                            .and_then(DepthFormat::from_name)
                            .ok_or_else(|| {
                                format!(
                                    "$.hello.capabilities.depth_formats[{i}] is {w}; known: {}",
                                    DEPTH_FORMATS.join(", ")
                                )
                            })
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                out.depth_formats = Some(formats);
            }
        }
        if let Some(conventions) = conventions {
            out.fixed = FixedClip {
                xy: convention(conventions, "clip_xy", ClipXy::from_name, &ClipXy::NAMES)?,
                z: convention(conventions, "clip_z", ClipZ::from_name, &ClipZ::NAMES)?,
                values: convention(
                    conventions,
                    "interpolate_from",
                    InterpolateFrom::from_name,
                    &InterpolateFrom::NAMES,
                )?,
                points: convention(
                    conventions,
                    "clip_points",
                    PointClip::from_name,
                    &PointClip::NAMES,
                )?,
                bounds: convention(
                    conventions,
                    "point_bounds",
                    PointBounds::from_name,
                    &PointBounds::NAMES,
                )?,
            };
            if out.fixed.xy.is_some() != out.fixed.z.is_some() {
                return Err("$.hello.conventions: declare clip_xy and clip_z together \
                            (a pipeline clips all six planes its own way, SPEC §16.9)"
                    .to_owned());
            }
        }
        Ok(out)
    }

    /// Why the scene needs a declaration this hello does not make, naming
    /// it; `who` is "the program (NAME VERSION)". `None`: nothing of
    /// SPEC.md §12.10 refuses it.
    pub fn refuses(&self, scene: &Scene, who: &str) -> Option<String> {
        if scene.in_clip_space() && self.clip_space != Some(true) {
            return Some(format!(
                "{who} declares no clip space ({}); {CLIP_SPACE}",
                said(self.clip_space.map(|b| b.to_string()), "clip_space")
            ));
        }
        if !self.points && scene.has_points() {
            return Some(format!(
                "{who} declares no points (its hello's primitives do not list \"points\"); {POINTS}"
            ));
        }
        let format = scene.rules.depth_format;
        if format != DepthFormat::Exact
            && !self
                .depth_formats
                .as_ref()
                .is_some_and(|l| l.contains(&format))
        {
            let listed = self.depth_formats.as_ref().map(|l| {
                format!(
                    "[{}]",
                    l.iter().map(|f| f.name()).collect::<Vec<_>>().join(", ")
                )
            });
            return Some(format!(
                "{who} declares no {} depth format ({}); {DEPTH_FORMATS_SENT}",
                format.name(),
                said(listed, "depth_formats")
            ));
        }
        if scene.rules.depth_bias.is_some() && self.polygon_offset != Some(true) {
            return Some(format!(
                "{who} declares no polygon offset ({}); {OFFSET}",
                said(self.polygon_offset.map(|b| b.to_string()), "polygon_offset")
            ));
        }
        None
    }
}

/// "its hello's KEY: VALUE", or "its hello declares no KEY".
fn said(value: Option<String>, key: &str) -> String {
    match value {
        Some(v) => format!("its hello's {key}: {v}"),
        None => format!("its hello declares no {key}"),
    }
}

const CLIP_SPACE: &str =
    "clip-space cases are sent only to programs that declare clip_space: true (SPEC §12.10)";
const POINTS: &str = "points are sent only to programs that list them (SPEC §12.10)";
const DEPTH_FORMATS_SENT: &str =
    "a depth format is sent only to programs that list it in depth_formats (SPEC §12.10)";
const OFFSET: &str =
    "polygon offset is sent only to programs that declare polygon_offset: true (SPEC §12.10)";

/// Why a scene cannot go to a program that wrote no hello (version 1, or
/// a one-shot program): what it needs of SPEC.md §12.10, which only a
/// hello declares. `None` for a scene that needs none of it.
pub fn needs_a_hello(scene: &Scene) -> Option<String> {
    let need = if scene.in_clip_space() {
        CLIP_SPACE
    } else if scene
        .primitives
        .iter()
        .any(|p| matches!(p, Primitive::Point(_)))
    {
        POINTS
    } else if scene.rules.depth_format != DepthFormat::Exact {
        DEPTH_FORMATS_SENT
    } else if scene.rules.depth_bias.is_some() {
        OFFSET
    } else if scene.is_conservative() {
        super::conservative::NOT_DECLARED
    } else {
        return None;
    };
    Some(format!(
        "{need}, in a hello of a persistent program; this program wrote none"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn parse(caps: Value, conventions: Value) -> Result<Declared3d, String> {
        Declared3d::parse(caps.as_object(), conventions.as_object())
    }

    #[test]
    fn reads_the_declarations_and_names_a_wrong_word() {
        let d = parse(
            json!({"clip_space": true, "depth_formats": ["unorm16", "float32"],
                   "polygon_offset": true}),
            json!({"clip_xy": "clip-then-snap", "clip_z": "per-sample",
                   "clip_points": "guard-band"}),
        )
        .unwrap();
        assert_eq!(d.clip_space, Some(true));
        assert_eq!(
            d.depth_formats,
            Some(vec![DepthFormat::Unorm16, DepthFormat::Float32])
        );
        assert_eq!(d.fixed.xy, Some(ClipXy::ClipThenSnap));
        assert_eq!(d.fixed.points, Some(PointClip::GuardBand));
        assert_eq!(
            d.fixed.rules(),
            Some((ClipXy::ClipThenSnap, ClipZ::PerSample))
        );
        let alone = parse(json!({}), json!({"clip_xy": "guard-band"})).unwrap_err();
        assert!(alone.contains("together"), "{alone}");
        let wrong = parse(json!({"depth_formats": ["exact"]}), json!({})).unwrap_err();
        assert!(
            wrong.contains("$.hello.capabilities.depth_formats[0]"),
            "{wrong}"
        );
        let wrong = parse(json!({}), json!({"clip_z": "sometimes"})).unwrap_err();
        assert!(wrong.contains("$.hello.conventions.clip_z"), "{wrong}");
        let wrong = parse(json!({"clip_space": "yes"}), json!({})).unwrap_err();
        assert!(wrong.contains("$.hello.capabilities.clip_space"), "{wrong}");
    }
}
