//! Determinism: one candidate's repetitions of one case compared (`run
//! --repeat N`, SPEC.md §6.6). Every channel a frame carries is compared
//! bit for bit with the first repetition's: its size and sample count,
//! coverage, last primitive, depth, each attribute, resolved coverage, time
//! coverage, an area method's per-primitive parts and the method it names.
//! A repetition that differs makes the candidate's verdict on the case
//! FLAKY, with every repetition's outcome and where each difference lies.
//!
//! What it does not do: compare timings, the counts a sample method keeps
//! of its own time loop (`Frame::sample_tests`, a cost, not an answer), or
//! `Frame::coverage_only` (what the program declared in its hello, not
//! what it drew).

use serde::Serialize;

use crate::frame::Frame;

/// One repetition's outcome, as reports name it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, serde::Deserialize)]
pub struct Repetition {
    /// Which repetition, from 1.
    pub repetition: usize,
    /// `PASS`, `FAIL`, `UNSUPPORTED` or `ERROR`.
    pub verdict: String,
    /// A failure's reasons, or why the case was unsupported or broke;
    /// empty on a pass.
    pub reasons: Vec<String>,
}

impl Repetition {
    /// `FAIL (first reason)`, `PASS`.
    pub fn describe(&self) -> String {
        match self.reasons.first() {
            None => self.verdict.clone(),
            Some(first) => format!("{} ({first})", self.verdict),
        }
    }
}

/// A sample (or a pixel, in a per-pixel channel) of a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, serde::Deserialize)]
pub struct At {
    pub x: u32,
    pub y: u32,
    /// The sample slot in its pixel; none in a per-pixel channel.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sample: Option<u32>,
}

/// How one channel of a later repetition's frame differs from the first
/// repetition's.
#[derive(Clone, Debug, PartialEq, Serialize, serde::Deserialize)]
pub struct Difference {
    /// The later repetition (the first is what it is compared with).
    pub repetition: usize,
    /// `coverage`, `last`, `depth`, `attribute K`, `resolved`, `time`,
    /// `parts`, `method`, `size` (width, height or samples per pixel),
    /// or `frame` (one repetition drew a frame, the other none).
    pub channel: String,
    /// The first sample or pixel that differs, in row-major order.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub first: Option<At>,
    /// The first repetition's value there, then the later one's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub values: Option<[f64; 2]>,
    /// How many samples (or pixels) of the channel differ, of how many.
    pub count: usize,
    pub of: usize,
}

impl Difference {
    pub fn describe(&self) -> String {
        let mut text = format!(
            "{} differs in repetition {} from the first",
            self.channel, self.repetition
        );
        if let Some(at) = self.first {
            text += &format!(" at pixel ({}, {})", at.x, at.y);
            if let Some(s) = at.sample {
                text += &format!(" sample {s}");
            }
        }
        if let Some([a, b]) = self.values {
            text += &format!(" ({a} then {b})");
        }
        if self.of > 0 {
            text += &format!(": {} of {}", self.count, self.of);
        }
        text
    }
}

/// A candidate whose repetitions of a case did not agree: every
/// repetition's outcome, and where the frames differed.
#[derive(Clone, Debug, PartialEq, Serialize, serde::Deserialize)]
pub struct Flaky {
    pub outcomes: Vec<Repetition>,
    pub differences: Vec<Difference>,
}

impl Flaky {
    /// `3 repetitions: PASS, FAIL (…), PASS; depth differs in repetition
    /// 2 from the first at pixel (1, 6) sample 0 (0.5 then 0.501): 7 of 64`.
    pub fn summary(&self) -> String {
        let outcomes: Vec<String> = self.outcomes.iter().map(Repetition::describe).collect();
        let mut text = format!(
            "{} repetitions: {}",
            self.outcomes.len(),
            outcomes.join(", ")
        );
        if let Some(first) = self.differences.first() {
            text += "; ";
            text += &first.describe();
            if self.differences.len() > 1 {
                text += &format!(" (and {} more differences)", self.differences.len() - 1);
            }
        }
        text
    }
}

