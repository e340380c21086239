//! How far a build is: a caller's hook, told the fraction of the build's steps done and the
//! name of the step that starts. Called from the thread that runs the build, between steps,
//! so a hook may update a progress bar without locking.

/// `hook(fraction, step)`: `fraction` in `0.0..=1.0`, never decreasing; the last call is
/// `(1.0, "done")` when the build succeeds.
pub type ProgressHook<'a> = dyn Fn(f64, &str) + Sync + 'a;

/// The hook of a build, or none (the default).
#[derive(Clone, Copy, Default)]
pub struct BuildProgress<'a>(Option<&'a ProgressHook<'a>>);

impl<'a> BuildProgress<'a> {
    pub fn new(hook: &'a ProgressHook<'a>) -> Self {
        BuildProgress(Some(hook))
    }

    pub(crate) fn at(&self, fraction: f64, step: &str) {
        if let Some(hook) = self.0 {
            hook(fraction, step);
        }
    }
}

impl std::fmt::Debug for BuildProgress<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.is_some() {
            "BuildProgress(hook)"
        } else {
            "BuildProgress(none)"
        })
    }
}
