//! Rasterizers in other processes, in any language, speaking the protocol
//! of SPEC.md §12: `external:PROGRAM [ARGS]` (one process per case) and
//! `external-persistent:PROGRAM [ARGS]` (JSON Lines, a process reused).
//! What a program may do, the process groups, protocol v2 and the hello:
//! [`docs/drivers/external.md`](../../../docs/drivers/external.md).
//!
//! A name passes `names.rs` (read into an adapter) and `preflight.rs` (can
//! the program start); a case passes `adapter.rs` (the
//! [`Rasterizer`](crate::rasterizer::Rasterizer), under `limits.rs`), then
//! `one_shot.rs` or `pool.rs` (with `worker.rs`'s persistent processes and
//! `process.rs`' waiting, killing and reading), whose requests are
//! `protocol.rs`' and answers `answer.rs`' (`answer_error.rs`: why a line gave no frame; `exr_answer.rs`: an answer in an EXR file; `values.rs`, `motion.rs`, `hello.rs` with `space.rs`:
//! clip space, points and depth formats, declared, and `conservative.rs`:
//! conservative rasterization, declared); `read.rs` reads
//! one line apart from a process; `running.rs` says whether one still runs; `envelope.rs` looks at a line's id
//! and shape; `messages.rs` quotes values.

mod adapter;
mod answer;
mod answer_error;
mod conservative;
mod envelope;
mod exr_answer;
mod hello;
mod limits;
mod messages;
mod motion;
mod names;
mod one_shot;
mod pool;
mod preflight;
mod process;
mod protocol;
mod read;
mod running;
mod space;
mod values;
mod worker;

pub use adapter::External;
pub use answer::{frame_from_answer, frame_from_line, frame_from_response};
pub use answer_error::AnswerError;
pub use hello::Answers;
pub use limits::{
    check_environment, DEFAULT_MAX_OUTPUT, DEFAULT_TIMEOUT, MAX_OUTPUT_ENV, TIMEOUT_ENV,
};
pub use messages::shorten;
pub use names::{by_name, check_name, split_name};
pub use preflight::preflight;
pub use protocol::{request, request_v2, Request, PROTOCOL, PROTOCOL_V2};
pub use read::{read_answer, read_hello};
