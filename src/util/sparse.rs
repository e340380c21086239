//! Sparse matrices in compressed sparse rows, the layout Eigen (`Map<SparseMatrix<double,
//! RowMajor, int64_t>>`) and SciPy (`csr_matrix((values, columns, offsets))`) take as is:
//! assembled from (row, column, value) entries given twice, once to count the rows and once
//! to place them, then each short row sorted in place: no entry list is stored or sorted as
//! a whole, and the caller's buffers can be the storage.

use crate::error::{Error, Result};
use std::ops::Range;

/// A sparse matrix: row `r` holds `columns[offsets[r]..offsets[r + 1]]` (sorted, each
/// once) with `values` at the same places.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SparseMatrix {
    pub n_rows: usize,
    pub n_cols: usize,
    /// `n_rows + 1` entries, the first 0.
    pub offsets: Vec<u64>,
    pub columns: Vec<u32>,
    pub values: Vec<f64>,
}

/// One entry of a matrix under construction.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Entry {
    pub row: u32,
    pub col: u32,
    pub value: f64,
}

/// A vector of `n` zeros, or an `OutOfMemory` error.
pub(crate) fn zeros<T: Copy + Default>(n: usize, what: &str) -> Result<Vec<T>> {
    filled(n, T::default(), what)
}

/// Fallible allocation, as everywhere: running out is an `OutOfMemory` error.
pub(crate) use crate::util::alloc::{try_reserve as reserve, try_vec as filled};

impl SparseMatrix {
    /// Row `r`: its columns and values.
    pub fn row(&self, r: usize) -> (&[u32], &[f64]) {
        let (a, b) = (self.offsets[r] as usize, self.offsets[r + 1] as usize);
        (&self.columns[a..b], &self.values[a..b])
    }

    /// The number of stored entries.
    pub fn nnz(&self) -> usize {
        self.columns.len()
    }

    /// The row offsets as 32-bit values, or `Error::too_large` when they do not fit.
    pub fn offsets_u32(&self) -> Result<Vec<u32>> {
        self.offsets
            .iter()
            .map(|&o| u32::try_from(o).map_err(|_| Error::too_large("offsets beyond 32 bits")))
            .collect()
    }
}

/// Takes one entry of a matrix: `row`, `col` and `value`.
pub(crate) trait Put {
    fn put(&mut self, row: u32, col: u32, value: f64);
}

/// The entries of a matrix, given each time `each` is called, in the same order.
pub(crate) trait Entries {
    fn each<P: Put>(&self, p: &mut P);

    /// Whether `each` gives the rows in increasing order (then placing them is a
    /// sequential pass and needs no blocking).
    fn rows_in_order(&self) -> bool {
        false
    }

    /// The number of entries `each` gives, when known without giving them (then the
    /// storage is asked for before they are counted by row).
    fn total(&self) -> Option<usize> {
        None
    }
}

impl Entries for [Entry] {
    fn each<P: Put>(&self, p: &mut P) {
        self.iter().for_each(|e| p.put(e.row, e.col, e.value));
    }
}

/// What a place given more than once holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Values {
    /// The sum of the values given there.
    Summed,
    /// `off`, whatever was given and how often (a pattern); with `degree_diagonal`, a
    /// diagonal place holds the number of other places in its row instead (a Laplacian).
    Pattern { off: f64, degree_diagonal: bool },
}

/// The size of a matrix and how its values are made.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Shape {
    pub n_rows: usize,
    pub n_cols: usize,
    pub values: Values,
}

/// A caller's storage for a matrix (the C API's buffers), initialised.
pub struct CsrSlices<'a> {
    pub offsets: &'a mut [u64],
    pub columns: &'a mut [u32],
    pub values: &'a mut [f64],
}

/// A matrix written into the caller's storage, or made in memory of its own when that
/// storage was not given or is short (it may then hold anything).
#[derive(Debug)]
pub enum Assembled {
    Written { n_offsets: usize, n_entries: usize },
    Owned(SparseMatrix),
}

