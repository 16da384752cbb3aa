//! Faults: external programs that flood, hang, leak or answer with hostile files.
