//! How a command ended: the exit codes of SPEC.md §9.

/// How a command ended, as SPEC.md §9 maps it to an exit code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Exit {
    /// 0: everything judged passes.
    Pass,
    /// 1: something failed.
    Fail,
    /// 2: bad input or bad usage, or a case over a resource limit.
    BadInput,
    /// 3: nothing was judged: every selected case unsupported by every
    /// candidate, or a selection that matched no case.
    NothingJudged,
    /// 128 + the signal (130: SIGINT, 143: SIGTERM): the run was stopped
    /// and its report is partial (`crate::stop`).
    Interrupted(i32),
}

impl Exit {
    /// The process exit code.
    pub fn code(self) -> u8 {
        match self {
            Exit::Pass => 0,
            Exit::Fail => 1,
            Exit::BadInput => 2,
            Exit::NothingJudged => 3,
            Exit::Interrupted(signal) => crate::stop::exit_code(signal),
        }
    }
}
