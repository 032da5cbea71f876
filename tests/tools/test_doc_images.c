/* test_doc_images.c: the pictures on the pages are what the programs draw
 * today. tools/make-doc-images.sh renders every picture of docs/images/
 * into a directory of the test's; each must hold the same pixels as the
 * committed one (the files may differ: a PNG encodes a picture many ways),
 * and the two directories the same names: no committed picture that the
 * script does not make, none it makes that is not committed. When a lesson
 * changes a picture on purpose, `sh tools/make-doc-images.sh` renders them
 * anew: look at each before committing it. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "harness/image_io.h"
#include "shell.h"
#include "test_support.h"

static void every_picture_on_the_pages_is_what_its_command_draws(void **state)
{
    (void)state;
    const char *bin = getenv("BIN_DIR") ? getenv("BIN_DIR") : "build/bin";
    char build[512];
    snprintf(build, sizeof build, "%s", bin);
    char *slash = strrchr(build, '/');
    if (!slash || strcmp(slash, "/bin") != 0)
        fail_msg("BIN_DIR %s does not end in /bin", bin);
    *slash = '\0';
    char *dir = strdup(test_dir("doc_images"));
    char top[4096];
    if (!getcwd(top, sizeof top))
        fail_msg("cannot tell the current directory");
    ShellResult r = run_shell(top, 300, "sh tools/make-doc-images.sh '%s' '%s/%s' >/dev/null", build,
                              top, dir);
    if (r.status != 0)
        fail_msg("make-doc-images.sh failed, status %d:\n%s", r.status, r.output);
    shell_result_free(&r);

    ShellResult names = run_shell(top, 30, "cd '%s' && find . -name '*.png' | sort", dir);
    ShellResult committed = run_shell(top, 30, "cd docs/images && find . -name '*.png' | sort");
    if (strcmp(names.output, committed.output) != 0)
        fail_msg("docs/images/ and what make-doc-images.sh makes differ in names:\n"
                 "made:\n%s\ncommitted:\n%s", names.output, committed.output);
    int stale = 0, n = 0;
    char *save = NULL;
    for (char *name = strtok_r(names.output, "\n", &save); name; name = strtok_r(NULL, "\n", &save)) {
        n++;
        Image made, page;
        Error err;
        char a[4096], b[4096];
        snprintf(a, sizeof a, "%s/%s", dir, name + 2);
        snprintf(b, sizeof b, "docs/images/%s", name + 2);
        if (!image_read_png(&made, a, &err) || !image_read_png(&page, b, &err))
            fail_msg("%s", err.msg);
        ImageDiff d = {0};
        bool sized = made.width == page.width && made.height == page.height;
        if (!sized || (image_compare(&made, &page, 0, &d, NULL, &err) && d.differing > 0)) {
            if (sized)
                print_error("docs/images/%s is stale: %ld pixels differ from what its command "
                            "draws now, in (%d,%d)-(%d,%d)\n", name + 2, d.differing, d.x0, d.y0,
                            d.x1, d.y1);
            else
                print_error("docs/images/%s is stale: %dx%d, its command draws %dx%d\n", name + 2,
                            page.width, page.height, made.width, made.height);
            stale++;
        }
        image_free(&made);
        image_free(&page);
    }
    shell_result_free(&names);
    shell_result_free(&committed);
    free(dir);
    if (n < 50)
        fail_msg("only %d pictures made: make-doc-images.sh makes them all", n);
    if (stale > 0)
        fail_msg("%d of %d pictures on the pages are stale (above): run "
                 "sh tools/make-doc-images.sh, look at each, commit them", stale, n);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_picture_on_the_pages_is_what_its_command_draws),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
