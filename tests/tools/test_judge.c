/* test_judge.c: tools/judge, which decides whether a graded test passed from
 * the record of what its checks saw (tests/support/observe.h), holding no
 * student code. Records are written by hand here: the teacher's run, then
 * the student's run as honest code, wrong code and a forger would leave it. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "harness/file.h"
#include "test_support.h"

/* The teacher's record of a made-up test: equality checks, a bound checked
 * in a loop, a number, the end. */
static const char TEACHER[] = "D 3 0123456789abcdef\n"
                              "B tests/x.c:10 < 1 1 40\n"
                              "C tests/x.c:12 0x1.4p+1 0x1.4p+1 0x1p-10\n"
                              "E passed\n";

typedef struct {
    int status;
    char *out;
} Verdict;

/* judge TEACHER STUDENT on two records written to files; its status and words. */
static Verdict judge(const char *teacher, const char *student, const char *outputs)
{
    const char *dir = test_dir("judge");
    Path ref = in_dir(dir, "teacher.obs"), rec = in_dir(dir, "student.obs");
    write_text(ref.path, teacher);
    if (student)
        write_text(rec.path, student);
    const char *args[] = {ref.path, rec.path, outputs ? outputs : dir, NULL};
    RunResult r = run_tool("judge", args);
    Verdict v = {r.status, r.out};
    free(r.err);
    return v;
}

/* The judge's status and a phrase of what it said. */
static void expect_said(Verdict v, int status, const char *words)
{
    if (v.status != status || !strstr(v.out, words))
        fail_msg("judge said (status %d, want %d; want the words \"%s\"):\n%s", v.status, status,
                 words, v.out);
    free(v.out);
}

static void expect_verdict(const char *teacher, const char *student, int status,
                           const char *words)
{
    expect_said(judge(teacher, student, NULL), status, words);
}

static void the_teachers_own_record_passes(void **state)
{
    (void)state;
    expect_verdict(TEACHER, TEACHER, 0, "judge: passed: 44 checks agree");
}

/* Other values in the equality checks, however the test program ended. */
static void other_values_fail(void **state)
{
    (void)state;
    expect_verdict(TEACHER,
                   "D 3 0123456789abcdee\nB tests/x.c:10 < 1 1 40\n"
                   "C tests/x.c:12 0x1.4p+1 0x1.4p+1 0x1p-10\nE passed\n",
                   1, "found other values than the teacher's solution's");
    expect_verdict(TEACHER,
                   "D 2 0123456789abcdef\nB tests/x.c:10 < 1 1 40\n"
                   "C tests/x.c:12 0x1.4p+1 0x1.4p+1 0x1p-10\nE passed\n",
                   1, "(2 checks, the teacher's run 3)");
}

/* A bound holds for other values than the teacher's, split into other runs:
 * 0 and 1 are both at most 1. A 2 is not. */
static void a_bound_takes_any_value_within_it(void **state)
{
    (void)state;
    expect_verdict(TEACHER,
                   "D 3 0123456789abcdef\nB tests/x.c:10 < 0 1 15\nB tests/x.c:10 < 1 1 25\n"
                   "C tests/x.c:12 0x1.4p+1 0x1.4p+1 0x1p-10\nE passed\n",
                   0, "passed");
    expect_verdict(TEACHER,
                   "D 3 0123456789abcdef\nB tests/x.c:10 < 1 1 39\nB tests/x.c:10 < 2 1 1\n"
                   "C tests/x.c:12 0x1.4p+1 0x1.4p+1 0x1p-10\nE passed\n",
                   1, "tests/x.c:10: got 2, wanted at most 1");
    /* The bound is the teacher's: a record that moves it changes nothing. */
    expect_verdict(TEACHER,
                   "D 3 0123456789abcdef\nB tests/x.c:10 < 2 2 40\n"
                   "C tests/x.c:12 0x1.4p+1 0x1.4p+1 0x1p-10\nE passed\n",
                   1, "got 2, wanted at most 1");
    /* Fewer checks of the bound than the teacher's run made. */
    expect_verdict(TEACHER,
                   "D 3 0123456789abcdef\nB tests/x.c:10 < 1 1 39\n"
                   "C tests/x.c:12 0x1.4p+1 0x1.4p+1 0x1p-10\nE passed\n",
                   1, "took another way");
}

/* The number: within the teacher's tolerance of the teacher's expected value
 * (2.5 within 2^-10), whatever expected value and tolerance the record says. */
