//! What the summary files keep of a run whose case entries are on disk
//! (`spool.rs`): the totals, the count per family and rasterizer, and a
//! bounded set of whole entries: the first [`LISTED`] cases, then the
//! cases worth a look (a failure, an error, a departure, a result with
//! some error: `html::cards_of`) up to [`LOOKED`] more. `summary.md`,
//! the plots and `index.html` are drawn from those entries, so a run of
//! any number of cases writes them in bounded memory; a run of at most
//! [`LISTED`] cases keeps every entry, and its files are what they would
//! be from the whole report. Where entries were left out, each file says
//! so and how many (`report.json` and `junit.xml` are written from every
//! entry).

use super::families::{count_family, FamilyCount};
use super::html::cards_of;
use super::json::{CaseEntry, RasterizerInfo, Totals};
use super::limits::{LISTED, LOOKED};

/// The bounded part of a run the summary files are drawn from.
#[derive(Debug)]
pub struct Digest {
    pub totals: Totals,
    pub families: Vec<FamilyCount>,
    /// The entries kept whole, in the run's order.
    pub cases: Vec<CaseEntry>,
    /// JUnit testcases: per case, one per result, or one when it has none.
    pub testcases: usize,
    rasterizers: usize,
    looked: usize,
}

impl Digest {
    pub fn new(rasterizers: &[RasterizerInfo]) -> Digest {
        Digest {
            totals: Totals::of(rasterizers),
            families: Vec::new(),
            cases: Vec::new(),
            testcases: 0,
            rasterizers: rasterizers.len(),
            looked: 0,
        }
    }

    /// Counts the next case, and keeps it whole if it is among the first
    /// [`LISTED`] or worth a look and under [`LOOKED`].
    pub fn add(&mut self, case: &CaseEntry) {
        self.totals.add(case);
        self.testcases += case.results.len().max(1);
        count_family(&mut self.families, case, self.rasterizers);
        if self.totals.cases <= LISTED {
            self.cases.push(case.clone());
        } else if self.looked < LOOKED && !cards_of(case).is_empty() {
            self.looked += 1;
            self.cases.push(case.clone());
        }
    }

    /// How many cases were counted and not kept.
    pub fn left_out(&self) -> usize {
        self.totals.cases - self.cases.len()
    }
}
