//! Points and lines set up for conservative tests (SPEC.md §19.8), in
//! production's integer units of 1/`one` px: a point's square, a
//! `parallelogram` line's band (its ends on the major axis, its width along
//! the minor), a `rectangle` line's rectangle. Per pixel, whether a square
//! centred on the pixel, of half side s = num/den units, meets the shape or
//! lies inside it.
//!
//! Each shape is tested by the edge functions of its sides at the pixel's
//! centre, moved by the square's half extent along each normal, as
//! `triangle.rs` does for triangles: over a square of half side s an edge
//! function of normal (A, B) ranges over E(c) ± (|A| + |B|)·s. The
//! rectangle's half width h reaches h·|d| along its normal and its corners
//! h·|d_y|/|d| past its ends on x: irrational, so those comparisons are
//! squared. Half sizes and half widths are exact fractions of units. Every
//! product is a big integer: the comparisons here are few per pixel and
//! their squares outgrow i128.

use dashu_int::IBig;

/// An exact fraction of units, n / d with d > 0.
#[derive(Clone, Debug)]
pub(crate) struct Frac {
    pub(crate) n: IBig,
    pub(crate) d: IBig,
}

/// A point or a line, ready for per-pixel tests.
#[derive(Clone, Debug)]
pub(crate) enum LineShape {
    /// A point's square: centre `c`, half side `h`. A degenerate line
    /// drawn is a square of half side 0.
    Square { c: [i128; 2], h: Frac },
    /// A parallelogram line from `a` to `b`: major axis `k` (0 for x-major,
    /// |d_x| ≥ |d_y|), half width `h` along the other.
    Band {
        a: [i128; 2],
        b: [i128; 2],
        k: usize,
        h: Frac,
    },
    /// A rectangle line from `a` to `b` (a ≠ b), half width `h`.
    Rectangle { a: [i128; 2], b: [i128; 2], h: Frac },
}

fn big(v: i128) -> IBig {
    IBig::from(v)
}

/// Whether a ≤ 0 or a² ≤ b (b ≥ 0): a ≤ √b.
fn at_most_root(a: &IBig, b: &IBig) -> bool {
    *a <= IBig::ZERO || a * a <= *b
}

impl LineShape {
    /// Whether the square centred at `c` (units) of half side num/den
    /// meets the shape (overestimation, SPEC.md §19.8).
    pub(crate) fn meets(&self, c: [i128; 2], num: &IBig, den: &IBig) -> bool {
        match self {
            LineShape::Square { c: p, h } => (0..2).all(|k| {
                // |c − p| ≤ s + h: |c − p|·den·hd ≤ num·hd + hn·den.
                big((c[k] - p[k]).abs()) * den * &h.d <= num * &h.d + &h.n * den
            }),
            LineShape::Band { a, b, k, h } => {
                let (k, m) = (*k, 1 - *k);
                // Both axes of the square against the band's box: the
                // major axis exactly, the minor grown by h.
                let reach = |lo: i128, hi: i128, v: i128, grow: &Frac| {
                    let gap = (v - hi).max(lo - v);
                    big(gap) * den * &grow.d <= num * &grow.d + &grow.n * den
                };
                let zero = Frac {
                    n: IBig::ZERO,
                    d: IBig::ONE,
                };
                if !reach(a[k].min(b[k]), a[k].max(b[k]), c[k], &zero)
                    || !reach(a[m].min(b[m]), a[m].max(b[m]), c[m], h)
                {
                    return false;
                }
                // The sides: |E(c)| − K·s ≤ h·|d_k|.
                let (e, kk, dk) = band_edge(a, b, k, m, c);
                big(e.abs()) * den * &h.d - big(kk) * num * &h.d <= &h.n * big(dk.abs()) * den
            }
            LineShape::Rectangle { a, b, h } => {
                let r = Rect::new(a, b, c);
                // Along d: E_d(c) ± K·s overlaps [0, |d|²].
                if big(r.along) * den + big(r.k) * num < IBig::ZERO
                    || big(r.along) * den - big(r.k) * num > big(r.length2) * den
                {
                    return false;
                }
                // Across: |E_n(c)| − K·s ≤ h·|d|, squared.
                let v = (big(r.across.abs()) * den - big(r.k) * num) * &h.d;
                let reach2 = &h.n * &h.n * big(r.length2) * den * den;
                if !at_most_root(&v, &reach2) {
                    return false;
                }
                // x and y: the ends' range grown by h·|d_other|/|d|:
                // gap·|d| ≤ h·|d_other|, squared.
                (0..2).all(|axis| {
                    let lo = a[axis].min(b[axis]);
                    let hi = a[axis].max(b[axis]);
                    let other = big(r.d[1 - axis]);
                    let reach2 = &h.n * &h.n * &other * &other * den * den;
                    [c[axis] - hi, lo - c[axis]].into_iter().all(|gap| {
                        let g = (big(gap) * den - num) * &h.d;
                        g <= IBig::ZERO || &g * &g * big(r.length2) <= reach2
                    })
                })
            }
        }
    }

