//! The tables a query reads, borrowed from the structure at the level that stores them and
//! computed for the one query below it: `O` at level 0 (O(T) time and memory, the same rule
//! level 1 stores), face and edge ranks at levels 0 and 1 (O(T)). Every query runs one code
//! path on a view, so the answers are identical, in the same order, at every level.

use crate::NONE;
use crate::chf::Chf;
use crate::chf::edges::{self, MultiFan};
use crate::chf::ids::{HalfEdge, first, he_face, local, sorted_triple, tet};
use crate::chf::star_pass as stars;
use crate::error::Result;
use crate::util::alloc::{or_panic, try_collect};
use crate::util::rank::RankBits;
use std::borrow::Cow;

/// Which ranks a query needs besides `V` and `O`.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Need {
    pub faces: bool,
    pub edges: bool,
}

impl Need {
    pub const NOTHING: Need = Need {
        faces: false,
        edges: false,
    };
    pub const FACES: Need = Need {
        faces: true,
        edges: false,
    };
    pub const EDGES: Need = Need {
        faces: false,
        edges: true,
    };
}

#[derive(Clone, Debug)]
pub(crate) struct View<'a> {
    pub v: &'a [u32],
    pub o: Cow<'a, [u32]>,
    /// Canonical half-faces; empty unless asked for.
    pub faces: Cow<'a, RankBits>,
    /// Canonical edge slots; empty unless asked for.
    pub edges: Cow<'a, RankBits>,
    /// Level-2 tables, when stored.
    vh: Option<&'a [u32]>,
    fh: Option<&'a [u32]>,
    eh: Option<&'a [u32]>,
    pub multi_fan: &'a [MultiFan],
    /// The explicit ids of an edited CHF, which replace the ranks.
    pub edit: Option<&'a crate::chf::edit::EditState>,
}

impl Chf {
    /// [`Chf::try_view`] for the one-element queries, which have no error to return.
    pub(crate) fn view(&self, need: Need) -> View<'_> {
        or_panic(self.try_view(need))
    }

    /// The tables `need` asks for, borrowed or computed; an error when memory runs out.
    pub(crate) fn try_view(&self, need: Need) -> Result<View<'_>> {
        if let Some(edit) = &self.edit {
            return Ok(View {
                v: &self.v,
                o: Cow::Borrowed(&self.o),
                faces: Cow::Owned(RankBits::default()),
                edges: Cow::Owned(RankBits::default()),
                vh: Some(&self.vh),
                fh: None,
                eh: None,
                multi_fan: &self.multi_fan,
                edit: Some(edit),
            });
        }
        let o: Cow<'_, [u32]> = if self.level >= 1 {
            Cow::Borrowed(&self.o)
        } else {
            Cow::Owned(self.try_opposites_by_rule()?)
        };
        let stored = self.level >= 2;
        let faces = match (stored, need.faces) {
            (true, _) => Cow::Borrowed(&self.face_bits),
            (false, true) => Cow::Owned(face_bits(&o)?),
            (false, false) => Cow::Owned(RankBits::default()),
        };
        let edges = match (stored, need.edges) {
            (true, _) => Cow::Borrowed(&self.edge_bits),
            (false, true) => {
                let flagged = stars::merged(&self.non_manifold, &self.seams)?;
                Cow::Owned(
                    stars::stars(
                        &self.v,
                        self.n_vertices,
                        &flagged,
                        stars::StarPass {
                            pairs: stars::Pairs::No,
                            tables: true,
                            threads: 1,
                        },
                    )?
                    .edge_bits,
                )
            }
            (false, false) => Cow::Owned(RankBits::default()),
        };
        Ok(View {
            v: &self.v,
            o,
            faces,
            edges,
            vh: stored.then_some(&self.vh[..]),
            fh: stored.then_some(&self.fh[..]),
            eh: stored.then_some(&self.eh[..]),
            multi_fan: &self.multi_fan,
            edit: None,
        })
    }

    /// `O` of a canonical `V` (oriented, split): two half-faces are twins when they are the
    /// only two on their vertex triple, run opposite ways, and are flagged neither
    /// non-manifold nor seam. Level 1 stores it; level 0 queries compute it.
    pub(crate) fn try_opposites_by_rule(&self) -> Result<Vec<u32>> {
        let flagged = stars::merged(&self.non_manifold, &self.seams)?;
        let pass = stars::StarPass {
            pairs: stars::Pairs::Opposites,
            tables: false,
            threads: 1,
        };
        let faces = stars::stars(&self.v, self.n_vertices, &flagged, pass)?.faces;
        Ok(faces.expect("faces were asked for").1)
    }

    /// The opposite of one half-face without building `O`: a scan at level 0, by the same
    /// rule level 1 stores.
    pub(crate) fn opposite_by_scan(&self, hf: u32) -> u32 {
        if self.non_manifold.binary_search(&hf).is_ok() || self.seams.binary_search(&hf).is_ok() {
            return NONE;
        }
        let key = sorted_triple(&self.v, hf);
        let mut found = NONE;
        for g in 0..self.v.len() as u32 {
            if g != hf && sorted_triple(&self.v, g) == key {
                if found != NONE {
                    return NONE;
                }
                found = g;
            }
        }
        if found != NONE && crate::chf::ids::same_direction(&self.v, hf, found) {
            return NONE;
        }
        found
    }
}

