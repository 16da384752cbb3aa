//! The `gl` and `softpipe` adapters: one [`Rasterizer`] over Mesa's GL,
//! `softpipe` insisting on that driver; what each declares of the
//! driver's conventions (see `docs/drivers/gl.md`).

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{
    ApiRecord, Capabilities, Prepared, RasterError, Rasterizer, ScreenViewport,
};
use crate::scene::{
    ClipXy, ClipZ, ConservativeSupport, FillRule, InterpolateFrom, LineClamp, LineParameter,
    LineRule, LineT, PointBounds, PointClip, Scene,
};

use super::accepted::accepted;
use super::context::{self, with_context};
use super::debug;
use super::prepared::prepare;
use crate::adapters::gpu;

/// The name of the adapter that draws with whatever Mesa's GL is.
pub const NAME: &str = "gl";
/// The name of the adapter that insists on softpipe.
pub const SOFTPIPE: &str = "softpipe";

/// Mesa's OpenGL through EGL: llvmpipe, or whatever `GALLIUM_DRIVER` names
/// (`softpipe: false`, named [`NAME`]); or softpipe, insisted on
/// (`softpipe: true`, named [`SOFTPIPE`]; see `docs/drivers/gl.md` on one
/// driver per process).
pub struct Gl {
    /// Insist on softpipe: ask for it when first to create the display,
    /// and fail where the process already holds another driver.
    pub softpipe: bool,
}

impl Rasterizer for Gl {
    fn name(&self) -> &str {
        if self.softpipe {
            SOFTPIPE
        } else {
            NAME
        }
    }

    /// For softpipe, llvmpipe's but clip space and points: softpipe's
    /// clipping and point conventions have not been measured (`tests/gl/`
    /// measures llvmpipe's), so it claims neither.
    fn capabilities(&self) -> Capabilities {
        if self.softpipe {
            Capabilities {
                clip_space: false,
                points: false,
                ..capabilities()
            }
        } else {
            capabilities()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        rasterize(scene, plan, self.softpipe)
    }

    /// llvmpipe's top-left rule, read in the case's y-down terms (see
    /// "Rules" in `docs/drivers/gl.md`): GL gives no choice. softpipe's
    /// rule, read in the case's y-down terms, is bottom-right.
    fn fixed_fill_rule(&self) -> Option<FillRule> {
        if self.softpipe {
            Some(FillRule::BottomRight)
        } else {
            Some(FillRule::BottomLeft)
        }
    }

    /// GL's aliased lines, which draw `diamond-exit`, may depart from the
    /// diamond-exit rule within the latitude GL 4.6 §14.5.1 allows: judged
    /// under it (SPEC.md §4.2.1).
    fn diamond_exit_latitude(&self) -> bool {
        true
    }

    /// GL 4.6 §14.5.1's formula for a line's t, the projection, has no
    /// clamp: every line is unclamped (SPEC.md §5.1). llvmpipe takes an
    /// aliased (`diamond-exit`) line's t along the major axis (measured on
    /// `lines/diamond_colour_interpolation` line by line: 1.1e-7 stated
    /// `major`, 2.1e-2 restated `projected`), which the GL and GLES CTS
    /// accept with a quality warning (`LINEINTERPOLATION_PROJECTED`), not
    /// a failure: declared as its own. A multisampled (`rectangle`) line
    /// is the projection's. softpipe's is not measured.
    fn fixed_line_parameter(&self, rule: LineRule) -> Option<LineT> {
        let parameter = match rule {
            LineRule::Rectangle => LineParameter::Projected,
            _ if self.softpipe => return None,
            _ => LineParameter::Major,
        };
        Some(LineT {
            parameter,
            clamp: LineClamp::Unclamped,
        })
    }

    /// GL states no tie rule for the border of a multisampled line's
    /// rectangle ("Coverage bits that correspond to sample points that
    /// intersect a rectangle are 1, other coverage bits are 0", OpenGL ES
    /// 3.0.3 §3.5.4; GL 4.6 §14.5.4 draws the same rectangle): its border
    /// samples are judged off the ties (SPEC.md §4.3.1).
    fn rectangle_border_no_tie_rule(&self) -> bool {
        true
    }

    /// GL lets the driver choose. llvmpipe clips against all six planes
    /// before the divide and snaps the new vertices (Mesa's draw module;
    /// measured on scenes that separate the conventions, `tests/gl/`: 6
    /// samples depart from per-sample near clipping, 3 from a guard band,
    /// none from clip then snap). softpipe's is not measured.
    fn fixed_clip_rules(&self) -> Option<(ClipXy, ClipZ)> {
        (!self.softpipe).then_some((ClipXy::ClipThenSnap, ClipZ::ClipThenSnap))
    }

    /// llvmpipe sets its planes up in floating point from the divided,
    /// unsnapped vertices, and snaps only the edges (SPEC.md §16.10: on
    /// the bundled clip-space cases its depth and attributes depart from
    /// the snapped positions' values by up to 1.3e-3, and from the
    /// unsnapped positions' by at most 2.3e-6). softpipe's is not measured.
    fn fixed_interpolate_from(&self) -> Option<InterpolateFrom> {
        (!self.softpipe).then_some(InterpolateFrom::Unsnapped)
    }

    /// The viewport the context draws a screen-space scene through
    /// (`GlContext::placed`), where it cannot hold the scene's vertices:
    /// `GL_MAX_VIEWPORT_DIMS` and `GL_VIEWPORT_BOUNDS_RANGE` are too small,
    /// and llvmpipe clips there (SPEC.md §16.9). `None` before the context
    /// exists, and for softpipe, whose clipping is not measured.
    fn screen_viewport(&self, scene: &Scene, plan: &Plan) -> Option<ScreenViewport> {
        if self.softpipe {
            return None;
        }
        let (bits, _) = accepted(scene, plan, self.softpipe).ok()?;
        let (_, view) = context::existing(|gl| gl.placed(scene, bits))?.ok()?;
        gpu::clipped_at(scene, bits, &view)
    }

    /// GL's own rule: llvmpipe pops a point whose centre is outside the
    /// side planes (measured in screen space, `tests/gl/`: a size-4 point
    /// centred at x = 17 of a 16-pixel target draws nothing), so the
    /// adapter refuses the points where that shows (`gpu::points`).
    /// softpipe's is not measured.
    fn fixed_point_clip(&self) -> Option<PointClip> {
        (!self.softpipe).then_some(PointClip::Pop)
    }

    /// Mesa limits a point's square to the viewport rectangle (measured on
    /// the bundled point cases with llvmpipe, SPEC.md §17.4).
    fn fixed_point_bounds(&self) -> Option<PointBounds> {
        (!self.softpipe).then_some(PointBounds::Viewport)
    }

    /// The context's `GL_SUBPIXEL_BITS` (SPEC.md §3.2; llvmpipe's is 8):
    /// a case at more bits, or unsnapped, is judged at these. `None` before
    /// the context exists (asked after a draw, so only where none could be
    /// made).
    fn fixed_subpixel_bits(&self) -> Option<u32> {
        context::existing(|gl| gl.subpixel_bits)
    }

    fn declared(&self) -> Option<String> {
        declared()
    }

    /// Both modes and the flag are claimed, so that a conservative case
    /// comes to [`Rasterizer::rasterize`] and is refused there naming the
    /// extensions the context lacks (`conservative.rs`).
    fn conservative(&self) -> Option<ConservativeSupport> {
        Some(ConservativeSupport {
            overestimate: true,
            underestimate: true,
            fully_covered: true,
            depth: true,
            ..ConservativeSupport::default()
        })
    }

    /// What the context's KHR_debug callback heard of this process's
    /// calls (`debug.rs`), once the context exists.
    fn api_record(&self) -> Option<ApiRecord> {
        context::existing(|gl| debug::snapshot(&gl.record))
    }

    fn prepare<'a>(
        &'a self,
        scene: &'a Scene,
        plan: &'a Plan,
    ) -> Option<Result<Box<dyn Prepared + 'a>, RasterError>> {
        Some(prepare(scene, plan, self.softpipe))
    }
}

