//! Finding a Vulkan device and creating it: the loader, the instance, the
//! physical device (`RASTERCHECK_VULKAN_DEVICE`, or the first GPU, or the
//! first device), what it offers for rasterization, and the logical
//! device with the features this adapter uses; the instance's messenger
//! keeps its API record (`messenger.rs`).

use std::ffi::CStr;

use ash::vk;

use super::conservative::ConservativeOffers;
use super::messenger::{self, Listening, Messenger, Record};
use crate::adapters::gpu;
use crate::rasterizer::ApiRecord;
use crate::scene::{DepthFormat, InterpolateFrom, LineParameter};

/// What the device offers that decides what it can draw.
#[derive(Clone)]
pub(super) struct Offers {
    /// `subPixelPrecisionBits`: the grid vertices snap to.
    pub subpixel_bits: u32,
    /// `maxFramebufferWidth` and height, the smaller, and `maxImageDimension2D`.
    pub max_side: u32,
    /// VK_EXT_line_rasterization's (or VK_KHR's) modes, when enabled.
    pub bresenham_lines: bool,
    pub rectangular_lines: bool,
    /// `strictLines`: whether DEFAULT lines are rectangles rather than
    /// parallelograms.
    pub strict_lines: bool,
    pub wide_lines: bool,
    pub line_width_range: [f32; 2],
    pub line_width_granularity: f32,
    /// `largePoints` (enabled), `pointSizeRange`, `pointSizeGranularity`:
    /// the point sizes the device draws (1 only without large points).
    pub large_points: bool,
    pub point_size_range: [f32; 2],
    pub point_size_granularity: f32,
    /// A depth-stencil format with stencil that can be an attachment.
    pub stencil_format: vk::Format,
    /// Sample counts a float colour target can be drawn with and then
    /// sampled (for the per-sample read-back), with a stencil beside it.
    pub msaa_counts: vk::SampleCountFlags,
    /// `standardSampleLocations`: multisampled targets sample at the
    /// standard locations, sample index i at location i.
    pub standard_locations: bool,
    /// `sampleRateShading`: depth and attributes interpolated at each
    /// sample of a multisampled target.
    pub sample_rate_shading: bool,
    /// VK_EXT_provoking_vertex's `provokingVertexLast`, enabled: flat
    /// values may come from the last vertex.
    pub provoking_last: bool,
    /// `depthClamp` with VK_EXT_depth_clip_enable's `depthClipEnable`,
    /// both enabled: depth clamped and not clipped (SPEC.md §16.2).
    pub depth_clamp: bool,
    /// The depth formats of SPEC.md §18 the device can attach and copy
    /// out (`D16_UNORM`, `X8_D24_UNORM_PACK32`, `D32_SFLOAT`), as
    /// `[unorm16, unorm24, float32]`.
    pub depth_formats: [bool; 3],
    /// Those the device can also sample in a shader (`SAMPLED_IMAGE`), for
    /// the per-sample read-back of a multisampled depth attachment.
    pub depth_sampled: [bool; 3],
    /// Sample counts a depth attachment can be drawn with and then sampled
    /// (`framebufferDepthSampleCounts` and `sampledImageDepthSampleCounts`).
    pub depth_msaa_counts: vk::SampleCountFlags,
    /// `depthBiasClamp`, enabled: a polygon offset may be clamped.
    pub depth_bias_clamp: bool,
    /// `independentBlend` (enabled): the coverage count blends additively
    /// while the value attachments beside it are written as they come, so
    /// a pipeline with value attachments needs it (VUID-VkPipelineColorBlendStateCreateInfo-pAttachments-00605).
    pub independent_blend: bool,
    /// `viewportBoundsRange` and `maxViewportDimensions`.
    pub viewport_bounds: [f32; 2],
    pub max_viewport: [u32; 2],
    /// The positions the driver sets its depth and attribute planes up
    /// from (SPEC.md §16.5, §16.10), known per driver
    /// ([`interpolate_from`]).
    pub interpolate_from: InterpolateFrom,
    /// Where the driver takes a Bresenham or DEFAULT line's t (SPEC.md
    /// §5.1), known per driver ([`line_parameter`]).
    pub line_parameter: LineParameter,
    /// VK_EXT_conservative_rasterization's properties, where the device
    /// lists the extension (it is then enabled); `None` where it does not.
    pub conservative: Option<ConservativeOffers>,
}

