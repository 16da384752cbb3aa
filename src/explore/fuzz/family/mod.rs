//! Scene generation: the eight [`Family`]s and [`generate`], which draws case
//! `index` of a seed from its own stream and keeps it only when it is a
//! valid case (SPEC.md §8). One file per family; `common.rs` holds what
//! several draw from.
//!
//! `list.rs` names the families; `generate.rs` draws a scene of one, from
//! the family's own file.

mod antialias;
mod clip;
mod common;
mod conservative;
mod conservative_lines;
mod generate;
mod lines;
mod list;
mod mesh;
mod motion;
mod polygons;
mod triangles;

pub use generate::{generate, scene_from_tape, tape_of_case};
pub use list::Family;
pub use mesh::{ear_clip, ear_clip_star, winds_one_way};