static void a_number_is_judged_by_the_teachers_tolerance(void **state)
{
    (void)state;
    expect_verdict(TEACHER,
                   "D 3 0123456789abcdef\nB tests/x.c:10 < 1 1 40\n"
                   "C tests/x.c:12 0x1.4008p+1 0x1.4p+1 0x1p-10\nE passed\n",
                   0, "passed");
    expect_verdict(TEACHER,
                   "D 3 0123456789abcdef\nB tests/x.c:10 < 1 1 40\n"
                   "C tests/x.c:12 0x1.6p+1 0x1.6p+1 0x1p+3\nE passed\n",
                   1, "tests/x.c:12: got 2.75, wanted 2.5 within");
    expect_verdict(TEACHER,
                   "D 3 0123456789abcdef\nB tests/x.c:10 < 1 1 40\n"
                   "C tests/x.c:12 nan 0x1.4p+1 0x1p-10\nE passed\n",
                   1, "got nan");
}

/* What the test program says of itself counts against it, never for it. */
static void a_failure_or_an_early_end_fails(void **state)
{
    (void)state;
    expect_verdict(TEACHER, "D 3 0123456789abcdef\nF tests/x.c:11\n", 1,
                   "the test failed at tests/x.c:11");
    expect_verdict(TEACHER,
                   "D 3 0123456789abcdef\nB tests/x.c:10 < 1 1 40\n"
                   "C tests/x.c:12 0x1.4p+1 0x1.4p+1 0x1p-10\nE failed\n",
                   1, "the test itself failed");
    expect_verdict(TEACHER, "D 3 0123456789abcdef\nB tests/x.c:10 < 1 1 40\n", 1,
                   "the record ends after tests/x.c:10: the test did not finish");
    expect_verdict(TEACHER, "E passed\n", 1, "took another way");
    expect_verdict(TEACHER, "", 1, "the record ends after the start");
    expect_verdict(TEACHER, NULL, 1, "the test wrote no record");
}

/* A record is input: lines that are not entries, a line too long, entries past
 * the end, NUL bytes; each a failure with words, never a crash. */
static void a_malformed_record_fails_cleanly(void **state)
{
    (void)state;
    expect_verdict(TEACHER, "D three 0123\n", 1, "an entry that is not one");
    expect_verdict(TEACHER, "Q tests/x.c:1\n", 1, "an entry that is not one");
    expect_verdict(TEACHER, "D 3 0123456789abcdef", 1, "a line that is not an entry");
    expect_verdict(TEACHER,
                   "D 3 0123456789abcdef\nB tests/x.c:10 < 1 1 0\n", 1, "an entry that is not one");
    char *long_line = malloc(20000);
    assert_non_null(long_line);
    memset(long_line, 'D', 19998);
    long_line[19998] = '\n';
    long_line[19999] = '\0';
    expect_verdict(TEACHER, long_line, 1, "a line that is not an entry");
    free(long_line);
    expect_verdict(TEACHER,
                   "D 3 0123456789abcdef\nB tests/x.c:10 < 1 1 40\n"
                   "C tests/x.c:12 0x1.4p+1 0x1.4p+1 0x1p-10\nE passed\nE passed\n",
                   1, "goes on past its end");
}

/* A teacher's record that did not pass judges nothing: status 2. */
static void a_reference_that_did_not_pass_is_refused(void **state)
{
    (void)state;
    expect_verdict("D 1 0000000000000001\nE failed\n", "D 1 0000000000000001\nE failed\n", 2,
                   "cannot judge");
    expect_verdict("D 1 0000000000000001\nF tests/x.c:3\nE passed\n", "E passed\n", 2,
                   "cannot judge");
    expect_verdict("D 1 0000000000000001\n", "D 1 0000000000000001\n", 2, "cannot judge");
}

/* ---- pictures ---- */

/* tests/expected/02_zbuffer/default.png, the picture of a P entry below. */
static Image expected_picture(void)
{
    return read_png("tests/expected/02_zbuffer/default.png");
}

static char *picture_record(const Image *im, long allowed)
{
    char *s = malloc(512);
    assert_non_null(s);
    snprintf(s, 512, "P tests/x.c:20 02_zbuffer default %ld 0 %d %d %016" PRIx64 "\nE passed\n",
             allowed, im->width, im->height, observe_picture_hash(im->width, im->height, im->rgb));
    return s;
}

/* The student's picture, written where the judge looks for it. */
static const char *student_outputs(const Image *im)
{
    const char *dir = test_dir("judge_outputs");
    Error err;
    char *sub = malloc(4096);
    assert_non_null(sub);
    snprintf(sub, 4096, "%s/02_zbuffer", dir);
    assert_true(make_dirs(sub, &err));
    if (im)
        assert_true(image_write_png(im, path_join(sub, "default.actual.png"), &err));
    free(sub);
    return dir;
}

