//! Case names unique in a run, checked from 64-bit hashes: a run keeps 8
//! bytes a slot (a 32-bit part of a name's hash and the index of the case
//! that first used it), not the name, and reads the earlier case file
//! again when two hashes meet, so that uniqueness stays exact (no
//! duplicate missed, none reported that is not one).

use std::collections::HashMap;
use std::hash::{BuildHasher, RandomState};

/// The slots of a table for `cases` names: 5 for every 4, and one more,
/// so that at most 4 of 5 are used (linear probing looks at about 13 slots
/// to find a free one at that load, 3 to find a name) and one is always
/// empty. At 8 bytes a slot: 10 bytes a case.
fn slots_for(cases: usize) -> usize {
    cases + cases / 4 + 1
}

/// The names seen so far in a run, by hash: an open-addressing table with
/// linear probing, made once at the run's number of cases (so that it
/// never grows, and never holds an old and a new table at once).
pub struct UniqueNames<S = RandomState> {
    /// Keyed afresh each run (`RandomState`), so that no input can be made
    /// to collide on purpose.
    hasher: S,
    /// 0 (empty) or a name's tag (the high 32 bits of its hash) above the
    /// index of the first case that used it, plus one. A name's first slot
    /// looked at comes from the low 32 bits of its hash, so that two names
    /// meet (and a file is read again) only when their tags agree in a
    /// slot looked at: at a load of 4/5, about 13 slots of 2^32 tags, 3
    /// names in 10^9.
    slots: Box<[u64]>,
    /// How many cases the table was made for.
    cases: usize,
    /// The names read again, or known, after two hashes met (rare), by the
    /// case that used them first; `None` when its file no longer reads.
    spelled: HashMap<usize, Option<String>>,
}

impl UniqueNames {
    /// A table for the names of cases `0..cases`.
    pub fn for_cases(cases: usize) -> UniqueNames {
        UniqueNames::with_hasher(cases, RandomState::new())
    }
}

impl<S: BuildHasher> UniqueNames<S> {
    /// A table for the names of cases `0..cases`, hashed by `hasher`.
    ///
    /// # Panics
    /// Past `u32::MAX` cases (a run refuses more: `case_list::MAX_CASES`).
    pub fn with_hasher(cases: usize, hasher: S) -> UniqueNames<S> {
        assert!(cases <= u32::MAX as usize, "{cases} cases: past u32::MAX");
        UniqueNames {
            hasher,
            slots: vec![0; slots_for(cases)].into_boxed_slice(),
            cases,
            spelled: HashMap::new(),
        }
    }

    /// Case `k` uses `name`: the index of an earlier case that used it
    /// already, or `None` (then the name is noted as case `k`'s).
    /// `name_of` reads an earlier case's name again (`None` when it no
    /// longer can be: then the names count as different); it is called
    /// only when `name`'s hash meets one seen before, at most once per
    /// earlier case.
    ///
    /// # Panics
    /// When `k` is not below the number of cases the table was made for.
    pub fn used_before(
        &mut self,
        name: &str,
        k: usize,
        mut name_of: impl FnMut(usize) -> Option<String>,
    ) -> Option<usize> {
        assert!(k < self.cases, "case {k} of {}", self.cases);
        let hash = self.hasher.hash_one(name);
        let tag = hash >> 32;
        // The low 32 bits, spread over the slots (`x · n / 2^32`).
        let n = self.slots.len();
        let mut i = (((hash & 0xffff_ffff) as u128 * n as u128) >> 32) as usize;
        let mut met = false;
        loop {
            let slot = self.slots[i];
            if slot == 0 {
                self.slots[i] = (tag << 32) | (k as u64 + 1);
                if met {
                    // Known without reading its file, should it meet again.
                    self.spelled.insert(k, Some(name.to_owned()));
                }
                return None;
            }
            if slot >> 32 == tag {
                met = true;
                let first = (slot & 0xffff_ffff) as usize - 1;
                let earlier = self.spelled.entry(first).or_insert_with(|| name_of(first));
                if earlier.as_deref() == Some(name) {
                    return Some(first);
                }
            }
            i = if i + 1 == n { 0 } else { i + 1 };
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
        let (found, reads) = check_all(&mut UniqueNames::for_cases(NAMES.len()), &NAMES);
        assert_eq!(found, EXPECTED);
        // Read again once per name that has a duplicate (64-bit hashes of
        // four names do not meet).
        assert_eq!(reads, 3);
    }

    #[test]
    fn hashes_that_meet_are_decided_by_the_real_names() {
        let colliding = |n| UniqueNames::with_hasher(n, Colliding);
        let (found, reads) = check_all(&mut colliding(NAMES.len()), &NAMES);
        assert_eq!(found, EXPECTED);
        // Only the first case's file is read again.
        assert_eq!(reads, 1);
        // Names that share a hash but differ are not duplicates.
        let (found, _) = check_all(&mut colliding(4), &["x", "y", "z", "y"]);
        assert_eq!(found, [None, None, None, Some(1)]);
        // A file that can no longer be read counts as another name.
        let mut table = colliding(3);
        assert_eq!(table.used_before("p", 0, |_| None), None);
        assert_eq!(table.used_before("p", 1, |_| None), None);
        assert_eq!(table.used_before("p", 2, |_| None), Some(1));
    }

    #[test]
    fn a_name_costs_10_bytes_of_table() {
        for n in [0, 1, 4, 1_000_000] {
            let bytes = std::mem::size_of_val(&*UniqueNames::for_cases(n).slots);
            assert_eq!(bytes, 8 * (n + n / 4 + 1), "{n} cases");
            assert!(bytes <= 10 * n + 8, "{n} cases");
        }
    }

    #[test]
    fn a_full_table_still_finds_every_duplicate() {
        // As many distinct names as cases, then the same again: the table
        // is at its fullest, every probe wraps past its end somewhere.
        for n in [1, 2, 3, 4, 5, 17, 1000] {
            let names: Vec<String> = (0..n).map(|k| format!("n{k}")).collect();
            let mut table = UniqueNames::for_cases(n);
            for (k, name) in names.iter().enumerate() {
                assert_eq!(table.used_before(name, k, |j| Some(names[j].clone())), None);
            }
            let mut again = UniqueNames::for_cases(2 * n);
            for (k, name) in names.iter().chain(&names).enumerate() {
                let found = again.used_before(name, k, |j| Some(names[j % n].clone()));
                assert_eq!(found, (k >= n).then_some(k - n), "{n} names, case {k}");
            }
            // Every name hashed alike: one probe run over the whole table.
            let mut one_run = UniqueNames::with_hasher(n, Colliding);
            for (k, name) in names.iter().enumerate() {
                assert_eq!(
                    one_run.used_before(name, k, |j| Some(names[j].clone())),
                    None
                );
            }
        }
    }
}
