//! The one trait every rasterizer implements: the reference, the production
//! rasterizer, deliberately wrong variants, and (later) third-party adapters.

use std::fmt;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::scene::{
    ClipXy, ClipZ, ConservativeSupport, FillRule, InterpolateFrom, LineRule, LineT, Pattern,
    PointBounds, PointClip, Scene,
};

/// Where a rasterizer puts a vertex before it rasterizes (SPEC.md §3.2): its
/// snapping, as a rasterizer that cannot choose it declares it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Snapping {
    /// Vertices are used exactly as given: judged as a case with
    /// `subpixel_bits: null`.
    None,
    /// Each coordinate is truncated to a whole pixel, ⌊c⌋ (towards −∞),
    /// in screen space.
    Truncate,
    /// Each coordinate is rounded to the nearest multiple of 2^-bits, ties
    /// to even (SPEC.md §2).
    Bits(u32),
}

impl Snapping {
    /// Reads a declaration: `"none"`, `"truncate"` or a number of bits (0
    /// to 16).
    pub fn from_json(value: &serde_json::Value) -> Option<Snapping> {
        match value {
            serde_json::Value::String(s) if s == "none" => Some(Snapping::None),
            serde_json::Value::String(s) if s == "truncate" => Some(Snapping::Truncate),
            serde_json::Value::Number(n) => n
                .as_u64()
                .filter(|&b| b <= 16)
                .map(|b| Snapping::Bits(b as u32)),
            _ => None,
        }
    }

    /// The words reports use: "no snapping", "truncation to whole pixels",
    /// "8 subpixel bits".
    pub fn words(self) -> String {
        match self {
            Snapping::None => "no snapping".to_owned(),
            Snapping::Truncate => "truncation to whole pixels".to_owned(),
            Snapping::Bits(bits) => format!("{bits} subpixel bits"),
        }
    }
}

/// Which way a rasterizer's y axis points (SPEC.md §2.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum YDirection {
    Down,
    Up,
}

/// Where a rasterizer's pixel (x, y) has its sample (SPEC.md §2.1): at
/// (x + ½, y + ½), or at (x, y).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelCentre {
    Half,
    Integer,
}

/// What a rasterizer can be asked to do. A case outside its capabilities is
/// reported as unsupported, never as passed or failed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Capabilities {
    pub triangles: bool,
    /// Cases with `subpixel_bits: null` (exact, unsnapped coordinates).
    pub ideal_geometry: bool,
    pub attributes: bool,
    pub depth: bool,
    /// `polygon` primitives (SPEC.md §14.1).
    pub polygons: bool,
    /// Scenes with `effects.antialias`: several samples per pixel and a
    /// resolved coverage per pixel (SPEC.md §14).
    pub antialias: bool,
    /// Scenes in which something moves (SPEC.md §15): a time coverage per
    /// pixel. A scene that declares motion blur and moves nothing is
    /// static and needs no such capability.
    pub motion_blur: bool,
    /// Scenes whose vertices are in clip space (SPEC.md §16): clipped,
    /// divided and put through a viewport before they are rasterized.
    pub clip_space: bool,
    /// Scenes with a depth format other than `exact` or a polygon offset
    /// (SPEC.md §18, `Scene::depth_rules_need_attachment`): only a
    /// rasterizer that writes a depth attachment of that format can follow
    /// them. An adapter that reads the fragment shader's depth (which
    /// carries neither offset nor quantization) sets this false.
    pub depth_attachment: bool,
    /// `point` primitives (SPEC.md §17).
    pub points: bool,
}

impl Capabilities {
    pub fn everything() -> Capabilities {
        Capabilities {
            triangles: true,
            ideal_geometry: true,
            attributes: true,
            depth: true,
            polygons: true,
            antialias: true,
            motion_blur: true,
            clip_space: true,
            depth_attachment: true,
            points: true,
        }
    }

