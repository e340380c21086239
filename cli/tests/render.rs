//! `topomesh render` and `check --render`: the marks are where the report and a brute
//! force over the input say, each boundary curve has its own colour, the same input gives
//! the same bytes, and what cannot be drawn is a clear error.

mod common;

use common::{temp, text, topomesh};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// One mark element of an SVG: its layer (group class and colour), the input ids it names,
/// and its screen position (a line's two ends, a dot's or cross's centre).
#[derive(Debug)]
struct Mark {
    class: String,
    colour: String,
    ids: Vec<u32>,
    at: Vec<[f64; 2]>,
}

/// The value of attribute `name` in the element `line`.
fn attr<'a>(line: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let start = line.find(&key)? + key.len();
    let len = line[start..].find('"')?;
    Some(&line[start..start + len])
}

fn num(line: &str, name: &str) -> f64 {
    attr(line, name).unwrap().parse().unwrap()
}

fn marks(svg: &str) -> Vec<Mark> {
    let mut group = (String::new(), String::new());
    let mut out = Vec::new();
    for line in svg.lines() {
        if line.starts_with("<g ") {
            let class = attr(line, "class").unwrap_or("").to_string();
            group = (class, attr(line, "stroke").unwrap_or("").to_string());
            continue;
        }
        let Some(ids) = attr(line, "data-v") else {
            continue;
        };
        let at = if line.starts_with("<line") {
            vec![
                [num(line, "x1"), num(line, "y1")],
                [num(line, "x2"), num(line, "y2")],
            ]
        } else if line.starts_with("<circle") {
            vec![[num(line, "cx"), num(line, "cy")]]
        } else {
            // A cross: M(x-r),(y-r) L(x+r),(y+r) ...: the centre is the first stroke's middle.
            let d: Vec<f64> = attr(line, "d").unwrap()[1..]
                .split(['L', 'M', ','])
                .map(|t| t.parse().unwrap())
                .collect();
            vec![[(d[0] + d[2]) / 2.0, (d[1] + d[3]) / 2.0]]
        };
        out.push(Mark {
            class: group.0.clone(),
            colour: group.1.clone(),
            ids: ids.split(' ').map(|t| t.parse().unwrap()).collect(),
            at,
        });
    }
    out
}

/// The front view's map from model (x, y) to the screen: x right, y down, one scale,
/// found from the two marked points farthest apart in x and checked on every mark.
struct Map {
    scale: f64,
    origin: [f64; 2],
}

impl Map {
    fn fit(pairs: &[([f64; 3], [f64; 2])]) -> Map {
        let lo = pairs
            .iter()
            .min_by(|a, b| a.0[0].total_cmp(&b.0[0]))
            .unwrap();
        let hi = pairs
            .iter()
            .max_by(|a, b| a.0[0].total_cmp(&b.0[0]))
            .unwrap();
        let scale = (hi.1[0] - lo.1[0]) / (hi.0[0] - lo.0[0]);
        let origin = [lo.1[0] - scale * lo.0[0], lo.1[1] + scale * lo.0[1]];
        let map = Map { scale, origin };
        for (p, s) in pairs {
            let m = map.at(*p);
            assert!(
                (m[0] - s[0]).abs() < 0.02 && (m[1] - s[1]).abs() < 0.02,
                "{p:?}: {s:?} != {m:?}"
            );
        }
        map
    }

    fn at(&self, p: [f64; 3]) -> [f64; 2] {
        [
            self.origin[0] + self.scale * p[0],
            self.origin[1] - self.scale * p[1],
        ]
    }
}

/// The RGB of every pixel of a PNG, and its width.
fn pixels(path: &Path) -> (Vec<u8>, usize) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!(info.color_type, png::ColorType::Rgb);
    buf.truncate(info.buffer_size());
    (buf, info.width as usize)
}

fn pixel((rgb, width): &(Vec<u8>, usize), [x, y]: [f64; 2]) -> String {
    let i = 3 * (y.floor() as usize * width + x.floor() as usize);
    format!("#{:02x}{:02x}{:02x}", rgb[i], rgb[i + 1], rgb[i + 2])
}

