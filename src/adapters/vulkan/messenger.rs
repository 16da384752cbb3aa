//! The API record of the Vulkan adapter: a `VK_EXT_debug_utils` messenger
//! on the instance that counts the error and warning messages (validation
//! and general) of the process's calls and keeps the first one's text
//! (SPEC.md §10, `api_record`; docs/drivers/vulkan.md "API record").
//!
//! The Khronos validation layer is on when the user turns it on through
//! the loader (`VK_INSTANCE_LAYERS`, `VK_LOADER_LAYERS_ENABLE`), or when
//! `RASTERCHECK_VULKAN_VALIDATION=1` (or [`ask_for_validation`]) asks
//! this adapter to enable it; asked and absent, the device is not made and
//! the error says why. Without the layer the messenger still counts what
//! the loader and the driver say, and the record says it was not
//! validated. Performance and informational messages are not counted, nor
//! the loader's own warnings about its set-up ([`counted`]).

use std::ffi::{c_char, c_void, CStr};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

use ash::vk;

use crate::rasterizer::ApiRecord;

/// The layer this adapter enables when asked.
pub(super) const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";

/// What to install when the layer is asked for and absent.
const LAYER_HINT: &str = "install vulkan-validationlayers (Debian)";

/// The longest first message kept, in characters.
const FIRST_CHARS: usize = 400;

static ASKED: AtomicBool = AtomicBool::new(false);

/// Asks this process's Vulkan device, when it is made (it is made once),
/// to enable the Khronos validation layer, as
/// `RASTERCHECK_VULKAN_VALIDATION=1` does; the driver tests ask. Says why
/// not where the layer is not installed (nothing is asked then).
pub fn ask_for_validation() -> Result<(), String> {
    // SAFETY: loading libvulkan runs its initialisers, as any Vulkan
    // program does.
    let entry = unsafe { ash::Entry::load() }.map_err(|e| format!("no Vulkan loader ({e})"))?;
    if !layer_present(&entry)? {
        return Err(format!(
            "the Khronos validation layer is not installed: {LAYER_HINT}"
        ));
    }
    ASKED.store(true, Ordering::SeqCst);
    Ok(())
}

/// Whether this process asks for the layer itself.
pub(super) fn asked() -> bool {
    ASKED.load(Ordering::SeqCst)
        || std::env::var("RASTERCHECK_VULKAN_VALIDATION").is_ok_and(|v| v == "1")
}

fn layer_present(entry: &ash::Entry) -> Result<bool, String> {
    // SAFETY: a loaded entry.
    let layers = unsafe { entry.enumerate_instance_layer_properties() }
        .map_err(|e| format!("listing Vulkan layers: {e}"))?;
    Ok(layers
        .iter()
        .any(|l| l.layer_name_as_c_str() == Ok(VALIDATION_LAYER)))
}

/// Whether the user turned the layer on through the loader's variables.
fn on_through_the_loader() -> bool {
    ["VK_INSTANCE_LAYERS", "VK_LOADER_LAYERS_ENABLE"]
        .iter()
        .any(|v| std::env::var(v).is_ok_and(|l| l.contains("validation")))
}

/// The instance's layers and extensions for the record, decided before
/// the instance is made.
pub(super) struct Listening {
    /// The layers to enable (the validation layer, where asked).
    pub layers: Vec<*const c_char>,
    /// `VK_EXT_debug_utils`, where offered.
    pub extensions: Vec<*const c_char>,
    /// Who validates the calls, for the record.
    validated_by: Option<String>,
}

impl Listening {
    /// `validate`: this process asks for the layer ([`asked`], or a
    /// caller that insists).
    pub(super) fn plan(entry: &ash::Entry, validate: bool) -> Result<Listening, String> {
        let mut layers = Vec::new();
        if validate {
            if !layer_present(entry)? {
                return Err(format!(
                    "RASTERCHECK_VULKAN_VALIDATION=1 asks for {}, which is not installed: {LAYER_HINT}",
                    VALIDATION_LAYER.to_string_lossy()
                ));
            }
            layers.push(VALIDATION_LAYER.as_ptr());
        }
        let mut offered = Vec::new();
        for layer in [None, validate.then_some(VALIDATION_LAYER)] {
            // SAFETY: a loaded entry; a layer it lists, or none.
            if let Ok(list) = unsafe { entry.enumerate_instance_extension_properties(layer) } {
                offered.extend(list);
            }
        }
        let debug_utils = offered
            .iter()
            .any(|e| e.extension_name_as_c_str() == Ok(ash::ext::debug_utils::NAME));
        let extensions = if debug_utils {
            vec![ash::ext::debug_utils::NAME.as_ptr()]
        } else {
            Vec::new()
        };
        let validated_by = (validate || on_through_the_loader()).then(|| {
            if debug_utils {
                "the Khronos validation layer".to_owned()
            } else {
                "the Khronos validation layer, unheard (no VK_EXT_debug_utils)".to_owned()
            }
        });
        Ok(Listening {
            layers,
            extensions,
            validated_by,
        })
    }

    /// Whether a messenger can be made on the instance.
    pub(super) fn hears(&self) -> bool {
        !self.extensions.is_empty()
    }
}

/// The counts the messenger keeps; boxed, so that the address the driver
/// calls back with stays put while the instance lives.
#[derive(Default)]
pub(super) struct Record(Box<Mutex<ApiRecord>>);

impl Record {
    pub(super) fn new(listening: &Listening) -> Record {
        Record(Box::new(Mutex::new(ApiRecord {
            validated_by: listening.validated_by.clone(),
            ..ApiRecord::default()
        })))
    }

