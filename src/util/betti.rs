//! Ranks over Z/2 for Betti numbers, near-linear where the matrix allows it.
//!
//! The boundary matrices of a built structure have at most two entries per column (CHE's
//! `d1`: an edge has two ends) or per row (CHE's `d2`, CHF's `d3`: a structure edge or face
//! has one or two cofaces, since the builds split what has more). Such a matrix over Z/2 is
//! the incidence matrix of a graph, with a one-entry line joined to a "ground" node: its
//! rank is the number of nodes minus the number of components that reach no ground
//! ([`Grounded`], a union-find). The other matrices (CHF's `d2`) first lose what a
//! spanning forest of their neighbours proves redundant ([`forest_lines`]), then the lines
//! with one entry ([`peeled_rank`]), and only the core left takes the column reduction of
//! persistent homology ([`column_rank`]).

use crate::NONE;
use crate::error::Result;
use crate::util::alloc::{try_collect, try_push, try_to_vec, try_vec, try_with_capacity};
use crate::util::dsu::Dsu;

/// The components of a graph whose lines join two of `n_nodes` nodes, or one node and the
/// ground (`(a, NONE)`), with the components that reach the ground marked.
pub(crate) struct Grounded {
    dsu: Dsu,
    grounded: Vec<bool>,
}

impl Grounded {
    pub(crate) fn new(n_nodes: usize, lines: impl Iterator<Item = (u32, u32)>) -> Result<Self> {
        let mut dsu = Dsu::new(n_nodes)?;
        let mut grounded = try_vec(n_nodes, false, "the grounded components")?;
        for (a, b) in lines {
            if b == NONE {
                grounded[a as usize] = true;
            } else {
                dsu.union(a, b);
            }
        }
        for x in 0..n_nodes as u32 {
            if grounded[x as usize] {
                let r = dsu.find(x);
                grounded[r as usize] = true;
            }
        }
        Ok(Grounded { dsu, grounded })
    }

    /// The root of `x`'s component when it reaches no ground.
    pub(crate) fn free_root(&mut self, x: u32) -> Option<u32> {
        let r = self.dsu.find(x);
        (!self.grounded[r as usize]).then_some(r)
    }

    /// The rank over Z/2 of the lines as columns: the nodes minus the free components.
    pub(crate) fn rank(&mut self) -> usize {
        let n = self.grounded.len();
        let free = (0..n as u32)
            .filter(|&x| self.free_root(x) == Some(x))
            .count();
        n - free
    }
}

/// Which of the lines of a graph (as in [`Grounded`]) a spanning forest takes, the ground
/// one more node: as many as the rank of the lines, and the other lines are sums of these.
///
/// For boundary matrices this says which lines a rank can skip. Where `d_k` is such a
/// graph over the columns of `d_{k+1}` (CHF's `d3`: faces joining tetrahedra), each forest
/// line `f` closes a subtree whose boundary is `f` plus lines outside the forest, so the
/// column `f` of `d_k` is a sum of non-forest columns (as `d_k d_{k+1} = 0`): the clearing
/// of persistent homology, without a reduction. Where `d_{k-1}` is such a graph over the
/// rows of `d_k` (CHF's `d1`: edges joining vertices), no boundary lies on a forest, so the
/// forest rows of `d_k` add nothing to its rank.
pub(crate) fn forest_lines(
    n_nodes: usize, lines: impl Iterator<Item = (u32, u32)>,
) -> Result<Vec<bool>> {
    let mut dsu = Dsu::new(n_nodes + 1)?;
    let ground = n_nodes as u32;
    try_collect(
        lines.map(|(a, b)| {
            let (ra, rb) = (dsu.find(a), dsu.find(if b == NONE { ground } else { b }));
            if ra != rb {
                dsu.union(ra, rb);
            }
            ra != rb
        }),
        "the spanning forest",
    )
}

/// The rank over Z/2 of the matrix whose column `c` holds the rows `columns[c]` that are
/// not NONE (no row twice). A row or column with one entry is a pivot that nothing else
/// needs: it leaves with its row and column and the rank grows by one; an empty one leaves
/// alone. What this peeling leaves takes [`column_rank`].
pub(crate) fn peeled_rank<const K: usize>(n_rows: usize, columns: &[[u32; K]]) -> Result<usize> {
    let mut p = Peel::new(n_rows, columns)?;
    let peeled = p.run()?;
    let core = p.core()?;
    Ok(peeled + column_rank(n_rows, core.into_iter())?)
}

