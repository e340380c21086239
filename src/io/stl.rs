//! STL, ASCII and binary: our own reader, and our own vertex welding.
//!
//! STL stores every triangle with its own three corners, so shared vertices have to be
//! recovered: corners whose `f32` coordinates are bitwise equal, with `-0.0` read as `0.0`,
//! become one vertex. That is a (radix) sort of the corners by their bits and a scan of the
//! runs, no hashing; vertices are numbered in order of first occurrence, so the output is
//! deterministic. NaN coordinates weld by their bits (no panic) and are reported, as in
//! every format, by `io::read`.
//!
//! ASCII or binary is decided by the size first: a file of exactly `84 + 50 n` bytes whose
//! header declares `n` triangles is binary even if it starts with `solid` (several
//! exporters write such headers). Otherwise a file starting with `solid` and holding no NUL
//! byte in its first 512 bytes is ASCII. An ASCII file may hold several `solid ... endsolid`
//! blocks: all are read, their triangles in one mesh, and a warning says how many there
//! were. ASCII errors name the line and the facet; binary ones the byte offset and the
//! triangle.

use super::MeshData;
use super::text::{Lexer, quote};
use super::warning::{Warning, count};
use crate::error::{Error, Result};
use crate::util::alloc::{try_collect, try_push, try_vec, try_with_capacity};
use glam::DVec3;

const HEADER: usize = 84;
const RECORD: usize = 50;

/// Parses STL from memory; `name` (usually the file name) prefixes every error.
pub(crate) fn parse(bytes: &[u8], name: &str) -> Result<MeshData> {
    if bytes.is_empty() {
        return Err(Error::parse(format!("{name}: empty file")));
    }
    let declared = (bytes.len() >= HEADER)
        .then(|| u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize);
    let exact_binary =
        declared.is_some_and(|n| n.checked_mul(RECORD) == Some(bytes.len() - HEADER));
    let ascii =
        !exact_binary && bytes.starts_with(b"solid") && !bytes[..bytes.len().min(512)].contains(&0);
    if ascii {
        let text = super::text::lossy(bytes)?;
        let (corners, warnings) = read_ascii(&text, name)?;
        let mut data = weld(corners)?;
        data.warnings = warnings;
        return Ok(data);
    }
    let Some(n) = declared else {
        return Err(Error::parse(format!(
            "{name}: not an STL file: too short for binary STL ({} bytes, the header alone \
             is {HEADER}) and not ASCII STL (which starts with 'solid')",
            bytes.len()
        )));
    };
    let need = n.saturating_mul(RECORD).saturating_add(HEADER);
    if bytes.len() < need {
        return Err(Error::parse(format!(
            "{name}: truncated binary STL: the header declares {n} triangles ({need} bytes), \
             the file has {} bytes (triangle {} is incomplete)",
            bytes.len(),
            (bytes.len() - HEADER) / RECORD
        )));
    }
    let mut data = weld(read_binary(bytes, n, name)?)?;
    if bytes.len() > need {
        let msg = format!(
            "{} after the {n} declared triangles, from byte {need} (ignored)",
            count((bytes.len() - need) as u64, ("byte", "bytes"))
        );
        data.warnings.push(Warning::new(name, None, msg));
    }
    Ok(data)
}

/// The corner keys of `n` binary records (the size already checked): a normal, three
/// corners of 3 little-endian `f32`s, and 2 attribute bytes each.
fn read_binary(bytes: &[u8], n: usize, name: &str) -> Result<Vec<u128>> {
    check_corner_count(n, name, None)?;
    let mut corners = try_with_capacity(3 * n, "the corners")?;
    for record in bytes[HEADER..HEADER + n * RECORD].chunks_exact(RECORD) {
        for corner in record[12..48].chunks_exact(12) {
            let f = |i: usize| {
                f32::from_le_bytes([corner[i], corner[i + 1], corner[i + 2], corner[i + 3]])
            };
            corners.push(corner_key([f(0), f(4), f(8)], corners.len()));
        }
    }
    Ok(corners)
}

