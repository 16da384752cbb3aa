//! Clip space and the provoking vertex in GL (SPEC.md §16): what the
//! context offers for them, why a scene is refused, and the state a
//! scene's draws are made under.
//!
//! # Clip space means §16.1's
//!
//! GL's clip volume is −w ≤ z ≤ w by default; `glClipControl(GL_LOWER_LEFT,
//! GL_ZERO_TO_ONE)` (GL 4.5, ARB_clip_control) makes it 0 ≤ z ≤ w, the
//! case's, and a context without it refuses clip-space cases (remapping z
//! in the shader would change the clipping the driver is judged on). It is
//! set once for the context: screen-space draws put z = w/2, inside both
//! (or, into a depth attachment, the case's z, clamped rather than
//! clipped: `depth.rs`).
//!
//! Rather than `GL_UPPER_LEFT`, the y axis is flipped as the screen-space
//! path flips it, so that the driver draws both kinds of case under one
//! state (one tie rule, one facing): the stream sends y negated (exact), the
//! canvas is the top `W × H` of the tile and its rows are read back
//! flipped. With the GL viewport at window y = Q − vy − vh, height vh, a
//! clip-space y lands on window y_w = Q − (vy + vh·(y/w + 1)/2) = Q − y_f:
//! screen row y_f, as §16.1 says. Negating y swaps the top and bottom
//! planes, which clip the same polygon.
//!
//! A viewport off the integers needs `glViewportArrayv` (GL 4.1,
//! ARB_viewport_array); without it such cases are refused. Depth range:
//! `glDepthRange(min_depth, max_depth)` (either may be the larger). `depth:
//! clamp` is `GL_DEPTH_CLAMP` (GL 3.2), which turns near and far clipping
//! off.
//!
//! # The provoking vertex
//!
//! `glProvokingVertex` (GL 3.2): `GL_FIRST_VERTEX_CONVENTION` unless the
//! case says `last`, set before each scene's draws, screen space and clip
//! space alike.

use glow::HasContext;

use dashu_ratio::RBig;

use crate::adapters::float_input::{f32_of, to_f32};
use crate::adapters::gpu;
use crate::scene::{DepthMode, ProvokingVertex, Scene};

use super::passes::DRIVER_BITS;

/// `glProvokingVertex(GLenum)`.
pub(super) type ProvokingFn = unsafe extern "system" fn(u32);
/// `glClipControl(GLenum origin, GLenum depth)`.
pub(super) type ClipControlFn = unsafe extern "system" fn(u32, u32);

/// What the context offers for clip space.
pub(super) struct Offers {
    /// glClipControl was found and set to `GL_ZERO_TO_ONE`.
    pub zero_to_one: bool,
    /// `glViewportArrayv`: viewports off the integers.
    pub float_viewports: bool,
    /// `GL_VIEWPORT_BOUNDS_RANGE` (with float viewports; else ±max side).
    pub bounds: [f32; 2],
    /// `GL_MAX_VIEWPORT_DIMS`.
    pub max_viewport: [u32; 2],
}

impl Offers {
    /// Queries the current context and sets its clip control to zero to
    /// one where it can.
    pub(super) unsafe fn set_up(gl: &glow::Context, clip_control: Option<ClipControlFn>) -> Offers {
        if let Some(clip_control) = clip_control {
            clip_control(glow::LOWER_LEFT, glow::ZERO_TO_ONE);
        }
        let version = gl.version();
        let float_viewports = (version.major, version.minor) >= (4, 1)
            || gl.supported_extensions().contains("GL_ARB_viewport_array");
        let mut dims = [0i32; 2];
        gl.get_parameter_i32_slice(glow::MAX_VIEWPORT_DIMS, &mut dims);
        let max_viewport = dims.map(|d| d.max(0) as u32);
        let mut bounds = [-(max_viewport[0] as f32), max_viewport[0] as f32];
        if float_viewports {
            gl.get_parameter_f32_slice(glow::VIEWPORT_BOUNDS_RANGE, &mut bounds);
        }
        Offers {
            zero_to_one: clip_control.is_some(),
            float_viewports,
            bounds,
            max_viewport,
        }
    }

    /// What the context allows of a screen-space scene's viewport in a
    /// `tile` (`gpu/view.rs`), in the tile's pixels (y down) for every
    /// tile of a framebuffer at most `max_side` square: window x from
    /// `ox + x0` to `ox + x0 + P` and window y from `oy + Q − y0 − H` to
    /// `oy + Q − y0` within the bounds range, for `ox` up to
    /// `max_side − P` and `oy` up to `max_side − Q`.
    pub(super) fn screen_limits(&self, tile: (u32, u32), max_side: u32) -> gpu::ViewLimits {
        let [lo, hi] = [self.bounds[0].ceil() as i64, self.bounds[1].floor() as i64];
        let side = i64::from(max_side);
        gpu::ViewLimits {
            max: self.max_viewport,
            x: [lo, hi - side + i64::from(tile.0)],
            y: [side - hi, i64::from(tile.1) - lo],
        }
    }

