/* test_test_support.c: the test helpers themselves (tests/support/).
 *
 * run_program is checked with the POSIX shell, /bin/sh, standing in for a
 * lesson: BIN_DIR and TOOL_DIR are pointed at /bin for those tests only.
 * The checks of expect.h are tested by their words, and once by a failing
 * check run in a child process. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "harness/image_io.h"
#include "harness/shade.h"
#include "target.h"
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

/* ---- the words of a failed check (expect.h) ---- */

/* msg holds want, or the test fails showing both. */
static void expect_words(const char *msg, const char *want)
{
    if (strcmp(msg, want) != 0)
        fail_msg("the message is\n  %s\nexpected\n  %s", msg, want);
}

static void count_checks_say_expected_and_got_in_decimal(void **state)
{
    (void)state;
    char msg[256] = "";
    assert_true(count_message(msg, sizeof msg, 9226, 9226, "covered pixels"));
    assert_false(count_message(msg, sizeof msg, 9226, 9230, "covered pixels"));
    expect_words(msg, "covered pixels: expected 9226, got 9230");
    assert_false(count_message(msg, sizeof msg, 67108864, 67174400, ""));
    expect_words(msg, "expected 67108864, got 67174400"); /* not 0x4000000, 0x4010000 */
    assert_true(at_least_message(msg, sizeof msg, 1, 1, "differing pixels"));
    assert_false(at_least_message(msg, sizeof msg, 1, 0, "differing pixels"));
    expect_words(msg, "differing pixels: expected at least 1, got 0");
    assert_true(at_most_message(msg, sizeof msg, 9, 9, "wrong pixels"));
    assert_false(at_most_message(msg, sizeof msg, 9, 12, "wrong pixels"));
    expect_words(msg, "wrong pixels: expected at most 9, got 12");
}

static void colour_checks_say_both_colours_in_decimal(void **state)
{
    (void)state;
    char msg[256] = "";
    Rgb red = {255, 0, 0}, dark = {0, 0, 3};
    assert_true(colour_message(msg, sizeof msg, red, red, "background"));
    assert_false(colour_message(msg, sizeof msg, red, dark, "background"));
    expect_words(msg, "background: expected rgb 255,0,0, got rgb 0,0,3");
    assert_false(colour_that_message(msg, sizeof msg, dark, false, "pixel (3, 4)",
                                     "a shade of red"));
    expect_words(msg, "pixel (3, 4): expected a shade of red, got rgb 0,0,3");

    Image im;
    Error err;
    assert_true(image_init(&im, 20, 50, &err));
    image_set(&im, 12, 40, dark);
    assert_true(pixel_message(msg, sizeof msg, &im, 12, 40, dark, "left wall"));
    assert_false(pixel_message(msg, sizeof msg, &im, 12, 40, red, "left wall"));
    expect_words(msg, "left wall: pixel (12, 40): expected rgb 255,0,0, got rgb 0,0,3");
    assert_false(pixel_message(msg, sizeof msg, &im, 20, 0, red, ""));
    expect_words(msg, "pixel (20, 0) is outside the 20 x 50 picture");
    image_free(&im);
}

static void face_checks_name_the_faces_and_their_id_colours(void **state)
{
    (void)state;
    char msg[256] = "";
    Image im;
    Error err;
    assert_true(image_init(&im, 20, 50, &err));
    image_set(&im, 12, 40, face_id_colour(2));
    assert_int_equal(face_at(&im, 12, 40), 2);
    assert_int_equal(face_at(&im, 0, 0), NO_FACE);
    expect_count(1, faces_shown(&im), "pixels with a face");
    assert_true(face_message(msg, sizeof msg, &im, 12, 40, 2, ""));
    assert_false(face_message(msg, sizeof msg, &im, 12, 40, 3, ""));
    expect_words(msg, "pixel (12, 40): expected face 3 (rgb 0,0,4), got face 2 (rgb 0,0,3)");
    assert_false(face_message(msg, sizeof msg, &im, 0, 0, 65535, "strip B"));
    expect_words(msg, "strip B: pixel (0, 0): expected face 65535 (rgb 1,0,0), "
                      "got no face (rgb 0,0,0)");
    image_free(&im);

    Target t;
    assert_true(target_init(&t, 4, 4, &err));
    for (int i = 0; i < 4 * 4; i++)
        t.face[i] = NO_FACE;
    t.face[1 * 4 + 3] = 7;
    expect_count(7, target_face_at(&t, 3, 1), "face in the target");
    assert_true(target_face_message(msg, sizeof msg, &t, 3, 1, 7, ""));
    assert_false(target_face_message(msg, sizeof msg, &t, 3, 1, NO_FACE, "corner"));
    expect_words(msg, "corner: pixel (3, 1): expected no face, got face 7");
    assert_false(target_face_message(msg, sizeof msg, &t, 0, 0, 0, ""));
    expect_words(msg, "pixel (0, 0): expected face 0, got no face");
    target_free(&t);
}

/* In a child process, a cmocka test whose expect_count fails. */
static void failing_count_check(void **state)
{
    (void)state;
    expect_count(9226, 9230, "covered pixels");
}

static void a_failed_check_fails_the_test_and_prints_its_words(void **state)
{
    (void)state;
    fflush(stdout);
    fflush(stderr);
    FILE *log = tmpfile();
    assert_non_null(log);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        dup2(fileno(log), STDOUT_FILENO);
        dup2(fileno(log), STDERR_FILENO);
        cmocka_set_test_filter("failing_count_check"); /* whatever TEST_FILTER said */
        const struct CMUnitTest child[] = {cmocka_unit_test(failing_count_check)};
        _exit(cmocka_run_group_tests(child, NULL, NULL) == 1 ? 0 : 3);
    }
    int st;
    assert_int_equal(waitpid(pid, &st, 0), pid);
    char text[8192];
    rewind(log);
    size_t n = fread(text, 1, sizeof text - 1, log);
    text[n] = '\0';
    fclose(log);
    if (!WIFEXITED(st) || WEXITSTATUS(st) != 0)
        fail_msg("the failing check did not fail its test once; its run printed:\n%s", text);
    if (!strstr(text, "covered pixels: expected 9226, got 9230"))
        fail_msg("the failure lacks the words; it printed:\n%s", text);
    if (!strstr(text, "test_test_support.c"))
        fail_msg("the failure does not point at the test's file; it printed:\n%s", text);
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
        cmocka_unit_test(count_checks_say_expected_and_got_in_decimal),
        cmocka_unit_test(colour_checks_say_both_colours_in_decimal),
        cmocka_unit_test(face_checks_name_the_faces_and_their_id_colours),
        cmocka_unit_test(a_failed_check_fails_the_test_and_prints_its_words),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