static Verdict judge_picture(long allowed, const Image *claimed, const Image *on_disk)
{
    Image want = expected_picture();
    char *teacher = picture_record(&want, allowed), *student = picture_record(claimed, allowed);
    Verdict v = judge(teacher, student, student_outputs(on_disk));
    free(teacher);
    free(student);
    image_free(&want);
    return v;
}

/* The picture itself: equal to the teacher's (by its hash), or within what
 * the check allows of tests/expected/, read from the run's own file. */
static void a_picture_is_compared_with_the_expected_one(void **state)
{
    (void)state;
    Image want = expected_picture();
    expect_said(judge_picture(0, &want, NULL), 0, "passed");

    Image three = expected_picture();
    for (int k = 0; k < 3; k++)
        image_set(&three, 10 + k, 20, (Rgb){1, 2, 3});
    expect_said(judge_picture(5, &three, &three), 0, "passed");
    expect_said(judge_picture(0, &three, &three), 1,
                           "3 pixels differ from the expected picture (allowed: 0");
    /* The record claims a picture the file is not. */
    expect_said(judge_picture(5, &three, &want), 1,
                           "the picture on disk is not the one the test checked");
    image_free(&three);
    image_free(&want);
}

/* Equality checks that differ before a picture that differs (a test that
 * read its picture back, whose hash is such a check): the judge names the
 * picture too, since no message of the test does. */
static void a_picture_behind_other_values_is_named(void **state)
{
    (void)state;
    Image want = expected_picture(), three = expected_picture();
    for (int k = 0; k < 3; k++)
        image_set(&three, 10 + k, 20, (Rgb){1, 2, 3});
    char *teacher_picture = picture_record(&want, 0), *student_picture = picture_record(&three, 0);
    char teacher[640], student[640];
    snprintf(teacher, sizeof teacher, "D 1 0123456789abcdef\n%s", teacher_picture);
    snprintf(student, sizeof student, "D 1 fedcba9876543210\n%s", student_picture);
    expect_said(judge(teacher, student, student_outputs(&three)), 1,
                "found other values than the teacher's solution's (1 checks, the teacher's run 1)"
                ": the messages above say which; the first picture that differs: tests/x.c:20: "
                "picture 02_zbuffer/default: 3 pixels differ");
    /* The same picture: the words on the checks alone. */
    snprintf(student, sizeof student, "D 1 fedcba9876543210\n%s", teacher_picture);
    Verdict v = judge(teacher, student, student_outputs(&want));
    if (v.status != 1 || strstr(v.out, "picture"))
        fail_msg("want the checks' words alone (status 1):\n%s", v.out);
    free(v.out);
    free(teacher_picture);
    free(student_picture);
    image_free(&three);
    image_free(&want);
}

/* The run's picture must be its own file: not missing, not a link to the
 * expected picture (which the run could not read, but a link needs no
 * reading). */
static void a_picture_that_is_a_link_is_refused(void **state)
{
    (void)state;
    Image want = expected_picture();
    Image other = expected_picture();
    image_set(&other, 0, 0, (Rgb){9, 9, 9});
    expect_said(judge_picture(5, &other, NULL), 1, "cannot read the picture");
    const char *dir = student_outputs(NULL);
    char here[4096], target[8192];
    assert_non_null(getcwd(here, sizeof here));
    snprintf(target, sizeof target, "%s/tests/expected/02_zbuffer/default.png", here);
    const char *link = path_join(dir, "02_zbuffer/default.actual.png");
    unlink(link);
    assert_int_equal(symlink(target, link), 0);
    /* A record claiming the expected picture's pixels under another hash. */
    Image want2 = expected_picture();
    char *teacher = picture_record(&want2, 5);
    char student[512];
    snprintf(student, sizeof student,
             "P tests/x.c:20 02_zbuffer default 5 0 %d %d 0000000000000001\nE passed\n",
             want.width, want.height);
    Verdict v = judge(teacher, student, dir);
    expect_said(v, 1, "cannot read the picture");
    free(teacher);
    image_free(&want2);
    image_free(&other);
    image_free(&want);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_teachers_own_record_passes),
        cmocka_unit_test(other_values_fail),
        cmocka_unit_test(a_bound_takes_any_value_within_it),
        cmocka_unit_test(a_number_is_judged_by_the_teachers_tolerance),
        cmocka_unit_test(a_failure_or_an_early_end_fails),
        cmocka_unit_test(a_malformed_record_fails_cleanly),
        cmocka_unit_test(a_reference_that_did_not_pass_is_refused),
        cmocka_unit_test(a_picture_is_compared_with_the_expected_one),
        cmocka_unit_test(a_picture_behind_other_values_is_named),
        cmocka_unit_test(a_picture_that_is_a_link_is_refused),
    };
    return cmocka_run_group_tests_name("tools judge", tests, NULL, NULL);
}
