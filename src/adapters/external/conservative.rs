//! What a program declares about conservative rasterization (SPEC.md
//! §12.11, §19): the hello's `capabilities.conservative` (its modes, its
//! uncertainty, its degenerate-primitive behaviour, points and lines, the
//! fully-covered flag, its depth), what a conservative case asks of it
//! (refused unsent, naming the declaration, when it asks for a mode, the
//! flag, conservative lines or depth it does not declare; never for its
//! uncertainty, which it cannot choose and is judged under, SPEC.md
//! §19.6), and the
//! conservative state a request carries. Like §12.10's, the declaration is
//! asked for: a conservative case goes only to a persistent program whose
//! hello makes it, since a program written before §12.11 would draw the
//! case with its fill rule and fail it.

use serde_json::{json, Map, Value};

use super::values::float_exact;
use crate::scene::{Conservative, ConservativeMode, ConservativeSupport, Number, Primitive, Scene};

/// A hello's `capabilities.conservative`; `None` fields: not declared.
#[derive(Clone, Debug, PartialEq)]
pub struct DeclaredConservative {
    /// The modes it draws (`modes`).
    pub modes: Vec<ConservativeMode>,
    /// Its uncertainty, u ≥ 0 px, exact: it grows a triangle by at most u
    /// (overestimation), or shrinks it by at most u (underestimation).
    /// Default 0.
    pub uncertainty: Number,
    /// `degenerate_triangles`, `degenerate_lines`, `points_and_lines`:
    /// fixed where declared (the case is judged under them), else it
    /// follows each case's (sent in the request).
    pub degenerate_triangles: Option<bool>,
    pub degenerate_lines: Option<bool>,
    pub points_and_lines: Option<bool>,
    /// It gives the fully-covered flag (`fully_covered: true`).
    pub fully_covered: bool,
    /// It gives the depth of a conservatively drawn pixel (`depth: true`,
    /// SPEC.md §12.11, judged by §19.9).
    pub depth: bool,
}

/// The keys of `capabilities.conservative` (their kinds are in
/// `hello.rs`' `KEYS`).
pub const PATH: &str = "$.hello.capabilities.conservative";

/// Why a conservative case is not sent to a program without a hello.
pub const NOT_DECLARED: &str = "conservative cases are sent only to programs that declare \
     capabilities.conservative (SPEC §12.11)";

impl DeclaredConservative {
    /// Reads `capabilities.conservative` (its keys and words already
    /// checked against `KEYS`); the uncertainty is an exact number, a JSON
    /// number or a string (`"1/512"`), from 0 to 1 px. The message names
    /// the JSON path.
    pub fn parse(object: &Map<String, Value>) -> Result<DeclaredConservative, String> {
        let flag = |key: &str| object.get(key).and_then(Value::as_bool);
        let modes = match object.get("modes").and_then(Value::as_array) {
            Some(list) => list
                .iter()
                .filter_map(Value::as_str)
                .filter_map(ConservativeMode::from_name)
                .collect(),
            None => ConservativeMode::ALL.to_vec(),
        };
        let uncertainty = match object.get("uncertainty") {
            None => Number::ZERO,
            Some(value) => {
                let text = match value {
                    Value::String(s) => s.clone(),
                    Value::Number(n) => n.to_string(),
                    _ => String::new(),
                };
                let n = Number::from_string(&text).map_err(|e| {
                    format!("{PATH}.uncertainty: {value} is not an exact number ({e})")
                })?;
                if n < Number::ZERO || n > Number::from_int(1) {
                    return Err(format!(
                        "{PATH}.uncertainty is {}; it must be from 0 to 1 (px)",
                        n.to_exact_string()
                    ));
                }
                n
            }
        };
        Ok(DeclaredConservative {
            modes,
            uncertainty,
            degenerate_triangles: flag("degenerate_triangles"),
            degenerate_lines: flag("degenerate_lines"),
            points_and_lines: flag("points_and_lines"),
            fully_covered: flag("fully_covered") == Some(true),
            depth: flag("depth") == Some(true),
        })
    }

