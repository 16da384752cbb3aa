//! An answer read as it is parsed (SPEC.md §12.2, §12.8, §12.9): one pass
//! of serde over the line, each fragment, coverage or time item written
//! straight into the frame, never into a `serde_json::Value` (whose
//! numbers, under `arbitrary_precision`, are heap strings: about 22 bytes
//! of memory per byte of answer, issue 36). An answer costs its line, the
//! frame, and one item's few [`Scalar`]s at a time; an area answer also
//! keeps its items per primitive (16 bytes each, less than their text),
//! as its judge needs them (§12.9).
//!
//! What is checked, and the messages, are those of the `Value` reader
//! this replaced: `$.protocol` first, then `$.unsupported`, `$.error`,
//! then the primitives (their count before their content), each message
//! naming the JSON path. A malformed item stops the composing; the rest
//! of the line is skipped, not kept.

use std::fmt;
use std::path::Path;

use serde::de::{self, DeserializeSeed, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde_json::Value;

use crate::frame::{Frame, Parts};
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::Scene;

use super::answer_error::AnswerError;
use super::envelope::not_json;
use super::exr_answer::frame_from_exr;
use super::hello::Answers;
use super::motion::TimeAnswer;
use super::protocol::{PROTOCOL, PROTOCOL_V2};
use super::values::{pixel_of, stored_depth, whole_below, Scalar, Text, NUMBER_TOKEN};

/// The method a coverage-only frame of a scene with values names: what the
/// reports show beside its verdict.
pub const COVERAGE_ONLY: &str = "coverage only: depth and attributes not judged";

/// Reads one response line into a frame, checking it against the request
/// (SPEC.md §12.2), for a program whose hello declared how its answers are
/// shaped (§12.9; `Answers::default()` for one that declared nothing).
pub fn frame_from_line(
    bytes: &[u8],
    scene: &Scene,
    plan: &Plan,
    answers: Answers,
) -> Result<Frame, AnswerError> {
    let bad = |why: String| AnswerError::Unfit(format!("bad response: {why}"));
    let mut reader = Reader::new(scene, plan, answers);
    let mut de = serde_json::Deserializer::from_slice(bytes);
    let parsed = (&mut reader).deserialize(&mut de).and_then(|()| de.end());
    if let Err(e) = parsed {
        return Err(AnswerError::Unfit(not_json(bytes, &e)));
    }
    if !reader.object {
        return Err(bad("not a JSON object".to_owned()));
    }
    if let Some(protocol) = reader.protocol {
        if !matches!(&protocol, Scalar::Other(text) if *text == format!("{PROTOCOL:?}") || *text == format!("{PROTOCOL_V2:?}"))
        {
            return Err(bad(format!(
                "$.protocol is {protocol}; this rastercheck speaks {PROTOCOL:?} and {PROTOCOL_V2:?}"
            )));
        }
    }
    if let Some(why) = reader.unsupported {
        return Err(AnswerError::Unsupported(why));
    }
    if let Some(why) = reader.error {
        return Err(AnswerError::Program(why));
    }
    match (reader.primitives, reader.exr) {
        (Some(_), None) => {
            if reader.entries != scene.primitives.len() {
                return Err(bad(format!(
                    "$.primitives has {} entries; the request has {} primitives",
                    reader.entries,
                    scene.primitives.len()
                )));
            }
            if let Some(why) = reader.why {
                return Err(bad(why));
            }
            reader.build.finish(scene, plan, answers).map_err(bad)
        }
        (None, Some(path)) => {
            let Some(path) = path else {
                return Err(bad("$.exr must be a string (a file path)".to_owned()));
            };
            if plan.motion.is_some() {
                return Err(bad(
                    "an exr response holds no time coverage; answer moving scenes with fragments or time (SPEC §12.8)"
                        .to_owned(),
                ));
            }
            if plan.antialias.is_some() {
                return Err(bad(
                    "an exr response holds one sample per pixel; answer antialiased scenes with fragments or coverage"
                        .to_owned(),
                ));
            }
            frame_from_exr(Path::new(&path), scene, plan).map_err(bad)
        }
        (Some(_), Some(_)) => Err(bad("give either $.primitives or $.exr, not both".to_owned())),
        (None, None) => Err(bad(
            "expected $.primitives, $.exr, $.unsupported or $.error".to_owned(),
        )),
    }
}

/// [`frame_from_line`] for a response already parsed (tests, and callers
/// that hold one), for a program that declared nothing about its answers
/// (version 1).
pub fn frame_from_response(
    response: &Value,
    scene: &Scene,
    plan: &Plan,
) -> Result<Frame, RasterError> {
    frame_from_answer(response, scene, plan, Answers::default())
}

/// [`frame_from_response`] for a program whose hello declared how its
/// answers are shaped (SPEC.md §12.9).
pub fn frame_from_answer(
    response: &Value,
    scene: &Scene,
    plan: &Plan,
    answers: Answers,
) -> Result<Frame, RasterError> {
    let line = serde_json::to_vec(response).expect("a JSON value serializes");
    frame_from_line(&line, scene, plan, answers).map_err(RasterError::from)
}

/// What a response said, read key by key.
struct Reader<'a> {
    scene: &'a Scene,
    plan: &'a Plan,
    answers: Answers,
    /// The line was a JSON object.
    object: bool,
    protocol: Option<Scalar>,
    unsupported: Option<String>,
    error: Option<String>,
    /// `$.primitives` was given (its content is in `build`).
    primitives: Option<()>,
    /// `$.exr`: `Some(None)` when it is not a string.
    exr: Option<Option<String>>,
    /// Entries in `$.primitives`.
    entries: usize,
    /// The first thing wrong in `$.primitives`; the rest is skipped.
    why: Option<String>,
    build: Build,
}

