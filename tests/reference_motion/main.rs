//! The certified time-coverage oracle (SPEC.md §15.2) against brute force:
//! the static reference at many exact instants of the shutter. Also the
//! bound's promises, hand-computed special cases, static primitives in
//! moving scenes, and two deliberately wrong oracles that the comparison
//! catches.
//!
//! The brute force is the midpoint rule over K equal strata of the
//! shutter. At one sample a primitive's coverage is a step function of τ
//! that changes at most C times (a root of one of the polynomials deciding
//! it: C = 8 for a triangle, whose area and three edge functions are
//! quadratics; C = 16 for a line: 2 instants where |dx| = |dy|, the roots
//! of dx and dy, of the 4 end conditions and of the 4 side quadratics,
//! see `motion/moving.rs`). A stratum holding c changes is off by at most
//! min(1, c/2)/K of the shutter, so the rule is within C/(2K) of the exact
//! value: a rigorous tolerance, with no guess about where the roots are.

mod brute;
mod random;
mod scenes;
mod special;