    /// Nothing at all: the base a rasterizer that takes little names what
    /// it takes on, `Capabilities { triangles: true, ..Capabilities::none() }`.
    pub fn none() -> Capabilities {
        Capabilities {
            triangles: false,
            ideal_geometry: false,
            attributes: false,
            depth: false,
            polygons: false,
            antialias: false,
            motion_blur: false,
            clip_space: false,
            depth_attachment: false,
            points: false,
        }
    }

    /// Why a scene asks for more than these capabilities, if it does.
    /// The harness checks this before it calls a rasterizer.
    pub fn refuses(&self, scene: &Scene) -> Option<String> {
        if !self.polygons && scene.has_polygons() {
            return Some("this rasterizer does not draw polygons".to_owned());
        }
        if !self.points && scene.has_points() {
            return Some("this rasterizer does not draw points".to_owned());
        }
        if !self.antialias && scene.effects.antialias.is_some() {
            return Some("this rasterizer does not antialias".to_owned());
        }
        if !self.clip_space && scene.in_clip_space() {
            return Some(
                "this rasterizer takes screen-space vertices only, not clip space".to_owned(),
            );
        }
        if !self.depth_attachment && scene.depth_rules_need_attachment() {
            return Some(
                "a depth format or polygon offset (SPEC.md §18) needs a depth attachment; this rasterizer reads the fragment's depth, which carries neither".to_owned(),
            );
        }
        if !self.motion_blur && scene.effects.motion_blur.is_some() && scene.moves() {
            return Some("this rasterizer does not draw moving primitives".to_owned());
        }
        None
    }
}

/// The conventions beyond the fill rule that a rasterizer declares in words
/// (an external program's hello, `conventions`, SPEC.md §12.7; a profile's
/// `conventions`, §13): read once here, so both read them alike.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Declaration {
    pub snapping: Option<Snapping>,
    pub sample_pattern: Option<Pattern>,
    pub y: Option<YDirection>,
    pub pixel_centre: Option<PixelCentre>,
    /// `diamond_exit`: `Some(true)` for `"latitude"` (its diamond-exit
    /// lines keep to the APIs' latitude, SPEC.md §4.2.1,
    /// [`Rasterizer::diamond_exit_latitude`]), `Some(false)` for
    /// `"exact-rule"`.
    pub diamond_exit_latitude: Option<bool>,
}

impl Declaration {
    /// The keys this reads, for a reader that checks for unknown ones.
    pub const KEYS: [&'static str; 5] = [
        "snapping",
        "sample_pattern",
        "y",
        "pixel_centre",
        "diamond_exit",
    ];

