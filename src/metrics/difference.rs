//! The signed differences every per-pixel metric starts from.

/// candidate − exact per pixel, a NaN error counted as infinite; empty when
/// either is missing or they differ in length.
pub(crate) fn signed_differences(exact: Option<&[f64]>, candidate: Option<&[f64]>) -> Vec<f64> {
    match (exact, candidate) {
        (Some(exact), Some(candidate)) if exact.len() == candidate.len() => exact
            .iter()
            .zip(candidate)
            .map(|(e, c)| {
                let error = c - e;
                if error.is_nan() {
                    f64::INFINITY
                } else {
                    error
                }
            })
            .collect(),
        _ => Vec::new(),
    }
}
