//! Running a few jobs at once on scoped threads (the standard library's; no pool).

/// A build's `threads` option made concrete: 0 is as many as the machine runs at once.
pub(crate) fn threads(threads: usize) -> usize {
    if threads == 0 {
        std::thread::available_parallelism().map_or(1, |n| n.get())
    } else {
        threads
    }
}

/// Runs `f` on every job, the first on the calling thread and each other one on a thread
/// of its own, and returns the answers in the jobs' order. A panic in a job is resumed
/// here, once every thread has stopped.
pub(crate) fn run_all<J: Send, T: Send>(jobs: Vec<J>, f: impl Fn(J) -> T + Sync) -> Vec<T> {
    if jobs.len() <= 1 {
        return jobs.into_iter().map(f).collect();
    }
    let f = &f;
    std::thread::scope(|s| {
        let mut jobs = jobs.into_iter();
        let first = jobs.next().expect("more than one job");
        let others: Vec<_> = jobs.map(|j| s.spawn(move || f(j))).collect();
        let mut out = vec![f(first)];
        for h in others {
            out.push(h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)));
        }
        out
    })
}

#[cfg(test)]
mod tests {
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
}
