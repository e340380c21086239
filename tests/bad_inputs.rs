//! The bad-input suite: every row of `tests/fixtures/bad/expected.tsv` names a crafted file
//! (or a `.arrays` description of a C call), the status it must give and the words its
//! message must hold. Files are read through `topomesh::io::load` (as a surface or a
//! volume, by the row's second column); `.arrays` rows call the C build and load functions.
//! `c-tests/c/test_bad_inputs.c` runs the same table through the C API.
//!
//! Table columns (tab-separated; `#` starts a comment line):
//! `file  as  status  words  [xfail]` where `as` is `che`, `chf` or `-` (a `.arrays` row),
//! `status` a `TOPOMESH_STATUS_` name without the prefix, and `words` space-separated pieces
//! the message must contain (for `OK`: `triangles=N`, `tetrahedra=N` facts about the mesh
//! built; `-` for none). A row marked `xfail` states how the input SHOULD be handled and
//! today is not: the test checks that it still fails (and prints it), and fails once it
//! passes, so that the mark is removed with the fix.
//!
//! `.arrays` keys, one per line: `kind che|chf|che_load|chf_load`, `vertices N`, `level N`,
//! `strict 0|1`, `threads N`, `out null`, `path P|null` (relative to the `.arrays` file),
//! and `elements` followed by the ids, by `null N` (a NULL array of N elements) or by
//! `strip N` (N elements, each starting one vertex after the last).

use std::ffi::{CString, c_char};
use std::path::{Path, PathBuf};
use std::ptr::{null, null_mut};
use topomesh::ffi::Status;
use topomesh::ffi::che::*;
use topomesh::ffi::chf::*;
use topomesh::ffi::status::topomesh_last_error;
use topomesh::io::load;
use topomesh::{BuildOptions, ErrorKind};

fn folder() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/bad")
}

/// One row of the table.
struct Row {
    line: usize,
    file: String,
    load_as: String,
    status: String,
    words: Vec<String>,
    xfail: bool,
}

fn rows() -> Vec<Row> {
    let table = std::fs::read_to_string(folder().join("expected.tsv")).expect("expected.tsv");
    let mut rows = Vec::new();
    for (i, line) in table.lines().enumerate() {
        if line.trim().is_empty() || line.starts_with('#') {
            continue;
        }
        let cols: Vec<&str> = line.split('\t').collect();
        assert!(
            (4..=5).contains(&cols.len()),
            "expected.tsv:{}: 4 or 5 columns: {line}",
            i + 1
        );
        let words = if cols[3] == "-" {
            vec![]
        } else {
            cols[3].split(' ').map(String::from).collect()
        };
        rows.push(Row {
            line: i + 1,
            file: cols[0].into(),
            load_as: cols[1].into(),
            status: cols[2].into(),
            words,
            xfail: cols.get(4) == Some(&"xfail"),
        });
    }
    rows
}

fn status_name(kind: ErrorKind) -> &'static str {
    match kind {
        ErrorKind::NullArgument => "NULL_ARGUMENT",
        ErrorKind::OutOfRange => "OUT_OF_RANGE",
        ErrorKind::InvalidInput => "INVALID_INPUT",
        ErrorKind::NonManifold => "NON_MANIFOLD",
        ErrorKind::BufferTooSmall => "BUFFER_TOO_SMALL",
        ErrorKind::Io => "IO",
        ErrorKind::Parse => "PARSE",
        ErrorKind::TooLarge => "TOO_LARGE",
        ErrorKind::Panic => "PANIC",
        #[allow(unreachable_patterns, reason = "new kinds land from other branches")]
        _ => "OTHER",
    }
}

fn c_status_name(s: Status) -> &'static str {
    match s {
        Status::Ok => "OK",
        Status::NullArgument => "NULL_ARGUMENT",
        Status::OutOfRange => "OUT_OF_RANGE",
        Status::InvalidInput => "INVALID_INPUT",
        Status::NonManifold => "NON_MANIFOLD",
        Status::BufferTooSmall => "BUFFER_TOO_SMALL",
        Status::Io => "IO",
        Status::Parse => "PARSE",
        Status::TooLarge => "TOO_LARGE",
        Status::Panic => "PANIC",
        #[allow(unreachable_patterns, reason = "new statuses land from other branches")]
        _ => "OTHER",
    }
}