impl Assembled {
    /// The matrix, when it was made in memory of its own.
    pub(crate) fn owned(self) -> Result<SparseMatrix> {
        match self {
            Assembled::Owned(m) => Ok(m),
            Assembled::Written { .. } => Err(Error::new(
                crate::ErrorKind::InvalidInput,
                "the matrix went to the caller's storage",
            )),
        }
    }
}

/// Rows per block of the blocked assembly: a block's cursors and columns stay in a core's
/// second-level cache while its entries are placed.
const BLOCK_ROWS: usize = 1 << 14;

/// Up to this many rows, the scattered writes of an unblocked placing stay in the cache
/// anyway, and spreading the entries by block first would only add a pass.
const UNBLOCKED_ROWS: usize = 4 * BLOCK_ROWS;

/// Storage offered for a matrix once its size is known: given the number of offsets (the
/// rows plus one) and of entries before repeats merge, the caller's slices of at least
/// those lengths, or `None` to have the matrix made in memory of its own.
pub type Storage<'s, 'a> = &'s mut dyn FnMut(usize, usize) -> Option<CsrSlices<'a>>;

/// The matrix of `entries`, in the storage `offer` gives when it holds every entry given
/// (repeats included), else in memory of its own. The offsets double as the rows'
/// cursors: when `entries` knows its total, the caller's offsets do, and the matrix in the
/// caller's storage allocates no array as long as a row.
pub(crate) fn assemble<E: Entries + ?Sized>(
    shape: Shape, entries: &E, offer: Storage,
) -> Result<Assembled> {
    let n = shape.n_rows;
    let known = entries.total();
    let mut offsets = Vec::new();
    let total = match known {
        Some(total) => total,
        None => {
            offsets = zeros::<u64>(n + 1, "matrix offsets")?;
            count_rows(&mut offsets, entries)
        }
    };
    let fits =
        |o: &CsrSlices| o.offsets.len() > n && o.columns.len() >= total && o.values.len() >= total;
    if let Some(out) = offer(n + 1, total).filter(fits) {
        let rows = &mut out.offsets[..n + 1];
        match known {
            Some(_) => counted(rows, entries, total)?,
            None => rows.copy_from_slice(&offsets),
        }
        drop(offsets);
        let nnz = fill(shape, entries, out)?;
        return Ok(Assembled::Written {
            n_offsets: n + 1,
            n_entries: nnz,
        });
    }
    if known.is_some() {
        offsets = zeros::<u64>(n + 1, "matrix offsets")?;
        counted(&mut offsets, entries, total)?;
    }
    let mut columns = zeros::<u32>(total, "matrix columns")?;
    let mut values = zeros::<f64>(total, "matrix values")?;
    let out = CsrSlices {
        offsets: &mut offsets,
        columns: &mut columns,
        values: &mut values,
    };
    let nnz = fill(shape, entries, out)?;
    columns.truncate(nnz);
    values.truncate(nnz);
    Ok(Assembled::Owned(SparseMatrix {
        n_rows: n,
        n_cols: shape.n_cols,
        offsets,
        columns,
        values,
    }))
}

/// Counts the rows of `entries` into `rows` (any content: zeroed first), which must come
/// to the `total` the entries gave: else the storage sized by it could be short.
fn counted<E: Entries + ?Sized>(rows: &mut [u64], entries: &E, total: usize) -> Result<()> {
    rows.fill(0);
    let found = count_rows(rows, entries);
    if found != total {
        let message = format!("a matrix expected {total} entries and was given {found}");
        return Err(Error::new(crate::ErrorKind::InvalidInput, message));
    }
    Ok(())
}

