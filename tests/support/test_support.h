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
 * test_dir: a fresh empty directory for one test's files, under $TEST_OUTPUT.
 *
 * Checks that say what was expected and what came, in words and decimal
 * (expect_count, expect_pixel, expect_face_at, ...): see expect.h, included
 * here so that every test has them.
 *
 * Every check, these and cmocka's, is also observed for the grader's judge
 * when the grader asks (observe.h, included here: it replaces cmocka's
 * assert_* and fail() by checks that observe). */
#ifndef TEST_SUPPORT_H
#define TEST_SUPPORT_H

#include <stdbool.h>
#include <time.h>

#include "expect.h"
#include "harness/image_io.h"
#include "observe.h"

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
/* Whether files a and b hold the same bytes (false if either cannot be read). */
bool files_same_bytes(const char *a, const char *b);
/* Like run_program, run in directory dir: what it writes to its default
 * out/<program>.png goes there, not into the student's out/. */
RunResult run_program_in(const char *dir, const char *program, const char *const *args);
/* Like run_program for a program in $TOOL_DIR. */
RunResult run_tool(const char *program, const char *const *args);
void run_result_free(RunResult *r);

/* $BIN_DIR (the lessons' executables) as an absolute path, for a command run
 * in another directory (shell.h). */
const char *abs_bin_dir(void);
/* "$TEST_OUTPUT/tmp/<name>", created empty (removed first if it existed).
 * The test programs run side by side (make test): a name one of them uses,
 * no other may (a lesson's name alone, say, in two of them). */
const char *test_dir(const char *name);
/* A path inside a directory: static buffer rotation, valid for a few calls. */
const char *path_join(const char *dir, const char *file);

bool file_exists(const char *path);

/* ---- files ---- */

/* A path of its own (not path_join's rotating buffers), for a test that keeps
 * several: Path out = in_dir(dir, "out.png"); then out.path. */
#define TEST_PATH_MAX 512
typedef struct {
    char path[TEST_PATH_MAX];
} Path;
Path in_dir(const char *dir, const char *file);

/* Writes text to path, replacing the file; fails the test when it cannot. */
void write_text(const char *path, const char *text);
/* write_text into dir/name; returns the path (path_join's buffer). */
const char *write_text_in(const char *dir, const char *name, const char *text);
/* write_text_in, then made executable (a script: text starts with "#!"). */
const char *write_program_in(const char *dir, const char *name, const char *text);
/* The whole file as a NUL-terminated string to free(); fails the test when it
 * cannot be read (or is larger than 4 MiB). */
char *read_text(const char *path);
/* Reads a PNG back (a lesson's output, say); fails the test, naming the file,
 * when it cannot. The caller frees the image. */
Image read_png(const char *path);

/* ---- runs of a lesson ---- */

/* run_program, requiring exit status 0 (else the test fails with the status and
 * stderr); returns stdout, to free(). */
char *run_ok(const char *program, const char *const *args);

/* Runs program with its default scene and --world-out, checks the summary
 * names the picture, its documented size, and compares it with
 * tests/expected/<program>/<expected>.png. */
void expect_default_world_view(const char *program, const char *expected);
/* The run must fail with exactly this stderr (whole lines, newline included)
 * and this exit status. */
void expect_run_error(const char *program, const char *const *args, int status,
                      const char *stderr_text);
/* The run must fail with the one line "<program>: error: <message>" on
 * stderr, this exit status, nothing on stdout and no file no_file. */
void expect_run_refused(const char *program, const char *const *args, int status,
                        const char *message, const char *no_file);
/* out must hold line somewhere (a summary line, with its newline if given). */
void expect_line(const char *out, const char *line);
/* err, a run's stderr, must hold no message of program's own (a line that
 * begins "<program>:", an error or a warning). Other lines are not the
 * program's: a student's debug print to stderr costs nothing. */
void expect_no_message(const char *err, const char *program);

/* strcmp for qsort over an array of fixed-size char arrays. */
int compare_strings(const void *a, const void *b);

/* Seconds from start (taken with clock_gettime(CLOCK_MONOTONIC)) to now. */
double seconds_since(const struct timespec *start);

/* From tests/support/test_hooks.c: UPDATE_EXPECTED=1 as it was when the
 * program started (never while grading), and whether make grade runs it. */
bool test_update_expected(void);
bool test_grading(void);

#endif
