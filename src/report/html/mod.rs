//! The HTML pages: `index.html`, light and built from the report alone,
//! and one page per case worth a look (`pages/<id>.html`), written while
//! the case's frames are in memory (`report::case_files`) and opened only
//! when wanted. Inline CSS, no network, no script but a few lines that
//! record on `<body>` what the browser test reads (pictures decoded, script
//! errors, load time).
//!
//! The index: a header with the command, the totals per rasterizer and the
//! golden files; a table of families × rasterizers; the failures first
//! (failures, errors, problems and a foil's departures, with their first
//! reason and a link to the card); then one section per family with a table
//! of cases × rasterizers, each result linking to its card.
//!
//! A case page holds the case's cards ([`cards_of`]), the most important
//! first:
//!
//! 1. failures and errors, unreadable cases, broken references, golden
//!    files that differ;
//! 2. a foil's departures;
//! 3. passing results with a nonzero interpolation error (their heat maps).
//!
//! A result card shows the reference, the candidate and the difference mask
//! (the PNGs `case_files` wrote, linked; colour key in `png.rs`), the
//! reasons, every metric, one heat map per interpolated channel
//! (|candidate − exact| per pixel on a viridis scale from 0 to the
//! channel's largest error), its files, and the case file. Links are
//! relative to the report folder, which the page's `<base>` names.
//!
//! An antialiased case's card shows its resolved coverage instead (drawn
//! from the frames, for passes too): the exact area and the candidate's
//! resolved value in grey, the signed error (red too much, blue too
//! little), and for a candidate whose samples differ every sample as a dot
//! coloured by how it differs (colour keys in `png.rs`). Passing antialiased results
//! with any coverage error get a card like passes with interpolation error.
//! With several samples per pixel a heat map shows each pixel's largest
//! error over its samples.
//!
//! A scene in which something moves (SPEC.md §15.4) is shown the same way
//! by its time coverage: the exact time coverage and the candidate's in
//! grey, and the signed error, with the time metrics (and the sample test
//! efficiency of a method that counts it). Passing results with any time
//! error get a card too.
//!
//! The pages are built in these rooms: `index.rs` (the index), `page.rs`
//! (a case's page), `shell.rs` (the head, style and script both share),
//! `cards.rs` (which results get a card, and the case and result cards),
//! `tables.rs` (table cells and metrics tables) and `pictures.rs` (coverage
//! pictures, heat maps, difference lists, PNG data URIs).

mod cards;
mod index;
mod page;
mod pictures;
mod shell;
mod tables;

pub use cards::{cards_of, relative_url, Card};
pub use index::render;
pub use page::{page, page_file};
pub use pictures::base64;