/// Fills `out`, which has room for every entry, from the rows' starts in `out.offsets`
/// (as `count_rows` leaves them), which serve as the rows' cursors and then as the kept
/// rows' starts. Summed values, rows given in order and small matrices are placed
/// directly. Otherwise the entries are first spread by block of rows into `out.values` (a
/// row and a column in each value's 8 bytes), then each block is placed and merged on its
/// own, so that the scattered writes stay within one block. Gives the number of entries
/// kept.
fn fill<E: Entries + ?Sized>(shape: Shape, entries: &E, out: CsrSlices) -> Result<usize> {
    let CsrSlices {
        offsets,
        columns,
        values,
    } = out;
    let n = shape.n_rows;
    let cursors = &mut offsets[..n + 1];
    let mut merged = Merged {
        mode: shape.values,
        read: 0,
        written: 0,
    };
    if shape.values == Values::Summed || entries.rows_in_order() || n <= UNBLOCKED_ROWS {
        // Summed values must travel with their entries: placed as a whole, unblocked.
        let summed = shape.values == Values::Summed;
        place(entries, cursors, columns, summed.then_some(&mut *values));
        merged.rows(cursors, 0..n, columns, values)?;
    } else {
        let blocks = (0..n.div_ceil(BLOCK_ROWS)).map(|b| cursors[b * BLOCK_ROWS]);
        let starts = crate::util::alloc::try_collect(blocks, "matrix blocks")?;
        spread(entries, starts, bytemuck::cast_slice_mut(&mut values[..]));
        for first in (0..n).step_by(BLOCK_ROWS) {
            let rows = first..(first + BLOCK_ROWS).min(n);
            // Read before the block is placed and merged, which changes only its own rows.
            let span = cursors[rows.start] as usize..cursors[rows.end] as usize;
            let pairs: &[[u32; 2]] = bytemuck::cast_slice(&values[..]);
            place(&pairs[span], cursors, columns, None);
            merged.rows(cursors, rows, columns, values)?;
        }
    }
    cursors[n] = merged.written as u64;
    Ok(merged.written)
}

/// Writes each entry's row and column into `pairs` at its block's next place, the blocks
/// starting at `starts`.
fn spread<E: Entries + ?Sized>(entries: &E, starts: Vec<u64>, pairs: &mut [[u32; 2]]) {
    struct Spread<'a> {
        cursor: Vec<u64>,
        pairs: &'a mut [[u32; 2]],
    }
    impl Put for Spread<'_> {
        #[inline(always)]
        fn put(&mut self, row: u32, col: u32, _: f64) {
            let slot = &mut self.cursor[row as usize / BLOCK_ROWS];
            self.pairs[*slot as usize] = [row, col];
            *slot += 1;
        }
    }
    entries.each(&mut Spread {
        cursor: starts,
        pairs,
    });
}

impl Entries for [[u32; 2]] {
    fn each<P: Put>(&self, p: &mut P) {
        self.iter().for_each(|&[row, col]| p.put(row, col, 0.0));
    }
}

/// Counts the entries of each row into `cursors` (rows + 1 entries, zero) and turns the
/// counts into the rows' starts; gives the number of entries.
fn count_rows<E: Entries + ?Sized>(cursors: &mut [u64], entries: &E) -> usize {
    struct Count<'a>(&'a mut [u64]);
    impl Put for Count<'_> {
        #[inline(always)]
        fn put(&mut self, row: u32, _: u32, _: f64) {
            self.0[row as usize + 1] += 1;
        }
    }
    entries.each(&mut Count(cursors));
    for r in 1..cursors.len() {
        cursors[r] += cursors[r - 1];
    }
    cursors[cursors.len() - 1] as usize
}

/// Places the entries in their rows, `cursors[r]` walking row r from its start (as
/// `count_rows` leaves them) to its end; with `values`, the values go along.
fn place<E: Entries + ?Sized>(
    entries: &E, cursors: &mut [u64], columns: &mut [u32], values: Option<&mut [f64]>,
) {
    struct Place<'a> {
        cursor: &'a mut [u64],
        columns: &'a mut [u32],
        values: Option<&'a mut [f64]>,
    }
    impl Put for Place<'_> {
        #[inline(always)]
        fn put(&mut self, row: u32, col: u32, value: f64) {
            let slot = &mut self.cursor[row as usize];
            self.columns[*slot as usize] = col;
            if let Some(values) = self.values.as_deref_mut() {
                values[*slot as usize] = value;
            }
            *slot += 1;
        }
    }
    entries.each(&mut Place {
        cursor: cursors,
        columns,
        values,
    });
}

/// The merging of placed rows into the matrix: the rows' entries lie one after the other
/// from `read` on, and what is kept is written from `written` on.
struct Merged {
    mode: Values,
    read: usize,
    written: usize,
}

