//! Level files: a built CHE or CHF saved and opened again equals the saved one (every array
//! and every answer), at every level; a damaged file gives an error naming the place and
//! never a panic.

mod che_common;
mod chf_common;

use che_common::{answers as che_answers, che_n, surfaces};
use chf_common::volumes;
use std::path::{Path, PathBuf};
use topomesh::generate::{grid, torus};
use topomesh::levelfile::{Mode, OpenOptions, Verify};
use topomesh::{BuildOptions, Che, Chf, ErrorKind, chf};

/// A fresh folder under the temp dir for one test.
fn folder(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("topomesh-level-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const FULL: OpenOptions = OpenOptions {
    verify: Verify::Full,
    mode: Mode::Loaded,
};

const MODES: [Mode; 2] = [Mode::Loaded, Mode::Mapped];

/// Every array and count the structure holds (its `Debug` prints them all).
fn che_state(che: &Che) -> String {
    format!("{che:?}")
}

#[test]
fn surfaces_round_trip_at_every_level() {
    let dir = folder("che");
    for (i, (tris, positions)) in surfaces().into_iter().enumerate() {
        let n = che_n(&tris, &positions);
        for level in 0..=3 {
            let che =
                Che::from_triangles(&tris, n, &positions, BuildOptions::level(level)).unwrap();
            let path = dir.join(format!("{i}-{level}.che"));
            che.save(&path).unwrap();
            // Before any query: a level-1 query fills the lazy edge directory.
            let state = che_state(&che);
            for (verify, mode) in [Verify::Full, Verify::Checksums, Verify::Trusted]
                .into_iter()
                .flat_map(|v| MODES.map(|m| (v, m)))
            {
                let back = Che::open(&path, OpenOptions { verify, mode }).unwrap();
                assert_eq!(back.is_mapped(), mode == Mode::Mapped);
                assert_eq!(che_state(&back), state, "mesh {i} level {level}");
                assert_eq!(back.report(), che.report());
                assert_eq!(
                    che_answers(&back),
                    che_answers(&che),
                    "mesh {i} level {level}"
                );
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Every array and count the structure holds.
fn chf_state(chf: &Chf) -> String {
    format!("{chf:?}")
}

#[test]
fn volumes_round_trip_at_every_level() {
    let dir = folder("chf");
    for (i, mesh) in volumes().into_iter().enumerate() {
        for level in 0..=3 {
            for with_positions in [false, true] {
                let built = mesh.build(level, with_positions);
                let path = dir.join(format!("{i}-{level}.chf"));
                built.save(&path).unwrap();
                for mode in MODES {
                    let options = OpenOptions {
                        verify: Verify::Full,
                        mode,
                    };
                    let back = Chf::open(&path, options).unwrap();
                    assert_eq!(
                        chf_state(&back),
                        chf_state(&built),
                        "mesh {i} level {level}"
                    );
                    assert_eq!(
                        chf_common::answers(&back),
                        chf_common::answers(&built),
                        "mesh {i} level {level}"
                    );
                }
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

fn small_che() -> Che {
    let s = grid(1, 1);
    Che::from_triangles(
        &s.triangles,
        s.positions.len(),
        &s.positions,
        BuildOptions::level(3),
    )
    .unwrap()
}

fn saved(dir: &Path, name: &str) -> (PathBuf, Vec<u8>) {
    let path = dir.join(name);
    small_che().save(&path).unwrap();
    let bytes = std::fs::read(&path).unwrap();
    (path, bytes)
}

/// Opens `bytes` written to `path`, as a CHE, loaded and mapped: both give the same
/// error, or the same structure (the loaded one is returned).
fn open_bytes(path: &Path, bytes: &[u8], verify: Verify) -> topomesh::error::Result<Che> {
    std::fs::write(path, bytes).unwrap();
    let mapped = Che::open(path, OpenOptions::mapped(verify));
    let loaded = Che::open(path, OpenOptions::loaded(verify));
    match (&loaded, &mapped) {
        (Ok(a), Ok(b)) => assert_eq!(che_state(a), che_state(b)),
        (Err(a), Err(b)) => assert_eq!((a.kind, &a.message), (b.kind, &b.message)),
        _ => panic!("loaded {loaded:?}, mapped {mapped:?}"),
    }
    drop(mapped);
    loaded
}

fn le_u64(b: &[u8], at: usize) -> u64 {
    u64::from_le_bytes(b[at..at + 8].try_into().unwrap())
}

/// The offset and count fields of the section entry named `name`.
fn entry(bytes: &[u8], name: &str) -> usize {
    let n = u32::from_le_bytes(bytes[28..32].try_into().unwrap()) as usize;
    (0..n)
        .map(|i| 64 + 64 * i)
        .find(|&at| bytes[at..at + 32].split(|&c| c == 0).next() == Some(name.as_bytes()))
        .unwrap()
}

/// Recomputes the table checksum after an edit, so that the damage reaches the checks
/// behind it.
fn reseal(bytes: &mut [u8]) {
    let n = u32::from_le_bytes(bytes[28..32].try_into().unwrap()) as usize;
    let mut h = crc32fast::Hasher::new();
    h.update(&bytes[..40]);
    h.update(&bytes[64..64 + 64 * n]);
    let crc = h.finalize();
    bytes[40..44].copy_from_slice(&crc.to_le_bytes());
}

fn expect_err(r: topomesh::error::Result<Che>, kind: ErrorKind, words: &[&str]) {
    let e = r.expect_err("an error");
    assert_eq!(e.kind, kind, "{e}");
    for w in words {
        assert!(e.message.contains(w), "{w:?} not in {e}");
    }
}

#[test]
fn bad_headers_name_the_byte() {
    let dir = folder("header");
    let (path, good) = saved(&dir, "m.che");
    let mut b = good.clone();
    b[0] = b'X';
    expect_err(
        open_bytes(&path, &b, Verify::Full),
        ErrorKind::Parse,
        &["byte 0", "magic"],
    );
    let mut b = good.clone();
    b[12] = 2;
    expect_err(
        open_bytes(&path, &b, Verify::Trusted),
        ErrorKind::Parse,
        &["byte 12", "version 2"],
    );
    let mut b = good.clone();
    b[16..20].copy_from_slice(&0x0102_0304u32.to_be_bytes());
    expect_err(
        open_bytes(&path, &b, Verify::Full),
        ErrorKind::Parse,
        &["byte 16", "big-endian"],
    );
    let mut b = good.clone();
    b[8..12].copy_from_slice(b"CHF\0");
    expect_err(
        open_bytes(&path, &b, Verify::Full),
        ErrorKind::Parse,
        &["byte 8", "CHF file"],
    );
    expect_err(
        open_bytes(&path, &good[..40], Verify::Full),
        ErrorKind::Parse,
        &["truncated"],
    );
    expect_err(
        open_bytes(&path, &good[..good.len() - 64], Verify::Full),
        ErrorKind::Parse,
        &["byte 32", "the file has"],
    );
    // A CHE file is not a CHF.
    std::fs::write(&path, &good).unwrap();
    let e = Chf::open(&path, FULL).err().unwrap();
    assert!(
        e.message.contains("expected a CHF file, found a CHE file"),
        "{e}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_sections_name_the_section() {
    let dir = folder("sections");
    let (path, good) = saved(&dir, "m.che");
    // An offset past the end of the file.
    let at = entry(&good, "O");
    let mut b = good.clone();
    b[at + 40..at + 48].copy_from_slice(&(good.len() as u64).to_le_bytes());
    reseal(&mut b);
    expect_err(
        open_bytes(&path, &b, Verify::Full),
        ErrorKind::Parse,
        &["section O", "past the end"],
    );
    // A huge count: refused against the file size, nothing allocated.
    let mut b = good.clone();
    b[at + 48..at + 56].copy_from_slice(&(u64::MAX / 8).to_le_bytes());
    reseal(&mut b);
    expect_err(
        open_bytes(&path, &b, Verify::Full),
        ErrorKind::Parse,
        &["section O"],
    );
    // A count that disagrees with the counts section.
    let mut b = good.clone();
    let count = le_u64(&b, at + 48);
    b[at + 48..at + 56].copy_from_slice(&(count - 1).to_le_bytes());
    reseal(&mut b);
    expect_err(
        open_bytes(&path, &b, Verify::Full),
        ErrorKind::Parse,
        &["section O", "the counts say"],
    );
    // A misaligned offset.
    let mut b = good.clone();
    let offset = le_u64(&b, at + 40);
    b[at + 40..at + 48].copy_from_slice(&(offset + 4).to_le_bytes());
    reseal(&mut b);
    expect_err(
        open_bytes(&path, &b, Verify::Full),
        ErrorKind::Parse,
        &["section O", "64-byte"],
    );
    // A damaged section.
    let mut b = good.clone();
    b[offset as usize] ^= 1;
    expect_err(
        open_bytes(&path, &b, Verify::Full),
        ErrorKind::Parse,
        &["section O", "checksum"],
    );
    // An id out of range with the checksum redone: the structural check catches it.
    let v = entry(&good, "V");
    let v_at = le_u64(&good, v + 40) as usize;
    let mut b = good.clone();
    b[v_at..v_at + 4].copy_from_slice(&1000u32.to_le_bytes());
    let v_len = le_u64(&good, v + 48) as usize * 4;
    let crc = crc32fast::hash(&b[v_at..v_at + v_len]);
    b[v + 36..v + 40].copy_from_slice(&crc.to_le_bytes());
    reseal(&mut b);
    expect_err(
        open_bytes(&path, &b, Verify::Full),
        ErrorKind::InvalidInput,
        &["V[0] = 1000"],
    );
    // Checksums only: the file is read as it is.
    assert!(open_bytes(&path, &b, Verify::Checksums).is_ok());
    let _ = std::fs::remove_dir_all(&dir);
}

/// A file large enough for a mapped full open to sum its sections on a thread of its own
/// (in table order) while it validates: damaged in two sections, `positions` before `r`
/// in the table but taken after it, it names `r` as a loaded open does (the first the
/// open takes), and whole, it opens as the loaded one does.
#[test]
fn a_large_damaged_file_names_the_section_taken_first() {
    let dir = folder("large");
    let path = dir.join("g.che");
    let s = grid(150, 150);
    let n = s.positions.len();
    let che = Che::from_triangles(&s.triangles, n, &s.positions, BuildOptions::level(2)).unwrap();
    che.save(&path).unwrap();
    let good = std::fs::read(&path).unwrap();
    assert!(good.len() > 1 << 20, "{} bytes", good.len());
    assert!(open_bytes(&path, &good, Verify::Full).is_ok());
    let mut b = good.clone();
    for name in ["positions", "r"] {
        b[le_u64(&good, entry(&good, name) + 40) as usize + 8] ^= 4;
    }
    expect_err(
        open_bytes(&path, &b, Verify::Full),
        ErrorKind::Parse,
        &["section r fails its checksum"],
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn every_prefix_of_a_file_is_refused() {
    let dir = folder("prefix");
    let (path, good) = saved(&dir, "m.che");
    for len in 0..good.len() {
        for verify in [Verify::Full, Verify::Trusted] {
            assert!(
                open_bytes(&path, &good[..len], verify).is_err(),
                "prefix {len}"
            );
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Every single-byte change gives an error, or (a byte of padding) the same mesh; never a
/// panic, with checks on or off.
#[test]
fn every_flipped_byte_is_caught_or_harmless() {
    let dir = folder("flip");
    let (path, good) = saved(&dir, "m.che");
    let expected = che_state(&small_che());
    let mut harmless = 0;
    for at in 0..good.len() {
        let mut b = good.clone();
        b[at] ^= 0x5a;
        if let Ok(che) = open_bytes(&path, &b, Verify::Full) {
            assert_eq!(che_state(&che), expected, "byte {at}");
            harmless += 1;
        }
        if let Ok(che) = Che::open(&path, OpenOptions::mapped(Verify::Trusted)) {
            // Queries on a damaged trusted file may answer wrongly, but every read is
            // bounds-checked against the mapping: the worst is a panic (a status in C).
            let _ = std::panic::catch_unwind(|| che_answers(&che));
        }
        let _ = open_bytes(&path, &b, Verify::Trusted);
    }
    assert!(
        harmless < good.len() / 2,
        "{harmless} of {} bytes unchecked",
        good.len()
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_volume_with_a_flipped_byte_is_refused() {
    let dir = folder("flip-chf");
    let path = dir.join("m.chf");
    let built = chf_common::cube(1, 1, 1, true).build(3, true);
    built.save(&path).unwrap();
    let good = std::fs::read(&path).unwrap();
    for at in (0..good.len()).step_by(7) {
        let mut b = good.clone();
        b[at] ^= 0xff;
        std::fs::write(&path, &b).unwrap();
        if let Ok(back) = Chf::open(&path, FULL) {
            assert_eq!(chf_state(&back), chf_state(&built), "byte {at}");
        }
        for mode in MODES {
            let options = OpenOptions {
                verify: Verify::Trusted,
                mode,
            };
            if let Ok(back) = Chf::open(&path, options) {
                // Queries on a damaged trusted file may answer wrongly but stay in bounds:
                // an id out of range is a panic, which the C API turns into a status.
                let _ = std::panic::catch_unwind(|| chf_common::answers(&back));
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn save_is_atomic_and_missing_files_are_io_errors() {
    let dir = folder("io");
    let e = Che::open(dir.join("absent.che"), FULL).err().unwrap();
    assert_eq!(e.kind, ErrorKind::Io);
    assert!(e.message.contains("absent.che"), "{e}");
    let che = small_che();
    che.save(dir.join("m.che")).unwrap();
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, vec![std::ffi::OsString::from("m.che")]);
    let _ = chf::BuildOptions::level(0);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A mapped mesh raised to a higher level (its new arrays in memory) and saved equals the
/// mesh built at that level; the file it came from stays as it was.
#[test]
fn a_mapped_mesh_is_raised_and_saved() {
    let dir = folder("raise");
    let s = torus(6, 5);
    let n = s.positions.len();
    let build = |level| {
        Che::from_triangles(&s.triangles, n, &s.positions, BuildOptions::level(level)).unwrap()
    };
    let low = dir.join("low.che");
    build(1).save(&low).unwrap();
    let before = std::fs::read(&low).unwrap();
    let mut che = Che::open(&low, OpenOptions::mapped(Verify::Trusted)).unwrap();
    assert!(che.is_mapped());
    che.build_level(3).unwrap();
    let fresh = build(3);
    assert_eq!(che_state(&che), che_state(&fresh));
    let high = dir.join("high.che");
    che.save(&high).unwrap();
    let back = Che::open(&high, OpenOptions::mapped(Verify::Full)).unwrap();
    assert_eq!(che_state(&back), che_state(&fresh));
    assert_eq!(che_answers(&back), che_answers(&fresh));
    assert_eq!(std::fs::read(&low).unwrap(), before);
    // Lowered and raised again: the same.
    che.build_level(0).unwrap();
    che.build_level(2).unwrap();
    assert_eq!(che_state(&che), che_state(&build(2)));

    let path = dir.join("m.chf");
    let mesh = chf_common::cube(2, 2, 2, true);
    mesh.build(1, true).save(&path).unwrap();
    let mut chf = Chf::open(&path, OpenOptions::mapped(Verify::Full)).unwrap();
    assert!(chf.is_mapped());
    chf.build_level(3).unwrap();
    assert_eq!(chf_state(&chf), chf_state(&mesh.build(3, true)));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Queries are `&self` on a mapped mesh as on a built one: threads share it.
#[test]
fn a_mapped_mesh_answers_from_many_threads() {
    let dir = folder("threads");
    let s = torus(24, 17);
    let n = s.positions.len();
    for level in [1, 2, 3] {
        let built =
            Che::from_triangles(&s.triangles, n, &s.positions, BuildOptions::level(level)).unwrap();
        let path = dir.join(format!("{level}.che"));
        built.save(&path).unwrap();
        let mapped = Che::open(&path, OpenOptions::mapped(Verify::Trusted)).unwrap();
        let expected = che_answers(&built);
        std::thread::scope(|scope| {
            let threads: Vec<_> = (0..6)
                .map(|_| scope.spawn(|| che_answers(&mapped)))
                .collect();
            for t in threads {
                assert_eq!(t.join().unwrap(), expected, "level {level}");
            }
        });
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A trusted mapped file whose ids point outside the structure opens (nothing checks the
/// ids), and its queries stay inside the mapping: an id out of range panics on a bounds
/// check (a status in C) rather than reading past an array.
#[test]
fn trusted_ids_out_of_range_never_read_outside() {
    let dir = folder("outside");
    let (path, good) = saved(&dir, "m.che");
    for name in ["V", "O", "VH", "EH", "CH", "curve_of"] {
        let at = entry(&good, name);
        let offset = le_u64(&good, at + 40) as usize;
        for bad in [1000u32, u32::MAX - 1] {
            let mut b = good.clone();
            b[offset..offset + 4].copy_from_slice(&bad.to_le_bytes());
            std::fs::write(&path, &b).unwrap();
            let che = Che::open(&path, OpenOptions::mapped(Verify::Trusted)).unwrap();
            let _ = std::panic::catch_unwind(|| che_answers(&che));
            let full = Che::open(&path, OpenOptions::mapped(Verify::Checksums));
            assert!(full.is_err(), "section {name}: the checksum catches it");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Edits on a mapped mesh copy the arrays they write into memory first: the same edits on
/// the mapped and the loaded copy of one file give the same structure, and the file
/// stays as it was.
#[test]
fn a_mapped_mesh_is_edited_in_memory() {
    let dir = folder("edit");
    let s = torus(6, 5);
    let n = s.positions.len();
    for level in 0..=3 {
        let path = dir.join(format!("t{level}.che"));
        Che::from_triangles(&s.triangles, n, &s.positions, BuildOptions::level(level))
            .unwrap()
            .save(&path)
            .unwrap();
        let before = std::fs::read(&path).unwrap();
        let open = |mode| {
            Che::open(
                &path,
                OpenOptions {
                    verify: Verify::Full,
                    mode,
                },
            )
            .unwrap()
        };
        let (mut mapped, mut loaded) = (open(Mode::Mapped), open(Mode::Loaded));
        for che in [&mut mapped, &mut loaded] {
            che.split_triangle(3, None).unwrap();
            che.flip_edge(0).unwrap();
            che.garbage_collect().unwrap();
        }
        assert_eq!(che_state(&mapped), che_state(&loaded), "level {level}");
        assert_eq!(che_answers(&mapped), che_answers(&loaded), "level {level}");
        assert_eq!(std::fs::read(&path).unwrap(), before);
    }
    let mesh = chf_common::cube(2, 2, 2, true);
    for level in 0..=3 {
        let path = dir.join(format!("c{level}.chf"));
        mesh.build(level, true).save(&path).unwrap();
        let open = |mode| {
            Chf::open(
                &path,
                OpenOptions {
                    verify: Verify::Full,
                    mode,
                },
            )
            .unwrap()
        };
        let (mut mapped, mut loaded) = (open(Mode::Mapped), open(Mode::Loaded));
        for chf in [&mut mapped, &mut loaded] {
            chf.split_tetrahedron(1, None).unwrap();
            chf.garbage_collect().unwrap();
        }
        assert_eq!(chf_state(&mapped), chf_state(&loaded), "level {level}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
