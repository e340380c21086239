//! Running a few jobs at once on scoped threads (the standard library's; no pool).

use std::sync::Mutex;

/// Below this many triangles or tetrahedra a build stays on the calling thread: starting
/// threads, several times per build, would cost more than they save on a mesh this small.
const PARALLEL_MIN_ELEMENTS: usize = 1 << 15;

/// The most threads a build starts, whatever its `threads` option says: each thread takes a
/// stack of its own, and a host passing a huge count (`UINT32_MAX`) must get a build, not
/// a process aborted when the system runs out of memory for stacks.
pub(crate) const MAX_BUILD_THREADS: usize = 256;

/// The threads a build of `n` triangles or tetrahedra takes for its `threads` option (0: as
/// many as the machine runs at once), at most `MAX_BUILD_THREADS`. Every step of the build
/// shares its work among that many, or runs alone when it is 1.
pub(crate) fn build_threads(option: usize, n: usize) -> usize {
    if n < PARALLEL_MIN_ELEMENTS {
        1
    } else if option == 0 {
        std::thread::available_parallelism().map_or(1, |n| n.get().min(MAX_BUILD_THREADS))
    } else {
        option.min(MAX_BUILD_THREADS)
    }
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
    let mut out: Vec<Option<T>> = std::thread::scope(|s| {
        let handles: Vec<_> = slots
            .iter()
            .map(|slot| {
                std::thread::Builder::new()
                    .spawn_scoped(s, move || take(slot).map(f))
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

#[cfg(test)]
mod tests {
    #[test]
    fn a_huge_thread_count_is_capped() {
        let n = super::PARALLEL_MIN_ELEMENTS;
        assert_eq!(
            super::build_threads(u32::MAX as usize, n),
            super::MAX_BUILD_THREADS
        );
        assert_eq!(super::build_threads(3, n), 3);
        assert_eq!(super::build_threads(u32::MAX as usize, n - 1), 1);
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

    #[test]
    #[should_panic(expected = "job 2")]
    fn a_panic_in_a_job_comes_back() {
        super::run_all((0..4).collect(), |j: u32| {
            assert!(j != 2, "job 2");
            j
        });
    }
}
