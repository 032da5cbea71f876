/* test_support.c: see test_support.h. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "test_support.h"

#include "harness/world_view.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "harness/file.h"
#include "shell.h" /* wait_child */

#define PATH_BUF 4096
#define TEXT_FILE_MAX (1 << 22) /* read_text: 4 MiB */
#define PATH_SLOTS 8 /* path_join's rotating buffers: "valid for a few calls" */

/* run_program: the time a lesson may take before it counts as hung. */
#define RUN_TIMEOUT_SECONDS 60

/* The environment the Makefile's test target sets, with its defaults. */
static const char *env_or(const char *name, const char *fallback)
{
    const char *v = getenv(name);
    return v && *v ? v : fallback;
}

static const char *test_output_dir(void)
{
    return env_or("TEST_OUTPUT", "build/test-output");
}

const char *path_join(const char *dir, const char *file)
{
    static char slots[PATH_SLOTS][PATH_BUF];
    static int next;
    char *buf = slots[next];
    next = (next + 1) % PATH_SLOTS;
    size_t n = strlen(dir);
    const char *sep = n > 0 && dir[n - 1] == '/' ? "" : "/";
    int len = snprintf(buf, PATH_BUF, "%s%s%s", dir, sep, file);
    if (len < 0 || len >= PATH_BUF)
        fail_msg("path too long: %s/%s", dir, file);
    return buf;
}

/* False for NULL: "no file to look for" (expect_run_refused's no_file). */
bool file_exists(const char *path)
{
    struct stat st;
    return path && stat(path, &st) == 0;
}

/* ---- expect_image ---- */

/* "02_zbuffer" -> "02": the LESSON= that `make update-expected` wants.
 * Other groups ("common", "tools") are selected by their whole name. */
static void lesson_selector(const char *group, char *out, size_t size)
{
    if (group[0] >= '0' && group[0] <= '9' && group[1] >= '0' && group[1] <= '9')
        snprintf(out, size, "%.2s", group);
    else
        snprintf(out, size, "%s", group);
}

/* UPDATE_EXPECTED=1 as the test program found it when it started (read by
 * test_hooks.c before the code under test runs), and never while grading. */
static bool update_requested(void)
{
    return test_update_expected();
}

/* Fails the test at the caller's line, after the lines print_error printed. */
static void fail_at(const char *file, int line)
{
    observed_fail(file, line);
}

static void update_expected(const Image *actual, const char *group, const char *path,
                            const char *file, int line)
{
    Error err;
    if (!make_dirs(path_join("tests/expected", group), &err) ||
        !image_write_png(actual, path, &err)) {
        print_error("cannot update the expected image: %s\n", err.msg);
        fail_at(file, line);
    }
    print_message("updated %s\n", path);
}

/* A diff picture for images of different sizes: the union of both, compared
 * where they overlap, magenta where only one of them has pixels. */
static bool diff_of_different_sizes(const Image *actual, const Image *expected,
                                    Image *diff, Error *err)
{
    int w = actual->width > expected->width ? actual->width : expected->width;
    int h = actual->height > expected->height ? actual->height : expected->height;
    if (!image_init(diff, w, h, err))
        return false;
    const Rgb mark = {255, 0, 255};
    for (int y = 0; y < h; y++) {
        for (int x = 0; x < w; x++) {
            bool in_a = x < actual->width && y < actual->height;
            bool in_e = x < expected->width && y < expected->height;
            Rgb c = mark;
            if (in_a && in_e) {
                Rgb ca = image_get(actual, x, y), ce = image_get(expected, x, y);
                if (ca.r == ce.r && ca.g == ce.g && ca.b == ce.b)
                    c = (Rgb){(uint8_t)(ce.r / 4), (uint8_t)(ce.g / 4), (uint8_t)(ce.b / 4)};
            }
            image_set(diff, x, y, c);
        }
    }
    return true;
}

