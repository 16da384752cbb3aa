//! What the probes found, piece by piece, as the profile records it: the
//! fill-rule evidence per mesh, interpolation per channel, the bits
//! resolved per axis, and the rules a tie sample is explained by.

use serde::Serialize;

/// The subpixel bits the probe scenes state: the most a case can.
pub const PROBE_BITS: u32 = 16;

#[derive(Clone, Debug, Serialize)]
pub struct Resolved {
    pub x: Option<u32>,
    pub y: Option<u32>,
}

#[derive(Clone, Debug, Serialize)]
pub struct MeshEvidence {
    pub mesh: String,
    /// The slope (dy/dx, y down) of its shared edge, for a tie mesh of
    /// one slope (`scenes::tie_slope_meshes`); only the samples on that
    /// edge are its tie samples.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub slope: Option<String>,
    pub tie_samples: usize,
    /// Tie samples each rule explains, in the order top-left, bottom-right,
    /// top-right, bottom-left, all-edges, none.
    pub explained: Vec<RuleCount>,
    /// Samples away from every edge that differ from the reference.
    pub off_edge_differences: usize,
    /// Why the rasterizer drew nothing, when it did not.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

/// A slope whose tie samples the nearest rule does not explain, and the
/// consistent rules that explain every one of them.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct SlopeRule {
    pub slope: String,
    pub follows: Vec<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct RuleCount {
    pub rule: String,
    pub samples: usize,
}

#[derive(Clone, Debug, Serialize)]
pub struct InterpolationProbe {
    pub case: String,
    /// `measured`, `unsupported` or `error`.
    pub status: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub why: Option<String>,
    pub channels: Vec<ChannelProbe>,
}

#[derive(Clone, Debug, Serialize)]
pub struct ChannelProbe {
    pub channel: String,
    pub max_abs: f64,
    pub max_ulp: f64,
    pub allowed_abs: f64,
    pub within_bound: bool,
}

/// The candidate rules: the five fill rules, then "none" (open edges).
pub const RULE_NAMES: [&str; 6] = [
    "top-left",
    "bottom-right",
    "top-right",
    "bottom-left",
    "all-edges",
    "none",
];
