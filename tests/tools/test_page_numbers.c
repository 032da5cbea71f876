/* test_page_numbers.c: every number a lesson page quotes from a program's
 * output, in its text and tables, is what that program prints today.
 *
 * The console blocks of the pages are checked whole by test_page_commands.c.
 * The numbers a page quotes in its sentences and tables are listed in
 * tests/tools/page_numbers.txt, each with the command that prints it;
 * tests/tools/page_numbers.sh runs every command once and checks that the
 * page still says it, that the command still prints it, and that the two
 * agree (to the decimals the page gives). docs/conventions.md, "Commands on
 * the pages", tells whoever writes a page to add a line there. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>

#include "shell.h"
#include "test_support.h"

#define TIMEOUT_SECONDS 120

static void every_number_quoted_on_a_page_is_printed(void **state)
{
    (void)state;
    const char *out = getenv("TEST_OUTPUT");
    if (!out || !*out)
        out = "build/test-output";
    ShellResult r = run_shell(NULL, TIMEOUT_SECONDS,
                              "sh tests/tools/page_numbers.sh tests/tools/page_numbers.txt "
                              "'%s/page-numbers'", out);
    print_message("%s", r.output);
    if (r.status != 0)
        fail_msg("a number on the pages is not what its program prints (above: list:line, "
                 "page, what differs); status %d", r.status);
    shell_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_number_quoted_on_a_page_is_printed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
