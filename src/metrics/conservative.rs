//! A conservative candidate judged pixel by pixel against the reference's
//! three classes (SPEC.md §19.5): a required pixel missing or a forbidden
//! pixel drawn fails; a pixel drawn in the allowed band is counted apart,
//! so a report shows how much of its uncertainty a rasterizer uses. The
//! fully-covered flag is judged the same way at every drawn pixel.

use serde::{Deserialize, Serialize};

use super::conservative_depth::ConservativeDepthMetrics;
use super::coverage::{CoverageMetrics, SampleDiff};
use crate::frame::Frame;
use crate::reference::conservative::{ConservativeClasses, PixelClass};

/// One pixel: its class and whether the candidate drew it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ConservativePixel {
    RequiredDrawn,
    RequiredMissing,
    BandDrawn,
    BandEmpty,
    ForbiddenDrawn,
    ForbiddenEmpty,
}

impl ConservativePixel {
    fn of(class: PixelClass, drawn: bool) -> ConservativePixel {
        match (class, drawn) {
            (PixelClass::Required, true) => ConservativePixel::RequiredDrawn,
            (PixelClass::Required, false) => ConservativePixel::RequiredMissing,
            (PixelClass::Allowed, true) => ConservativePixel::BandDrawn,
            (PixelClass::Allowed, false) => ConservativePixel::BandEmpty,
            (PixelClass::Forbidden, true) => ConservativePixel::ForbiddenDrawn,
            (PixelClass::Forbidden, false) => ConservativePixel::ForbiddenEmpty,
        }
    }

    /// Whether the candidate is wrong here.
    pub fn is_wrong(self) -> bool {
        matches!(
            self,
            ConservativePixel::RequiredMissing | ConservativePixel::ForbiddenDrawn
        )
    }
}

/// The fully-covered flag at the drawn pixels (SPEC.md §19.4).
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct FlagMetrics {
    /// Whether the frame gave a flag per pixel at all.
    pub given: bool,
    /// Drawn pixels whose flag was judged.
    pub judged: u64,
    /// Drawn pixels whose flag must be true, reported false.
    pub false_where_true: u64,
    /// Drawn pixels whose flag must be false, reported true.
    pub true_where_false: u64,
    /// Drawn pixels whose flag may be either (the uncertainty's band, or
    /// an open last writer), and of them those reported true.
    pub band: u64,
    pub band_true: u64,
    /// The first pixel with a wrong flag.
    pub first_wrong: Option<[u32; 2]>,
}

/// Everything measured for one conservative candidate (`report.json`'s
/// `results[].conservative`, without the per-pixel map).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ConservativeMetrics {
    /// The mode and uncertainty judged under ("overestimate, uncertainty
    /// 1/256 px").
    pub judged_under: String,
    /// Where the candidate is judged under its own declared uncertainty or
    /// properties (SPEC.md §19.6), the mode and uncertainty the case
    /// states: a convention, counted apart in the run's summary, never a
    /// failure and never hidden. `None` when judged under the case's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub case_states: Option<String>,
    /// Pixels the reference requires, and in its allowed band.
    pub required: u64,
    pub band: u64,
    pub required_missing: u64,
    pub forbidden_drawn: u64,
    /// Pixels drawn in the allowed band: neither required nor forbidden.
    pub band_drawn: u64,
    pub first_missing: Option<[u32; 2]>,
    pub first_forbidden: Option<[u32; 2]>,
    /// Multisampled (SPEC.md §19.10): drawn pixels with only some of their
    /// samples covered (a conservatively drawn pixel covers all), and the
    /// first.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub partly_covered: u64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_partly_covered: Option<[u32; 2]>,
    pub flag: Option<FlagMetrics>,
    /// The depth at the drawn pixels, for a case with depth (SPEC.md
    /// §19.9, `conservative_depth.rs`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub depth: Option<ConservativeDepthMetrics>,
    /// One entry per pixel, row-major (for the report's picture); not
    /// written to `report.json`.
    #[serde(skip)]
    pub pixels: Vec<ConservativePixel>,
}