/// The frame being composed, in the form the first entry chose.
enum Build {
    /// No entry read yet.
    Undecided,
    /// Fragments of a static scene (SPEC.md §12.2).
    Fragments(Box<Fragments>),
    /// Antialiased coverage per primitive (§12.2, §12.9).
    Coverage { resolved: Vec<f64>, parts: Parts },
    /// A moving scene's masks or time coverage (§12.8).
    Time(TimeAnswer),
}

struct Fragments {
    frame: Frame,
    samples: Option<u32>,
    depth: bool,
    attributes: usize,
    /// Each fragment ends with the fully-covered flag, 0 or 1 (a
    /// conservative case that asks for it, SPEC.md §12.11).
    flag: bool,
    arity: usize,
}

/// Which array an entry gives its items in.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Form {
    Fragments,
    Coverage,
    Time,
}

impl<'a> Reader<'a> {
    fn new(scene: &'a Scene, plan: &'a Plan, answers: Answers) -> Reader<'a> {
        Reader {
            scene,
            plan,
            answers,
            object: false,
            protocol: None,
            unsupported: None,
            error: None,
            primitives: None,
            exr: None,
            entries: 0,
            why: None,
            build: Build::Undecided,
        }
    }

    /// The message for an entry that gives no array of the form expected.
    fn no_items(&self, p: usize) -> String {
        match (&self.build, self.plan.motion.is_some()) {
            (Build::Coverage { .. }, _) => format!("$.primitives[{p}].coverage must be an array"),
            (Build::Time(t), _) => format!(
                "$.primitives[{p}] must be an object with a {} array (SPEC §12.8)",
                t.field()
            ),
            (_, true) => {
                format!("$.primitives[{p}] must be an object with a fragments array (SPEC §12.8)")
            }
            _ => format!("$.primitives[{p}] must be an object with a fragments array"),
        }
    }

    /// Sets the frame's form from an entry's key, or says why the key does
    /// not fit the scene or the entries before.
    fn choose(&mut self, form: Form) -> Result<(), String> {
        let motion = self.plan.motion.is_some();
        if motion && form == Form::Coverage {
            return Err(format!(
                "$.primitives[{}] must be an object with a fragments array (SPEC §12.8)",
                self.entries
            ));
        }
        if !motion && form == Form::Time {
            return Err(format!(
                "$.primitives[{}] must be an object with a fragments array",
                self.entries
            ));
        }
        let chosen = match &self.build {
            Build::Undecided => None,
            Build::Fragments(_) => Some(Form::Fragments),
            Build::Coverage { .. } => Some(Form::Coverage),
            Build::Time(t) if t.field() == "time" => Some(Form::Time),
            Build::Time(_) => Some(Form::Fragments),
        };
        match chosen {
            Some(c) if c == form => return Ok(()),
            Some(_) if motion => {
                return Err(
                    "$.primitives: give time for every primitive or fragments for every one".into(),
                )
            }
            Some(_) => {
                return Err("give coverage for every primitive or fragments for every one".into())
            }
            None => {}
        }
        let (scene, plan) = (self.scene, self.plan);
        let (width, height) = (scene.canvas.width, scene.canvas.height);
        self.build = match form {
            _ if motion => Build::Time(TimeAnswer::new(scene, plan, form == Form::Time)?),
            Form::Coverage => {
                if plan.antialias.is_none() {
                    return Err(
                        "coverage entries answer antialiased scenes only; give fragments".into(),
                    );
                }
                Build::Coverage {
                    resolved: vec![0.0; width as usize * height as usize],
                    parts: Parts {
                        coverage: Vec::with_capacity(scene.primitives.len()),
                        step: self.answers.step(),
                        saturates: self.answers.saturates(),
                    },
                }
            }
            _ => Build::Fragments(Box::new(Fragments::new(scene, plan, self.answers))),
        };
        Ok(())
    }

    /// One item of entry `p` (`f`: its index), `None` when it is not an
    /// array; `len` is its length, of which `values` holds the first few.
    fn item(
        &mut self,
        p: usize,
        f: usize,
        values: Option<(&[Scalar], usize)>,
    ) -> Result<(), String> {
        let (width, height) = (self.scene.canvas.width, self.scene.canvas.height);
        match &mut self.build {
            Build::Undecided => Ok(()),
            Build::Fragments(fr) => fr.item(p, f, values, self.scene),
            Build::Coverage { resolved, parts } => {
                let at = || format!("$.primitives[{p}].coverage[{f}]");
                let triple = values
                    .filter(|(_, len)| *len == 3)
                    .ok_or_else(|| format!("{} must be [x, y, fraction]", at()))?
                    .0;
                let (x, y) = pixel_of(triple, (width, height), &at)?;
                let c = triple[2]
                    .as_f64()
                    .filter(|c| (0.0..=1.0).contains(c))
                    .ok_or_else(|| {
                        format!("{}[2]: {} is not a fraction in [0, 1]", at(), triple[2])
                    })?;
                let pixel = y * width + x;
                resolved[pixel as usize] += c;
                if parts.coverage.len() <= p {
                    parts.coverage.resize_with(p + 1, Vec::new);
                }
                parts.coverage[p].push((pixel, c));
                Ok(())
            }
            Build::Time(t) => t.item(p, f, values, (width, height)),
        }
    }
}

