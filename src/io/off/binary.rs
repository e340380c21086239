//! `OFF BINARY` (Geomview's binary variant): after the keyword line, big-endian 32-bit
//! integers and IEEE floats: the counts `nv nf ne`, each vertex's `x y z` (then its normal,
//! colour and texture coordinates when the keyword has the `N`, `C`, `ST` prefixes), and each
//! face as `k i1 .. ik`, then its number of colour components and those components.
//! Errors name the byte offset of what failed.

use super::{FANNED, Header, Prefixes, check_vertex_count};
use crate::error::{Error, Result};
use crate::io::MeshData;
use crate::io::text::room;
use crate::io::warning::{Tally, Warning, count};
use crate::util::alloc::{try_push, try_with_capacity};
use glam::DVec3;

/// The binary payload, read from `pos`.
pub(super) struct Binary<'a> {
    pub(super) b: &'a [u8],
    pub(super) pos: usize,
    pub(super) name: &'a str,
}

impl Binary<'_> {
    fn err(&self, at: usize, msg: &str) -> Error {
        Error::parse(format!("{}: at byte {at}: {msg}", self.name))
    }

    /// The next 4 bytes, or an end-of-file error naming `what`.
    fn word(&mut self, what: &dyn Fn() -> String) -> Result<[u8; 4]> {
        let at = self.pos;
        let bytes = self.b.get(at..at + 4).ok_or_else(|| {
            self.err(
                at,
                &format!("unexpected end of file (truncated?): expected {}", what()),
            )
        })?;
        self.pos += 4;
        Ok([bytes[0], bytes[1], bytes[2], bytes[3]])
    }

    fn int(&mut self, what: &dyn Fn() -> String) -> Result<i32> {
        self.word(what).map(i32::from_be_bytes)
    }

    /// A count: a non-negative int.
    fn count(&mut self, what: &dyn Fn() -> String) -> Result<u64> {
        let at = self.pos;
        let n = self.int(what)?;
        u64::try_from(n).map_err(|_| self.err(at, &format!("{} is {n}, negative", what())))
    }

    fn float(&mut self, what: &dyn Fn() -> String) -> Result<f32> {
        self.word(what).map(f32::from_be_bytes)
    }

    fn left(&self) -> usize {
        self.b.len().saturating_sub(self.pos)
    }

    /// Moves past `n` words, or errors naming `what` at the end of the input.
    fn skip(&mut self, n: usize, what: &dyn Fn() -> String) -> Result<()> {
        if n.saturating_mul(4) > self.left() {
            let msg = format!("unexpected end of file (truncated?): expected {}", what());
            return Err(self.err(self.b.len(), &msg));
        }
        self.pos += 4 * n;
        Ok(())
    }
}

/// Reads the counts, vertices and faces of a binary OFF into `data`.
pub(super) fn read(bin: &mut Binary, header: &Header, data: &mut MeshData) -> Result<()> {
    let nv = bin.count(&|| "the number of vertices".into())?;
    check_vertex_count(nv, bin.name, None)?;
    let nf = bin.count(&|| "the number of faces".into())?;
    bin.count(&|| "the number of edges".into())?;
    data.positions = vertices(bin, nv, header.prefixes)?;
    let mut polygons = Tally::default();
    data.triangles = faces(bin, nv as u32, nf, &mut polygons)?;
    polygons.into_warnings(bin.name, &mut data.warnings);
    if bin.left() > 0 {
        let msg = format!(
            "{} after the {nf} declared faces, from byte {} (ignored)",
            count(bin.left() as u64, ("byte", "bytes")),
            bin.pos
        );
        data.warnings.push(Warning::new(bin.name, None, msg));
    }
    Ok(())
}

fn vertices(bin: &mut Binary, nv: u64, prefixes: Prefixes) -> Result<Vec<DVec3>> {
    let extra = prefixes.binary_extra();
    let room = room(nv, bin.left(), 4 * (3 + extra));
    let mut positions = try_with_capacity(room, "the vertices")?;
    for i in 0..nv {
        let mut p = [0.0; 3];
        for (c, axis) in p.iter_mut().zip(["x", "y", "z"]) {
            *c = f64::from(bin.float(&|| format!("coordinate {axis} of vertex {i}"))?);
        }
        try_push(&mut positions, DVec3::from_array(p), "the vertices")?;
        bin.skip(extra, &|| {
            format!("the normal, colour or texture of vertex {i}")
        })?;
    }
    Ok(positions)
}

fn faces(bin: &mut Binary, nv: u32, nf: u64, polygons: &mut Tally) -> Result<Vec<[u32; 3]>> {
    // A triangle takes at least 5 words: its count, 3 ids, its number of colours.
    let mut triangles = try_with_capacity(room(nf, bin.left(), 20), "the triangles")?;
    for f in 0..nf {
        let at = bin.pos;
        let k = bin.count(&|| format!("the vertex count of face {f}"))?;
        if k < 3 {
            let msg = format!("face {f} has {k} vertices; a face needs at least 3");
            return Err(bin.err(at, &msg));
        }
        if k > 3 {
            polygons.add(FANNED, None);
        }
        let mut index = || -> Result<u32> {
            let at = bin.pos;
            let v = bin.int(&|| format!("a vertex index of face {f}"))?;
            u32::try_from(v).ok().filter(|&v| v < nv).ok_or_else(|| {
                Error::out_of_range(format!(
                    "{}: at byte {at}: face {f}: vertex index {v} is out of range (the file has \
                     {nv} vertices)",
                    bin.name
                ))
            })
        };
        let first = index()?;
        let mut prev = index()?;
        for _ in 2..k {
            let v = index()?;
            try_push(&mut triangles, [first, prev, v], "the triangles")?;
            prev = v;
        }
        let at = bin.pos;
        let colours = bin.count(&|| format!("the number of colour components of face {f}"))?;
        if colours > 4 {
            let msg = format!("face {f} has {colours} colour components (0 to 4)");
            return Err(bin.err(at, &msg));
        }
        bin.skip(colours as usize, &|| {
            format!("a colour component of face {f}")
        })?;
    }
    Ok(triangles)
}
