//! What a script relies on: exit codes, output that never panics, JSON it can parse,
//! `--quiet` and `--verbose`, messages that name the problem.

mod common;

use common::{bowties, temp, text, topomesh};
use serde::de::{self, Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};
use std::collections::HashSet;
use std::fmt;
use std::process::{Command, Output, Stdio};
use std::sync::OnceLock;

const TWO_TETS: &str = "MeshVersionFormatted 2\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n\
    0 1 0 0\n0 0 1 0\n1 1 1 0\nTetrahedra\n2\n1 2 3 4 0\n2 3 4 5 0\nEnd\n";
/// Three tetrahedra on one face: a non-manifold face.
const THREE_TETS: &str = "MeshVersionFormatted 2\nDimension 3\nVertices\n6\n0 0 0 0\n\
    1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\n-1 -1 -1 0\nTetrahedra\n3\n1 2 3 4 0\n2 3 4 5 0\n\
    2 3 4 6 0\nEnd\n";

fn code(args: &[&str]) -> Option<i32> {
    topomesh(args).status.code()
}

/// A torus file, written once: tests run at once and must not see it half written.
fn torus_file() -> String {
    static PATH: OnceLock<String> = OnceLock::new();
    PATH.get_or_init(|| {
        let off = topomesh::generate::to_off(&topomesh::generate::torus(5, 4));
        temp("torus.off", &off).to_str().unwrap().to_string()
    })
    .clone()
}

#[test]
fn every_subcommand_exits_0_on_good_input() {
    let torus = torus_file();
    let tets = temp("two.mesh", TWO_TETS);
    let tets = tets.to_str().unwrap();
    let out = temp("torus-out.vtk", "");
    let out = out.to_str().unwrap();
    for args in [
        &[][..],
        &["info", &torus],
        &["info", "--json", tets],
        &["check", &torus],
        &["check", tets],
        &["convert", &torus, out],
        &["bench", "--repeat", "1", &torus],
        &["bench", "--repeat", "1", "--json", tets],
        &["--help"],
        &["check", "--help"],
        &["--version"],
    ] {
        assert_eq!(code(args), Some(0), "{args:?}");
    }
}

#[test]
fn check_exits_1_on_a_mesh_with_a_problem_and_strict_info_too() {
    let bowtie = temp("bowtie1.off", &bowties(1));
    let three = temp("three.mesh", THREE_TETS);
    for path in [&bowtie, &three] {
        let path = path.to_str().unwrap();
        assert_eq!(code(&["check", path]), Some(1), "{path}");
        assert_eq!(code(&["check", "--json", path]), Some(1), "{path}");
        assert_eq!(code(&["-q", "check", path]), Some(1), "{path}");
        assert_eq!(code(&["info", "--strict", path]), Some(1), "{path}");
        // Without --strict, info repairs and describes it.
        assert_eq!(code(&["info", path]), Some(0), "{path}");
    }
}

