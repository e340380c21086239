//! Level files (`.che`, `.chf`) from mutated bytes, opened loaded and mapped. The first byte
//! chooses: bit 0 a CHF instead of a CHE, bit 1 re-seal the checksums before opening (so
//! that the mutations reach the length and structure checks behind them). Every open
//! either fails with an error, the same in both modes, or gives the same structure in
//! both; a structure opened with full checks (or opened trusted and then validated)
//! answers every query without a panic. Panics, aborts and reads outside the file are
//! the bugs.
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::path::{Path, PathBuf};
use topomesh::levelfile::{OpenOptions, Verify};
use topomesh::{Che, Chf};

fn u64_at(b: &[u8], at: usize) -> Option<u64> {
    Some(u64::from_le_bytes(b.get(at..at + 8)?.try_into().ok()?))
}

/// Recomputes the CRC-32 of every section that lies inside the file, then of the header
/// and the table, as the writer does.
fn reseal(b: &mut [u8]) {
    let Some(n) = u64_at(b, 24).map(|x| (x >> 32) as usize) else {
        return;
    };
    let table_end = 64usize.saturating_add(n.saturating_mul(64));
    if table_end > b.len() {
        return;
    }
    for i in 0..n {
        let e = 64 + 64 * i;
        let elem = u32::from_le_bytes(b[e + 32..e + 36].try_into().unwrap());
        let size = if elem == 1 { 4 } else { 8 };
        let (offset, count) = (u64_at(b, e + 40).unwrap(), u64_at(b, e + 48).unwrap());
        let end = count.checked_mul(size).and_then(|n| n.checked_add(offset));
        if let Some(end) = end.filter(|&end| end <= b.len() as u64) {
            let crc = crc32fast::hash(&b[offset as usize..end as usize]);
            b[e + 36..e + 40].copy_from_slice(&crc.to_le_bytes());
        }
    }
    let mut h = crc32fast::Hasher::new();
    h.update(&b[..40]);
    h.update(&b[64..table_end]);
    let crc = h.finalize();
    b[40..44].copy_from_slice(&crc.to_le_bytes());
}

/// A file of this process's own (libFuzzer may run several processes), removed at the end
/// of each input: libFuzzer ends a process without unwinding, so nothing later would.
fn scratch(ext: &str) -> PathBuf {
    std::env::temp_dir().join(format!("topomesh-fuzz-{}.{ext}", std::process::id()))
}

/// Opens `path` loaded and mapped with `verify`: the same error or the same structure.
fn both<T>(
    path: &Path, verify: Verify, open: fn(&Path, OpenOptions) -> topomesh::error::Result<T>,
    state: fn(&T) -> String,
) -> Option<T> {
    let loaded = open(path, OpenOptions::loaded(verify));
    let mapped = open(path, OpenOptions::mapped(verify));
    match (loaded, mapped) {
        (Ok(a), Ok(b)) => {
            assert_eq!(state(&a), state(&b), "loaded and mapped differ");
            Some(b)
        }
        (Err(a), Err(b)) => {
            assert_eq!((a.kind, a.message), (b.kind, b.message));
            None
        }
        (a, b) => panic!("loaded ok: {}, mapped ok: {}", a.is_ok(), b.is_ok()),
    }
}

fn che_queries(che: &Che) {
    for v in 0..che.num_vertices() as u32 {
        let _ = che.vertex_vertices(v).count();
        let _ = che.vertex_triangles(v).count();
    }
    for t in 0..che.num_triangles() as u32 {
        let _ = che.triangle_triangles(t);
    }
    for e in 0..che.num_edges() as u32 {
        let _ = che.edge_triangles(e);
    }
    let _ = che.all_vertex_vertices();
    let _ = che.summary();
}

fn chf_queries(chf: &Chf) {
    for v in 0..chf.num_vertices() as u32 {
        let _ = chf.vertex_vertices(v).count();
    }
    for t in 0..chf.num_tetrahedra() as u32 {
        let _ = chf.tetrahedron_tetrahedra(t);
    }
    let _ = chf.all_vertex_vertices();
    let _ = chf.summary();
}

fuzz_target!(|data: &[u8]| {
    let Some((&choice, bytes)) = data.split_first() else {
        return;
    };
    let mut bytes = bytes.to_vec();
    if choice & 2 != 0 {
        reseal(&mut bytes);
    }
    if choice & 1 == 0 {
        let path = scratch("che");
        std::fs::write(&path, &bytes).unwrap();
        let state = |c: &Che| format!("{c:?}");
        let open = |p: &Path, o| Che::open(p, o);
        if let Some(che) = both(&path, Verify::Full, open, state) {
            che_queries(&che);
        }
        if let Some(che) = both(&path, Verify::Trusted, open, state)
            && che.validate().is_ok()
        {
            che_queries(&che);
        }
        let _ = std::fs::remove_file(&path);
    } else {
        let path = scratch("chf");
        std::fs::write(&path, &bytes).unwrap();
        let state = |c: &Chf| format!("{c:?}");
        let open = |p: &Path, o| Chf::open(p, o);
        if let Some(chf) = both(&path, Verify::Full, open, state) {
            chf_queries(&chf);
        }
        if let Some(chf) = both(&path, Verify::Trusted, open, state)
            && chf.validate().is_ok()
        {
            chf_queries(&chf);
        }
        let _ = std::fs::remove_file(&path);
    }
});