/// The positions a driver interpolates from, by its `driverID`:
/// SwiftShader sets its planes up from the snapped vertices (its
/// `SetupRoutine` builds them from the fixed-point positions, measured:
/// `tests/vulkan.rs`); Mesa's lavapipe, and any other driver, from the
/// divided, unsnapped ones (measured on lavapipe). A driver that departs
/// from its declaration is judged under it and shows it.
pub(super) fn interpolate_from(driver: vk::DriverId) -> InterpolateFrom {
    match driver {
        vk::DriverId::GOOGLE_SWIFTSHADER => InterpolateFrom::Snapped,
        _ => InterpolateFrom::Unsnapped,
    }
}

/// Where a driver takes the t of its Bresenham (and DEFAULT) lines, by its
/// `driverID` (SPEC.md §5.1): SwiftShader projects the fragment centre
/// onto the segment, the spec's formula (measured on
/// `lines/diamond_colour_interpolation` line by line: 2.6e-7 restated
/// `projected`, 5.7e-2 as stated `major`); Mesa's lavapipe, and any
/// driver not known otherwise, along the major axis (1.1e-7 stated
/// `major`, 2.1e-2 restated `projected`), as Vulkan's non-strict lines
/// interpolate ("as if the parallelogram was decomposed into two
/// triangles where each pair of vertices at each end of the line has
/// identical attributes") and as VK-GL-CTS accepts for Bresenham lines
/// (`LINEINTERPOLATION_PROJECTED`, a quality warning, not a failure). A
/// driver that departs from its declaration is judged under it and
/// shows it.
pub(super) fn line_parameter(driver: vk::DriverId) -> LineParameter {
    match driver {
        vk::DriverId::GOOGLE_SWIFTSHADER => LineParameter::Projected,
        _ => LineParameter::Major,
    }
}

/// The attachment formats of `unorm16`, `unorm24` and `float32`.
pub(super) const DEPTH_FORMATS: [vk::Format; 3] = [
    vk::Format::D16_UNORM,
    vk::Format::X8_D24_UNORM_PACK32,
    vk::Format::D32_SFLOAT,
];

/// The attachment format of a depth format of SPEC.md §18, and its index
/// in [`DEPTH_FORMATS`] and `Offers::depth_formats`; `None` for `exact`.
pub(super) fn depth_attachment(format: DepthFormat) -> Option<(vk::Format, usize)> {
    let i = match format {
        DepthFormat::Unorm16 => 0,
        DepthFormat::Unorm24 => 1,
        DepthFormat::Float32 => 2,
        DepthFormat::Exact => return None,
    };
    Some((DEPTH_FORMATS[i], i))
}

/// The device this adapter draws with, created once.
pub(super) struct Device {
    /// Keeps the loader loaded while the device lives.
    _entry: ash::Entry,
    pub instance: ash::Instance,
    /// The debug-utils messenger, where the instance offers one; destroyed
    /// before the instance.
    messenger: Option<Messenger>,
    /// What it (and the instance's own creation) heard; outlives both.
    record: Record,
    physical: vk::PhysicalDevice,
    pub device: ash::Device,
    pub queue: vk::Queue,
    pub family: u32,
    pub memory: vk::PhysicalDeviceMemoryProperties,
    /// "NAME (DRIVER DRIVER_INFO, Vulkan X.Y.Z)".
    pub description: String,
    pub offers: Offers,
}

/// What to install when no loader or driver is found.
pub(super) const INSTALL_HINT: &str =
    "install libvulkan1 and a driver (Debian: mesa-vulkan-drivers for lavapipe)";

