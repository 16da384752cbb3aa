//! The registry: every rasterizer name rastercheck accepts, one row each,
//! with what it is, the cargo feature it needs, whether it is a default row
//! of the conformance matrix, and how to make it. Resolving a name
//! (`-r NAME`), listing names (`rastercheck rasterizers`), the matrix's
//! default rows, "did you mean" and the README's rasterizers table all read
//! this one table.
//!
//! Besides the built-in rows, a name may run an external program
//! (`external:PROGRAM`, `external-persistent:PROGRAM`, and either one as
//! `NAME=external…`); parsing those forms is `adapters::external`'s.

use crate::adapters::external;
use crate::production::foils::{
    Alpha, AnyCoverage, AreaSampler, CoarseEdges, CoarseSnap, ConservativeCentreBox,
    ConservativeCentreFlag, ConservativeDepthUnclamped, ConservativeOpenEnds, ConservativeOvergrow,
    DdaF32, DdaF64, EmptyAntialias, FloatF32, FloatF64, GridSamples, OffsetSampler,
    OutlineOverFill, SlopeTies, Truncate,
};
use crate::production::mutants::{Mutant, Mutation};
use crate::production::Production;
use crate::rasterizer::Rasterizer;
use crate::reference::Reference;

/// What a rasterizer is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// The exact reference: the oracle every other is judged against.
    Exact,
    /// The production rasterizer, or one of its methods measured on its own.
    Production,
    /// Deliberately inexact, to show what the reference catches; its
    /// failures are recorded as `foil`.
    Foil,
    /// Production with one realistic bug, to prove a check can fail.
    Mutant,
    /// A graphics driver (Vulkan, OpenGL).
    Driver,
    /// A third-party rasterizing library.
    Library,
    /// A program speaking the protocol of SPEC.md §12.
    External,
}

impl Kind {
    /// The kind in words, as `rastercheck rasterizers` prints it.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Exact => "exact reference",
            Kind::Production => "production",
            Kind::Foil => "foil",
            Kind::Mutant => "mutant",
            Kind::Driver => "driver",
            Kind::Library => "library",
            Kind::External => "external program",
        }
    }
}

/// How a row's rasterizer is made: `None` when its cargo feature is not
/// compiled into this build.
type Make = fn() -> Option<Box<dyn Rasterizer>>;

/// One rasterizer name.
#[derive(Clone, Copy)]
pub struct Entry {
    pub name: &'static str,
    pub kind: Kind,
    /// The cargo feature that compiles it in, if it needs one.
    pub feature: Option<&'static str>,
    /// Whether `matrix` runs it when no rows are named.
    pub matrix_default: bool,
    /// One line saying what it is.
    pub description: &'static str,
    make: Make,
}

impl Entry {
    /// Whether this build has it.
    pub fn compiled(&self) -> bool {
        (self.make)().is_some()
    }

    /// A new instance, or `None` when it is not compiled into this build.
    pub fn make(&self) -> Option<Box<dyn Rasterizer>> {
        (self.make)()
    }
}

/// A row that is always compiled in.
const fn row(
    name: &'static str,
    kind: Kind,
    matrix_default: bool,
    description: &'static str,
    make: Make,
) -> Entry {
    Entry {
        name,
        kind,
        feature: None,
        matrix_default,
        description,
        make,
    }
}

/// A row behind a cargo feature.
const fn featured(
    name: &'static str,
    kind: Kind,
    feature: &'static str,
    matrix_default: bool,
    description: &'static str,
    make: Make,
) -> Entry {
    Entry {
        name,
        kind,
        feature: Some(feature),
        matrix_default,
        description,
        make,
    }
}

fn boxed(r: impl Rasterizer + 'static) -> Option<Box<dyn Rasterizer>> {
    Some(Box::new(r))
}

/// One of production's methods that is a rasterizer of its own.
fn method(name: &str) -> Option<Box<dyn Rasterizer>> {
    crate::production::methods()
        .into_iter()
        .find(|m| m.name == name)
        .map(|m| (m.make)())
}

fn mutant(m: Mutation) -> Option<Box<dyn Rasterizer>> {
    boxed(Mutant(m))
}

