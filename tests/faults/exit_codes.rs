//! Faults: exit codes (SPEC §9): nothing judged, bad environment, broken pipes, absurd flags.
