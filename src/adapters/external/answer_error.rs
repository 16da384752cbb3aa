//! Why a response line gave no frame, and by whose doing: the kind the
//! pool acts on (a v1 process is retired only for an ill-fitting line), and
//! the [`RasterError`] a result shows.

use crate::rasterizer::RasterError;

/// How the failure of an answer that is the program's own `error` begins.
pub(super) const PROGRAM_ERROR: &str = "the program reported an error: ";

/// Why a response line gave no frame, by whose doing: the program's own
/// answer (`unsupported`, `error`: it is in step, and said so), or a line
/// that does not fit its request (under protocol v1 it may be another
/// request's answer).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AnswerError {
    /// The program answered `unsupported`, with its reason.
    Unsupported(String),
    /// The program answered `error`, with its text.
    Program(String),
    /// The line is not an answer to this request: not JSON, or not shaped
    /// as its request asks (SPEC.md §12.2).
    Unfit(String),
}

impl From<AnswerError> for RasterError {
    fn from(e: AnswerError) -> RasterError {
        match e {
            AnswerError::Unsupported(why) => RasterError::Unsupported(why),
            AnswerError::Program(why) => RasterError::Failed(format!("{PROGRAM_ERROR}{why}")),
            AnswerError::Unfit(why) => RasterError::Failed(why),
        }
    }
}
