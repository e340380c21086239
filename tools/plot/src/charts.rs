//! The three charts of a benchmark page: memory against sweep time (the thesis's first
//! figure), build time against mesh size (log-log), and the per-relation ratios as bars.

use crate::results::{BUILD, MEMORY, Results};
use crate::svg::{Axis, Frame, PALETTE, Svg};

/// What the page measures, for the labels: "triangle" or "tetrahedron".
pub struct Labels<'a> {
    pub element: &'a str,
}

impl Labels<'_> {
    /// The element's plural, for the axis and title labels.
    pub fn elements(&self) -> String {
        match self.element.strip_suffix("on") {
            Some(stem) if self.element.ends_with("hedron") => format!("{stem}a"),
            _ => format!("{}s", self.element),
        }
    }
}

const W: f64 = 760.0;
const H: f64 = 460.0;

fn frame(x: Axis, y: Axis) -> Frame {
    Frame {
        left: 80.0,
        top: 40.0,
        width: W - 80.0 - 200.0,
        height: H - 40.0 - 60.0,
        x,
        y,
    }
}

/// A library's colour, the same in every chart of a page.
fn colour(res: &Results, library: &str) -> &'static str {
    PALETTE[res.library_index(library) % PALETTE.len()]
}

/// Bytes per element against the summed time of the sweeps every library ran, on the
/// largest mesh; one point per library (per level for topomesh).
pub fn memory_chart(res: &Results, labels: &Labels) -> Result<String, String> {
    let (mesh, elements) = res.largest_mesh().ok_or("no results")?;
    let sweeps = res.common_sweeps(mesh);
    if sweeps.is_empty() {
        return Err(format!("{mesh}: no sweep that every library ran"));
    }
    let mut pts = Vec::new();
    for lib in res.libraries(mesh) {
        let (Some(mem), Some(time)) = (
            res.best(mesh, lib, MEMORY),
            sweeps
                .iter()
                .map(|q| res.best(mesh, lib, q))
                .sum::<Option<f64>>(),
        ) else {
            continue;
        };
        pts.push((lib, mem / elements as f64, time));
    }
    let xs: Vec<f64> = pts.iter().map(|p| p.1).collect();
    let ys: Vec<f64> = pts.iter().map(|p| p.2).collect();
    let f = frame(
        Axis::linear(&xs, &format!("connectivity bytes per {}", labels.element)),
        Axis::linear(
            &ys,
            &format!(
                "sweep time, ms: {} (fastest access path)",
                sweeps.join(" + ")
            ),
        ),
    );
    let mut svg = Svg::new(
        W,
        H,
        &format!(
            "Memory against sweep time: {mesh} ({elements} {})",
            labels.elements()
        ),
    );
    svg.axes(&f);
    let mut legend = Vec::new();
    for (lib, x, y) in &pts {
        svg.raw(&format!(
            "<circle class=\"point\" data-series=\"{}\" data-x=\"{x}\" data-y=\"{y}\" cx=\"{:.1}\" cy=\"{:.1}\" r=\"6\" fill=\"{}\" fill-opacity=\"0.85\" stroke=\"white\"/>",
            crate::svg::esc(lib),
            f.px(*x),
            f.py(*y),
            colour(res, lib)
        ));
        legend.push((lib.to_string(), colour(res, lib)));
    }
    svg.legend(f.left + f.width + 20.0, f.top + 10.0, &legend);
    Ok(svg.finish())
}

/// Build time against the number of elements, log-log, one line per library.
pub fn build_chart(res: &Results, labels: &Labels) -> Result<String, String> {
    let libs = res.built_libraries();
    let series: Vec<(&str, Vec<(f64, f64)>)> =
        libs.iter().map(|l| (*l, res.build_series(l))).collect();
    let all: Vec<(f64, f64)> = series.iter().flat_map(|s| s.1.iter().copied()).collect();
    if all.is_empty() {
        return Err("no build times".into());
    }
    let xs: Vec<f64> = all.iter().map(|p| p.0).collect();
    let ys: Vec<f64> = all.iter().map(|p| p.1).collect();
    let f = frame(
        Axis::log(&xs, &[], &format!("{} (log)", labels.elements())),
        Axis::log(&ys, &[], "build time, ms (log)"),
    );
    let mut svg = Svg::new(
        W,
        H,
        "Build time against mesh size (topomesh on one thread)",
    );
    svg.axes(&f);
    let mut legend = Vec::new();
    for (lib, pts) in &series {
        let c = colour(res, lib);
        let path: Vec<String> = pts
            .iter()
            .map(|(x, y)| format!("{:.1},{:.1}", f.px(*x), f.py(*y)))
            .collect();
        svg.raw(&format!(
            "<polyline class=\"series\" data-series=\"{}\" points=\"{}\" fill=\"none\" stroke=\"{c}\" stroke-width=\"2\"/>",
            crate::svg::esc(lib),
            path.join(" ")
        ));
        for (x, y) in pts {
            svg.raw(&format!(
                "<circle class=\"point\" data-series=\"{}\" data-x=\"{x}\" data-y=\"{y}\" cx=\"{:.1}\" cy=\"{:.1}\" r=\"4\" fill=\"{c}\"/>",
                crate::svg::esc(lib),
                f.px(*x),
                f.py(*y)
            ));
        }
        legend.push((lib.to_string(), c));
    }
    svg.legend(f.left + f.width + 20.0, f.top + 10.0, &legend);
    Ok(svg.finish())
}

