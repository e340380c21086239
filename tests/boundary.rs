//! What the C boundary lets out: nothing on the host's stderr when it catches a panic (the
//! panic hook is silent inside the guard and the host's own hook still runs outside it),
//! and no control character from a file in an error's detail.

use std::process::Command;
use topomesh::ffi::{Status, guarded_panic};

/// Set in the environment of the child process that `panics_in_the_guard_print_nothing`
/// runs (this test binary again, on one test).
const CHILD: &str = "TOPOMESH_TEST_PANIC_CHILD";

#[test]
fn panics_in_the_guard_print_nothing() {
    let exe = std::env::current_exe().unwrap();
    let out = Command::new(exe)
        .args(["--exact", "child_panics", "--nocapture", "--test-threads=1"])
        .env(CHILD, "1")
        .env("RUST_BACKTRACE", "1")
        .output()
        .unwrap();
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert!(out.status.success(), "child failed:\n{stdout}\n{stderr}");
    assert!(stdout.contains("child: done"), "the child ran:\n{stdout}");
    // The host's hook ran for the panic outside the guard, and for nothing else.
    assert_eq!(
        stderr, "host hook: outside the guard\n",
        "stdout:\n{stdout}"
    );
}

/// The child's side: runs only under `panics_in_the_guard_print_nothing`.
#[test]
fn child_panics() {
    if std::env::var_os(CHILD).is_none() {
        return;
    }
    // The host's hook, set before the library's is installed (on the first guarded call).
    std::panic::set_hook(Box::new(|info| {
        let what = (info.payload().downcast_ref::<&str>().map(|s| s.to_string()))
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_default();
        eprintln!("host hook: {what}");
    }));
    let mut detail = vec![0 as std::ffi::c_char; 256];
    let mut len = 0;
    // On the calling thread, then on a thread the guarded call started (as a build does).
    for jobs in [1, 3, 1] {
        assert_eq!(guarded_panic("inside the guard", jobs), Status::Panic);
        let status = unsafe {
            topomesh::ffi::status::topomesh_last_error(detail.as_mut_ptr(), 256, &mut len)
        };
        assert_eq!(status, Status::Ok);
        let text = unsafe { std::ffi::CStr::from_ptr(detail.as_ptr()) };
        let text = text.to_string_lossy();
        assert!(
            text.contains("inside the guard"),
            "the detail names the panic: {text}"
        );
        // The place is known when the panic happened on the calling thread.
        assert_eq!(text.contains("boundary.rs:"), jobs == 1, "{text}");
    }
    // Outside the guard the host's hook runs.
    let outside = std::panic::catch_unwind(|| panic!("outside the guard"));
    assert!(outside.is_err());
    println!("child: done");
}

/// The calling thread's `topomesh_last_error`.
fn last_error() -> String {
    let mut detail = vec![0 as std::ffi::c_char; 4096];
    let mut len = 0;
    let status =
        unsafe { topomesh::ffi::status::topomesh_last_error(detail.as_mut_ptr(), 4096, &mut len) };
    assert_eq!(status, Status::Ok);
    let text = unsafe { std::ffi::CStr::from_ptr(detail.as_ptr()) };
    text.to_string_lossy().into_owned()
}

#[test]
fn control_characters_from_files_are_escaped_in_errors() {
    use std::os::unix::ffi::OsStrExt;
    use topomesh::ffi::che::che_mesh_load;
    let dir = std::env::temp_dir().join(format!("topomesh-escape-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // A file whose content sends a colour change, in a token the parser names.
    let content = dir.join("red.off");
    std::fs::write(&content, "OFF\n\x1b[31m 1 0\n0 0 0\n").unwrap();
    // A file name with one, and a line break, that does not exist.
    let name = dir.join("bad\x1b[31m\nname.off");
    for (path, shown) in [
        (&content, "\\u{1b}[31m"),
        (&name, "bad\\u{1b}[31m\\nname.off"),
    ] {
        let rust = topomesh::io::load::che(path, topomesh::BuildOptions::default()).unwrap_err();
        let c_path = std::ffi::CString::new(path.as_os_str().as_bytes()).unwrap();
        let mut m = std::ptr::null_mut();
        let status = unsafe { che_mesh_load(c_path.as_ptr(), 2, &mut m) };
        assert!(status != Status::Ok && m.is_null());
        for text in [rust.message.clone(), rust.to_string(), last_error()] {
            assert!(text.contains(shown), "{shown:?} not in {text:?}");
            assert!(!text.chars().any(char::is_control), "{text:?}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
