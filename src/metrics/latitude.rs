//! A candidate that draws `diamond-exit` lines with the latitude its API
//! allows (Vulkan's Bresenham lines, GL's aliased lines; SPEC.md §4.2.1)
//! judged under that latitude against each line's exact diamond-exit
//! fragments (`reference::diamond_lines`):
//!
//! 1. each fragment lies within one unit in x and in y of a diamond-exit
//!    fragment of its line;
//! 2. a line's fragment count differs from the diamond-exit count by at
//!    most one;
//! 3. an x-major line has no two fragments in one column (y-major: row);
//! 4. two connected segments (one ends where the next starts, both
//!    x-major or both y-major, running the same way) draw no fragment
//!    twice.
//!
//! Every pixel within one unit of some line's diamond-exit fragment (the
//! latitude's reach) is judged here instead of sample by sample: its count
//! must lie between what the other primitives give it and that plus the
//! lines that may reach it. Every other pixel is judged exactly. A
//! fragment a later primitive covers cannot be seen: rules 2 and 4 are
//! judged on what can be seen, a rule failing only when no hidden
//! fragment could save it, and the hidden places are counted (`unseen`).
//! The fragments that used the latitude are counted too, never hidden.
//!
//! What this does not judge: the spec's "fragments also must not be
//! omitted so as to interrupt continuity of the connected segments",
//! which states no measure; nor a scene with more than one sample per
//! pixel (the latitude is stated for aliased lines).

use std::collections::{BTreeMap, HashSet};

use serde::{Deserialize, Serialize};

use super::counted::counted;
use super::coverage::{CoverageMetrics, SampleDiff};
use crate::frame::Frame;
use crate::reference::DiamondLine;

/// What a candidate made of its diamond-exit lines under the latitude.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct LatitudeMetrics {
    /// Diamond-exit lines judged.
    pub lines: u64,
    /// Fragments off the exact set but within one unit of it (allowed).
    pub moved: u64,
    /// Lines with one fragment more or fewer than the exact set (allowed).
    pub count_changed: u64,
    /// Places where a later primitive hides a possible fragment.
    pub unseen: u64,
    /// Rule 1: fragments more than one unit from every fragment of their line.
    pub too_far: u64,
    /// Rule 2: lines whose count differs by more than one.
    pub count_off: u64,
    /// Rule 3: columns (x-major) or rows (y-major) holding two fragments of one line.
    pub crowded: u64,
    /// Rule 4: pixels drawn by both of two connected segments.
    pub duplicated: u64,
    /// Pixels in the latitude's reach covered more often than the lines
    /// that may reach them and the other primitives explain.
    pub overdrawn: u64,
    /// Pixels in the latitude's reach covered less often than the other
    /// primitives cover them.
    pub underdrawn: u64,
}

impl LatitudeMetrics {
    /// The console's and the case page's line.
    pub fn line(&self) -> String {
        let mut line = format!(
            "judged under the latitude for diamond-exit lines (Vulkan Bresenham lines, GL 4.6 §14.5.1): {}, {} moved by one unit, {} one fragment off",
            counted(self.lines, "line", "lines"),
            counted(self.moved, "fragment", "fragments"),
            counted(self.count_changed, "line", "lines")
        );
        if self.unseen > 0 {
            line.push_str(&format!(
                ", {} hidden by later primitives",
                counted(self.unseen, "place", "places")
            ));
        }
        line
    }

    /// Why it breaks the latitude; empty when it keeps to it. Each reason
    /// is said in the number its count takes ("1 line differs", "2 lines
    /// differ").
    pub fn failures(&self) -> Vec<String> {
        let mut out = Vec::new();
        let mut say = |n: u64, one: &str, many: &str| {
            if n > 0 {
                out.push(format!("lines (latitude): {}", counted(n, one, many)));
            }
        };
        say(
            self.too_far,
            "fragment lies more than one unit from every diamond-exit fragment of its line",
            "fragments lie more than one unit from every diamond-exit fragment of their line",
        );
        say(
            self.count_off,
            "line differs from the diamond-exit fragment count by more than one",
            "lines differ from the diamond-exit fragment count by more than one",
        );
        say(
            self.crowded,
            "major-axis step holds two fragments of one line",
            "major-axis steps hold two fragments of one line",
        );
        say(
            self.duplicated,
            "pixel is drawn by both of two connected segments",
            "pixels are drawn by both of two connected segments",
        );
        say(
            self.overdrawn,
            "pixel is covered more often than the lines that may reach it allow",
            "pixels are covered more often than the lines that may reach them allow",
        );
        say(
            self.underdrawn,
            "pixel near a line misses the other primitives' coverage",
            "pixels near a line miss the other primitives' coverage",
        );
        out
    }
}

