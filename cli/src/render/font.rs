//! A 3 x 5 pixel font for the raster's legend and curve numbers: the PNG needs text, and a
//! font file or a text-shaping crate would weigh more than the whole render.

/// Pixels between the left edges of two characters, per unit of scale.
pub const ADVANCE: usize = 4;
/// Glyph height, per unit of scale.
pub const HEIGHT: usize = 5;

/// Each glyph as five rows of three pixels, `x` lit.
const GLYPHS: &[(char, [&str; 5])] = &[
    ('0', ["xxx", "x.x", "x.x", "x.x", "xxx"]),
    ('1', [".x.", "xx.", ".x.", ".x.", "xxx"]),
    ('2', ["xxx", "..x", "xxx", "x..", "xxx"]),
    ('3', ["xxx", "..x", "xxx", "..x", "xxx"]),
    ('4', ["x.x", "x.x", "xxx", "..x", "..x"]),
    ('5', ["xxx", "x..", "xxx", "..x", "xxx"]),
    ('6', ["xxx", "x..", "xxx", "x.x", "xxx"]),
    ('7', ["xxx", "..x", "..x", "..x", "..x"]),
    ('8', ["xxx", "x.x", "xxx", "x.x", "xxx"]),
    ('9', ["xxx", "x.x", "xxx", "..x", "xxx"]),
    ('a', [".x.", "x.x", "xxx", "x.x", "x.x"]),
    ('b', ["xx.", "x.x", "xx.", "x.x", "xx."]),
    ('c', [".xx", "x..", "x..", "x..", ".xx"]),
    ('d', ["xx.", "x.x", "x.x", "x.x", "xx."]),
    ('e', ["xxx", "x..", "xx.", "x..", "xxx"]),
    ('f', ["xxx", "x..", "xx.", "x..", "x.."]),
    ('g', [".xx", "x..", "x.x", "x.x", ".xx"]),
    ('h', ["x.x", "x.x", "xxx", "x.x", "x.x"]),
    ('i', ["xxx", ".x.", ".x.", ".x.", "xxx"]),
    ('j', ["..x", "..x", "..x", "x.x", ".x."]),
    ('k', ["x.x", "x.x", "xx.", "x.x", "x.x"]),
    ('l', ["x..", "x..", "x..", "x..", "xxx"]),
    ('m', ["x.x", "xxx", "xxx", "x.x", "x.x"]),
    ('n', ["xx.", "x.x", "x.x", "x.x", "x.x"]),
    ('o', [".x.", "x.x", "x.x", "x.x", ".x."]),
    ('p', ["xx.", "x.x", "xx.", "x..", "x.."]),
    ('q', [".x.", "x.x", "x.x", "xx.", ".xx"]),
    ('r', ["xx.", "x.x", "xx.", "x.x", "x.x"]),
    ('s', [".xx", "x..", ".x.", "..x", "xx."]),
    ('t', ["xxx", ".x.", ".x.", ".x.", ".x."]),
    ('u', ["x.x", "x.x", "x.x", "x.x", "xxx"]),
    ('v', ["x.x", "x.x", "x.x", "x.x", ".x."]),
    ('w', ["x.x", "x.x", "xxx", "xxx", "x.x"]),
    ('x', ["x.x", "x.x", ".x.", "x.x", "x.x"]),
    ('y', ["x.x", "x.x", ".x.", ".x.", ".x."]),
    ('z', ["xxx", "..x", ".x.", "x..", "xxx"]),
    (' ', ["...", "...", "...", "...", "..."]),
    (':', ["...", ".x.", "...", ".x.", "..."]),
    ('-', ["...", "...", "xxx", "...", "..."]),
    (',', ["...", "...", "...", ".x.", "x.."]),
    ('.', ["...", "...", "...", "...", ".x."]),
    ('(', [".x.", "x..", "x..", "x..", ".x."]),
    (')', [".x.", "..x", "..x", "..x", ".x."]),
    ('/', ["..x", "..x", ".x.", "x..", "x.."]),
    ('=', ["...", "xxx", "...", "xxx", "..."]),
    ('+', ["...", ".x.", "xxx", ".x.", "..."]),
    ('_', ["...", "...", "...", "...", "xxx"]),
    ('#', ["x.x", "xxx", "x.x", "xxx", "x.x"]),
    ('?', ["xxx", "..x", ".x.", "...", ".x."]),
];

/// The lit pixels of `c` (case folded; `?` for a character the font lacks), as
/// (column, row) pairs.
pub fn pixels(c: char) -> impl Iterator<Item = (usize, usize)> {
    let c = c.to_ascii_lowercase();
    let rows = GLYPHS
        .iter()
        .find(|(g, _)| *g == c)
        .or_else(|| GLYPHS.iter().find(|(g, _)| *g == '?'))
        .map(|(_, rows)| *rows)
        .unwrap_or_default();
    rows.into_iter().enumerate().flat_map(|(y, row)| {
        row.bytes()
            .enumerate()
            .filter(|&(_, b)| b == b'x')
            .map(move |(x, _)| (x, y))
    })
}

/// The width in pixels of `text` at `scale`.
pub fn width(text: &str, scale: usize) -> usize {
    text.chars().count() * ADVANCE * scale
}
