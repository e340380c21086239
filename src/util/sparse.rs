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

/// Storage offered for a matrix once its size is known: given the number of offsets (the
/// rows plus one) and of entries before repeats merge, the caller's slices of at least
/// those lengths, or `None` to have the matrix made in memory of its own.
pub type Storage<'s, 'a> = &'s mut dyn FnMut(usize, usize) -> Option<CsrSlices<'a>>;

/// The matrix of `entries`, in the storage `offer` gives when it holds every entry given
/// (repeats included), else in memory of its own.
pub(crate) fn assemble<E: Entries + ?Sized>(
    shape: Shape, entries: &E, offer: Storage,
) -> Result<Assembled> {
    let n = shape.n_rows;
    let blocks = block_starts(n, entries)?;
    let total = blocks[blocks.len() - 1] as usize;
    let fits =
        |o: &CsrSlices| o.offsets.len() > n && o.columns.len() >= total && o.values.len() >= total;
    if let Some(out) = offer(n + 1, total).filter(fits) {
        let nnz = fill(shape, entries, &blocks, out)?;
        return Ok(Assembled::Written {
            n_offsets: n + 1,
            n_entries: nnz,
        });
    }
    let mut offsets = zeros::<u64>(n + 1, "matrix offsets")?;
    let mut columns = zeros::<u32>(total, "matrix columns")?;
    let mut values = zeros::<f64>(total, "matrix values")?;
    let out = CsrSlices {
        offsets: &mut offsets,
        columns: &mut columns,
        values: &mut values,
    };
    let nnz = fill(shape, entries, &blocks, out)?;
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

/// Where each block of `BLOCK_ROWS` rows starts among the entries, in entry order by
/// block, with the number of entries last.
fn block_starts<E: Entries + ?Sized>(n_rows: usize, entries: &E) -> Result<Vec<u64>> {
    struct Count<'a>(&'a mut [u64]);
    impl Put for Count<'_> {
        #[inline(always)]
        fn put(&mut self, row: u32, _: u32, _: f64) {
            self.0[row as usize / BLOCK_ROWS + 1] += 1;
        }
    }
    let mut starts = zeros::<u64>(n_rows.div_ceil(BLOCK_ROWS) + 1, "matrix blocks")?;
    entries.each(&mut Count(&mut starts));
    for b in 1..starts.len() {
        starts[b] += starts[b - 1];
    }
    Ok(starts)
}

/// Fills `out`, which has room for every entry: the entries are first spread by block of
/// rows into `out.values` (a row and a column in each value's 8 bytes; summed values go
/// to their place directly), then each block is counted, placed and merged on its own, so
/// that the scattered writes stay within one block. Gives the number of entries kept.
fn fill<E: Entries + ?Sized>(
    shape: Shape, entries: &E, blocks: &[u64], out: CsrSlices,
) -> Result<usize> {
    let CsrSlices {
        offsets,
        columns,
        values,
    } = out;
    let offsets = &mut offsets[..shape.n_rows + 1];
    if shape.values == Values::Summed || entries.rows_in_order() {
        // Summed values must travel with their entries: placed as a whole, unblocked.
        count_rows(offsets, entries);
        let summed = shape.values == Values::Summed;
        place(entries, offsets, columns, summed.then_some(&mut *values));
        let w = merge_rows(
            shape.values,
            offsets,
            0..shape.n_rows,
            0,
            0,
            columns,
            values,
        )?;
        offsets[shape.n_rows] = w as u64;
        return Ok(w);
    }
    spread(entries, blocks, bytemuck::cast_slice_mut(&mut values[..]));
    let mut w = 0;
    for (b, span) in blocks.windows(2).enumerate() {
        let rows = b * BLOCK_ROWS..((b + 1) * BLOCK_ROWS).min(shape.n_rows);
        let pairs: &[[u32; 2]] = bytemuck::cast_slice(&values[..]);
        let pairs = &pairs[span[0] as usize..span[1] as usize];
        place_block(
            pairs,
            &mut offsets[rows.start..=rows.end],
            rows.start,
            w,
            columns,
        );
        w = merge_rows(shape.values, offsets, rows, w, w, columns, values)?;
    }
    offsets[shape.n_rows] = w as u64;
    Ok(w)
}