/// What Mesa's GL draws here: triangles, `diamond-exit` and `rectangle`
/// lines (`lines.rs` refuses the other rules) and polygons by stencil then
/// cover, snapped to the case's grid; antialiased scenes by shifted passes
/// (`passes.rs`) or native MSAA (`msaa.rs`); moving scenes by time passes
/// (`time.rs`); clip-space scenes, clipped by the driver (`clip.rs`); depth
/// formats and polygon offsets into a real depth attachment (`depth.rs`).
fn capabilities() -> Capabilities {
    Capabilities {
        polygons: true,
        motion_blur: true,
        clip_space: true,
        points: true,
        depth_attachment: true,
        ..gpu::capabilities(true)
    }
}

/// What the reports show beside the adapter's name, once the context
/// exists: the renderer, when antialiased cases are drawn by the driver's
/// multisampling (its positions listed) and when by shifted passes, how
/// rectangle lines are drawn, that moving scenes are drawn by time
/// passes, and that depth formats and offsets use a depth attachment.
fn declared() -> Option<String> {
    let description = context::existing_description()?;
    let offered = context::existing(|gl| {
        gl.offered
            .iter()
            .map(|o| o.describe())
            .collect::<Vec<_>>()
            .join("; ")
    })?;
    Some(format!(
        "{description}; antialiasing by the driver's MSAA where a case's sample positions \
         are exactly the driver's ({offered}; y down), by shifted passes (one single-sample \
         pass per sample slot) otherwise and with a depth attachment; rectangle lines in a \
         multisampled target, one sample read; motion by time passes (one scissored draw per \
         pixel and time test); depth formats and polygon offsets into a real depth attachment, \
         its stored values read back"
    ))
}

/// Sets the scene up, clears, draws and reads back, with the context held
/// throughout, and deletes what it set up.
fn rasterize(scene: &Scene, plan: &Plan, softpipe: bool) -> Result<Frame, RasterError> {
    if scene.is_conservative() {
        let why = with_context(|gl| Ok(super::conservative::refusal(gl)))?;
        return Err(RasterError::Unsupported(why));
    }
    let (bits, depth) = accepted(scene, plan, softpipe)?;
    with_context(|gl| {
        gl.insist_on_softpipe(softpipe)?;
        // SAFETY: GL calls on the context current on this thread, with
        // buffers sized to what is read and written.
        unsafe {
            let drawing = gl.set_up(scene, plan, bits, depth)?;
            gl.clear(&drawing);
            gl.draw(&drawing);
            let frame = gl.read_back(&drawing);
            gl.delete(&drawing);
            frame
        }
    })
}
