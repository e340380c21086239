//! Wavefront OBJ, parsed by the `tobj` crate (triangulated, positions only).
//!
//! tobj splits a file into models at every `o`, `g` (and `usemtl`) line and gives each model
//! its own copy of the vertices it uses, so merging its models would cut the surface apart
//! along group borders. Before handing the text to tobj, one pass over the bytes therefore
//! turns the keywords of the lines we do not want it to act on into comments, in place:
//! `o`, `g`, `usemtl`, `mtllib` (no material file is ever opened), `l` (tobj would read a
//! 3-point polyline as a triangle), `vt` and `vn` (we only need positions); and blanks the
//! colour of `v x y z r g b`. The same pass refuses faces of fewer than 3 vertices, with
//! their line. tobj then yields one model whose faces keep their connectivity; polygons are
//! fan-triangulated by tobj. Vertices are numbered in order of first use by a face and
//! vertices no face uses are dropped (tobj's numbering). Positions are `f32` in tobj.
//!
//! tobj's errors carry no line; we find the offending line again (an error path only) and
//! name it, with the file, in the message.

use super::MeshData;
use crate::error::{Error, Result};
use glam::DVec3;
use std::io::Cursor;
use std::path::Path;

/// Reads an OBJ file.
pub fn read(path: &Path) -> Result<MeshData> {
    let bytes = super::read_bytes(path)?;
    parse(bytes, &path.display().to_string())
}

/// Parses OBJ from memory (the buffer is edited in place, see the module notes); `name`
/// (usually the file name) prefixes every error.
pub(crate) fn parse(mut bytes: Vec<u8>, name: &str) -> Result<MeshData> {
    prepare(&mut bytes, name)?;
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: false,
        ignore_points: true,
        ignore_lines: true,
    };
    let (models, _materials) = tobj::load_obj_buf(&mut Cursor::new(&bytes[..]), &options, |_| {
        Err(tobj::LoadError::OpenFileFailed)
    })
    .map_err(|e| {
        let kind = if e == tobj::LoadError::FaceVertexOutOfBounds {
            crate::error::ErrorKind::OutOfRange
        } else {
            crate::error::ErrorKind::Parse
        };
        match locate(&bytes, &e) {
            Some(line) => Error::new(kind, format!("{name}:{line}: {e}")),
            None => Error::new(kind, format!("{name}: {e}")),
        }
    })?;

    let mut data = MeshData::default();
    for model in &models {
        let mesh = &model.mesh;
        let offset = data.positions.len();
        let count = mesh.positions.len() / 3;
        let base = u32::try_from(offset + count)
            .map(|_| offset as u32)
            .map_err(|_| Error::too_large(format!("{name}: more than {} vertices", u32::MAX)))?;
        data.positions.extend(
            mesh.positions
                .chunks_exact(3)
                .map(|p| DVec3::new(f64::from(p[0]), f64::from(p[1]), f64::from(p[2]))),
        );
        for t in mesh.indices.chunks_exact(3) {
            if t.iter().any(|&v| v as usize >= count) {
                return Err(Error::parse(format!(
                    "{name}: model '{}': tobj returned the index {t:?} beyond its {count} vertices",
                    model.name
                )));
            }
            data.triangles.push([t[0] + base, t[1] + base, t[2] + base]);
        }
    }
    if data.triangles.is_empty() {
        return Err(Error::parse(format!(
            "{name}: no faces ('f' lines): empty, not an OBJ file, or only points and lines"
        )));
    }
    Ok(data)
}

/// Byte ranges of the whitespace-separated words of `line`.
fn words(line: &[u8]) -> impl Iterator<Item = (usize, usize)> + '_ {
    let mut i = 0;
    std::iter::from_fn(move || {
        while i < line.len() && line[i].is_ascii_whitespace() {
            i += 1;
        }
        if i >= line.len() {
            return None;
        }
        let start = i;
        while i < line.len() && !line[i].is_ascii_whitespace() {
            i += 1;
        }
        Some((start, i))
    })
}

/// Lines of `bytes` with their 1-based numbers.
fn lines(bytes: &[u8]) -> impl Iterator<Item = (usize, &[u8])> {
    bytes
        .split(|&c| c == b'\n')
        .enumerate()
        .map(|(i, l)| (i + 1, l))
}

