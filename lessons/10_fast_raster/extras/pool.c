/* pool.c: lesson 10's threads, shown but not taught (fast_raster.h,
 * run_threads). Started at the first finish with more than one thread, they
 * are kept: each waits for the next work, spinning a while before it
 * sleeps, as a thread asleep may take 50 microseconds or more to wake,
 * fast_finish hands out two works one after the other (the held faces'
 * set-up, then the tiles), and while a frame's faces are held the next
 * finish comes a fraction of a millisecond later (held.c); the calling
 * thread, its share done, spins too before it sleeps till the others are
 * done. A thread not started leaves its share to the calling thread; the
 * browser's build, which has no threads, draws so. */
#include "engine.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#if defined(__x86_64__)
#include <emmintrin.h> /* _mm_pause */
#endif

#define SPINS 16000    /* looks for work before a thread sleeps: 0.4 ms on a Zen 5 */
#define POOL_MAX 255   /* threads besides the calling one (--threads: 1 to 256) */

typedef struct { Pool *pool; int k; unsigned seen; pthread_t id; } Worker; /* thread k */

struct Pool {
    pthread_mutex_t lock;
    pthread_cond_t go, done; /* work handed out; the last share done */
    atomic_uint round;       /* one more for each work handed out */
    atomic_int busy;         /* threads not done with this round's shares */
    bool quit, refused;      /* refused: a thread could not start (none is tried again) */
    void *(*run)(void *); char *args; size_t size; int n; /* the round's work */
    int workers; Worker worker[POOL_MAX]; /* started: threads 1 .. workers */
};

static void pause_a_moment(void)
{
#if defined(__x86_64__)
    _mm_pause();
#endif
}

/* Thread k: run(args + k size) once in each round whose n is above k; until quit. */
static void *work(void *arg)
{
    Worker *w = arg;
    Pool *p = w->pool;
    for (;;) {
        for (int i = 0; i < SPINS && atomic_load(&p->round) == w->seen; i++)
            pause_a_moment();
        pthread_mutex_lock(&p->lock);
        while (atomic_load(&p->round) == w->seen && !p->quit)
            pthread_cond_wait(&p->go, &p->lock);
        if (p->quit) {
            pthread_mutex_unlock(&p->lock);
            return NULL;
        }
        w->seen = atomic_load(&p->round);
        bool mine = w->k < p->n;
        void *(*run)(void *) = p->run;
        void *share = p->args + (size_t)w->k * p->size;
        pthread_mutex_unlock(&p->lock);
        if (!mine)
            continue;
        run(share);
        pthread_mutex_lock(&p->lock);
        if (atomic_fetch_sub(&p->busy, 1) == 1)
            pthread_cond_signal(&p->done);
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
    return p;
}

void run_threads(Pool **pool, int n, void *(*run)(void *), void *args, size_t size)
{
    if (n > 1 && !*pool)
        *pool = pool_new();
    Pool *p = *pool;
    while (p && p->workers < n - 1 && p->workers < POOL_MAX && !p->refused) {
        Worker *w = &p->worker[p->workers]; /* waits for the next round, not the last */
        *w = (Worker){.pool = p, .k = p->workers + 1, .seen = atomic_load(&p->round)};
        p->refused = pthread_create(&w->id, NULL, work, w) != 0;
        p->workers += !p->refused;
    }
    int helped = p ? p->workers : 0; /* shares 1 .. helped on the pool's threads */
    if (helped > n - 1)
        helped = n - 1;
    if (helped > 0) {
        pthread_mutex_lock(&p->lock);
        p->run = run, p->args = args, p->size = size, p->n = helped + 1;
        atomic_store(&p->busy, helped);
        atomic_fetch_add(&p->round, 1);
        pthread_cond_broadcast(&p->go);
        pthread_mutex_unlock(&p->lock);
    }
    run(args); /* share 0 */
    for (int k = helped + 1; k < n; k++) /* no thread for them: here, in order */
        run((char *)args + (size_t)k * size);
    if (helped > 0) { /* spinning a moment first: the others are near done */
        for (int i = 0; i < SPINS && atomic_load(&p->busy) > 0; i++)
            pause_a_moment();
        pthread_mutex_lock(&p->lock);
        while (atomic_load(&p->busy) > 0)
            pthread_cond_wait(&p->done, &p->lock);
        pthread_mutex_unlock(&p->lock);
    }
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
