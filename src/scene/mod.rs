//! The scene model: what a case asks to be drawn, and under which rules.
//!
//! This is the only code the reference and the production rasterizer share.
//! It holds exact numbers and names of conventions; it draws nothing and
//! decides nothing about coverage.
//!
//! `model.rs` holds the [`Scene`] and its canvas and effects,
//! `primitive.rs` what it draws, `expect.rs` what it expects; the rules
//! live in `rules.rs`, `clip.rs` (clip space), `depth.rs` (formats and
//! offset; `scene_depth.rs` asks them of a scene), `samples.rs` and
//! `time.rs` (antialiasing and motion), `conservative.rs` (conservative
//! rasterization, SPEC.md §19); exact numbers in `number.rs`;
//! `names.rs` writes each convention's words once; `case/` reads a file.

#[macro_use]
mod names;

pub mod case;
pub mod clip;
pub mod conservative;
mod conservative_lines;
pub mod depth;
pub mod expect;
pub mod model;
pub mod number;
pub mod primitive;
pub mod rules;
pub mod samples;
mod scene_depth;
pub mod time;

pub use case::{parse_case, CaseError, Limits};
pub use clip::{
    ClipRules, ClipXy, ClipZ, DepthMode, InterpolateFrom, PointBounds, PointClip, Viewport,
};
pub use conservative::{Conservative, ConservativeMode, ConservativePromise, ConservativeSupport};
pub use depth::{DepthBias, DepthFormat};
pub use expect::{Expect, TimePin};
pub use model::{Canvas, Effects, Scene};
pub use number::Number;
pub use primitive::{Line, Point, Polygon, Primitive, Triangle, Vertex};
pub use rules::{
    Cull, DeclaredRule, FillRule, Interpolation, LastPixel, LineClamp, LineParameter, LineRule,
    LineT, PolygonFill, ProvokingVertex, Rules,
};
pub use samples::{Antialias, Pattern};
pub use time::{MotionBlur, TimePattern};
