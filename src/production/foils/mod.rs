//! Foils: deliberately inexact rasterizers built from production, to show
//! what the exact reference catches that a looser check would not. They are
//! not candidates for correctness; each documents where it departs from
//! SPEC.md.

/// Declares a foil: a unit struct whose `Rasterizer` impl gives its name,
/// says it is a foil, takes production's capabilities, and draws with the
/// given function of the scene and plan.
macro_rules! foil {
    ($(#[$doc:meta])* $name:ident, $label:literal, $draw:expr) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, Default)]
        pub struct $name;

        impl Rasterizer for $name {
            fn name(&self) -> &str {
                $label
            }

            fn is_foil(&self) -> bool {
                true
            }

            fn capabilities(&self) -> Capabilities {
                Capabilities {
                    polygons: false,
                    antialias: false,
                    motion_blur: false,
                    ..Production.capabilities()
                }
            }

            fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
                $draw(scene, plan)
            }
        }
    };
}

pub mod any_coverage;
pub mod area_sampler;
pub mod dda;
pub mod float_edges;
pub mod offset_sampler;

pub use any_coverage::AnyCoverage;
pub use area_sampler::AreaSampler;
pub use dda::{DdaF32, DdaF64};
pub use float_edges::{FloatF32, FloatF64};
pub use offset_sampler::OffsetSampler;

/// The foils that sample otherwise than at one point per pixel centre,
/// each wrong in that one way (what `probe` must tell apart).
pub const SAMPLER_FOILS: [&str; 3] = [
    "foil-offset-sampler",
    "foil-area-sampler",
    "foil-any-coverage",
];