impl Fragments {
    fn new(scene: &Scene, plan: &Plan, answers: Answers) -> Fragments {
        // The values a coverage-only program does not give are not judged;
        // the result says so.
        let unjudged = answers.coverage_only && plan.interpolates();
        let (depth, attributes) = if unjudged {
            (false, 0)
        } else {
            (plan.depth, plan.attributes)
        };
        let given = Plan {
            depth,
            attributes,
            ..plan.clone()
        };
        let samples = plan.antialias.as_ref().map(|aa| aa.offsets.len() as u32);
        let mut frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, &given);
        frame.coverage_only = answers.coverage_only;
        if unjudged {
            frame.method = Some(COVERAGE_ONLY);
        }
        let flag = super::conservative::flagged(scene);
        if flag {
            frame.fully_covered = Some(vec![false; frame.pixel_count()]);
        }
        let arity = 2
            + usize::from(samples.is_some())
            + usize::from(depth)
            + attributes
            + usize::from(flag);
        Fragments {
            frame,
            samples,
            depth,
            attributes,
            flag,
            arity,
        }
    }

    fn item(
        &mut self,
        p: usize,
        f: usize,
        values: Option<(&[Scalar], usize)>,
        scene: &Scene,
    ) -> Result<(), String> {
        let (width, height) = (scene.canvas.width, scene.canvas.height);
        let arity = self.arity;
        let slot_field = usize::from(self.samples.is_some());
        let at = || format!("$.primitives[{p}].fragments[{f}]");
        let numbers = values
            .filter(|(_, len)| *len == arity)
            .ok_or_else(|| {
                format!(
                    "{} must be an array of {arity} numbers: x, y{}{}{}{}",
                    at(),
                    if self.samples.is_some() {
                        ", sample"
                    } else {
                        ""
                    },
                    if self.depth { ", depth" } else { "" },
                    if self.attributes > 0 {
                        format!(", {} attributes", self.attributes)
                    } else {
                        String::new()
                    },
                    if self.flag {
                        ", fully covered (0 or 1)"
                    } else {
                        ""
                    }
                )
            })?
            .0;
        let (numbers, flag) = match numbers.split_last() {
            Some((last, rest)) if self.flag => (
                rest,
                Some(super::conservative::flag(last.as_f64()).ok_or_else(|| {
                    format!(
                        "{}[{}]: {last} {}",
                        at(),
                        arity - 1,
                        super::conservative::NOT_A_FLAG
                    )
                })?),
            ),
            _ => (numbers, None),
        };
        let (x, y) = pixel_of(numbers, (width, height), &at)?;
        let slot = match self.samples {
            Some(n) => whole_below(&numbers[2], n).ok_or_else(|| {
                format!(
                    "{}[2]: {} is not a sample index in [0, {n})",
                    at(),
                    numbers[2]
                )
            })?,
            None => 0,
        };
        let frame = &mut self.frame;
        let i = frame.index(x, y) + slot as usize;
        frame.hit(i, p);
        // The last fragment written at a pixel leaves its flag (SPEC.md §19.4),
        // one per pixel, multisampled too (§19.10).
        let pixel = i / frame.samples.max(1) as usize;
        if let (Some(slot), Some(flag)) = (
            frame.fully_covered.as_mut().and_then(|f| f.get_mut(pixel)),
            flag,
        ) {
            *slot = flag;
        }
        for (k, v) in numbers[2 + slot_field..].iter().enumerate() {
            let v = v.as_f64().ok_or_else(|| {
                format!("{}[{}] must be a finite number", at(), k + 2 + slot_field)
            })?;
            match (&mut frame.depth, k) {
                (Some(depth), 0) => {
                    depth[i] = stored_depth(v, scene.rules.depth_format).ok_or_else(|| {
                        format!(
                            "{}[{}]: {v} is not a {} depth (SPEC §12.10)",
                            at(),
                            2 + slot_field,
                            scene.rules.depth_format.name()
                        )
                    })?
                }
                (Some(_), k) => frame.attributes[k - 1][i] = v,
                (None, k) => frame.attributes[k][i] = v,
            }
        }
        Ok(())
    }
}

