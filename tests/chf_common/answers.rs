//! The structure's answers to every relation, and their check against the reference.

use super::mesh::sorted;
use super::reference::{EdgeKey, FaceKey, Reference};
use std::collections::BTreeSet;
use topomesh::NONE;
use topomesh::chf::Chf;

/// Every relation of every element, as the structure answers it (ids, in its order).
#[derive(Debug, PartialEq, Eq)]
pub struct Answers {
    pub vv: Vec<Vec<u32>>,
    pub ve: Vec<Vec<u32>>,
    pub vf: Vec<Vec<u32>>,
    pub vt: Vec<Vec<u32>>,
    pub ev: Vec<[u32; 2]>,
    pub ee: Vec<Vec<u32>>,
    pub ef: Vec<Vec<u32>>,
    pub et: Vec<Vec<u32>>,
    pub fv: Vec<[u32; 3]>,
    pub fe: Vec<[u32; 3]>,
    pub ff: Vec<Vec<u32>>,
    pub ft: Vec<Vec<u32>>,
    pub tv: Vec<[u32; 4]>,
    pub te: Vec<[u32; 6]>,
    pub tf: Vec<[u32; 4]>,
    pub tt: Vec<[u32; 4]>,
    pub boundary: (Vec<bool>, Vec<bool>, Vec<bool>),
}

pub fn answers(chf: &Chf) -> Answers {
    let nv = chf.num_vertices() as u32;
    let ne = chf.num_edges() as u32;
    let nf = chf.num_faces() as u32;
    let nt = chf.num_tetrahedra() as u32;
    Answers {
        vv: (0..nv).map(|v| chf.vertex_vertices(v).collect()).collect(),
        ve: (0..nv).map(|v| chf.vertex_edges(v).collect()).collect(),
        vf: (0..nv).map(|v| chf.vertex_faces(v).collect()).collect(),
        vt: (0..nv)
            .map(|v| chf.vertex_tetrahedra(v).collect())
            .collect(),
        ev: (0..ne).map(|e| chf.edge_vertices(e)).collect(),
        ee: (0..ne).map(|e| chf.edge_edges(e).collect()).collect(),
        ef: (0..ne).map(|e| chf.edge_faces(e).collect()).collect(),
        et: (0..ne).map(|e| chf.edge_tetrahedra(e).collect()).collect(),
        fv: (0..nf).map(|f| chf.face_vertices(f)).collect(),
        fe: (0..nf).map(|f| chf.face_edges(f)).collect(),
        ff: (0..nf).map(|f| chf.face_faces(f).to_vec()).collect(),
        ft: (0..nf).map(|f| chf.face_tetrahedra(f).to_vec()).collect(),
        tv: (0..nt).map(|t| chf.tetrahedron_vertices(t)).collect(),
        te: (0..nt).map(|t| chf.tetrahedron_edges(t)).collect(),
        tf: (0..nt).map(|t| chf.tetrahedron_faces(t)).collect(),
        tt: (0..nt).map(|t| chf.tetrahedron_tetrahedra(t)).collect(),
        boundary: (
            (0..nv).map(|v| chf.is_boundary_vertex(v)).collect(),
            (0..ne).map(|e| chf.is_boundary_edge(e)).collect(),
            (0..nf).map(|f| chf.is_boundary_face(f)).collect(),
        ),
    }
}

fn set<T: Ord + Clone>(xs: impl IntoIterator<Item = T>) -> BTreeSet<T> {
    xs.into_iter().collect()
}

fn once<T: Ord + Clone + std::fmt::Debug>(xs: &[T], what: &str) -> BTreeSet<T> {
    let s = set(xs.iter().cloned());
    assert_eq!(s.len(), xs.len(), "{what}: repeated ids in {xs:?}");
    s
}