/// The latitude judgement of `candidate`'s diamond-exit lines; `None` when
/// it has not one sample per pixel lining up with the reference's. The
/// reach of the latitude is then taken out of `coverage`'s exact
/// comparison (it is judged here).
pub fn measure(
    lines: &[DiamondLine],
    reference: &Frame,
    candidate: &Frame,
    coverage: &mut CoverageMetrics,
) -> Option<LatitudeMetrics> {
    if candidate.samples != 1
        || reference.samples != 1
        || candidate.coverage.len() != reference.coverage.len()
        || candidate.last.len() != reference.last.len()
        || coverage.mask.len() != reference.coverage.len()
    {
        return None;
    }
    let (w, h) = (reference.width as i64, reference.height as i64);
    let pixels = reference.coverage.len();
    let xy = |p: usize| (p as i64 % w, p as i64 / w);
    let near = |p: usize| {
        let (x, y) = xy(p);
        (-1..=1)
            .flat_map(move |dy| (-1..=1).map(move |dx| (x + dx, y + dy)))
            .filter(|&(x, y)| x >= 0 && y >= 0 && x < w && y < h)
            .map(move |(x, y)| (y * w + x) as usize)
    };
    let exact: Vec<HashSet<usize>> = lines
        .iter()
        .map(|l| l.pixels.iter().copied().collect())
        .collect();
    let reach: Vec<HashSet<usize>> = lines
        .iter()
        .map(|l| l.pixels.iter().flat_map(|&p| near(p)).collect())
        .collect();
    // Per pixel: lines lighting it exactly, lines that may reach it.
    let mut lit = vec![0u16; pixels];
    let mut reachable = vec![0u16; pixels];
    for (e, r) in exact.iter().zip(&reach) {
        e.iter().for_each(|&p| lit[p] += 1);
        r.iter().for_each(|&p| reachable[p] += 1);
    }
    let mut m = LatitudeMetrics {
        lines: lines.len() as u64,
        ..LatitudeMetrics::default()
    };
    for p in (0..pixels).filter(|&p| reachable[p] > 0) {
        // What the other primitives give it, exactly.
        let others = reference.coverage[p].saturating_sub(lit[p]);
        let c = candidate.coverage[p];
        m.overdrawn += u64::from(c > others + reachable[p]);
        m.underdrawn += u64::from(c < others);
        match std::mem::replace(&mut coverage.mask[p], SampleDiff::Same) {
            SampleDiff::Missing => coverage.missing -= 1,
            SampleDiff::Extra => coverage.extra -= 1,
            SampleDiff::WrongOwner => coverage.wrong_owner -= 1,
            SampleDiff::Same | SampleDiff::Tie => {}
        }
    }
    for (k, line) in lines.iter().enumerate() {
        let id = line.primitive as u32 + 1;
        let major = |p: usize| if line.x_major { xy(p).0 } else { xy(p).1 };
        let seen: Vec<usize> = (0..pixels).filter(|&p| candidate.last[p] == id).collect();
        let mut steps: BTreeMap<i64, u64> = BTreeMap::new();
        for &p in &seen {
            if !exact[k].contains(&p) {
                if near(p).any(|q| exact[k].contains(&q)) {
                    m.moved += 1;
                } else {
                    m.too_far += 1;
                }
            }
            *steps.entry(major(p)).or_default() += 1;
        }
        m.crowded += steps.values().filter(|&&n| n > 1).count() as u64;
        // Steps where a later primitive may hide one of its fragments.
        let hidden: HashSet<i64> = reach[k]
            .iter()
            .filter(|&&p| candidate.last[p] > id)
            .map(|&p| major(p))
            .filter(|s| !steps.contains_key(s))
            .collect();
        let (seen, hidden, exact_count) = (seen.len(), hidden.len(), exact[k].len());
        m.unseen += hidden as u64;
        if seen > exact_count + 1 || seen + hidden + 1 < exact_count {
            m.count_off += 1;
        } else if hidden == 0 && seen != exact_count {
            m.count_changed += 1;
        }
    }
    for (a, first) in lines.iter().enumerate() {
        for (b, next) in lines.iter().enumerate() {
            if a == b || !first.joins(next) {
                continue;
            }
            let ids = [first.primitive as u32 + 1, next.primitive as u32 + 1];
            m.duplicated += reach[a]
                .intersection(&reach[b])
                .filter(|&&p| {
                    reachable[p] == 2
                        && reference.coverage[p] == lit[p]
                        && candidate.coverage[p] >= 2
                        && ids.contains(&candidate.last[p])
                })
                .count() as u64;
        }
    }
    Some(m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::coverage::compare;
    use crate::plan::Plan;
    use crate::reference::{diamond_lines, render};
    use crate::scene::{parse_case, Limits, Scene};

    fn scene(lines: &str) -> Scene {
        let text = format!(
            r#"{{"name": "t", "canvas": {{"width": 12, "height": 8}},
                "rules": {{"subpixel_bits": 8}}, "primitives": [{lines}]}}"#
        );
        parse_case(&text, "t.json", &Limits::default()).unwrap()
    }

    /// The reference's frame, the candidate `edit` makes of it, and the
    /// latitude metrics with the exact comparison left.
    fn judged(scene: &Scene, edit: impl Fn(&mut Frame)) -> (LatitudeMetrics, CoverageMetrics) {
        let plan = Plan::for_scene(scene);
        let reference = render(scene, &plan);
        let mut candidate = reference.clone();
        edit(&mut candidate);
        let lines = diamond_lines(scene, &plan).unwrap();
        let mut coverage = compare(&reference, &candidate);
        let m = measure(&lines, &reference, &candidate, &mut coverage).unwrap();
        (m, coverage)
    }

    fn set(frame: &mut Frame, x: u32, y: u32, count: u16, last: u32) {
        let i = frame.index(x, y);
        frame.coverage[i] = count;
        frame.last[i] = last;
    }

    const SHALLOW: &str = r#"{"line": [[1.5, 1.5], [9.5, 5.5]], "rule": "diamond-exit"}"#;

    #[test]
    fn the_exact_line_keeps_to_the_latitude_without_using_it() {
        let (m, c) = judged(&scene(SHALLOW), |_| {});
        assert!(m.failures().is_empty(), "{m:?}");
        assert_eq!((m.moved, m.count_changed, c.mismatched()), (0, 0, 0));
    }

    #[test]
    fn one_unit_is_latitude_and_two_are_not() {
        // (5,3) is lit exactly; (5,4) is one unit off, (5,5) two.
        let (m, c) = judged(&scene(SHALLOW), |f| {
            set(f, 5, 3, 0, 0);
            set(f, 5, 4, 1, 1);
        });
        assert!(m.failures().is_empty(), "{m:?}");
        assert_eq!((m.moved, c.mismatched()), (1, 0));
        let (m, c) = judged(&scene(SHALLOW), |f| {
            set(f, 5, 3, 0, 0);
            set(f, 5, 5, 1, 1);
        });
        assert_eq!(m.too_far, 1, "{m:?}");
        assert_eq!(
            c.extra, 1,
            "two units off lies outside the reach: judged exactly"
        );
    }

    #[test]
    fn a_ninth_fragment_is_latitude_and_a_tenth_is_not() {
        // Eight exact fragments, (1,1) .. (8,4); (9,5) is the one it may add.
        let (m, _) = judged(&scene(SHALLOW), |f| set(f, 9, 5, 1, 1));
        assert!(m.failures().is_empty(), "{m:?}");
        assert_eq!(m.count_changed, 1);
        let (m, _) = judged(&scene(SHALLOW), |f| {
            set(f, 9, 5, 1, 1);
            set(f, 0, 0, 1, 1);
        });
        assert_eq!(m.count_off, 1, "{m:?}");
    }

    #[test]
    fn failure_reasons_take_the_number_of_their_count() {
        let one = LatitudeMetrics {
            too_far: 1,
            count_off: 1,
            crowded: 1,
            duplicated: 1,
            overdrawn: 1,
            underdrawn: 1,
            ..LatitudeMetrics::default()
        };
        assert_eq!(
            one.failures(),
            [
                "lines (latitude): 1 fragment lies more than one unit from every diamond-exit fragment of its line",
                "lines (latitude): 1 line differs from the diamond-exit fragment count by more than one",
                "lines (latitude): 1 major-axis step holds two fragments of one line",
                "lines (latitude): 1 pixel is drawn by both of two connected segments",
                "lines (latitude): 1 pixel is covered more often than the lines that may reach it allow",
                "lines (latitude): 1 pixel near a line misses the other primitives' coverage",
            ]
        );
        let two = LatitudeMetrics {
            too_far: 2,
            count_off: 2,
            crowded: 2,
            duplicated: 2,
            overdrawn: 2,
            underdrawn: 2,
            ..LatitudeMetrics::default()
        };
        assert_eq!(
            two.failures(),
            [
                "lines (latitude): 2 fragments lie more than one unit from every diamond-exit fragment of their line",
                "lines (latitude): 2 lines differ from the diamond-exit fragment count by more than one",
                "lines (latitude): 2 major-axis steps hold two fragments of one line",
                "lines (latitude): 2 pixels are drawn by both of two connected segments",
                "lines (latitude): 2 pixels are covered more often than the lines that may reach them allow",
                "lines (latitude): 2 pixels near a line miss the other primitives' coverage",
            ]
        );
    }

    #[test]
    fn two_fragments_in_one_column_are_caught() {
        let (m, _) = judged(&scene(SHALLOW), |f| set(f, 3, 3, 1, 1));
        assert_eq!(m.crowded, 1, "{m:?}");
    }

    #[test]
    fn connected_segments_drawing_their_joint_twice_are_caught() {
        let strip = r#"{"line": [[0.5, 1.5], [4.5, 1.5]], "rule": "diamond-exit"},
                       {"line": [[4.5, 1.5], [9.5, 2.5]], "rule": "diamond-exit"}"#;
        let (m, _) = judged(&scene(strip), |_| {});
        assert!(m.failures().is_empty(), "{m:?}");
        // The first segment also lights its last pixel (4,1), the second's first.
        let (m, _) = judged(&scene(strip), |f| set(f, 4, 1, 2, 2));
        assert_eq!(m.duplicated, 1, "{m:?}");
    }
}