/// Corner ids must fit in 32 bits.
fn check_corner_count(triangles: usize, name: &str, line: Option<usize>) -> Result<()> {
    if triangles.saturating_mul(3) > (u32::MAX - 3) as usize {
        let place = line.map_or(String::new(), |l| format!(":{l}"));
        return Err(Error::too_large(format!(
            "{name}{place}: more than {triangles} triangles; corner ids must fit in 32 bits"
        )));
    }
    Ok(())
}

/// Reads every `solid ... endsolid` block of an ASCII STL: the corner keys, and the
/// warnings (how many solids, text after the last one).
fn read_ascii(text: &str, name: &str) -> Result<(Vec<u128>, Vec<Warning>)> {
    let mut lx = Lexer::new(text, name, false);
    // A facet takes well over 100 bytes.
    let mut corners = try_with_capacity(3 * (text.len() / 100), "the corners")?;
    let mut warnings = Vec::new();
    let mut solids = 0u64;
    let mut second_line = None;
    while let Some(tok) = lx.next() {
        if !tok.eq_ignore_ascii_case("solid") {
            let msg = format!(
                "text after the last 'endsolid', from '{}' (ignored)",
                quote(tok)
            );
            warnings.push(Warning::new(name, Some(lx.line()), msg));
            break;
        }
        solids += 1;
        if solids == 2 {
            second_line = Some(lx.line());
        }
        lx.next_line(); // the solid's name
        read_solid(&mut lx, &mut corners)?;
    }
    if solids > 1 {
        let msg = format!(
            "{} ('solid ... endsolid' blocks) read into one mesh",
            count(solids, ("solid", "solids"))
        );
        warnings.insert(0, Warning::new(name, second_line, msg));
    }
    Ok((corners, warnings))
}

/// Reads the facets of one solid up to its `endsolid` line.
fn read_solid(lx: &mut Lexer, corners: &mut Vec<u128>) -> Result<()> {
    loop {
        let tok = lx.expect("'facet' or 'endsolid'")?;
        if tok.eq_ignore_ascii_case("endsolid") {
            lx.next_line(); // the solid's name
            return Ok(());
        }
        if !tok.eq_ignore_ascii_case("facet") {
            return Err(lx.bad("'facet' or 'endsolid'", tok));
        }
        let facet = corners.len() / 3;
        check_corner_count(facet + 1, lx.name(), Some(lx.line()))?;
        read_facet(lx, corners).map_err(|e| in_facet(lx, e, facet))?;
    }
}

/// Reads a facet after its `facet` keyword: the normal (ignored) and the three corners.
fn read_facet(lx: &mut Lexer, corners: &mut Vec<u128>) -> Result<()> {
    lx.keyword("normal")?;
    for _ in 0..3 {
        f32_token(lx, "a normal coordinate")?;
    }
    lx.keyword("outer")?;
    lx.keyword("loop")?;
    for _ in 0..3 {
        lx.keyword("vertex")?;
        let mut p = [0.0f32; 3];
        for c in &mut p {
            *c = f32_token(lx, "a coordinate")?;
        }
        try_push(corners, corner_key(p, corners.len()), "the corners")?;
    }
    lx.keyword("endloop")?;
    lx.keyword("endfacet")
}

/// A coordinate as STL stores it: an `f32`, parsed directly (no rounding through `f64`).
fn f32_token(lx: &mut Lexer, what: &str) -> Result<f32> {
    let t = lx.expect(what)?;
    t.parse().map_err(|_| lx.bad(what, t))
}

/// `file:line: msg` becomes `file:line: facet {facet}: msg`.
fn in_facet(lx: &Lexer, e: Error, facet: usize) -> Error {
    let prefix = format!("{}:{}: ", lx.name(), lx.line());
    match e.message.strip_prefix(&prefix) {
        Some(msg) => Error::new(e.kind, format!("{prefix}facet {facet}: {msg}")),
        None => e,
    }
}

