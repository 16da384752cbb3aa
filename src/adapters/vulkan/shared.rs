//! The device and its kept pipelines, made once per process on first use
//! and shared by every case, one case at a time.

use std::sync::{Mutex, MutexGuard, OnceLock};

use super::device::Device;
use super::pipelines::{self, Pipelines};
use super::unpack::Unpack;

/// The device's description, or why there is none. Creates the shared
/// device on first use.
pub fn device_description() -> Result<String, String> {
    Ok(lock(shared()?).device.description.clone())
}

/// The device and its kept pipelines, made once and shared by every case.
pub(super) struct Shared {
    // Dropped in this order: the pipelines before their device.
    pub(super) pipelines: Pipelines,
    pub(super) unpack: Unpack,
    pub(super) device: Device,
}

pub(super) fn shared() -> Result<&'static Mutex<Shared>, &'static String> {
    static SHARED: OnceLock<Result<Mutex<Shared>, String>> = OnceLock::new();
    SHARED
        .get_or_init(|| {
            let device = Device::new(false)?;
            if !device.blends(pipelines::COUNT_FORMAT) {
                return Err(format!(
                    "{}: R32_SFLOAT does not blend, and the coverage count needs it",
                    device.description
                ));
            }
            let pipelines = Pipelines::new(&device)?;
            let unpack = Unpack::new(&device.device)?;
            Ok(Mutex::new(Shared {
                pipelines,
                unpack,
                device,
            }))
        })
        .as_ref()
}

/// The shared device, for one case at a time; a case that panicked
/// holding it leaves it usable.
pub(super) fn lock(shared: &'static Mutex<Shared>) -> MutexGuard<'static, Shared> {
    shared
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}