/// A path in the test's directory, with no file there yet.
fn out(name: &str) -> PathBuf {
    let path = temp(name, "");
    std::fs::remove_file(&path).unwrap();
    path
}

/// Runs `topomesh render` on `mesh` into `image`, seen from the front unless `extra` says.
fn render(mesh: &Path, image: &Path, extra: &[&str]) {
    let mut args = vec![
        "render",
        mesh.to_str().unwrap(),
        "-o",
        image.to_str().unwrap(),
    ];
    if !extra.contains(&"--view") {
        args.extend_from_slice(&["--view", "front"]);
    }
    args.extend_from_slice(&["--size", "900x600"]);
    args.extend_from_slice(extra);
    let run = topomesh(&args);
    assert!(run.status.success(), "{:?}", text(&run));
}

/// An OFF file of `positions` and `triangles`.
fn off(positions: &[[f64; 3]], triangles: &[[u32; 3]]) -> String {
    let mut s = format!("OFF\n{} {} 0\n", positions.len(), triangles.len());
    for p in positions {
        s += &format!("{} {} {}\n", p[0], p[1], p[2]);
    }
    for t in triangles {
        s += &format!("3 {} {} {}\n", t[0], t[1], t[2]);
    }
    s
}

/// A 6 x 6 grid of squares with two squares taken out: three boundary curves.
fn holed_grid() -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let n = 6u32;
    let positions = (0..=n)
        .flat_map(|y| (0..=n).map(move |x| [x as f64, y as f64, 0.0]))
        .collect();
    let mut triangles = Vec::new();
    for y in 0..n {
        for x in 0..n {
            if (x, y) == (1, 1) || (x, y) == (4, 3) {
                continue;
            }
            let v = y * (n + 1) + x;
            triangles.push([v, v + 1, v + n + 2]);
            triangles.push([v, v + n + 2, v + n + 1]);
        }
    }
    (positions, triangles)
}

/// The edges of exactly one triangle, as sorted pairs: the boundary, by brute force.
fn boundary_edges(triangles: &[[u32; 3]]) -> BTreeSet<[u32; 2]> {
    let mut uses: BTreeMap<[u32; 2], usize> = BTreeMap::new();
    for t in triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            *uses.entry([a.min(b), a.max(b)]).or_default() += 1;
        }
    }
    uses.into_iter()
        .filter(|&(_, n)| n == 1)
        .map(|(e, _)| e)
        .collect()
}

#[test]
fn boundary_curves_are_the_boundary_each_in_its_own_colour() {
    let (positions, triangles) = holed_grid();
    let mesh = temp("holed-grid.off", &off(&positions, &triangles));
    let (svg_path, png_path) = (out("holed-grid.svg"), out("holed-grid.png"));
    render(&mesh, &svg_path, &["--show", "boundary"]);
    render(&mesh, &png_path, &["--show", "boundary"]);
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    let lines: Vec<Mark> = marks(&svg)
        .into_iter()
        .filter(|m| m.class == "boundary")
        .collect();
    let drawn: BTreeSet<[u32; 2]> = lines
        .iter()
        .map(|m| [m.ids[0].min(m.ids[1]), m.ids[0].max(m.ids[1])])
        .collect();
    assert_eq!(drawn, boundary_edges(&triangles));
    assert_eq!(lines.len(), drawn.len(), "each boundary edge once");
    let colours: BTreeSet<&str> = lines.iter().map(|m| m.colour.as_str()).collect();
    assert_eq!(colours.len(), 3, "three curves, three colours: {colours:?}");
    assert_eq!(svg.matches("<text class=\"label boundary\"").count(), 3);

    let pairs: Vec<_> = lines
        .iter()
        .flat_map(|m| {
            [
                (positions[m.ids[0] as usize], m.at[0]),
                (positions[m.ids[1] as usize], m.at[1]),
            ]
        })
        .collect();
    Map::fit(&pairs);
    // The PNG has each curve's colour at the middle of each of its edges, away from the
    // curve numbers.
    let labels: Vec<[f64; 2]> = svg
        .lines()
        .filter(|l| l.starts_with("<text class=\"label"))
        .map(|l| [num(l, "x"), num(l, "y")])
        .collect();
    let image = pixels(&png_path);
    let mut checked = 0;
    for m in &lines {
        let mid = [
            (m.at[0][0] + m.at[1][0]) / 2.0,
            (m.at[0][1] + m.at[1][1]) / 2.0,
        ];
        let near_label = labels
            .iter()
            .any(|l| (mid[0] - l[0] - 15.0).abs() < 30.0 && (mid[1] - l[1] + 7.0).abs() < 15.0);
        if !near_label {
            assert_eq!(pixel(&image, mid), m.colour, "edge {:?}", m.ids);
            checked += 1;
        }
    }
    assert!(checked > lines.len() / 2, "{checked} of {}", lines.len());
}