/// The in-place pass described in the module notes.
fn prepare(bytes: &mut [u8], name: &str) -> Result<()> {
    if bytes.starts_with(b"\xEF\xBB\xBF") {
        bytes[..3].fill(b' '); // UTF-8 byte order mark: tobj would not see the first keyword
    }
    let mut line_no = 0;
    for line in bytes.split_mut(|&c| c == b'\n') {
        line_no += 1;
        // The first word, the spans of the next (up to) 7 and the number of words after it.
        let (first, rest, n) = {
            let mut w = words(line);
            let Some(first) = w.next() else { continue };
            let mut rest = [(0, 0); 7];
            let mut n = 0;
            for span in w {
                if let Some(slot) = rest.get_mut(n) {
                    *slot = span;
                }
                n += 1;
            }
            (first, rest, n)
        };
        match &line[first.0..first.1] {
            b"o" | b"g" | b"usemtl" | b"mtllib" | b"l" | b"vt" | b"vn" => line[first.0] = b'#',
            b"f" if n < 3 => {
                return Err(Error::parse(format!(
                    "{name}:{line_no}: face has {n} vertices; a face needs at least 3"
                )));
            }
            // x y z r g b: keep the position only.
            b"v" if n == 6 => line[rest[3].0..rest[5].1].fill(b' '),
            _ => {}
        }
    }
    Ok(())
}

fn text(word: &[u8]) -> Option<&str> {
    std::str::from_utf8(word).ok()
}

