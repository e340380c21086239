/* Running the same queries on one const mesh from several threads at once (CHE and CHF). */
#ifndef TOPOMESH_TEST_THREADS_H
#define TOPOMESH_TEST_THREADS_H

#include "check.h"

#include <pthread.h>

#define N_THREADS 4

/* One thread's work: the mesh, what it saw (the origin map's address and a count of
   answers), and whether a call failed. */
typedef struct thread_job {
    const void *m;
    const uint32_t *origins;
    size_t total;
    int failed;
} thread_job;

/* Runs `work` on N_THREADS threads over mesh m and checks that none failed, that all saw
   one origin map (materialised once) and the same total, and that total is `want`. */
static inline void run_threads(const void *m, void *(*work)(void *), size_t want) {
    pthread_t th[N_THREADS];
    thread_job jobs[N_THREADS];
    for (int i = 0; i < N_THREADS; i++) {
        jobs[i] = (thread_job){m, NULL, 0, 0};
        CHECK(pthread_create(&th[i], NULL, work, &jobs[i]) == 0);
    }
    for (int i = 0; i < N_THREADS; i++) CHECK(pthread_join(th[i], NULL) == 0);
    for (int i = 0; i < N_THREADS; i++) {
        CHECK(!jobs[i].failed);
        CHECK(jobs[i].origins == jobs[0].origins && jobs[i].total == want);
    }
}

#endif
