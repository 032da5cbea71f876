/* pool.c: lesson 10's threads, shown but not taught (fast_raster.h,
 * run_threads). Started at the first finish with more than one thread, they
 * are kept. A work is handed out in shares; each thread, the calling one
 * first, takes the next share not yet taken till none is left, so a thread
 * the system keeps from running (the cores shared with other work) leaves
 * its share to another, and none waits for it. Between works each waits,
 * spinning a while before it sleeps, as a thread asleep may take 50
 * microseconds or more to wake, fast_finish hands out two works one after
 * the other (the held faces' set-up, then the tiles), and while a frame's
 * faces are held the next finish comes a fraction of a millisecond later
 * (held.c); the calling thread, its shares done, spins too before it sleeps
 * till the others are done. A spin that ended in sleep halves the next, one
 * that found its work doubles it (SPIN_NS at most): on a busy machine, where a
 * thread spinning keeps a core from the thread with work, the spins die out.
 * A spin is timed by the clock, not counted in pauses: a pause takes from
 * about 10 cycles to 140 from one x86-64 to another.
 * With no thread (the browser's build has none), the calling thread runs
 * every share. */
#include "engine.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <time.h>
#if defined(__x86_64__)
#include <emmintrin.h> /* _mm_pause */
#endif

#define SPIN_NS 400000  /* looks for work before a thread sleeps: 0.4 ms at most */
#define POOL_MAX 255    /* threads besides the calling one (--threads: 1 to 256) */

typedef struct { Pool *pool; unsigned seen; int64_t spin; pthread_t id; } Worker; /* spin: ns */

struct Pool {
    pthread_mutex_t lock;
    pthread_cond_t go, done; /* work handed out; the last share done */
    atomic_uint round;       /* one more for each work handed out */
    atomic_int busy;         /* shares taken and not yet done */
    bool quit, refused;      /* refused: a thread could not start (none is tried again) */
    void *(*run)(void *); char *args; size_t size; int n; /* the round's work */
    int taken; int64_t spin; /* shares taken (under the lock); the calling thread's spin */
    int workers; Worker worker[POOL_MAX]; /* started: threads 1 .. workers */
};

static int64_t now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (int64_t)t.tv_sec * 1000000000 + t.tv_nsec;
}

/* One more look of a spin begun at start, to last ns: false once they are
 * past (the clock read at every 64th look), else a pause first. */
static bool spinning(int64_t start, int64_t ns, int *looks)
{
    if ((*looks)++ % 64 == 0 && now_ns() - start >= ns)
        return false;
#if defined(__x86_64__)
    _mm_pause();
#endif
    return true;
}

/* The next spin, after one that found what it waited for (ended) or not. */
static int64_t next_spin(int64_t ns, bool ended)
{
    return ended ? (ns * 2 + 400 < SPIN_NS ? ns * 2 + 400 : SPIN_NS) : ns / 2;
}

/* The round's shares not yet taken, one after another, here; p->lock held. */
static void take_shares(Pool *p)
{
    while (p->taken < p->n) {
        void *share = p->args + (size_t)p->taken++ * p->size;
        void *(*run)(void *) = p->run;
        atomic_fetch_add(&p->busy, 1);
        pthread_mutex_unlock(&p->lock);
        run(share);
        pthread_mutex_lock(&p->lock);
        if (atomic_fetch_sub(&p->busy, 1) == 1)
            pthread_cond_signal(&p->done);
    }
}

/* A pool thread: the shares it takes of each round; until quit. */
static void *work(void *arg)
{
    Worker *w = arg;
    Pool *p = w->pool;
    for (;;) {
        int64_t start = now_ns();
        for (int looks = 0; atomic_load(&p->round) == w->seen && spinning(start, w->spin, &looks);)
            continue;
        w->spin = next_spin(w->spin, atomic_load(&p->round) != w->seen);
        pthread_mutex_lock(&p->lock);
        while (atomic_load(&p->round) == w->seen && !p->quit)
            pthread_cond_wait(&p->go, &p->lock);
        if (p->quit) {
            pthread_mutex_unlock(&p->lock);
            return NULL;
        }
        w->seen = atomic_load(&p->round);
        take_shares(p);
        pthread_mutex_unlock(&p->lock);
    }
}

static Pool *pool_new(void) /* no thread yet; NULL: out of memory */
{
    Pool *p = calloc(1, sizeof *p);
    if (!p)
        return NULL;
    pthread_mutex_init(&p->lock, NULL);
    pthread_cond_init(&p->go, NULL), pthread_cond_init(&p->done, NULL);
    atomic_init(&p->round, 0), atomic_init(&p->busy, 0);
    p->spin = SPIN_NS;
    return p;
}

void run_threads(Pool **pool, int n, void *(*run)(void *), void *args, size_t size)
{
    if (n > 1 && !*pool)
        *pool = pool_new();
    Pool *p = *pool;
    while (p && p->workers < n - 1 && p->workers < POOL_MAX && !p->refused) {
        Worker *w = &p->worker[p->workers]; /* waits for the next round, not the last */
        *w = (Worker){.pool = p, .seen = atomic_load(&p->round), .spin = SPIN_NS};
        p->refused = pthread_create(&w->id, NULL, work, w) != 0;
        p->workers += !p->refused;
    }
    if (n < 2 || !p || p->workers == 0) { /* no thread: every share here, in order */
        for (int k = 0; k < n; k++)
            run((char *)args + (size_t)k * size);
        return;
    }
    pthread_mutex_lock(&p->lock);
    p->run = run, p->args = args, p->size = size, p->n = n, p->taken = 0;
    atomic_fetch_add(&p->round, 1);
    pthread_cond_broadcast(&p->go);
    take_shares(p); /* share 0 first, then any no thread has taken */
    pthread_mutex_unlock(&p->lock);
    int64_t start = now_ns(); /* the others are near done */
    for (int looks = 0; atomic_load(&p->busy) > 0 && spinning(start, p->spin, &looks);)
        continue;
    p->spin = next_spin(p->spin, atomic_load(&p->busy) == 0);
    pthread_mutex_lock(&p->lock);
    while (atomic_load(&p->busy) > 0)
        pthread_cond_wait(&p->done, &p->lock);
    pthread_mutex_unlock(&p->lock);
}

void pool_free(Pool *p)
{
    if (!p)
        return;
    pthread_mutex_lock(&p->lock);
    p->quit = true;
    atomic_fetch_add(&p->round, 1); /* a thread still spinning stops at once */
    pthread_cond_broadcast(&p->go);
    pthread_mutex_unlock(&p->lock);
    for (int k = 0; k < p->workers; k++)
        pthread_join(p->worker[k].id, NULL);
    pthread_mutex_destroy(&p->lock);
    pthread_cond_destroy(&p->go), pthread_cond_destroy(&p->done);
    free(p);
}
