//! The device and its kept pipelines, made once per process on first use
//! and shared by every case, one case at a time: one per device asked for
//! (`-r vulkan` takes the default device, `-r vulkan@DEVICE` the one named).

use std::sync::{Mutex, MutexGuard};

use super::device::Device;
use super::pipelines::{self, Pipelines};
use super::unpack::Unpack;

/// The default device's description, or why there is none. Creates the
/// shared device on first use.
pub fn device_description() -> Result<String, String> {
    device_description_of(None)
}

/// The description of the device whose name contains `wanted` (the
/// default device for `None`), or why there is none.
pub fn device_description_of(wanted: Option<&str>) -> Result<String, String> {
    Ok(lock(shared(wanted)?).device.description.clone())
}

/// The device and its kept pipelines, made once and shared by every case.
pub(super) struct Shared {
    // Dropped in this order: the pipelines before their device.
    pub(super) pipelines: Pipelines,
    pub(super) unpack: Unpack,
    pub(super) device: Device,
}

/// What was made for one device asked for: it, or why not.
type Made = Result<Mutex<Shared>, String>;

/// The shared device whose name contains `wanted` (the default device for
/// `None`), made on first use and kept for the process.
pub(super) fn shared(wanted: Option<&str>) -> Result<&'static Mutex<Shared>, &'static String> {
    static MADE: Mutex<Vec<(Option<String>, &'static Made)>> = Mutex::new(Vec::new());
    let mut made = MADE.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    if let Some((_, kept)) = made.iter().find(|(w, _)| w.as_deref() == wanted) {
        return kept.as_ref();
    }
    // Kept for the process, as a static would be: a handful at most.
    let kept: &'static Made = Box::leak(Box::new(make(wanted)));
    made.push((wanted.map(str::to_owned), kept));
    kept.as_ref()
}

fn make(wanted: Option<&str>) -> Made {
    let device = Device::new(false, wanted)?;
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
}

/// The shared device, for one case at a time; a case that panicked
/// holding it leaves it usable.
pub(super) fn lock(shared: &'static Mutex<Shared>) -> MutexGuard<'static, Shared> {
    shared
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}