/* Writes <name>.actual.png and <name>.diff.png; prints where they are. */
static void write_mismatch_pictures(const Image *actual, const Image *diff,
                                    const char *group, const char *name,
                                    const char *expected_path)
{
    char actual_name[PATH_BUF], diff_name[PATH_BUF];
    snprintf(actual_name, sizeof actual_name, "%s.actual.png", name);
    snprintf(diff_name, sizeof diff_name, "%s.diff.png", name);
    const char *dir = path_join(test_output_dir(), group);
    const char *actual_path = path_join(dir, actual_name);
    const char *diff_path = path_join(dir, diff_name);
    Error err;
    if (!make_dirs(dir, &err) || !image_write_png(actual, actual_path, &err) ||
        !image_write_png(diff, diff_path, &err))
        print_error("  (could not save the pictures: %s)\n", err.msg);
    print_error("  expected: %s\n  actual:   %s\n  diff:     %s  (magenta: pixels that differ)\n",
                expected_path, actual_path, diff_path);
}

/* A passing test leaves no stale .actual/.diff from an earlier failure. */
static void remove_old_mismatch_pictures(const char *group, const char *name)
{
    char file[PATH_BUF];
    const char *dir = path_join(test_output_dir(), group);
    snprintf(file, sizeof file, "%s.actual.png", name);
    unlink(path_join(dir, file));
    snprintf(file, sizeof file, "%s.diff.png", name);
    unlink(path_join(dir, file));
}

void expect_image_tolerant(const Image *actual, const char *group, const char *name,
                           long max_differing_pixels, int channel_tolerance,
                           const char *file, int line)
{
    char expected_path[PATH_BUF], lesson[PATH_BUF];
    snprintf(expected_path, sizeof expected_path, "tests/expected/%s/%s.png", group, name);
    lesson_selector(group, lesson, sizeof lesson);
    if (observing()) {
        /* Observed for the grader: the picture is written where the judge
         * finds it, and the judge compares it with the expected image, which
         * this program does not read (observe.h). */
        char actual_name[PATH_BUF];
        snprintf(actual_name, sizeof actual_name, "%s.actual.png", name);
        const char *dir = path_join(test_output_dir(), group);
        Error err;
        if (!make_dirs(dir, &err) || !image_write_png(actual, path_join(dir, actual_name), &err)) {
            print_error("cannot write the picture for the grader: %s\n", err.msg);
            fail_at(file, line);
        }
        observe_picture(file, line, group, name, max_differing_pixels, channel_tolerance,
                        actual->width, actual->height, (const uint8_t *)actual->rgb);
        return;
    }
    if (update_requested()) {
        update_expected(actual, group, expected_path, file, line);
        return;
    }
    if (!file_exists(expected_path)) {
        if (test_grading())
            print_error("no expected image %s\n", expected_path);
        else
            print_error("no expected image %s\n"
                        "  to create it from the current output (then look at it!):\n"
                        "  make update-expected LESSON=%s\n", expected_path, lesson);
        fail_at(file, line);
    }
    Image expected;
    Error err;
    if (!image_read_png(&expected, expected_path, &err)) {
        print_error("%s\n", err.msg);
        fail_at(file, line);
    }

    Image diff = {0, 0, NULL};
    ImageDiff d;
    bool same_size = actual->width == expected.width && actual->height == expected.height;
    if (same_size) {
        if (!image_compare(actual, &expected, channel_tolerance, &d, &diff, &err)) {
            image_free(&expected);
            print_error("%s\n", err.msg);
            fail_at(file, line);
        }
        if (d.differing <= max_differing_pixels) {
            image_free(&diff);
            image_free(&expected);
            remove_old_mismatch_pictures(group, name);
            return;
        }
        print_error("image %s/%s differs from the expected image\n", group, name);
    } else {
        print_error("image %s/%s is %dx%d, the expected image is %dx%d\n", group, name,
                    actual->width, actual->height, expected.width, expected.height);
        if (!diff_of_different_sizes(actual, &expected, &diff, &err))
            print_error("  (no diff picture: %s)\n", err.msg);
    }
    if (diff.rgb)
        write_mismatch_pictures(actual, &diff, group, name, expected_path);
    if (same_size)
        print_error("  %ld pixels differ (allowed: %ld, tolerance %d per channel), "
                    "largest channel difference %d, within x %d..%d, y %d..%d\n",
                    d.differing, max_differing_pixels, channel_tolerance,
                    d.max_channel_diff, d.x0, d.x1, d.y0, d.y1);
    /* (Not while grading: the expected images are the teacher's.) */
    if (!test_grading())
        print_error("  if the change is intended: make update-expected LESSON=%s\n", lesson);
    image_free(&diff);
    image_free(&expected);
    fail_at(file, line);
}

