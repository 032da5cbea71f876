/* test_page_commands.c: every command on the pages runs as printed.
 *
 * The pages (README.md and the docs/ pages) show commands for a student to paste. This
 * test runs tests/tools/page_commands.sh, which takes every command of them
 * and runs it in a fresh copy of the tree (the files git knows, and the built
 * build/ beside them, so nothing rebuilds; `make run` first):
 *
 *   ```sh       every line is a command (blank and comment lines aside; a
 *               line ending in \ goes on); a comment `# exit N` says the
 *               command ends with status N, else it must end with 0.
 *   ```console  "$ " lines are commands; the lines after one are what it
 *               prints, stdout and stderr together. "..." on a line of its
 *               own stands for any number of lines, <name> (a word in angle
 *               brackets, e.g. <seconds>) for any text within a line.
 *               "$ echo $?" and a number: the status of the command before.
 *   other blocks are not run; a command line in a block with no language is
 *               an error (mark it sh or console).
 *
 * Commands that take minutes (make test or grade without TEST=, bench,
 * sanitize, fuzz, valgrind) are dry-run with make -n. docs/conventions.md,
 * "Commands on the pages", says the same for whoever writes a page.
 *
 * On a failure the output names page:line and the command, what the page
 * expected and what came. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shell.h"
#include "test_support.h"

#define TIMEOUT_SECONDS 120

static const char *build_dir(char *buf, size_t size)
{
    /* BIN_DIR is <build>/bin (make test sets it); the build is its parent. */
    const char *bin = getenv("BIN_DIR");
    if (!bin || !*bin)
        bin = "build/bin";
    snprintf(buf, size, "%s", bin);
    char *slash = strrchr(buf, '/');
    if (slash && strcmp(slash, "/bin") == 0)
        *slash = '\0';
    else
        snprintf(buf, size, "build");
    return buf;
}

static void every_page_command_runs_as_printed(void **state)
{
    (void)state;
    char build[4096];
    const char *out = getenv("TEST_OUTPUT");
    if (!out || !*out)
        out = "build/test-output";
    ShellResult r = run_shell(NULL, TIMEOUT_SECONDS, "sh tests/tools/page_commands.sh '%s' '%s/tmp/page-commands'",
                              build_dir(build, sizeof build), out);
    print_message("%s", r.output);
    if (r.status != 0)
        fail_msg("a command on the pages did not run as printed (above: page:line, expected, came); "
                 "status %d",
                 r.status);
    shell_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_page_command_runs_as_printed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
