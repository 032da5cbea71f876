/* neutered_checks.c: the test framework's checks as a forger would leave
 * them, for make grade-check (tools/grade-check.sh): every check still
 * records what it saw (tests/support/observe.h), honestly, but none ever
 * fails, and fail() does nothing, so a test runs on to its end whatever its
 * code computed. Linked in place of tests/support/observe.c, it is what a
 * submission that made the test program's asserts do nothing would get.
 * The judge must score such a handout no higher than the untouched one.
 *
 * It is observe.c with its cmocka-facing functions renamed out of the way and
 * replaced below. */
#define observed_true kept_observed_true
#define observed_int_equal kept_observed_int_equal
#define observed_int_not_equal kept_observed_int_not_equal
#define observed_string_equal kept_observed_string_equal
#define observed_memory_equal kept_observed_memory_equal
#define observed_fail kept_observed_fail
#include "observe.c"
#undef observed_true
#undef observed_int_equal
#undef observed_int_not_equal
#undef observed_string_equal
#undef observed_memory_equal
#undef observed_fail

void observed_true(uintmax_t value, const char *expression, const char *file, int line);
void observed_int_equal(uintmax_t a, uintmax_t b, const char *file, int line);
void observed_int_not_equal(uintmax_t a, uintmax_t b, const char *file, int line);
void observed_string_equal(const char *a, const char *b, const char *file, int line);
void observed_memory_equal(const void *a, const void *b, size_t size, const char *file,
                           int line);
void observed_fail(const char *file, int line);

void observed_true(uintmax_t value, const char *expression, const char *file, int line)
{
    (void)expression;
    observe_exact(file, line, "T %d", value != 0);
}

void observed_int_equal(uintmax_t a, uintmax_t b, const char *file, int line)
{
    observe_exact(file, line, "I %ju %ju", a, b);
}

void observed_int_not_equal(uintmax_t a, uintmax_t b, const char *file, int line)
{
    observe_exact(file, line, "N %ju %ju", a, b);
}

void observed_string_equal(const char *a, const char *b, const char *file, int line)
{
    observe_exact_string(file, line, "S", a);
    observe_exact_string(file, line, "S", b);
}

void observed_memory_equal(const void *a, const void *b, size_t size, const char *file,
                           int line)
{
    observe_exact(file, line, "M %016" PRIx64 " %016" PRIx64 " %zu",
                  observe_hash(OBSERVE_HASH_START, a, size),
                  observe_hash(OBSERVE_HASH_START, b, size), size);
}

void observed_fail(const char *file, int line)
{
    (void)file, (void)line;
}
