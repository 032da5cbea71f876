/* round_trip.c: bench_round_trip [--reps N], how far apart the machine's
 * cores are for threads that pass data, as lesson 10's pass their bins.
 *
 * Two threads bounce one counter, each waiting for the other's number
 * before it writes the next: each bounce takes the counter's cache line
 * from one core to the other and back. A repetition is BOUNCES bounces,
 * or as many as 50 ms of the wall clock allow (one core: the two threads
 * take turns on it); its time is the wall clock's per bounce. Prints one
 * line of tests/bench/measure.h's columns, round_trip,cores: the median,
 * least and most of N repetitions (BENCH_REPS unless given), after one
 * untimed, in seconds to the nanosecond. tests/bench/run-bench.sh prints each round's
 * (docs/performance.md, "Two cores far apart"). */
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdio.h>

#include "measure.h"

#define BOUNCES 20000
#define SPINS 1000 /* looks at the counter before the core is handed over */

typedef struct {
    _Alignas(64) atomic_long count; /* odd: the other thread's turn */
    atomic_bool stop;
} Ball;

/* Waits till *count is at least want (or stop); false when stopped. */
static bool wait_for(Ball *b, long want)
{
    for (int i = 0; atomic_load_explicit(&b->count, memory_order_acquire) < want; i++) {
        if (atomic_load_explicit(&b->stop, memory_order_relaxed))
            return false;
        if (i >= SPINS)
            sched_yield(), i = 0;
    }
    return true;
}

/* The other thread: each odd number answered with the next even one. */
static void *answer(void *arg)
{
    Ball *b = arg;
    for (long n = 1; wait_for(b, n); n += 2)
        atomic_store_explicit(&b->count, n + 1, memory_order_release);
    return NULL;
}

/* Seconds per bounce of one repetition, counting on from *count. */
static double bounce(Ball *b, long *count)
{
    double start = now_wall_seconds(), now = start;
    int k = 0;
    for (; k < BOUNCES && now - start < 0.05; k++) {
        atomic_store_explicit(&b->count, *count + 1, memory_order_release);
        wait_for(b, *count + 2);
        *count += 2;
        if (k % 256 == 255)
            now = now_wall_seconds();
    }
    return (now_wall_seconds() - start) / k;
}

int main(int argc, char **argv)
{
    const char *program = argc > 0 ? argv[0] : "bench_round_trip";
    int reps;
    int usage = bench_parse_reps(argc, argv, program, &reps);
    if (usage != 0)
        return usage;
    static Ball ball;
    atomic_init(&ball.count, 0), atomic_init(&ball.stop, false);
    pthread_t other;
    if (pthread_create(&other, NULL, answer, &ball) != 0) {
        fprintf(stderr, "%s: error: no second thread\n", program);
        return 1;
    }
    double times[MAX_REPS];
    long count = 0;
    for (int k = -BENCH_WARMUP; k < reps; k++) {
        double t = bounce(&ball, &count);
        if (k >= 0)
            times[k] = t;
    }
    atomic_store(&ball.stop, true);
    pthread_join(other, NULL);
    double median, least, most;
    summarise_times(times, reps, &median, &least, &most);
    printf("round_trip,cores,0,0,%d,0,0,%.9f,%.9f,%.9f,0\n", reps, median, least, most); /* ns */
    return 0;
}