/* ---- run_program ---- */

/* The whole of a temporary file, as a NUL-terminated string. */
static char *slurp(FILE *fp)
{
    size_t cap = 4096, len = 0;
    char *buf = malloc(cap);
    if (!buf)
        fail_msg("out of memory");
    rewind(fp);
    size_t got;
    while ((got = fread(buf + len, 1, cap - len - 1, fp)) > 0) {
        len += got;
        if (cap - len - 1 == 0) {
            cap *= 2;
            buf = realloc(buf, cap);
            if (!buf)
        fail_msg("out of memory");
        }
    }
    buf[len] = '\0';
    return buf;
}

/* In the child: stdin from /dev/null, stdout and stderr to the files, then exec.
 * If exec fails, its errno goes back through report_fd (closed by a
 * successful exec, as it is close-on-exec). */
/* The directory the next child runs in (run_program_in), or NULL: this one. */
static const char *child_dir;

static void exec_child(const char *path, char **argv, FILE *out, FILE *err, int report_fd)
{
    int null_fd = open("/dev/null", O_RDONLY);
    if ((child_dir && chdir(child_dir) != 0) || null_fd < 0 || dup2(null_fd, STDIN_FILENO) < 0 ||
        dup2(fileno(out), STDOUT_FILENO) < 0 || dup2(fileno(err), STDERR_FILENO) < 0) {
        int e = errno;
        (void)!write(report_fd, &e, sizeof e);
        _exit(127);
    }
    execv(path, argv);
    int e = errno;
    (void)!write(report_fd, &e, sizeof e);
    _exit(127);
}

static RunResult run_in(const char *dir, const char *program, const char *const *args)
{
    const char *path = path_join(dir, program);
    size_t argc = 0;
    while (args && args[argc])
        argc++;
    char **argv = calloc(argc + 2, sizeof *argv);
    if (!argv)
        fail_msg("out of memory");
    argv[0] = (char *)path; /* execv's argv is not const, but it does not write */
    for (size_t i = 0; i < argc; i++)
        argv[i + 1] = (char *)args[i];

    FILE *out = tmpfile(), *err = tmpfile();
    int report[2];
    if (!out || !err || pipe(report) != 0)
        fail_msg("cannot set up a run of %s: %s", path, strerror(errno));
    fcntl(report[1], F_SETFD, FD_CLOEXEC);
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid < 0)
        fail_msg("cannot fork to run %s: %s", path, strerror(errno));
    if (pid == 0)
        exec_child(path, argv, out, err, report[1]);
    close(report[1]);
    int exec_errno = 0;
    ssize_t n = read(report[0], &exec_errno, sizeof exec_errno);
    close(report[0]);

    RunResult r;
    r.status = wait_child(pid, RUN_TIMEOUT_SECONDS, false);
    r.out = slurp(out);
    r.err = slurp(err);
    fclose(out);
    fclose(err);
    free(argv);
    if (n == (ssize_t)sizeof exec_errno) {
        run_result_free(&r);
        fail_msg("cannot run %s: %s (was it built? make builds the lessons and tools)",
                 path, strerror(exec_errno));
    }
    /* How the program ended, for the grader's judge (observe.h). Not what it
     * printed: a student's debug print may be there; what a test reads of
     * that, its checks observe. */
    observe_exact(__FILE__, __LINE__, "run %s status %d", program, r.status);
    return r;
}

