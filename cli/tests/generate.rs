//! `topomesh generate`, as a user runs it: each shape in a mesh format and as a level
//! file, its topology read back by `info`, and the refusals.

mod common;

use common::{text, topomesh};

fn path(name: &str) -> String {
    let dir = std::env::temp_dir().join(format!("topomesh-cli-gen-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name).to_str().unwrap().to_string()
}

/// `info --json` of `file`, parsed.
fn info(file: &str) -> serde_json::Value {
    let out = topomesh(&["info", "--json", file]);
    let (stdout, stderr) = text(&out);
    assert!(out.status.success(), "{file}: {stderr}");
    serde_json::from_str(&stdout).unwrap()
}

fn generate(args: &[&str]) -> (bool, Option<i32>, String, String) {
    let mut all = vec!["generate"];
    all.extend_from_slice(args);
    let out = topomesh(&all);
    let (stdout, stderr) = text(&out);
    (out.status.success(), out.status.code(), stdout, stderr)
}

#[test]
fn each_shape_has_its_size_and_topology() {
    let torus = path("torus.off");
    let (ok, _, stdout, stderr) = generate(&["torus", "--triangles", "5000", "-o", &torus]);
    assert!(ok, "{stderr}");
    assert!(stdout.starts_with("torus -> "), "{stdout}");
    let j = info(&torus);
    assert_eq!(
        (j["genus"].as_i64(), j["boundary_curves"].as_i64()),
        (Some(1), Some(0))
    );
    let t = j["triangles"].as_u64().unwrap();
    assert!((5000..5300).contains(&t), "{t} triangles");

    let sphere = path("sphere.ply");
    let (ok, ..) = generate(&["sphere", "--triangles", "3000", "-o", &sphere, "--binary"]);
    assert!(ok);
    let j = info(&sphere);
    assert_eq!(
        (j["genus"].as_i64(), j["euler_characteristic"].as_i64()),
        (Some(0), Some(2))
    );

    let cube = path("box.node");
    let (ok, ..) = generate(&["box", "--tetrahedra", "6000", "-o", &cube]);
    assert!(ok);
    let j = info(&cube);
    assert_eq!(j["tetrahedra"].as_u64(), Some(6000));
    assert_eq!(j["euler_characteristic"].as_i64(), Some(1));
    assert_eq!(j["boundary_components"].as_u64(), Some(1));
}

#[test]
fn level_files_hold_the_built_shape() {
    let che = path("sphere.che");
    let (ok, _, _, stderr) = generate(&["sphere", "--triangles", "2000", "-o", &che]);
    assert!(ok, "{stderr}");
    assert_eq!(info(&che)["euler_characteristic"].as_i64(), Some(2));
    let chf = path("box.chf");
    let (ok, ..) = generate(&["box", "-o", &chf]);
    assert!(ok);
    let t = info(&chf)["tetrahedra"].as_u64().unwrap();
    assert!((100_000..120_000).contains(&t), "{t} tetrahedra by default");
}

#[test]
fn refusals_name_the_problem_and_write_nothing() {
    let out = path("refused.off");
    for (args, says) in [
        (vec!["box", "--triangles", "10"], "use --tetrahedra"),
        (vec!["torus", "--tetrahedra", "10"], "use --triangles"),
        (vec!["torus", "--triangles", "0"], "ids are 32 bits"),
        (
            vec!["sphere", "--triangles", "99999999999"],
            "ids are 32 bits",
        ),
        (
            vec!["box", "--tetrahedra", "18446744073709551615"],
            "ids are 32 bits",
        ),
    ] {
        let mut all = args.clone();
        all.extend_from_slice(&["-o", &out]);
        let (ok, code, _, stderr) = generate(&all);
        assert!(!ok && code == Some(3), "{args:?}: {code:?} {stderr}");
        assert!(stderr.contains(says), "{args:?}: {stderr}");
        assert!(
            !std::path::Path::new(&out).exists(),
            "{args:?} wrote a file"
        );
    }
    for (shape, file, says) in [
        ("torus", "t.chf", "its level file is .che"),
        ("box", "b.che", "its level file is .chf"),
    ] {
        let (ok, _, _, stderr) = generate(&[shape, "-o", &path(file)]);
        assert!(!ok && stderr.contains(says), "{shape}: {stderr}");
    }
}

/// `--stream` writes the file the in-memory build saves, and refuses what it cannot write.
#[test]
fn a_streamed_torus_is_the_file_the_build_saves() {
    let (streamed, built) = (path("streamed.che"), path("built.che"));
    let (ok, _, stdout, stderr) =
        generate(&["torus", "--triangles", "20000", "-o", &streamed, "--stream"]);
    assert!(ok, "{stderr}");
    assert!(stdout.contains("(streamed)"), "{stdout}");
    let (ok, ..) = generate(&["torus", "--triangles", "20000", "-o", &built]);
    assert!(ok);
    assert!(std::fs::read(&streamed).unwrap() == std::fs::read(&built).unwrap());
    assert_eq!(info(&streamed)["genus"].as_i64(), Some(1));
    for args in [
        ["sphere", "-o", streamed.as_str()],
        ["torus", "-o", path("t.off").as_str()],
    ] {
        let mut all = args.to_vec();
        all.push("--stream");
        let (ok, code, _, stderr) = generate(&all);
        assert!(!ok && code == Some(3), "{args:?}: {code:?} {stderr}");
        assert!(stderr.contains("--stream writes a torus"), "{stderr}");
    }
}

/// `--level` sets a level file's level (the header's byte 20), and is refused elsewhere.
#[test]
fn level_sets_the_level_of_a_level_file() {
    for (shape, size, file, level) in [
        ("box", "--tetrahedra", "box1.chf", "1"),
        ("torus", "--triangles", "torus0.che", "0"),
        ("torus", "--triangles", "torus1s.che", "1"),
    ] {
        let out = path(file);
        let mut args = vec![shape, size, "3000", "-o", &out, "--level", level];
        if file.ends_with("s.che") {
            args.push("--stream");
        }
        let (ok, _, _, stderr) = generate(&args);
        assert!(ok, "{file}: {stderr}");
        let bytes = std::fs::read(&out).unwrap();
        assert_eq!(bytes[20].to_string(), level, "{file}");
    }
    let off = path("t.off");
    let (ok, code, _, stderr) = generate(&["torus", "-o", &off, "--level", "1"]);
    assert!(!ok && code == Some(3), "{code:?} {stderr}");
    assert!(
        stderr.contains("--level applies to a level file"),
        "{stderr}"
    );
}
