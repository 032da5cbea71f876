/* observe.h: what a test saw of the code under test, written down for a judge
 * that never runs that code (tools/judge.c, docs/teaching.md "Who decides
 * that a test passed").
 *
 * When the grader runs a test program with GRADE_OBSERVE_FD=n in its
 * environment, every check of the test also writes what it compared to file
 * descriptor n: the values of an assert_int_equal, a hash of the two strings
 * of an assert_string_equal, the count and the bound of an expect_at_least,
 * a hash of a picture and where it is. The grader has the same record from a
 * run of the teacher's solution, made beforehand. The test passes when the
 * judge, a program that holds no student code, finds the two records agree:
 * the same checks in the same order, equal where the check wants equality,
 * within the bound or tolerance that the teacher's run recorded, each picture
 * within what expect_image allows of tests/expected/ (which the judge reads
 * and the test program, while observed, does not). The test program's own
 * verdict is only one line of that record.
 *
 * So code linked into a test program can print, exit or neuter its asserts
 * as it likes: what counts is the values it computed, and to write down the
 * right ones it has to compute them.
 *
 * The record is text, one line an entry:
 *   D <count> <hash>            the checks that want equality since the last
 *                               line, folded into one hash (FNV-1a, 64 bits)
 *   B <site> <op> <actual> <bound> <count> expect_at_least (>), expect_at_most (<):
 *                               count checks in a row with these values
 *   C <site> <actual> <expected> <tolerance>   a number that must be within
 *                               tolerance of the expected (C99 %a, exact)
 *   P <site> <group> <name> <max_differing> <tolerance> <width> <height> <hash>
 *                               expect_image: a picture, written to
 *                               $TEST_OUTPUT/<group>/<name>.actual.png
 *   F <site>                    a failure the test itself declared (fail())
 *   E passed|failed             the end, with the test program's own verdict
 * <site> is file:line of the check. Paths in compared strings are written
 * with $TEST_OUTPUT and $PWD in place of those directories, so that two runs
 * in the same place agree.
 *
 * Without GRADE_OBSERVE_FD (make test, make grade without a reference) the
 * checks behave exactly as cmocka's and nothing is written.
 *
 * Include after <cmocka.h>: this header replaces cmocka's assert_* and fail()
 * macros by ones that observe, then call cmocka's own functions. */
#ifndef OBSERVE_H
#define OBSERVE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define OBSERVE_HASH_START 1469598103934665603ull /* FNV-1a 64 offset basis */

/* FNV-1a, 64 bits: the hash of the record (shared with tools/judge.c). */
static inline uint64_t observe_hash(uint64_t h, const void *data, size_t n)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < n; i++) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

/* Whether this run is observed (GRADE_OBSERVE_FD was given). */
bool observing(void);
/* From tests/support/test_hooks.c, before main(): the descriptor to write to. */
void observe_start(int fd);
/* The last line of the record: the test program's own verdict. */
void observe_end(bool passed);

