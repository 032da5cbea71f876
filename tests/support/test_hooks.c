/* test_hooks.c: what every test binary does before its main() starts.
 *
 * - TEST_FILTER=name in the environment runs only the tests of that name
 *   (cmocka's * and ? wildcards work). make grade runs each test alone this
 *   way when a test binary crashed or hung, so that one broken test costs
 *   only its own points.
 * - stdout is unbuffered: cmocka prints a test's name and result on stdout and
 *   its failure messages on stderr. When both go to one log (make test, make
 *   grade), each message then lands under the test that printed it. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>

/* A constructor rather than a call in every test's main(): the tests stay as
 * they are, and a new test binary gets the same behaviour for free. */
__attribute__((constructor)) static void before_main(void)
{
    const char *filter = getenv("TEST_FILTER");
    if (filter && *filter)
        cmocka_set_test_filter(filter);
    setvbuf(stdout, NULL, _IONBF, 0);
}
