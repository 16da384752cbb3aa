//! The exact values at a covered sample of a clip-space triangle or a
//! point: depth, the depth interval an offset allows (SPEC.md §18),
//! attributes.

use dashu_ratio::RBig;

/// The exact depth and attributes at a covered sample.
#[derive(Clone, Debug)]
pub struct Values {
    /// z_f: z_ndc through the viewport's depth range (clamped under
    /// `depth: clamp`).
    pub depth: RBig,
    /// The depth before the format (SPEC.md §18): z_f plus the piece's
    /// offset interval under `depth_bias`, then clamped under `depth:
    /// clamp`; [depth, depth] without an offset.
    pub depth_interval: [RBig; 2],
    pub attributes: Vec<RBig>,
}