/// What a file gives when loaded: the status name and the message (or, for OK, the facts).
fn load_file(path: &Path, load_as: &str) -> (String, String) {
    let options = BuildOptions::level(2);
    let got = match load_as {
        "che" => load::che(path, options).map(|m| format!("triangles={}", m.num_triangles())),
        "chf" => load::chf(path, options).map(|m| format!("tetrahedra={}", m.num_tetrahedra())),
        other => panic!("unknown load kind {other}"),
    };
    match got {
        Ok(facts) => ("OK".into(), facts),
        Err(e) => (status_name(e.kind).into(), e.message),
    }
}

/// A `.arrays` description, parsed.
#[derive(Default)]
struct Call {
    kind: String,
    vertices: usize,
    level: u32,
    strict: bool,
    threads: u32,
    out_null: bool,
    path: Option<String>,
    elements: Vec<u32>,
    /// `elements null N`: a NULL array said to hold N elements.
    null_elements: Option<usize>,
}

fn parse_call(path: &Path) -> Call {
    let text = std::fs::read_to_string(path).expect("an .arrays file");
    let mut call = Call {
        level: 2,
        ..Call::default()
    };
    let mut strip = None;
    for line in text.lines() {
        let mut words = line.split_whitespace();
        let key = words.next().unwrap_or_default();
        let rest: Vec<&str> = words.collect();
        let num = |i: usize| rest[i].parse::<u64>().expect("a number");
        match key {
            "kind" => call.kind = rest[0].into(),
            "vertices" => call.vertices = num(0) as usize,
            "level" => call.level = num(0) as u32,
            "strict" => call.strict = num(0) != 0,
            "threads" => call.threads = num(0) as u32,
            "out" => call.out_null = true,
            "path" => call.path = (rest[0] != "null").then(|| rest[0].into()),
            "elements" if rest.first() == Some(&"null") => {
                call.null_elements = Some(num(1) as usize)
            }
            "elements" if rest.first() == Some(&"strip") => strip = Some(num(1) as u32),
            "elements" => call.elements = rest.iter().map(|w| w.parse().expect("an id")).collect(),
            "" => {}
            other => panic!("{}: unknown key {other}", path.display()),
        }
    }
    if let Some(n) = strip {
        let k = if call.kind == "chf" { 4 } else { 3 };
        call.elements = (0..n).flat_map(|i| (0..k).map(move |j| i + j)).collect();
    }
    call
}

fn last_error() -> String {
    let mut buf = vec![0 as c_char; 4096];
    let mut len = 0;
    // SAFETY: the buffer holds `buf.len()` bytes.
    unsafe { topomesh_last_error(buf.as_mut_ptr(), buf.len(), &mut len) };
    let bytes: Vec<u8> = buf
        .iter()
        .take_while(|&&c| c != 0)
        .map(|&c| c as u8)
        .collect();
    String::from_utf8_lossy(&bytes).into_owned()
}

/// Makes the call an `.arrays` file describes through the C API: the status name and the
/// message (or, for OK, the facts).
fn run_call(file: &Path) -> (String, String) {
    let call = parse_call(file);
    let elements = match call.null_elements {
        Some(_) => null(),
        None => call.elements.as_ptr(),
    };
    let k = if call.kind == "chf" { 4 } else { 3 };
    let n = call.null_elements.unwrap_or(call.elements.len() / k);
    let path = call
        .path
        .as_ref()
        .map(|p| CString::new(file.parent().unwrap().join(p).to_str().unwrap()).unwrap());
    let path = path.as_ref().map_or(null(), |p| p.as_ptr());
    let (mut che, mut chf): (*mut CheMesh, *mut ChfMesh) = (null_mut(), null_mut());
    let che_out = if call.out_null {
        null_mut()
    } else {
        &mut che as *mut _
    };
    let chf_out = if call.out_null {
        null_mut()
    } else {
        &mut chf as *mut _
    };
    let che_options = CheBuildOptions {
        level: call.level,
        strict: call.strict.into(),
        threads: call.threads,
        ..CheBuildOptions::default()
    };
    let chf_options = ChfBuildOptions {
        level: call.level,
        strict: call.strict.into(),
        threads: call.threads,
        ..ChfBuildOptions::default()
    };
    // SAFETY: the arrays hold what the counts say, or are NULL; the outputs are NULL or
    // writable; the path is NUL-terminated or NULL.
    let status = unsafe {
        match call.kind.as_str() {
            "che" => che_mesh_from_triangles_ex(
                elements,
                n,
                call.vertices,
                null(),
                &che_options,
                che_out,
            ),
            "chf" => chf_mesh_from_tetrahedra_ex(
                elements,
                n,
                call.vertices,
                null(),
                &chf_options,
                chf_out,
            ),
            "che_load" => che_mesh_load_ex(path, &che_options, che_out),
            "chf_load" => chf_mesh_load_ex(path, &chf_options, chf_out),
            other => panic!("{}: unknown kind {other}", file.display()),
        }
    };
    let message = if status == Status::Ok {
        String::new()
    } else {
        last_error()
    };
    // SAFETY: each is NULL or a live handle, freed once.
    let facts = unsafe {
        let facts = if !che.is_null() {
            format!("triangles={}", che_mesh_num_triangles(che))
        } else if !chf.is_null() {
            format!("tetrahedra={}", chf_mesh_num_tetrahedra(chf))
        } else {
            String::new()
        };
        che_mesh_free(che);
        chf_mesh_free(chf);
        facts
    };
    let message = if status == Status::Ok { facts } else { message };
    (c_status_name(status).into(), message)
}