impl Merged {
    /// Sorts the `rows` of `columns` (with their values when they are summed) and merges
    /// repeated columns, in place. Row r ends where `cursors[r]` says (as the placing
    /// leaves it), which then takes the kept row's start.
    fn rows(
        &mut self, cursors: &mut [u64], rows: Range<usize>, columns: &mut [u32], values: &mut [f64],
    ) -> Result<()> {
        let (mut start, mut w) = (self.read, self.written);
        let (mut scratch, mut long, mut keys) = (Vec::new(), Vec::new(), [0; 8]);
        for r in rows {
            let (end, first) = (cursors[r] as usize, w);
            cursors[r] = w as u64;
            match self.mode {
                Values::Summed => {
                    sort_pairs(
                        &mut columns[start..end],
                        &mut values[start..end],
                        &mut scratch,
                    )?;
                    for i in start..end {
                        if w > first && columns[w - 1] == columns[i] {
                            values[w - 1] += values[i];
                            continue;
                        }
                        (columns[w], values[w]) = (columns[i], values[i]);
                        w += 1;
                    }
                }
                Values::Pattern {
                    off,
                    degree_diagonal,
                } => {
                    let row = sorted_row(&columns[start..end], &mut keys, &mut long)?;
                    let mut diagonal = None;
                    for &c in row {
                        if w > first && columns[w - 1] == c {
                            continue;
                        }
                        if degree_diagonal && c as usize == r {
                            diagonal = Some(w);
                        }
                        (columns[w], values[w]) = (c, off);
                        w += 1;
                    }
                    if let Some(d) = diagonal {
                        values[d] = (w - first - 1) as f64;
                    }
                }
            }
            start = end;
        }
        (self.read, self.written) = (start, w);
        Ok(())
    }
}

/// A row's columns, sorted, in `keys` when at most 8 (most rows of a mesh's matrices) and
/// in `long` otherwise. The short ones go through a sorting network, which has no branch on
/// the keys where an insertion sort mispredicts about once per entry.
fn sorted_row<'k>(
    row: &[u32], keys: &'k mut [u32; 8], long: &'k mut Vec<u32>,
) -> Result<&'k [u32]> {
    let n = row.len();
    if n > 8 {
        long.clear();
        reserve(long, n, "a matrix row")?;
        long.extend_from_slice(row);
        long.sort_unstable();
        return Ok(long);
    }
    let key = |i: usize| if i < n { row[i] } else { u32::MAX };
    let [mut a, mut b, mut c, mut d] = [key(0), key(1), key(2), key(3)];
    let [mut e, mut f, mut g, mut h] = [key(4), key(5), key(6), key(7)];
    macro_rules! exchange {
        ($($x:ident $y:ident),*) => {$(
            let low = $x.min($y);
            $y = $x.max($y);
            $x = low;
        )*};
    }
    // An optimal network for 8 keys (19 exchanges), layer by layer.
    exchange!(a c, b d, e g, f h);
    exchange!(a e, b f, c g, d h);
    exchange!(a b, c d, e f, g h);
    exchange!(c e, d f);
    exchange!(b e, d g);
    exchange!(b c, d e, f g);
    *keys = [a, b, c, d, e, f, g, h];
    Ok(&keys[..n])
}

