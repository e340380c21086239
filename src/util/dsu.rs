//! Union-find over `0..n` with path halving; the smaller root wins, so results do not
//! depend on the order of unions.

pub(crate) struct Dsu(Vec<u32>);

impl Dsu {
    pub(crate) fn new(n: usize) -> crate::error::Result<Self> {
        let ids = crate::util::alloc::try_collect(0..n as u32, "the union-find")?;
        Ok(Dsu(ids))
    }

    pub(crate) fn find(&mut self, mut x: u32) -> u32 {
        while self.0[x as usize] != x {
            let up = self.0[self.0[x as usize] as usize];
            self.0[x as usize] = up;
            x = up;
        }
        x
    }

    pub(crate) fn union(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            self.0[ra.max(rb) as usize] = ra.min(rb);
        }
    }

    /// Number of sets among the elements marked in `used`.
    pub(crate) fn roots_among(&mut self, used: &[bool]) -> u64 {
        (0..used.len() as u32)
            .filter(|&x| used[x as usize] && self.find(x) == x)
            .count() as u64
    }
}

/// The components of the input vertices that the elements use, and how many input vertices
/// no element uses: `v` holds `K` structure vertex ids per element, `origin` maps them to
/// the `n` input vertices, and the vertices of one element are connected.
pub(crate) fn element_components<const K: usize>(
    v: &[u32], n: usize, origin: impl Fn(u32) -> u32,
) -> crate::error::Result<(u64, u64)> {
    let mut used = crate::util::alloc::try_vec(n, false, "the used vertices")?;
    let mut dsu = Dsu::new(n)?;
    for element in v.chunks_exact(K) {
        let a = origin(element[0]);
        used[a as usize] = true;
        for &x in &element[1..] {
            let b = origin(x);
            used[b as usize] = true;
            dsu.union(a, b);
        }
    }
    let components = dsu.roots_among(&used);
    let isolated = used.iter().filter(|&&u| !u).count() as u64;
    Ok((components, isolated))
}

/// The boundary a summary walks: the vertices on it (of `0..n`) and the union-find that
/// joins them along its edges, whose sets among them are its components (curves).
pub(crate) struct BoundaryMarks {
    pub on_boundary: Vec<bool>,
    dsu: Dsu,
}

impl BoundaryMarks {
    pub(crate) fn new(n: usize) -> crate::error::Result<Self> {
        Ok(BoundaryMarks {
            on_boundary: crate::util::alloc::try_vec(n, false, "the summary's boundary marks")?,
            dsu: Dsu::new(n)?,
        })
    }

    /// Boundary edge `a-b`: both ends on the boundary, in one component.
    pub(crate) fn edge(&mut self, a: u32, b: u32) {
        self.on_boundary[a as usize] = true;
        self.on_boundary[b as usize] = true;
        self.dsu.union(a, b);
    }

    /// The components of the boundary edges given.
    pub(crate) fn components(&mut self) -> u64 {
        self.dsu.roots_among(&self.on_boundary)
    }
}

/// The input boundary among the half-elements (half-edges, half-faces) with opposites
/// `o`: the unpaired ones that are neither `non_manifold` nor `seams` (both sorted).
pub(crate) fn input_boundary<'a>(
    o: &'a [u32], non_manifold: &'a [u32], seams: &'a [u32],
) -> impl Iterator<Item = u32> + 'a {
    (0..o.len() as u32).filter(move |h| {
        o[*h as usize] == crate::NONE
            && non_manifold.binary_search(h).is_err()
            && seams.binary_search(h).is_err()
    })
}

/// The input complex as the summaries count it (`v`, `n` and `origin` as for
/// [`element_components`]): its components and isolated vertices and the vertices it keeps,
/// the `welded` ones left out (the weld merged them into another: they are not vertices
/// of the welded complex), plus the marks of its boundary that the summary's boundary pass
/// fills. Panics only when memory runs out, as the summaries.
pub(crate) struct InputComplex {
    pub components: u64,
    pub isolated: u64,
    pub kept: usize,
    pub boundary: BoundaryMarks,
}

impl InputComplex {
    pub(crate) fn new<const K: usize>(
        v: &[u32], n: usize, welded: usize, origin: impl Fn(u32) -> u32,
    ) -> crate::error::Result<Self> {
        let (components, isolated) = element_components::<K>(v, n, origin)?;
        Ok(InputComplex {
            components,
            isolated: isolated - welded as u64,
            kept: n - welded,
            boundary: BoundaryMarks::new(n)?,
        })
    }
}