/* The bytes of a file the test reads, observed (none: "absent"). */
static void observe_file(const char *path)
{
    if (!observing())
        return;
    char *data = NULL;
    size_t len = 0;
    Error err;
    if (read_file(path, 1 << 28, &data, &len, &err))
        observe_exact_data(__FILE__, __LINE__, "file", data, len);
    else
        observe_exact(__FILE__, __LINE__, "file absent");
    free(data);
}

bool files_same_bytes(const char *a, const char *b)
{
    observe_file(a);
    observe_file(b);
    FILE *f = fopen(a, "rb"), *g = fopen(b, "rb");
    bool same = f && g;
    for (int c; same && (c = getc(f)) != EOF;)
        same = c == getc(g);
    same = same && getc(g) == EOF;
    if (f)
        fclose(f);
    if (g)
        fclose(g);
    return same;
}

RunResult run_program(const char *program, const char *const *args)
{
    return run_in(env_or("BIN_DIR", "build/bin"), program, args);
}

RunResult run_program_in(const char *dir, const char *program, const char *const *args)
{
    child_dir = dir;
    RunResult r = run_in(abs_bin_dir(), program, args);
    child_dir = NULL;
    return r;
}

RunResult run_tool(const char *program, const char *const *args)
{
    return run_in(env_or("TOOL_DIR", "build/tools"), program, args);
}

void run_result_free(RunResult *r)
{
    free(r->out);
    free(r->err);
    r->out = NULL;
    r->err = NULL;
}

/* ---- test_dir ---- */

/* rm -rf, without following symbolic links out of the tree. */
static void remove_tree(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return;
    if (S_ISDIR(st.st_mode)) {
        DIR *d = opendir(path);
        if (d) {
            struct dirent *e;
            while ((e = readdir(d)) != NULL) {
                if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
                    continue;
                char child[PATH_BUF];
                snprintf(child, sizeof child, "%s/%s", path, e->d_name);
                remove_tree(child);
            }
            closedir(d);
        }
        rmdir(path);
    } else {
        unlink(path);
    }
}

const char *abs_bin_dir(void)
{
    static char path[4096 + 16];
    const char *bin = env_or("BIN_DIR", "build/bin");
    char here[4096];
    if (bin[0] == '/')
        snprintf(path, sizeof path, "%s", bin);
    else if (getcwd(here, sizeof here))
        snprintf(path, sizeof path, "%s/%s", here, bin);
    else
        fail_msg("getcwd failed");
    return path;
}

const char *test_dir(const char *name)
{
    if (name[0] == '\0' || strstr(name, "..") || name[0] == '/')
        fail_msg("test_dir wants a plain name, not \"%s\"", name);
    /* Its own buffers, so that path_join calls do not overwrite it. */
    static char slots[PATH_SLOTS][PATH_BUF];
    static int next;
    char *dir = slots[next];
    next = (next + 1) % PATH_SLOTS;
    int len = snprintf(dir, PATH_BUF, "%s/tmp/%s", test_output_dir(), name);
    if (len < 0 || len >= PATH_BUF)
        fail_msg("path too long: %s/tmp/%s", test_output_dir(), name);
    remove_tree(dir);
    Error err;
    if (!make_dirs(dir, &err))
        fail_msg("%s", err.msg);
    return dir;
}

/* ---- files ---- */

Path in_dir(const char *dir, const char *file)
{
    Path p;
    int len = snprintf(p.path, sizeof p.path, "%s", path_join(dir, file));
    if (len < 0 || (size_t)len >= sizeof p.path)
        fail_msg("path too long: %s/%s", dir, file);
    return p;
}

void write_text(const char *path, const char *text)
{
    FILE *fp = fopen(path, "wb");
    if (!fp)
        fail_msg("cannot create %s: %s", path, strerror(errno));
    bool written = fputs(text, fp) != EOF;
    if (fclose(fp) != 0 || !written)
        fail_msg("cannot write %s", path);
}

const char *write_text_in(const char *dir, const char *name, const char *text)
{
    const char *path = path_join(dir, name);
    write_text(path, text);
    return path;
}

