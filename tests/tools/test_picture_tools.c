/* test_picture_tools.c: tools/magnify and tools/bar_chart, which draw the
 * pages' close-ups and charts: each writes its picture, and refuses, with
 * one line and status 2, an OUT that names its own input by any spelling
 * (./in.png, a link), leaving the input as it was. tools/diagrams writes its
 * nine pictures all or none: a failure, or a signal, at one of them leaves
 * none of the others, and a signal ends it with one line. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "harness/image_io.h"
#include "shell.h"
#include "test_support.h"

#define CSV "group,one,two\nsmall,1.5,2\nlarge,4,0.5\n"

/* The bytes of file path (a PNG holds NULs: compared as bytes). */
static char *bytes_of(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    char *b = malloc(1 << 20);
    assert_non_null(b);
    *n = fread(b, 1, 1 << 20, f);
    fclose(f);
    return b;
}

/* tool with args must refuse: status 2, one line "<tool>: error: ...",
 * and the file at input keep its bytes. */
static void expect_refused_keeping(const char *tool, const char *const *args, const char *input)
{
    size_t n0, n1;
    char *before = bytes_of(input, &n0);
    RunResult r = run_tool(tool, args);
    char prefix[64];
    snprintf(prefix, sizeof prefix, "%s: error: ", tool);
    const char *newline = strchr(r.err, '\n');
    if (r.status != 2 || strncmp(r.err, prefix, strlen(prefix)) != 0 || !newline || newline[1])
        fail_msg("%s %s %s: status %d, wanted 2 and one line \"%s...\":\n%s", tool, args[0],
                 args[1], r.status, prefix, r.err);
    char *after = bytes_of(input, &n1);
    if (n0 != n1 || memcmp(before, after, n0) != 0)
        fail_msg("%s %s %s changed its input", tool, args[0], args[1]);
    free(before);
    free(after);
    run_result_free(&r);
}

static void magnify_scales_and_never_replaces_its_input(void **state)
{
    (void)state;
    const char *dir = test_dir("magnify");
    char in[512], out[512], same[512], link[512];
    snprintf(in, sizeof in, "%s/in.png", dir);
    snprintf(out, sizeof out, "%s/out.png", dir);
    snprintf(same, sizeof same, "%s/./in.png", dir);
    snprintf(link, sizeof link, "%s/link.png", dir);
    Image im;
    Error err;
    assert_true(image_init(&im, 3, 2, &err));
    image_fill(&im, (Rgb){200, 40, 40});
    assert_true(image_write_png(&im, in, &err));
    image_free(&im);

    const char *args[] = {in, out, "4", NULL};
    RunResult r = run_tool("magnify", args);
    assert_int_equal(r.status, 0);
    run_result_free(&r);
    Image big = read_png(out);
    expect_count(12, big.width, "magnified width");
    expect_count(8, big.height, "magnified height");
    image_free(&big);

    const char *onto[] = {in, same, "4", NULL};
    expect_refused_keeping("magnify", onto, in);
    assert_int_equal(symlink("in.png", link), 0);
    const char *through[] = {in, link, "4", NULL};
    expect_refused_keeping("magnify", through, in);
}

static void bar_chart_draws_and_never_replaces_its_input(void **state)
{
    (void)state;
    const char *dir = test_dir("bar_chart");
    char in[512], out[512], same[512];
    snprintf(in, sizeof in, "%s/times.csv", dir);
    snprintf(out, sizeof out, "%s/chart.png", dir);
    snprintf(same, sizeof same, "%s/../bar_chart/times.csv", dir);
    write_text(in, CSV);

    const char *args[] = {in, out, "milliseconds", NULL};
    RunResult r = run_tool("bar_chart", args);
    assert_int_equal(r.status, 0);
    run_result_free(&r);
    Image chart = read_png(out);
    expect_count(1280, chart.width, "chart width");
    image_free(&chart);

    const char *onto[] = {in, same, "milliseconds", NULL};
    expect_refused_keeping("bar_chart", onto, in);
}

/* Entries of dir besides . and .. */
static int entries_of(const char *dir)
{
    ShellResult r = run_shell(dir, 10, "ls -A | wc -l");
    int n = atoi(r.output);
    shell_result_free(&r);
    return n;
}

static void diagrams_are_written_all_or_none(void **state)
{
    (void)state;
    char abs_tools[PATH_MAX]; /* build/tools, beside build/bin */
    snprintf(abs_tools, sizeof abs_tools, "%s/../tools", abs_bin_dir());

    /* The fourth picture's name is a directory: status 1, one line, and the
     * three drawn before it are not left behind. */
    const char *dir = test_dir("diagrams_fail");
    char blocked[512];
    snprintf(blocked, sizeof blocked, "%s/05_clipping_cases.png", dir);
    assert_int_equal(mkdir(blocked, 0755), 0);
    ShellResult r = run_shell(dir, 60, "%s/diagrams .", abs_tools);
    if (r.status != 1 || strcmp(r.output, "diagrams: error: cannot write ./05_clipping_cases.png: "
                                          "Is a directory\n") != 0)
        fail_msg("status %d, wanted 1 and one line:\n%s", r.status, r.output);
    shell_result_free(&r);
    expect_count(1, entries_of(dir), "entries left (the directory alone)");

    /* The first picture goes into a pipe whose buffer is full, so the run
     * waits there; SIGTERM then ends it with one line and no file. */
    dir = test_dir("diagrams_signal");
    char fifo[512];
    snprintf(fifo, sizeof fifo, "%s/02_edge_functions.png", dir);
    assert_int_equal(mkfifo(fifo, 0644), 0);
    int fd = open(fifo, O_RDWR | O_NONBLOCK); /* a reader that never reads */
    assert_true(fd >= 0);
    static const char junk[4096];
    while (write(fd, junk, sizeof junk) > 0)
        continue;
    assert_int_equal(errno, EAGAIN);
    r = run_shell(dir, 60, "%s/diagrams . & sleep 1; kill -TERM $!; wait $!; echo status $?",
                  abs_tools);
    close(fd);
    if (strcmp(r.output, "diagrams: error: stopped by SIGTERM\nstatus 143\n") != 0)
        fail_msg("wanted one line and status 143:\n%s", r.output);
    shell_result_free(&r);
    expect_count(1, entries_of(dir), "entries left (the pipe alone)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(magnify_scales_and_never_replaces_its_input),
        cmocka_unit_test(bar_chart_draws_and_never_replaces_its_input),
        cmocka_unit_test(diagrams_are_written_all_or_none),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
