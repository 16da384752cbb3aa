//! The targets by the names of their files in `fuzz/fuzz_targets/`, and
//! running one by name.

use super::arithmetic::exact_arithmetic;
use super::case_file::case_json;
use super::response::protocol_response;
use super::scene::scene_reference_vs_production;

/// The targets, by the names of their files in `fuzz/fuzz_targets/`.
pub const TARGETS: [&str; 4] = [
    "case_json",
    "scene_reference_vs_production",
    "protocol_response",
    "exact_arithmetic",
];

/// Runs target `name` on `data`; `false` for an unknown name.
pub fn run(name: &str, data: &[u8]) -> bool {
    match name {
        "case_json" => case_json(data),
        "scene_reference_vs_production" => scene_reference_vs_production(data),
        "protocol_response" => protocol_response(data),
        "exact_arithmetic" => exact_arithmetic(data),
        _ => return false,
    }
    true
}
