//! Mesa's environment noise, quieted where the adapters start Mesa: the
//! warnings it (and the libraries it loads) print on stderr about the
//! machine's environment rather than about a case, which read like
//! rastercheck's own errors.
//!
//! - `XDG_RUNTIME_DIR`: Mesa's Vulkan device-select layer asks Wayland for
//!   the default device, and libwayland says "error: XDG_RUNTIME_DIR is
//!   invalid or not set in the environment." where it is unset (a CI
//!   container, a shell without a login session). Given a private, empty
//!   directory of our own, it finds no display there and says nothing.
//! - `EGL_LOG_LEVEL=fatal` and `LIBGL_DEBUG=quiet`: EGL's and the DRI
//!   loader's warnings while probing for drivers this machine has none of.
//!
//! Each is set only where the user has not set it, and before Mesa is
//! loaded (Mesa reads them when it starts): a user who wants the warnings
//! sets the variable.

use std::sync::Once;

/// Sets the variables above that the user has not set, once per process.
/// Called before the first EGL display or Vulkan instance is made.
pub(crate) fn quiet_mesa() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
            if let Some(dir) = private_runtime_dir() {
                set("XDG_RUNTIME_DIR", &dir);
            }
        }
        for (name, value) in [("EGL_LOG_LEVEL", "fatal"), ("LIBGL_DEBUG", "quiet")] {
            if std::env::var_os(name).is_none() {
                set(name, value);
            }
        }
    });
}

/// A directory only this user may use (mode 0700), made if missing: the
/// system's temporary folder's `rastercheck-runtime-UID`. `None` where it
/// cannot be made or is not this user's own.
fn private_runtime_dir() -> Option<String> {
    use std::os::unix::fs::{DirBuilderExt, MetadataExt, PermissionsExt};
    // SAFETY: getuid cannot fail and has no preconditions.
    let uid = unsafe { libc::getuid() };
    let dir = std::env::temp_dir().join(format!("rastercheck-runtime-{uid}"));
    let _ = std::fs::DirBuilder::new().mode(0o700).create(&dir);
    let metadata = std::fs::symlink_metadata(&dir).ok()?;
    let private =
        metadata.is_dir() && metadata.uid() == uid && metadata.permissions().mode() & 0o077 == 0;
    private.then(|| dir.to_str().map(str::to_owned)).flatten()
}

fn set(name: &str, value: &str) {
    // Before Mesa is loaded: nothing outside Rust's own locked
    // environment access reads the variables yet (as `gl`'s
    // `GALLIUM_DRIVER` for softpipe).
    std::env::set_var(name, value);
}