impl Build {
    fn finish(self, scene: &Scene, plan: &Plan, answers: Answers) -> Result<Frame, String> {
        let (width, height) = (scene.canvas.width, scene.canvas.height);
        match self {
            // No entries (a scene without primitives): fragments.
            Build::Undecided if plan.motion.is_some() => {
                Ok(TimeAnswer::new(scene, plan, false)?.finish(width, height))
            }
            Build::Undecided => Build::Fragments(Box::new(Fragments::new(scene, plan, answers)))
                .finish(scene, plan, answers),
            Build::Fragments(fr) => {
                let mut frame = fr.frame;
                if fr.samples.is_some() {
                    frame.resolve();
                }
                Ok(frame)
            }
            Build::Coverage {
                resolved,
                mut parts,
            } => {
                parts.coverage.resize_with(scene.primitives.len(), Vec::new);
                Ok(Frame {
                    parts: Some(parts),
                    ..Frame::resolved_only(width, height, resolved)
                })
            }
            Build::Time(t) => Ok(t.finish(width, height)),
        }
    }
}

/// The scalar visits of a visitor that takes none of them: each gives
/// `$body` (`$this` is the visitor).
macro_rules! scalars {
    ($value:ty, |$this:ident| $body:expr) => {
        fn visit_bool<E: de::Error>(self, _: bool) -> Result<$value, E> {
            let $this = self;
            Ok($body)
        }
        fn visit_i64<E: de::Error>(self, _: i64) -> Result<$value, E> {
            let $this = self;
            Ok($body)
        }
        fn visit_u64<E: de::Error>(self, _: u64) -> Result<$value, E> {
            let $this = self;
            Ok($body)
        }
        fn visit_f64<E: de::Error>(self, _: f64) -> Result<$value, E> {
            let $this = self;
            Ok($body)
        }
        fn visit_str<E: de::Error>(self, _: &str) -> Result<$value, E> {
            let $this = self;
            Ok($body)
        }
        fn visit_unit<E: de::Error>(self) -> Result<$value, E> {
            let $this = self;
            Ok($body)
        }
    };
}

