//! Outputs for people: magnified PNG images of frames and their differences.

pub mod png;
