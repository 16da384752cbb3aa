//! The antialiasing methods that are rasterizers of their own, by name.

use super::refine::AdaptiveRefine;
use super::{area, resolve};
use crate::production::method::Method;

/// The antialiasing methods that are rasterizers of their own.
pub fn methods() -> Vec<Method> {
    vec![
        Method {
            name: "adaptive-refine",
            make: || Box::new(AdaptiveRefine),
        },
        Method {
            name: "area-f32",
            make: || Box::new(area::AreaF32),
        },
        Method {
            name: "adaptive-resolve",
            make: || Box::new(resolve::AdaptiveResolve),
        },
    ]
}
