//! `topomesh convert mesh.off mesh.che` saves the built structure, `topomesh info mesh.che`
//! opens it: the same summary as building the mesh; a damaged level file is a clear error.

mod common;

use common::{bowties, temp, text, topomesh};

/// `info --json` of `path`, parsed.
fn info(args: &[&str]) -> serde_json::Value {
    let out = topomesh(args);
    assert!(out.status.success(), "{}", text(&out).1);
    serde_json::from_slice(&out.stdout).unwrap()
}

/// The JSON of `info` without what differs between building and opening: the times, the
/// file name.
fn comparable(mut json: serde_json::Value) -> serde_json::Value {
    let map = json.as_object_mut().unwrap();
    for key in ["read_seconds", "build_seconds", "file"] {
        map.remove(key);
    }
    json
}

#[test]
fn a_surface_saved_and_opened_says_what_it_built() {
    let off = temp("bowties.off", &bowties(3));
    let che = off.with_file_name("bowties.che");
    let out = topomesh(&["convert", off.to_str().unwrap(), che.to_str().unwrap()]);
    assert!(out.status.success(), "{}", text(&out).1);
    assert!(
        text(&out).0.contains("18 vertices, 6 triangles"),
        "{}",
        text(&out).0
    );
    for level in ["0", "2", "3"] {
        let built = info(&["info", "--json", "--level", level, off.to_str().unwrap()]);
        let opened = info(&["info", "--json", "--level", level, che.to_str().unwrap()]);
        assert_eq!(opened["split_vertices"], 3);
        assert_eq!(comparable(opened), comparable(built), "level {level}");
    }
}

#[test]
fn a_volume_saved_and_opened_says_what_it_built() {
    let mesh = temp(
        "pair.mesh",
        "MeshVersionFormatted 2\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\n\
         Tetrahedra\n2\n1 2 3 4 0\n2 3 4 5 0\nEnd\n",
    );
    let chf = mesh.with_file_name("pair.chf");
    let out = topomesh(&["convert", mesh.to_str().unwrap(), chf.to_str().unwrap()]);
    assert!(out.status.success(), "{}", text(&out).1);
    let built = info(&["info", "--json", mesh.to_str().unwrap()]);
    let opened = info(&["info", "--json", chf.to_str().unwrap()]);
    assert_eq!(opened["kind"], "volume");
    assert_eq!(opened["faces"], 7);
    assert_eq!(comparable(opened), comparable(built));
}

#[test]
fn level_files_refuse_what_they_cannot_hold() {
    let off = temp("one.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    let (src, chf) = (off.to_str().unwrap(), off.with_file_name("one.chf"));
    let out = topomesh(&["convert", src, chf.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(3));
    assert!(
        text(&out).1.contains("goes to a .che level file"),
        "{}",
        text(&out).1
    );
    assert!(!chf.exists());
    let che = off.with_file_name("one.che");
    let out = topomesh(&["convert", "--binary", src, che.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(3));
    assert!(text(&out).1.contains("do not apply"), "{}", text(&out).1);
    // A damaged level file: the error names the section and the byte.
    assert!(
        topomesh(&["convert", src, che.to_str().unwrap()])
            .status
            .success()
    );
    let mut bytes = std::fs::read(&che).unwrap();
    let last = bytes.len() - 1;
    bytes.truncate(last);
    std::fs::write(&che, &bytes).unwrap();
    let out = topomesh(&["info", che.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(3));
    let (_, stderr) = text(&out);
    assert!(
        stderr.contains("one.che") && stderr.contains("byte 32"),
        "{stderr}"
    );
}