    /// Why this context cannot draw a clip-space scene, if it cannot.
    pub(super) fn refusal(&self, scene: &Scene) -> Option<String> {
        let v = scene.viewport.as_ref()?;
        if let Some(why) = gpu::clip_space_refusal(scene, "Mesa's GL", DRIVER_BITS) {
            return Some(why);
        }
        if !self.zero_to_one {
            return Some(
                "no glClipControl (GL 4.5, ARB_clip_control): the clip volume's z \
                 would be −w to w, not 0 to w"
                    .to_owned(),
            );
        }
        let [x, y, w, h] = [&v.x, &v.y, &v.width, &v.height].map(|n| n.as_rbig().clone());
        let integral = [&x, &y, &w, &h].iter().all(|c| c.is_int());
        if !integral && !self.float_viewports {
            return Some(
                "a viewport off the integers needs glViewportArrayv (GL 4.1, \
                 ARB_viewport_array)"
                    .to_owned(),
            );
        }
        // The window y of the viewport's lower edge, Q − y − height (the
        // module's notes), must be an f32 too: GL takes it.
        let q = scene.canvas.height.next_power_of_two();
        let window_y = RBig::from(q) - v.y.as_rbig() - v.height.as_rbig();
        if RBig::try_from(to_f32(&window_y)).ok() != Some(window_y.clone()) {
            return Some(format!(
                "viewport: its window y {q} − y − height is not an f32, the type GL takes"
            ));
        }
        let [x, w, h] = [&v.x, &v.width, &v.height].map(f32_of);
        let y = to_f32(&window_y);
        let [lo, hi] = self.bounds;
        let inside = x >= lo
            && x + w <= hi
            && y >= lo
            && y + h <= hi
            && w <= self.max_viewport[0] as f32
            && h <= self.max_viewport[1] as f32;
        (!inside).then(|| {
            format!(
                "viewport at window ({x}, {y}), {w}×{h}: the context's viewports lie in [{lo}, {hi}], \
                 at most {}×{}",
                self.max_viewport[0], self.max_viewport[1]
            )
        })
    }
}

/// The vertex post-processing state of one scene's draws.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Stage {
    pub provoking_last: bool,
    /// A screen-space scene drawn into a depth attachment (`depth.rs`):
    /// `GL_DEPTH_CLAMP` on, so that its z (the position's) is clamped to
    /// the depth range [0, 1], not clipped.
    pub screen_clamp: bool,
    /// A clip-space scene's viewport `[x, y, width, height]` in pixels of
    /// the canvas (y down, §16.1), depth range and clamp.
    pub clip: Option<([f32; 4], [f64; 2], bool)>,
}

impl Stage {
    pub(super) fn of(scene: &Scene) -> Stage {
        Stage {
            provoking_last: scene.rules.provoking_vertex == ProvokingVertex::Last,
            screen_clamp: scene.viewport.is_none() && scene.depth_rules_need_attachment(),
            clip: scene.viewport.as_ref().map(|v| {
                let rect = [&v.x, &v.y, &v.width, &v.height].map(f32_of);
                let depth = [&v.min_depth, &v.max_depth].map(|n| f64::from(f32_of(n)));
                (rect, depth, scene.rules.clip.depth == DepthMode::Clamp)
            }),
        }
    }

    /// Sets the provoking vertex, depth range and clamp (a screen-space
    /// scene's: [0, 1], clamped where it has a depth attachment), and the
    /// viewport
    /// of a pass whose tile (`P × Q`, `tile`) has its lower-left window
    /// corner at `origin`: for screen space, `view` in the tile with its
    /// corner (canvas pixels, y down) at `corner`, the view's moved by the
    /// pass's shift (`gpu::Stream::viewport_corner`); for clip space, the
    /// case's viewport (the module's notes).
    pub(super) unsafe fn set(
        &self,
        gl: &glow::Context,
        provoking: ProvokingFn,
        origin: (u32, u32),
        tile: (u32, u32),
        (view, corner): (gpu::View, [f32; 2]),
    ) {
        provoking(if self.provoking_last {
            glow::LAST_VERTEX_CONVENTION
        } else {
            glow::FIRST_VERTEX_CONVENTION
        });
        let (ox, oy) = origin;
        let Some(([x, y, w, h], [near, far], clamp)) = self.clip else {
            // The view in window coordinates (y up, the tile's canvas row
            // y at window row Q − 1 − y): `Offers::screen_limits` kept it
            // within the context's bounds for every tile, with a pixel to
            // spare for the shift. Exact: integers within the bounds
            // (±32768) and a shift on the 8-bit grid fit an f32 (and f64,
            // where they are summed).
            let (vw, vh) = view.size;
            let gx = f64::from(ox) + f64::from(corner[0]);
            let gy = f64::from(oy) + f64::from(tile.1) - f64::from(corner[1]) - f64::from(vh);
            if gx.fract() == 0.0 && gy.fract() == 0.0 {
                gl.viewport(gx as i32, gy as i32, vw as i32, vh as i32);
            } else {
                // `GlContext::set_up` refused this without float viewports.
                gl.viewport_f32_slice(0, 1, &[[gx as f32, gy as f32, vw as f32, vh as f32]]);
            }
            gl.depth_range_f64(0.0, 1.0);
            if self.screen_clamp {
                gl.enable(glow::DEPTH_CLAMP);
            } else {
                gl.disable(glow::DEPTH_CLAMP);
            }
            return;
        };
        // Exact: `Offers::refusal` kept viewports whose window y is an f32
        // (clip-space scenes are drawn in one tile, at the origin).
        let (gx, gy) = (ox as f32 + x, (oy + tile.1) as f32 - y - h);
        if [gx, gy, w, h].iter().all(|c| c.fract() == 0.0) {
            gl.viewport(gx as i32, gy as i32, w as i32, h as i32);
        } else {
            gl.viewport_f32_slice(0, 1, &[[gx, gy, w, h]]);
        }
        gl.depth_range_f64(near, far);
        if clamp {
            gl.enable(glow::DEPTH_CLAMP);
        } else {
            gl.disable(glow::DEPTH_CLAMP);
        }
    }
}
