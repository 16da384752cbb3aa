//! One convention probe, for clipping (`clip.rs`) and for points
//! (`points.rs`): scenes stated under two of four combinations of a pair of
//! conventions, each drawn by the candidate and compared, sample by sample
//! (count and owner), with the reference under every combination. What the
//! mismatch counts conclude ([`conclude`], through `verdict.rs`) is the
//! same for both; only the pair's names differ.

use std::marker::PhantomData;

use serde::ser::{Serialize, SerializeStruct, Serializer};

use super::verdict::{verdict, Verdict};
use crate::frame::Frame;

/// A combination of two conventions a probe tells apart.
pub trait Convention: Copy {
    /// The profile's names for the two conventions (`clip_xy`, `clip_z`).
    const FIELDS: [&'static str; 2];
    /// What the probe scenes are called in a finding ("clipping").
    const SCENES: &'static str;
    /// The names of this combination's two values.
    fn names(self) -> [&'static str; 2];
}

/// What a convention probe found. Written into the profile with the
/// pair's own field names (`clip_xy`/`clip_z`, `clip_points`/`point_bounds`)
/// in place of `own`.
#[derive(Clone, Debug)]
pub struct ConventionProbe<C> {
    /// "follows each case's clip_xy and clip_z", "its own: clip_xy
    /// guard-band, clip_z per-sample" (fixed), or the nearest combination
    /// and why it is not certain.
    pub finding: String,
    /// Whether it follows each case's conventions.
    pub follows_case: bool,
    /// Its own two conventions, when they are fixed (or the nearest).
    pub own: Option<[&'static str; 2]>,
    /// Whether one answer explains every sample of every scene.
    pub consistent: bool,
    /// Samples that differ from the reference under each combination,
    /// per statement: `[stated][combination]`, combinations in the order
    /// the probe lists them.
    pub mismatches: Vec<Vec<usize>>,
    /// Scenes drawn, or found to separate the combinations.
    pub scenes: usize,
    convention: PhantomData<C>,
}

impl<C: Convention> Serialize for ConventionProbe<C> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut out = s.serialize_struct("ConventionProbe", 7)?;
        out.serialize_field("finding", &self.finding)?;
        out.serialize_field("follows_case", &self.follows_case)?;
        out.serialize_field(C::FIELDS[0], &self.own.map(|o| o[0]))?;
        out.serialize_field(C::FIELDS[1], &self.own.map(|o| o[1]))?;
        out.serialize_field("consistent", &self.consistent)?;
        out.serialize_field("mismatches", &self.mismatches)?;
        out.serialize_field("scenes", &self.scenes)?;
        out.end()
    }
}

fn describe<C: Convention>(c: C) -> String {
    let [a, b] = C::FIELDS;
    let [x, y] = c.names();
    format!("{a} {x}, {b} {y}")
}

/// Samples whose coverage count or owner differ.
pub(super) fn differing(a: &Frame, b: &Frame) -> usize {
    (0..a.coverage.len())
        .filter(|&i| a.coverage[i] != b.coverage[i] || a.last[i] != b.last[i])
        .count()
}

/// What `mismatches` (per statement, over `all`) say, the statements being
/// `all[0]` and `all[3]` (the defaults and their opposite); `drawn` is
/// whether the candidate drew any scene, `scenes` the count reported.
pub(super) fn conclude<C: Convention>(
    all: &[C; 4],
    mismatches: Vec<Vec<usize>>,
    drawn: bool,
    scenes: usize,
) -> ConventionProbe<C> {
    let probe =
        |finding: String, follows_case, own: Option<C>, consistent, mismatches| ConventionProbe {
            finding,
            follows_case,
            own: own.map(C::names),
            consistent,
            mismatches,
            scenes,
            convention: PhantomData,
        };
    if !drawn {
        let finding = format!("unknown: it drew none of the {} scenes", C::SCENES);
        return probe(finding, false, None, false, mismatches);
    }
    let Verdict {
        follows,
        fixed,
        best,
        nearest,
    } = verdict(&mismatches, [0, 3]);
    let (finding, own) = if follows {
        let [a, b] = C::FIELDS;
        (format!("follows each case's {a} and {b}"), None)
    } else if fixed {
        (format!("its own: {}", describe(all[best])), Some(all[best]))
    } else {
        (
            format!(
                "nearest {} ({} samples differ over {scenes} scenes stated twice); inconsistent",
                describe(all[nearest]),
                mismatches[0][nearest] + mismatches[1][nearest],
            ),
            Some(all[nearest]),
        )
    };
    probe(finding, follows, own, follows || fixed, mismatches)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{PointBounds, PointClip};

    /// The profile keeps each probe's own field names, in their order.
    #[test]
    fn a_probe_is_written_with_its_pairs_names() {
        let all = [
            (PointClip::Pop, PointBounds::Canvas),
            (PointClip::Pop, PointBounds::Viewport),
            (PointClip::GuardBand, PointBounds::Canvas),
            (PointClip::GuardBand, PointBounds::Viewport),
        ];
        let fixed = conclude(&all, vec![vec![3, 0, 2, 1], vec![3, 0, 2, 1]], true, 5);
        assert_eq!(
            fixed.finding,
            "its own: clip_points pop, point_bounds viewport"
        );
        let json = serde_json::to_string(&fixed).unwrap();
        assert_eq!(
            json,
            r#"{"finding":"its own: clip_points pop, point_bounds viewport","follows_case":false,"clip_points":"pop","point_bounds":"viewport","consistent":true,"mismatches":[[3,0,2,1],[3,0,2,1]],"scenes":5}"#
        );
        let follows = conclude(&all, vec![vec![0, 1, 1, 1], vec![1, 1, 1, 0]], true, 5);
        assert!(follows.follows_case && follows.consistent);
        assert_eq!(
            follows.finding,
            "follows each case's clip_points and point_bounds"
        );
        let none = conclude(&all, vec![vec![0; 4]; 2], false, 0);
        assert_eq!(none.finding, "unknown: it drew none of the point scenes");
    }
}
