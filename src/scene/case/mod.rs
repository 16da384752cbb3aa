//! Reading a case file into a `Scene`, with errors that name the file and
//! the JSON path of the offending value.
//!
//! The file is parsed into a `serde_json::Value` (with `arbitrary_precision`,
//! so every number keeps the text it was written as) and then walked by hand.
//! Walking by hand, rather than deriving `Deserialize`, is what lets every
//! error carry its JSON path, suggest the field that was meant, and read
//! numbers exactly.
//!
//! The reader is in these rooms:
//!
//! - `json.rs`: the JSON access layer (paths, fields with "did you mean",
//!   typed getters), which knows nothing of the format;
//! - `schema.rs`: the walk that maps each field of the format onto the
//!   scene model;
//! - `validate.rs`: documented ranges, and the checks across fields on the
//!   whole scene;
//! - `clip.rs`, `point.rs`, `depth.rs` and `conservative.rs`: the
//!   clip-space (§16), point (§17), depth (§18) and conservative (§19)
//!   fields and their checks;
//! - `parse.rs`: the entry point, [`parse_case`]; `reader.rs` the walk's
//!   type, `limits.rs` the run's [`Limits`], `error.rs` [`CaseError`].

mod clip;
mod conservative;
mod depth;
mod error;
mod json;
mod limits;
mod parse;
mod point;
mod reader;
mod schema;
mod validate;

pub use error::CaseError;
pub use json::{closest, edit_distance};
pub use limits::Limits;
pub use parse::parse_case;