    /// The words `diamond_exit` takes (not `"exact"`: a hello's
    /// descriptions say `"arithmetic": "exact"`, which would then read as a
    /// `diamond_exit` misplaced).
    pub const DIAMOND_EXIT: [&'static str; 2] = ["exact-rule", "latitude"];

    /// Reads `snapping`, `sample_pattern`, `y`, `pixel_centre` and
    /// `diamond_exit` from an
    /// object at JSON path `at`; other keys are left to the caller. A
    /// message names the path of the first bad value.
    pub fn read(
        object: &serde_json::Map<String, serde_json::Value>,
        at: &str,
    ) -> Result<Declaration, String> {
        let word = |key: &str, known: &[&str]| -> Result<Option<String>, String> {
            match object.get(key) {
                None | Some(serde_json::Value::Null) => Ok(None),
                Some(serde_json::Value::String(w)) if known.contains(&w.as_str()) => {
                    Ok(Some(w.clone()))
                }
                Some(other) => Err(format!(
                    "{at}.{key} is {other}; known: {}",
                    known.join(", ")
                )),
            }
        };
        let snapping = match object.get("snapping") {
            None | Some(serde_json::Value::Null) => None,
            Some(value) => Some(Snapping::from_json(value).ok_or_else(|| {
                format!(
                    "{at}.snapping is {value}; known: \"none\", \"truncate\" or a number of subpixel bits from 0 to 16"
                )
            })?),
        };
        let sample_pattern = word("sample_pattern", &["standard"])?.map(|_| Pattern::Standard);
        let y = word("y", &["down", "up"])?.map(|w| {
            if w == "up" {
                YDirection::Up
            } else {
                YDirection::Down
            }
        });
        let pixel_centre = word("pixel_centre", &["half", "integer"])?.map(|w| {
            if w == "integer" {
                PixelCentre::Integer
            } else {
                PixelCentre::Half
            }
        });
        let diamond_exit_latitude =
            word("diamond_exit", &Self::DIAMOND_EXIT)?.map(|w| w == "latitude");
        Ok(Declaration {
            snapping,
            sample_pattern,
            y,
            pixel_centre,
            diamond_exit_latitude,
        })
    }
}

/// `Unsupported` for a scene that needs the last vertex to provoke
/// (`Scene::needs_last_provoking_vertex`), from a rasterizer whose flat
/// values are always the first vertex's: it answers that it cannot, rather
/// than draw the first vertex's values and be judged wrong, or worse, be
/// right by chance where the two vertices agree.
pub fn refuse_last_provoking(scene: &Scene, who: &str) -> Result<(), RasterError> {
    if scene.needs_last_provoking_vertex() {
        return Err(RasterError::Unsupported(format!(
            "provoking_vertex: last on a flat primitive with attributes: \
             {who} takes flat values from the first vertex only"
        )));
    }
    Ok(())
}

/// What an API's own checker said of the calls an adapter made to a
/// driver, over the process so far (SPEC.md §10, `api_record`): the
/// Khronos validation layer through a debug-utils messenger, or GL's
/// KHR_debug. A verdict drawn by invalid calls may rest on undefined
/// behaviour, so a record that is not clean is reported beside them.
#[derive(Clone, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct ApiRecord {
    /// What checked the calls ("the Khronos validation layer", "KHR_debug");
    /// `None` where only the driver's own messages were counted.
    pub validated_by: Option<String>,
    /// Messages of error severity (Vulkan) or type or severity (GL).
    pub errors: u64,
    /// Messages of warning severity (Vulkan).
    pub warnings: u64,
    /// The first message: its id (a VUID) and text, trimmed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub first: Option<String>,
}

impl ApiRecord {
    pub fn is_clean(&self) -> bool {
        self.errors + self.warnings == 0
    }
}

impl fmt::Display for ApiRecord {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let by = match &self.validated_by {
            Some(by) => format!("checked by {by}"),
            None => "not validated: only the driver's own messages were counted".to_owned(),
        };
        if self.is_clean() {
            return write!(f, "0 messages ({by})");
        }
        write!(
            f,
            "{} errors, {} warnings ({by}); first: {}; its verdicts may rest on undefined behaviour",
            self.errors,
            self.warnings,
            self.first.as_deref().unwrap_or("(no text)")
        )
    }
}

/// A rectangle of the canvas's pixels (x right, y down) a screen-space
/// scene is drawn through, and clipped at by a driver that clips at its
/// side planes: its corner and its sides ([`Rasterizer::screen_viewport`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ScreenViewport {
    pub origin: [i64; 2],
    pub size: [u32; 2],
}

impl ScreenViewport {
    /// In words: "its 64 × 64 px viewport at (0, 0)".
    pub fn words(&self) -> String {
        format!(
            "its {} × {} px viewport at ({}, {})",
            self.size[0], self.size[1], self.origin[0], self.origin[1]
        )
    }
}

/// Why a rasterizer produced no frame.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RasterError {
    /// The scene asks for something this rasterizer does not do.
    Unsupported(String),
    /// The rasterizer broke.
    Failed(String),
}

impl fmt::Display for RasterError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RasterError::Unsupported(why) => write!(f, "unsupported: {why}"),
            RasterError::Failed(why) => write!(f, "failed: {why}"),
        }
    }
}

