//! Outputs: for people, magnified PNG images and (with `--report`) an HTML
//! page; for machines, `report.json`, `junit.xml` and `summary.md`.
//!
//! `write.rs`'s `write_all` writes the whole folder:
//!
//! ```text
//! DIR/report.json          the run, machine-readable (SPEC.md §10)
//! DIR/junit.xml            one testcase per case × rasterizer
//! DIR/summary.md           totals, failures first, worst metrics, the plots
//! DIR/plots/*.svg          accuracy charts (plots/mod.rs)
//! DIR/images/<id>/*.png    reference, candidate and difference mask, for
//!                          every result that is not a pass (antialiased
//!                          cases: resolved coverage, signed error, samples;
//!                          moving scenes: time coverage, signed error;
//!                          conservative cases: <rast>.conservative.png, the
//!                          three classes and its pixels, conservative.rs)
//! DIR/exr/<id>/<rast>.exr  signed float error maps, for every result that
//!                          is not a pass or has any nonzero error (per
//!                          sample; antialiased: resolved error per pixel;
//!                          moving: exact, candidate and error per pixel)
//! DIR/pages/<id>.html      one page per case worth a look (failures,
//!                          departures, results with some error): its
//!                          cards, pictures embedded, loaded only when opened
//! DIR/index.html           the light page for people: totals, families,
//!                          failures first, links to the case pages
//! ```
//!
//! The pictures, error maps and case page of a case are written as soon as
//! it is judged, while its frames are in memory (`case_files.rs`); the rest
//! at the end, from `report.json`'s model alone.
//!
//! `report.json` names the machine it was made on (`machine.rs`: host and
//! day) and reads back into its model (`interned.rs`: the model's words),
//! so that `merge/` can put the reports of shards and of other machines
//! together and write them with the same writers, and so that
//! `baseline_rows.rs` can hold a report's rows (a merged one's devices
//! among them) to a baseline (`baseline check --report`).
//!
//! Every file is written whole or not at all (`files.rs`'s [`write_file`]:
//! a temporary name, then a rename). A run writes only into a folder it
//! claims (`folder.rs`: new, empty, or marked by an earlier run; locked
//! while it writes), and first removes what an earlier run wrote there
//! ([`remove_owned`]), never a user's own files.

pub mod baseline_rows;
pub mod case_files;
pub mod conservative;
pub mod diff;
pub mod digest;
pub mod escape;
pub mod exr;
pub mod families;
pub mod files;
pub mod folder;
pub mod html;
pub mod interned;
pub mod json;
pub mod junit;
pub mod limits;
pub mod machine;
pub mod merge;
pub mod plots;
pub mod png;
pub mod spool;
pub mod summary;
pub mod write;

pub use escape::escape;
pub use files::{relative, remove_owned, write_file, OWNED_FILES, OWNED_FOLDERS, TEMPORARY_SUFFIX};
pub use limits::{MAX_PAGES, MAX_PICTURED, MAX_PROBLEM_PAGES};
pub use write::{write_all, write_json, write_summaries};
