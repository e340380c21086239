//! The charts drawn from a small fixed results file: the points and bars in the SVG text
//! carry the values computed by hand from the file, at the places the axes give.

use topomesh_plot::charts::{Labels, build_chart, memory_chart, ratio_chart};
use topomesh_plot::results::Results;

const RESULTS: &str = "\
mesh\telements\tlibrary\tkind\tpath\tquantity\tvalue
# two meshes; two peers and two topomesh levels, the second with two access paths
small\t100\tOpenMesh\tpeer\t\tbuild_ms\t2
small\t100\tOpenMesh\tpeer\t\tmemory_bytes\t4000
small\t100\tCGAL\tpeer\t\tbuild_ms\t1.5
small\t100\tCHE L1\ttopomesh\tC API\tbuild_ms\t0.5
small\t100\tCHE L2\ttopomesh\tC API\tbuild_ms\t0.6
big\t10000\tOpenMesh\tpeer\t\tbuild_ms\t200
big\t10000\tOpenMesh\tpeer\t\tmemory_bytes\t400000
big\t10000\tOpenMesh\tpeer\t\tVV\t10
big\t10000\tOpenMesh\tpeer\t\tFF\t4
big\t10000\tOpenMesh\tpeer\t\tcurves\t1
big\t10000\tCGAL\tpeer\t\tbuild_ms\t100
big\t10000\tCGAL\tpeer\t\tmemory_bytes\t410000
big\t10000\tCGAL\tpeer\t\tVV\t8
big\t10000\tCGAL\tpeer\t\tFF\t5
big\t10000\tCHE L1\ttopomesh\t\tbuild_ms\t50
big\t10000\tCHE L1\ttopomesh\t\tmemory_bytes\t160000
big\t10000\tCHE L1\ttopomesh\tCSR bulk\tVV\t16
big\t10000\tCHE L1\ttopomesh\tzero-copy\tFF\t2
big\t10000\tCHE L2\ttopomesh\t\tbuild_ms\t40
big\t10000\tCHE L2\ttopomesh\t\tmemory_bytes\t200000
big\t10000\tCHE L2\ttopomesh\tC API\tVV\t6
big\t10000\tCHE L2\ttopomesh\tzero-copy\tVV\t4
big\t10000\tCHE L2\ttopomesh\tC API\tFF\t3
big\t10000\tCHE L2\ttopomesh\tzero-copy\tFF\t1
";

/// Every element of `svg` that starts with `<tag class="class"`, as its attributes.
fn elements(svg: &str, tag: &str, class: &str) -> Vec<Vec<(String, String)>> {
    let start = format!("<{tag} class=\"{class}\"");
    let mut out = Vec::new();
    for piece in svg.split('<').skip(1) {
        let el = format!("<{piece}");
        if !el.starts_with(&start) {
            continue;
        }
        let body = &el[tag.len() + 1..el.find('>').unwrap()];
        let mut attrs = Vec::new();
        for kv in body
            .split("\" ")
            .map(|s| s.trim().trim_end_matches('/').trim_end_matches('"'))
        {
            if let Some((k, v)) = kv.split_once("=\"") {
                attrs.push((k.to_string(), v.to_string()));
            }
        }
        out.push(attrs);
    }
    out
}

fn get<'a>(attrs: &'a [(String, String)], key: &str) -> &'a str {
    &attrs
        .iter()
        .find(|(k, _)| k == key)
        .unwrap_or_else(|| panic!("no {key} in {attrs:?}"))
        .1
}

fn num(attrs: &[(String, String)], key: &str) -> f64 {
    get(attrs, key).parse().unwrap()
}

fn labels() -> Labels<'static> {
    Labels {
        element: "triangle",
    }
}

#[test]
fn memory_chart_has_one_point_per_library_on_the_largest_mesh() {
    let res = Results::parse(RESULTS).unwrap();
    let svg = memory_chart(&res, &labels()).unwrap();
    let pts = elements(&svg, "circle", "point");
    let got: Vec<(String, f64, f64)> = pts
        .iter()
        .map(|p| {
            (
                get(p, "data-series").to_string(),
                num(p, "data-x"),
                num(p, "data-y"),
            )
        })
        .collect();
    // Bytes per triangle on "big"; time = VV + FF at each library's fastest path ("curves"
    // is left out: not every library ran it).
    let want = vec![
        ("OpenMesh".to_string(), 40.0, 14.0),
        ("CGAL".to_string(), 41.0, 13.0),
        ("CHE L1".to_string(), 16.0, 18.0),
        ("CHE L2".to_string(), 20.0, 5.0),
    ];
    assert_eq!(got, want);
    assert!(
        svg.contains("VV + FF"),
        "the y label names the sweeps summed"
    );
    // Placed by the axes: a smaller x is further left, a smaller time lower (larger y).
    let cx: Vec<f64> = pts.iter().map(|p| num(p, "cx")).collect();
    let cy: Vec<f64> = pts.iter().map(|p| num(p, "cy")).collect();
    assert!(cx[2] < cx[3] && cx[3] < cx[0] && cx[0] < cx[1]);
    assert!(cy[3] > cy[1] && cy[1] > cy[0] && cy[0] > cy[2]);
}