/// Every built-in rasterizer, in the order `rasterizers` lists them (and
/// the matrix's default rows keep).
#[rustfmt::skip]
pub const ENTRIES: &[Entry] = &[
    row("reference", Kind::Exact, false,
        "the exact reference rasterizer (rationals): the oracle everything is judged against",
        || boxed(Reference)),
    row("production", Kind::Production, true,
        "the fast fixed-point rasterizer, exact on the cases it accepts",
        || boxed(Production)),
    row("dda-f32", Kind::Foil, true,
        "the classic floating-point DDA line walker, in f32",
        || boxed(DdaF32)),
    row("dda-f64", Kind::Foil, true,
        "the classic floating-point DDA line walker, in f64",
        || boxed(DdaF64)),
    row("float-f32", Kind::Foil, true,
        "the textbook floating-point triangle rasterizer, in f32",
        || boxed(FloatF32)),
    row("float-f64", Kind::Foil, true,
        "the textbook floating-point triangle rasterizer, in f64",
        || boxed(FloatF64)),
    row("foil-offset-sampler", Kind::Foil, true,
        "production sampling at the pixel's corner (1, 1) instead of its centre",
        || boxed(OffsetSampler)),
    row("foil-area-sampler", Kind::Foil, true,
        "a pixel drawn by a primitive covering at least half its area",
        || boxed(AreaSampler)),
    row("foil-any-coverage", Kind::Foil, true,
        "a pixel drawn by every triangle touching it (conservative rasterization)",
        || boxed(AnyCoverage)),
    row("foil-snap4", Kind::Foil, false,
        "production snapping to 4 subpixel bits, and declaring them",
        || boxed(CoarseSnap::HONEST)),
    row("foil-snap4-as-8", Kind::Foil, false,
        "production snapping to 4 subpixel bits while declaring 8",
        || boxed(CoarseSnap::AS_8)),
    row("foil-grid-samples", Kind::Foil, false,
        "production sampling on a k×k grid while declaring the standard positions",
        || boxed(GridSamples)),
    row("foil-slope-ties", Kind::Foil, false,
        "production with ties by slope: bottom-right, but top-left on slopes 3, 3/2, -3, -1/3, -2/3",
        || boxed(SlopeTies)),
    row("foil-truncate", Kind::Foil, false,
        "production truncating every vertex to whole pixels, and declaring it",
        || boxed(Truncate::HONEST)),
    row("foil-truncate-undeclared", Kind::Foil, false,
        "production truncating every vertex to whole pixels, declaring nothing",
        || boxed(Truncate::UNDECLARED)),
    row("foil-coarse-edges", Kind::Foil, false,
        "vertices at 8 subpixel bits, slanted edges stepped by slopes truncated to 1/16 px per row",
        || boxed(CoarseEdges)),
    row("foil-outline-over-fill", Kind::Foil, false,
        "production's fill with each triangle's edges stroked over it as one-pixel hairlines",
        || boxed(OutlineOverFill)),
    row("foil-empty-antialias", Kind::Foil, false,
        "an area method answering every antialiased scene with no coverage at all",
        || boxed(EmptyAntialias)),
    row("foil-alpha256", Kind::Foil, false,
        "an area method storing area × 256 capped at 255 in a byte, and declaring that encoding",
        || boxed(Alpha::FRACTION)),
    row("foil-alpha256-as-unorm", Kind::Foil, false,
        "the same bytes as foil-alpha256, declared as 8-bit unorm (steps of 1/255)",
        || boxed(Alpha::FRACTION_AS_UNORM)),
    row("foil-alpha255", Kind::Foil, false,
        "an area method storing area × 255 in a byte (8-bit unorm), and declaring it",
        || boxed(Alpha::UNORM)),
    row("foil-conservative-overgrow", Kind::Foil, false,
        "conservative overestimation grown 1/8 px past the uncertainty it declares",
        || boxed(ConservativeOvergrow)),
    row("foil-conservative-centre-box", Kind::Foil, false,
        "conservative overestimation tested only in the box of pixel centres (misses touched corner pixels)",
        || boxed(ConservativeCentreBox)),
    row("foil-conservative-centre-flag", Kind::Foil, false,
        "conservative rasterization flagging a pixel fully covered when its centre is covered",
        || boxed(ConservativeCentreFlag)),
    row("foil-conservative-depth-unclamped", Kind::Foil, false,
        "conservative rasterization writing an extrapolated depth past [0, 1] without the format's clamp",
        || boxed(ConservativeDepthUnclamped)),
    row("foil-conservative-open-ends", Kind::Foil, false,
        "conservative lines drawn with open end caps (misses pixels touching a line's end only)",
        || boxed(ConservativeOpenEnds)),
    row("polygon-convex", Kind::Production, false,
        "convex-polygon span fill, two monotone chains per sample row",
        || method("polygon-convex")),
    row("polygon-tessellate", Kind::Production, false,
        "simple polygons by ear clipping into production's triangles",
        || method("polygon-tessellate")),
    row("flood-fill", Kind::Foil, false,
        "a polygon's outline drawn with midpoint lines, then flood-filled",
        || method("flood-fill")),
    row("adaptive-refine", Kind::Foil, false,
        "antialiasing by adaptive sampling: blocks settled from their corners (inexact)",
        || method("adaptive-refine")),
    row("area-f32", Kind::Foil, false,
        "analytic area coverage in f32 by signed-area accumulation (font rasterizers' method)",
        || method("area-f32")),
    row("adaptive-resolve", Kind::Production, false,
        "adaptive sampling computing only the resolved coverage, no sample mask",
        || method("adaptive-resolve")),
    row("production-tiled", Kind::Production, false,
        "production drawn band by band in parallel",
        || method("production-tiled")),
    row("mutant:flipped-ties", Kind::Mutant, false,
        "the mirror-image tie rule: shared-edge samples go to the other triangle",
        || mutant(Mutation::FlippedTies)),
    row("mutant:closed-edges", Kind::Mutant, false,
        "every edge owns its samples: shared edges drawn twice",
        || mutant(Mutation::ClosedEdges)),
    row("mutant:vertex-nudge", Kind::Mutant, false,
        "each triangle's first vertex moved one subpixel right",
        || mutant(Mutation::VertexNudge)),
    row("mutant:shrunk", Kind::Mutant, false,
        "every vertex pulled one subpixel toward its centroid: cracks open",
        || mutant(Mutation::Shrunk)),
    row("mutant:no-perspective", Kind::Mutant, false,
        "perspective-correct interpolation done linearly in screen space",
        || mutant(Mutation::NoPerspective)),
    row("mutant:thick-lines", Kind::Mutant, false,
        "midpoint lines drawn as one-pixel-wide rectangles",
        || mutant(Mutation::ThickLines)),
    row("mutant:midpoint-for-diamond", Kind::Mutant, false,
        "diamond-exit lines drawn by the half-open midpoint rule",
        || mutant(Mutation::MidpointForDiamond)),
    row("mutant:shifted-samples", Kind::Mutant, false,
        "every sample offset moved one lattice unit right",
        || mutant(Mutation::ShiftedSamples)),
    row("mutant:coarse-resolve", Kind::Mutant, false,
        "resolved coverage rounded down to quarters",
        || mutant(Mutation::CoarseResolve)),
    row("mutant:leaky-full", Kind::Mutant, false,
        "fully covered pixels resolve to 1 − 2^-20",
        || mutant(Mutation::LeakyFull)),
    row("mutant:motion-at-open", Kind::Mutant, false,
        "every moving primitive drawn where it is at shutter open",
        || mutant(Mutation::MotionAtOpen)),
    row("mutant:motion-half-shutter", Kind::Mutant, false,
        "an accumulation buffer over the first half of the shutter only",
        || mutant(Mutation::MotionHalfShutter)),
    featured("tiny-skia", Kind::Library, "tiny-skia", true,
        "tiny-skia 0.12's aliased path fill, one triangle at a time",
        tiny_skia),
    featured("euc", Kind::Library, "euc", true,
        "euc 0.5.3's triangle rasterizer with its vertex and fragment pipeline",
        euc),
    featured("vello-cpu", Kind::Library, "vello", false,
        "vello_cpu 0.3's antialiased path fill",
        vello_cpu),
    featured("vulkan", Kind::Driver, "vulkan", true,
        "any Vulkan driver through ash (lavapipe, or a GPU's own); `vulkan@DEVICE` draws on the device whose name contains DEVICE",
        || vulkan(false, None)),
    featured("vulkan-passes", Kind::Driver, "vulkan", false,
        "the vulkan adapter drawing every sample pattern by shifted passes (`vulkan-passes@DEVICE` too)",
        || vulkan(true, None)),
    featured("lavapipe", Kind::Driver, "lavapipe", true,
        "Mesa's Vulkan rasterizer on the CPU, through wgpu",
        lavapipe),
    featured("gl", Kind::Driver, "gl", true,
        "Mesa's OpenGL through EGL (llvmpipe, or GALLIUM_DRIVER's)",
        gl),
    featured("softpipe", Kind::Driver, "gl", false,
        "Mesa's OpenGL through EGL, insisting on softpipe",
        softpipe),
];