// ---------------------------------------------------------------------------
// The serde side: the response object, `$.primitives`, an entry, its items.

impl<'de> DeserializeSeed<'de> for &mut Reader<'_> {
    type Value = ();

    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<(), D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for &mut Reader<'_> {
    type Value = ();

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a response object")
    }
    scalars!((), |_this| ());
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        while seq.next_element::<IgnoredAny>()?.is_some() {}
        Ok(())
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        self.object = true;
        while let Some(key) = map.next_key::<String>()? {
            match key.as_str() {
                // A number, as `serde_json` hands one over: not an object.
                NUMBER_TOKEN => {
                    map.next_value::<IgnoredAny>()?;
                    self.object = false;
                }
                "protocol" => self.protocol = Some(map.next_value::<Scalar>()?),
                "unsupported" => self.unsupported = Some(map.next_value::<Text>()?.0),
                "error" => self.error = Some(map.next_value::<Text>()?.0),
                "exr" => self.exr = Some(map.next_value::<Text>()?.1),
                "primitives" => {
                    if self.primitives.is_some() {
                        self.why
                            .get_or_insert_with(|| "$.primitives is given twice".to_owned());
                        map.next_value::<IgnoredAny>()?;
                        continue;
                    }
                    self.primitives = Some(());
                    map.next_value_seed(Entries(&mut *self))?;
                }
                _ => {
                    map.next_value::<IgnoredAny>()?;
                }
            }
        }
        Ok(())
    }
}

/// `$.primitives`: its entries, counted, each composed into the frame.
struct Entries<'r, 'a>(&'r mut Reader<'a>);

impl<'de> DeserializeSeed<'de> for Entries<'_, '_> {
    type Value = ();
    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<(), D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Entries<'_, '_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an array of primitives")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        let reader = self.0;
        let count = reader.scene.primitives.len();
        loop {
            let p = reader.entries;
            let more = if reader.why.is_some() || p >= count {
                seq.next_element::<IgnoredAny>()?.is_some()
            } else {
                seq.next_element_seed(Entry {
                    reader: &mut *reader,
                    p,
                })?
                .is_some()
            };
            if !more {
                return Ok(());
            }
            reader.entries += 1;
        }
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        while map.next_entry::<IgnoredAny, IgnoredAny>()?.is_some() {}
        self.0.not_an_array();
        Ok(())
    }
    scalars!((), |this| {
        this.0.not_an_array();
    });
}

impl Reader<'_> {
    /// `$.primitives` is not an array: said before any count.
    fn not_an_array(&mut self) {
        self.why = Some("$.primitives must be an array".to_owned());
        // Its count is taken as the request's, so that the message is this.
        self.entries = self.scene.primitives.len();
    }
}