/// The state of [`peeled_rank`]: live entries per row and column (`DEAD` once gone), the
/// columns of each row, and the lines whose count fell to one or none.
struct Peel<'a, const K: usize> {
    columns: &'a [[u32; K]],
    col_live: Vec<u32>,
    row_live: Vec<u32>,
    row_start: Vec<usize>,
    row_cols: Vec<u32>,
    col_stack: Vec<u32>,
    row_stack: Vec<u32>,
}

const DEAD: u32 = u32::MAX;

impl<'a, const K: usize> Peel<'a, K> {
    fn new(n_rows: usize, columns: &'a [[u32; K]]) -> Result<Self> {
        let mut row_live = try_vec(n_rows, 0u32, "the row counts")?;
        for &r in columns.iter().flatten().filter(|&&r| r != NONE) {
            row_live[r as usize] += 1;
        }
        let mut row_start = try_vec(n_rows + 1, 0usize, "the row offsets")?;
        for r in 0..n_rows {
            row_start[r + 1] = row_start[r] + row_live[r] as usize;
        }
        let mut row_cols = try_vec(row_start[n_rows], 0u32, "the row entries")?;
        let mut fill = try_to_vec(&row_start[..n_rows], "the row cursors")?;
        let mut col_live = try_vec(columns.len(), 0u32, "the column counts")?;
        for (c, col) in columns.iter().enumerate() {
            for &r in col.iter().filter(|&&r| r != NONE) {
                row_cols[fill[r as usize]] = c as u32;
                fill[r as usize] += 1;
                col_live[c] += 1;
            }
        }
        let col_stack = try_collect(
            (0..columns.len() as u32).filter(|&c| col_live[c as usize] <= 1),
            "the peeling",
        )?;
        let row_stack = try_collect(
            (0..n_rows as u32).filter(|&r| row_live[r as usize] <= 1),
            "the peeling",
        )?;
        Ok(Peel {
            columns,
            col_live,
            row_live,
            row_start,
            row_cols,
            col_stack,
            row_stack,
        })
    }

    /// Peels until no live line has fewer than two entries; the pivots it took.
    fn run(&mut self) -> Result<usize> {
        let mut rank = 0;
        loop {
            if let Some(c) = self.col_stack.pop() {
                if self.col_live[c as usize] == 1 {
                    let r = self.live_row(c);
                    self.kill_col(c)?;
                    self.kill_row(r)?;
                    rank += 1;
                } else if self.col_live[c as usize] == 0 {
                    self.kill_col(c)?;
                }
            } else if let Some(r) = self.row_stack.pop() {
                if self.row_live[r as usize] == 1 {
                    let c = self.live_col(r);
                    self.kill_row(r)?;
                    self.kill_col(c)?;
                    rank += 1;
                } else if self.row_live[r as usize] == 0 {
                    self.kill_row(r)?;
                }
            } else {
                return Ok(rank);
            }
        }
    }

    fn live_row(&self, c: u32) -> u32 {
        let col = &self.columns[c as usize];
        *col.iter()
            .find(|&&r| r != NONE && self.row_live[r as usize] != DEAD)
            .expect("a column with a live entry")
    }

    fn live_col(&self, r: u32) -> u32 {
        let cols = &self.row_cols[self.row_start[r as usize]..self.row_start[r as usize + 1]];
        *cols
            .iter()
            .find(|&&c| self.col_live[c as usize] != DEAD)
            .expect("a row with a live entry")
    }

    fn kill_col(&mut self, c: u32) -> Result<()> {
        self.col_live[c as usize] = DEAD;
        for &r in self.columns[c as usize].iter().filter(|&&r| r != NONE) {
            let n = &mut self.row_live[r as usize];
            if *n != DEAD {
                *n -= 1;
                if *n <= 1 {
                    try_push(&mut self.row_stack, r, "the peeling")?;
                }
            }
        }
        Ok(())
    }

    fn kill_row(&mut self, r: u32) -> Result<()> {
        self.row_live[r as usize] = DEAD;
        for &c in &self.row_cols[self.row_start[r as usize]..self.row_start[r as usize + 1]] {
            let n = &mut self.col_live[c as usize];
            if *n != DEAD {
                *n -= 1;
                if *n <= 1 {
                    try_push(&mut self.col_stack, c, "the peeling")?;
                }
            }
        }
        Ok(())
    }