/// Sorts `columns` and `values` together by column: in place when short, through
/// `scratch` when long.
fn sort_pairs(
    columns: &mut [u32], values: &mut [f64], scratch: &mut Vec<(u32, f64)>,
) -> Result<()> {
    if columns.len() <= 16 {
        for i in 1..columns.len() {
            let mut j = i;
            while j > 0 && columns[j - 1] > columns[j] {
                columns.swap(j - 1, j);
                values.swap(j - 1, j);
                j -= 1;
            }
        }
        return Ok(());
    }
    scratch.clear();
    reserve(scratch, columns.len(), "a matrix row")?;
    scratch.extend(columns.iter().copied().zip(values.iter().copied()));
    scratch.sort_unstable_by_key(|&(c, _)| c);
    for (i, &(c, x)) in scratch.iter().enumerate() {
        (columns[i], values[i]) = (c, x);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    fn e(row: u32, col: u32, value: f64) -> Entry {
        Entry { row, col, value }
    }

    fn owned(shape: Shape, entries: &[Entry]) -> SparseMatrix {
        assemble(shape, entries, &mut |_, _| None)
            .unwrap()
            .owned()
            .unwrap()
    }

    /// The matrix by a map, as `shape.values` says.
    fn brute(shape: Shape, entries: &[Entry]) -> SparseMatrix {
        let mut map = BTreeMap::<(u32, u32), f64>::new();
        for x in entries {
            *map.entry((x.row, x.col)).or_default() += x.value;
        }
        let mut m = SparseMatrix {
            n_rows: shape.n_rows,
            n_cols: shape.n_cols,
            offsets: vec![0; shape.n_rows + 1],
            ..Default::default()
        };
        for (&(r, c), &x) in &map {
            m.offsets[r as usize + 1] += 1;
            m.columns.push(c);
            m.values.push(match shape.values {
                Values::Summed => x,
                Values::Pattern {
                    degree_diagonal, ..
                } if degree_diagonal && r == c => {
                    map.range((r, 0)..(r + 1, 0)).count() as f64 - 1.0
                }
                Values::Pattern { off, .. } => off,
            });
        }
        for r in 0..shape.n_rows {
            m.offsets[r + 1] += m.offsets[r];
        }
        m
    }

    /// Entries in rows across several blocks, with repeats and some in order.
    fn random_entries(n_rows: usize, n: usize, seed: u64) -> Vec<Entry> {
        let mut x = seed;
        let mut next = move || {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (x >> 33) as u32
        };
        let mut out: Vec<Entry> = (0..n)
            .map(|_| {
                let r = next() % n_rows as u32;
                e(
                    r,
                    next() % 40 + r / 2,
                    [1.0, -1.0, 2.5][next() as usize % 3],
                )
            })
            .collect();
        let repeats: Vec<Entry> = out.iter().step_by(7).copied().collect();
        out.extend(repeats);
        out
    }

    #[test]
    fn rows_of_every_length_are_sorted() {
        let (mut keys, mut long) = ([0; 8], Vec::new());
        // Every row of 0s and 1s up to 8 long (a network sorting those sorts everything).
        for n in 0..=8 {
            for bits in 0..1u32 << n {
                let row: Vec<u32> = (0..n).map(|i| bits >> i & 1).collect();
                let mut want = row.clone();
                want.sort_unstable();
                assert_eq!(sorted_row(&row, &mut keys, &mut long).unwrap(), want);
            }
        }
        for n in 0..20 {
            let row: Vec<u32> = random_entries(50, n, n as u64)
                .iter()
                .map(|x| x.col)
                .collect();
            let mut want = row.clone();
            want.sort_unstable();
            assert_eq!(
                sorted_row(&row, &mut keys, &mut long).unwrap(),
                want,
                "{row:?}"
            );
        }
    }

    #[test]
    fn entries_are_sorted_and_summed() {
        let shape = Shape {
            n_rows: 3,
            n_cols: 4,
            values: Values::Summed,
        };
        let entries = [
            e(2, 1, 1.0),
            e(0, 3, 2.0),
            e(0, 0, -1.0),
            e(2, 1, 4.0),
            e(0, 3, -2.0),
        ];
        let m = owned(shape, &entries);
        assert_eq!(m.offsets, [0, 2, 2, 3]);
        assert_eq!(m.columns, [0, 3, 1]);
        assert_eq!(m.values, [-1.0, 0.0, 5.0]);
    }

    /// Entries that tell their total, right or wrong.
    struct Known<'a>(&'a [Entry], Option<usize>);

    impl Entries for Known<'_> {
        fn each<P: Put>(&self, p: &mut P) {
            self.0.each(p);
        }
        fn total(&self) -> Option<usize> {
            self.1
        }
    }

    #[test]
    fn a_wrong_total_is_an_error_in_memory_and_in_the_callers_storage() {
        let entries = random_entries(100, 500, 5);
        let shape = Shape {
            n_rows: 100,
            n_cols: 100,
            values: Values::Summed,
        };
        for total in [499, 501] {
            let given = Known(&entries, Some(total));
            let e = assemble(shape, &given, &mut |_, _| None).unwrap_err();
            assert!(e.message.contains("expected"), "{e}");
            let (mut o, mut c, mut v) = (vec![0; 101], vec![0; 600], vec![0.0; 600]);
            let mut slices = Some(CsrSlices {
                offsets: &mut o,
                columns: &mut c,
                values: &mut v,
            });
            let e = assemble(shape, &given, &mut |_, _| slices.take()).unwrap_err();
            assert!(e.message.contains("expected"), "{e}");
        }
    }

    #[test]
    fn every_mode_matches_a_map_in_memory_and_in_the_callers_storage() {
        let n_rows = UNBLOCKED_ROWS + 2 * BLOCK_ROWS + 17;
        let entries = random_entries(n_rows, 200_000, 7);
        let modes = [
            Values::Summed,
            Values::Pattern {
                off: 1.0,
                degree_diagonal: false,
            },
            Values::Pattern {
                off: -1.0,
                degree_diagonal: true,
            },
        ];
        let known_entries = Known(&entries, Some(entries.len()));
        for (values, known) in modes.into_iter().flat_map(|m| [(m, false), (m, true)]) {
            let shape = Shape {
                n_rows,
                n_cols: n_rows + 40,
                values,
            };
            let given: &dyn Fn(Storage) -> Result<Assembled> = match known {
                true => &|offer| assemble(shape, &known_entries, offer),
                false => &|offer| assemble(shape, &entries[..], offer),
            };
            let want = brute(shape, &entries);
            let mine = given(&mut |_, _| None).unwrap().owned().unwrap();
            assert_eq!(mine, want, "{values:?} in memory, total known: {known}");
            let total = entries.len();
            let (mut o, mut c, mut v) = (vec![9; n_rows + 1], vec![9; total], vec![9.0; total]);
            let mut slices = Some(CsrSlices {
                offsets: &mut o,
                columns: &mut c,
                values: &mut v,
            });
            let mut offer = |rows, n| {
                assert_eq!((rows, n), (n_rows + 1, total));
                slices.take()
            };
            let got = given(&mut offer).unwrap();
            let Assembled::Written {
                n_offsets,
                n_entries,
            } = got
            else {
                panic!("{values:?}: not written in the storage offered");
            };
            assert_eq!((n_offsets, n_entries), (n_rows + 1, want.nnz()));
            assert_eq!(o, want.offsets);
            assert_eq!(
                (&c[..n_entries], &v[..n_entries]),
                (&want.columns[..], &want.values[..])
            );
        }
    }

    #[test]
    fn rows_in_order_are_placed_alike() {
        struct Sorted(Vec<Entry>);
        impl Entries for Sorted {
            fn each<P: Put>(&self, p: &mut P) {
                self.0.each(p);
            }
            fn rows_in_order(&self) -> bool {
                true
            }
        }
        let mut entries = random_entries(2 * BLOCK_ROWS, 50_000, 3);
        entries.sort_by_key(|x| x.row);
        let shape = Shape {
            n_rows: 2 * BLOCK_ROWS,
            n_cols: 3 * BLOCK_ROWS,
            values: Values::Pattern {
                off: 1.0,
                degree_diagonal: false,
            },
        };
        let got = assemble(shape, &Sorted(entries.clone()), &mut |_, _| None).unwrap();
        assert_eq!(got.owned().unwrap(), brute(shape, &entries));
    }

    #[test]
    fn short_storage_gives_a_matrix_of_its_own() {
        let entries = [e(0, 1, 1.0), e(0, 1, 1.0), e(1, 0, 1.0)];
        let shape = Shape {
            n_rows: 2,
            n_cols: 2,
            values: Values::Summed,
        };
        // Room for the merged entries (2), not for every entry given (3).
        let (mut o, mut c, mut v) = ([0; 3], [0; 2], [0.0; 2]);
        let mut slices = Some(CsrSlices {
            offsets: &mut o,
            columns: &mut c,
            values: &mut v,
        });
        let mut offer = |_, _| slices.take();
        let m = assemble(shape, &entries[..], &mut offer)
            .unwrap()
            .owned()
            .unwrap();
        assert_eq!(
            (m.offsets, m.columns, m.values),
            (vec![0, 1, 2], vec![1, 0], vec![2.0, 1.0])
        );
    }
}
