//! The driver's own multisampling: the sample counts it offers
//! (`GL_MAX_SAMPLES`) and where each count's samples lie
//! (`glGetMultisamplefv(GL_SAMPLE_POSITION, i)`), queried once per
//! context on a multisampled framebuffer of each count, and which case
//! patterns are exactly one of them.
//!
//! GL reports a position within the pixel from its lower-left corner, y up
//! in window coordinates. The adapter draws the canvas upside down in the
//! window and flips the rows back (`mod.rs`), so within a pixel a window
//! offset (x, y) is the case's offset (x, 1 − y) from the top-left corner,
//! y down. Positions are kept in those terms, exact (a GL float is a
//! dyadic rational; f64 holds it).
//!
//! llvmpipe offers 4× only, at its fixed positions (the D3D/Vulkan
//! standard 4× pattern in gallium's memory order, which is GL's window y:
//! read y down, it is that pattern flipped vertically). `tests/gl/msaa.rs`
//! prints what the driver reports and checks that a tiny triangle around
//! each position lights exactly that sample.

use glow::HasContext;

use crate::plan::SamplePlan;

/// `glGetMultisamplefv(GLenum pname, GLuint index, GLfloat *val)`.
type GetMultisamplefv = unsafe extern "system" fn(u32, u32, *mut f32);

/// One sample count the driver draws, and its samples' positions.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct DriverSamples {
    /// The count asked for and granted (`GL_SAMPLES` of the framebuffer).
    pub count: u32,
    /// Each sample's offset from the pixel's top-left corner, y down, in
    /// pixels (the case's terms), in the driver's sample order.
    pub positions: Vec<[f64; 2]>,
}

impl DriverSamples {
    /// Sample i's offset in the case's terms, on `2^-bits` of a pixel, if
    /// it lies on that grid.
    pub(super) fn on_grid(&self, i: usize, bits: u32) -> Option<[i64; 2]> {
        let scale = f64::from(1u32 << bits);
        let p = self.positions[i].map(|c| c * scale);
        p.iter()
            .all(|c| c.fract() == 0.0)
            .then(|| p.map(|c| c as i64))
    }

    /// Names the positions for reports: "(x, y) …", y down.
    pub(super) fn describe(&self) -> String {
        let positions: Vec<String> = self
            .positions
            .iter()
            .map(|[x, y]| format!("({x}, {y})"))
            .collect();
        format!("{}×: {}", self.count, positions.join(" "))
    }
}

/// `GL_MAX_SAMPLES`, and every power-of-two sample count from 2 to it,
/// with its positions, as the driver grants it; counts it grants as
/// another count are listed once. None where the entry point is missing.
pub(super) unsafe fn query(
    gl: &glow::Context,
    get: Option<extern "system" fn()>,
) -> Result<(u32, Vec<DriverSamples>), String> {
    let max = gl.get_parameter_i32(glow::MAX_SAMPLES).max(0) as u32;
    let Some(get) = get else {
        return Ok((max, Vec::new()));
    };
    // SAFETY: glGetMultisamplefv's signature.
    let get: GetMultisamplefv = std::mem::transmute(get);
    let mut offered: Vec<DriverSamples> = Vec::new();
    let mut n = 2;
    while n <= max {
        let texture = gl.create_texture()?;
        let fbo = gl.create_framebuffer()?;
        gl.bind_texture(glow::TEXTURE_2D_MULTISAMPLE, Some(texture));
        gl.tex_image_2d_multisample(
            glow::TEXTURE_2D_MULTISAMPLE,
            n as i32,
            glow::R32F as i32,
            4,
            4,
            true,
        );
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
        gl.framebuffer_texture_2d(
            glow::FRAMEBUFFER,
            glow::COLOR_ATTACHMENT0,
            glow::TEXTURE_2D_MULTISAMPLE,
            Some(texture),
            0,
        );
        let complete = gl.check_framebuffer_status(glow::FRAMEBUFFER) == glow::FRAMEBUFFER_COMPLETE;
        let granted = gl.get_parameter_i32(glow::SAMPLES).max(0) as u32;
        if complete && granted >= 2 && !offered.iter().any(|o| o.count == granted) {
            let positions = (0..granted)
                .map(|i| {
                    let mut v = [0f32; 2];
                    get(glow::SAMPLE_POSITION, i, v.as_mut_ptr());
                    [f64::from(v[0]), 1.0 - f64::from(v[1])]
                })
                .collect();
            offered.push(DriverSamples {
                count: granted,
                positions,
            });
        }
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        gl.bind_texture(glow::TEXTURE_2D_MULTISAMPLE, None);
        gl.delete_framebuffer(fbo);
        gl.delete_texture(texture);
        n *= 2;
    }
    Ok((max, offered))
}

/// Where native multisampling draws `aa` exactly: the driver count whose
/// positions are the plan's offsets, and for each driver sample the plan
/// slot at the same offset. None where no count's positions are exactly
/// the pattern's (as a set).
pub(super) fn native(aa: &SamplePlan, offered: &[DriverSamples]) -> Option<(u32, Vec<usize>)> {
    let unit = 2f64.powi(aa.position_bits as i32);
    let offsets: Vec<[f64; 2]> = aa
        .offsets
        .iter()
        .map(|o| o.map(|c| f64::from(c) / unit))
        .collect();
    offered.iter().find_map(|driver| {
        if driver.positions.len() != offsets.len() {
            return None;
        }
        let mut slots = Vec::with_capacity(offsets.len());
        for p in &driver.positions {
            let slot = offsets
                .iter()
                .enumerate()
                .position(|(s, o)| o == p && !slots.contains(&s))?;
            slots.push(slot);
        }
        Some((driver.count, slots))
    })
}
