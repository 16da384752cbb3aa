//! The declarations foils share: `foil!`, a unit struct drawing with its
//! own function under production's capabilities, less those it lacks (or
//! the ones given, and the conservative support given); and
//! `coverage_foil!`, one that draws triangles' coverage and nothing else.

/// Declares a foil: a unit struct whose `Rasterizer` impl gives its name,
/// says it is a foil, takes production's capabilities (or, after
/// `capabilities:`, the ones given), declares no conservative support (or,
/// after `conservative:`, the `ConservativeSupport` given), and draws with
/// the given function of the scene and plan.
macro_rules! foil {
    (@declare $(#[$doc:meta])* $name:ident, $label:literal, $capabilities:expr, $conservative:expr, $draw:expr) => {
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
                $capabilities
            }

            fn conservative(&self) -> Option<$crate::scene::ConservativeSupport> {
                $conservative
            }

            fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
                $draw(scene, plan)
            }
        }
    };
    ($(#[$doc:meta])* $name:ident, $label:literal, capabilities: $capabilities:expr, conservative: $conservative:expr, $draw:expr) => {
        $crate::production::foils::declare::foil!(
            @declare $(#[$doc])* $name, $label, $capabilities, Some($conservative), $draw
        );
    };
    ($(#[$doc:meta])* $name:ident, $label:literal, $draw:expr) => {
        $crate::production::foils::declare::foil!(
            $(#[$doc])* $name,
            $label,
            capabilities: Capabilities {
                polygons: false,
                antialias: false,
                motion_blur: false,
                clip_space: false,
                points: false,
                ..Production.capabilities()
            },
            $draw
        );
    };
    ($(#[$doc:meta])* $name:ident, $label:literal, capabilities: $capabilities:expr, $draw:expr) => {
        $crate::production::foils::declare::foil!(
            @declare $(#[$doc])* $name, $label, $capabilities, None, $draw
        );
    };
}

pub(super) use foil;

/// Declares a coverage-only triangle foil: a [`foil!`] that takes
/// triangles (at any coordinates) and nothing else, refuses a plan that
/// asks for depth or attributes, and otherwise draws with the given
/// function of the scene and plan.
macro_rules! coverage_foil {
    ($(#[$doc:meta])* $name:ident, $label:literal, $draw:expr) => {
        $crate::production::foils::declare::foil!(
            $(#[$doc])* $name,
            $label,
            capabilities: Capabilities {
                triangles: true,
                ideal_geometry: true,
                ..Capabilities::none()
            },
            |scene: &Scene, plan: &Plan| -> Result<Frame, RasterError> {
                if plan.interpolates() {
                    return Err(RasterError::Unsupported(
                        concat!($label, " draws coverage only, not depth or attributes").to_owned(),
                    ));
                }
                $draw(scene, plan)
            }
        );
    };
}

pub(super) use coverage_foil;
