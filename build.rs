//! Gives the cdylib its SONAME, so that hosts link against `libtopomesh.so.0` (installed as
//! `libtopomesh.so.0.1.0` with the usual symlinks by the CMake packaging project).

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let target_os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if target_os == "linux" || target_os == "android" || target_os.ends_with("bsd") {
        let major = std::env::var("CARGO_PKG_VERSION_MAJOR").unwrap_or_else(|_| "0".into());
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libtopomesh.so.{major}");
    }
}
