/* test_test_support.c: the test helpers themselves (tests/support/).
 *
 * run_program is checked with the POSIX shell, /bin/sh, standing in for a
 * lesson: BIN_DIR and TOOL_DIR are pointed at /bin for those tests only. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "image.h"
#include "test_support.h"

/* Saves an environment variable and restores it afterwards. */
typedef struct {
    const char *name;
    char *value; /* NULL when it was unset */
} SavedEnv;

static SavedEnv env_set(const char *name, const char *value)
{
    SavedEnv s = {name, NULL};
    const char *old = getenv(name);
    if (old) {
        s.value = malloc(strlen(old) + 1);
        assert_non_null(s.value);
        strcpy(s.value, old);
    }
    if (value)
        setenv(name, value, 1);
    else
        unsetenv(name);
    return s;
}

static void env_restore(SavedEnv *s)
{
    if (s->value)
        setenv(s->name, s->value, 1);
    else
        unsetenv(s->name);
    free(s->value);
}

static void path_join_puts_one_slash_between(void **state)
{
    (void)state;
    assert_string_equal(path_join("out", "a.png"), "out/a.png");
    assert_string_equal(path_join("out/", "a.png"), "out/a.png");
}

static void test_dir_starts_empty_every_time(void **state)
{
    (void)state;
    const char *base = getenv("TEST_OUTPUT") ? getenv("TEST_OUTPUT") : "build/test-output";
    char want[512];
    snprintf(want, sizeof want, "%s/tmp/fresh", base);
    const char *first = test_dir("fresh");
    assert_string_equal(first, want);

    char leftover[512];
    snprintf(leftover, sizeof leftover, "%s/sub/old.txt", first);
    assert_int_equal(mkdir(path_join(first, "sub"), 0777), 0);
    FILE *fp = fopen(leftover, "w");
    assert_non_null(fp);
    fclose(fp);

    const char *again = test_dir("fresh");
    assert_false(file_exists(leftover));
    assert_false(file_exists(path_join(again, "sub")));
    struct stat st;
    assert_int_equal(stat(again, &st), 0);
    assert_true(S_ISDIR(st.st_mode));
}

static void run_program_captures_output_and_exit_status(void **state)
{
    (void)state;
    SavedEnv bin = env_set("BIN_DIR", "/bin");
    const char *args[] = {"-c", "printf 'to out'; printf 'to err' >&2; exit 3", NULL};
    RunResult r = run_program("sh", args);
    env_restore(&bin);
    assert_int_equal(r.status, 3);
    assert_string_equal(r.out, "to out");
    assert_string_equal(r.err, "to err");
    run_result_free(&r);
}

static void run_program_reports_a_signal_as_128_plus_its_number(void **state)
{
    (void)state;
    SavedEnv bin = env_set("BIN_DIR", "/bin");
    const char *args[] = {"-c", "kill -KILL $$", NULL};
    RunResult r = run_program("sh", args);
    env_restore(&bin);
    assert_int_equal(r.status, 128 + 9); /* SIGKILL is 9 everywhere */
    run_result_free(&r);
}

static void run_program_gives_an_empty_stdin(void **state)
{
    (void)state;
    /* cat ends at once on /dev/null; an inherited stdin could make it wait. */
    SavedEnv bin = env_set("BIN_DIR", "/bin");
    const char *args[] = {"-c", "cat; echo done", NULL};
    RunResult r = run_program("sh", args);
    env_restore(&bin);
    assert_int_equal(r.status, 0);
    assert_string_equal(r.out, "done\n");
    run_result_free(&r);
}

static void run_program_captures_large_output_whole(void **state)
{
    (void)state;
    /* 200000 bytes: far more than a pipe buffer holds. */
    SavedEnv bin = env_set("BIN_DIR", "/bin");
    const char *args[] = {"-c", "head -c 200000 /dev/zero | tr '\\0' a", NULL};
    RunResult r = run_program("sh", args);
    env_restore(&bin);
    assert_int_equal(r.status, 0);
    assert_int_equal(strlen(r.out), 200000);
    assert_int_equal(strspn(r.out, "a"), 200000);
    run_result_free(&r);
}

static void run_tool_looks_in_tool_dir(void **state)
{
    (void)state;
    SavedEnv tool = env_set("TOOL_DIR", "/bin");
    const char *args[] = {"-c", "exit 5", NULL};
    RunResult r = run_tool("sh", args);
    env_restore(&tool);
    assert_int_equal(r.status, 5);
    run_result_free(&r);
}

/* expect_image reads tests/expected/ relative to the current directory: run it
 * inside a scratch directory so that the repository's images are not touched. */
static void expect_image_update_then_match(void **state)
{
    (void)state;
    const char *dir = test_dir("expect_image");
    char cwd[4096];
    assert_non_null(getcwd(cwd, sizeof cwd));
    assert_int_equal(chdir(dir), 0);
    SavedEnv out = env_set("TEST_OUTPUT", "output");

    Image im;
    Error err;
    assert_true(image_init(&im, 3, 2, &err));
    image_set(&im, 2, 1, (Rgb){10, 20, 30});

    /* UPDATE_EXPECTED=1 writes the expected image... */
    SavedEnv update = env_set("UPDATE_EXPECTED", "1");
    expect_image(&im, "selftest", "picture");
    env_restore(&update);
    update = env_set("UPDATE_EXPECTED", NULL);
    Image written;
    bool exists = image_read_png(&written, "tests/expected/selftest/picture.png", &err);

    /* ...which then matches exactly, and within a tolerance after a change. */
    expect_image(&im, "selftest", "picture");
    image_set(&im, 0, 0, (Rgb){1, 0, 0});
    expect_image_tolerant(&im, "selftest", "picture", 1, 1, __FILE__, __LINE__);
    env_restore(&update);
    env_restore(&out);
    assert_int_equal(chdir(cwd), 0);

    assert_true(exists);
    assert_int_equal(written.width, 3);
    assert_int_equal(written.height, 2);
    Rgb c = image_get(&written, 2, 1);
    assert_int_equal(c.r, 10);
    assert_int_equal(c.g, 20);
    assert_int_equal(c.b, 30);
    image_free(&written);
    image_free(&im);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(path_join_puts_one_slash_between),
        cmocka_unit_test(test_dir_starts_empty_every_time),
        cmocka_unit_test(run_program_captures_output_and_exit_status),
        cmocka_unit_test(run_program_reports_a_signal_as_128_plus_its_number),
        cmocka_unit_test(run_program_gives_an_empty_stdin),
        cmocka_unit_test(run_program_captures_large_output_whole),
        cmocka_unit_test(run_tool_looks_in_tool_dir),
        cmocka_unit_test(expect_image_update_then_match),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