impl std::error::Error for RasterError {}

pub trait Rasterizer: Send + Sync {
    /// The name used on the command line and in reports.
    fn name(&self) -> &str;

    fn capabilities(&self) -> Capabilities;

    /// Whether this is a deliberately inexact method kept for measurement
    /// (a foil, such as a float DDA): its departures from the reference are
    /// reported, and never counted as failures.
    fn is_foil(&self) -> bool {
        false
    }

    /// Draws the scene's primitives in order, without depth testing; each
    /// sample keeps the values of the last primitive that covered it.
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError>;

    /// What the program behind this rasterizer says it is, once it has
    /// said so: an external program's hello names itself and its version
    /// (SPEC.md §12.7). Reports show it beside the name it was given.
    fn declared(&self) -> Option<String> {
        None
    }

    /// The most bytes this rasterizer holds of one case's answer beside
    /// its frame: an external program's answer line, at most its output
    /// limit (SPEC.md §12.5). The runner counts it in the case's memory
    /// budget (§8); 0 for one that draws into its frame.
    fn answer_bytes(&self) -> u64 {
        0
    }

    /// What the API's checker said of this adapter's calls so far, for a
    /// driver adapter that listens ([`ApiRecord`]); `None` for one that
    /// calls no driver API, or before it has made its device.
    fn api_record(&self) -> Option<ApiRecord> {
        None
    }

    /// The fill rule this rasterizer follows whatever a case states, when
    /// it cannot follow the case's: a driver's rule fixed by its API, a
    /// library's own, a program's declared convention (SPEC.md §3.1). A
    /// case under another rule is judged against the reference drawn under
    /// this one, and reported as such: a convention, not a failure.
    /// `None` for a rasterizer that follows each case's rule. Asked after
    /// the rasterizer has drawn the case, so a program may declare it in
    /// its hello.
    fn fixed_fill_rule(&self) -> Option<FillRule> {
        None
    }

    /// Whether this rasterizer declares no tie rule at all (`fill_rule:
    /// "none"`, SPEC.md §3.1.1): a sample exactly on an edge may go to
    /// either side. It is judged exactly off the ties, its tie samples
    /// counted apart. Asked, like [`Rasterizer::fixed_fill_rule`], after it
    /// has drawn the case.
    fn no_tie_rule(&self) -> bool {
        false
    }

    /// Whether this rasterizer draws `diamond-exit` lines with the latitude
    /// its API allows instead of the exact rule (SPEC.md §4.2.1): Vulkan's
    /// Bresenham lines and GL's aliased lines may move a fragment by one
    /// unit, change the count by one, and so on. A case's diamond-exit
    /// lines are then judged under those rules against the exact
    /// diamond-exit fragments, the fragments that used the latitude
    /// counted apart, and the result says so. `false` for a rasterizer
    /// that draws the exact rule.
    fn diamond_exit_latitude(&self) -> bool {
        false
    }

    /// The line parameter this rasterizer takes a line's values at, for
    /// lines drawn under `rule`, whatever a case states (SPEC.md §5.1):
    /// projected onto the segment or along the major axis, clamped to
    /// [0, 1] or not. A case whose lines of that rule state another (or
    /// any case, where it declares no clamp) is judged against the
    /// reference computing the values with this one, and the result says
    /// so. `None` for a rasterizer that follows each line's `parameter`
    /// and clamps, as SPEC does.
    fn fixed_line_parameter(&self, _rule: LineRule) -> Option<LineT> {
        None
    }

    /// Whether this rasterizer gives no tie rule for a sample exactly on a
    /// `rectangle` line's border (SPEC.md §4.3.1): such samples are then
    /// judged as `fill_rule: "none"` judges ties (either side accepted,
    /// counted apart, §3.1.1), every sample off the border exactly.
    /// `false` for one whose rectangle lines keep the case's fill rule.
    fn rectangle_border_no_tie_rule(&self) -> bool {
        false
    }