/// Writes each entry's row and column into `pairs` at its block's next place (`blocks`
/// as `block_starts` gives them).
fn spread<E: Entries + ?Sized>(entries: &E, blocks: &[u64], pairs: &mut [[u32; 2]]) {
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
    let cursor = blocks[..blocks.len() - 1].to_vec();
    entries.each(&mut Spread { cursor, pairs });
}

/// Places one block's `pairs` (rows from `base` on) in `columns` from `at` on, row after
/// row; `offsets` are the block's rows plus one, and each ends as its row's end.
fn place_block(
    pairs: &[[u32; 2]], offsets: &mut [u64], base: usize, at: usize, columns: &mut [u32],
) {
    offsets.fill(0);
    for &[row, _] in pairs {
        offsets[row as usize - base + 1] += 1;
    }
    offsets[0] = at as u64;
    for r in 1..offsets.len() {
        offsets[r] += offsets[r - 1];
    }
    for &[row, col] in pairs {
        let slot = &mut offsets[row as usize - base];
        columns[*slot as usize] = col;
        *slot += 1;
    }
}

/// Counts the entries of each row into `offsets` (rows + 1 entries, set to zero here) and
/// turns the counts into the rows' starts; gives the number of entries.
fn count_rows<E: Entries + ?Sized>(offsets: &mut [u64], entries: &E) -> usize {
    struct Count<'a>(&'a mut [u64]);
    impl Put for Count<'_> {
        #[inline(always)]
        fn put(&mut self, row: u32, _: u32, _: f64) {
            self.0[row as usize + 1] += 1;
        }
    }
    offsets.fill(0);
    entries.each(&mut Count(offsets));
    for r in 1..offsets.len() {
        offsets[r] += offsets[r - 1];
    }
    offsets[offsets.len() - 1] as usize
}

/// Places the entries in their rows, `offsets[r]` walking row r from its start (as
/// `count_rows` leaves them) to its end; with `values`, the values go along.
fn place<E: Entries + ?Sized>(
    entries: &E, offsets: &mut [u64], columns: &mut [u32], values: Option<&mut [f64]>,
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
        cursor: offsets,
        columns,
        values,
    });
}

/// Sorts the `rows` of `columns` (with their values when they are summed) and merges
/// repeated columns, in place: the rows' entries lie one after the other from `start`,
/// each row ending where `offsets[r]` says (as the placing cursors leave them), and what
/// is kept is written from `w` on, `offsets[r]` becoming its row's start. Gives where the
/// writing ended.
fn merge_rows(
    mode: Values, offsets: &mut [u64], rows: Range<usize>, mut start: usize, mut w: usize,
    columns: &mut [u32], values: &mut [f64],
) -> Result<usize> {
    let mut scratch = Vec::new();
    for r in rows {
        let (end, first) = (offsets[r] as usize, w);
        offsets[r] = w as u64;
        match mode {
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
                columns[start..end].sort_unstable();
                let mut diagonal = None;
                for i in start..end {
                    let c = columns[i];
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
    Ok(w)
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

    #[test]
    fn every_mode_matches_a_map_in_memory_and_in_the_callers_storage() {
        let n_rows = 3 * BLOCK_ROWS + 17;
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
        for values in modes {
            let shape = Shape {
                n_rows,
                n_cols: n_rows + 40,
                values,
            };
            let want = brute(shape, &entries);
            assert_eq!(owned(shape, &entries), want, "{values:?} in memory");
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
            let got = assemble(shape, &entries[..], &mut offer).unwrap();
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
