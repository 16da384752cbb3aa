//! An area method's coverage per primitive, before it is summed.

/// Each primitive's covered fraction of the pixels it touches, as an area
/// method gives it before the fractions are summed into `resolved`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Parts {
    /// Per primitive, in scene order: (pixel index, fraction) for the
    /// pixels it touches; a pixel not listed is 0. A pixel listed twice by
    /// one primitive counts twice, as in the sum.
    pub coverage: Vec<Vec<(u32, f64)>>,
    /// The quantization the rasterizer declares: its fractions are
    /// multiples of `step` (1/255 for 8 bits); 0 when it declares none.
    pub step: f64,
    /// The coverage encoding saturates (`coverage_encoding: "fraction"`,
    /// SPEC.md §12.9): fractions are multiples of `step` = 1/2^k capped at
    /// 1 − step, which then stands for a whole pixel as well as 1 does.
    pub saturates: bool,
}