/// Finds the line tobj's error `e` is about (after `prepare`), by checking lines the way
/// tobj does.
fn locate(bytes: &[u8], e: &tobj::LoadError) -> Option<usize> {
    use tobj::LoadError as L;
    if *e == L::ReadError {
        return lines(bytes)
            .find(|(_, l)| std::str::from_utf8(l).is_err())
            .map(|(n, _)| n);
    }
    let keyword = |l: &[u8]| words(l).next().map(|(s, e)| l[s..e].to_vec());
    let total_v = lines(bytes)
        .filter(|(_, l)| keyword(l).as_deref() == Some(b"v"))
        .count();
    let mut nv = 0usize;
    for (n, line) in lines(bytes) {
        let mut w = words(line).map(|(s, e)| &line[s..e]);
        match w.next() {
            Some(b"v") => {
                nv += 1;
                let floats: Vec<&[u8]> = w.collect();
                let parses = |t: &[u8]| text(t).and_then(|t| t.parse::<f32>().ok());
                let found = match floats.len() {
                    0..=2 => L::PositionParseError,
                    _ if floats[..3].iter().any(|t| parses(t).is_none()) => L::PositionParseError,
                    3 => continue,
                    4 => match parses(floats[3]) {
                        None => L::PositionParseError,
                        Some(0.0) => L::ScalingByZeroError,
                        Some(_) => continue,
                    },
                    _ => L::ColorParseError,
                };
                if found == *e {
                    return Some(n);
                }
            }
            Some(b"f") => {
                for corner in w {
                    let parts: Vec<&[u8]> = corner.split(|&c| c == b'/').collect();
                    let ints: Vec<Option<isize>> = parts
                        .iter()
                        .map(|p| text(p).and_then(|t| t.parse::<isize>().ok()))
                        .collect();
                    let bad_syntax = parts.len() > 3
                        || parts
                            .iter()
                            .zip(&ints)
                            .any(|(p, i)| !p.is_empty() && i.is_none());
                    let found = if bad_syntax {
                        L::FaceParseError
                    } else {
                        let v = match ints[0] {
                            Some(x) if x < 0 => nv.checked_sub(x.unsigned_abs()),
                            Some(x) if x > 0 => Some(x as usize - 1),
                            _ => None,
                        };
                        if v.is_some_and(|v| v < total_v) {
                            continue;
                        }
                        L::FaceVertexOutOfBounds
                    };
                    if found == *e {
                        return Some(n);
                    }
                }
            }
            _ => {}
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::ErrorKind;

    fn p(s: &str) -> Result<MeshData> {
        parse(s.as_bytes().to_vec(), "t.obj")
    }

    fn err(s: &str) -> Error {
        match p(s) {
            Ok(m) => panic!("expected an error, got {m:?}"),
            Err(e) => e,
        }
    }

    /// A unit cube as 6 quads, each face in its own group with its own material.
    const CUBE: &str = "# cube\nmtllib cube.mtl\no cube\n\
        v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n\
        vt 0 0\nvn 0 0 1\n\
        g bottom\nusemtl a\nf 1 3 4 2\ng top\nusemtl b\nf 5/1 6/1 8/1 7/1\n\
        g front\nf 1//1 2//1 6//1 5//1\ng back\nf 3 7 8 4\n\
        g left\nf 1 5 7 3\ng right\ns 1\nf 2/1/1 4/1/1 8/1/1 6/1/1\nl 1 2 3\n";

    #[test]
    fn cube_groups_stay_connected() {
        let m = p(CUBE).unwrap();
        assert_eq!(m.triangles.len(), 12);
        // One shared vertex per corner: the groups were not cut apart.
        assert_eq!(m.positions.len(), 8);
        // Every edge of a closed surface is used exactly twice.
        let mut edges = std::collections::HashMap::new();
        for t in &m.triangles {
            for i in 0..3 {
                let (a, b) = (t[i], t[(i + 1) % 3]);
                *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
            }
        }
        assert_eq!(edges.len(), 18);
        assert!(edges.values().all(|&n| n == 2));
        // First face, fan-triangulated: (1,3,4), (1,4,2) in file numbering.
        let pos = |v: u32| m.positions[v as usize];
        let t0 = m.triangles[0].map(pos);
        let t1 = m.triangles[1].map(pos);
        assert_eq!(
            t0,
            [
                DVec3::ZERO,
                DVec3::new(0.0, 1.0, 0.0),
                DVec3::new(1.0, 1.0, 0.0)
            ]
        );
        assert_eq!(
            t1,
            [
                DVec3::ZERO,
                DVec3::new(1.0, 1.0, 0.0),
                DVec3::new(1.0, 0.0, 0.0)
            ]
        );
    }

    #[test]
    fn pentagon_is_fanned_and_relative_indices_work() {
        let m =
            p("\u{feff}v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf -5 -4 -3 -2 -1\n").unwrap();
        assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 3], [0, 3, 4]]);
        assert_eq!(m.positions[4], DVec3::new(0.0, 1.0, 0.0));
    }

    #[test]
    fn vertex_colours_and_w_are_handled() {
        // Colours on some vertices only: tobj alone would fail on the mismatched colour list.
        let m = p("v 0 0 0 1 0 0\nv 2 0 0 2\nv 0 1 0\nf 1 2 3\n").unwrap();
        assert_eq!(m.positions[1], DVec3::new(1.0, 0.0, 0.0));
        assert_eq!(m.positions[2], DVec3::new(0.0, 1.0, 0.0));
    }

    #[test]
    fn nan_coordinates_are_accepted() {
        let m = p("v nan 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
        assert!(m.positions[0].x.is_nan());
        assert!(m.positions[1].x.is_infinite());
    }

    #[test]
    fn out_of_range_index_names_the_line() {
        let e = err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\nf 1 3 4\n");
        assert_eq!(e.kind, ErrorKind::OutOfRange);
        assert!(e.message.starts_with("t.obj:6: "), "{}", e.message);
        assert!(e.message.contains("out of bounds"), "{}", e.message);
        let e = err("v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n");
        assert!(e.message.starts_with("t.obj:3: "), "{}", e.message);
        let e = err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
        assert!(e.message.starts_with("t.obj:4: "), "{}", e.message);
    }

    #[test]
    fn bad_tokens_name_the_line() {
        let e = err("v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n");
        assert_eq!(e.kind, ErrorKind::Parse);
        assert!(
            e.message.starts_with("t.obj:2: position parse error"),
            "{}",
            e.message
        );
        let e = err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2/x 3\n");
        assert!(
            e.message.starts_with("t.obj:5: face parse error"),
            "{}",
            e.message
        );
        let e = err("v 0 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assert!(e.message.starts_with("t.obj:1: scaling"), "{}", e.message);
    }

    #[test]
    fn invalid_utf8_names_the_line() {
        let mut b = b"v 0 0 0\nv 1 0 0\nv 0 1 0\n# caf".to_vec();
        b.extend([0xe9, b'\n']);
        b.extend(b"f 1 2 3\n");
        let e = parse(b, "t.obj").unwrap_err();
        assert!(
            e.message.starts_with("t.obj:4: read error"),
            "{}",
            e.message
        );
    }

    #[test]
    fn small_faces_are_errors() {
        let e = err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n");
        assert!(
            e.message.starts_with("t.obj:5: face has 2 vertices"),
            "{}",
            e.message
        );
        let e = err("v 0 0 0\nf\n");
        assert!(
            e.message.starts_with("t.obj:2: face has 0 vertices"),
            "{}",
            e.message
        );
    }

    #[test]
    fn truncated_garbage_and_empty_files_are_errors() {
        // Cut inside a vertex.
        let e = err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nv 1 1");
        assert!(
            e.message.starts_with("t.obj:5: position parse error"),
            "{}",
            e.message
        );
        let e = err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2");
        assert!(
            e.message.starts_with("t.obj:4: face has 2"),
            "{}",
            e.message
        );
        let e = err("");
        assert!(e.message.starts_with("t.obj: no faces"), "{}", e.message);
        let e = err("hello\nworld\n");
        assert!(e.message.contains("no faces"), "{}", e.message);
        let e = err("v 0 0 0\nl 1 1 1\n");
        assert!(e.message.contains("no faces"), "{}", e.message);
    }

    #[test]
    fn reads_a_file_and_names_it() {
        let path = std::env::temp_dir().join(format!("topomesh-obj-{}.obj", std::process::id()));
        std::fs::write(&path, CUBE).unwrap();
        let m = read(&path);
        let _ = std::fs::remove_file(&path);
        assert_eq!(m.unwrap().triangles.len(), 12);
        let e = read(Path::new("/nonexistent/y.obj")).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Io);
        assert!(e.message.contains("/nonexistent/y.obj"), "{}", e.message);
    }
}
