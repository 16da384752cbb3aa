//! The declarations foils share: `foil!`, a unit struct drawing with its
//! own function under production's capabilities, less those it lacks; and
//! `coverage_foil!`, one that draws triangles' coverage and nothing else.

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
                    clip_space: false,
                    points: false,
                    ..Production.capabilities()
                }
            }

            fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
                $draw(scene, plan)
            }
        }
    };
}

pub(super) use foil;

/// Declares a coverage-only triangle foil: a unit struct whose
/// `Rasterizer` impl gives its name, says it is a foil, takes triangles
/// (at any coordinates) and nothing else, refuses a plan that asks for
/// depth or attributes, and draws with the given function of the scene
/// and plan.
macro_rules! coverage_foil {
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
                    triangles: true,
                    ideal_geometry: true,
                    ..Capabilities::none()
                }
            }

            fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
                if plan.interpolates() {
                    return Err(RasterError::Unsupported(
                        concat!($label, " draws coverage only, not depth or attributes").to_owned(),
                    ));
                }
                $draw(scene, plan)
            }
        }
    };
}

pub(super) use coverage_foil;
