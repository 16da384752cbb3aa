//! llvmpipe behind a GPU API (`lavapipe`, `gl`): which methods are drivers,
//! and `LP_NUM_THREADS`, pinned to one rasterizer thread before any driver
//! starts. The llvmpipe targets are judged in `targets.rs`.

/// Whether a method is llvmpipe behind a GPU API: warmed up before the
/// rounds (its device, context and pipelines are created on first use).
pub(super) fn is_driver(name: &str) -> bool {
    DRIVERS.iter().any(|(n, _)| *n == name)
}

/// The llvmpipe methods, by adapter name, with what each goes through.
pub const DRIVERS: [(&str, &str); 2] = [
    ("lavapipe", "lavapipe (Vulkan) through wgpu"),
    ("gl", "Mesa's OpenGL through EGL surfaceless"),
];

/// The command that measures the llvmpipe rows.
pub const LLVMPIPE_COMMAND: &str = "cargo run --release --features lavapipe,gl -- bench";

/// The value of `LP_NUM_THREADS`, if set.
pub fn lp_num_threads() -> Option<String> {
    std::env::var("LP_NUM_THREADS").ok()
}

/// Where a llvmpipe adapter is compiled in: sets `LP_NUM_THREADS=1` (one
/// rasterizer thread; the calling thread bins and waits) unless the user
/// set it, before any driver starts (llvmpipe reads it when its screen is
/// created). Returns (its value, whether the bench set it).
pub(super) fn pin_llvmpipe_threads() -> Option<(String, bool)> {
    if !cfg!(any(feature = "lavapipe", feature = "gl")) {
        return None;
    }
    match lp_num_threads() {
        Some(v) => Some((v, false)),
        None => {
            // Before any driver is loaded, on the one thread running the
            // bench: nothing reads the environment concurrently.
            std::env::set_var("LP_NUM_THREADS", "1");
            Some(("1".to_owned(), true))
        }
    }
}
