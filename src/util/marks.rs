//! A growable row of marks, one bit per element: the removed vertices and tetrahedra of
//! an edited structure. A `Vec<bool>` spends a byte on each, eight times what the answer
//! needs, on arrays as long as the mesh.

use crate::error::Result;
use crate::util::alloc::{try_grow, try_vec};

/// Marks `0..len`, all clear until [`Marks::set`].
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Marks {
    words: Vec<u64>,
    len: usize,
}

impl Marks {
    /// `len` clear marks; `what` names the array in an out-of-memory error.
    pub(crate) fn clear_of(len: usize, what: &str) -> Result<Self> {
        Ok(Marks {
            words: try_vec(len.div_ceil(64), 0, what)?,
            len,
        })
    }

    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Mark `i`, or `None` past the end.
    pub(crate) fn get(&self, i: usize) -> Option<bool> {
        (i < self.len).then(|| self.words[i / 64] >> (i % 64) & 1 == 1)
    }

    /// Sets mark `i`. Panics past the end, as indexing a slice does.
    pub(crate) fn set(&mut self, i: usize) {
        assert!(i < self.len, "mark {i} of {}", self.len);
        self.words[i / 64] |= 1 << (i % 64);
    }

    /// Room for `additional` more marks, growing by amortised steps.
    pub(crate) fn try_grow(&mut self, additional: usize, what: &str) -> Result<()> {
        let more = (self.len + additional)
            .div_ceil(64)
            .saturating_sub(self.words.len());
        try_grow(&mut self.words, more, what)
    }

    /// One more mark at the end, clear unless `mark`; room made first by
    /// [`Marks::try_grow`] (else the push may allocate).
    pub(crate) fn push(&mut self, mark: bool) {
        if self.len.is_multiple_of(64) {
            self.words.push(0);
        }
        self.len += 1;
        if mark {
            self.set(self.len - 1);
        }
    }

    /// `len` clear marks, in the place of these.
    pub(crate) fn reset(&mut self, len: usize, what: &str) -> Result<()> {
        *self = Marks::clear_of(len, what)?;
        Ok(())
    }

    /// The marks in order.
    pub(crate) fn iter(&self) -> impl Iterator<Item = bool> + '_ {
        (0..self.len).map(|i| self[i])
    }

    /// How many marks are clear.
    pub(crate) fn count_clear(&self) -> usize {
        let set: u32 = self.words.iter().map(|w| w.count_ones()).sum();
        self.len - set as usize
    }

    /// Bytes of the marks as stored.
    pub(crate) fn memory_bytes(&self) -> usize {
        8 * self.words.len()
    }
}

impl std::ops::Index<usize> for Marks {
    type Output = bool;

    /// Mark `i`; panics past the end, as indexing a slice does.
    fn index(&self, i: usize) -> &bool {
        match self.get(i) {
            Some(true) => &true,
            Some(false) => &false,
            None => panic!("mark {i} of {}", self.len),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Marks;

    /// Pushes, sets and resets across word boundaries answer as a `Vec<bool>` does.
    #[test]
    fn marks_are_a_vec_of_bools() {
        let mut rnd = crate::util::test_rng(7);
        for start in [0, 1, 63, 64, 65, 200] {
            let mut marks = Marks::clear_of(start, "test").unwrap();
            let mut bools = vec![false; start];
            for _ in 0..300 {
                match rnd(3) {
                    0 => {
                        let mark = rnd(2) == 1;
                        marks.try_grow(1, "test").unwrap();
                        marks.push(mark);
                        bools.push(mark);
                    }
                    _ if !bools.is_empty() => {
                        let i = rnd(bools.len()) as usize;
                        marks.set(i);
                        bools[i] = true;
                    }
                    _ => {}
                }
                assert_eq!(marks.len(), bools.len());
                assert!(marks.iter().eq(bools.iter().copied()));
                let clear = bools.iter().filter(|&&b| !b).count();
                assert_eq!(marks.count_clear(), clear);
                assert_eq!(marks.get(bools.len()), None);
                for (i, &b) in bools.iter().enumerate() {
                    assert_eq!((marks.get(i), marks[i]), (Some(b), b));
                }
                assert_eq!(marks.memory_bytes(), 8 * bools.len().div_ceil(64));
            }
            marks.reset(start, "test").unwrap();
            assert_eq!(marks, Marks::clear_of(start, "test").unwrap());
        }
    }

    #[test]
    #[should_panic(expected = "mark 5 of 5")]
    fn a_mark_past_the_end_panics() {
        let _ = Marks::clear_of(5, "test").unwrap()[5];
    }
}