fn tiny_skia() -> Option<Box<dyn Rasterizer>> {
    #[cfg(feature = "tiny-skia")]
    return boxed(crate::adapters::tiny_skia::TinySkia);
    #[cfg(not(feature = "tiny-skia"))]
    None
}

fn euc() -> Option<Box<dyn Rasterizer>> {
    #[cfg(feature = "euc")]
    return boxed(crate::adapters::euc::Euc);
    #[cfg(not(feature = "euc"))]
    None
}

fn vello_cpu() -> Option<Box<dyn Rasterizer>> {
    #[cfg(feature = "vello")]
    return boxed(crate::adapters::vello::VelloCpu);
    #[cfg(not(feature = "vello"))]
    None
}

fn vulkan(passes_only: bool, on: Option<&'static str>) -> Option<Box<dyn Rasterizer>> {
    #[cfg(feature = "vulkan")]
    return boxed(crate::adapters::vulkan::Vulkan { passes_only, on });
    #[cfg(not(feature = "vulkan"))]
    {
        let _ = (passes_only, on);
        None
    }
}

/// `vulkan@DEVICE` or `vulkan-passes@DEVICE`: the row's adapter on the
/// device whose name contains DEVICE; `None` for any other name.
fn on_device(name: &str) -> Option<(&'static Entry, bool)> {
    let (row, device) = name.split_once('@')?;
    let passes_only = match row {
        "vulkan" => false,
        "vulkan-passes" => true,
        _ => return None,
    };
    let ok = !device.trim().is_empty() && !device.contains('@');
    ok.then(|| (entry(row).expect("a row"), passes_only))
}