/// One entry of `$.primitives`: an object with one array of items.
struct Entry<'r, 'a> {
    reader: &'r mut Reader<'a>,
    p: usize,
}

impl<'de> DeserializeSeed<'de> for Entry<'_, '_> {
    type Value = ();
    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<(), D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl Entry<'_, '_> {
    fn not_an_object(self) {
        let why = self.reader.no_items(self.p);
        self.reader.why.get_or_insert(why);
    }
}

impl<'de> Visitor<'de> for Entry<'_, '_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a primitive's answer")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        let (reader, p) = (self.reader, self.p);
        let mut given = false;
        while let Some(key) = map.next_key::<String>()? {
            let form = match key.as_str() {
                "fragments" => Form::Fragments,
                "coverage" => Form::Coverage,
                "time" => Form::Time,
                _ => {
                    map.next_value::<IgnoredAny>()?;
                    continue;
                }
            };
            if reader.why.is_some() {
                map.next_value::<IgnoredAny>()?;
                continue;
            }
            if let Err(why) = reader.choose(form) {
                reader.why = Some(why);
                map.next_value::<IgnoredAny>()?;
                continue;
            }
            given = true;
            map.next_value_seed(Items {
                reader: &mut *reader,
                p,
            })?;
        }
        if !given && reader.why.is_none() {
            let why = reader.no_items(p);
            reader.why = Some(why);
        }
        Ok(())
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        while seq.next_element::<IgnoredAny>()?.is_some() {}
        self.not_an_object();
        Ok(())
    }
    scalars!((), |this| {
        this.not_an_object();
    });
}

/// An entry's array of items, each applied to the frame as it is read.
struct Items<'r, 'a> {
    reader: &'r mut Reader<'a>,
    p: usize,
}

impl<'de> DeserializeSeed<'de> for Items<'_, '_> {
    type Value = ();
    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<(), D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Items<'_, '_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an array of items")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        let (reader, p) = (self.reader, self.p);
        // The most values of one item kept: the longest item the form
        // takes, and one more to see that an item is too long.
        let keep = match &reader.build {
            Build::Fragments(fr) => fr.arity + 1,
            _ => 4,
        };
        let mut values = Vec::with_capacity(keep);
        let mut f = 0;
        loop {
            if reader.why.is_some() {
                while seq.next_element::<IgnoredAny>()?.is_some() {}
                return Ok(());
            }
            values.clear();
            let Some(len) = seq.next_element_seed(Item(&mut values, keep))? else {
                return Ok(());
            };
            let item = len.map(|len| (&values[..], len));
            if let Err(why) = reader.item(p, f, item) {
                reader.why = Some(why);
            }
            f += 1;
        }
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        while map.next_entry::<IgnoredAny, IgnoredAny>()?.is_some() {}
        self.not_an_array();
        Ok(())
    }
    scalars!((), |this| {
        this.not_an_array();
    });
}

impl Items<'_, '_> {
    fn not_an_array(self) {
        let why = self.reader.no_items(self.p);
        self.reader.why.get_or_insert(why);
    }
}

/// One item: its first few values kept (at most the number given), its
/// length counted; `None` when it is not an array.
struct Item<'v>(&'v mut Vec<Scalar>, usize);

impl<'de> DeserializeSeed<'de> for Item<'_> {
    type Value = Option<usize>;
    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<Option<usize>, D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Item<'_> {
    type Value = Option<usize>;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an item")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Option<usize>, A::Error> {
        let mut len = 0;
        while len < self.1 {
            match seq.next_element::<Scalar>()? {
                Some(v) => self.0.push(v),
                None => return Ok(Some(len)),
            }
            len += 1;
        }
        while seq.next_element::<IgnoredAny>()?.is_some() {
            len += 1;
        }
        Ok(Some(len))
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Option<usize>, A::Error> {
        while map.next_entry::<IgnoredAny, IgnoredAny>()?.is_some() {}
        Ok(None)
    }
    scalars!(Option<usize>, |_this| None);
}

