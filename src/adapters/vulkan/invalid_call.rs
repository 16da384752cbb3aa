//! A deliberately invalid Vulkan call on a device of its own, with the
//! Khronos validation layer on, for the test that shows the API record
//! hears what the layer says (tests/vulkan.rs). The process's shared
//! device and its record are not touched.

use ash::vk;

use super::device::Device;
use crate::rasterizer::ApiRecord;

/// The VUID the invalid call breaks: a sampler with anisotropic filtering
/// on a device made without the `samplerAnisotropy` feature.
pub const INVALID_CALL_VUID: &str = "VUID-VkSamplerCreateInfo-anisotropyEnable-01070";

/// Makes a device of its own with the validation layer enabled (an error
/// where the layer is not installed), creates one sampler with
/// `anisotropyEnable` while the device was made without
/// `samplerAnisotropy` ([`INVALID_CALL_VUID`]; the layer passes the call
/// on, and every driver here draws anisotropically anyway), destroys it
/// and the device, and returns what that device's messenger heard.
pub fn invalid_call_record() -> Result<ApiRecord, String> {
    let device = Device::new(true, None)?;
    let info = vk::SamplerCreateInfo::default()
        .anisotropy_enable(true)
        .max_anisotropy(4.0)
        .max_lod(0.25);
    // SAFETY: a valid device; the sampler is destroyed before it. The
    // create info breaks a rule of valid usage on purpose, which the
    // layer reports before it passes the call on.
    unsafe {
        let sampler = device
            .device
            .create_sampler(&info, None)
            .map_err(|e| format!("creating the invalid sampler: {e}"))?;
        device.device.destroy_sampler(sampler, None);
    }
    Ok(device.api_record())
}
