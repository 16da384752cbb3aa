//! The search `rastercheck fuzz` runs: generate, judge, shrink each failure
//! of a kind asked for, pin the reference's result in the shrunk case, read
//! it back and judge it again, and write it. With its options, its summary,
//! the default folder and the clock seed.

use std::borrow::Cow;
use std::path::{Path, PathBuf};

use dashu_ratio::RBig;

use super::case_json::case_json;
use super::family::{generate, scene_from_tape, Family};
use super::geometry::num;
use super::judge::{evaluate, samples_per_pixel, Failure, Kind, Outcome};
use super::rng::{fnv1a, Rng};
use super::shrink::{shrink, Shrunk};
use crate::plan::Plan;
use crate::rasterizer::Rasterizer;
use crate::reference;
use crate::scene::time::limits::TIME_ONE;
use crate::scene::{Number, Primitive, Scene, TimePin};

/// What `rastercheck fuzz` was asked to do.
#[derive(Clone, Debug)]
pub struct Options {
    pub seed: u64,
    /// The number of the first case tried (`--first-case`; 0 by default):
    /// cases `first`, `first + 1`, … of the seed.
    pub first: u64,
    /// Scenes to try.
    pub cases: u64,
    /// One family, or all of them in turn.
    pub family: Option<Family>,
    /// Only failures of these kinds count (all when empty).
    pub check: Vec<Kind>,
    /// Stop after this many failures.
    pub max_failures: usize,
    /// Folder for the case files.
    pub out: PathBuf,
    /// The command line that draws the scenes again, for descriptions,
    /// less what picks a case (`--seed`, `--family`, `--first-case`,
    /// `--cases`), which each finding adds for its own: `rastercheck fuzz
    /// -r R` with `--check` and `--profile`, or with `--from-crash FILE`,
    /// which draws its one scene.
    pub command: String,
}

impl Options {
    /// The first of a failure's kinds that `--check` asks for (any, when it
    /// names none): the kind to shrink for.
    fn first_asked(&self, failure: &Failure) -> Option<Kind> {
        failure
            .kinds
            .iter()
            .copied()
            .find(|k| self.check.is_empty() || self.check.contains(k))
    }
}

/// One failure found, shrunk and written.
#[derive(Clone, Debug)]
pub struct Found {
    pub index: u64,
    pub family: Family,
    pub kind: Kind,
    pub path: PathBuf,
    pub original: Scene,
    pub shrunk: Shrunk,
}

/// What a search did.
#[derive(Clone, Debug, Default)]
pub struct Summary {
    pub cases: u64,
    pub passed: u64,
    pub unsupported: u64,
    /// Failures of kinds `--check` did not ask for.
    pub ignored: u64,
    pub found: Vec<Found>,
}

fn sanitize(text: &str) -> String {
    let s: String = text
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '_'
            }
        })
        .collect();
    let s = s.trim_matches('_').to_owned();
    s.chars().take(40).collect()
}

fn describe_size(scene: &Scene) -> String {
    let count = |f: fn(&Primitive) -> bool| scene.primitives.iter().filter(|p| f(p)).count();
    let triangles = count(|p| matches!(p, Primitive::Triangle(_)));
    let lines = count(|p| matches!(p, Primitive::Line(_)));
    let polygons = count(|p| matches!(p, Primitive::Polygon(_)));
    let points = count(|p| matches!(p, Primitive::Point(_)));
    let mut parts = Vec::new();
    for (n, what) in [
        (triangles, "triangle"),
        (lines, "line"),
        (polygons, "polygon"),
        (points, "point"),
    ] {
        if n > 0 {
            parts.push(format!("{n} {what}{}", if n == 1 { "" } else { "s" }));
        }
    }
    let antialias = scene.effects.antialias.as_ref().map_or(String::new(), |a| {
        let s = if a.samples == 1 { "" } else { "s" };
        format!(" at {} {} sample{s} per pixel", a.samples, a.pattern.name())
    });
    let moving = scene.primitives.iter().filter(|p| p.moves()).count();
    let motion = match &scene.effects.motion_blur {
        Some(b) if moving > 0 => {
            let shutter = if b.shutter == [0, TIME_ONE] {
                String::new()
            } else {
                let [open, close] = b.shutter.map(|t| Number::ratio(t.into(), TIME_ONE.into()));
                format!(" over the shutter [{open}, {close}]")
            };
            let s = if b.samples == 1 { "" } else { "s" };
            format!(
                ", {moving} moving, with {} {} time sample{s}{shutter}",
                b.samples,
                b.pattern.name()
            )
        }
        _ => String::new(),
    };
    format!(
        "{} on a {}×{} canvas{antialias}{motion}",
        parts.join(" and "),
        scene.canvas.width,
        scene.canvas.height
    )
}

