//! What the driver behind Mesa's GL reports of itself: its renderer and
//! its multisampling, asked of the shared context.

use super::context::context;

/// The driver's multisampling, as queried once per context.
#[derive(Clone, Debug, PartialEq)]
pub struct DriverMultisampling {
    /// `GL_MAX_SAMPLES`.
    pub max_samples: u32,
    /// Each count it grants, with its samples' positions in its sample
    /// order: offsets from the pixel's top-left corner, y down, in pixels
    /// (GL's `GL_SAMPLE_POSITION`, y up, flipped).
    pub counts: Vec<(u32, Vec<[f64; 2]>)>,
}

/// The driver's multisampling, or why there is no context. Creates the
/// shared context on first use.
pub fn driver_multisampling() -> Result<DriverMultisampling, String> {
    let gl = context()?;
    let gl = gl.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    Ok(DriverMultisampling {
        max_samples: gl.max_samples,
        counts: gl
            .offered
            .iter()
            .map(|o| (o.count, o.positions.clone()))
            .collect(),
    })
}

/// The renderer (`GL_RENDERER`, `GL_VERSION`), or why there is none. Creates
/// the shared context on first use.
pub fn renderer_description() -> Result<String, String> {
    let gl = context()?;
    let gl = gl.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    Ok(format!("{} ({})", gl.renderer, gl.version))
}