    /// What the program is judged under (SPEC.md §19.6): its modes, its
    /// flag, its uncertainty in both modes, its fixed properties.
    pub fn support(&self) -> ConservativeSupport {
        ConservativeSupport {
            overestimate: self.modes.contains(&ConservativeMode::Overestimate),
            underestimate: self.modes.contains(&ConservativeMode::Underestimate),
            fully_covered: self.fully_covered,
            overestimation_uncertainty: Some(self.uncertainty.clone()),
            underestimation_uncertainty: Some(self.uncertainty.clone()),
            degenerate_triangles: self.degenerate_triangles,
            degenerate_lines: self.degenerate_lines,
            points_and_lines: self.points_and_lines,
            // A program that gives no depth there is refused a case with
            // depth (SPEC.md §12.11, §19.9).
            depth: self.depth,
        }
    }
}

/// Why a conservative scene asks more than `declared` (the hello's
/// `capabilities.conservative`, `None` when it has none), naming the
/// declaration; `who` is "the program (NAME VERSION)". `None` for a scene
/// that is not conservative, or one the declaration covers.
pub fn refuses(
    scene: &Scene,
    declared: Option<&DeclaredConservative>,
    who: &str,
) -> Option<String> {
    let case = scene.effects.conservative.as_ref()?;
    let Some(d) = declared else {
        return Some(format!(
            "{who} declares no conservative rasterization (its hello declares no \
             capabilities.conservative); {NOT_DECLARED}"
        ));
    };
    if !d.modes.contains(&case.mode) {
        let modes: Vec<&str> = d.modes.iter().map(|m| m.name()).collect();
        return Some(format!(
            "{who} declares no conservative {} (its hello's conservative.modes: [{}])",
            case.mode.name(),
            modes.join(", ")
        ));
    }
    if case.fully_covered && !d.fully_covered {
        return Some(format!(
            "{who} gives no fully-covered flag (its hello's conservative.fully_covered is not true)"
        ));
    }
    let lines = scene
        .primitives
        .iter()
        .any(|p| matches!(p, Primitive::Line(_) | Primitive::Point(_)));
    if lines && case.points_and_lines && d.points_and_lines != Some(true) {
        return Some(format!(
            "{who} declares no conservative points and lines (its hello's \
             conservative.points_and_lines is not true)"
        ));
    }
    if scene.has_depth && !d.depth {
        return Some(format!(
            "{who} gives no depth under conservative rasterization (its hello's \
             conservative.depth is not true; SPEC §12.11)"
        ));
    }
    None
}

/// The conservative state of a request's `rules` (SPEC.md §12.11): the
/// case's, with the uncertainty as a float and, in `exact`, as a string.
pub fn request_rules(case: &Conservative) -> Value {
    let (float, exact) = float_exact(&case.uncertainty);
    json!({
        "mode": case.mode.name(),
        "uncertainty": float,
        "fully_covered": case.fully_covered,
        "degenerate_triangles": case.degenerate_triangles,
        "degenerate_lines": case.degenerate_lines,
        "points_and_lines": case.points_and_lines,
        "exact": {"uncertainty": exact},
    })
}

/// An answer's fully-covered flag: 0 or 1, nothing else.
pub fn flag(value: Option<f64>) -> Option<bool> {
    match value {
        Some(0.0) => Some(false),
        Some(1.0) => Some(true),
        _ => None,
    }
}

/// What a fragment's last value is when it is not 0 or 1.
pub const NOT_A_FLAG: &str = "is not a fully-covered flag (0 or 1, SPEC §12.11)";

