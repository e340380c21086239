//! Test helpers shared by the CHE and CHF export tests, and the tests of `boundary`.

use super::boundary::*;
use super::status::Status;
use crate::error::{Error, ErrorKind};
use std::ptr::null_mut;

/// A build export taking flat cells (`che_mesh_from_triangles`, `chf_mesh_from_tetrahedra`).
pub(super) type Build<H> =
    unsafe extern "C" fn(*const u32, usize, usize, *const f64, u32, *mut *mut H) -> Status;
/// A one-element relation export.
pub(super) type Relation<H> =
    unsafe extern "C" fn(*const H, u32, *mut u32, usize, *mut usize) -> Status;
/// A bulk CSR export.
pub(super) type Bulk<H> = unsafe extern "C" fn(
    *const H,
    *mut u32,
    usize,
    *mut u32,
    usize,
    *mut usize,
    *mut usize,
) -> Status;

/// A new handle from `cells` (`per` ids each) over `n_vertices` vertices, without positions.
pub(super) fn build<H>(
    f: Build<H>, cells: &[u32], per: usize, n_vertices: usize, level: u32,
) -> *mut H {
    let mut m = null_mut();
    // SAFETY: a live array of `cells.len()` ids and a local out-pointer.
    let s = unsafe {
        f(
            cells.as_ptr(),
            cells.len() / per,
            n_vertices,
            std::ptr::null(),
            level,
            &mut m,
        )
    };
    assert_eq!(s, Status::Ok);
    m
}

/// All rows of a relation, one call per element.
pub(super) fn rows<H>(m: *const H, f: Relation<H>, n: usize) -> Vec<Vec<u32>> {
    (0..n as u32)
        .map(|x| {
            let mut len = 0;
            // SAFETY: live mesh; a size query, then a buffer of that size.
            unsafe {
                assert_eq!(f(m, x, null_mut(), 0, &mut len), Status::Ok);
                let mut buf = vec![0u32; len];
                assert_eq!(f(m, x, buf.as_mut_ptr(), len, &mut len), Status::Ok);
                buf
            }
        })
        .collect()
}

/// The same rows from a bulk call.
pub(super) fn bulk<H>(m: *const H, f: Bulk<H>) -> Vec<Vec<u32>> {
    let (mut no, mut ni) = (0, 0);
    // SAFETY: live mesh; a size query, then buffers of those sizes (never empty).
    unsafe {
        assert_eq!(
            f(m, null_mut(), 0, null_mut(), 0, &mut no, &mut ni),
            Status::Ok
        );
        let (mut off, mut idx) = (vec![0u32; no], vec![0u32; ni.max(1)]);
        let s = f(
            m,
            off.as_mut_ptr(),
            no,
            idx.as_mut_ptr(),
            ni,
            &mut no,
            &mut ni,
        );
        assert_eq!(s, Status::Ok);
        off.windows(2)
            .map(|w| idx[w[0] as usize..w[1] as usize].to_vec())
            .collect()
    }
}

/// `validate` passes on every build of `meshes` at every level and names a NULL handle.
pub(super) fn validates<H>(
    meshes: impl Fn(u32) -> Vec<*mut H>, validate: unsafe extern "C" fn(*const H) -> Status,
    free: unsafe extern "C" fn(*mut H),
) {
    for level in 0..=3 {
        for m in meshes(level) {
            // SAFETY: a live mesh, freed once.
            unsafe {
                assert_eq!(validate(m), Status::Ok, "level {level}");
                free(m);
            }
        }
    }
    // SAFETY: NULL is a documented argument.
    assert_eq!(unsafe { validate(std::ptr::null()) }, Status::NullArgument);
    assert!(with_last_error(|e| e.contains("'m'")));
    // SAFETY: NULL is a no-op.
    unsafe { free(null_mut()) };
}

fn last() -> String {
    with_last_error(|s| s.to_string())
}