/// A corner as one sortable number: the bits of x, y, z (-0.0 as 0.0), then the corner's
/// index, which makes every key distinct and orders equal positions by first occurrence.
fn corner_key([x, y, z]: [f32; 3], index: usize) -> u128 {
    let bits = |x: f32| u128::from(if x == 0.0 { 0 } else { x.to_bits() });
    bits(x) << 96 | bits(y) << 64 | bits(z) << 32 | index as u128
}

/// Merges the corners (keys in corner order, fewer than `u32::MAX`) with equal positions
/// into vertices numbered by first occurrence; every 3 corners make a triangle.
fn weld(mut keys: Vec<u128>) -> Result<MeshData> {
    let n = keys.len();
    sort_by_position(&mut keys)?;
    // Runs of equal positions, in sorted order: run_of[corner], and each run's position.
    let mut run_of = try_vec(n, 0u32, "the corners' vertices")?;
    let mut run_pos: Vec<u128> = Vec::new();
    for (j, &k) in keys.iter().enumerate() {
        if j == 0 || k >> 32 != keys[j - 1] >> 32 {
            try_push(&mut run_pos, k >> 32, "the distinct positions")?;
        }
        run_of[k as u32 as usize] = (run_pos.len() - 1) as u32;
    }
    drop(keys);
    // Number the runs in order of their first corner; a corner becomes its run's vertex.
    let mut id_of_run = try_vec(run_pos.len(), u32::MAX, "the vertex ids")?;
    let mut positions = try_with_capacity(run_pos.len(), "the vertices")?;
    for r in run_of.iter_mut() {
        let id = &mut id_of_run[*r as usize];
        if *id == u32::MAX {
            *id = positions.len() as u32;
            let p = run_pos[*r as usize];
            let f = |shift: u32| f64::from(f32::from_bits((p >> shift) as u32));
            positions.push(DVec3::new(f(64), f(32), f(0)));
        }
        *r = *id;
    }
    let triangles = run_of.chunks_exact(3).map(|t| [t[0], t[1], t[2]]);
    Ok(MeshData {
        positions,
        triangles: try_collect(triangles, "the triangles")?,
        ..MeshData::default()
    })
}

