//! A compact list of case files (id and path): every case's id and path
//! back to back in one text buffer, with one packed number and one place
//! per case, so that a selection of a million cases costs tens of bytes a
//! case, not a `CaseFile` (two heap strings) each.

use std::cmp::Ordering;
use std::path::{Path, PathBuf};

/// Bits of a packed bound that hold the end of a case's text; the bits
/// above hold the length of its id. 2^40 bytes of text and ids of up to
/// 2^24 bytes: far past what memory or a file system holds.
const END_BITS: u32 = 40;
const END_MASK: u64 = (1 << END_BITS) - 1;

/// Case files in order, compactly: each case file found has its id and
/// then its path (when the path is UTF-8) in `text`, and one `u64` in
/// `bounds`: where its text ends and how long its id is; `order` lists the
/// ones in the list, in its order, by their place in `bounds`. Sorting and
/// selecting reorder and shorten `order` alone, in place, so a list never
/// needs a second copy of its text: a case costs its id and path, 8 bytes
/// of bounds and 4 of order. A path that is not UTF-8 (rare) is kept whole
/// in `odd`, by its place in `bounds`.
#[derive(Clone, Debug, Default)]
pub struct CaseList {
    text: String,
    bounds: Vec<u64>,
    odd: Vec<(u32, PathBuf)>,
    order: Vec<u32>,
}

/// The most case files one list holds (its places are `u32`s).
pub const MAX_CASES: usize = u32::MAX as usize;

impl CaseList {
    pub fn len(&self) -> usize {
        self.order.len()
    }

    pub fn is_empty(&self) -> bool {
        self.order.is_empty()
    }

    /// Adds a case file by its id and path; `false`, and nothing added,
    /// when the list holds [`MAX_CASES`].
    pub fn push(&mut self, id: &str, path: &Path) -> bool {
        let Ok(place) = u32::try_from(self.bounds.len()) else {
            return false;
        };
        self.text.push_str(id);
        match path.to_str() {
            Some(path) => self.text.push_str(path),
            None => self.odd.push((place, path.to_owned())),
        }
        self.bounds
            .push(self.text.len() as u64 | ((id.len() as u64) << END_BITS));
        self.order.push(place);
        true
    }

    /// The byte range of the text at `place` in `bounds`, and its id's
    /// length.
    fn span(&self, place: u32) -> (usize, usize, usize) {
        let place = place as usize;
        let start = match place {
            0 => 0,
            _ => (self.bounds[place - 1] & END_MASK) as usize,
        };
        let end = (self.bounds[place] & END_MASK) as usize;
        (start, end, (self.bounds[place] >> END_BITS) as usize)
    }

    /// Case `k`'s id. Panics past the end, as indexing does.
    pub fn id(&self, k: usize) -> &str {
        let (start, _, id_len) = self.span(self.order[k]);
        &self.text[start..start + id_len]
    }

    /// Case `k`'s path. Panics past the end, as indexing does.
    pub fn path(&self, k: usize) -> &Path {
        let place = self.order[k];
        let (start, end, id_len) = self.span(place);
        match self.odd.binary_search_by_key(&place, |(i, _)| *i) {
            Ok(i) => &self.odd[i].1,
            Err(_) => Path::new(&self.text[start + id_len..end]),
        }
    }

    /// Case `k`'s id and path, or `None` past the end.
    pub fn get(&self, k: usize) -> Option<(String, PathBuf)> {
        (k < self.len()).then(|| (self.id(k).to_owned(), self.path(k).to_owned()))
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
    /// (and `CaseFile`s) compare: by id, then by path (component by component).
    fn compare_places(&self, a: u32, b: u32) -> Ordering {
        let id = |place| {
            let (start, _, id_len) = self.span(place);
            &self.text[start..start + id_len]
        };
        let path = |place| {
            let (start, end, id_len) = self.span(place);
            match self.odd.binary_search_by_key(&place, |(i, _)| *i) {
                Ok(i) => self.odd[i].1.as_path(),
                Err(_) => Path::new(&self.text[start + id_len..end]),
            }
        };
        id(a).cmp(id(b)).then_with(|| path(a).cmp(path(b)))
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