// ---------------------------------------------------------------------------
#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    use crate::adapters::external::answer_error::PROGRAM_ERROR;

    // The moving scene motion.rs's tests send: what its answers answer.
    use crate::adapters::external::motion::tests::scene;

    /// `$.primitives` read as an answer, or the message of its refusal.
    fn read(primitives: &Value, scene: &Scene, plan: &Plan) -> Result<Frame, String> {
        let line = serde_json::to_vec(&json!({ "primitives": primitives })).unwrap();
        frame_from_line(&line, scene, plan, Answers::default()).map_err(|e| format!("{e:?}"))
    }

    #[test]
    fn masks_count_tests_and_time_adds_coverage() {
        let scene = scene();
        let plan = Plan::for_scene(&scene);
        // Pixel 0: two moving tests and one static sample (N = 2 tests):
        // 4 of M·N = 4. Pixel 1: one moving test, listed twice: 2 of 4.
        let masks = json!([
            {"fragments": [[0, 0, 0], [0, 0, 3], [1, 0, 2], [1, 0, 2]]},
            {"fragments": [[0, 0, 1]]}
        ]);
        let frame = read(&masks, &scene, &plan).unwrap();
        assert_eq!(frame.time, Some(vec![1.0, 0.5]));
        assert_eq!(frame.samples, 0);
        let time = json!([{"time": [[0, 0, 0.25], [1, 0, 1]]}, {"time": [[0, 0, 0.5]]}]);
        let frame = read(&time, &scene, &plan).unwrap();
        assert_eq!(frame.time, Some(vec![0.75, 1.0]));
        for (bad, says) in [
            (
                json!([{"fragments": [[0, 0, 4]]}, {"fragments": []}]),
                "$.primitives[0].fragments[0][2]: 4 is not a time slot in [0, 4)",
            ),
            (
                json!([{"fragments": []}, {"fragments": [[0, 0, 2]]}]),
                "$.primitives[1].fragments[0][2]: 2 is not a spatial sample in [0, 2)",
            ),
            (
                json!([{"time": [[0, 0, 1.5]]}, {"time": []}]),
                "$.primitives[0].time[0][2]: 1.5 is not a time coverage in [0, 1]",
            ),
            (
                json!([{"time": []}, {"fragments": []}]),
                "time for every primitive or fragments for every one",
            ),
            (
                json!([{"fragments": [[2, 0, 0]]}, {"fragments": []}]),
                "$.primitives[0].fragments[0]: (2, 0) is not a pixel",
            ),
            (
                json!([{"fragments": [[0, 0]]}, {"fragments": []}]),
                "$.primitives[0].fragments[0] must be [x, y, time slot]",
            ),
            (
                json!([{"coverage": []}, {"coverage": []}]),
                "$.primitives[0] must be an object with a fragments array",
            ),
        ] {
            let why = read(&bad, &scene, &plan).unwrap_err();
            assert!(why.contains(says), "{why}");
        }
    }

    /// The program's own answers and a line that fits no request are told
    /// apart by kind, not by their text (`pool.rs` retires a v1 process
    /// for the second only).
    #[test]
    fn the_programs_own_error_is_a_kind_of_its_own() {
        let scene = scene();
        let plan = Plan::for_scene(&scene);
        let kind = |line: &str| frame_from_line(line.as_bytes(), &scene, &plan, Answers::default());
        assert_eq!(
            kind(r#"{"error": "bad response: out of memory"}"#).unwrap_err(),
            AnswerError::Program("bad response: out of memory".to_owned())
        );
        assert_eq!(
            kind(r#"{"unsupported": "no motion"}"#).unwrap_err(),
            AnswerError::Unsupported("no motion".to_owned())
        );
        assert!(matches!(kind("drawing…"), Err(AnswerError::Unfit(_))));
        assert!(matches!(
            kind(r#"{"primitives": []}"#),
            Err(AnswerError::Unfit(_))
        ));
        let failed = RasterError::from(AnswerError::Program("x".to_owned()));
        assert_eq!(
            failed.to_string(),
            RasterError::Failed(format!("{PROGRAM_ERROR}x")).to_string()
        );
    }
}
