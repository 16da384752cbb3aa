//! How many results get pictures and pages over a run, at most.

/// Results that get PNG pictures, at most, over a run.
pub const MAX_PICTURED: usize = 200;

/// Case pages for failures, errors and problems, at most, over a run.
pub const MAX_PROBLEM_PAGES: usize = 1000;

/// Case pages for a foil's departures and passes with some error, at most,
/// over a run. Which cases get one is decided as cases finish, so past
/// this many the choice depends on the order threads finish in: it is
/// kept well above the bundled cases' 424 (every one of which may have
/// a pass with some error) so that their report does not.
pub const MAX_PAGES: usize = 1000;

/// The first cases of a run the summary files (`summary.md`, the plots,
/// `index.html`) are drawn from whole (`digest.rs`).
pub const LISTED: usize = 2000;

/// Further cases worth a look (a failure, an error, a departure, some
/// error) the summary files are drawn from whole, at most.
pub const LOOKED: usize = 2000;