#[test]
fn a_panic_becomes_a_status() {
    let s = guard(|| panic!("boom"));
    assert_eq!(s, Status::Panic);
    assert!(last().contains("boom"), "{}", last());
    let v: u32 = guard_or(7, || panic!("{}", String::from("bang")));
    assert_eq!(v, 7);
    assert!(last().contains("bang"));
}

#[test]
fn errors_map_one_to_one() {
    use ErrorKind::*;
    let kinds = [
        NullArgument,
        OutOfRange,
        InvalidInput,
        NonManifold,
        BufferTooSmall,
    ];
    let kinds = kinds
        .into_iter()
        .chain([Io, Parse, TooLarge, Panic, OutOfMemory]);
    for (i, k) in kinds.into_iter().enumerate() {
        let s = guard(|| Err(Error::new(k, format!("kind {i}"))));
        assert_eq!(s as u32, i as u32 + 1);
        assert_eq!(last(), format!("kind {i}"));
    }
}

/// A C enum value picks its entry of the core's list by index: the lists are in the
/// order of the values.
#[test]
fn c_enum_lists_are_in_order() {
    use crate::che::{HalfEdgeArray, MatrixKind};
    use crate::chf::VolumeMatrixKind;
    for (i, k) in HalfEdgeArray::ALL.into_iter().enumerate() {
        assert_eq!(k as usize, i);
    }
    for (i, k) in MatrixKind::ALL.into_iter().enumerate() {
        assert_eq!(k as usize, i);
    }
    for (i, k) in VolumeMatrixKind::ALL.into_iter().enumerate() {
        assert_eq!(k as usize, i);
    }
}

#[test]
fn statuses_are_in_order() {
    for (i, (s, _)) in super::status::STATUSES.into_iter().enumerate() {
        assert_eq!(s as usize, i);
    }
}

#[test]
fn sinks_count_past_capacity() {
    use crate::che::Push;
    let mut buf = [0u32; 2];
    let mut len = 0usize;
    // SAFETY: local buffers of the stated sizes.
    let mut s = unsafe { sink(buf.as_mut_ptr(), 2, &mut len, "buf") }.unwrap();
    s.extend([1, 2, 3]);
    let e = s.finish().unwrap_err();
    assert_eq!(e.kind, ErrorKind::BufferTooSmall);
    assert_eq!((len, buf), (3, [1, 2]));
    // SAFETY: a size query writes only `len`.
    let mut s = unsafe { sink(null_mut(), 0, &mut len, "buf") }.unwrap();
    s.extend([1, 2, 3, 4]);
    s.push(5);
    s.finish().unwrap();
    assert_eq!(len, 5);
}

#[test]
fn last_error_sizes_truncates_and_terminates() {
    use super::status::{topomesh_last_error, topomesh_version};
    let _ = guard(|| Err(Error::invalid("abcdef")));
    let (mut buf, mut len) = ([7 as std::ffi::c_char; 4], 0usize);
    // SAFETY: local buffers of the stated sizes; NULL with 0 is a size query.
    unsafe {
        assert_eq!(topomesh_last_error(null_mut(), 0, &mut len), Status::Ok);
        assert_eq!(len, 7);
        assert_eq!(
            topomesh_last_error(buf.as_mut_ptr(), 0, &mut len),
            Status::BufferTooSmall
        );
        assert_eq!(buf[0], 7, "nothing written without room for the NUL");
        assert_eq!(
            topomesh_last_error(buf.as_mut_ptr(), 4, &mut len),
            Status::BufferTooSmall
        );
        assert_eq!(std::ffi::CStr::from_ptr(buf.as_ptr()), c"abc");
        assert_eq!(
            topomesh_last_error(null_mut(), 1, &mut len),
            Status::NullArgument
        );
        assert_eq!(
            topomesh_last_error(buf.as_mut_ptr(), 4, null_mut()),
            Status::NullArgument
        );
        let version = std::ffi::CStr::from_ptr(topomesh_version());
        assert_eq!(version.to_str().unwrap(), env!("CARGO_PKG_VERSION"));
    }
    assert_eq!(last(), "abcdef", "reading the detail leaves it");
}
