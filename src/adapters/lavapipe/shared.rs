//! The wgpu device lavapipe draws on, made once per process on first use
//! and shared by every case, one case at a time; what it reports of itself.

use std::sync::{Mutex, MutexGuard, OnceLock};

use super::device::Gpu;

/// The multisampled formats this adapter draws 4× MSAA into, as
/// "count FORMAT, values FORMAT", or why it cannot.
pub fn msaa_formats() -> Result<String, String> {
    let gpu = lock(gpu()?);
    Ok(format!(
        "count {:?}, values {:?}",
        gpu.msaa.count, gpu.msaa.values
    ))
}

/// The adapter wgpu found, as "name (driver, driver info)", or why none was
/// found. Creates the shared device on first use.
pub fn adapter_description() -> Result<String, String> {
    Ok(lock(gpu()?).description.clone())
}

pub(super) fn gpu() -> Result<&'static Mutex<Gpu>, &'static String> {
    static GPU: OnceLock<Result<Mutex<Gpu>, String>> = OnceLock::new();
    GPU.get_or_init(|| Gpu::new().map(Mutex::new)).as_ref()
}

/// The shared device, for one case (or one phase of a prepared scene) at a
/// time; a case that panicked holding it leaves it usable.
pub(super) fn lock(gpu: &'static Mutex<Gpu>) -> MutexGuard<'static, Gpu> {
    gpu.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
}