fn lavapipe() -> Option<Box<dyn Rasterizer>> {
    #[cfg(feature = "lavapipe")]
    return boxed(crate::adapters::lavapipe::Lavapipe);
    #[cfg(not(feature = "lavapipe"))]
    None
}

fn gl() -> Option<Box<dyn Rasterizer>> {
    #[cfg(feature = "gl")]
    return boxed(crate::adapters::gl::Gl { softpipe: false });
    #[cfg(not(feature = "gl"))]
    None
}

fn softpipe() -> Option<Box<dyn Rasterizer>> {
    #[cfg(feature = "gl")]
    return boxed(crate::adapters::gl::Gl { softpipe: true });
    #[cfg(not(feature = "gl"))]
    None
}

/// The external example program among the matrix's default rows.
pub const PYTHON_EXAMPLE: &str =
    "external-persistent:python3 examples/python_rasterizer.py --persistent";

/// The forms that run an external program, with what each means, as
/// `rastercheck rasterizers` lists them after the built-in names.
pub const EXTERNAL_FORMS: [(&str, &str); 4] = [
    (
        "external:PROGRAM [ARGS]",
        "a program speaking SPEC.md §12's protocol, started once per case",
    ),
    (
        "external-persistent:PROGRAM [ARGS]",
        "the same program started once and sent every case in turn",
    ),
    (
        "NAME=external:PROGRAM [ARGS]",
        "an external program, called NAME in reports and baselines",
    ),
    (
        "NAME=external-persistent:PROGRAM [ARGS]",
        "a persistent external program, called NAME",
    ),
];

/// The row of a built-in name, compiled into this build or not.
pub fn entry(name: &str) -> Option<&'static Entry> {
    ENTRIES.iter().find(|e| e.name == name)
}

