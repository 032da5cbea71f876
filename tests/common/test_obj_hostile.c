/* test_obj_hostile.c: OBJ files that no modelling program writes, but that a
 * student will find or make. test_mesh.c tests each defect of a single line
 * (index 0, out of range either way, fewer than 3 corners, nan, inf, 1e300,
 * a NUL byte, CRLF and odd white space, a missing .mtl, no faces); here are
 * the ones that threaten the reader itself: a line megabytes long that is
 * wrong, a material library that never ends or never answers, and inputs the
 * fuzzer found (tests/fuzz/fuzz_obj.c). Every message names file:line. */
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

#include "harness/mesh_build.h"
#include "test_support.h"

#define TRIANGLE "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
/* A reader stuck on a pipe would hang the test run: this alarm ends it. */
#define HANG_LIMIT_SECONDS 20

static void expect_parse_error(const char *text, size_t len, const char *expected)
{
    Mesh m;
    Error err = {"(no message)"};
    mesh_init(&m);
    if (mesh_parse_obj(&m, text, len, "x.obj", NULL, &err))
        fail_msg("parsing succeeded, expected \"%s\"", expected);
    if (strcmp(err.msg, expected) != 0)
        fail_msg("wrong message\n  got:      \"%s\"\n  expected: \"%s\"", err.msg, expected);
    assert_int_equal(m.nfaces, 0);
    mesh_free(&m);
}

/* ---- Lines of any length ------------------------------------------------- */

#define HUGE_LINE 4000000 /* bytes */

/* The first 40 characters of a word, then "...": how messages quote it. */
static void quoted_start(char *out, const char *first, char fill)
{
    size_t n = strlen(first);
    strcpy(out, first);
    memset(out + n, fill, 40 - n);
    strcpy(out + 40, "...");
}

static void megabyte_line_that_is_wrong_is_named_with_its_line(void **state)
{
    (void)state;
    /* Line 4 is a vertex whose x is four million digits: a number far beyond
     * any double. The message quotes the first 40 characters and names line 4. */
    char *text = malloc(HUGE_LINE + 64);
    assert_non_null(text);
    strcpy(text, TRIANGLE "v ");
    size_t n = strlen(text);
    memset(text + n, '7', HUGE_LINE);
    strcpy(text + n + HUGE_LINE, " 0 0\nf 1 2 3\n");
    char word[64], expected[256];
    quoted_start(word, "", '7');
    snprintf(expected, sizeof expected,
             "x.obj:4: vertex coordinate '%s' is out of range (|x| <= 1e+30)", word);
    expect_parse_error(text, strlen(text), expected);

    /* The same line as an unknown statement "qq777...": a warning, naming line 4. */
    memset(text + strlen(TRIANGLE), 'q', 2);
    Mesh m;
    Error err;
    mesh_init(&m);
    assert_true(mesh_parse_obj(&m, text, strlen(text), "x.obj", NULL, &err));
    assert_int_equal(m.nwarnings, 1);
    quoted_start(word, "qq", '7');
    snprintf(expected, sizeof expected, "x.obj:4: '%s' statements are ignored", word);
    assert_string_equal(m.warnings[0], expected);
    mesh_free(&m);
    free(text);
}

static void face_of_a_million_corners_is_refused_by_its_count(void **state)
{
    (void)state;
    /* A face line of 1 000 000 corners: refused for its size before any corner
     * is read, with the count and the line. */
    size_t corners = 1000000;
    char *text = malloc(corners * 3 + 64);
    assert_non_null(text);
    strcpy(text, TRIANGLE "f");
    char *p = text + strlen(text);
    for (size_t i = 0; i < corners; i++) {
        memcpy(p, " -1", 3);
        p += 3;
    }
    strcpy(p, "\n");
    expect_parse_error(text, strlen(text), "x.obj:4: face has 1000000 corners (at most 4096)");
    free(text);
}

/* ---- Material libraries that are not files ----------------------------- */

static void mtllib_that_is_a_pipe_or_a_device_is_a_warning(void **state)
{
    (void)state;
    /* A named pipe with no writer would block the reader for ever, and
     * /dev/zero never ends: both are refused as "not a regular file", with a
     * warning naming the mtllib line, and the mesh is read without them. */
    const char *dir = test_dir("obj_mtl_pipe");
    char obj[512], fifo[512], expected[1024];
    snprintf(obj, sizeof obj, "%s", path_join(dir, "x.obj"));
    snprintf(fifo, sizeof fifo, "%s", path_join(dir, "pipe.mtl"));
    assert_int_equal(mkfifo(fifo, 0600), 0);
    write_text(obj, "mtllib pipe.mtl\n# a comment\nmtllib /dev/zero\n" TRIANGLE "f 1 2 3\n");

    alarm(HANG_LIMIT_SECONDS);
    Mesh m;
    Error err;
    mesh_init(&m);
    bool ok = mesh_load_obj(&m, obj, &err);
    alarm(0);
    if (!ok)
        fail_msg("%s", err.msg);
    assert_int_equal(m.nfaces, 1);
    assert_int_equal(m.nwarnings, 2);
    snprintf(expected, sizeof expected,
             "%s:1: material library 'pipe.mtl' is not a regular file; ignored", obj);
    assert_string_equal(m.warnings[0], expected);
    snprintf(expected, sizeof expected,
             "%s:3: material library '/dev/zero' is not a regular file; ignored", obj);
    assert_string_equal(m.warnings[1], expected);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(megabyte_line_that_is_wrong_is_named_with_its_line),
        cmocka_unit_test(face_of_a_million_corners_is_refused_by_its_count),
        cmocka_unit_test(mtllib_that_is_a_pipe_or_a_device_is_a_warning),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