/// Where `later` (repetition `repetition`) differs from `first`, channel by
/// channel; empty when they are the same frame bit for bit (or both
/// absent).
pub fn compare(first: Option<&Frame>, later: Option<&Frame>, repetition: usize) -> Vec<Difference> {
    let whole = |channel: &str| Difference {
        repetition,
        channel: channel.to_owned(),
        first: None,
        values: None,
        count: 0,
        of: 0,
    };
    let (a, b) = match (first, later) {
        (None, None) => return Vec::new(),
        (Some(a), Some(b)) => (a, b),
        _ => return vec![whole("frame")],
    };
    if (a.width, a.height, a.samples) != (b.width, b.height, b.samples) {
        return vec![whole("size")];
    }
    let per_sample = |i: usize| {
        let s = a.samples.max(1) as usize;
        let pixel = i / s;
        At {
            x: (pixel % a.width.max(1) as usize) as u32,
            y: (pixel / a.width.max(1) as usize) as u32,
            sample: Some((i % s) as u32),
        }
    };
    let per_pixel = |i: usize| At {
        x: (i % a.width.max(1) as usize) as u32,
        y: (i / a.width.max(1) as usize) as u32,
        sample: None,
    };
    let mut out = Vec::new();
    let mut channel =
        |name: String, x: Vec<u64>, y: Vec<u64>, value: &dyn Fn(u64) -> f64, pixel: bool| {
            let diff = if x.len() != y.len() {
                Some(Difference {
                    of: x.len().max(y.len()),
                    count: x.len().abs_diff(y.len()),
                    ..whole(&name)
                })
            } else {
                let differing: Vec<usize> = (0..x.len()).filter(|&i| x[i] != y[i]).collect();
                differing.first().map(|&i| Difference {
                    first: Some(if pixel { per_pixel(i) } else { per_sample(i) }),
                    values: Some([value(x[i]), value(y[i])]),
                    count: differing.len(),
                    of: x.len(),
                    ..whole(&name)
                })
            };
            out.extend(diff);
        };
    let ints = |v: &[u16]| v.iter().map(|&c| u64::from(c)).collect::<Vec<_>>();
    let bits = |v: &[f64]| v.iter().map(|f| f.to_bits()).collect::<Vec<_>>();
    let int = &|v: u64| v as f64;
    let float = &|v: u64| f64::from_bits(v);
    channel(
        "coverage".into(),
        ints(&a.coverage),
        ints(&b.coverage),
        int,
        false,
    );
    channel(
        "last".into(),
        a.last.iter().map(|&l| u64::from(l)).collect(),
        b.last.iter().map(|&l| u64::from(l)).collect(),
        int,
        false,
    );
    let optional = |v: &Option<Vec<f64>>| v.as_deref().map(bits).unwrap_or_default();
    channel(
        "depth".into(),
        optional(&a.depth),
        optional(&b.depth),
        float,
        false,
    );
    let count = a.attributes.len().max(b.attributes.len());
    for k in 0..count {
        let of = |f: &Frame| f.attributes.get(k).map(|v| bits(v)).unwrap_or_default();
        channel(format!("attribute {k}"), of(a), of(b), float, false);
    }
    channel(
        "resolved".into(),
        optional(&a.resolved),
        optional(&b.resolved),
        float,
        true,
    );
    channel(
        "time".into(),
        optional(&a.time),
        optional(&b.time),
        float,
        true,
    );
    if a.parts != b.parts {
        let (x, y) = (
            a.parts.clone().unwrap_or_default(),
            b.parts.clone().unwrap_or_default(),
        );
        let pixels = x.coverage.len().max(y.coverage.len());
        let differing: Vec<usize> = (0..pixels)
            .filter(|&i| x.coverage.get(i) != y.coverage.get(i))
            .collect();
        out.push(Difference {
            first: differing.first().map(|&i| per_pixel(i)),
            count: differing.len(),
            of: pixels,
            ..whole("parts")
        });
    }
    if a.method != b.method {
        out.push(whole("method"));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_frame_has_no_difference() {
        let a = Frame::new(4, 2, true, 1);
        assert!(compare(Some(&a), Some(&a.clone()), 2).is_empty());
        assert!(compare(None, None, 2).is_empty());
    }

    #[test]
    fn a_difference_names_its_channel_sample_and_count() {
        let a = Frame::new(4, 2, true, 1);
        let mut b = a.clone();
        // Pixel (1, 1): slot 1·4 + 1 = 5.
        b.coverage[5] = 1;
        b.depth.as_mut().unwrap()[5] = 0.5;
        b.depth.as_mut().unwrap()[6] = 0.25;
        let d = compare(Some(&a), Some(&b), 3);
        assert_eq!(d.len(), 2, "{d:?}");
        assert_eq!(d[0].channel, "coverage");
        assert_eq!(
            d[0].first,
            Some(At {
                x: 1,
                y: 1,
                sample: Some(0)
            })
        );
        assert_eq!((d[0].count, d[0].of), (1, 8));
        assert_eq!(d[1].channel, "depth");
        assert_eq!(d[1].values, Some([0.0, 0.5]));
        assert_eq!(d[1].count, 2);
        assert_eq!(d[1].repetition, 3);
        assert!(
            d[1].describe().contains("pixel (1, 1) sample 0"),
            "{}",
            d[1].describe()
        );
        assert_eq!(compare(Some(&a), None, 2)[0].channel, "frame");
    }
}