impl Device {
    /// The device, with the Khronos validation layer enabled where this
    /// process asks for it (`messenger::asked`) or `validate` insists.
    pub(super) fn new(validate: bool, wanted: Option<&str>) -> Result<Device, String> {
        gpu::quiet_mesa();
        // SAFETY: loading libvulkan runs its initialisers, as any Vulkan
        // program does.
        let entry = unsafe { ash::Entry::load() }
            .map_err(|e| format!("no Vulkan loader ({e}): {INSTALL_HINT}"))?;
        let listening = Listening::plan(&entry, validate || messenger::asked())?;
        let record = Record::new(&listening);
        let mut hear_creation = record.create_info();
        let app = vk::ApplicationInfo::default()
            .application_name(c"rastercheck")
            .api_version(vk::API_VERSION_1_2);
        let mut info = vk::InstanceCreateInfo::default()
            .application_info(&app)
            .enabled_layer_names(&listening.layers)
            .enabled_extension_names(&listening.extensions);
        if listening.hears() {
            info = info.push_next(&mut hear_creation);
        }
        // SAFETY: a valid create info; the instance is destroyed in Drop.
        let instance = unsafe { entry.create_instance(&info, None) }
            .map_err(|e| format!("creating a Vulkan instance: {e}: {INSTALL_HINT}"))?;
        // SAFETY: the instance enables VK_EXT_debug_utils where it hears.
        // The record's box moves into the device, which destroys the
        // messenger and then the instance before it lets the record go;
        // on failure the record is let go here, after both.
        let messenger = unsafe {
            match listening.hears() {
                true => Messenger::new(&entry, &instance, &record).map(Some),
                false => Ok(None),
            }
        };
        let made = messenger.and_then(|messenger| {
            // SAFETY: a valid instance; the messenger is destroyed with it.
            match unsafe { Self::on(entry.clone(), instance.clone(), wanted) } {
                Ok(device) => Ok((device, messenger)),
                Err(e) => {
                    if let Some(m) = &messenger {
                        unsafe { m.destroy() };
                    }
                    Err(e)
                }
            }
        });
        match made {
            Ok((mut device, messenger)) => {
                device.messenger = messenger;
                device.record = record;
                Ok(device)
            }
            Err(e) => {
                // SAFETY: nothing made from the instance outlives this.
                unsafe { instance.destroy_instance(None) };
                Err(e)
            }
        }
    }

    /// What the messenger heard so far.
    pub(super) fn api_record(&self) -> ApiRecord {
        self.record.get()
    }