/// Checks every relation of `a` (answers of `chf`) against the reference, as sets, plus
/// the rotation order around every edge.
pub fn check_against_reference(chf: &Chf, a: &Answers, r: &Reference) {
    let edge_key = |e: u32| -> EdgeKey {
        let mut ts = a.et[e as usize].clone();
        ts.sort_unstable();
        (sorted(a.ev[e as usize]), ts)
    };
    let face_key = |f: u32| -> FaceKey {
        let mut ts = a.ft[f as usize].clone();
        ts.sort_unstable();
        (sorted(a.fv[f as usize]), ts)
    };
    // Ids name the reference's edges and faces one-to-one.
    let edges: Vec<EdgeKey> = (0..chf.num_edges() as u32).map(edge_key).collect();
    let faces: Vec<FaceKey> = (0..chf.num_faces() as u32).map(face_key).collect();
    assert_eq!(once(&edges, "edges"), set(r.edges.iter().cloned()));
    assert_eq!(once(&faces, "faces"), set(r.faces.iter().cloned()));
    let ek = |ids: &[u32]| {
        ids.iter()
            .map(|&e| edges[e as usize].clone())
            .collect::<Vec<_>>()
    };
    let fk = |ids: &[u32]| {
        ids.iter()
            .map(|&f| faces[f as usize].clone())
            .collect::<Vec<_>>()
    };

    for v in 0..chf.num_vertices() as u32 {
        let i = v as usize;
        assert_eq!(once(&a.vt[i], "VT"), r.vt(v), "VT({v})");
        assert_eq!(once(&a.vv[i], "VV"), r.vv(v), "VV({v})");
        assert_eq!(once(&ek(&a.ve[i]), "VE"), r.ve(v), "VE({v})");
        assert_eq!(once(&fk(&a.vf[i]), "VF"), r.vf(v), "VF({v})");
        let on_boundary = r.vf(v).iter().any(Reference::boundary_face);
        assert_eq!(a.boundary.0[i], on_boundary, "boundary vertex {v}");
    }
    for e in 0..chf.num_edges() as u32 {
        let i = e as usize;
        let key = &edges[i];
        let ef = r.ef(key);
        assert_eq!(once(&fk(&a.ef[i]), "EF"), ef, "EF({e})");
        assert_eq!(once(&ek(&a.ee[i]), "EE"), r.ee(key), "EE({e})");
        once(&a.et[i], "ET");
        let open = ef.iter().any(Reference::boundary_face);
        assert_eq!(a.boundary.1[i], open, "boundary edge {e}");
        check_rotation(&a.et[i], &fk(&a.ef[i]), open, key);
    }
    for f in 0..chf.num_faces() as u32 {
        let i = f as usize;
        let key = &faces[i];
        assert_eq!(once(&ek(&a.fe[i]), "FE"), r.fe(key), "FE({f})");
        assert_eq!(once(&fk(&a.ff[i]), "FF"), r.ff(key), "FF({f})");
        assert_eq!(a.boundary.2[i], Reference::boundary_face(key));
        // FE: edge j runs from vertex j to vertex j + 1.
        for j in 0..3 {
            let pair = sorted([a.fv[i][j], a.fv[i][(j + 1) % 3]]);
            assert_eq!(edges[a.fe[i][j] as usize].0, pair, "FE({f}) order");
        }
    }
    for t in 0..chf.num_tetrahedra() as u32 {
        let i = t as usize;
        assert_eq!(a.tv[i], r.tv[i]);
        assert_eq!(once(&ek(&a.te[i]), "TE"), r.te(t), "TE({t})");
        assert_eq!(once(&fk(&a.tf[i]), "TF"), r.tf(t), "TF({t})");
        let tt: Vec<u32> = a.tt[i].iter().copied().filter(|&u| u != NONE).collect();
        assert_eq!(set(tt), r.tt(t), "TT({t})");
        for k in 0..4 {
            // Face k is opposite vertex k; its neighbour is across it.
            let f = &faces[a.tf[i][k] as usize];
            assert!(!f.0.contains(&a.tv[i][k]));
            let across = f.1.iter().copied().find(|&u| u != t).unwrap_or(NONE);
            assert_eq!(a.tt[i][k], across);
        }
    }
}

/// ET walks around the edge: consecutive tetrahedra share a glued face holding it (the last
/// and the first too when closed); EF lists the faces crossed, starting and ending on the
/// boundary when open.
fn check_rotation(et: &[u32], ef: &[FaceKey], open: bool, edge: &EdgeKey) {
    assert!(!et.is_empty());
    let k = et.len();
    assert_eq!(
        ef.len(),
        if open { k + 1 } else { k },
        "EF size of {edge:?}"
    );
    if open {
        assert!(ef[0].1.len() == 1 && ef[0].1[0] == et[0]);
        assert!(ef[k].1.len() == 1 && ef[k].1[0] == et[k - 1]);
    }
    for i in 0..k {
        // Face i + 1 (open) or i + 1 mod k (closed) is between et[i] and the next.
        let f = &ef[(i + 1) % ef.len()];
        assert!(f.1.contains(&et[i]), "rotation of {edge:?}");
        if open && i + 1 == k {
            continue;
        }
        let next = et[(i + 1) % k];
        assert!(
            f.1.contains(&next) && f.1.len() == 2,
            "rotation of {edge:?}"
        );
    }
}
