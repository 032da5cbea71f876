/* fail_alloc.c: a library preloaded into a lesson (LD_PRELOAD) that makes
 * one chosen allocation fail, as a machine out of memory would
 * (tests/tools/test_alloc_failure.c; make builds it as build/tests/fail_alloc.so).
 *
 *   FAIL_ALLOC_AT=n       the n-th call (from 0) of malloc, calloc, realloc,
 *                         aligned_alloc or posix_memalign fails: NULL (or
 *                         ENOMEM), errno ENOMEM; every other call goes on
 *   FAIL_ALLOC_COUNT=path at exit, the number of calls is written there
 *
 * The calls are counted across threads. Until the real functions are found
 * (dlsym may itself allocate), calloc is served from a small static buffer. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

static void *(*real_malloc)(size_t);
static void *(*real_calloc)(size_t, size_t);
static void *(*real_realloc)(void *, size_t);
static void *(*real_aligned_alloc)(size_t, size_t);
static int (*real_posix_memalign)(void **, size_t, size_t);
static long fail_at = -1;
static long calls;
static int ready;
static _Alignas(16) char early[8192];
static size_t early_used;

/* The next definition of a function, as POSIX has dlsym's result stored. */
#define FIND(fn, name) (*(void **)&(fn) = dlsym(RTLD_NEXT, name))

static void find_real(void)
{
    if (ready)
        return;
    ready = 1;
    FIND(real_malloc, "malloc");
    FIND(real_calloc, "calloc");
    FIND(real_realloc, "realloc");
    FIND(real_aligned_alloc, "aligned_alloc");
    FIND(real_posix_memalign, "posix_memalign");
    const char *at = getenv("FAIL_ALLOC_AT");
    fail_at = at ? atol(at) : -1;
}

/* Whether this call is the one to fail. */
static int fails(void)
{
    long k = __atomic_fetch_add(&calls, 1, __ATOMIC_RELAXED);
    if (k != fail_at)
        return 0;
    errno = ENOMEM;
    return 1;
}

__attribute__((destructor)) static void write_count(void)
{
    const char *path = getenv("FAIL_ALLOC_COUNT");
    FILE *f = path ? fopen(path, "w") : NULL;
    if (f) {
        fprintf(f, "%ld\n", __atomic_load_n(&calls, __ATOMIC_RELAXED));
        fclose(f);
    }
}

void *malloc(size_t n)
{
    find_real();
    return fails() ? NULL : real_malloc(n);
}

void *calloc(size_t count, size_t size)
{
    if (!real_calloc) { /* dlsym's own, before the real one is known */
        if (!ready)
            find_real();
        if (!real_calloc) {
            size_t n = (count * size + 15) & ~(size_t)15;
            if (n > sizeof early - early_used)
                return NULL;
            void *p = early + early_used;
            early_used += n;
            return p; /* zeroed: static */
        }
    }
    return fails() ? NULL : real_calloc(count, size);
}

void *realloc(void *p, size_t n)
{
    find_real();
    return fails() ? NULL : real_realloc(p, n);
}

void *aligned_alloc(size_t alignment, size_t n)
{
    find_real();
    return fails() ? NULL : real_aligned_alloc(alignment, n);
}

int posix_memalign(void **p, size_t alignment, size_t n)
{
    find_real();
    return fails() ? ENOMEM : real_posix_memalign(p, alignment, n);
}

void free(void *p)
{
    static void (*real_free)(void *);
    if ((char *)p >= early && (char *)p < early + sizeof early)
        return; /* from the static buffer */
    if (!real_free)
        FIND(real_free, "free");
    real_free(p);
}