/// Problems apart from each other: a bowtie (non-manifold vertex 0), three triangles on
/// edge {5, 6}, two triangles oriented against each other, a degenerate triangle (7).
fn broken() -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let positions = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 0.0, 0.0],
        [-1.0, -1.0, 0.0],
        [10.0, 0.0, 0.0],
        [10.0, 2.0, 0.0],
        [11.0, 1.0, 0.0],
        [9.0, 1.0, 0.0],
        [10.5, 1.5, 1.0],
        [20.0, 0.0, 0.0],
        [21.0, 0.0, 0.0],
        [21.0, 1.0, 0.0],
        [20.0, 1.0, 0.0],
        [30.0, 0.0, 0.0],
        [31.0, 0.0, 0.0],
    ];
    let triangles = vec![
        [0, 1, 2],
        [0, 3, 4],
        [5, 6, 7],
        [6, 5, 8],
        [5, 6, 9],
        [10, 11, 12],
        [10, 13, 12],
        [14, 14, 15],
    ];
    (positions, triangles)
}

fn check_json(mesh: &Path) -> serde_json::Value {
    let run = topomesh(&["check", "--json", mesh.to_str().unwrap()]);
    serde_json::from_slice(&run.stdout).unwrap()
}

/// The ids `check --json` lists for `problem`.
fn listed(json: &serde_json::Value, problem: &str) -> Vec<serde_json::Value> {
    let p = json["problems"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["problem"] == problem);
    p.unwrap_or_else(|| panic!("{problem} not in {json}"))["examples"]
        .as_array()
        .unwrap()
        .clone()
}