/// Whether `frame` draws pixel `i` (row-major): `Some(drawn)` when its
/// samples are all covered or none, `None` when only some are, which no
/// class admits (SPEC.md §19.10).
pub fn pixel_drawn(frame: &Frame, i: usize) -> Option<bool> {
    let n = frame.samples.max(1) as usize;
    let run = frame.coverage.get(i * n..(i + 1) * n)?;
    let any = run.iter().any(|&c| c > 0);
    (run.iter().all(|&c| c > 0) == any).then_some(any)
}

/// Why a candidate's frame cannot be judged against conservative classes:
/// another canvas, or other than `samples` samples per pixel (the case's
/// `effects.antialias` count, 1 without it).
pub fn shape_problem(classes: &ConservativeClasses, frame: &Frame, samples: u32) -> Option<String> {
    if (frame.width, frame.height) != (classes.width, classes.height) {
        return Some(format!(
            "{}×{} for a {}×{} canvas",
            frame.width, frame.height, classes.width, classes.height
        ));
    }
    if frame.samples != samples || frame.coverage.len() != frame.pixel_count() * samples as usize {
        return Some(format!(
            "{} samples per pixel; this conservative scene is drawn with {samples} per pixel (SPEC.md §19.5, §19.10)",
            frame.samples
        ));
    }
    if let Some(flags) = &frame.fully_covered {
        if flags.len() != frame.pixel_count() {
            return Some(format!(
                "{} fully-covered flags for {} pixels",
                flags.len(),
                frame.pixel_count()
            ));
        }
    }
    None
}

/// Measures `frame` against `classes` (same shape: [`shape_problem`]
/// first). `judged_under` names the mode and uncertainty.
pub fn measure(
    classes: &ConservativeClasses,
    frame: &Frame,
    judged_under: String,
) -> ConservativeMetrics {
    let width = classes.width as usize;
    let at = |i: usize| [(i % width) as u32, (i / width) as u32];
    let mut m = ConservativeMetrics {
        judged_under,
        case_states: None,
        required: classes.count(PixelClass::Required) as u64,
        band: classes.count(PixelClass::Allowed) as u64,
        required_missing: 0,
        forbidden_drawn: 0,
        band_drawn: 0,
        first_missing: None,
        first_forbidden: None,
        partly_covered: 0,
        first_partly_covered: None,
        flag: None,
        depth: None,
        pixels: Vec::with_capacity(classes.drawn.len()),
    };
    // A pixel's samples are of its class (SPEC.md §19.10): a required
    // pixel is drawn when all its samples are, any other when any is.
    let samples = frame.samples.max(1) as usize;
    let covered = |i: usize| frame.coverage[i * samples..(i + 1) * samples].iter();
    let any = |i: usize| covered(i).any(|&c| c > 0);
    for (i, &class) in classes.drawn.iter().enumerate() {
        let all = covered(i).all(|&c| c > 0);
        if any(i) && !all {
            m.partly_covered += 1;
            m.first_partly_covered.get_or_insert(at(i));
        }
        let drawn = match class {
            PixelClass::Required => all,
            _ => any(i),
        };
        let pixel = ConservativePixel::of(class, drawn);
        match pixel {
            ConservativePixel::RequiredMissing => {
                m.required_missing += 1;
                m.first_missing.get_or_insert(at(i));
            }
            ConservativePixel::ForbiddenDrawn => {
                m.forbidden_drawn += 1;
                m.first_forbidden.get_or_insert(at(i));
            }
            ConservativePixel::BandDrawn => m.band_drawn += 1,
            _ => {}
        }
        m.pixels.push(pixel);
    }
    m.flag = classes.fully_covered.as_ref().map(|flag_classes| {
        let mut f = FlagMetrics {
            given: frame.fully_covered.is_some(),
            ..FlagMetrics::default()
        };
        let Some(flags) = &frame.fully_covered else {
            return f;
        };
        for (i, (&class, &flag)) in flag_classes.iter().zip(flags).enumerate() {
            if !any(i) {
                continue;
            }
            f.judged += 1;
            match class {
                PixelClass::Required if !flag => f.false_where_true += 1,
                PixelClass::Forbidden if flag => f.true_where_false += 1,
                PixelClass::Allowed => {
                    f.band += 1;
                    f.band_true += u64::from(flag);
                }
                _ => continue,
            }
            if !class.admits(flag) {
                f.first_wrong.get_or_insert(at(i));
            }
        }
        f
    });
    m
}