/* A check that wants equality: its words are folded into the hash. */
void observe_exact(const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* A string compared: its hash and length, with paths written as above. */
void observe_exact_string(const char *file, int line, const char *tag, const char *s);
/* actual >= bound ('>') or actual <= bound ('<'). */
void observe_bound(const char *file, int line, char op, long actual, long bound);
/* A picture that expect_image compares with tests/expected/<group>/<name>.png. */
void observe_picture(const char *file, int line, const char *group, const char *name,
                     long max_differing, int tolerance, int width, int height,
                     const uint8_t *rgb);
/* A number that the test wants within tolerance of expected: the judge takes
 * the teacher's run's expected and tolerance, and the student's actual. */
void observe_close(const char *file, int line, double actual, double expected, double tolerance);
/* fail(): the test declared a failure here. */
void observe_failure(const char *file, int line);

/* The picture hash that P lines carry: width, height, then the RGB bytes. */
static inline uint64_t observe_picture_hash(int width, int height, const uint8_t *rgb)
{
    int32_t size[2] = {width, height};
    uint64_t h = observe_hash(OBSERVE_HASH_START, size, sizeof size);
    if (rgb && width > 0 && height > 0)
        h = observe_hash(h, rgb, (size_t)width * (size_t)height * 3);
    return h;
}

/* What a test is about to judge in a loop of its own (an if, then fail_msg):
 * the data itself, so that the judge sees what the test saw.
 *   observe_data(what, pointer, bytes)       bytes that must be equal
 *   observe_value(what, integer)             an integer that must be equal
 *   observe_number(what, number)             a double that must be equal
 *   observe_near(actual, expected, tolerance) a number within tolerance
 *   observe_target(t)                         a Target's face and overdraw
 *                                             buffers, equal
 *   observe_coverage(t)                       its overdraw buffer alone (the
 *                                             fragments tested per pixel): what
 *                                             a coverage test reads
 *   observe_worst(values, n, expected, tolerance)   n floats that must each be
 *                                             within tolerance of expected: the
 *                                             farthest of them (NaN: infinitely far) */
#define observe_data(what, p, n) observe_exact_data(__FILE__, __LINE__, (what), (p), (n))
#define observe_value(what, v) observe_exact(__FILE__, __LINE__, "%s %lld", (what), (long long)(v))
#define observe_number(what, v) observe_exact(__FILE__, __LINE__, "%s %a", (what), (double)(v))
#define observe_near(a, e, tol) observe_close(__FILE__, __LINE__, (a), (e), (tol))
#define observe_target(t) observe_target_at(__FILE__, __LINE__, (t), true)
#define observe_coverage(t) observe_target_at(__FILE__, __LINE__, (t), false)
#define observe_worst(v, n, e, tol) observe_worst_at(__FILE__, __LINE__, (v), (n), (e), (tol))
void observe_exact_data(const char *file, int line, const char *what, const void *p, size_t n);
void observe_target_at(const char *file, int line, const void *target, bool faces);
void observe_worst_at(const char *file, int line, const float *values, size_t n, double expected,
                      double tolerance);

/* cmocka's checks, observed. Each writes what it compared, then calls
 * cmocka's own function (which fails the test as usual). */
void observed_true(uintmax_t value, const char *expression, const char *file, int line);
void observed_int_equal(uintmax_t a, uintmax_t b, const char *file, int line);
void observed_int_not_equal(uintmax_t a, uintmax_t b, const char *file, int line);
void observed_string_equal(const char *a, const char *b, const char *file, int line);
void observed_memory_equal(const void *a, const void *b, size_t size, const char *file,
                           int line);
void observed_fail(const char *file, int line);

#undef assert_true
#define assert_true(c) observed_true((uintmax_t)!!(c), #c, __FILE__, __LINE__)
#undef assert_false
#define assert_false(c) observed_true((uintmax_t)!(c), "!(" #c ")", __FILE__, __LINE__)
#undef assert_non_null
#define assert_non_null(c) observed_true((uintmax_t)((c) != NULL), #c, __FILE__, __LINE__)
#undef assert_null
#define assert_null(c) observed_true((uintmax_t)((c) == NULL), "!(" #c ")", __FILE__, __LINE__)
/* Pointers differ from run to run: whether they are equal is what is observed. */
#undef assert_ptr_equal
#define assert_ptr_equal(a, b) \
    observed_true((uintmax_t)((const void *)(a) == (const void *)(b)), #a " == " #b, __FILE__, \
                  __LINE__)
#undef assert_int_equal
#define assert_int_equal(a, b) \
    observed_int_equal((uintmax_t)(a), (uintmax_t)(b), __FILE__, __LINE__)
#undef assert_int_not_equal
#define assert_int_not_equal(a, b) \
    observed_int_not_equal((uintmax_t)(a), (uintmax_t)(b), __FILE__, __LINE__)
#undef assert_string_equal
#define assert_string_equal(a, b) \
    observed_string_equal((const char *)(a), (const char *)(b), __FILE__, __LINE__)
#undef assert_memory_equal
#define assert_memory_equal(a, b, size) \
    observed_memory_equal((const void *)(a), (const void *)(b), (size), __FILE__, __LINE__)
#undef fail
#define fail() observed_fail(__FILE__, __LINE__)

#endif
