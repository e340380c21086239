//! Ranks over Z/2 for Betti numbers, near-linear where the matrix allows it.
//!
//! The boundary matrices of a built structure have at most two entries per column (CHE's
//! `d1`: an edge has two ends) or per row (CHE's `d2`, CHF's `d3`: a structure edge or face
//! has one or two cofaces, since the builds split what has more). Such a matrix over Z/2 is
//! the incidence matrix of a graph, with a one-entry line joined to a "ground" node: its
//! rank is the number of nodes minus the number of components that reach no ground
//! ([`Grounded`], a union-find). The other matrices (CHF's `d2`) take the column
//! reduction of persistent homology ([`column_rank`]).

use crate::NONE;
use crate::error::Result;
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
        let mut grounded = vec![false; n_nodes];
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

/// The rank over Z/2 of the matrix with the given columns (each a sorted list of row
/// indices): each column is reduced by the earlier column owning its largest row (the
/// pivot), XOR-merging the sorted lists, until it is empty or owns a new pivot.
pub(crate) fn column_rank(n_rows: usize, columns: impl Iterator<Item = Vec<u32>>) -> usize {
    let mut owner = vec![NONE; n_rows];
    let mut reduced: Vec<Vec<u32>> = Vec::new();
    for mut col in columns {
        while let Some(&low) = col.last() {
            let o = owner[low as usize];
            if o == NONE {
                owner[low as usize] = reduced.len() as u32;
                reduced.push(col);
                break;
            }
            col = xor_sorted(&col, &reduced[o as usize]);
        }
    }
    reduced.len()
}

/// The symmetric difference of two sorted lists.
fn xor_sorted(a: &[u32], b: &[u32]) -> Vec<u32> {
    let (mut i, mut j, mut out) = (0, 0, Vec::with_capacity(a.len() + b.len()));
    while i < a.len() && j < b.len() {
        match a[i].cmp(&b[j]) {
            std::cmp::Ordering::Less => (out.push(a[i]), i += 1).1,
            std::cmp::Ordering::Greater => (out.push(b[j]), j += 1).1,
            std::cmp::Ordering::Equal => (i += 1, j += 1).1,
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

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
                column_rank(n, cols)
            );
        }
    }
}
