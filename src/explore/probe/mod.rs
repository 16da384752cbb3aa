//! Convention probing: what a rasterizer does, found from its rendered
//! frames alone, and the profile (`rastercheck-profile/1`) that `run
//! --profile` judges it by.
//!
//! Every probe draws small scenes built here (no case files) and reads the
//! frames back; nothing about the rasterizer is assumed or asked. What each
//! probe draws and why it decides what it says is in `run.rs`'s module doc.
//!
//! The rooms: `run.rs` holds [`probe`], which runs every probe in the
//! order its module doc gives into a [`Profile`] (`profile.rs`, with the
//! evidence of `evidence.rs`); `diagnose.rs` is the sampler, position and
//! tie-rule decision alone (in the words of `diagnosis.rs`); `scenes.rs`
//! builds the probe scenes, `sampler.rs` and `infer.rs` decide what each
//! probe found (`outline.rs` tells outline over fill from any-coverage,
//! `truncation.rs` finds vertices truncated to whole pixels, `coverage.rs`
//! an area method's coverage encoding), `clip.rs` and `points.rs` probe clip-space conventions
//! (through `convention.rs`), `conservative.rs` measures a conservative
//! rasterizer's uncertainty, `describe.rs` puts the profile into words.
//! Reading a profile for `run --profile` is the harness's
//! (`harness/profile.rs`).

mod clip;
mod conservative;
mod convention;
mod coverage;
mod describe;
mod diagnose;
pub mod diagnosis;
mod evidence;
mod infer;
mod outline;
mod points;
mod profile;
mod run;
mod sampler;
mod scenes;
mod truncation;
mod verdict;

pub use clip::{probe_clip, ClipProbe};
pub use conservative::{probe_conservative, ConservativeProbe, Reach};
pub use convention::{Convention, ConventionProbe};
pub use diagnose::diagnose;
pub use diagnosis::{Diagnosis, Sampler, SamplerKind};
pub use evidence::{
    ChannelProbe, InterpolationProbe, MeshEvidence, Resolved, RuleCount, SlopeRule, PROBE_BITS,
    RULE_NAMES,
};
pub use points::{probe_points, PointProbe};
pub use profile::Profile;
pub use run::probe;

pub use crate::harness::profile::SCHEMA;
