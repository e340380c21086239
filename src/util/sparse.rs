//! Sparse matrices in compressed sparse rows, the layout Eigen (`Map<SparseMatrix<double,
//! RowMajor, int64_t>>`) and SciPy (`csr_matrix((values, columns, offsets))`) take as is:
//! built from (row, column, value) entries by two counting passes, so that the columns of
//! every row come out sorted without a comparison sort.

use crate::error::{Error, Result};

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
    /// The matrix of `entries`; entries at the same place are summed (a sum of 0 stays as
    /// an explicit entry, so that the pattern does not depend on cancellation).
    pub(crate) fn from_entries(n_rows: usize, n_cols: usize, entries: &[Entry]) -> Result<Self> {
        // Counting sort by column, then a stable one by row: rows with sorted columns.
        let by_col = counting_sort(entries, n_cols, |e| e.col)?;
        let sorted = counting_sort(&by_col, n_rows, |e| e.row)?;
        let mut offsets = zeros::<u64>(n_rows + 1, "matrix offsets")?;
        let mut columns = zeros::<u32>(0, "matrix columns")?;
        let mut values = zeros::<f64>(0, "matrix values")?;
        columns
            .try_reserve_exact(sorted.len())
            .and_then(|_| values.try_reserve_exact(sorted.len()))
            .map_err(|_| Error::too_large(format!("{} matrix entries", sorted.len())))?;
        let mut last: Option<(u32, u32)> = None;
        for e in &sorted {
            if last == Some((e.row, e.col)) {
                *values.last_mut().expect("an entry before") += e.value;
                continue;
            }
            last = Some((e.row, e.col));
            columns.push(e.col);
            values.push(e.value);
            offsets[e.row as usize + 1] += 1;
        }
        for r in 0..n_rows {
            offsets[r + 1] += offsets[r];
        }
        Ok(SparseMatrix {
            n_rows,
            n_cols,
            offsets,
            columns,
            values,
        })
    }

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

/// A stable counting sort of `xs` by `key`, whose values are below `n`.
fn counting_sort<T: Copy>(xs: &[T], n: usize, key: impl Fn(&T) -> u32) -> Result<Vec<T>> {
    let mut start = zeros::<usize>(n + 1, "counting sort buckets")?;
    for x in xs {
        start[key(x) as usize + 1] += 1;
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut out = Vec::new();
    out.try_reserve_exact(xs.len())
        .map_err(|_| Error::too_large(format!("{} entries to sort", xs.len())))?;
    // Every slot is written once below: fill with the first element as a placeholder.
    if let Some(&first) = xs.first() {
        out.resize(xs.len(), first);
    }
    for x in xs {
        let slot = &mut start[key(x) as usize];
        out[*slot] = *x;
        *slot += 1;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn entries_are_sorted_and_summed() {
        let e = |row, col, value| Entry { row, col, value };
        let m = SparseMatrix::from_entries(
            3,
            4,
            &[
                e(2, 1, 1.0),
                e(0, 3, 2.0),
                e(0, 0, -1.0),
                e(2, 1, 4.0),
                e(0, 3, -2.0),
            ],
        )
        .unwrap();
        assert_eq!(m.offsets, [0, 2, 2, 3]);
        assert_eq!(m.columns, [0, 3, 1]);
        assert_eq!(m.values, [-1.0, 0.0, 5.0]);
    }
}
