/* observe.c: see observe.h. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "observe.h"
#include "target.h"

#include <fcntl.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define ENTRY_MAX 1024
#define PATH_MAX_LEN 4096

static FILE *record;           /* NULL: not observed */
static uint64_t folded = OBSERVE_HASH_START;
static unsigned long folded_count;
static char output_dir[PATH_MAX_LEN]; /* $TEST_OUTPUT, as given */
static char work_dir[PATH_MAX_LEN];   /* $PWD, as getcwd() says */

bool observing(void)
{
    return record != NULL;
}

void observe_start(int fd)
{
    int flags = fcntl(fd, F_GETFD);
    if (flags < 0)
        return;
    (void)fcntl(fd, F_SETFD, flags | FD_CLOEXEC); /* not for the programs a test runs */
    record = fdopen(fd, "w");
    if (!getcwd(work_dir, sizeof work_dir))
        work_dir[0] = '\0';
    /* $TEST_OUTPUT as a path from $PWD when it is inside it, as strings are
     * hashed with $PWD/ taken out first. */
    const char *out = getenv("TEST_OUTPUT");
    size_t pwd = strlen(work_dir);
    if (out && pwd > 0 && strncmp(out, work_dir, pwd) == 0 && out[pwd] == '/')
        out += pwd + 1;
    snprintf(output_dir, sizeof output_dir, "%s", out ? out : "");
}

/* A bound checked again and again with the same values (a check in a loop
 * over pixels) is one line with a count: the last one, not yet written. */
static struct {
    char site[ENTRY_MAX];
    char op;
    long actual, bound;
    unsigned long count;
} pending;

static void flush_pending_bound(void)
{
    if (!record || pending.count == 0)
        return;
    fprintf(record, "B %s %c %ld %ld %lu\n", pending.site, pending.op, pending.actual,
            pending.bound, pending.count);
    pending.count = 0;
}

/* The equality checks so far, as one D line (none if there were none). */
static void flush_folded(void)
{
    if (!record)
        return;
    flush_pending_bound();
    if (folded_count == 0)
        return;
    fprintf(record, "D %lu %016" PRIx64 "\n", folded_count, folded);
    folded = OBSERVE_HASH_START;
    folded_count = 0;
}

void observe_end(bool passed)
{
    if (!record)
        return;
    flush_folded();
    fprintf(record, "E %s\n", passed ? "passed" : "failed");
    fflush(record);
}

void observe_exact(const char *file, int line, const char *fmt, ...)
{
    if (!record)
        return;
    char entry[ENTRY_MAX];
    int n = snprintf(entry, sizeof entry, "%s:%d ", file, line);
    if (n < 0 || (size_t)n >= sizeof entry)
        n = 0;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(entry + n, sizeof entry - (size_t)n, fmt, ap);
    va_end(ap);
    flush_pending_bound();
    folded = observe_hash(folded, entry, strlen(entry) + 1);
    folded_count++;
}

/* Hashes s with each occurrence of dir written as name. */
static uint64_t hash_replacing(uint64_t h, const char *s, const char *dir, const char *name,
                               size_t *length)
{
    size_t n = strlen(dir);
    while (*s) {
        const char *at = n > 0 ? strstr(s, dir) : NULL;
        size_t plain = at ? (size_t)(at - s) : strlen(s);
        h = observe_hash(h, s, plain);
        *length += plain;
        s += plain;
        if (at) {
            h = observe_hash(h, name, strlen(name));
            *length += strlen(name);
            s += n;
        }
    }
    return h;
}

void observe_exact_string(const char *file, int line, const char *tag, const char *s)
{
    if (!record)
        return;
    if (!s) {
        observe_exact(file, line, "%s null", tag);
        return;
    }
    /* $PWD first: TEST_OUTPUT may be relative to it. Then $TEST_OUTPUT, in
     * what is left (a copy with $PWD/ taken out). */
    size_t len = strlen(s);
    char *copy = malloc(len + 1);
    if (!copy) {
        observe_exact(file, line, "%s unhashed", tag);
        return;
    }
    char *w = copy;
    size_t pwd = strlen(work_dir);
    for (const char *p = s; *p;) {
        if (pwd > 0 && strncmp(p, work_dir, pwd) == 0 && p[pwd] == '/') {
            p += pwd + 1;
            continue;
        }
        *w++ = *p++;
    }
    *w = '\0';
    size_t hashed = 0;
    uint64_t h = hash_replacing(OBSERVE_HASH_START, copy, output_dir, "$TEST_OUTPUT", &hashed);
    free(copy);
    observe_exact(file, line, "%s %016" PRIx64 " %zu", tag, h, hashed);
}