    /// The clip-space conventions (`clip_xy`, `clip_z`) this rasterizer
    /// follows whatever a case states, when it cannot follow the case's: a
    /// driver clips as its hardware or its software pipeline does (SPEC.md
    /// §16.2, §16.3). A clip-space case under other conventions is judged
    /// against the reference drawn under these, and reported as such, as
    /// for [`Rasterizer::fixed_fill_rule`]. `None` for a rasterizer that
    /// follows each case's.
    fn fixed_clip_rules(&self) -> Option<(ClipXy, ClipZ)> {
        None
    }

    /// The viewport a screen-space `scene` is drawn through, when it does
    /// not hold every vertex of the scene: a driver that clips at its side
    /// planes ([`Rasterizer::fixed_clip_rules`]'s `clip-then-snap`) clips
    /// the scene there. An adapter draws such a scene through a viewport
    /// that encloses its vertices where the device allows one, and through
    /// a smaller one where the device's largest viewport cannot hold them
    /// (a device limit); it says which here, from the same computation it
    /// draws with, so the judge restates the case clipped exactly at that
    /// rectangle (SPEC.md §16.9) and never guesses. `None` for a
    /// rasterizer that clips no screen-space scene, and for a scene it
    /// draws whole.
    fn screen_viewport(&self, _scene: &Scene, _plan: &Plan) -> Option<ScreenViewport> {
        None
    }

    /// The subpixel bits this rasterizer snaps vertices to whatever a case
    /// states, when its vertex precision is fixed: a driver's
    /// `subPixelPrecisionBits` or `GL_SUBPIXEL_BITS` (SPEC.md §3.2). A case
    /// stated at more bits, or unsnapped (`subpixel_bits: null`), is judged
    /// against the reference drawn at these, and reported as such, as for
    /// [`Rasterizer::fixed_fill_rule`]; a case at fewer bits is drawn as
    /// stated (its vertices lie on this finer grid). `None` for a
    /// rasterizer that follows each case's bits.
    fn fixed_subpixel_bits(&self) -> Option<u32> {
        None
    }

    /// How this rasterizer snaps vertices whatever a case states (SPEC.md
    /// §3.2): its fixed bits ([`Rasterizer::fixed_subpixel_bits`]) by
    /// default; a library that does not snap, or truncates to whole
    /// pixels, says so here. `None` for a rasterizer that follows each
    /// case's bits.
    fn fixed_snapping(&self) -> Option<Snapping> {
        self.fixed_subpixel_bits().map(Snapping::Bits)
    }

    /// The sample positions this rasterizer uses whatever an antialiased
    /// case states (SPEC.md §14.2.1): `Pattern::Standard` for a device
    /// that has only its standard positions. A case stating another
    /// pattern is judged against the reference drawn at these, with the
    /// same sample count, and reported as such. `None` for a rasterizer
    /// that draws each case's positions.
    fn fixed_sample_pattern(&self) -> Option<Pattern> {
        None
    }

    /// Which way this rasterizer's y axis points, when it is not SPEC's
    /// down and no adapter turns it round (SPEC.md §2.1): a case is then
    /// judged with its y-dependent words mirrored. `None` (or `Down`) for
    /// one that reads coordinates as the case does.
    fn fixed_y_direction(&self) -> Option<YDirection> {
        None
    }

    /// Where this rasterizer's pixel has its sample, when it is not SPEC's
    /// (x + ½, y + ½) and no adapter moves it (SPEC.md §2.1): a case is then
    /// judged moved by (½, ½). `None` (or `Half`) for SPEC's centre.
    fn fixed_pixel_centre(&self) -> Option<PixelCentre> {
        None
    }

    /// The positions this rasterizer interpolates clip-space values from
    /// whatever a case states (SPEC.md §16.5): a driver sets its planes up
    /// as its pipeline does. Judged as [`Rasterizer::fixed_clip_rules`].
    fn fixed_interpolate_from(&self) -> Option<InterpolateFrom> {
        None
    }

