//! Fallible allocation: every array whose size depends on the input is asked for here, so
//! that running out of memory is an [`ErrorKind::OutOfMemory`](crate::ErrorKind) error
//! naming the bytes and the array, never an abort of the process that loaded the library.
//!
//! Each helper asks with `try_reserve_exact` (or `try_reserve` for amortised growth), and
//! on failure builds the error, whose message is the only further allocation, a short one.
//! `pages` wraps these for the build's large arrays, on huge pages.

use crate::error::{Error, Result};

/// The bytes of `n` values of `T`, saturating (a count this large fails anyway).
pub(crate) fn bytes_of<T>(n: usize) -> u64 {
    (n as u64).saturating_mul(std::mem::size_of::<T>() as u64)
}

/// Room for `additional` more elements in `v`, exactly.
pub(crate) fn try_reserve<T>(v: &mut Vec<T>, additional: usize, what: &str) -> Result<()> {
    v.try_reserve_exact(additional)
        .map_err(|_| Error::out_of_memory(bytes_of::<T>(v.len().saturating_add(additional)), what))
}

/// Room for `additional` more elements in `v`, growing by amortised steps: for arrays that
/// grow a few elements at a time (an edit's appends), where growing exactly would move the
/// whole array on every call.
pub(crate) fn try_grow<T>(v: &mut Vec<T>, additional: usize, what: &str) -> Result<()> {
    v.try_reserve(additional)
        .map_err(|_| Error::out_of_memory(bytes_of::<T>(v.len().saturating_add(additional)), what))
}

/// An empty hash map with room for `n` entries.
pub(crate) fn try_hash_map<K: Eq + std::hash::Hash, V>(
    n: usize, what: &str,
) -> Result<std::collections::HashMap<K, V>> {
    let mut m = std::collections::HashMap::new();
    m.try_reserve(n)
        .map_err(|_| Error::out_of_memory(bytes_of::<(K, V)>(n), what))?;
    Ok(m)
}

/// An empty vector with room for `n` elements.
pub(crate) fn try_with_capacity<T>(n: usize, what: &str) -> Result<Vec<T>> {
    let mut v = Vec::new();
    try_reserve(&mut v, n, what)?;
    Ok(v)
}

/// `vec![value; n]`.
pub(crate) fn try_vec<T: Clone>(n: usize, value: T, what: &str) -> Result<Vec<T>> {
    let mut v = try_with_capacity(n, what)?;
    v.resize(n, value);
    Ok(v)
}

/// `v.resize(len, value)`, growing to exactly `len` when it grows.
pub(crate) fn try_resize<T: Clone>(v: &mut Vec<T>, len: usize, value: T, what: &str) -> Result<()> {
    try_reserve(v, len.saturating_sub(v.len()), what)?;
    v.resize(len, value);
    Ok(())
}

/// `slice.to_vec()`.
pub(crate) fn try_to_vec<T: Clone>(slice: &[T], what: &str) -> Result<Vec<T>> {
    let mut v = try_with_capacity(slice.len(), what)?;
    v.extend_from_slice(slice);
    Ok(v)
}

/// `v.extend(items)`: room for the iterator's lower bound is asked for at once; when the
/// upper bound is unknown or more than the room, the rest grows by amortised steps, each
/// one fallible. The room too grows by amortised steps (exactly the bound on an empty
/// vector): extending a vector row after row must not move it at every row.
pub(crate) fn try_extend<T>(
    v: &mut Vec<T>, items: impl IntoIterator<Item = T>, what: &str,
) -> Result<()> {
    let items = items.into_iter();
    let (low, high) = items.size_hint();
    if v.capacity() - v.len() < low {
        try_grow(v, low, what)?;
    }
    if high.is_some_and(|high| high <= v.capacity() - v.len()) {
        // Cannot outgrow the room: `extend` does not allocate.
        v.extend(items);
        return Ok(());
    }
    for item in items {
        try_push(v, item, what)?;
    }
    Ok(())
}