    /// Whether the square centred at `c` of half side num/den lies inside
    /// the shape (underestimation and the fully-covered flag).
    pub(crate) fn holds(&self, c: [i128; 2], num: &IBig, den: &IBig) -> bool {
        match self {
            LineShape::Square { c: p, h } => (0..2).all(|k| {
                // |c − p| + s ≤ h.
                big((c[k] - p[k]).abs()) * den * &h.d + num * &h.d <= &h.n * den
            }),
            LineShape::Band { a, b, k, h } => {
                let (k, m) = (*k, 1 - *k);
                let (lo, hi) = (a[k].min(b[k]), a[k].max(b[k]));
                if big(c[k] - lo) * den < *num || big(hi - c[k]) * den < *num {
                    return false;
                }
                let (e, kk, dk) = band_edge(a, b, k, m, c);
                big(e.abs()) * den * &h.d + big(kk) * num * &h.d <= &h.n * big(dk.abs()) * den
            }
            LineShape::Rectangle { a, b, h } => {
                let r = Rect::new(a, b, c);
                if big(r.along) * den - big(r.k) * num < IBig::ZERO
                    || big(r.along) * den + big(r.k) * num > big(r.length2) * den
                {
                    return false;
                }
                let v = (big(r.across.abs()) * den + big(r.k) * num) * &h.d;
                &v * &v <= &h.n * &h.n * big(r.length2) * den * den
            }
        }
    }

    /// The shape's box in units, [x0, y0, x1, y1], a superset: grown by
    /// its half width rounded up.
    pub(crate) fn bounds(&self) -> [i128; 4] {
        let (p, q, h) = match self {
            LineShape::Square { c, h } => (c, c, h),
            LineShape::Band { a, b, h, .. } | LineShape::Rectangle { a, b, h } => (a, b, h),
        };
        let grow = i128::try_from(&((&h.n + &h.d - IBig::ONE) / &h.d)).unwrap_or(i128::MAX / 4);
        [
            p[0].min(q[0]) - grow,
            p[1].min(q[1]) - grow,
            p[0].max(q[0]) + grow,
            p[1].max(q[1]) + grow,
        ]
    }
}

/// A band's side function at `c`: E = (c_m − a_m)·d_k − (c_k − a_k)·d_m,
/// with |E| ≤ h·|d_k| inside; K = |d_k| + |d_m|; and d_k.
fn band_edge(a: &[i128; 2], b: &[i128; 2], k: usize, m: usize, c: [i128; 2]) -> (i128, i128, i128) {
    let d = [b[0] - a[0], b[1] - a[1]];
    let e = (c[m] - a[m]) * d[k] - (c[k] - a[k]) * d[m];
    (e, d[k].abs() + d[m].abs(), d[k])
}

/// A rectangle line's edge functions at a pixel's centre.
struct Rect {
    d: [i128; 2],
    length2: i128,
    /// d·(c − a).
    along: i128,
    /// d × (c − a).
    across: i128,
    /// |d_x| + |d_y|.
    k: i128,
}

impl Rect {
    fn new(a: &[i128; 2], b: &[i128; 2], c: [i128; 2]) -> Rect {
        let d = [b[0] - a[0], b[1] - a[1]];
        let q = [c[0] - a[0], c[1] - a[1]];
        Rect {
            d,
            length2: d[0] * d[0] + d[1] * d[1],
            along: q[0] * d[0] + q[1] * d[1],
            across: d[0] * q[1] - d[1] * q[0],
            k: d[0].abs() + d[1].abs(),
        }
    }
}
