//! The API record of the GL adapter: a debug context (EGL 1.5's
//! `EGL_CONTEXT_OPENGL_DEBUG`) whose KHR_debug callback counts the
//! messages that say a call was invalid and keeps the first one's text
//! (SPEC.md §10, `api_record`; docs/drivers/gl.md "API record").
//!
//! Counted as errors: type `ERROR` (a GL error: the call did nothing) or
//! `UNDEFINED_BEHAVIOR`, and anything of `HIGH` severity; as warnings:
//! `DEPRECATED_BEHAVIOR` and `PORTABILITY` of `MEDIUM` severity. Mesa's
//! performance, shader-compiler and other notes are not counted.

use std::sync::{Arc, Mutex};

use glow::HasContext;
use khronos_egl as egl;

use crate::rasterizer::ApiRecord;

/// The longest first message kept, in characters.
const FIRST_CHARS: usize = 400;

/// The attributes that ask EGL for a debug context, before the list's
/// `NONE`.
pub(super) const DEBUG_CONTEXT: [egl::Int; 2] = [egl::CONTEXT_OPENGL_DEBUG, egl::TRUE as egl::Int];

/// The record a context's callback counts into.
pub(super) type Shared = Arc<Mutex<ApiRecord>>;

/// Installs the callback on the current context `gl`, synchronous (called
/// in the thread of the call that caused it), and returns the record it
/// counts into.
///
/// # Safety
/// `gl` is current on this thread.
pub(super) unsafe fn listen(gl: &mut glow::Context) -> Shared {
    let debug_context =
        gl.get_parameter_i32(glow::CONTEXT_FLAGS) as u32 & glow::CONTEXT_FLAG_DEBUG_BIT != 0;
    let record: Shared = Arc::new(Mutex::new(ApiRecord {
        validated_by: Some(if debug_context {
            "KHR_debug (a debug context)".to_owned()
        } else {
            "KHR_debug (not a debug context: the driver may say less)".to_owned()
        }),
        ..ApiRecord::default()
    }));
    gl.enable(glow::DEBUG_OUTPUT);
    gl.enable(glow::DEBUG_OUTPUT_SYNCHRONOUS);
    let heard = Arc::clone(&record);
    gl.debug_message_callback(move |_source, kind, id, severity, message| {
        count(&heard, kind, id, severity, message);
    });
    record
}

fn count(record: &Mutex<ApiRecord>, kind: u32, id: u32, severity: u32, message: &str) {
    let error = matches!(
        kind,
        glow::DEBUG_TYPE_ERROR | glow::DEBUG_TYPE_UNDEFINED_BEHAVIOR
    ) || severity == glow::DEBUG_SEVERITY_HIGH;
    let warning = matches!(
        kind,
        glow::DEBUG_TYPE_DEPRECATED_BEHAVIOR | glow::DEBUG_TYPE_PORTABILITY
    ) && severity == glow::DEBUG_SEVERITY_MEDIUM;
    if !error && !warning {
        return;
    }
    let mut record = record.lock().unwrap_or_else(|e| e.into_inner());
    if error {
        record.errors += 1;
    } else {
        record.warnings += 1;
    }
    if record.first.is_none() {
        let mut first = format!("message {id}: {}", message.trim());
        if first.chars().count() > FIRST_CHARS {
            first = first.chars().take(FIRST_CHARS).collect::<String>() + "…";
        }
        record.first = Some(first);
    }
}

/// What the callback heard so far.
pub(super) fn snapshot(record: &Shared) -> ApiRecord {
    record.lock().unwrap_or_else(|e| e.into_inner()).clone()
}
