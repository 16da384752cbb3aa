//! Faults: hostile case input (huge files, special files, symlink loops, duplicate keys and ids).