/// One bit per half-face, set on canonical ones.
pub(crate) fn face_bits(o: &[u32]) -> Result<RankBits> {
    // A word at a time: 64 independent compares the compiler can vectorize.
    let words = o.chunks(64).enumerate().map(|(w, chunk)| {
        let base = 64 * w as u32;
        chunk.iter().enumerate().fold(0u64, |word, (i, &g)| {
            word | (((g == NONE) | (base + (i as u32) < g)) as u64) << i
        })
    });
    RankBits::from_words(try_collect(words, "the face bits")?, o.len())
}

/// The position of the `k`-th set bit (binary search on the rank): O(log n).
fn select(bits: &RankBits, n: usize, k: usize) -> usize {
    let (mut lo, mut hi) = (0usize, n);
    // Smallest i with rank(i) + bit(i) > k.
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if bits.rank(mid) + bits.get(mid) as usize > k {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo
}

impl View<'_> {
    #[inline]
    pub fn opposite(&self, hf: u32) -> u32 {
        self.o[hf as usize]
    }

    /// What a star walk reads ahead for the face ids of `t` (see `star.rs`).
    #[inline]
    pub fn ahead_faces(&self, t: u32) -> u32 {
        match self.edit {
            Some(e) => e.hf_face[4 * t as usize],
            None => self.faces.word(4 * t as usize),
        }
    }

    /// What a star walk reads ahead for the edge ids of `t`.
    #[inline]
    pub fn ahead_edges(&self, t: u32) -> u32 {
        match self.edit {
            Some(e) => e.slot_edge[6 * t as usize],
            None => self.edges.word(6 * t as usize),
        }
    }

    /// The face id of `hf` if `hf` names its face (is canonical), once per face.
    #[inline]
    pub fn face_if_canonical(&self, hf: u32) -> Option<u32> {
        (self.canonical_half_face(hf) == hf).then(|| self.face_of(hf))
    }

    /// The edge id of slot `s` if it names its edge; every slot of an edited CHF (the
    /// callers keep each id once).
    #[inline]
    pub fn edge_if_canonical(&self, s: usize) -> Option<u32> {
        match self.edit {
            Some(e) => Some(e.slot_edge[s]),
            None => self.edges.get(s).then(|| self.edges.rank(s) as u32),
        }
    }

    /// The same view, borrowing what this one computed (for many queries on one view).
    pub fn reborrow(&self) -> View<'_> {
        View {
            v: self.v,
            o: Cow::Borrowed(&self.o),
            faces: Cow::Borrowed(&*self.faces),
            edges: Cow::Borrowed(&*self.edges),
            vh: self.vh,
            fh: self.fh,
            eh: self.eh,
            multi_fan: self.multi_fan,
            edit: self.edit,
        }
    }

    /// The half-face that names its face: itself on the boundary, else the smaller twin.
    #[inline]
    pub fn canonical_half_face(&self, hf: u32) -> u32 {
        let g = self.o[hf as usize];
        if g != NONE && g < hf { g } else { hf }
    }

    #[inline]
    pub fn face_of(&self, hf: u32) -> u32 {
        if let Some(s) = self.edit {
            return s.hf_face[hf as usize];
        }
        self.faces.rank(self.canonical_half_face(hf) as usize) as u32
    }

    /// The canonical half-face of face `f`.
    #[inline]
    pub fn face_half_face(&self, f: u32) -> u32 {
        if let Some(s) = self.edit {
            return s.face_hf[f as usize];
        }
        match self.fh {
            Some(fh) => fh[f as usize],
            None => select(&self.faces, self.v.len(), f as usize) as u32,
        }
    }

    /// The canonical slot of the edge of half-edge `he`. O(k).
    #[inline]
    pub fn edge_slot_of(&self, he: HalfEdge) -> u64 {
        edges::canonical_slot(self.v, &self.o, &self.edges, he)
    }

    #[inline]
    pub fn edge_of(&self, he: HalfEdge) -> u32 {
        if let Some(s) = self.edit {
            return s.slot_edge[crate::chf::ids::slot_of(he) as usize];
        }
        self.edges.rank(self.edge_slot_of(he) as usize) as u32
    }

    /// The canonical slot of edge `e`: O(1) at level 2 (its tetrahedron is stored, and it
    /// is the right one of the marked slots there), O(log T) below.
    pub fn edge_slot(&self, e: u32) -> u64 {
        let Some(eh) = self.eh else {
            return select(&self.edges, self.v.len() / 4 * 6, e as usize) as u64;
        };
        let base = 6 * eh[e as usize] as u64;
        let mut k = e as usize - self.edges.rank(base as usize);
        for s in base..base + 6 {
            if self.edges.get(s as usize) {
                if k == 0 {
                    return s;
                }
                k -= 1;
            }
        }
        unreachable!("edge {e} has no canonical slot in its tetrahedron")
    }

    /// The canonical half-edge of edge `e`: where its rotation starts.
    #[inline]
    pub fn edge_half_edge(&self, e: u32) -> HalfEdge {
        if let Some(s) = self.edit {
            return s.edge_he[e as usize];
        }
        edges::slot_canonical_half_edge(&self.o, self.edge_slot(e))
    }

    /// A half-face holding `x`, a boundary one when `x` is on the boundary (the first such
    /// in half-face order), `NONE` when `x` is isolated. O(1) at level 2, a scan below.
    pub fn start_half_face(&self, x: u32) -> u32 {
        if let Some(vh) = self.vh {
            return vh[x as usize];
        }
        let mut any = NONE;
        for hf in 0..self.v.len() as u32 {
            if self.holds(hf, x) {
                if self.o[hf as usize] == NONE {
                    return hf;
                }
                if any == NONE {
                    any = hf;
                }
            }
        }
        any
    }

    #[inline]
    pub fn is_boundary_half_edge(&self, he: HalfEdge) -> bool {
        self.o[he_face(he) as usize] == NONE
    }

    /// Does half-face `hf` hold vertex `x`?
    #[inline]
    pub fn holds(&self, hf: u32, x: u32) -> bool {
        let base = first(tet(hf)) as usize;
        (0..4).any(|i| i != local(hf) as usize && self.v[base + i] == x)
    }
}