    /// What the side planes do to points (`clip_points`, SPEC.md §17) in
    /// this rasterizer whatever a case states, when it cannot follow the
    /// case's: a clip-space case with points under another is judged
    /// under this, and reported as such, as for
    /// [`Rasterizer::fixed_clip_rules`]. `None` for a rasterizer that
    /// follows each case's.
    fn fixed_point_clip(&self) -> Option<PointClip> {
        None
    }

    /// What limits a kept point's square (`point_bounds`, SPEC.md §17.2)
    /// in this rasterizer whatever a case states: judged as
    /// [`Rasterizer::fixed_point_clip`].
    fn fixed_point_bounds(&self) -> Option<PointBounds> {
        None
    }

    /// Whether and how this rasterizer draws conservative scenes
    /// (`effects.conservative`, SPEC.md §19): the modes it draws, whether
    /// it gives the fully-covered flag, and the uncertainty and API
    /// properties it cannot choose. `None` (the default): every
    /// conservative case is `unsupported`, with that reason. Asked before
    /// the case is drawn (a mode or flag it lacks refuses the case unsent)
    /// and again after (a program may declare its uncertainty in its
    /// hello): the case is judged under [`ConservativeSupport::restate`].
    fn conservative(&self) -> Option<ConservativeSupport> {
        None
    }

    /// What this rasterizer declares for conservative `scene`: by default
    /// [`Rasterizer::conservative`]. One whose uncertainty depends on what
    /// it asks its device for per case (Vulkan's extra overestimation
    /// size, SPEC.md §19.6) answers per case; the harness asks this one.
    fn conservative_for(&self, scene: &Scene) -> Option<ConservativeSupport> {
        let _ = scene;
        self.conservative()
    }

    /// The method's own draw call for `scene`, set up once so that it can
    /// be drawn again and again: what `rastercheck bench` times as the
    /// method's work, apart from what an adapter does around it. `None`
    /// for a method that has no draw call apart from [`Rasterizer::rasterize`].
    fn prepare<'a>(
        &'a self,
        _scene: &'a Scene,
        _plan: &'a Plan,
    ) -> Option<Result<Box<dyn Prepared + 'a>, RasterError>> {
        None
    }
}

/// A method's draw call with its input converted and (for a driver)
/// uploaded, and its targets allocated: the set-up a real application
/// does once. The bench times [`Prepared::draw`] as the method's own work,
/// and the set-up and [`Prepared::read_back`] apart from it.
pub trait Prepared: Send {
    /// Empties the targets. Untimed, between draws.
    fn clear(&mut self) -> Result<(), RasterError>;

    /// Draws every primitive into the targets as they stand, and returns
    /// when the drawing is done (for a driver: from submission to its
    /// fence). Nothing else is inside the timing.
    fn draw(&mut self) -> Result<(), RasterError>;

    /// The targets as a frame whose `last` holds each sample's last
    /// primitive (index + 1, 0 where none), as [`Rasterizer::rasterize`]'s
    /// frame does; its coverage counts are exact only where the method keeps
    /// them (a pixmap keeps the last colour, not a count). The bench checks
    /// that the owners agree with the whole call's, so the draw it timed is
    /// the one it judged.
    fn read_back(&mut self) -> Result<Frame, RasterError>;
}

/// A frame from a buffer of each pixel's last primitive (index + 1, 0 where
/// none), as a prepared draw into a colour target reads back: `last` is
/// the buffer, and every covered pixel counts one cover.
pub fn owners_frame(width: u32, height: u32, owners: &[u32]) -> Frame {
    let mut frame = Frame::new(width, height, false, 0);
    frame.last.copy_from_slice(owners);
    for (count, &owner) in frame.coverage.iter_mut().zip(owners) {
        *count = u16::from(owner > 0);
    }
    frame
}
