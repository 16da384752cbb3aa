//! One line read as the adapter reads it, apart from a process: an answer
//! into a frame, a hello into what it refuses (the fuzz targets drive
//! these).

use super::answer::frame_from_line;
use super::envelope::not_json;
use super::hello::{self, Answers, Hello};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::Scene;

/// Reads one response line as the adapter does, into a frame for `scene`
/// drawn under `plan`, or the reason it is refused (an unsupported case, a
/// reported error, a malformed answer). The `protocol_response` fuzz target
/// drives it.
pub fn read_answer(line: &[u8], scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    Ok(frame_from_line(line, scene, plan, Answers::default())?)
}

/// Reads a line as a hello: `Ok(None)` when it is not one, else the reason
/// its declared capabilities refuse `scene` drawn under `plan`, if any.
pub fn read_hello(line: &[u8], scene: &Scene, plan: &Plan) -> Result<Option<String>, String> {
    let value = serde_json::from_slice(line).map_err(|e| not_json(line, &e))?;
    if !hello::is_hello(&value) {
        return Ok(None);
    }
    Ok(Hello::parse(&value)?.refuses(scene, plan))
}