    /// The device on `instance`, without its messenger and record (`new`
    /// gives it them).
    unsafe fn on(
        entry: ash::Entry,
        instance: ash::Instance,
        wanted: Option<&str>,
    ) -> Result<Device, String> {
        let physical = choose(&instance, wanted)?;
        let properties = instance.get_physical_device_properties(physical);
        let name = properties
            .device_name_as_c_str()
            .map(|c| c.to_string_lossy().into_owned())
            .unwrap_or_default();
        let extensions: Vec<String> = instance
            .enumerate_device_extension_properties(physical)
            .map_err(|e| format!("{name}: listing extensions: {e}"))?
            .iter()
            .filter_map(|e| e.extension_name_as_c_str().ok())
            .map(|c| c.to_string_lossy().into_owned())
            .collect();
        let has = |ext: &CStr| extensions.iter().any(|e| e.as_bytes() == ext.to_bytes());
        let line_ext = [
            ash::khr::line_rasterization::NAME,
            ash::ext::line_rasterization::NAME,
        ]
        .into_iter()
        .find(|e| has(e));

        let conservative_ext = has(ash::ext::conservative_rasterization::NAME);
        let mut driver = vk::PhysicalDeviceDriverProperties::default();
        let mut conservative_properties =
            vk::PhysicalDeviceConservativeRasterizationPropertiesEXT::default();
        let mut properties2 = vk::PhysicalDeviceProperties2::default().push_next(&mut driver);
        if conservative_ext {
            properties2 = properties2.push_next(&mut conservative_properties);
        }
        instance.get_physical_device_properties2(physical, &mut properties2);
        let conservative =
            conservative_ext.then(|| ConservativeOffers::of(&conservative_properties));
        let c_text = |r: Result<&CStr, _>| r.map(|c: &CStr| c.to_string_lossy().into_owned());
        let driver_name = c_text(driver.driver_name_as_c_str()).unwrap_or_default();
        let driver_info = c_text(driver.driver_info_as_c_str()).unwrap_or_default();
        let v = properties.api_version;
        let description = format!(
            "{name} ({driver_name} {driver_info}, Vulkan {}.{}.{})",
            vk::api_version_major(v),
            vk::api_version_minor(v),
            vk::api_version_patch(v)
        );

        let provoking_ext = has(ash::ext::provoking_vertex::NAME);
        let depth_clip_ext = has(ash::ext::depth_clip_enable::NAME);
        let mut lines = vk::PhysicalDeviceLineRasterizationFeaturesKHR::default();
        let mut provoking = vk::PhysicalDeviceProvokingVertexFeaturesEXT::default();
        let mut depth_clip = vk::PhysicalDeviceDepthClipEnableFeaturesEXT::default();
        let mut features2 = vk::PhysicalDeviceFeatures2::default();
        if line_ext.is_some() {
            features2 = features2.push_next(&mut lines);
        }
        if provoking_ext {
            features2 = features2.push_next(&mut provoking);
        }
        if depth_clip_ext {
            features2 = features2.push_next(&mut depth_clip);
        }
        instance.get_physical_device_features2(physical, &mut features2);
        let base = features2.features;
        let provoking_last = provoking_ext && provoking.provoking_vertex_last == vk::TRUE;
        let depth_clamp = base.depth_clamp == vk::TRUE
            && depth_clip_ext
            && depth_clip.depth_clip_enable == vk::TRUE;
        let wide_lines = base.wide_lines == vk::TRUE;
        let large_points = base.large_points == vk::TRUE;
        let sample_rate_shading = base.sample_rate_shading == vk::TRUE;
        let depth_bias_clamp = base.depth_bias_clamp == vk::TRUE;
        let independent_blend = base.independent_blend == vk::TRUE;
        let (bresenham, rectangular) = (lines.bresenham_lines, lines.rectangular_lines);

        let family = instance
            .get_physical_device_queue_family_properties(physical)
            .iter()
            .position(|f| f.queue_flags.contains(vk::QueueFlags::GRAPHICS))
            .ok_or_else(|| format!("{name}: no graphics queue"))? as u32;
        let priorities = [1.0];
        let queues = [vk::DeviceQueueCreateInfo::default()
            .queue_family_index(family)
            .queue_priorities(&priorities)];
        let enabled = vk::PhysicalDeviceFeatures::default()
            .wide_lines(wide_lines)
            .large_points(large_points)
            .sample_rate_shading(sample_rate_shading)
            .depth_clamp(depth_clamp)
            .depth_bias_clamp(depth_bias_clamp)
            .independent_blend(independent_blend);
        let mut enable_lines = vk::PhysicalDeviceLineRasterizationFeaturesKHR::default()
            .bresenham_lines(bresenham == vk::TRUE)
            .rectangular_lines(rectangular == vk::TRUE);
        let mut enable_provoking =
            vk::PhysicalDeviceProvokingVertexFeaturesEXT::default().provoking_vertex_last(true);
        let mut enable_depth_clip =
            vk::PhysicalDeviceDepthClipEnableFeaturesEXT::default().depth_clip_enable(true);
        let mut names: Vec<*const std::ffi::c_char> = line_ext.iter().map(|e| e.as_ptr()).collect();
        if provoking_last {
            names.push(ash::ext::provoking_vertex::NAME.as_ptr());
        }
        if depth_clamp {
            names.push(ash::ext::depth_clip_enable::NAME.as_ptr());
        }
        if conservative.is_some() {
            names.push(ash::ext::conservative_rasterization::NAME.as_ptr());
        }
        let mut info = vk::DeviceCreateInfo::default()
            .queue_create_infos(&queues)
            .enabled_features(&enabled)
            .enabled_extension_names(&names);
        if line_ext.is_some() {
            info = info.push_next(&mut enable_lines);
        }
        if provoking_last {
            info = info.push_next(&mut enable_provoking);
        }
        if depth_clamp {
            info = info.push_next(&mut enable_depth_clip);
        }
        let device = instance
            .create_device(physical, &info, None)
            .map_err(|e| format!("{name}: creating the device: {e}"))?;
        let queue = device.get_device_queue(family, 0);
        let memory = instance.get_physical_device_memory_properties(physical);

        let limits = properties.limits;
        let stencil_format = [
            vk::Format::S8_UINT,
            vk::Format::D24_UNORM_S8_UINT,
            vk::Format::D32_SFLOAT_S8_UINT,
        ]
        .into_iter()
        .find(|&f| {
            instance
                .get_physical_device_format_properties(physical, f)
                .optimal_tiling_features
                .contains(vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT)
        })
        .unwrap_or(vk::Format::UNDEFINED);
        let depth_features = |needs: vk::FormatFeatureFlags| {
            DEPTH_FORMATS.map(|f| {
                instance
                    .get_physical_device_format_properties(physical, f)
                    .optimal_tiling_features
                    .contains(vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT | needs)
            })
        };
        let depth_formats = depth_features(vk::FormatFeatureFlags::TRANSFER_SRC);
        let depth_sampled = depth_features(vk::FormatFeatureFlags::SAMPLED_IMAGE);
        let offers = Offers {
            subpixel_bits: limits.sub_pixel_precision_bits,
            max_side: limits
                .max_framebuffer_width
                .min(limits.max_framebuffer_height)
                .min(limits.max_image_dimension2_d),
            bresenham_lines: bresenham == vk::TRUE,
            rectangular_lines: rectangular == vk::TRUE,
            strict_lines: limits.strict_lines == vk::TRUE,
            wide_lines,
            line_width_range: limits.line_width_range,
            line_width_granularity: limits.line_width_granularity,
            large_points,
            point_size_range: limits.point_size_range,
            point_size_granularity: limits.point_size_granularity,
            stencil_format,
            msaa_counts: limits.framebuffer_color_sample_counts
                & limits.sampled_image_color_sample_counts
                & limits.framebuffer_stencil_sample_counts,
            standard_locations: limits.standard_sample_locations == vk::TRUE,
            sample_rate_shading,
            provoking_last,
            depth_clamp,
            depth_formats,
            depth_sampled,
            depth_msaa_counts: limits.framebuffer_depth_sample_counts
                & limits.sampled_image_depth_sample_counts,
            depth_bias_clamp,
            independent_blend,
            viewport_bounds: limits.viewport_bounds_range,
            max_viewport: limits.max_viewport_dimensions,
            interpolate_from: interpolate_from(driver.driver_id),
            line_parameter: line_parameter(driver.driver_id),
            conservative: conservative.map(|c| c.on_grid(limits.sub_pixel_precision_bits)),
        };
        Ok(Device {
            _entry: entry,
            instance,
            messenger: None,
            record: Record::default(),
            physical,
            device,
            queue,
            family,
            memory,
            description,
            offers,
        })
    }

