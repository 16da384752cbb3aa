//! Watertightness of a mesh: no hole inside it, no sample covered twice.

use super::ties::forgiven;
use crate::frame::Frame;
use crate::reference::TieSet;

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WatertightMetrics {
    /// Samples in the mesh's interior (see `reference::mesh_interior`).
    pub interior: u64,
    /// Interior samples the candidate leaves uncovered.
    pub holes: u64,
    /// Samples the candidate covers more than once where the reference
    /// covers them at most once.
    pub overdraw: u64,
}

impl WatertightMetrics {
    pub fn is_watertight(&self) -> bool {
        self.holes == 0 && self.overdraw == 0
    }
}

/// `None` when the candidate has no mask, or the interior does not have
/// one entry per sample of both frames.
pub fn measure(
    interior: &[bool],
    reference: &Frame,
    candidate: &Frame,
) -> Option<WatertightMetrics> {
    measure_off_ties(interior, reference, candidate, None)
}

/// [`measure`], for a candidate with no tie rule: the holes and overdraw
/// a choice of sides gives at a tie sample are counted with the ties
/// (`ties.rs`), not here.
pub fn measure_off_ties(
    interior: &[bool],
    reference: &Frame,
    candidate: &Frame,
    ties: Option<&TieSet>,
) -> Option<WatertightMetrics> {
    if candidate.samples == 0
        || interior.len() != candidate.sample_count()
        || interior.len() != reference.sample_count()
    {
        return None;
    }
    let mut m = WatertightMetrics {
        interior: 0,
        holes: 0,
        overdraw: 0,
    };
    for (i, &inside) in interior.iter().enumerate() {
        let c = candidate.coverage[i];
        m.interior += u64::from(inside);
        if forgiven(ties, candidate, i) {
            continue;
        }
        m.holes += u64::from(inside && c == 0);
        m.overdraw += u64::from(c > 1 && reference.coverage[i] <= 1);
    }
    Some(m)
}
