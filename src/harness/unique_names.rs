//! Case names unique in a run, checked from 64-bit hashes: a run keeps one
//! hash and one index per name, not the name, and reads the earlier case
//! file again when two hashes meet, so that uniqueness stays exact (no
//! duplicate missed, none reported that is not one).

use std::collections::{HashMap, HashSet};
use std::hash::{BuildHasher, RandomState};

/// The names seen so far in a run, by hash.
#[derive(Default)]
pub struct UniqueNames<S = RandomState> {
    /// Keyed afresh each run (`RandomState`), so that no input can be made
    /// to collide on purpose.
    hasher: S,
    /// Each hash seen, with the index of the first case whose name has it.
    first: HashMap<u64, usize>,
    /// The real names behind hashes that met (rare): each with the first
    /// case that used it.
    spelled: HashMap<String, usize>,
    /// The first cases whose names were read again into `spelled`.
    read: HashSet<usize>,
}

impl UniqueNames {
    pub fn new() -> UniqueNames {
        UniqueNames::default()
    }

    /// Room for `n` names made at once: a table grown by doubling holds
    /// its old and new halves together while it grows (half as much again
    /// at its peak).
    pub fn with_capacity(n: usize) -> UniqueNames {
        UniqueNames {
            first: HashMap::with_capacity(n),
            ..UniqueNames::default()
        }
    }
}

impl<S: BuildHasher> UniqueNames<S> {
    /// Case `k` uses `name`: the index of an earlier case that used it
    /// already, or `None` (then the name is noted as case `k`'s).
    /// `name_of` reads an earlier case's name again (`None` when it no
    /// longer can be: then the names count as different); it is called
    /// only when `name`'s hash is one seen before, once per earlier case.
    pub fn used_before(
        &mut self,
        name: &str,
        k: usize,
        name_of: impl FnOnce(usize) -> Option<String>,
    ) -> Option<usize> {
        let hash = self.hasher.hash_one(name);
        let first = *self.first.entry(hash).or_insert(k);
        if first == k {
            return None;
        }
        if self.read.insert(first) {
            if let Some(earlier) = name_of(first) {
                self.spelled.entry(earlier).or_insert(first);
            }
        }
        match self.spelled.get(name) {
            Some(&earlier) => Some(earlier),
            None => {
                self.spelled.insert(name.to_owned(), k);
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every name's hash the same: every check after the first meets an
    /// earlier hash, and the real names decide.
    #[derive(Default)]
    struct Colliding;
    impl BuildHasher for Colliding {
        type Hasher = Constant;
        fn build_hasher(&self) -> Constant {
            Constant
        }
    }
    struct Constant;
    impl std::hash::Hasher for Constant {
        fn finish(&self) -> u64 {
            7
        }
        fn write(&mut self, _: &[u8]) {}
    }

    /// Each case's earlier user over `names` in order, and how many names
    /// were read again.
    fn check_all<S: BuildHasher>(
        table: &mut UniqueNames<S>,
        names: &[&str],
    ) -> (Vec<Option<usize>>, usize) {
        let mut reads = 0;
        let found = (0..names.len())
            .map(|k| {
                table.used_before(names[k], k, |j| {
                    reads += 1;
                    Some(names[j].to_owned())
                })
            })
            .collect();
        (found, reads)
    }

    const NAMES: [&str; 8] = ["a", "b", "a", "c", "b", "d", "a", "c"];
    const EXPECTED: [Option<usize>; 8] =
        [None, None, Some(0), None, Some(1), None, Some(0), Some(3)];

    #[test]
    fn finds_every_duplicate_with_its_first_user() {
        let (found, reads) = check_all(&mut UniqueNames::new(), &NAMES);
        assert_eq!(found, EXPECTED);
        // Read again once per name that has a duplicate (64-bit hashes of
        // four names do not meet).
        assert_eq!(reads, 3);
    }

    #[test]
    fn hashes_that_meet_are_decided_by_the_real_names() {
        let (found, reads) = check_all(&mut UniqueNames::<Colliding>::default(), &NAMES);
        assert_eq!(found, EXPECTED);
        // Only the first case's file is read again.
        assert_eq!(reads, 1);
        // Names that share a hash but differ are not duplicates.
        let (found, _) = check_all(
            &mut UniqueNames::<Colliding>::default(),
            &["x", "y", "z", "y"],
        );
        assert_eq!(found, [None, None, None, Some(1)]);
        // A file that can no longer be read counts as another name.
        let mut table = UniqueNames::<Colliding>::default();
        assert_eq!(table.used_before("p", 0, |_| None), None);
        assert_eq!(table.used_before("p", 1, |_| None), None);
        assert_eq!(table.used_before("p", 2, |_| None), Some(1));
    }
}