#[test]
fn build_chart_is_log_log_with_a_line_per_library() {
    let res = Results::parse(RESULTS).unwrap();
    let svg = build_chart(&res, &labels()).unwrap();
    let lines = elements(&svg, "polyline", "series");
    let names: Vec<&str> = lines.iter().map(|l| get(l, "data-series")).collect();
    assert_eq!(names, ["OpenMesh", "CGAL", "CHE L1", "CHE L2"]);
    let pts = elements(&svg, "circle", "point");
    assert_eq!(pts.len(), 8);
    let om: Vec<(f64, f64)> = pts
        .iter()
        .filter(|p| get(p, "data-series") == "OpenMesh")
        .map(|p| (num(p, "data-x"), num(p, "data-y")))
        .collect();
    assert_eq!(om, [(100.0, 2.0), (10000.0, 200.0)]);
    // Log scales: OpenMesh's 100x in size and in time span the same pixel distance on
    // each axis as two decades do; CHE L1's two points (100x in size) the same x distance.
    let at = |s: &str, x: f64| {
        let p = pts
            .iter()
            .find(|p| get(p, "data-series") == s && num(p, "data-x") == x)
            .unwrap();
        (num(p, "cx"), num(p, "cy"))
    };
    let (a, b) = (at("OpenMesh", 100.0), at("OpenMesh", 10000.0));
    let (c, d) = (at("CHE L1", 100.0), at("CHE L1", 10000.0));
    assert!((b.0 - a.0 - (d.0 - c.0)).abs() < 0.15);
    // 0.5 -> 50 ms is also two decades: the same rise as OpenMesh's 2 -> 200 ms.
    assert!(((a.1 - b.1) - (c.1 - d.1)).abs() < 0.15);
}

#[test]
fn ratio_chart_has_a_bar_per_level_and_quantity() {
    let res = Results::parse(RESULTS).unwrap();
    let svg = ratio_chart(&res).unwrap();
    let bars = elements(&svg, "rect", "bar");
    let got: Vec<(String, String, f64)> = bars
        .iter()
        .map(|b| {
            (
                get(b, "data-group").to_string(),
                get(b, "data-series").to_string(),
                num(b, "data-value"),
            )
        })
        .collect();
    // Faster (smaller) peer over topomesh's best path.
    let want = [
        ("build", "CHE L1", 100.0 / 50.0),
        ("build", "CHE L2", 100.0 / 40.0),
        ("memory", "CHE L1", 400000.0 / 160000.0),
        ("memory", "CHE L2", 400000.0 / 200000.0),
        ("VV", "CHE L1", 8.0 / 16.0),
        ("VV", "CHE L2", 8.0 / 4.0),
        ("FF", "CHE L1", 4.0 / 2.0),
        ("FF", "CHE L2", 4.0 / 1.0),
    ];
    assert_eq!(got.len(), want.len());
    for (g, w) in got.iter().zip(want) {
        assert_eq!((g.0.as_str(), g.1.as_str()), (w.0, w.1));
        assert!((g.2 - w.2).abs() < 1e-12, "{g:?} against {w:?}");
    }
    // A bar above 1 rises from the line at 1; one below hangs from it.
    let vv1 = &bars[4];
    let ff2 = &bars[7];
    let top_of = |b: &Vec<(String, String)>| num(b, "y");
    let bottom_of = |b: &Vec<(String, String)>| num(b, "y") + num(b, "height");
    assert!(
        (top_of(vv1) - bottom_of(ff2)).abs() < 0.2,
        "both meet the line at 1"
    );
}

#[test]
fn same_results_same_bytes() {
    let res = Results::parse(RESULTS).unwrap();
    assert_eq!(
        memory_chart(&res, &labels()).unwrap(),
        memory_chart(&res, &labels()).unwrap()
    );
    assert_eq!(ratio_chart(&res).unwrap(), ratio_chart(&res).unwrap());
}

#[test]
fn bad_results_are_refused_with_the_line() {
    let e = Results::parse("small\t100\tOpenMesh\tpeer\t\tbuild_ms\n").unwrap_err();
    assert!(e.contains("line 1") && e.contains("6 fields"), "{e}");
    let e = Results::parse("a\t1\tX\tpeer\t\tbuild_ms\t2\nb\t1\tX\tfriend\t\tbuild_ms\t2\n")
        .unwrap_err();
    assert!(e.contains("line 2") && e.contains("friend"), "{e}");
    let e = Results::parse("a\t1\tX\tpeer\t\tbuild_ms\tNaN\n").unwrap_err();
    assert!(e.contains("NaN"), "{e}");
    assert!(memory_chart(&Results::default(), &labels()).is_err());
    let only_peers = Results::parse("a\t1\tX\tpeer\t\tbuild_ms\t2\n").unwrap();
    assert!(
        ratio_chart(&only_peers)
            .unwrap_err()
            .contains("no topomesh")
    );
}