/// The shrunk scene as the case to write: named, described, with the
/// reference's sample count pinned.
fn finished_case(
    candidate: &dyn Rasterizer,
    origin: &Origin,
    family: Family,
    original: &Scene,
    kind: Kind,
    shrunk: &Shrunk,
) -> Scene {
    // Stated under the rule it was judged under.
    let mut scene = super::judge::as_judged(&shrunk.scene, candidate)
        .map_or_else(|_| shrunk.scene.clone(), Cow::into_owned);
    scene.name = format!(
        "fuzz_{}_{}_{}",
        sanitize(candidate.name()),
        kind.name(),
        origin.tag
    );
    let reasons = shrunk.failure.reasons_for(kind).join("; ");
    scene.description = format!(
        "Found by `{}`: {} ({} family), originally {}, shrunk to {} in {} evaluations. {} fails it: {reasons}. A correct rasterizer {}.",
        origin.command,
        origin.said,
        family.name(),
        describe_size(original),
        describe_size(&shrunk.scene),
        shrunk.evaluations,
        candidate.name(),
        kind.promise(),
    );
    let plan = Plan::for_scene(&scene);
    if plan.motion.is_some() {
        // Judged on time coverage only: pin the reference's time coverage
        // of the first pixel the failure shows, exact when the oracle's
        // bound is 0 (the nearest f64 otherwise, well within the pin's
        // tolerance of bound + 10^-12).
        let per_pixel = samples_per_pixel(&scene);
        let p = shrunk
            .failure
            .focus(kind)
            .first()
            .map_or(0, |i| i / per_pixel);
        let certified = reference::motion::time_coverage(&scene, &plan);
        if let Some(c) = certified.get(p) {
            let value = if c.bound == RBig::ZERO {
                num(&c.value)
            } else {
                let nearest = reference::area::to_f64_nearest(&c.value);
                Number::from_decimal(&format!("{nearest}")).expect("an f64 is a decimal")
            };
            let width = scene.canvas.width as usize;
            scene.expect.time_coverage = vec![TimePin {
                pixel: [(p % width) as u32, (p / width) as u32],
                value,
            }];
        }
        return scene;
    }
    scene.expect.samples_covered = Some(reference::render(&scene, &plan).covered_samples());
    if scene.effects.antialias.is_some() {
        let total = reference::exact_areas(&scene)
            .iter()
            .fold(RBig::ZERO, |sum, a| sum + a);
        scene.expect.area = Some(num(&total));
    }
    scene
}

/// Searches `options.cases` scenes for failures of `candidate`, shrinks and
/// writes each (up to `max_failures`), and reports progress through `log`.
/// `Err` when a case file cannot be written.
pub fn search(
    candidate: &dyn Rasterizer,
    options: &Options,
    log: &mut dyn FnMut(&str),
) -> Result<Summary, String> {
    let mut summary = Summary::default();
    if candidate.is_foil() {
        log(&format!(
            "note: {} is a foil: `run` reports its departures as FOIL, never as failures",
            candidate.name()
        ));
    }
    for index in options.first..options.first.saturating_add(options.cases) {
        let (family, scene) = generate(options.seed, index, options.family);
        summary.cases += 1;
        let failure = match evaluate(&scene, candidate) {
            Outcome::Pass => {
                summary.passed += 1;
                continue;
            }
            Outcome::Unsupported(_) => {
                summary.unsupported += 1;
                continue;
            }
            Outcome::Invalid(why) => {
                log(&format!(
                    "note: case {index} ({}) skipped: {why}",
                    family.name()
                ));
                continue;
            }
            Outcome::Broken(why) => {
                log(&format!(
                    "error: case {index} ({}) skipped: {why} (a bug in rastercheck; please report it)",
                    family.name()
                ));
                continue;
            }
            Outcome::Fail(f) => f,
        };
        let Some(kind) = options.first_asked(&failure) else {
            summary.ignored += 1;
            continue;
        };
        log(&format!(
            "FAIL  case {index} ({}, {}): {}",
            family.name(),
            describe_size(&scene),
            failure.reasons_for(kind).join("; ")
        ));
        let origin = Origin {
            tag: format!("{}_{index}", options.seed),
            said: format!("case {index} of seed {}", options.seed),
            command: reproduction(options, index, family),
        };
        let (path, shrunk) = keep(
            candidate, options, &origin, family, &scene, failure, kind, log,
        )?;
        summary.found.push(Found {
            index,
            family,
            kind,
            path,
            original: scene,
            shrunk,
        });
        if summary.found.len() >= options.max_failures {
            break;
        }
    }
    Ok(summary)
}

/// Where a failing scene came from: a tag for its file name, words for its
/// description, and the command that draws it again.
struct Origin {
    tag: String,
    said: String,
    command: String,
}

