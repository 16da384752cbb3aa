//! The harness: from case files on disk to one outcome per case.
//!
//! A case passes through: [`discover`] (case files, their ids and golden
//! roots) → [`load`] (the file read into a scene) → [`oracle`] (the
//! reference's answer, once for every candidate) → [`judge`] (each
//! candidate's frame against it, under the conventions [`profile`] says it
//! follows, a line parameter among them: [`line_parameters`]) → [`golden`]
//! (the blessed reference output) → [`baseline`]
//! (recorded metrics a later run must not get worse than). [`runner`] runs
//! many cases at once: selection, parallel execution, limits, outcomes in a
//! fixed order. [`flaky`] compares a candidate's repetitions of a case (`run --repeat`).
//! [`clipped`] restates a screen-space case clipped at a driver's viewport.
//! [`panics`] is the text of a caught panic; [`today`] the date reports are
//! stamped with; [`case_hash`] the hash of a case file a report names.
//! [`case_list`] holds a selection compactly (a million cases at tens of
//! bytes each); [`unique_names`] checks a run's case names are unique from
//! their 64-bit hashes.
//! [`conservative`] refuses and judges a conservative case's candidate
//! (SPEC.md §19) against the oracle's three classes; [`conservative_depth`]
//! judges its depth (§19.9).

pub mod baseline;
pub mod case_hash;
pub mod case_list;
pub mod clipped;
pub mod conservative;
pub mod conservative_depth;
pub mod discover;
pub mod flaky;
pub mod golden;
pub mod judge;
pub mod line_parameters;
pub mod load;
pub mod oracle;
pub mod panics;
pub mod profile;
pub mod runner;
pub mod today;
pub mod unique_names;