const char *write_program_in(const char *dir, const char *name, const char *text)
{
    const char *path = write_text_in(dir, name, text);
    if (chmod(path, 0755) != 0)
        fail_msg("chmod %s: %s", path, strerror(errno));
    return path;
}

char *read_text(const char *path)
{
    char *data = NULL;
    size_t len = 0;
    Error err;
    if (!read_file(path, TEXT_FILE_MAX, &data, &len, &err))
        fail_msg("%s", err.msg);
    observe_exact_data(__FILE__, __LINE__, "text", data, len);
    return data;
}

Image read_png(const char *path)
{
    Image im;
    Error err;
    if (!image_read_png(&im, path, &err))
        fail_msg("cannot read %s: %s", path, err.msg);
    observe_exact(__FILE__, __LINE__, "png %016" PRIx64,
                  observe_picture_hash(im.width, im.height, im.rgb));
    return im;
}

/* ---- runs of a lesson ---- */

char *run_ok(const char *program, const char *const *args)
{
    RunResult r = run_program(program, args);
    if (r.status != 0)
        fail_msg("%s exited with status %d, expected 0; stderr:\n%s", program, r.status, r.err);
    char *out = r.out;
    r.out = NULL;
    run_result_free(&r);
    return out;
}

void expect_run_error(const char *program, const char *const *args, int status,
                      const char *stderr_text)
{
    RunResult r = run_program(program, args);
    if (r.status != status || strcmp(r.err, stderr_text) != 0)
        fail_msg("exit %d, stderr:\n%s\nexpected exit %d, stderr:\n%s", r.status, r.err,
                 status, stderr_text);
    run_result_free(&r);
}

void expect_run_refused(const char *program, const char *const *args, int status,
                        const char *message, const char *no_file)
{
    RunResult r = run_program(program, args);
    char want[PATH_BUF];
    snprintf(want, sizeof want, "%s: error: %s\n", program, message);
    assert_string_equal(r.err, want);
    expect_count(status, r.status, "exit status");
    assert_string_equal(r.out, "");
    if (file_exists(no_file))
        fail_msg("%s was written by a run that failed", no_file);
    run_result_free(&r);
}

void expect_line(const char *out, const char *line)
{
    observe_exact_string(__FILE__, __LINE__, "line", line);
    observe_value("has the line", strstr(out, line) != NULL);
    if (!strstr(out, line))
        fail_msg("the summary lacks the line\n%s\nit was:\n%s", line, out);
}

void expect_no_message(const char *err, const char *program)
{
    size_t n = strlen(program);
    bool found = false;
    for (const char *l = err; l && *l && !found;) {
        found = strncmp(l, program, n) == 0 && l[n] == ':';
        l = strchr(l, '\n');
        l = l ? l + 1 : NULL;
    }
    observe_exact_string(__FILE__, __LINE__, "program", program);
    observe_value("has no message", !found);
    if (found)
        fail_msg("%s wrote a message of its own on stderr:\n%s", program, err);
}

int compare_strings(const void *a, const void *b)
{
    return strcmp((const char *)a, (const char *)b);
}

double seconds_since(const struct timespec *start)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - start->tv_sec) + (double)(now.tv_nsec - start->tv_nsec) / 1e9;
}

void expect_default_world_view(const char *program, const char *expected)
{
    char name[128];
    snprintf(name, sizeof name, "%s_world_out", program);
    const char *dir = test_dir(name);
    Path out = in_dir(dir, "out.png"), world = in_dir(dir, "world.png");
    const char *args[] = {"--out", out.path, "--world-out", world.path, NULL};
    char *summary = run_ok(program, args);
    char line[TEST_PATH_MAX + 16];
    snprintf(line, sizeof line, "  wrote %s\n", world.path);
    expect_line(summary, line);
    free(summary);
    Image im = read_png(world.path);
    expect_count(WORLD_VIEW_WIDTH, im.width, "world view width");
    expect_count(WORLD_VIEW_HEIGHT, im.height, "world view height");
    expect_image(&im, program, expected);
    image_free(&im);
}