/// The command that draws case `index` of the search, of `family`, again:
/// the search's command with `--seed`, `--family`, `--first-case` and
/// `--cases 1`. It names the family even when the search named none: a
/// case's scene depends only on the seed, its number and its family, while
/// which family an unnamed search gives case `index` depends on the
/// families a version has ([`Family::ALL`]), so this command stays valid
/// when families are added.
fn reproduction(options: &Options, index: u64, family: Family) -> String {
    format!(
        "{} --seed {} --family {} --first-case {index} --cases 1",
        options.command,
        options.seed,
        family.name()
    )
}

/// Shrinks a failure of `kind`, pins the reference's result, reads the case
/// back and judges it again, and writes it under `options.out`.
#[allow(clippy::too_many_arguments)]
fn keep(
    candidate: &dyn Rasterizer,
    options: &Options,
    origin: &Origin,
    family: Family,
    scene: &Scene,
    failure: Failure,
    kind: Kind,
    log: &mut dyn FnMut(&str),
) -> Result<(PathBuf, Shrunk), String> {
    let shrunk = shrink(scene, failure, kind, candidate);
    let case = finished_case(candidate, origin, family, scene, kind, &shrunk);
    let text = case_json(&case);
    // The file must say what the shrinker saw: read it back and judge
    // it again.
    let reread = crate::scene::parse_case(&text, "the shrunk case", &Default::default())
        .map_err(|e| format!("internal error: the shrunk case does not read back: {e}"))?;
    match evaluate(&reread, candidate) {
        Outcome::Fail(f) if f.kinds.contains(&kind) => {}
        other => {
            return Err(format!(
                "internal error: the shrunk case read back no longer fails {}: {other:?}",
                kind.name()
            ))
        }
    }
    std::fs::create_dir_all(&options.out).map_err(|e| format!("{}: {e}", options.out.display()))?;
    let path = options.out.join(format!("{}.json", case.name));
    std::fs::write(&path, &text).map_err(|e| format!("{}: {e}", path.display()))?;
    log(&format!(
        "      shrunk in {} evaluations, {} rounds, {:.0} ms: {}",
        shrunk.evaluations,
        shrunk.rounds,
        shrunk.elapsed.as_secs_f64() * 1000.0,
        describe_size(&shrunk.scene)
    ));
    log(&format!("      wrote {}", path.display()));
    for reason in shrunk.failure.reasons_for(kind) {
        log(&format!("        {reason}"));
    }
    log(&format!("      found again by: {}", origin.command));
    Ok((path, shrunk))
}

/// A libFuzzer input of the scene target (a tape, [`scene_from_tape`]):
/// judges `candidate` on the scene it draws and, when it fails a kind
/// asked for, shrinks and writes it as `search` does. `file` names the
/// input in the case's description and file name.
pub fn from_tape(
    candidate: &dyn Rasterizer,
    tape: &[u8],
    file: &str,
    options: &Options,
    log: &mut dyn FnMut(&str),
) -> Result<Summary, String> {
    let (family, scene) = scene_from_tape(tape);
    let mut summary = Summary {
        cases: 1,
        ..Summary::default()
    };
    let failure = match evaluate(&scene, candidate) {
        Outcome::Pass => {
            summary.passed = 1;
            return Ok(summary);
        }
        Outcome::Unsupported(_) => {
            summary.unsupported = 1;
            return Ok(summary);
        }
        Outcome::Invalid(why) | Outcome::Broken(why) => {
            return Err(format!("{file}: the scene it draws is not judged: {why}"))
        }
        Outcome::Fail(f) => f,
    };
    let Some(kind) = options.first_asked(&failure) else {
        summary.ignored = 1;
        return Ok(summary);
    };
    log(&format!(
        "FAIL  {file} ({}, {}): {}",
        family.name(),
        describe_size(&scene),
        failure.reasons_for(kind).join("; ")
    ));
    let hash = fnv1a(tape);
    let origin = Origin {
        tag: format!("crash_{:08x}", hash as u32),
        said: format!("the libFuzzer input {file}"),
        command: options.command.clone(),
    };
    let (path, shrunk) = keep(
        candidate, options, &origin, family, &scene, failure, kind, log,
    )?;
    summary.found.push(Found {
        index: 0,
        family,
        kind,
        path,
        original: scene,
        shrunk,
    });
    Ok(summary)
}

/// Where `rastercheck fuzz` writes by default.
pub fn default_out() -> &'static Path {
    Path::new("fuzz-cases")
}

/// A seed from the clock, for runs that name none (it is printed).
pub fn clock_seed() -> u64 {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos() as u64);
    Rng::new(nanos ^ u64::from(std::process::id())).next_u64() % 1_000_000_000
}
