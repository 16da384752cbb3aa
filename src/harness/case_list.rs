//! A compact list of case files (id and path): every case's id back to
//! back in one text buffer, its path rebuilt from the id and a prefix
//! shared by a run of cases, and 8 bytes more per case, so that a
//! selection of a million cases costs its ids and 8 bytes a case, not a
//! `CaseFile` (two heap strings) each.

use std::borrow::Cow;
use std::cmp::Ordering;
use std::path::{Path, PathBuf};

/// The extension a case file found by a walk has: a path that is its
/// prefix, its id and this is kept as the prefix alone.
const EXTENSION: &str = ".json";

/// Case files in order, compactly. Each case file found has a place (the
/// order it was pushed in) and its id in `text`; `ends` holds where each
/// place's id ends, modulo 2^32 (`wraps`: the places at which the true
/// end passed another multiple of 2^32, so that the text may pass 4 GiB);
/// `order` lists the places in the list, in its order. A path is almost
/// always a prefix, the id and `.json` (`cases/` + `triangles/fan` +
/// `.json`): `runs` names, for each run of places that share a prefix,
/// its first place and its prefix in `prefixes`; a path that is not so
/// (given by hand with another extension, not UTF-8, rare) is kept whole
/// in `odd`, by its place. Sorting and selecting reorder and shorten
/// `order` alone, in place, so a list never needs a second copy of its
/// text: a case costs its id, 4 bytes of end and 4 of order.
#[derive(Clone, Debug, Default)]
pub struct CaseList {
    text: String,
    ends: Vec<u32>,
    wraps: Vec<u32>,
    prefixes: Vec<String>,
    runs: Vec<(u32, u32)>,
    odd: Vec<(u32, PathBuf)>,
    order: Vec<u32>,
}

/// The most case files one list holds (its places are `u32`s; a run
/// names a case by its place plus one in 32 bits,
/// `harness/unique_names.rs`).
pub const MAX_CASES: usize = u32::MAX as usize;

impl CaseList {
    pub fn len(&self) -> usize {
        self.order.len()
    }

    pub fn is_empty(&self) -> bool {
        self.order.is_empty()
    }

    /// Adds a case file by its id and path; `false`, and nothing added,
    /// when the list holds [`MAX_CASES`] (or the id is 4 GiB long).
    pub fn push(&mut self, id: &str, path: &Path) -> bool {
        if self.ends.len() >= MAX_CASES || u32::try_from(id.len()).is_err() {
            return false;
        }
        let place = self.ends.len() as u32;
        let before = self.text.len() as u64;
        self.text.push_str(id);
        let end = self.text.len() as u64;
        if end >> 32 != before >> 32 {
            self.wraps.push(place);
        }
        self.ends.push(end as u32);
        self.order.push(place);
        // The prefix, when the path is one, the id and `.json`.
        let prefix = path
            .to_str()
            .and_then(|p| p.strip_suffix(EXTENSION))
            .and_then(|p| p.strip_suffix(id));
        match prefix {
            Some(prefix) => {
                let same = self
                    .runs
                    .last()
                    .is_some_and(|&(_, k)| self.prefixes[k as usize] == prefix);
                if !same {
                    self.runs.push((place, self.prefixes.len() as u32));
                    self.prefixes.push(prefix.to_owned());
                }
            }
            None => self.odd.push((place, path.to_owned())),
        }
        true
    }

    /// The id at `place`.
    fn id_at(&self, place: u32) -> &str {
        let end_at = |place: u32| {
            let high = self.wraps.partition_point(|&w| w <= place) as u64;
            ((high << 32) | self.ends[place as usize] as u64) as usize
        };
        let start = match place {
            0 => 0,
            _ => end_at(place - 1),
        };
        &self.text[start..end_at(place)]
    }

    /// The path at `place`: its prefix, id and `.json`, or kept whole.
    fn path_at(&self, place: u32) -> Cow<'_, Path> {
        if let Ok(i) = self.odd.binary_search_by_key(&place, |(p, _)| *p) {
            return Cow::Borrowed(self.odd[i].1.as_path());
        }
        let run = self.runs.partition_point(|&(first, _)| first <= place) - 1;
        let prefix = &self.prefixes[self.runs[run].1 as usize];
        Cow::Owned(PathBuf::from(format!(
            "{prefix}{}{EXTENSION}",
            self.id_at(place)
        )))
    }

    /// Case `k`'s id. Panics past the end, as indexing does.
    pub fn id(&self, k: usize) -> &str {
        self.id_at(self.order[k])
    }

    /// Case `k`'s path. Panics past the end, as indexing does.
    pub fn path(&self, k: usize) -> Cow<'_, Path> {
        self.path_at(self.order[k])
    }

    /// Case `k`'s id and path, or `None` past the end.
    pub fn get(&self, k: usize) -> Option<(String, PathBuf)> {
        (k < self.len()).then(|| (self.id(k).to_owned(), self.path(k).into_owned()))
    }

    /// Every id, in order.
    pub fn ids(&self) -> impl Iterator<Item = &str> {
        (0..self.len()).map(|k| self.id(k))
    }

    /// The cases `keep` is true of, in order; `keep` is given the list and
    /// each case's index, in order.
    pub fn retain(mut self, mut keep: impl FnMut(&CaseList, usize) -> bool) -> CaseList {
        // Asked first, of the whole list (1 byte a case), then kept.
        let kept: Vec<bool> = (0..self.len()).map(|k| keep(&self, k)).collect();
        let mut k = 0;
        self.order.retain(|_| {
            k += 1;
            kept[k - 1]
        });
        self
    }

    /// Case `a` against case `b` by their places, as (id, path) pairs
    /// (and `CaseFile`s) compare: by id, then by path (component by
    /// component; built only when the ids are equal).
    fn compare_places(&self, a: u32, b: u32) -> Ordering {
        self.id_at(a)
            .cmp(self.id_at(b))
            .then_with(|| self.path_at(a).cmp(&self.path_at(b)))
    }

    /// Sorted as a `Vec` of (id, path) pairs (or of `CaseFile`s) sorts, each (id, path) pair once, as
    /// `sort` then `dedup` leave it.
    pub fn sorted(mut self) -> CaseList {
        let mut order = std::mem::take(&mut self.order);
        order.sort_unstable_by(|&a, &b| self.compare_places(a, b));
        order.dedup_by(|b, a| self.compare_places(*a, *b) == Ordering::Equal);
        self.order = order;
        self
    }

    /// Every case's id and path, in order.
    pub fn into_vec(self) -> Vec<(String, PathBuf)> {
        (0..self.len()).filter_map(|k| self.get(k)).collect()
    }
}