#[test]
fn problems_are_marked_where_check_lists_them() {
    let (positions, triangles) = broken();
    let mesh = temp("broken.off", &off(&positions, &triangles));
    let (svg_path, png_path) = (out("broken.svg"), out("broken.png"));
    // The problems alone: a boundary curve's number could cover a mark.
    let shows = ["--show", "non-manifold,seams,split,flipped,dropped"];
    render(&mesh, &svg_path, &shows);
    render(&mesh, &png_path, &shows);
    let all = marks(&std::fs::read_to_string(&svg_path).unwrap());
    let image = pixels(&png_path);
    let pairs: Vec<_> = (all.iter().filter(|m| m.class.starts_with("non-manifold")))
        .flat_map(|m| {
            m.ids
                .iter()
                .zip(&m.at)
                .map(|(&v, &s)| (positions[v as usize], s))
        })
        .collect();
    let map = Map::fit(&pairs);
    let json = check_json(&mesh);
    let of = |class: &str| all.iter().filter(|m| m.class == class).collect::<Vec<_>>();

    let vertices = listed(&json, "non_manifold_vertices");
    assert!(vertices.contains(&0.into()), "{vertices:?}");
    for v in vertices {
        let v = v.as_u64().unwrap() as u32;
        let dot = of("non-manifold-vertex")
            .into_iter()
            .find(|m| m.ids == [v])
            .unwrap();
        assert_eq!(pixel(&image, dot.at[0]), "#e60000", "vertex {v}");
    }
    let edges = listed(&json, "non_manifold_edges");
    assert_eq!(edges, [serde_json::json!([5, 6])]);
    let line = of("non-manifold")
        .into_iter()
        .find(|m| m.ids == [5, 6] || m.ids == [6, 5])
        .unwrap();
    let mid = map.at([10.0, 1.0, 0.0]);
    assert_eq!(pixel(&image, mid), "#e60000");
    assert!((line.at[0][0] - mid[0]).abs() < 0.02);

    assert_eq!(
        listed(&json, "degenerate_triangles"),
        [serde_json::json!(7)]
    );
    let cross = of("dropped");
    assert_eq!(cross.len(), 1);
    assert_eq!(cross[0].ids, [7]);
    let centre = map.at([30.0 + 1.0 / 3.0, 0.0, 0.0]);
    assert!(
        (cross[0].at[0][0] - centre[0]).abs() < 0.02,
        "{:?} {centre:?}",
        cross[0]
    );
    assert_eq!(pixel(&image, centre), "#000000");

    let flipped = of("flipped");
    assert_eq!(flipped.len(), 1, "check counts one: {json}");
    let t = flipped[0].ids[0] as usize;
    assert!(t == 5 || t == 6);
    let c = triangles[t].map(|v| positions[v as usize]);
    let centre = map.at([0, 1, 2].map(|k| (c[0][k] + c[1][k] + c[2][k]) / 3.0));
    assert!(
        (flipped[0].at[0][0] - centre[0]).abs() < 0.02
            && (flipped[0].at[0][1] - centre[1]).abs() < 0.02
    );
    assert_eq!(pixel(&image, centre), "#ff00aa");
}

