//! `Che::release_mapped_pages`, in a test binary of its own: it reads the process's
//! resident file pages, which other tests mapping files at the same time would move.

use topomesh::generate::torus;
use topomesh::levelfile::{OpenOptions, Verify};
use topomesh::{BuildOptions, Che};

/// `release_mapped_pages` takes a mapped file's pages out of the resident set, and the
/// queries answer as before from the pages read again.
#[cfg(target_os = "linux")]
#[test]
fn released_pages_leave_the_resident_set_and_come_back() {
    let rss_file = || {
        let status = std::fs::read_to_string("/proc/self/status").unwrap();
        let line = status.lines().find(|l| l.starts_with("RssFile:")).unwrap();
        line.split_whitespace()
            .nth(1)
            .unwrap()
            .parse::<u64>()
            .unwrap()
            * 1024
    };
    let dir = std::env::temp_dir().join(format!("topomesh-release-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("t.che");
    let s = torus(1000, 600);
    let built = Che::from_triangles(
        &s.triangles,
        s.positions.len(),
        &s.positions,
        BuildOptions::level(2),
    );
    built.unwrap().save(&path).unwrap();
    let che = Che::open(&path, OpenOptions::mapped(Verify::Trusted)).unwrap();
    let sweep = |che: &Che| -> u64 {
        (0..che.num_vertices() as u32)
            .flat_map(|x| che.vertex_vertices(x))
            .map(u64::from)
            .sum()
    };
    let before = sweep(&che);
    let touched = rss_file();
    che.release_mapped_pages().unwrap();
    let released = rss_file();
    assert!(
        touched > 20 << 20 && released < touched / 4,
        "resident file pages {touched} B before the release, {released} B after"
    );
    assert_eq!(sweep(&che), before);
    drop(che);
    let _ = std::fs::remove_dir_all(&dir);
}
