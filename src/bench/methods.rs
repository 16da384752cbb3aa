//! The methods each workload measures, in table order: the triangle
//! methods (production, its tiled form, the naive floor, the float foils and
//! the adapters compiled in), the antialiasing methods (production's
//! patterns and the area and adaptive methods) and the motion rows.

use super::foils::NaiveBbox;
use super::timing::{OnPool, TILED_THREADS};
use super::workloads::SEED;
use crate::rasterizer::Rasterizer;
use crate::scene::{Antialias, Pattern, TimePattern};

/// The triangle methods, in table order: (name, rasterizer).
pub fn triangle_methods() -> Vec<(String, Box<dyn Rasterizer>)> {
    let mut out: Vec<(String, Box<dyn Rasterizer>)> = vec![
        (
            "production".to_owned(),
            Box::new(crate::production::Production),
        ),
        (
            "production-tiled".to_owned(),
            Box::new(OnPool::new(
                Box::new(crate::production::tiled::Tiled),
                TILED_THREADS,
            )),
        ),
        ("naive".to_owned(), Box::new(NaiveBbox)),
    ];
    let mut names = vec!["float-f32", "float-f64"];
    if cfg!(feature = "tiny-skia") {
        names.push("tiny-skia");
    }
    if cfg!(feature = "euc") {
        names.push("euc");
    }
    if cfg!(feature = "lavapipe") {
        names.push("lavapipe");
    }
    if cfg!(feature = "gl") {
        names.push("gl");
    }
    for name in names {
        if let Some(r) = crate::registry::by_name(name) {
            out.push((name.to_owned(), r));
        }
    }
    out
}

/// Methods whose coverage is exact by construction.
pub(super) fn is_exact(name: &str) -> bool {
    matches!(
        name,
        "production" | "production-tiled" | "naive" | "reference"
    )
}

/// One antialiasing method of the bench: a production pattern, or a
/// measured method of its own.
pub(super) struct AaMethod {
    pub(super) name: String,
    pub(super) antialias: Option<Antialias>,
    pub(super) rasterizer: Box<dyn Rasterizer>,
}

pub(super) fn aa_methods(counts: &[u32]) -> Vec<AaMethod> {
    let production = || -> Box<dyn Rasterizer> { Box::new(crate::production::Production) };
    let with = |samples: u32, pattern: Pattern, adaptive: bool| Antialias {
        samples,
        pattern,
        seed: SEED,
        adaptive,
        position_bits: 8,
    };
    let mut out = vec![AaMethod {
        name: "production 1× (aliased)".to_owned(),
        antialias: None,
        rasterizer: production(),
    }];
    for pattern in [
        Pattern::Standard,
        Pattern::Grid,
        Pattern::Stratified,
        Pattern::Random,
        Pattern::NRooks,
    ] {
        for &n in counts {
            if pattern.check_count(n).is_err() || (pattern == Pattern::Standard && n > 16) {
                continue;
            }
            out.push(AaMethod {
                name: format!("production {n}× {}", pattern.name()),
                antialias: Some(with(n, pattern, false)),
                rasterizer: production(),
            });
        }
    }
    out.push(AaMethod {
        name: "production 16× standard, adaptive".to_owned(),
        antialias: Some(with(16, Pattern::Standard, true)),
        rasterizer: production(),
    });
    out.push(AaMethod {
        name: "adaptive-resolve 16× standard".to_owned(),
        antialias: Some(with(16, Pattern::Standard, true)),
        rasterizer: Box::new(crate::production::adaptive::resolve::AdaptiveResolve),
    });
    for name in ["adaptive-refine", "area-f32", "tiny-skia", "vello-cpu"] {
        if let Some(r) = crate::registry::by_name(name) {
            out.push(AaMethod {
                name: format!("{name} (16× standard case)"),
                antialias: Some(with(16, Pattern::Standard, false)),
                rasterizer: r,
            });
        }
    }
    out
}

/// One motion row: its name, its time pattern and N (none: the static frame
/// at shutter open), and the threads it runs on.
pub(super) type MotionMethod = (String, Option<(TimePattern, u32)>, usize);

pub(super) fn motion_methods() -> Vec<MotionMethod> {
    let mut out = vec![(MOTION_BASELINE.to_owned(), None, 1)];
    for n in [4, 16, 64] {
        out.push((
            format!("production {n}× stratified"),
            Some((TimePattern::Stratified, n)),
            1,
        ));
    }
    out.push((
        "production 16× random".to_owned(),
        Some((TimePattern::Random, 16)),
        1,
    ));
    out.push((
        format!("production-tiled 64× stratified ({TILED_THREADS} threads)"),
        Some((TimePattern::Stratified, 64)),
        TILED_THREADS,
    ));
    out
}

/// The motion workload's baseline: its triangles drawn once at shutter
/// open, as if nothing moved.
pub const MOTION_BASELINE: &str = "production, static at shutter open";
