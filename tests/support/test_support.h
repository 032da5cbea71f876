/* test_support.h: what every test of the series shares.
 *
 * Include after <cmocka.h> (which needs <stdarg.h>, <stddef.h>, <stdint.h>, <setjmp.h>).
 *
 * expect_image: compare a picture with tests/expected/<group>/<name>.png.
 *   Exact by default; a test that allows differences says how many pixels may
 *   differ and by how much per channel. On a mismatch it writes
 *     $TEST_OUTPUT/<group>/<name>.actual.png   and   <name>.diff.png
 *   prints the three paths, the number of differing pixels, the largest channel
 *   difference and the command that accepts an intended change
 *   (make update-expected LESSON=NN), then fails the test.
 *   With UPDATE_EXPECTED=1 in the environment it writes the expected image
 *   instead (that is what make update-expected does).
 *
 * run_program: run one lesson's executable ($BIN_DIR/<program>) or a tool
 *   ($TOOL_DIR/<program>) with arguments, capturing stdout, stderr and the exit
 *   status, to test the command line end to end.
 *
 * test_dir: a fresh empty directory for one test's files, under $TEST_OUTPUT. */
#ifndef TEST_SUPPORT_H
#define TEST_SUPPORT_H

#include <stdbool.h>

#include "image.h"

void expect_image_tolerant(const Image *actual, const char *group, const char *name,
                           long max_differing_pixels, int channel_tolerance,
                           const char *file, int line);
#define expect_image(actual, group, name) \
    expect_image_tolerant((actual), (group), (name), 0, 0, __FILE__, __LINE__)

typedef struct {
    int status;  /* exit status, or 128 + signal number if it died of a signal */
    char *out;   /* everything printed on stdout, NUL-terminated */
    char *err;   /* everything printed on stderr, NUL-terminated */
} RunResult;

/* args: NULL-terminated, without the program name. Fails the test when the
 * program cannot be started at all. Kills it after 60 seconds (status 124). */
RunResult run_program(const char *program, const char *const *args);
/* Like run_program for a program in $TOOL_DIR. */
RunResult run_tool(const char *program, const char *const *args);
void run_result_free(RunResult *r);

/* "$TEST_OUTPUT/tmp/<name>", created empty (removed first if it existed). */
const char *test_dir(const char *name);
/* A path inside a directory: static buffer rotation, valid for a few calls. */
const char *path_join(const char *dir, const char *file);

bool file_exists(const char *path);

#endif