/// The built-in names compiled into this build (the names `-r` accepts
/// besides the external forms).
pub fn names() -> Vec<&'static str> {
    ENTRIES
        .iter()
        .filter(|e| e.compiled())
        .map(|e| e.name)
        .collect()
}

/// Why a name does not make a rasterizer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Missing {
    /// A built-in name whose cargo feature this build lacks.
    NotCompiled { feature: &'static str },
    /// No name rastercheck knows.
    Unknown,
}

/// A rasterizer by name: a built-in one, or an external program
/// (`external:…`, `external-persistent:…`, or either as `NAME=…`).
pub fn resolve(name: &str) -> Result<Box<dyn Rasterizer>, Missing> {
    if let Some((e, passes_only)) = on_device(name) {
        // The name lives as long as the process, as the rows' names do.
        let on: &'static str = Box::leak(name.to_owned().into_boxed_str());
        return vulkan(passes_only, Some(on)).ok_or(Missing::NotCompiled {
            feature: e.feature.unwrap_or_default(),
        });
    }
    if let Some(e) = entry(name) {
        return e.make().ok_or(Missing::NotCompiled {
            feature: e.feature.unwrap_or_default(),
        });
    }
    external::by_name(name).ok_or(Missing::Unknown)
}

/// A rasterizer by name, `None` when there is none in this build.
pub fn by_name(name: &str) -> Option<Box<dyn Rasterizer>> {
    resolve(name).ok()
}

/// The name reports use for a `-r` argument: NAME in `NAME=external…`, the
/// argument itself otherwise.
pub fn called(name: &str) -> &str {
    external::split_name(name).map_or(name, |(called, _)| called)
}

/// The matrix's rows when none are named: the default rows in registry
/// order, with the Python example program before the drivers.
pub fn matrix_default_rows() -> Vec<String> {
    let mut rows: Vec<String> = Vec::new();
    for e in ENTRIES.iter().filter(|e| e.matrix_default) {
        if e.kind == Kind::Driver && !rows.iter().any(|r| r == PYTHON_EXAMPLE) {
            rows.push(PYTHON_EXAMPLE.to_owned());
        }
        rows.push(e.name.to_owned());
        if e.name == "vulkan" {
            rows.push(SWIFTSHADER_ROW.to_owned());
        }
    }
    rows
}

/// The matrix's row for Google's SwiftShader beside the default Vulkan
/// device: a row that says why where SwiftShader's ICD is not given to
/// the loader (`VK_ADD_DRIVER_FILES`, docs/drivers.md).
pub const SWIFTSHADER_ROW: &str = "vulkan@swiftshader";

/// The built-in name nearest to a mistyped one, if one is plausibly meant.
pub fn suggestion(name: &str) -> Option<&'static str> {
    let all: Vec<&'static str> = ENTRIES.iter().map(|e| e.name).collect();
    crate::scene::case::closest(name, &all)
}