/// Whether an answer's fragments end with the fully-covered flag: the
/// case asks for it.
pub fn flagged(scene: &Scene) -> bool {
    scene
        .effects
        .conservative
        .as_ref()
        .is_some_and(|c| c.fully_covered)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{parse_case, Limits};

    fn declared(v: Value) -> Result<DeclaredConservative, String> {
        DeclaredConservative::parse(v.as_object().unwrap())
    }

    fn scene(conservative: Value) -> Scene {
        parse_case(
            &json!({
                "name": "c", "canvas": {"width": 4, "height": 4},
                "effects": {"conservative": conservative},
                "primitives": [{"triangle": [[0.5, 0.5], [3.5, 0.5], [0.5, 3.5]]}],
            })
            .to_string(),
            "c",
            &Limits::default(),
        )
        .unwrap()
    }

    #[test]
    fn reads_a_declaration_and_its_uncertainty_exactly() {
        let d = declared(json!({"modes": ["overestimate"], "uncertainty": "1/512",
                                "degenerate_triangles": true, "fully_covered": true}))
        .unwrap();
        assert_eq!(d.modes, vec![ConservativeMode::Overestimate]);
        assert_eq!(d.uncertainty, Number::ratio(1, 512));
        assert_eq!(d.degenerate_triangles, Some(true));
        assert_eq!(
            d.support().overestimation_uncertainty,
            Some(Number::ratio(1, 512))
        );
        let n = declared(json!({"uncertainty": 0.001953125})).unwrap();
        assert_eq!(n.uncertainty, Number::ratio(1, 512));
        assert_eq!(n.modes.len(), 2, "no modes listed: both");
        let e = declared(json!({"uncertainty": "2"})).unwrap_err();
        assert!(
            e.starts_with("$.hello.capabilities.conservative.uncertainty is 2"),
            "{e}"
        );
        let e = declared(json!({"uncertainty": "a/b"})).unwrap_err();
        assert!(
            e.starts_with("$.hello.capabilities.conservative.uncertainty:"),
            "{e}"
        );
    }

    /// A case asking for a mode not offered or the flag undeclared is
    /// refused, naming the declaration; a case stating another uncertainty
    /// is sent either way (the program is judged under its own, SPEC.md
    /// §19.6).
    #[test]
    fn a_case_asking_more_than_declared_is_refused_naming_it() {
        let who = "the program (toy 1)";
        let d = declared(json!({"modes": ["overestimate"], "uncertainty": "1/256"})).unwrap();
        let over = |u: &str| scene(json!({"mode": "overestimate", "uncertainty": u}));
        assert_eq!(refuses(&over("1/256"), Some(&d), who), None);
        assert_eq!(refuses(&over("1/2"), Some(&d), who), None);
        assert_eq!(
            refuses(&over("1/512"), Some(&d), who),
            None,
            "a tighter case is sent and judged under the declared 1/256"
        );
        assert_eq!(refuses(&over("0"), Some(&d), who), None);
        let under = refuses(
            &scene(json!({"mode": "underestimate", "uncertainty": "1/2"})),
            Some(&d),
            who,
        )
        .unwrap();
        assert!(
            under.contains("conservative.modes: [overestimate]"),
            "{under}"
        );
        let flag = refuses(
            &scene(json!({"mode": "overestimate", "uncertainty": "1/2", "fully_covered": true})),
            Some(&d),
            who,
        )
        .unwrap();
        assert!(flag.contains("no fully-covered flag"), "{flag}");
        let none = refuses(&over("0"), None, who).unwrap();
        assert!(
            none.contains("declares no conservative rasterization"),
            "{none}"
        );
    }

    /// A conservative case with depth goes only to a program declaring
    /// `depth: true` (SPEC.md §12.11); the same case without z to either.
    #[test]
    fn a_case_with_depth_needs_the_depth_declared() {
        let who = "the program (toy 1)";
        let deep = parse_case(
            &json!({
                "name": "d", "canvas": {"width": 4, "height": 4},
                "effects": {"conservative": {"mode": "overestimate"}},
                "primitives": [{"triangle": [{"position": [0, 0], "z": 0},
                                             {"position": [4, 0], "z": 1},
                                             {"position": [0, 4], "z": 0}]}],
            })
            .to_string(),
            "d",
            &Limits::default(),
        )
        .unwrap();
        let without = declared(json!({"modes": ["overestimate"]})).unwrap();
        let why = refuses(&deep, Some(&without), who).unwrap();
        assert!(
            why.contains("gives no depth under conservative rasterization")
                && why.contains("conservative.depth is not true"),
            "{why}"
        );
        assert!(!without.support().depth);
        let with = declared(json!({"modes": ["overestimate"], "depth": true})).unwrap();
        assert_eq!(refuses(&deep, Some(&with), who), None);
        assert!(with.support().depth);
        let flat = scene(json!({"mode": "overestimate"}));
        assert_eq!(refuses(&flat, Some(&without), who), None);
    }

    #[test]
    fn a_request_carries_the_state_exactly() {
        let s =
            scene(json!({"mode": "underestimate", "uncertainty": "1/3", "fully_covered": true}));
        let rules = request_rules(s.effects.conservative.as_ref().unwrap());
        assert_eq!(rules["mode"], "underestimate");
        assert_eq!(rules["exact"]["uncertainty"], "1/3");
        assert_eq!(rules["fully_covered"], true);
        assert!(flagged(&s));
    }
}
