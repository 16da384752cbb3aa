//! Faults: wrong answers the harness gave (golden lookup, the reference on its own cases, motion).
