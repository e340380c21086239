//! Running a few jobs at once on scoped threads (the standard library's; no pool).

use std::sync::Mutex;

/// Below this many triangles or tetrahedra a build stays on the calling thread: starting
/// threads, several times per build, would cost more than they save on a mesh this small.
const PARALLEL_MIN_ELEMENTS: usize = 1 << 15;

/// The fewest elements a thread of a build gets: a thread with less work than this costs
/// more to start than it saves, and a huge `threads` option must not start a thread for
/// every few elements (the system may refuse, or the process run out of memory for stacks).
const MIN_ELEMENTS_PER_THREAD: usize = 1 << 13;

/// The threads a build of `n` triangles or tetrahedra takes for its `threads` option (0: as
/// many as the machine runs at once), as `planned_threads` plans them. Every step of the build
/// shares its work among that many, or runs alone when it is 1.
pub(crate) fn build_threads(option: usize, n: usize) -> usize {
    planned_threads(option, n)
}

/// The threads a build of `elements` triangles or tetrahedra starts when asked for
/// `requested` (0: as many as the machine runs at once): never more than the machine runs
/// at once (`std::thread::available_parallelism`), never fewer than
/// `MIN_ELEMENTS_PER_THREAD` elements per thread, and 1 below `PARALLEL_MIN_ELEMENTS`.
/// The result of a build does not depend on it.
pub fn planned_threads(requested: usize, elements: usize) -> usize {
    // Asking the machine reads its cgroup files on Linux, which costs more than a whole
    // build of a small mesh: ask only when the answer can change the plan.
    if elements < PARALLEL_MIN_ELEMENTS {
        return 1;
    }
    let available = std::thread::available_parallelism().map_or(1, |n| n.get());
    plan(requested, elements, available)
}

/// `planned_threads` for a machine that runs `available` threads at once.
fn plan(requested: usize, elements: usize, available: usize) -> usize {
    if elements < PARALLEL_MIN_ELEMENTS {
        return 1;
    }
    let wanted = if requested == 0 { available } else { requested };
    let most = (elements / MIN_ELEMENTS_PER_THREAD).max(1);
    wanted.min(available).min(most).max(1)
}

/// Runs `f` on every job, the first on the calling thread and each other one on a thread
/// of its own, and returns the answers in the jobs' order. A job whose thread cannot be
/// started (the system refuses) runs on the calling thread instead. A panic in a job is
/// resumed here, once every thread has stopped.
pub(crate) fn run_all<J: Send, T: Send>(jobs: Vec<J>, f: impl Fn(J) -> T + Sync) -> Vec<T> {
    if jobs.len() <= 1 {
        return jobs.into_iter().map(f).collect();
    }
    let f = &f;
    let mut jobs = jobs.into_iter();
    let first = jobs.next().expect("more than one job");
    // Each other job waits in a slot until its thread takes it; a slot still full after
    // the threads have stopped is a job whose thread could not start.
    let slots: Vec<Mutex<Option<J>>> = jobs.map(|j| Mutex::new(Some(j))).collect();
    let take = |slot: &Mutex<Option<J>>| slot.lock().unwrap_or_else(|e| e.into_inner()).take();
    // A panic on a job's thread comes back to the caller, which may report it itself.
    let silenced = super::panics::is_quiet();
    let mut out: Vec<Option<T>> = std::thread::scope(|s| {
        let handles: Vec<_> = slots
            .iter()
            .map(|slot| {
                std::thread::Builder::new()
                    .spawn_scoped(s, move || {
                        super::panics::quiet_if(silenced, || take(slot).map(f))
                    })
                    .ok()
            })
            .collect();
        let mut out = vec![Some(f(first))];
        for h in handles {
            out.push(h.and_then(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e))));
        }
        out
    });
    for (answer, slot) in out[1..].iter_mut().zip(&slots) {
        if answer.is_none() {
            *answer = take(slot).map(f);
        }
    }
    out.into_iter().map(|t| t.expect("every job ran")).collect()
}

/// What a loop over `0..n` stopping at its first `Some` would give, with `check` run on
/// `threads` contiguous parts of `0..n` at once (each stopping at its own first): the
/// answer of the first part that has one, so the same whatever the threads.
pub(crate) fn first_found<T: Send>(
    n: usize, threads: usize, check: impl Fn(std::ops::Range<usize>) -> Option<T> + Sync,
) -> Option<T> {
    let part = n.div_ceil(threads.max(1)).max(1);
    let parts: Vec<_> = (0..n).step_by(part).map(|a| a..(a + part).min(n)).collect();
    run_all(parts, check).into_iter().flatten().next()
}

#[cfg(test)]
mod tests {
    use super::{MIN_ELEMENTS_PER_THREAD, PARALLEL_MIN_ELEMENTS, plan};

    #[test]
    fn the_plan_never_exceeds_the_machine_or_the_work() {
        for available in [1, 2, 3, 8, 64] {
            for requested in [0, 1, 2, 5, 64, 100_000, usize::MAX] {
                for elements in [0, 1, 1000, PARALLEL_MIN_ELEMENTS - 1, PARALLEL_MIN_ELEMENTS]
                    .into_iter()
                    .chain([100_000, 1 << 24, usize::MAX])
                {
                    let t = plan(requested, elements, available);
                    let wanted = if requested == 0 { available } else { requested };
                    let expected = if elements < PARALLEL_MIN_ELEMENTS {
                        1
                    } else {
                        wanted
                            .min(available)
                            .min(elements / MIN_ELEMENTS_PER_THREAD)
                    };
                    assert_eq!(
                        t, expected,
                        "{requested} of {available}, {elements} elements"
                    );
                    assert!(t >= 1 && t <= available);
                }
            }
        }
    }

    #[test]
    fn planned_threads_stay_within_the_machine() {
        let available = std::thread::available_parallelism().map_or(1, |n| n.get());
        assert_eq!(super::planned_threads(100_000, 1 << 20), available.min(128));
        assert_eq!(super::planned_threads(1, 1 << 20), 1);
        assert_eq!(super::planned_threads(100_000, 10), 1);
    }

    #[test]
    fn answers_come_in_the_jobs_order() {
        for n in 0..6u32 {
            let jobs: Vec<u32> = (0..n).collect();
            assert_eq!(
                super::run_all(jobs, |j| j * 10),
                (0..n).map(|j| j * 10).collect::<Vec<_>>()
            );
        }
    }

    /// The first hit over the parts is the loop's first hit, for any number of parts.
    #[test]
    fn the_first_found_is_the_loops_first() {
        let hits = [3usize, 7, 8, 19];
        for n in [0, 1, 5, 8, 20, 33] {
            let expected = hits.iter().copied().find(|&i| i < n);
            for threads in 0..7 {
                let found =
                    super::first_found(n, threads, |r| r.into_iter().find(|i| hits.contains(i)));
                assert_eq!(found, expected, "{n} elements, {threads} threads");
            }
        }
    }

    #[test]
    #[should_panic(expected = "job 2")]
    fn a_panic_in_a_job_comes_back() {
        super::run_all((0..4).collect(), |j: u32| {
            assert!(j != 2, "job 2");
            j
        });
    }
}