/// `check --render` draws what `render` draws of the problems, in the same picture.
#[test]
fn check_render_is_the_picture_of_the_problems() {
    let (positions, triangles) = broken();
    let mesh = temp("broken-check.off", &off(&positions, &triangles));
    let (by_check, by_render) = (out("by-check.png"), out("by-render.png"));
    let run = topomesh(&[
        "check",
        mesh.to_str().unwrap(),
        "--render",
        by_check.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(1), "{:?}", text(&run));
    let shows = "non-manifold,seams,split,flipped,dropped";
    let args = [
        "render",
        mesh.to_str().unwrap(),
        "-o",
        by_render.to_str().unwrap(),
        "--show",
        shows,
    ];
    assert!(topomesh(&args).status.success());
    assert_eq!(
        std::fs::read(&by_check).unwrap(),
        std::fs::read(&by_render).unwrap()
    );
}

#[test]
fn the_same_mesh_gives_the_same_bytes() {
    let (positions, triangles) = holed_grid();
    let mesh = temp("same.off", &off(&positions, &triangles));
    for ext in ["png", "svg"] {
        let (a, b) = (out(&format!("same-a.{ext}")), out(&format!("same-b.{ext}")));
        render(
            &mesh,
            &a,
            &["--view", "iso", "--show", "boundary,components"],
        );
        render(
            &mesh,
            &b,
            &["--view", "iso", "--show", "boundary,components"],
        );
        let (a, b) = (std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
        assert!(a.len() > 100);
        assert_eq!(a, b, "{ext}");
    }
}

/// Two triangles apart: two components, two colours.
#[test]
fn components_have_their_own_colours() {
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [5.0, 0.0, 0.0],
        [6.0, 0.0, 0.0],
        [5.0, 1.0, 0.0],
    ];
    let mesh = temp("two.off", &off(&positions, &[[0, 1, 2], [3, 4, 5]]));
    let svg_path = out("two.svg");
    render(&mesh, &svg_path, &["--show", "components"]);
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    let fills: BTreeSet<&str> = svg
        .lines()
        .filter(|l| l.starts_with("<polygon"))
        .map(|l| attr(l, "fill").unwrap())
        .collect();
    assert_eq!(fills.len(), 2, "{fills:?}");
    assert!(svg.contains(">2 components<"), "{svg}");
}

/// Two tetrahedra sharing only vertex 0: every vertex and edge on the boundary, vertex 0
/// non-manifold; a cut through the first shows its four faces.
#[test]
fn volume_classes_and_cut() {
    let node =
        "7 3 0 0\n0 0 0 0\n1 -1 0 0\n2 -0.2 1 0\n3 -0.2 0 1\n4 1 0 0\n5 0.2 1 0\n6 0.2 0 -1\n";
    let ele = "2 4 0\n0 0 1 2 3\n1 0 4 5 6\n";
    let mesh = temp("two-tets.ele", ele);
    temp("two-tets.node", node);
    let json = check_json(&mesh);
    assert_eq!(
        listed(&json, "non_manifold_vertices"),
        [serde_json::json!(0)]
    );
    let svg_path = out("two-tets.svg");
    render(&mesh, &svg_path, &["--show", "classes"]);
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    let all = marks(&svg);
    let lines = |class: &str| {
        all.iter()
            .filter(|m| m.class == class && m.at.len() == 2)
            .count()
    };
    assert_eq!((lines("boundary"), lines("interior")), (12, 0));
    let nm: Vec<_> = all
        .iter()
        .filter(|m| m.class == "non-manifold" && m.at.len() == 1)
        .collect();
    assert_eq!(nm.len(), 1);
    assert_eq!(nm[0].ids, [0]);
    let boundary_dots: BTreeSet<u32> = (all
        .iter()
        .filter(|m| m.class == "boundary" && m.at.len() == 1))
    .map(|m| m.ids[0])
    .collect();
    assert_eq!(boundary_dots, (0..7).collect());

    let cut_path = out("two-tets-cut.svg");
    render(&mesh, &cut_path, &["--cut", "x=0.25"]);
    let svg = std::fs::read_to_string(&cut_path).unwrap();
    assert_eq!(svg.matches("<polygon").count(), 4, "{svg}");
}

#[test]
fn what_cannot_be_drawn_is_a_clear_error() {
    let image = out("never.png");
    let empty = temp("empty.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
    let nan = temp("nan.off", "OFF\n3 1 0\nnan 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    let cases: [(&Path, &str); 2] = [(&empty, "empty mesh"), (&nan, "NaN")];
    for (mesh, says) in cases {
        let run = topomesh(&[
            "render",
            mesh.to_str().unwrap(),
            "-o",
            image.to_str().unwrap(),
        ]);
        let (_, stderr) = text(&run);
        assert_eq!(run.status.code(), Some(3), "{stderr}");
        assert!(stderr.contains(says), "{stderr}");
        assert!(!image.exists());
    }
    // A level file of a surface built without positions.
    let che = topomesh::Che::from_triangles(&[[0, 1, 2]], 3, &[], topomesh::BuildOptions::level(3))
        .unwrap();
    let bare = out("bare.che");
    che.save(&bare).unwrap();
    let run = topomesh(&[
        "render",
        bare.to_str().unwrap(),
        "-o",
        image.to_str().unwrap(),
    ]);
    let (_, stderr) = text(&run);
    assert_eq!(run.status.code(), Some(3), "{stderr}");
    assert!(stderr.contains("no vertex positions"), "{stderr}");

    let tri = temp("tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    let tri = tri.to_str().unwrap();
    for bad in [
        vec!["--show", "boundary,holes"],
        vec!["--view", "back"],
        vec!["--size", "10x10"],
        vec!["--cut", "w=0.5"],
    ] {
        let mut args = vec!["render", tri, "-o", image.to_str().unwrap()];
        args.extend(&bad);
        assert_eq!(topomesh(&args).status.code(), Some(2), "{bad:?}");
    }
    assert_eq!(
        topomesh(&["render", tri, "-o", "x.jpg"]).status.code(),
        Some(2)
    );
    assert!(!image.exists());
}