/// Stable LSD radix sort of `keys` on their bits 32..128 (the position), 16 bits a pass.
/// The low 32 bits (the corner index) increase along the input, so stability leaves the
/// keys ordered by position, then index. A pass whose digit is the same for all keys (a
/// flat or axis-aligned part of the data) is skipped.
fn sort_by_position(keys: &mut Vec<u128>) -> Result<()> {
    const PASSES: usize = 6;
    const RADIX: usize = 1 << 16;
    let digit = |k: u128, pass: usize| (k >> (32 + 16 * pass)) as usize & (RADIX - 1);
    let mut hist = try_vec(PASSES * RADIX, 0usize, "the sort's histograms")?;
    for &k in keys.iter() {
        for pass in 0..PASSES {
            hist[pass * RADIX + digit(k, pass)] += 1;
        }
    }
    let mut tmp = try_vec(keys.len(), 0u128, "the sorted corners")?;
    for (pass, h) in hist.chunks_exact_mut(RADIX).enumerate() {
        if h.contains(&keys.len()) {
            continue;
        }
        let mut sum = 0;
        for c in h.iter_mut() {
            (*c, sum) = (sum, sum + *c);
        }
        for &k in keys.iter() {
            let slot = &mut h[digit(k, pass)];
            tmp[*slot] = k;
            *slot += 1;
        }
        std::mem::swap(keys, &mut tmp);
    }
    Ok(())
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::error::ErrorKind;

    /// A unit cube as 12 triangles, each with its own corners, as in an STL file.
    pub(in crate::io) fn cube() -> Vec<[[f32; 3]; 3]> {
        let c = |i: usize| [(i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32];
        let quads = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        quads
            .iter()
            .flat_map(|q| [[c(q[0]), c(q[1]), c(q[2])], [c(q[0]), c(q[2]), c(q[3])]])
            .collect()
    }

    pub(in crate::io) fn ascii(tris: &[[[f32; 3]; 3]]) -> String {
        let mut s = String::from("solid cube\n");
        for t in tris {
            s += "  facet normal 0 0 0\n    outer loop\n";
            for v in t {
                s += &format!("      vertex {} {} {}\n", v[0], v[1], v[2]);
            }
            s += "    endloop\n  endfacet\n";
        }
        s + "endsolid cube\n"
    }

    fn binary(header: &[u8], tris: &[[[f32; 3]; 3]]) -> Vec<u8> {
        let mut b = header.to_vec();
        b.resize(80, b' ');
        b.extend((tris.len() as u32).to_le_bytes());
        for t in tris {
            b.extend([0u8; 12]);
            for x in t.iter().flatten() {
                b.extend(x.to_le_bytes());
            }
            b.extend([0u8; 2]);
        }
        b
    }

    fn temp(tag: &str, bytes: &[u8]) -> std::path::PathBuf {
        let path =
            std::env::temp_dir().join(format!("topomesh-stl-{}-{tag}.stl", std::process::id()));
        std::fs::write(&path, bytes).unwrap();
        path
    }

    /// Checks the welded mesh has the same triangles, corner by corner, as `tris`.
    fn check_same(m: &MeshData, tris: &[[[f32; 3]; 3]]) {
        assert_eq!(m.triangles.len(), tris.len());
        for (t, want) in m.triangles.iter().zip(tris) {
            for (&v, w) in t.iter().zip(want) {
                let p = m.positions[v as usize];
                assert_eq!([p.x as f32, p.y as f32, p.z as f32], *w);
            }
        }
    }

    #[test]
    fn ascii_cube_welds_to_8_vertices() {
        let tris = cube();
        let m = parse(ascii(&tris).as_bytes(), "c.stl").unwrap();
        assert_eq!(m.positions.len(), 8);
        check_same(&m, &tris);
        // First-occurrence order: the first triangle's corners are vertices 0, 1, 2.
        assert_eq!(m.triangles[0], [0, 1, 2]);
        assert_eq!(m.triangles[1], [0, 2, 3]);
    }

    #[test]
    fn binary_cube_file_welds_to_8_vertices() {
        let tris = cube();
        let path = temp("bin", &binary(b"binary cube", &tris));
        let m = crate::io::read(&path);
        let _ = std::fs::remove_file(&path);
        let m = m.unwrap();
        assert_eq!(m.positions.len(), 8);
        check_same(&m, &tris);
    }

    #[test]
    fn binary_starting_with_solid_is_read_as_binary() {
        let tris = cube();
        let m = parse(&binary(b"solid but binary", &tris), "c.stl").unwrap();
        assert_eq!(m.positions.len(), 8);
        check_same(&m, &tris);
    }

    #[test]
    fn ascii_with_bare_solid_line_and_crlf() {
        let text = ascii(&cube())
            .replace("solid cube\n", "solid\n")
            .replace('\n', "\r\n");
        let m = parse(text.as_bytes(), "c.stl").unwrap();
        assert_eq!(m.positions.len(), 8);
        assert_eq!(m.triangles.len(), 12);
    }

    #[test]
    fn negative_zero_welds_with_zero_but_nothing_else_does() {
        let mut tris = cube();
        tris[3][0] = tris[3][0].map(|x| if x == 0.0 { -0.0 } else { x });
        // 1 + 1e-7 is a different f32 from 1: a new vertex, not welded.
        tris[5][1] = [1.0 + 1e-7, 1.0, 1.0];
        let m = parse(&binary(b"x", &tris), "c.stl").unwrap();
        assert_eq!(m.positions.len(), 9);
        assert_eq!(m.triangles[3][0], m.triangles[2][0]);
        assert_eq!(
            m.positions[8],
            DVec3::new(f64::from(1.0f32 + 1e-7), 1.0, 1.0)
        );
    }

    #[test]
    fn nan_coordinates_do_not_panic() {
        let mut tris = cube();
        tris[0][0] = [f32::NAN, 0.0, 0.0];
        tris[1][0] = [f32::NAN, 0.0, 0.0];
        tris[2][2] = [f32::INFINITY, 0.0, 0.0];
        let m = parse(&binary(b"x", &tris), "c.stl").unwrap();
        assert_eq!(m.triangles.len(), 12);
        assert_eq!(m.triangles[0][0], m.triangles[1][0]);
        assert!(m.positions[m.triangles[0][0] as usize].x.is_nan());
    }

    #[test]
    fn weld_matches_a_naive_reference() {
        // Corners drawn from a small pool (so there are many repeats), with values that
        // differ in every 16-bit digit, -0.0, NaN and infinities.
        let pool = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            1.5,
            1e-30,
            3e30,
            0.1,
            65536.0,
            1.0 + 1e-7,
            f32::NAN,
            f32::INFINITY,
        ];
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            pool[(seed >> 33) as usize % pool.len()]
        };
        let corners: Vec<[f32; 3]> = (0..3000).map(|_| [next(), next(), next()]).collect();
        let keys = corners
            .iter()
            .enumerate()
            .map(|(i, &c)| corner_key(c, i))
            .collect();
        let m = weld(keys).unwrap();

        let canon = |c: [f32; 3]| c.map(|x| if x == 0.0 { 0 } else { x.to_bits() });
        let mut ids = std::collections::HashMap::new();
        let mut want_positions = Vec::new();
        let want: Vec<u32> = corners
            .iter()
            .map(|&c| {
                *ids.entry(canon(c)).or_insert_with(|| {
                    want_positions.push(canon(c));
                    want_positions.len() as u32 - 1
                })
            })
            .collect();
        assert_eq!(m.triangles.concat(), want);
        let got: Vec<[u32; 3]> = m
            .positions
            .iter()
            .map(|p| canon([p.x as f32, p.y as f32, p.z as f32]))
            .collect();
        assert_eq!(got, want_positions);
        assert!(m.positions.len() > 100 && m.positions.len() < 3000);
    }

    #[test]
    fn empty_solid_is_an_empty_mesh() {
        let m = parse(b"solid empty\nendsolid empty\n", "e.stl").unwrap();
        assert!(m.positions.is_empty() && m.triangles.is_empty());
        let m = parse(&binary(b"x", &[]), "e.stl").unwrap();
        assert!(m.triangles.is_empty());
    }

    #[test]
    fn truncated_binary_is_an_error() {
        let mut b = binary(b"x", &cube());
        b.truncate(b.len() - 10);
        let e = parse(&b, "t.stl").unwrap_err();
        assert_eq!(e.kind, ErrorKind::Parse);
        assert!(
            e.message.starts_with("t.stl: truncated binary STL"),
            "{}",
            e.message
        );
        assert!(e.message.contains("triangle 11"), "{}", e.message);
        // A huge declared count is checked against the size, not allocated.
        let mut b = binary(b"x", &cube());
        b[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
        let e = parse(&b, "t.stl").unwrap_err();
        assert!(e.message.contains("4294967295 triangles"), "{}", e.message);
    }

    #[test]
    fn truncated_ascii_is_an_error_with_line_and_facet() {
        let text = ascii(&cube());
        let cut = &text[..text.find("endloop").unwrap() + 100];
        let e = parse(cut.as_bytes(), "t.stl").unwrap_err();
        assert_eq!(e.kind, ErrorKind::Parse);
        // The cut falls in facet 1, in the first letter of its third corner on line 13.
        assert_eq!(e.message, "t.stl:13: facet 1: expected vertex, found 'v'");
        let e = parse(b"solid x\nfacet normal 0 0\n", "g.stl").unwrap_err();
        assert_eq!(
            e.message,
            "g.stl:3: facet 0: unexpected end of file, expected a normal coordinate"
        );
        let e = parse(
            ascii(&cube())
                .trim_end()
                .trim_end_matches("endsolid cube")
                .as_bytes(),
            "t.stl",
        );
        assert_eq!(
            e.unwrap_err().message,
            "t.stl:86: unexpected end of file, expected 'facet' or 'endsolid'"
        );
    }

    #[test]
    fn bad_ascii_token_is_an_error_with_line_and_facet() {
        let cases = [
            (
                "vertex 1 1 0",
                "vertex 1 x 0",
                "t.stl:6: facet 0: expected a coordinate, found 'x'",
            ),
            (
                "outer loop",
                "outer",
                "t.stl:4: facet 0: expected loop, found 'vertex'",
            ),
            (
                "  facet normal",
                "  facet normals",
                "t.stl:2: facet 0: expected normal, found 'normals'",
            ),
            (
                "  facet normal",
                "  facets normal",
                "t.stl:2: expected 'facet' or 'endsolid', found 'facets'",
            ),
        ];
        for (from, to, want) in cases {
            let text = ascii(&cube()).replacen(from, to, 1);
            let e = parse(text.as_bytes(), "t.stl").unwrap_err();
            assert_eq!((e.kind, e.message.as_str()), (ErrorKind::Parse, want));
        }
    }

    #[test]
    fn every_solid_is_read_and_counted() {
        let tris = cube();
        let text = ascii(&tris[..4]) + &ascii(&tris[4..10]) + "\n" + &ascii(&tris[10..]);
        let m = parse(text.as_bytes(), "s.stl").unwrap();
        check_same(&m, &tris);
        assert_eq!(m.positions.len(), 8);
        let warnings: Vec<String> = m.warnings.iter().map(|w| w.to_string()).collect();
        // The second solid starts after the first's 4 facets of 7 lines and its 2 lines.
        assert_eq!(
            warnings,
            ["s.stl:31: 3 solids ('solid ... endsolid' blocks) read into one mesh"]
        );
        let one = parse(ascii(&tris).as_bytes(), "s.stl").unwrap();
        assert!(one.warnings.is_empty(), "{:?}", one.warnings);
    }

    #[test]
    fn trailing_text_and_bytes_are_reported() {
        let text = ascii(&cube()) + "\n  garbage here\n";
        let m = parse(text.as_bytes(), "s.stl").unwrap();
        assert_eq!(m.triangles.len(), 12);
        assert_eq!(
            m.warnings[0].to_string(),
            "s.stl:88: text after the last 'endsolid', from 'garbage' (ignored)"
        );
        let mut b = binary(b"x", &cube());
        let size = b.len();
        // Not a multiple of the record size more: read as binary with its declared count.
        b.extend([1, 2, 3]);
        let m = parse(&b, "b.stl").unwrap();
        assert_eq!(m.triangles.len(), 12);
        assert_eq!(
            m.warnings[0].to_string(),
            format!("b.stl: 3 bytes after the 12 declared triangles, from byte {size} (ignored)")
        );
    }

    #[test]
    fn non_finite_ascii_coordinates_are_read_and_reported() {
        let text = ascii(&cube())
            .replacen("vertex 1 1 0", "vertex 1 nan 0", 1)
            .replacen("vertex 0 0 0", "vertex -inf 0 0", 1);
        let m = crate::io::parse(text.as_bytes(), crate::io::Format::Stl, "n.stl").unwrap();
        assert_eq!(m.triangles.len(), 12);
        assert_eq!(m.positions[0].x, f64::NEG_INFINITY);
        assert!(m.positions[2].y.is_nan());
        assert_eq!(
            m.warnings[0].to_string(),
            "n.stl: 2 vertices have a NaN or infinite coordinate (0-based ids 0, 2); \
             geometric checks skip them"
        );
    }

    #[test]
    fn garbage_and_empty_files_are_errors() {
        let e = parse(b"", "g.stl").unwrap_err();
        assert!(e.message.contains("empty file"), "{}", e.message);
        let e = parse(b"hello world", "g.stl").unwrap_err();
        assert!(e.message.contains("not an STL file"), "{}", e.message);
        // 100 bytes of noise: a binary header declaring far more than is there.
        let noise: Vec<u8> = (0..100u32).map(|i| (i * 37 % 251) as u8).collect();
        let e = parse(&noise, "g.stl").unwrap_err();
        assert!(e.message.contains("truncated binary STL"), "{}", e.message);
    }
}