/// `v.push(item)`, growing by amortised steps.
pub(crate) fn try_push<T>(v: &mut Vec<T>, item: T, what: &str) -> Result<()> {
    if v.len() == v.capacity() {
        v.try_reserve(1)
            .map_err(|_| Error::out_of_memory(bytes_of::<T>(2 * v.len()), what))?;
    }
    v.push(item);
    Ok(())
}

/// The value of `r`, for the queries whose signature has no error (one element's relation
/// at a level that stores no `O`, a view): running out of memory there is a panic, never
/// an abort. Behind the C boundary (a quiet section, see `util::panics`) its payload is
/// the [`Error`] itself, so that the boundary reports the error's own status
/// (`OUT_OF_MEMORY`) and message rather than a panic; elsewhere it is the message, which
/// the panic hook prints. Rust callers that must not panic use the `try_` form of the
/// query where there is one.
pub(crate) fn or_panic<T>(r: Result<T>) -> T {
    r.unwrap_or_else(|e| {
        if crate::util::panics::is_quiet() {
            std::panic::panic_any(e)
        } else {
            panic!("{e}")
        }
    })
}

/// What a fill gives back: nothing, or a result (the C skin's `csr` exports take either).
pub(crate) trait Done {
    fn done(self) -> Result<()>;
}

impl Done for () {
    fn done(self) -> Result<()> {
        Ok(())
    }
}

impl Done for Result<()> {
    fn done(self) -> Result<()> {
        self
    }
}

/// `items.collect::<Vec<_>>()`, fallibly.
pub(crate) fn try_collect<T>(items: impl IntoIterator<Item = T>, what: &str) -> Result<Vec<T>> {
    let mut v = Vec::new();
    try_extend(&mut v, items, what)?;
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ErrorKind;

    #[test]
    fn a_huge_request_is_an_error_naming_it() {
        let e = try_vec(usize::MAX / 8, 0u64, "the test array").unwrap_err();
        assert_eq!(e.kind, ErrorKind::OutOfMemory);
        assert_eq!(e.bytes(), Some(bytes_of::<u64>(usize::MAX / 8)));
        assert!(e.message.ends_with("for the test array"), "{}", e.message);
        let e = try_with_capacity::<u32>(usize::MAX / 2, "x").unwrap_err();
        assert_eq!(e.kind, ErrorKind::OutOfMemory);
        let mut v = vec![1u8; 3];
        let e = try_resize(&mut v, usize::MAX, 0, "y").unwrap_err();
        assert_eq!((e.kind, v), (ErrorKind::OutOfMemory, vec![1, 1, 1]));
    }

    #[test]
    fn the_helpers_give_what_the_infallible_forms_give() {
        assert_eq!(try_vec(3, 7u32, "").unwrap(), vec![7; 3]);
        assert_eq!(try_to_vec(&[1, 2], "").unwrap(), vec![1, 2]);
        let mut v = vec![1, 2, 3];
        try_resize(&mut v, 1, 0, "").unwrap();
        try_resize(&mut v, 3, 9, "").unwrap();
        assert_eq!(v, vec![1, 9, 9]);
        // Exact size, filtered (upper bound above the room) and unknown upper bound.
        assert_eq!(try_collect(0..5u32, "").unwrap(), vec![0, 1, 2, 3, 4]);
        let mut v = try_with_capacity(2, "").unwrap();
        try_extend(&mut v, (0..100u32).filter(|x| x % 40 == 0), "").unwrap();
        assert_eq!(v, vec![0, 40, 80]);
        let unbounded = (0..4u32).flat_map(|x| 0..x);
        assert_eq!(try_collect(unbounded, "").unwrap(), vec![0, 0, 1, 0, 1, 2]);
        assert_eq!(bytes_of::<u64>(usize::MAX), u64::MAX);
    }
}
