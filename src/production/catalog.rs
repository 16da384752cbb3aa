//! Every production method measured on its own, by its command-line name:
//! the polygon fills, the antialiasing methods and the parallel one.

use super::adaptive::{AdaptiveRefine, AdaptiveResolve};
use super::antialias::area::AreaF32;
use super::method::Method;
use super::{polygon, tiled};

/// Production's other methods, each measured against the reference on its
/// own.
pub fn methods() -> Vec<Method> {
    let mut all = polygon::methods();
    all.extend([
        Method {
            name: "adaptive-refine",
            make: || Box::new(AdaptiveRefine),
        },
        Method {
            name: "area-f32",
            make: || Box::new(AreaF32),
        },
        Method {
            name: "adaptive-resolve",
            make: || Box::new(AdaptiveResolve),
        },
        Method {
            name: "production-tiled",
            make: || Box::new(tiled::Tiled),
        },
    ]);
    all
}