    /// The live columns with their live rows, sorted.
    fn core(&self) -> Result<Vec<Vec<u32>>> {
        try_collect(
            (0..self.columns.len())
                .filter(|&c| self.col_live[c] != DEAD)
                .map(|c| {
                    let mut col: Vec<u32> = self.columns[c]
                        .iter()
                        .copied()
                        .filter(|&r| r != NONE && self.row_live[r as usize] != DEAD)
                        .collect();
                    col.sort_unstable();
                    col
                }),
            "the core columns",
        )
    }
}

/// The rank over Z/2 of the matrix with the given columns (each a sorted list of row
/// indices): each column is reduced by the earlier column owning its largest row (the
/// pivot), XOR-merging the sorted lists, until it is empty or owns a new pivot.
pub(crate) fn column_rank(n_rows: usize, columns: impl Iterator<Item = Vec<u32>>) -> Result<usize> {
    let mut owner = try_vec(n_rows, NONE, "the pivots")?;
    let mut reduced: Vec<Vec<u32>> = Vec::new();
    for mut col in columns {
        while let Some(&low) = col.last() {
            let o = owner[low as usize];
            if o == NONE {
                owner[low as usize] = reduced.len() as u32;
                try_push(&mut reduced, col, "the reduced columns")?;
                break;
            }
            col = xor_sorted(&col, &reduced[o as usize])?;
        }
    }
    Ok(reduced.len())
}

/// The symmetric difference of two sorted lists.
fn xor_sorted(a: &[u32], b: &[u32]) -> Result<Vec<u32>> {
    let mut out = try_with_capacity(a.len() + b.len(), "a reduced column")?;
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        match a[i].cmp(&b[j]) {
            std::cmp::Ordering::Less => (out.push(a[i]), i += 1).1,
            std::cmp::Ordering::Greater => (out.push(b[j]), j += 1).1,
            std::cmp::Ordering::Equal => (i += 1, j += 1).1,
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn peeled_rank_agrees_with_the_column_reduction() {
        let mut rnd = crate::util::test_rng(11);
        for round in 0..400 {
            let n_rows = 1 + round % 13;
            let columns: Vec<[u32; 3]> = (0..rnd(20))
                .map(|_| {
                    let mut c = [NONE; 3];
                    for slot in c.iter_mut().take(rnd(4) as usize) {
                        *slot = rnd(n_rows);
                    }
                    // Distinct rows: a repeat becomes NONE.
                    let mut seen = Vec::new();
                    c.map(|r| {
                        if r == NONE || seen.contains(&r) {
                            NONE
                        } else {
                            seen.push(r);
                            r
                        }
                    })
                })
                .collect();
            let sorted = columns.iter().map(|c| {
                let mut v: Vec<u32> = c.iter().copied().filter(|&r| r != NONE).collect();
                v.sort_unstable();
                v
            });
            assert_eq!(
                peeled_rank(n_rows, &columns).unwrap(),
                column_rank(n_rows, sorted).unwrap(),
                "round {round}: {columns:?}"
            );
        }
    }

    #[test]
    fn forest_lines_count_the_rank() {
        let mut rnd = crate::util::test_rng(5);
        for round in 0..200 {
            let n = 1 + round % 9;
            let lines: Vec<(u32, u32)> = (0..rnd(12))
                .map(|_| {
                    let (a, b) = (rnd(n), rnd(n + 1));
                    if b as usize == n || b == a {
                        (a, NONE)
                    } else {
                        (a, b)
                    }
                })
                .collect();
            let tree = forest_lines(n, lines.iter().copied()).unwrap();
            let rank = Grounded::new(n, lines.iter().copied()).unwrap().rank();
            assert_eq!(tree.iter().filter(|&&t| t).count(), rank, "{lines:?}");
        }
    }

    #[test]
    fn graph_and_column_ranks_agree() {
        let mut rnd = crate::util::test_rng(7);
        for round in 0..200 {
            let n = 1 + round % 9;
            let lines: Vec<(u32, u32)> = (0..rnd(12))
                .map(|_| {
                    let a = rnd(n);
                    let b = rnd(n + 1);
                    if b as usize == n || b == a {
                        (a, NONE)
                    } else {
                        (a, b)
                    }
                })
                .collect();
            let cols = lines.iter().map(|&(a, b)| {
                let mut c = vec![a];
                if b != NONE {
                    c.push(b);
                }
                c.sort_unstable();
                c
            });
            assert_eq!(
                Grounded::new(n, lines.iter().copied()).unwrap().rank(),
                column_rank(n, cols).unwrap()
            );
        }
    }
}
