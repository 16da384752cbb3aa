//! Polygons (SPEC.md §14.1 and §14.2): production's scanline fill against
//! the reference, sample for sample (counts and owners), on random stars, concave, self-intersecting and multi-contour
//! polygons with vertices on pixel centres and half-integers, under all four
//! tie rules and both fills, with and without antialiasing; the convex and
//! tessellating methods where they apply; the flood-fill foil departing on a
//! sliver; and a wrong tie caught.
//!
//! The reference is itself checked against a brute force written here,
//! which decides each sample from scratch as SPEC.md words it (the nudged
//! ray to +x, one exact i128 sign per edge), sharing no code with either.

mod methods;
mod scanline;
mod shapes;
