//! The adapter for a rasterizer that is another program: its name, its
//! limits, how it is started, and the [`Rasterizer`] that sends each case
//! one-shot (`one_shot.rs`) or to the pool of persistent processes
//! (`pool.rs`).

use std::os::unix::process::CommandExt;
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicBool, AtomicU32, AtomicU64};
use std::sync::Mutex;
use std::time::Duration;

use super::answer::frame_from_line;
use super::hello::{Answers, Hello};
use super::limits::{max_output_from_env, timeout_from_env};
use super::motion;
use super::protocol::Request;
use super::space::needs_a_hello;
use super::worker::Worker;
use crate::deadline;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, PixelCentre, RasterError, Rasterizer, Snapping, YDirection};
use crate::scene::{
    ClipXy, ClipZ, ConservativeSupport, DeclaredRule, FillRule, InterpolateFrom, Pattern,
    PointBounds, PointClip, Scene,
};

/// A rasterizer that is another program.
pub struct External {
    pub(super) name: String,
    pub(super) program: String,
    pub(super) args: Vec<String>,
    /// The per-case time limit, or why the environment's value is refused.
    pub(super) timeout: Result<Duration, String>,
    /// The most bytes read from stdout per response, or why the
    /// environment's value is refused.
    pub(super) max_output: Result<u64, String>,
    /// Idle processes of a persistent adapter; `None` in one-shot mode.
    pub(super) pool: Option<Mutex<Vec<Worker>>>,
    /// The id of the next v2 request (unique in the adapter's life).
    pub(super) next_id: AtomicU64,
    /// Whether a process of this program wrote no hello: later processes
    /// are not waited for (a hello that comes later is still read).
    pub(super) said_no_hello: AtomicBool,
    /// The name and version the first hello declared.
    pub(super) declared: Mutex<Option<String>>,
    /// How the program's answers are shaped, as its hello declared
    /// (coverage only, quantized coverage: SPEC.md §12.9).
    pub(super) answers: Mutex<Answers>,
    /// v2: why the program is sent no more cases (its answers carry no
    /// `id`, or the wrong ones: SPEC.md §12.7), with the hello that still
    /// refuses cases by what it declares.
    pub(super) broken: Mutex<Option<(String, Option<Hello>)>>,
    /// v2: requests that timed out with an answer under another id.
    pub(super) wrong_ids: AtomicU32,
    /// What its hello declares of conservative rasterization (SPEC.md
    /// §12.11), once a hello declaring it is read.
    pub(super) conservative: Mutex<Option<ConservativeSupport>>,
}

impl External {
    /// `name` is what reports call it; the program and its arguments are
    /// run as given, in rastercheck's working directory.
    pub fn new(name: &str, program: String, args: Vec<String>, persistent: bool) -> External {
        External {
            name: name.to_owned(),
            program,
            args,
            timeout: timeout_from_env(),
            max_output: max_output_from_env(),
            pool: persistent.then(|| Mutex::new(Vec::new())),
            next_id: AtomicU64::new(1),
            said_no_hello: AtomicBool::new(false),
            declared: Mutex::new(None),
            answers: Mutex::new(Answers::default()),
            broken: Mutex::new(None),
            wrong_ids: AtomicU32::new(0),
            conservative: Mutex::new(None),
        }
    }

    /// The same adapter with another per-case time limit (the environment's
    /// `RASTERCHECK_EXTERNAL_TIMEOUT` is the default).
    pub fn with_timeout(mut self, timeout: Duration) -> External {
        self.timeout = Ok(timeout);
        self
    }

    /// The same adapter with another output limit in bytes (the
    /// environment's `RASTERCHECK_EXTERNAL_MAX_OUTPUT` is the default).
    pub fn with_max_output(mut self, bytes: u64) -> External {
        self.max_output = Ok(bytes);
        self
    }

    /// How the program's answers are shaped, as its hello declared.
    pub(super) fn answers(&self) -> Answers {
        *self.answers.lock().unwrap_or_else(|e| e.into_inner())
    }

