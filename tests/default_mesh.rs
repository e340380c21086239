//! The CLI's embedded default mesh is the generated torus it claims to be.

#[test]
fn default_mesh_is_the_generated_torus() {
    let text = topomesh::generate::to_off(&topomesh::generate::torus(24, 12));
    let embedded = include_str!("../data/default.off");
    if std::env::var_os("TOPOMESH_BLESS").is_some() {
        std::fs::write(
            concat!(env!("CARGO_MANIFEST_DIR"), "/data/default.off"),
            &text,
        )
        .unwrap();
        return;
    }
    assert_eq!(
        embedded, text,
        "regenerate with TOPOMESH_BLESS=1 cargo test --test default_mesh"
    );
}
