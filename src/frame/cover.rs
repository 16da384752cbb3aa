//! Covering a run of samples at once: the hot loop of span filling.

/// Adds one cover to every count of a run and makes `last` (index + 1)
/// their last primitive: two passes the compiler vectorises, a saturating
/// add and a fill. Where the processor has AVX2 the same code runs
/// compiled for it, 32 bytes a store instead of SSE2's 16: filling spans
/// is bound by stores.
#[inline]
pub fn cover_run(coverage: &mut [u16], last: &mut [u32], last_index: u32) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has AVX2, as just checked (a cached flag).
        unsafe { cover_run_avx2(coverage, last, last_index) };
        return;
    }
    cover_run_portable(coverage, last, last_index);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn cover_run_avx2(coverage: &mut [u16], last: &mut [u32], last_index: u32) {
    cover_run_portable(coverage, last, last_index);
}

#[inline(always)]
fn cover_run_portable(coverage: &mut [u16], last: &mut [u32], last_index: u32) {
    for c in coverage.iter_mut() {
        *c = c.saturating_add(1);
    }
    last.fill(last_index);
}