/// The registry as a Markdown table (name, kind, feature, description),
/// for the README.
pub fn markdown_table() -> String {
    let mut out =
        String::from("| Name | Kind | Cargo feature | Description |\n|---|---|---|---|\n");
    for e in ENTRIES {
        out.push_str(&format!(
            "| `{}` | {} | {} | {} |\n",
            e.name,
            e.kind.name(),
            e.feature.map_or("—".to_owned(), |f| format!("`{f}`")),
            e.description
        ));
    }
    for (form, description) in EXTERNAL_FORMS {
        out.push_str(&format!(
            "| `{form}` | {} | — | {description} |\n",
            Kind::External.name()
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_each_rasterizer_answers_to_its_own() {
        for (i, e) in ENTRIES.iter().enumerate() {
            assert!(
                ENTRIES[..i].iter().all(|o| o.name != e.name),
                "{} twice",
                e.name
            );
            if let Some(r) = e.make() {
                assert_eq!(r.name(), e.name);
                assert_eq!(r.is_foil(), e.kind == Kind::Foil, "{}", e.name);
            }
        }
    }

    /// The names the five lists held before the registry, all still rows,
    /// and the matrix's default rows as they were.
    #[test]
    fn the_names_accepted_before_are_rows_and_the_matrix_rows_are_kept() {
        let before = "reference production dda-f32 dda-f64 float-f32 float-f64 \
            foil-offset-sampler foil-area-sampler foil-any-coverage foil-snap4 foil-snap4-as-8 \
            foil-grid-samples polygon-convex \
            polygon-tessellate flood-fill adaptive-refine area-f32 adaptive-resolve \
            production-tiled mutant:flipped-ties mutant:closed-edges mutant:vertex-nudge \
            mutant:shrunk mutant:no-perspective mutant:thick-lines \
            mutant:midpoint-for-diamond mutant:shifted-samples mutant:coarse-resolve \
            mutant:leaky-full mutant:motion-at-open mutant:motion-half-shutter vulkan \
            vulkan-passes lavapipe gl softpipe tiny-skia euc vello-cpu foil-slope-ties \
            foil-truncate foil-truncate-undeclared foil-coarse-edges foil-outline-over-fill \
            foil-empty-antialias foil-alpha256 foil-alpha256-as-unorm foil-alpha255 \
            foil-conservative-overgrow foil-conservative-centre-box foil-conservative-centre-flag \
            foil-conservative-depth-unclamped foil-conservative-open-ends";
        let rows: Vec<&str> = ENTRIES.iter().map(|e| e.name).collect();
        let mut before: Vec<&str> = before.split_whitespace().collect();
        assert_eq!(before.len(), rows.len());
        before.retain(|n| !rows.contains(n));
        assert!(before.is_empty(), "no row for {before:?}");
        assert_eq!(
            matrix_default_rows(),
            [
                "production",
                "dda-f32",
                "dda-f64",
                "float-f32",
                "float-f64",
                "foil-offset-sampler",
                "foil-area-sampler",
                "foil-any-coverage",
                "tiny-skia",
                "euc",
                PYTHON_EXAMPLE,
                "vulkan",
                SWIFTSHADER_ROW,
                "lavapipe",
                "gl",
            ]
        );
    }

    #[test]
    fn every_production_method_and_mutant_has_a_row() {
        for m in crate::production::methods() {
            assert!(entry(m.name).is_some(), "{} has no row", m.name);
        }
        for m in Mutation::ALL {
            assert_eq!(entry(m.name()).map(|e| e.kind), Some(Kind::Mutant));
        }
        for name in crate::production::foils::SAMPLER_FOILS {
            assert_eq!(entry(name).map(|e| e.kind), Some(Kind::Foil));
        }
    }

    #[test]
    fn a_vulkan_device_is_named_after_an_at() {
        for (name, device_named) in [
            ("vulkan@swiftshader", true),
            ("vulkan-passes@llvmpipe", true),
            ("vulkan@", false),
            ("vulkan@a@b", false),
            ("gl@llvmpipe", false),
        ] {
            assert_eq!(on_device(name).is_some(), device_named, "{name}");
        }
        #[cfg(feature = "vulkan")]
        assert_eq!(
            by_name("vulkan@swiftshader").map(|r| r.name().to_owned()),
            Some("vulkan@swiftshader".to_owned())
        );
        assert_eq!(resolve("gl@llvmpipe").err(), Some(Missing::Unknown));
    }

    #[test]
    fn external_forms_resolve_through_the_adapter() {
        let r = by_name("mine=external:prog").expect("an external form");
        assert_eq!(r.name(), "mine");
        assert_eq!(called("mine=external-persistent:prog --a=b"), "mine");
        assert_eq!(called("external:prog --a=b"), "external:prog --a=b");
        assert!(matches!(resolve("no-such"), Err(Missing::Unknown)));
    }

    #[test]
    fn a_typo_suggests_the_name() {
        assert_eq!(suggestion("producton"), Some("production"));
        assert_eq!(suggestion("tinyskia"), Some("tiny-skia"));
        assert_eq!(suggestion("zzzzzzzzzzzz"), None);
    }

    #[test]
    fn the_markdown_table_has_a_line_per_name_and_form() {
        let table = markdown_table();
        assert_eq!(
            table.lines().count(),
            2 + ENTRIES.len() + EXTERNAL_FORMS.len()
        );
        assert!(table.contains("| `vello-cpu` | library | `vello` |"));
    }
}
