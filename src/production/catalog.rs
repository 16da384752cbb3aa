//! Every production method measured on its own: the polygon fills, the
//! antialiasing methods and the parallel one.

use super::method::Method;
use super::{antialias, polygon, tiled};

/// Production's other methods, each measured against the reference on its
/// own.
pub fn methods() -> Vec<Method> {
    let mut all = polygon::methods();
    all.extend(antialias::methods());
    all.push(Method {
        name: "production-tiled",
        make: || Box::new(tiled::Tiled),
    });
    all
}
