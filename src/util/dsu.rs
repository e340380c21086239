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

/// The input complex as the summaries count it (`v`, `n` and `origin` as for
/// [`element_components`]): its components and isolated vertices and the vertices it keeps,
/// the `welded` ones left out (the weld merged them into another: they are not vertices
/// of the welded complex), plus the marks and the union-find over the input vertices that
/// the summary's boundary pass fills. Panics only when memory runs out, as the summaries.
pub(crate) struct InputComplex {
    pub components: u64,
    pub isolated: u64,
    pub kept: usize,
    pub on_boundary: Vec<bool>,
    pub dsu: Dsu,
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
            on_boundary: crate::util::alloc::try_vec(n, false, "the summary's boundary marks")?,
            dsu: Dsu::new(n)?,
        })
    }
}
