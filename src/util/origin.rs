//! Where each element of a structure comes from in the input: the vertex, triangle and
//! tetrahedron origin maps of CHE and CHF, stored empty when they are the identity.

use std::ops::Deref;

/// Structure element -> input element; no storage when every element is its own origin.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct OriginMap(Vec<u32>);

impl OriginMap {
    /// The vertex map after a split: the input vertices map to themselves, and copy
    /// `n_vertices + i` to `copies[i]`; the identity when nothing was copied.
    pub(crate) fn with_copies(
        n_vertices: usize, copies: &[u32],
    ) -> crate::error::Result<OriginMap> {
        if copies.is_empty() {
            Ok(OriginMap::default())
        } else {
            let ids = (0..n_vertices as u32).chain(copies.iter().copied());
            Ok(OriginMap(crate::util::alloc::try_collect(
                ids,
                "the vertex origins",
            )?))
        }
    }

    /// The input element `x` comes from.
    #[inline]
    pub(crate) fn get(&self, x: u32) -> u32 {
        origin(&self.0, x)
    }

    /// Appends the origin of a new element (an edit; the map must be explicit).
    pub(crate) fn push(&mut self, x: u32, what: &str) -> crate::error::Result<()> {
        crate::util::alloc::try_push(&mut self.0, x, what)
    }

    /// Room for `n` more pushes (by amortised steps), so that they cannot fail.
    pub(crate) fn reserve(&mut self, n: usize, what: &str) -> crate::error::Result<()> {
        crate::util::alloc::try_grow(&mut self.0, n, what)
    }

    /// The first violation of a vertex map's rules, in words: `n` vertices over `n_input`
    /// input vertices, the input vertices their own origins, each copy from an input
    /// vertex, and a map written out as soon as there is a copy. A file can state any of
    /// these wrongly; queries index by the origins, so they are checked before use.
    pub(crate) fn vertex_violation(&self, n: usize, n_input: usize) -> Option<String> {
        if n < n_input {
            return Some(format!(
                "{n} vertices, fewer than the {n_input} input vertices"
            ));
        }
        if self.0.is_empty() {
            return (n != n_input).then(|| format!("no vertex origins for {} copies", n - n_input));
        }
        if self.0.len() != n {
            return Some(format!("{} vertex origins for {n} vertices", self.0.len()));
        }
        self.0.iter().enumerate().find_map(|(v, &x)| {
            let ok = if v < n_input {
                x as usize == v
            } else {
                (x as usize) < n_input
            };
            (!ok).then(|| format!("vertex {v} has origin {x}"))
        })
    }

    /// The map, or `None` when it is the identity.
    pub(crate) fn explicit(&self) -> Option<&[u32]> {
        (!self.0.is_empty()).then_some(&self.0[..])
    }

    /// The map as a vector of `len` entries, the identity written out first when it was
    /// stored empty (an edit adds elements with another origin, or none).
    pub(crate) fn written_out(&mut self, len: usize) -> crate::error::Result<&mut Vec<u32>> {
        if self.0.is_empty() && len > 0 {
            self.0 = crate::util::alloc::try_collect(0..len as u32, "the origin map")?;
        }
        Ok(&mut self.0)
    }
}

/// The stored map (empty for the identity).
impl Deref for OriginMap {
    type Target = [u32];
    fn deref(&self) -> &[u32] {
        &self.0
    }
}

impl From<Vec<u32>> for OriginMap {
    fn from(map: Vec<u32>) -> Self {
        OriginMap(map)
    }
}

/// The input element `x` comes from, by a map stored empty for the identity.
#[inline]
pub(crate) fn origin(map: &[u32], x: u32) -> u32 {
    if map.is_empty() { x } else { map[x as usize] }
}

/// Where a sorted id list (an origin map, the flagged half-edges or half-faces) breaks its
/// rule: each id below `n` and larger than the one before. `name` names the list.
pub(crate) fn increasing_below_violation(xs: &[u32], n: usize, name: &str) -> Option<String> {
    xs.iter().enumerate().find_map(|(i, &x)| {
        if x as usize >= n {
            Some(format!("{name}[{i}] = {x} is not below {n}"))
        } else if i > 0 && xs[i - 1] >= x {
            Some(format!("{name}[{i}] = {x} does not increase"))
        } else {
            None
        }
    })
}