#[test]
fn usage_errors_exit_2() {
    let torus = torus_file();
    for args in [
        &["--bogus"][..],
        &["frobnicate"],
        &["info", "--level", "7"],
        &["info", "--level", "x"],
        &["check"],
        &["check", &torus, "extra"],
        &["convert", &torus],
        &["bench", "--repeat", "many"],
        &["-q", "-v", "info"],
    ] {
        let out = topomesh(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert!(
            text(&out).1.starts_with("error: "),
            "{args:?}: {}",
            text(&out).1
        );
    }
}

#[test]
fn unreadable_or_invalid_input_exits_3_for_every_subcommand() {
    let bad = temp(
        "bad-index.off",
        "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n",
    );
    let bad = bad.to_str().unwrap();
    let garbage = temp("garbage.ply", "this is not a ply file\n");
    let garbage = garbage.to_str().unwrap();
    let out = temp("out.vtk", "");
    let out = out.to_str().unwrap();
    for input in [
        "/nonexistent/mesh.off",
        "/nonexistent/mesh.xyz",
        bad,
        garbage,
    ] {
        for args in [
            &["info", input][..],
            &["info", "--json", input],
            &["check", input],
            &["check", "--json", input],
            &["convert", input, out],
            &["bench", "--repeat", "1", input],
        ] {
            let o = topomesh(args);
            assert_eq!(o.status.code(), Some(3), "{args:?}");
            let (stdout, stderr) = text(&o);
            assert!(stdout.is_empty(), "{args:?}: {stdout}");
            assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
            assert!(stderr.starts_with("topomesh: error: "), "{stderr}");
            assert!(stderr.contains(input), "{args:?}: {stderr}");
        }
    }
    // An output format that does not exist is invalid input too.
    let torus = torus_file();
    assert_eq!(code(&["convert", &torus, "/tmp/x.xyz"]), Some(3));
}

#[test]
fn a_missing_file_is_named_missing_whatever_its_extension() {
    for path in [
        "/nonexistent/mesh.off",
        "/nonexistent/mesh.xyz",
        "/nonexistent/mesh",
    ] {
        let out = topomesh(&["info", path]);
        assert_eq!(out.status.code(), Some(3));
        let (_, stderr) = text(&out);
        assert_eq!(
            stderr.trim_end(),
            format!("topomesh: error: {path}: No such file or directory (os error 2)"),
        );
    }
}

/// Runs `args` with stdout on `stdout`, capturing stderr.
fn run_with_stdout(args: &[&str], stdout: Stdio) -> Output {
    Command::new(env!("CARGO_BIN_EXE_topomesh"))
        .args(args)
        .stdout(stdout)
        .stderr(Stdio::piped())
        .output()
        .expect("run topomesh")
}

fn printing_commands(torus: &str) -> Vec<Vec<String>> {
    let cmds: [&[&str]; 9] = [
        &["--help"],
        &["check", "--help"],
        &["--version"],
        &["info"],
        &["info", "--json"],
        &["check", torus],
        &["check", "--json", torus],
        &["bench", "--repeat", "1"],
        &["bench", "--repeat", "1", "--json"],
    ];
    cmds.iter()
        .map(|c| c.iter().map(|s| s.to_string()).collect())
        .collect()
}

#[test]
fn a_closed_pipe_is_a_quiet_success() {
    let torus = torus_file();
    for args in printing_commands(&torus) {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        // The reading end is closed before the command starts: its first write fails.
        let (reader, writer) = std::io::pipe().unwrap();
        drop(reader);
        let out = run_with_stdout(&args, writer.into());
        assert_eq!(out.status.code(), Some(0), "{args:?}: {}", text(&out).1);
        assert!(out.stderr.is_empty(), "{args:?}: {}", text(&out).1);
    }
}

#[test]
fn a_closed_pipe_from_a_spawned_reader_is_a_quiet_success() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_topomesh"))
        .args(["info"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", text(&out).1);
    assert!(out.stderr.is_empty(), "{}", text(&out).1);
}

#[test]
#[cfg(target_os = "linux")]
fn a_full_disk_is_one_error_line_and_exit_3() {
    let torus = torus_file();
    for args in printing_commands(&torus) {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let full = std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap();
        let out = run_with_stdout(&args, full.into());
        assert_eq!(out.status.code(), Some(3), "{args:?}");
        let (_, stderr) = text(&out);
        assert_eq!(
            stderr, "topomesh: error: writing the output: No space left on device (os error 28)\n",
            "{args:?}"
        );
    }
}

/// Any JSON value, refused when an object has a key twice (serde_json keeps the last).
struct Unique;

impl<'de> Deserialize<'de> for Unique {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(UniqueVisitor)
    }
}

struct UniqueVisitor;

impl<'de> Visitor<'de> for UniqueVisitor {
    type Value = Unique;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("JSON")
    }
    fn visit_bool<E>(self, _: bool) -> Result<Unique, E> {
        Ok(Unique)
    }
    fn visit_i64<E>(self, _: i64) -> Result<Unique, E> {
        Ok(Unique)
    }
    fn visit_u64<E>(self, _: u64) -> Result<Unique, E> {
        Ok(Unique)
    }
    fn visit_f64<E>(self, _: f64) -> Result<Unique, E> {
        Ok(Unique)
    }
    fn visit_str<E>(self, _: &str) -> Result<Unique, E> {
        Ok(Unique)
    }
    fn visit_unit<E>(self) -> Result<Unique, E> {
        Ok(Unique)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Unique, A::Error> {
        while seq.next_element::<Unique>()?.is_some() {}
        Ok(Unique)
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Unique, A::Error> {
        let mut seen = HashSet::new();
        while let Some(key) = map.next_key::<String>()? {
            if !seen.insert(key.clone()) {
                return Err(de::Error::custom(format!("duplicate key {key:?}")));
            }
            map.next_value::<Unique>()?;
        }
        Ok(Unique)
    }
}

/// The JSON a command printed: checked for duplicate keys, then parsed.
fn json(out: &Output) -> serde_json::Value {
    assert!(matches!(out.status.code(), Some(0 | 1)), "{}", text(out).1);
    if let Err(e) = serde_json::from_slice::<Unique>(&out.stdout) {
        panic!("{e}: {}", text(out).0);
    }
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn the_duplicate_key_check_finds_duplicates() {
    assert!(serde_json::from_str::<Unique>(r#"{"a": [{"b": 1, "c": {"b": 2}}]}"#).is_ok());
    assert!(serde_json::from_str::<Unique>(r#"{"a": 1, "b": 2, "a": 3}"#).is_err());
    assert!(serde_json::from_str::<Unique>(r#"[{"x": {"y": 1, "y": 1}}]"#).is_err());
}

#[test]
fn every_json_document_has_its_schema_and_no_duplicate_keys() {
    let torus = torus_file();
    let bowtie = temp("bowtie-json.off", &bowties(1));
    let bowtie = bowtie.to_str().unwrap();
    let tets = temp("two-json.mesh", TWO_TETS);
    let three = temp("three-json.mesh", THREE_TETS);
    let (tets, three) = (tets.to_str().unwrap(), three.to_str().unwrap());
    for (schema, args) in [
        (2, &["info", "--json"][..]),
        (2, &["info", "--json", bowtie]),
        (2, &["info", "--json", "--level", "0", tets]),
        (1, &["check", "--json", &torus]),
        (1, &["check", "--json", bowtie]),
        (1, &["check", "--json", three]),
        (1, &["bench", "--json", "--repeat", "1"]),
        (1, &["bench", "--json", "--repeat", "1", tets]),
    ] {
        let j = json(&topomesh(args));
        assert_eq!(j["schema"], schema, "{args:?}");
        // The schema is the first field.
        let first = text(&topomesh(args)).0;
        assert!(
            first.starts_with(&format!("{{\n  \"schema\": {schema},")),
            "{first}"
        );
    }
}

#[test]
fn an_undefined_genus_is_null() {
    let bowtie = temp("bowtie-genus.off", &bowties(1));
    let j = json(&topomesh(&["info", "--json", bowtie.to_str().unwrap()]));
    assert_eq!(j["manifold"], false);
    assert!(j["genus"].is_null(), "{}", j["genus"]);
    let j = json(&topomesh(&["info", "--json"]));
    assert_eq!(j["genus"], 1);
}

#[test]
fn check_json_lists_each_problem_with_its_ids() {
    let seven = temp("bowties7.off", &bowties(7));
    let out = topomesh(&["check", "--json", seven.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let j = json(&out);
    assert_eq!(j["ok"], false);
    assert_eq!(j["kind"], "surface");
    assert_eq!(j["elements"], 14);
    assert_eq!(
        j["problems"],
        serde_json::json!([{
            "problem": "non_manifold_vertices",
            "count": 7,
            "examples": [0, 5, 10, 15, 20, 25, 30],
        }])
    );
    let torus = torus_file();
    let j = json(&topomesh(&["check", "--json", &torus]));
    assert_eq!(j["ok"], true);
    assert_eq!(j["problems"], serde_json::json!([]));
    assert_eq!(
        (j["elements"].as_u64(), j["euler_characteristic"].as_i64()),
        (Some(40), Some(0))
    );
}

#[test]
fn bench_json_has_every_level() {
    let j = json(&topomesh(&[
        "bench",
        "--json",
        "--repeat",
        "3",
        "--threads",
        "1",
    ]));
    assert_eq!(
        (j["kind"].as_str(), j["elements"].as_u64()),
        (Some("surface"), Some(576))
    );
    assert_eq!(
        (j["repeat"].as_u64(), j["threads"].as_u64()),
        (Some(3), Some(1))
    );
    let levels = j["levels"].as_array().unwrap();
    let numbers: Vec<u64> = levels
        .iter()
        .map(|l| l["level"].as_u64().unwrap())
        .collect();
    assert_eq!(numbers, [0, 1, 2, 3]);
    assert!(levels[0]["sweeps"].is_null());
    assert_eq!(levels[1]["sweeps"]["method"], "bulk");
    assert_eq!(levels[2]["sweeps"]["method"], "per_element");
    for l in levels {
        let b = &l["build"];
        let (min, median, max) = (b["min"].as_f64(), b["median"].as_f64(), b["max"].as_f64());
        assert!(min <= median && median <= max, "{b}");
        assert!(l["topology_bytes"].as_u64().unwrap() > 0);
    }
}

#[test]
fn counts_agree_with_their_noun_and_long_id_lists_are_capped() {
    let one = temp("bowtie-one.off", &bowties(1));
    let two = temp("bowtie-two.off", &bowties(2));
    let seven = temp("bowtie-seven.off", &bowties(7));
    let check = |p: &std::path::Path| text(&topomesh(&["check", p.to_str().unwrap()])).0;
    assert!(
        check(&one).ends_with(": 1 non-manifold vertex: 0\n"),
        "{}",
        check(&one)
    );
    assert!(
        check(&two).ends_with(": 2 non-manifold vertices: 0, 5\n"),
        "{}",
        check(&two)
    );
    assert!(
        check(&seven).ends_with(": 7 non-manifold vertices: 0, 5, 10, 15, 20 ... and 2 more\n"),
        "{}",
        check(&seven)
    );
    // --verbose shows every id the report kept.
    let out = topomesh(&["-v", "check", seven.to_str().unwrap()]);
    let (stdout, _) = text(&out);
    assert!(
        stdout.contains(": 7 non-manifold vertices: 0, 5, 10, 15, 20, 25, 30\n"),
        "{stdout}"
    );
    let torus = torus_file();
    assert!(
        text(&topomesh(&["check", &torus]))
            .0
            .ends_with("ok: a manifold of 40 triangles, euler characteristic 0\n")
    );
    let tets = temp("two-noun.mesh", TWO_TETS);
    let out = text(&topomesh(&["info", tets.to_str().unwrap()])).0;
    assert!(
        out.contains("5 vertices, 9 edges, 7 faces, 8 half-faces"),
        "{out}"
    );
}

#[test]
fn quiet_prints_nothing_and_verbose_the_whole_report() {
    let torus = torus_file();
    let bowtie = temp("bowtie-quiet.off", &bowties(1));
    let bowtie = bowtie.to_str().unwrap();
    for args in [
        &["-q", "info"][..],
        &["info", "--quiet", "--json"],
        &["-q", "check", &torus],
        &["check", "-q", bowtie],
        &["-q", "bench", "--repeat", "1"],
    ] {
        let out = topomesh(args);
        assert!(
            out.stdout.is_empty() && out.stderr.is_empty(),
            "{args:?}: {:?}",
            text(&out)
        );
    }
    // Errors still reach stderr.
    let out = topomesh(&["-q", "check", "/nonexistent/mesh.off"]);
    assert_eq!(out.status.code(), Some(3));
    assert!(text(&out).1.contains("/nonexistent/mesh.off"));

    let (plain, _) = text(&topomesh(&["check", bowtie]));
    let (verbose, _) = text(&topomesh(&["check", "--verbose", bowtie]));
    assert!(!plain.contains("build report"), "{plain}");
    assert!(verbose.starts_with(&plain), "{verbose}");
    assert!(
        verbose.contains("build report\n") && verbose.contains("vertices added by splits  1\n")
    );
    let (info, _) = text(&topomesh(&["-v", "info"]));
    assert!(info.contains("memory by container\n"), "{info}");
    let (bench, _) = text(&topomesh(&["-v", "bench", "--repeat", "2"]));
    assert!(bench.lines().nth(1).unwrap().ends_with(" ms)"), "{bench}");
}

#[test]
fn every_help_has_examples_and_the_exit_codes() {
    for sub in ["info", "check", "convert", "bench"] {
        let out = topomesh(&[sub, "--help"]);
        assert_eq!(out.status.code(), Some(0));
        let (help, _) = text(&out);
        assert!(help.contains("Examples:\n  topomesh "), "{sub}: {help}");
        assert!(help.contains("Exit codes:\n  0  success"), "{sub}: {help}");
        assert!(
            help.contains("\n  3  unreadable or invalid input"),
            "{sub}: {help}"
        );
    }
    let (help, _) = text(&topomesh(&["--help"]));
    assert!(help.contains("Exit codes:") && help.contains("--quiet") && help.contains("--verbose"));
}