impl PartialEq for CaseList {
    /// The same cases in the same order.
    fn eq(&self, other: &CaseList) -> bool {
        self.len() == other.len()
            && (0..self.len()).all(|k| self.id(k) == other.id(k) && self.path(k) == other.path(k))
    }
}

impl Eq for CaseList {}

impl<'a> FromIterator<(&'a str, &'a Path)> for CaseList {
    fn from_iter<I: IntoIterator<Item = (&'a str, &'a Path)>>(cases: I) -> Self {
        let mut list = CaseList::default();
        for (id, path) in cases {
            list.push(id, path);
        }
        list
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn case(id: &str, path: &str) -> (String, PathBuf) {
        (id.to_owned(), path.into())
    }

    fn list(cases: &[(String, PathBuf)]) -> CaseList {
        cases
            .iter()
            .map(|(id, path)| (id.as_str(), path.as_path()))
            .collect()
    }

    #[test]
    fn sorts_and_dedups_as_a_vec_of_pairs_does() {
        let cases = vec![
            case("b/2", "cases/b/2.json"),
            case("a/1", "x/cases/a/1.json"),
            case("a/1", "cases/a/1.json"),
            case("a/10", "cases/a/10.json"),
            case("b/2", "cases/b/2.json"),
            case("a/1", "cases/./a/1.json"),
            case("", ""),
            case("é/ü", "cases/é/ü.json"),
            case("a/2", "cases/a/2.txt"),
            case("a/3", "other/a/3.json"),
            case("b/3", "cases/b/3.json"),
        ];
        let mut expected = cases.clone();
        expected.sort();
        expected.dedup();
        let sorted = list(&cases).sorted();
        assert_eq!(sorted.clone().into_vec(), expected);
        assert_eq!(sorted.len(), expected.len());
        assert_eq!(
            sorted.ids().collect::<Vec<_>>(),
            expected.iter().map(|c| c.0.as_str()).collect::<Vec<_>>()
        );
        assert_eq!(sorted.get(sorted.len()), None);
        // `keep` sees the whole list, by the indices before the cut.
        let odd = sorted.retain(|list, k| {
            (k % 2 == 1 || list.id(k).is_empty()) && (k == 0 || !list.id(k - 1).is_empty())
        });
        assert_eq!(
            odd.into_vec(),
            expected
                .iter()
                .enumerate()
                .filter(|(k, c)| {
                    (k % 2 == 1 || c.0.is_empty()) && (*k == 0 || !expected[k - 1].0.is_empty())
                })
                .map(|(_, c)| c.clone())
                .collect::<Vec<_>>()
        );
    }

    #[test]
    fn a_case_found_by_a_walk_costs_its_id_and_8_bytes() {
        // As a walk over `gen/` (RELIABILITY.md's generated cases) and over
        // `cases/` gives them.
        let n = 10_000;
        let cases: Vec<(String, PathBuf)> = (0..n)
            .map(|k| format!("gen/c{k:07}"))
            .map(|id| (id.clone(), format!("{id}.json").into()))
            .chain((0..n).map(|k| {
                let id = format!("triangles/t{k:07}");
                (id.clone(), format!("cases/{id}.json").into())
            }))
            .collect();
        let list = list(&cases);
        let ids: usize = cases.iter().map(|c| c.0.len()).sum();
        let bytes = list.text.len()
            + 4 * (list.ends.len() + list.order.len() + list.wraps.len())
            + 8 * list.runs.len()
            + list.prefixes.iter().map(String::len).sum::<usize>()
            + list.odd.len() * std::mem::size_of::<(u32, PathBuf)>();
        // Two runs of one prefix each (8 bytes and the prefix), no path
        // kept whole.
        assert_eq!((list.runs.len(), list.odd.len()), (2, 0));
        assert_eq!(bytes, ids + 8 * cases.len() + 2 * 8 + "cases/".len());
        let sorted = list.sorted();
        assert_eq!(sorted.into_vec(), cases);
    }

    #[cfg(unix)]
    #[test]
    fn keeps_a_path_that_is_not_utf8() {
        use std::os::unix::ffi::OsStrExt;
        let bad = PathBuf::from(std::ffi::OsStr::from_bytes(b"cases/a/\xff.json"));
        let cases = vec![
            case("a/z", "cases/a/z.json"),
            ("a/\u{fffd}".to_owned(), bad.clone()),
            case("a/b", "cases/a/b.json"),
        ];
        let mut expected = cases.clone();
        expected.sort();
        let sorted = list(&cases).sorted();
        assert_eq!(sorted.clone().into_vec(), expected);
        assert_eq!(sorted.path(2), bad.as_path());
    }
}