    /// The create info of a messenger that counts into this record: for
    /// the instance's own creation and destruction (chained to its create
    /// info) and for the messenger made after it.
    pub(super) fn create_info(&self) -> vk::DebugUtilsMessengerCreateInfoEXT<'static> {
        vk::DebugUtilsMessengerCreateInfoEXT::default()
            .message_severity(
                vk::DebugUtilsMessageSeverityFlagsEXT::WARNING
                    | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR,
            )
            .message_type(
                vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                    | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION,
            )
            .pfn_user_callback(Some(on_message))
            .user_data(&*self.0 as *const Mutex<ApiRecord> as *mut c_void)
    }

    pub(super) fn get(&self) -> ApiRecord {
        self.0.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }
}

/// The messenger made on an instance; destroyed before it.
pub(super) struct Messenger {
    loader: ash::ext::debug_utils::Instance,
    handle: vk::DebugUtilsMessengerEXT,
}

impl Messenger {
    /// # Safety
    /// `instance` was made with `VK_EXT_debug_utils` enabled, and `record`
    /// outlives the messenger.
    pub(super) unsafe fn new(
        entry: &ash::Entry,
        instance: &ash::Instance,
        record: &Record,
    ) -> Result<Messenger, String> {
        let loader = ash::ext::debug_utils::Instance::new(entry, instance);
        let handle = loader
            .create_debug_utils_messenger(&record.create_info(), None)
            .map_err(|e| format!("creating a debug-utils messenger: {e}"))?;
        Ok(Messenger { loader, handle })
    }

    /// # Safety
    /// Before the instance is destroyed.
    pub(super) unsafe fn destroy(&self) {
        self.loader.destroy_debug_utils_messenger(self.handle, None);
    }
}

/// The loader's id for the messages it writes about itself.
const LOADER_MESSAGE: &str = "Loader Message";

/// Whether a message counts against the record: every error, and every
/// warning but the loader's general ones about its own set-up (which layers
/// an environment variable such as `VK_INSTANCE_LAYERS` added, a driver it
/// passed over), which say nothing of this process's calls. Without this,
/// turning the layer on the loader's usual way marked every verdict as
/// resting on undefined behaviour.
fn counted(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    types: vk::DebugUtilsMessageTypeFlagsEXT,
    id: Option<&str>,
) -> bool {
    severity.contains(vk::DebugUtilsMessageSeverityFlagsEXT::ERROR)
        || types.contains(vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION)
        || id != Some(LOADER_MESSAGE)
}

/// Counts one message into the record behind `user`; never asks the
/// driver to abort the call (the layer passes it on, and the record says
/// what followed).
unsafe extern "system" fn on_message(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    if user.is_null() {
        return vk::FALSE;
    }
    // SAFETY: the callback data and its strings are valid for the call.
    let text = |p: *const c_char| (!p.is_null()).then(|| CStr::from_ptr(p).to_string_lossy());
    let data = data.as_ref();
    let id = data.and_then(|d| text(d.p_message_id_name));
    if !counted(severity, types, id.as_deref()) {
        return vk::FALSE;
    }
    // SAFETY: `user` is the boxed record of `Record::create_info`, alive
    // while the instance is.
    let record = &*(user as *const Mutex<ApiRecord>);
    let mut record = record.lock().unwrap_or_else(|e| e.into_inner());
    if severity.contains(vk::DebugUtilsMessageSeverityFlagsEXT::ERROR) {
        record.errors += 1;
    } else {
        record.warnings += 1;
    }
    if record.first.is_none() {
        let message = data.and_then(|d| text(d.p_message));
        // The layer's text repeats the id and lists handles before its
        // last " | "; what follows is the rule broken.
        let message = message.map(|m| match m.rsplit_once(" | ") {
            Some((_, rule)) => rule.trim().to_owned(),
            None => m.trim().to_owned(),
        });
        let mut first = match (id, message) {
            (Some(id), Some(m)) => format!("{id}: {m}"),
            (Some(id), None) => id.into_owned(),
            (None, Some(m)) => m.trim().to_owned(),
            (None, None) => "(no text)".to_owned(),
        };
        if first.chars().count() > FIRST_CHARS {
            first = first.chars().take(FIRST_CHARS).collect::<String>() + "…";
        }
        record.first = Some(first);
    }
    vk::FALSE
}

#[cfg(test)]
mod tests {
    use super::*;

    use vk::DebugUtilsMessageSeverityFlagsEXT as Severity;
    use vk::DebugUtilsMessageTypeFlagsEXT as Type;

    /// The loader's warning that `VK_INSTANCE_LAYERS` added the layer is not
    /// counted; the same severity from the layer (a VUID), a general
    /// warning from anyone else, and any error are.
    #[test]
    fn only_the_loaders_own_warnings_are_passed_over() {
        assert!(!counted(
            Severity::WARNING,
            Type::GENERAL,
            Some(LOADER_MESSAGE)
        ));
        assert!(counted(
            Severity::ERROR,
            Type::GENERAL,
            Some(LOADER_MESSAGE)
        ));
        assert!(counted(
            Severity::WARNING,
            Type::VALIDATION,
            Some("VUID-VkPipelineColorBlendStateCreateInfo-pAttachments-00605")
        ));
        assert!(counted(
            Severity::WARNING,
            Type::GENERAL,
            Some("WARNING-something")
        ));
        assert!(counted(Severity::WARNING, Type::GENERAL, None));
        assert!(counted(
            Severity::WARNING,
            Type::GENERAL | Type::VALIDATION,
            Some(LOADER_MESSAGE)
        ));
    }
}
