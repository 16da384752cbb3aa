//! The reference's answer for a conservative scene (SPEC.md §19): each
//! pixel's class, three-valued, for whether it is drawn and for its
//! fully-covered flag.

/// What a pixel may be, three-valued (SPEC.md §19.1, §19.2, §19.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PixelClass {
    /// Must be drawn (for the flag: must be true).
    Required,
    /// May be drawn or not: the uncertainty's band (for the flag: either).
    Allowed,
    /// Must not be drawn (for the flag: must be false).
    Forbidden,
}

impl PixelClass {
    /// Whether `drawn` (or a flag's value) is what this class permits.
    pub fn admits(self, drawn: bool) -> bool {
        match self {
            PixelClass::Required => drawn,
            PixelClass::Allowed => true,
            PixelClass::Forbidden => !drawn,
        }
    }

    /// The word reports use.
    pub fn name(self) -> &'static str {
        match self {
            PixelClass::Required => "required",
            PixelClass::Allowed => "allowed",
            PixelClass::Forbidden => "forbidden",
        }
    }

    /// The class of a pixel some primitive may draw when an earlier one
    /// left it `self` (SPEC.md §19.5): what either makes required is
    /// required; what neither may draw is forbidden; else allowed.
    pub fn union(self, other: PixelClass) -> PixelClass {
        use PixelClass::{Allowed, Forbidden, Required};
        match (self, other) {
            (Required, _) | (_, Required) => Required,
            (Forbidden, Forbidden) => Forbidden,
            _ => Allowed,
        }
    }
}

/// Each pixel's class for one conservative scene, row-major from the
/// top-left: whether it is drawn (`drawn`), and, when the case asks for
/// the flag, what its fully-covered flag may be where it is drawn
/// (`fully_covered`: the flag of the fragment its last writer leaves,
/// SPEC.md §19.4).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ConservativeClasses {
    pub width: u32,
    pub height: u32,
    pub drawn: Vec<PixelClass>,
    pub fully_covered: Option<Vec<PixelClass>>,
    /// Index + 1 of the last primitive that must draw each pixel; 0 where
    /// none must.
    pub last_required: Vec<u32>,
}

impl ConservativeClasses {
    /// Every pixel forbidden, the flag (when asked) false.
    pub fn empty(width: u32, height: u32, flag: bool) -> ConservativeClasses {
        let n = width as usize * height as usize;
        ConservativeClasses {
            width,
            height,
            drawn: vec![PixelClass::Forbidden; n],
            fully_covered: flag.then(|| vec![PixelClass::Forbidden; n]),
            last_required: vec![0; n],
        }
    }

    /// How many pixels are of `class`.
    pub fn count(&self, class: PixelClass) -> usize {
        self.drawn.iter().filter(|&&c| c == class).count()
    }
}