/// The ratios of one mesh: per topomesh library, one per group (None where not measured).
pub struct Ratios {
    pub mesh: String,
    pub groups: Vec<String>,
    pub bars: Vec<(String, Vec<Option<f64>>)>,
}

/// For each quantity (build, memory, every common sweep) and each topomesh library on the
/// largest mesh: the faster peer's value over topomesh's (above 1: topomesh is faster or
/// smaller), both at their best access path.
pub fn ratios(res: &Results) -> Result<Ratios, String> {
    let (mesh, _) = res.largest_mesh().ok_or("no results")?;
    let mut groups: Vec<String> = vec![BUILD.into(), MEMORY.into()];
    groups.extend(res.common_sweeps(mesh).into_iter().map(String::from));
    let libs = res.libraries(mesh);
    let peers: Vec<&str> = libs.iter().copied().filter(|l| res.is_peer(l)).collect();
    if peers.is_empty() {
        return Err(format!("{mesh}: no peer to compare with"));
    }
    let mut bars = Vec::new();
    for lib in libs.iter().filter(|l| !res.is_peer(l)) {
        let vals = groups
            .iter()
            .map(|q| {
                let peer = peers
                    .iter()
                    .filter_map(|p| res.best(mesh, p, q))
                    .reduce(f64::min)?;
                let ours = res.best(mesh, lib, q).filter(|v| *v > 0.0)?;
                Some(peer / ours)
            })
            .collect();
        bars.push((lib.to_string(), vals));
    }
    if bars.is_empty() {
        return Err(format!("{mesh}: no topomesh library"));
    }
    Ok(Ratios {
        mesh: mesh.to_string(),
        groups,
        bars,
    })
}

fn group_label(q: &str) -> &str {
    match q {
        BUILD => "build",
        MEMORY => "memory",
        q => q,
    }
}

/// The ratios as bars from 1 (log scale), grouped by quantity.
pub fn ratio_chart(res: &Results) -> Result<String, String> {
    let Ratios { mesh, groups, bars } = ratios(res)?;
    let vals: Vec<f64> = bars
        .iter()
        .flat_map(|b| b.1.iter().flatten().copied())
        .collect();
    let f = frame(
        Axis {
            min: 0.0,
            max: groups.len() as f64,
            log: false,
            label: String::new(),
        },
        Axis::log(
            &vals,
            &[1.0],
            "faster peer ÷ topomesh (log; above 1: topomesh faster or smaller)",
        ),
    );
    let mut svg = Svg::new(W, H, &format!("topomesh against the faster peer: {mesh}"));
    let mut labelled = f.clone();
    labelled.x.label = "quantity (fastest access path of each library)".into();
    svg.axes_with(&labelled, false);
    let slot = f.width / groups.len() as f64;
    let bw = slot * 0.8 / bars.len().max(1) as f64;
    let one = f.py(1.0);
    for (g, q) in groups.iter().enumerate() {
        let x0 = f.left + slot * g as f64 + slot * 0.1;
        svg.text(
            x0 + slot * 0.4,
            f.top + f.height + 16.0,
            "middle",
            group_label(q),
        );
        for (i, (lib, vs)) in bars.iter().enumerate() {
            let Some(v) = vs[g] else { continue };
            let y = f.py(v);
            let x = x0 + bw * i as f64;
            svg.raw(&format!(
                "<rect class=\"bar\" data-group=\"{}\" data-series=\"{}\" data-value=\"{v}\" x=\"{:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"{}\"/>",
                group_label(q),
                crate::svg::esc(lib),
                x,
                y.min(one),
                bw * 0.9,
                (y - one).abs().max(0.5),
                colour(res, lib)
            ));
            let label_y = if v >= 1.0 {
                y.min(one) - 3.0
            } else {
                y.max(one) + 10.0
            };
            svg.raw(&format!(
                "<text x=\"{:.1}\" y=\"{label_y:.1}\" text-anchor=\"middle\" font-size=\"9\">{v:.1}</text>",
                x + bw * 0.45
            ));
        }
    }
    svg.line(
        (f.left, one),
        (f.left + f.width, one),
        "stroke=\"#000\" stroke-width=\"1.5\"",
    );
    let legend: Vec<(String, &str)> = bars
        .iter()
        .map(|b| (b.0.clone(), colour(res, &b.0)))
        .collect();
    svg.legend(f.left + f.width + 20.0, f.top + 10.0, &legend);
    Ok(svg.finish())
}