/// The coverage comparison a conservative candidate reports beside its
/// classes: its pixels against the required set, a pixel drawn in the
/// allowed band counted the same (neither missing nor extra).
pub fn coverage(m: &ConservativeMetrics, frame: &Frame) -> CoverageMetrics {
    let mask: Vec<SampleDiff> = m
        .pixels
        .iter()
        .map(|p| match p {
            ConservativePixel::RequiredMissing => SampleDiff::Missing,
            ConservativePixel::ForbiddenDrawn => SampleDiff::Extra,
            _ => SampleDiff::Same,
        })
        .collect();
    CoverageMetrics {
        samples: mask.len() as u64,
        reference_covered: m.required,
        candidate_covered: frame
            .coverage
            .chunks(frame.samples.max(1) as usize)
            .filter(|run| run.iter().any(|&c| c > 0))
            .count() as u64,
        missing: m.required_missing,
        extra: m.forbidden_drawn,
        wrong_owner: 0,
        mask,
    }
}

/// The reasons a conservative candidate fails, if it does.
pub fn failures(m: &ConservativeMetrics) -> Vec<String> {
    let mut out = Vec::new();
    if let Some([x, y]) = m.first_missing {
        out.push(format!(
            "conservative: {} required pixel(s) not drawn (of {}), first ({x}, {y}) ({})",
            m.required_missing, m.required, m.judged_under
        ));
    }
    if let Some([x, y]) = m.first_forbidden {
        out.push(format!(
            "conservative: {} forbidden pixel(s) drawn, first ({x}, {y}): beyond the allowed band ({})",
            m.forbidden_drawn, m.judged_under
        ));
    }
    if let Some([x, y]) = m.first_partly_covered {
        out.push(format!(
            "conservative: {} drawn pixel(s) with only some of their samples covered, first ({x}, {y}): a conservatively drawn pixel covers all its samples (SPEC.md §19.10)",
            m.partly_covered
        ));
    }
    if let Some(f) = &m.flag {
        if !f.given {
            out.push(
                "conservative: the case asks for the fully-covered flag and the frame gives none"
                    .to_owned(),
            );
        } else if let Some([x, y]) = f.first_wrong {
            out.push(format!(
                "conservative: fully-covered flag wrong at {} drawn pixel(s) ({} false where it must be true, {} true where it must be false), first ({x}, {y})",
                f.false_where_true + f.true_where_false,
                f.false_where_true,
                f.true_where_false
            ));
        }
    }
    out
}

/// One line for the console: "drawn in the allowed band 3 of 12".
pub fn summary(m: &ConservativeMetrics) -> String {
    let mut out = format!(
        "conservative ({}): required {} (missing {}), drawn in the allowed band {} of {}, forbidden drawn {}",
        m.judged_under, m.required, m.required_missing, m.band_drawn, m.band, m.forbidden_drawn
    );
    if m.partly_covered > 0 {
        out.push_str(&format!(", partly covered {}", m.partly_covered));
    }
    if let Some(f) = &m.flag {
        out.push_str(&format!(
            "; flag wrong at {} of {} drawn",
            f.false_where_true + f.true_where_false,
            f.judged
        ));
    }
    if let Some(d) = &m.depth {
        out.push_str("; ");
        out.push_str(&super::conservative_depth::summary(d));
    }
    out
}

fn is_zero(n: &u64) -> bool {
    *n == 0
}