void observe_bound(const char *file, int line, char op, long actual, long bound)
{
    if (!record)
        return;
    char site[ENTRY_MAX];
    snprintf(site, sizeof site, "%s:%d", file, line);
    op = op == '<' ? '<' : '>';
    if (pending.count > 0 && pending.op == op && pending.actual == actual &&
        pending.bound == bound && strcmp(pending.site, site) == 0) {
        pending.count++;
        return;
    }
    flush_folded();
    snprintf(pending.site, sizeof pending.site, "%s", site);
    pending.op = op;
    pending.actual = actual;
    pending.bound = bound;
    pending.count = 1;
}

void observe_picture(const char *file, int line, const char *group, const char *name,
                     long max_differing, int tolerance, int width, int height,
                     const uint8_t *rgb)
{
    if (!record)
        return;
    flush_folded();
    fprintf(record, "P %s:%d %s %s %ld %d %d %d %016" PRIx64 "\n", file, line, group, name,
            max_differing, tolerance, width, height, observe_picture_hash(width, height, rgb));
}

void observe_close(const char *file, int line, double actual, double expected, double tolerance)
{
    if (!record)
        return;
    flush_folded();
    fprintf(record, "C %s:%d %a %a %a\n", file, line, actual, expected, tolerance);
}

void observe_exact_data(const char *file, int line, const char *what, const void *p, size_t n)
{
    if (!record)
        return;
    observe_exact(file, line, "data %s %016" PRIx64 " %zu", what,
                  p ? observe_hash(OBSERVE_HASH_START, p, n) : 0, n);
}

void observe_target_at(const char *file, int line, const void *target, bool faces)
{
    if (!record)
        return;
    const Target *t = target;
    size_t n = t && t->width > 0 && t->height > 0 ? (size_t)t->width * (size_t)t->height : 0;
    observe_exact(file, line, "target %d %d", t ? t->width : 0, t ? t->height : 0);
    if (n == 0)
        return;
    if (faces)
        observe_exact_data(file, line, "face", t->face, n * sizeof *t->face);
    if (t->counting)
        observe_exact_data(file, line, "overdraw", t->overdraw, n * sizeof *t->overdraw);
}

void observe_worst_at(const char *file, int line, const float *values, size_t n, double expected,
                      double tolerance)
{
    if (!record)
        return;
    double worst = 0;
    for (size_t i = 0; i < n; i++) {
        double off = isnan(values[i]) ? INFINITY : fabs(values[i] - expected);
        worst = off > worst ? off : worst;
    }
    observe_close(file, line, expected + worst, expected, tolerance);
}

void observe_failure(const char *file, int line)
{
    if (!record)
        return;
    flush_folded();
    fprintf(record, "F %s:%d\n", file, line);
}

/* ---- cmocka's checks, observed ---- */

void observed_true(uintmax_t value, const char *expression, const char *file, int line)
{
    observe_exact(file, line, "T %d", value != 0);
    _assert_true(value, expression, file, line);
}

void observed_int_equal(uintmax_t a, uintmax_t b, const char *file, int line)
{
    observe_exact(file, line, "I %ju %ju", a, b);
    _assert_int_equal(a, b, file, line);
}

void observed_int_not_equal(uintmax_t a, uintmax_t b, const char *file, int line)
{
    observe_exact(file, line, "N %ju %ju", a, b);
    _assert_int_not_equal(a, b, file, line);
}

void observed_string_equal(const char *a, const char *b, const char *file, int line)
{
    observe_exact_string(file, line, "S", a);
    observe_exact_string(file, line, "S", b);
    _assert_string_equal(a, b, file, line);
}

void observed_memory_equal(const void *a, const void *b, size_t size, const char *file,
                           int line)
{
    observe_exact(file, line, "M %016" PRIx64 " %016" PRIx64 " %zu",
                  observe_hash(OBSERVE_HASH_START, a, size),
                  observe_hash(OBSERVE_HASH_START, b, size), size);
    _assert_memory_equal(a, b, size, file, line);
}

void observed_fail(const char *file, int line)
{
    observe_failure(file, line);
    _fail(file, line);
}