#[test]
fn every_bad_input_gives_its_status_and_words() {
    let rows = rows();
    assert!(rows.len() >= 100, "the table has {} rows", rows.len());
    let (mut failures, mut still_xfail) = (Vec::new(), 0);
    for row in &rows {
        let path = folder().join(&row.file);
        let (status, message) = match row.load_as.as_str() {
            "-" => run_call(&path),
            load_as => load_file(&path, load_as),
        };
        let missing: Vec<&String> = row
            .words
            .iter()
            .filter(|w| !message.contains(w.as_str()))
            .collect();
        let passed = status == row.status && missing.is_empty();
        let report = format!(
            "expected.tsv:{} {}: got {status} \"{message}\", expected {} with {:?}",
            row.line, row.file, row.status, row.words
        );
        match (passed, row.xfail) {
            (true, false) => {}
            (false, true) => {
                still_xfail += 1;
                println!("xfail (still wrong today) {report}");
            }
            (true, true) => failures.push(format!("{report}: passes now, remove its xfail mark")),
            (false, false) => failures.push(report),
        }
    }
    println!("{} rows, {} expected failures", rows.len(), still_xfail);
    assert!(
        failures.is_empty(),
        "{} rows failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn every_fixture_has_a_row() {
    let named: std::collections::HashSet<String> = rows().into_iter().map(|r| r.file).collect();
    let mut unnamed = Vec::new();
    for dir in std::fs::read_dir(folder()).unwrap() {
        let dir = dir.unwrap().path();
        if !dir.is_dir() {
            continue;
        }
        for f in std::fs::read_dir(&dir).unwrap() {
            let f = f.unwrap().path();
            let rel = f
                .strip_prefix(folder())
                .unwrap()
                .to_str()
                .unwrap()
                .to_owned();
            // A TetGen row names one of its two files; the other is its sibling.
            let sibling = rel.strip_suffix(".ele").map(|s| format!("{s}.node"));
            if !named.contains(&rel) && !sibling.is_some_and(|s| named.contains(&s)) {
                unnamed.push(rel);
            }
        }
    }
    assert!(
        unnamed.is_empty(),
        "fixtures without a row in expected.tsv: {unnamed:?}"
    );
}

/// Positions whose length does not match the vertex count cannot be said in C (a pointer
/// has no length); the core API refuses them naming both numbers.
#[test]
fn positions_of_the_wrong_length_are_refused() {
    use glam::DVec3;
    let tris = [[0u32, 1, 2]];
    let short = [DVec3::ZERO; 2];
    let e = topomesh::Che::from_triangles(&tris, 3, &short, BuildOptions::level(2)).unwrap_err();
    assert_eq!(e.kind, ErrorKind::InvalidInput, "{e}");
    assert!(e.message.contains('2') && e.message.contains('3'), "{e}");
    let tets = [[0u32, 1, 2, 3]];
    let long = [DVec3::ZERO; 5];
    let e = topomesh::Chf::from_tetrahedra(&tets, 4, &long, topomesh::chf::BuildOptions::level(2))
        .unwrap_err();
    assert_eq!(e.kind, ErrorKind::InvalidInput, "{e}");
    assert!(e.message.contains('5') && e.message.contains('4'), "{e}");
}
