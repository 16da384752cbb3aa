//! Faults: reports that must stay whole (atomic writes, stale files, signals).
