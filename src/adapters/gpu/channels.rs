//! The channels a GPU API adapter writes per sample (primitive + 1, depth,
//! attributes), and the four-channel targets that carry them.

use crate::plan::Plan;

/// Attributes a vertex can carry through the pipelines.
pub(crate) const MAX_ATTRIBUTES: usize = 16;
/// Channels written per sample: primitive + 1, depth, and the attributes.
pub(crate) const CHANNELS: usize = 2 + MAX_ATTRIBUTES;
/// Four-channel targets needed for every channel.
pub(crate) const GROUPS: usize = CHANNELS.div_ceil(4);

/// Four-channel targets the plan needs.
pub(crate) fn groups(plan: &Plan) -> usize {
    let groups = if plan.interpolates() {
        (2 + plan.attributes).div_ceil(4)
    } else {
        1
    };
    debug_assert!(groups <= GROUPS);
    groups
}
