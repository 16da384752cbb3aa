//! The `case_json` target: arbitrary bytes into the case reader.

use crate::explore::fuzz::case_json::case_json as write_case;
use crate::harness::oracle;
use crate::production::Production;
use crate::rasterizer::{RasterError, Rasterizer};
use crate::scene::{parse_case, Limits};

/// The reader's limits here: SPEC.md's, with a smaller canvas, fewer
/// primitives and samples, so that a case the reader accepts runs through
/// the reference in milliseconds. Over these, the reader must refuse with
/// an error, which is also checked.
pub(super) fn limits() -> Limits {
    Limits {
        max_canvas_pixels: 64 * 64,
        max_primitives: 64,
        max_samples: 1 << 16,
        max_case_bytes: 1 << 20,
        ..Limits::default()
    }
}

/// Reads `data` as a case file. No input may panic the reader; an accepted
/// case must write back to a file that reads back as the same case, and
/// must run through the reference. Production must then draw it without
/// an error (a panic is a finding too) and, where nothing moves, cover exactly the reference's
/// samples with the same owners (values are judged against bounds, not
/// here; a case's own expectations may be wrong, and are not judged); a
/// conservative case's pixels each as the reference's class allows.
pub fn case_json(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(scene) = parse_case(text, "fuzz.json", &limits()) else {
        return;
    };
    let written = write_case(&scene);
    match parse_case(&written, "written.json", &limits()) {
        Ok(again) => assert_eq!(
            write_case(&again),
            written,
            "a case does not read back as written"
        ),
        Err(e) => panic!("an accepted case, written back, is refused: {e}\n{written}"),
    }
    let reference = oracle::run_reference(&scene);
    if Production.capabilities().refuses(&scene).is_some() || reference.time.is_some() {
        return;
    }
    // A conservative case (SPEC.md §19): every pixel as its class allows.
    if let Some(classes) = &reference.conservative {
        let Ok(classes) = classes else {
            return;
        };
        match Production.rasterize(&scene, &reference.plan) {
            Ok(frame) => {
                let wrong = (0..classes.drawn.len())
                    .filter(|&i| {
                        crate::metrics::conservative::pixel_drawn(&frame, i)
                            .is_none_or(|drawn| !classes.drawn[i].admits(drawn))
                    })
                    .count();
                assert!(
                    wrong == 0,
                    "{FOUND_BY_CASE_TARGET}: {wrong} pixels outside the conservative classes\n{written}"
                );
            }
            Err(RasterError::Unsupported(_)) => {}
            Err(RasterError::Failed(why)) => {
                panic!("production breaks on an accepted case: {why}\n{written}")
            }
        }
        return;
    }
    match Production.rasterize(&scene, &reference.plan) {
        Ok(frame) => {
            let differ = (0..frame.coverage.len().max(reference.frame.coverage.len()))
                .filter(|&i| {
                    frame.coverage.get(i) != reference.frame.coverage.get(i)
                        || frame.last.get(i) != reference.frame.last.get(i)
                })
                .count();
            assert!(
                differ == 0,
                "{FOUND_BY_CASE_TARGET}: {differ} samples differ\n{written}"
            );
        }
        Err(RasterError::Unsupported(_)) => {}
        Err(RasterError::Failed(why)) => {
            panic!("production breaks on an accepted case: {why}\n{written}")
        }
    }
}

/// What the target's panic message starts with when production and the
/// reference cover different samples.
pub const FOUND_BY_CASE_TARGET: &str = "production's coverage differs from the reference's";
