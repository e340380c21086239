//! The benchmark results the scripts write: one measurement per line, tab-separated,
//! `mesh elements library kind path quantity value`, where `kind` is `peer` or `topomesh`,
//! `quantity` is `build_ms`, `memory_bytes` or a sweep name (its time in ms), and `path`
//! the access path (empty when there is one). Lines starting with `#` and a header line
//! starting with `mesh` are skipped.

/// One measurement.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    pub mesh: String,
    pub elements: u64,
    pub library: String,
    pub peer: bool,
    pub path: String,
    pub quantity: String,
    pub value: f64,
}

pub const BUILD: &str = "build_ms";
pub const MEMORY: &str = "memory_bytes";

/// All the measurements of a run.
#[derive(Clone, Debug, Default)]
pub struct Results {
    pub rows: Vec<Row>,
}

fn parse_line(n: usize, line: &str) -> Result<Row, String> {
    let f: Vec<&str> = line.split('\t').collect();
    if f.len() != 7 {
        return Err(format!("line {n}: {} fields, expected 7", f.len()));
    }
    let number = |s: &str, what: &str| -> Result<f64, String> {
        s.trim()
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite() && *v >= 0.0)
            .ok_or_else(|| format!("line {n}: {what} {s:?} is not a non-negative number"))
    };
    let peer = match f[3] {
        "peer" => true,
        "topomesh" => false,
        k => return Err(format!("line {n}: kind {k:?} is neither peer nor topomesh")),
    };
    Ok(Row {
        mesh: f[0].to_string(),
        elements: number(f[1], "elements")? as u64,
        library: f[2].to_string(),
        peer,
        path: f[4].to_string(),
        quantity: f[5].to_string(),
        value: number(f[6], "value")?,
    })
}

impl Results {
    /// Parses the text of a results file.
    pub fn parse(text: &str) -> Result<Results, String> {
        let mut rows = Vec::new();
        for (i, line) in text.lines().enumerate() {
            if line.trim().is_empty() || line.starts_with('#') || line.starts_with("mesh\t") {
                continue;
            }
            rows.push(parse_line(i + 1, line)?);
        }
        Ok(Results { rows })
    }

    /// The mesh with the most elements (the first of them on a tie).
    pub fn largest_mesh(&self) -> Option<(&str, u64)> {
        let mut best: Option<(&str, u64)> = None;
        for r in &self.rows {
            if best.is_none_or(|(_, e)| r.elements > e) {
                best = Some((&r.mesh, r.elements));
            }
        }
        best
    }

    /// Distinct values of `key` over the rows that pass `keep`, in order of appearance.
    fn distinct<'a>(
        &'a self, keep: impl Fn(&Row) -> bool, key: impl Fn(&'a Row) -> &'a str,
    ) -> Vec<&'a str> {
        let mut out: Vec<&str> = Vec::new();
        for r in self.rows.iter().filter(|r| keep(r)) {
            let k = key(r);
            if !out.contains(&k) {
                out.push(k);
            }
        }
        out
    }

    /// The libraries measured on `mesh`, in order of appearance.
    pub fn libraries(&self, mesh: &str) -> Vec<&str> {
        self.distinct(|r| r.mesh == mesh, |r| &r.library)
    }

    /// Where `library` first appears among all the rows: its colour in every chart.
    pub fn library_index(&self, library: &str) -> usize {
        let all = self.distinct(|_| true, |r| &r.library);
        all.iter().position(|l| *l == library).unwrap_or(all.len())
    }

    pub fn is_peer(&self, library: &str) -> bool {
        self.rows.iter().any(|r| r.library == library && r.peer)
    }

    /// The smallest value of `quantity` for `library` on `mesh` over its access paths.
    pub fn best(&self, mesh: &str, library: &str, quantity: &str) -> Option<f64> {
        self.rows
            .iter()
            .filter(|r| r.mesh == mesh && r.library == library && r.quantity == quantity)
            .map(|r| r.value)
            .reduce(f64::min)
    }

    /// The sweeps every library ran on `mesh`, in order of appearance.
    pub fn common_sweeps(&self, mesh: &str) -> Vec<&str> {
        let libs = self.libraries(mesh);
        self.distinct(
            |r| r.mesh == mesh && r.quantity != BUILD && r.quantity != MEMORY,
            |r| &r.quantity,
        )
        .into_iter()
        .filter(|q| libs.iter().all(|l| self.best(mesh, l, q).is_some()))
        .collect()
    }

    /// The build times of `library` as (elements, ms), by size.
    pub fn build_series(&self, library: &str) -> Vec<(f64, f64)> {
        let mut pts: Vec<(f64, f64)> = self
            .rows
            .iter()
            .filter(|r| r.library == library && r.quantity == BUILD && r.value > 0.0)
            .map(|r| (r.elements as f64, r.value))
            .collect();
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        pts
    }

    /// Every library with a build time, in order of appearance.
    pub fn built_libraries(&self) -> Vec<&str> {
        self.distinct(|r| r.quantity == BUILD, |r| &r.library)
    }
}
