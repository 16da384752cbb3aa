//! How a result's change of state is classed: each state's kind (good,
//! failing, unjudged), and the class of a move from one to another.

/// How a result's state counts: judged good, failing, or not judged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Good,
    Failing,
    Unjudged,
}

/// The kind of a state: a verdict, a case status, or a golden status.
pub fn kind(state: &str) -> Kind {
    match state {
        "pass" | "foil" | "match" => Kind::Good,
        "fail" | "flaky" | "error" | "unreadable" | "reference-failed" | "limit-exceeded"
        | "differ" | "missing" => Kind::Failing,
        // unsupported, not-run, absent
        _ => Kind::Unjudged,
    }
}

/// Where a changed result goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Class {
    /// Good or not judged before, failing now: a regression.
    NewlyFailing,
    /// Judged before (good or failing), not judged now: a regression
    /// (coverage lost).
    NoLongerJudged,
    /// Failing before, good now.
    Fixed,
    /// Failing before and now (the state may have changed).
    StillFailing,
    /// Any other change of state (not judged → good, pass ↔ foil,
    /// unsupported ↔ not-run): not a regression.
    Other,
}

impl Class {
    /// The class of a change of state; `None` when nothing changed.
    pub fn of(old: &str, new: &str) -> Option<Class> {
        use Kind::*;
        Some(match (kind(old), kind(new)) {
            (Good | Unjudged, Failing) => Class::NewlyFailing,
            (Failing, Good) => Class::Fixed,
            (Failing, Failing) => Class::StillFailing,
            (Good | Failing, Unjudged) => Class::NoLongerJudged,
            _ if old == new => return None,
            _ => Class::Other,
        })
    }
}