    /// A memory type index that `bits` allows and that has `flags`.
    pub(super) fn memory_type(&self, bits: u32, flags: vk::MemoryPropertyFlags) -> Option<u32> {
        (0..self.memory.memory_type_count).find(|&i| {
            bits & (1 << i) != 0
                && self.memory.memory_types[i as usize]
                    .property_flags
                    .contains(flags)
        })
    }

    /// Whether `format` can be a colour attachment that blends.
    pub(super) fn blends(&self, format: vk::Format) -> bool {
        // SAFETY: a valid physical device.
        unsafe {
            self.instance
                .get_physical_device_format_properties(self.physical, format)
        }
        .optimal_tiling_features
        .contains(vk::FormatFeatureFlags::COLOR_ATTACHMENT_BLEND)
    }
}

impl Drop for Device {
    fn drop(&mut self) {
        // SAFETY: the device is idle once waited for; nothing made from it
        // outlives it (the pipelines are destroyed by their owner first).
        unsafe {
            let _ = self.device.device_wait_idle();
            self.device.destroy_device(None);
            if let Some(m) = &self.messenger {
                m.destroy();
            }
            self.instance.destroy_instance(None);
        }
    }
}

/// The physical device: the one whose name contains `wanted` (the
/// `DEVICE` of `-r vulkan@DEVICE`), else `RASTERCHECK_VULKAN_DEVICE`
/// (either case-insensitive), else the first that is not a CPU, else the
/// first.
unsafe fn choose(
    instance: &ash::Instance,
    wanted: Option<&str>,
) -> Result<vk::PhysicalDevice, String> {
    let devices = instance
        .enumerate_physical_devices()
        .map_err(|e| format!("listing Vulkan devices: {e}"))?;
    let named: Vec<(vk::PhysicalDevice, String, vk::PhysicalDeviceType)> = devices
        .iter()
        .map(|&d| {
            let p = instance.get_physical_device_properties(d);
            let name = p
                .device_name_as_c_str()
                .map(|c| c.to_string_lossy().into_owned())
                .unwrap_or_default();
            (d, name, p.device_type)
        })
        .collect();
    let asked = match wanted {
        Some(w) => Some((w.to_owned(), format!("-r vulkan@{w}"))),
        None => std::env::var("RASTERCHECK_VULKAN_DEVICE")
            .ok()
            .map(|w| (w.clone(), format!("RASTERCHECK_VULKAN_DEVICE={w}"))),
    };
    if let Some((wanted, said)) = asked {
        let lower = wanted.to_lowercase();
        return named
            .iter()
            .find(|(_, name, _)| name.to_lowercase().contains(&lower))
            .map(|(d, _, _)| *d)
            .ok_or_else(|| {
                let all: Vec<&str> = named.iter().map(|(_, n, _)| n.as_str()).collect();
                format!(
                    "{said} names none of the devices {all:?} (a driver outside the \
                     loader's search path is added with VK_ADD_DRIVER_FILES=ICD.json)"
                )
            });
    }
    named
        .iter()
        .find(|(_, _, kind)| *kind != vk::PhysicalDeviceType::CPU)
        .or(named.first())
        .map(|(d, _, _)| *d)
        .ok_or_else(|| format!("no Vulkan device: {INSTALL_HINT}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// SwiftShader is declared to interpolate from the snapped positions,
    /// Mesa's lavapipe (and any driver not known otherwise) from the
    /// unsnapped ones; `tests/vulkan.rs` checks each declaration against
    /// the driver's frames (`clip_space_values_come_from_the_declared_positions`).
    #[test]
    fn each_driver_declares_its_own_positions() {
        assert_eq!(
            interpolate_from(vk::DriverId::GOOGLE_SWIFTSHADER),
            InterpolateFrom::Snapped
        );
        assert_eq!(
            interpolate_from(vk::DriverId::MESA_LLVMPIPE),
            InterpolateFrom::Unsnapped
        );
    }

    /// SwiftShader projects a Bresenham line's t onto the segment,
    /// lavapipe takes it along the major axis (SPEC.md §5.1; measured on
    /// `lines/diamond_colour_interpolation`, `tests/line_conventions.rs`).
    #[test]
    fn each_driver_declares_its_own_line_parameter() {
        assert_eq!(
            line_parameter(vk::DriverId::GOOGLE_SWIFTSHADER),
            LineParameter::Projected
        );
        assert_eq!(
            line_parameter(vk::DriverId::MESA_LLVMPIPE),
            LineParameter::Major
        );
    }
}