    pub(super) fn command(&self) -> Command {
        let mut command = Command::new(&self.program);
        command
            .args(&self.args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            // A group of its own, so that what it starts can be killed with it.
            .process_group(0);
        command
    }

    pub(super) fn start(&self) -> Result<Child, RasterError> {
        let child = self
            .command()
            .spawn()
            .map_err(|e| RasterError::Failed(format!("cannot start {:?}: {e}", self.program)))?;
        // Killed on SIGINT or SIGTERM; forgotten when reaped (`wait_until`, `kill`).
        crate::stop::register(child.id());
        Ok(child)
    }
}

impl Rasterizer for External {
    fn name(&self) -> &str {
        &self.name
    }

    /// Everything: the program says what it does not do, case by case
    /// (`unsupported`, or its hello). Moving scenes go only to a program
    /// whose version 2 hello declares motion (SPEC.md §12.8); the adapter
    /// refuses them itself, since only the hello says. Clip space, points,
    /// depth formats and polygon offset likewise go only to a program whose
    /// hello declares them (SPEC.md §12.10, `space.rs`).
    fn capabilities(&self) -> Capabilities {
        Capabilities::everything()
    }

    fn fixed_fill_rule(&self) -> Option<FillRule> {
        self.answers().fill_rule.and_then(DeclaredRule::fill_rule)
    }

    fn no_tie_rule(&self) -> bool {
        self.answers().fill_rule == Some(DeclaredRule::NoTieRule)
    }

    fn fixed_clip_rules(&self) -> Option<(ClipXy, ClipZ)> {
        self.answers().clip.rules()
    }

    fn fixed_interpolate_from(&self) -> Option<InterpolateFrom> {
        self.answers().clip.values
    }

    fn fixed_point_clip(&self) -> Option<PointClip> {
        self.answers().clip.points
    }

    fn fixed_point_bounds(&self) -> Option<PointBounds> {
        self.answers().clip.bounds
    }

    fn fixed_snapping(&self) -> Option<Snapping> {
        self.answers().declaration.snapping
    }

    fn fixed_sample_pattern(&self) -> Option<Pattern> {
        self.answers().declaration.sample_pattern
    }

    fn fixed_y_direction(&self) -> Option<YDirection> {
        self.answers().declaration.y
    }

    fn fixed_pixel_centre(&self) -> Option<PixelCentre> {
        self.answers().declaration.pixel_centre
    }

    fn diamond_exit_latitude(&self) -> bool {
        self.answers().declaration.diamond_exit_latitude == Some(true)
    }

    /// Its hello's declaration (SPEC.md §12.11) once read; before, or
    /// when it declares none, both modes and the flag, so that a
    /// conservative case comes to [`Rasterizer::rasterize`] and is refused
    /// there naming the declaration (or the missing hello).
    fn conservative(&self) -> Option<ConservativeSupport> {
        let declared = self
            .conservative
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone();
        Some(declared.unwrap_or(ConservativeSupport {
            overestimate: true,
            underestimate: true,
            fully_covered: true,
            depth: true,
            ..ConservativeSupport::default()
        }))
    }

    fn declared(&self) -> Option<String> {
        self.declared
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone()
    }

    fn answer_bytes(&self) -> u64 {
        // The line is held as it came, read into the frame without a
        // `Value` (`answer.rs`); over the limit, the program is killed.
        self.max_output.clone().unwrap_or(0)
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        // Checked here too, for callers that skip the harness: a request
        // cannot carry a point.
        if let Some(why) = self.capabilities().refuses(scene) {
            return Err(RasterError::Unsupported(why));
        }
        let mut timeout = self.timeout.clone().map_err(RasterError::Failed)?;
        let max_output = self.max_output.clone().map_err(RasterError::Failed)?;
        // The case's deadline (`--case-timeout`) stops the program too; the
        // runner then judges the case over the limit.
        if let Some(left) = deadline::remaining() {
            timeout = timeout.min(left);
        }
        let response = match &self.pool {
            // One-shot programs speak version 1: no moving vertices.
            None if plan.motion.is_some() => {
                return Err(RasterError::Unsupported(motion::NOT_DECLARED.to_owned()))
            }
            None => {
                if let Some(why) = needs_a_hello(scene) {
                    return Err(RasterError::Unsupported(why));
                }
                self.one_shot(Request::v1(scene, plan).to_vec(), timeout, max_output)?
            }
            // Read into a frame there, before the process is reused.
            Some(pool) => return self.persistent(pool, scene, plan, timeout, max_output, false),
        };
        let answers = self.answers();
        Ok(frame_from_line(response.as_bytes(), scene, plan, answers)?)
    }
}
