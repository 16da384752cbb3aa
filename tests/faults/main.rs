//! Faults injected into whole runs (issue 17): every verdict survives a
//! crash, hang, huge or hostile input, signal or limit in one case. Each
//! module is one family of fault; each test asserts that the run finishes,
//! the other cases keep their verdicts, report.json parses, and the exit
//! code is the documented one.

#[path = "../common/mod.rs"]
mod common;

mod answers;
mod exit_codes;
mod external;
mod input;
mod memory;
mod reports;
