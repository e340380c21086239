//! A build tells its progress hook how far it is: fractions that never decrease, from 0 to
//! 1, each with the name of the step that starts, the same at every level and thread count.

mod chf_common;

use std::sync::Mutex;
use topomesh::{BuildOptions, BuildProgress, Che, Chf, chf, generate};

/// The calls a hook received.
fn recorded(build: impl FnOnce(BuildProgress)) -> Vec<(f64, String)> {
    let calls = Mutex::new(Vec::new());
    let hook = |fraction: f64, step: &str| calls.lock().unwrap().push((fraction, step.to_string()));
    build(BuildProgress::new(&hook));
    calls.into_inner().unwrap()
}

fn check(calls: &[(f64, String)], what: &str) {
    assert!(calls.len() >= 4, "{what}: {calls:?}");
    assert_eq!(calls[0].0, 0.0, "{what}: {calls:?}");
    assert_eq!(calls.last().unwrap(), &(1.0, "done".to_string()), "{what}");
    assert!(
        calls.windows(2).all(|w| w[0].0 <= w[1].0),
        "{what}: {calls:?}"
    );
    assert!(
        calls.iter().all(|(_, step)| !step.is_empty()),
        "{what}: {calls:?}"
    );
}

#[test]
fn both_builds_report_every_step_in_order() {
    let grid = generate::grid(40, 30);
    let tets = chf_common::cube(6, 6, 6, false);
    for level in 0..=3u8 {
        for threads in [1, 2] {
            let what = format!("level {level}, {threads} threads");
            let calls = recorded(|p| {
                let options = BuildOptions {
                    level,
                    threads,
                    ..BuildOptions::default()
                };
                let n = grid.positions.len();
                Che::from_triangles_with_progress(&grid.triangles, n, &grid.positions, options, p)
                    .unwrap();
            });
            check(&calls, &format!("CHE {what}"));
            let calls = recorded(|p| {
                let options = chf::BuildOptions {
                    level,
                    threads,
                    ..Default::default()
                };
                let n = tets.positions.len();
                Chf::from_tetrahedra_with_progress(&tets.tets, n, &tets.positions, options, p)
                    .unwrap();
            });
            check(&calls, &format!("CHF {what}"));
        }
    }
}

#[test]
fn a_failed_build_never_reports_done() {
    let calls = recorded(|p| {
        let options = BuildOptions {
            strict: true,
            ..BuildOptions::default()
        };
        // Three triangles on one edge: refused in strict mode.
        let tris = [[0, 1, 2], [1, 0, 3], [0, 1, 4]];
        assert!(Che::from_triangles_with_progress(&tris, 5, &[], options, p).is_err());
    });
    assert!(calls.iter().all(|(f, _)| *f < 1.0), "{calls:?}");
}
