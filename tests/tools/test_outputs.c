/* test_outputs.c: what a run does with its outputs (docs/robustness.md,
 * "Outputs"), run end to end against the lessons:
 *
 *   - two outputs, or an output and an input (OBJ, .mtl, segments, --compare
 *     reference), that are one file under two names are refused, status 2,
 *     a lesson's own outputs (--colour-out, --hiz-out, ...) as the shared ones,
 *     and one its default run writes (lesson 09's skip picture) as if given;
 *   - a failed output leaves no output of the run new or changed;
 *   - SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGUSR1 and SIGABRT during a
 *     large write remove the temporary files, status 128 + the signal; a
 *     signal at any time prints one line naming it; a file size limit
 *     (ulimit -f) is a failure with one line, status 1;
 *   - pipes and other files that are not regular are refused quickly;
 *   - --out - writes the PNG on standard output, the summary on stderr;
 *   - a failed write to standard output is a failure (status 1), a pipe
 *     whose reader has gone too (no SIGPIPE);
 *   - the --compare reader refuses truncated, malformed and oversized files;
 *   - and the smaller cases: long names, read-only files, links, a name
 *     ending in '/', a byte order mark, a model far from the origin, control
 *     characters in warnings. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "shell.h"
#include "test_support.h"

#define TEXT_MAX 2048
#define TRIANGLE_OBJ "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
#define OLD_BYTES "the bytes of an earlier file\n"

/* Entries of dir, "." and ".." aside. */
static int entries(const char *dir)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    closedir(d);
    return n;
}

/* True when dir holds a file whose name starts with '.' (a temporary file). */
static bool has_temporary(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return false;
    bool found = false;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (e->d_name[0] == '.' && strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
            found = true;
    closedir(d);
    return found;
}

static void expect_refused(const char *lesson, const char *const *args, int status,
                           const char *message_fmt, const char *dir)
{
    char message[TEXT_MAX];
    snprintf(message, sizeof message, message_fmt, dir, dir, dir);
    expect_run_refused(lesson, args, status, message, NULL);
}

/* The run fails with status and the one line message on stderr; what it
 * printed on stdout before (the summary, ahead of --compare) does not matter. */
static void expect_failure(const char *lesson, const char *const *args, int status,
                           const char *message)
{
    RunResult r = run_program(lesson, args);
    char want[TEXT_MAX];
    snprintf(want, sizeof want, "%s: error: %s\n", lesson, message);
    assert_string_equal(r.err, want);
    assert_int_equal(r.status, status);
    run_result_free(&r);
}

/* ---- 1. one file under two names ---- */

static void outputs_and_inputs_are_compared_by_identity(void **state)
{
    (void)state;
    const char *dir = test_dir("outputs_identity");
    Path a = in_dir(dir, "a.png"), dot_a = in_dir(dir, "./a.png"),
         up_a = in_dir(dir, "new/../a.png"), sym = in_dir(dir, "link.png"),
         obj = in_dir(dir, "m.obj"), mtl = in_dir(dir, "m.mtl"), steps = in_dir(dir, "st"),
         step1 = in_dir(dir, "st/step_0001.png"), hard = in_dir(dir, "hard.obj");
    write_text(obj.path, "mtllib m.mtl\n" TRIANGLE_OBJ);
    write_text(mtl.path, "newmtl red\nKd 1 0 0\n");
    assert_int_equal(symlink("a.png", sym.path), 0); /* dangling: a.png does not exist */
    assert_int_equal(link(obj.path, hard.path), 0);

    const char *same_name[] = {"--out", a.path, "--depth-out", dot_a.path, NULL};
    expect_refused("02_zbuffer", same_name, 2, "--out and --depth-out both name %s/./a.png", dir);
    const char *dotdot[] = {"--out", a.path, "--id-out", up_a.path, NULL};
    expect_refused("03_perspective_z", dotdot, 2, "--out and --id-out both name %s/new/../a.png",
                   dir);
    const char *dangling[] = {"--out", a.path, "--world-out", sym.path, NULL};
    expect_refused("04_scanline_inverse_z", dangling, 2,
                   "--out and --world-out both name %s/link.png", dir);
    const char *hard_link[] = {"--obj", obj.path, "--out", hard.path, NULL};
    expect_refused("02_zbuffer", hard_link, 2, "--obj and --out both name %s/hard.obj", dir);
    const char *naive[] = {"--out", a.path, "--compare-naive", dot_a.path, NULL};
    expect_refused("03_perspective_z", naive, 2, "--out and --compare-naive both name %s/./a.png",
                   dir);
    const char *diff[] = {"--out", a.path, "--compare", obj.path, "--depth-out",
                          in_dir(dir, "./a.diff.png").path, NULL};
    expect_refused("02_zbuffer", diff, 2,
                   "--depth-out names %s/a.diff.png, where the diff picture of --out goes", dir);
    const char *in_steps[] = {"--out", step1.path, "--steps", steps.path, NULL};
    expect_refused("02_zbuffer", in_steps, 2,
                   "--out names %s/st/step_0001.png, where --steps writes its pictures", dir);
    const char *steps01[] = {"--out", step1.path, "--steps", steps.path, NULL};
    expect_refused("01_ybuffer", steps01, 2,
                   "--out names %s/st/step_0001.png, where --steps writes its pictures", dir);
    const char *onto_mtl[] = {"--obj", obj.path, "--out", a.path, "--depth-out", mtl.path, NULL};
    char want[TEXT_MAX];
    snprintf(want, sizeof want, "--depth-out names %s, a material library that %s reads",
             mtl.path, obj.path);
    expect_run_refused("04_scanline_inverse_z", onto_mtl, 2, want, a.path);
    char *now = read_text(mtl.path);
    assert_string_equal(now, "newmtl red\nKd 1 0 0\n");
    free(now);
    assert_false(file_exists(a.path));
    assert_false(file_exists(steps.path));

    /* A lesson's own outputs, checked as the shared ones: against each other,
     * the shared ones and the inputs, by any spelling; empty or "-" refused. */
    const char *own_two[] = {"--colour-out", a.path, "--shade-count-out", dot_a.path, NULL};
    expect_refused("08_early_z", own_two, 2, "--colour-out and --shade-count-out both name "
                   "%s/./a.png", dir);
    const char *own_out[] = {"--out", a.path, "--hiz-out", up_a.path, NULL};
    expect_refused("09_hierarchical_z", own_out, 2, "--out and --hiz-out both name "
                   "%s/new/../a.png", dir);
    const char *own_empty[] = {"--precision-plot", "", NULL};
    expect_refused("06_depth_precision", own_empty, 2, "--precision-plot: the file name is empty",
                   dir);
    const char *own_stdout[] = {"--colour-out", "-", NULL};
    expect_refused("09_hierarchical_z", own_stdout, 2, "--colour-out: '-' (standard output) is "
                   "for --out only; name a file", dir);
    const char *own_mtl[] = {"--obj", obj.path, "--out", a.path, "--compare-drop", mtl.path,
                             NULL};
    snprintf(want, sizeof want, "--compare-drop names %s, a material library that %s reads",
             mtl.path, obj.path);
    expect_run_refused("05_clipping", own_mtl, 2, want, a.path);
    now = read_text(mtl.path);
    assert_string_equal(now, "newmtl red\nKd 1 0 0\n");
    free(now);
}

/* Lesson 09's default run (no --out) writes its skip picture too, to
 * out/09_hierarchical_z_skips.png: checked as if --skip-out had been given,
 * against an input and against another output. */
static void a_default_output_is_checked_as_a_given_one(void **state)
{
    (void)state;
    const char *dir = test_dir("outputs_default_skip");
    Path skips = in_dir(dir, "out/09_hierarchical_z_skips.png");
    assert_int_equal(mkdir(path_join(dir, "out"), 0777), 0);
    write_text(skips.path, TRIANGLE_OBJ);
    const char *as_obj[] = {"--obj", "out/09_hierarchical_z_skips.png", NULL};
    const char *as_ids[] = {"--id-out", "out/09_hierarchical_z_skips.png", NULL};
    const char *const *args[] = {as_obj, as_ids};
    const char *first[] = {"--obj", "--id-out"};
    for (int i = 0; i < 2; i++) {
        RunResult r = run_program_in(dir, "09_hierarchical_z", args[i]);
        char want[TEXT_MAX];
        snprintf(want, sizeof want, "09_hierarchical_z: error: %s and --skip-out both name "
                 "out/09_hierarchical_z_skips.png\n", first[i]);
        assert_string_equal(r.err, want);
        expect_count(2, r.status, "exit status");
        run_result_free(&r);
        char *now = read_text(skips.path);
        assert_string_equal(now, TRIANGLE_OBJ);
        free(now);
    }
    assert_false(file_exists(path_join(dir, "out/09_hierarchical_z.png")));
}

/* Every output a run writes is listed under its summary, a lesson's own too. */
static void every_output_is_listed_in_the_summary(void **state)
{
    (void)state;
    const char *dir = test_dir("outputs_listed");
    Path out = in_dir(dir, "out.png"), colour = in_dir(dir, "colour.png"),
         heat = in_dir(dir, "heat.png"), hiz = in_dir(dir, "hiz.png"),
         plot = in_dir(dir, "plot.png"), ladder = in_dir(dir, "ladder.png");
    struct { const char *lesson, *flag; const Path *path; } runs[] = {
        {"08_early_z", "--colour-out", &colour}, {"08_early_z", "--shade-count-out", &heat},
        {"09_hierarchical_z", "--hiz-out", &hiz}, {"06_depth_precision", "--precision-plot", &plot},
        {"06_depth_precision", "--ladder-out", &ladder},
    };
    for (size_t k = 0; k < sizeof runs / sizeof runs[0]; k++) {
        const char *args[] = {"--width", "40", "--height", "30", "--out", out.path,
                              runs[k].flag, runs[k].path->path, NULL};
        char *text = run_ok(runs[k].lesson, args);
        char line[TEXT_MAX];
        snprintf(line, sizeof line, "  wrote %s\n", runs[k].path->path);
        expect_line(text, line);
        free(text);
    }
}

/* ---- 2. all or nothing ---- */

static void failed_output_leaves_no_output_of_the_run(void **state)
{
    (void)state;
    const char *dir = test_dir("outputs_all_or_nothing");
    Path out = in_dir(dir, "new/out.png"), old = in_dir(dir, "old.png");
    write_text(old.path, OLD_BYTES);
    /* /dev/full fails only when written: after the picture was. */
    const char *args[] = {"--width", "16", "--height", "16", "--out", out.path, "--id-out",
                          old.path, "--depth-out", "/dev/full", NULL};
    const char *all[] = {"02_zbuffer", "03_perspective_z", "04_scanline_inverse_z"};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) {
        expect_run_refused(all[i], args, 1, "cannot write /dev/full: No space left on device",
                           out.path);
        char *now = read_text(old.path);
        assert_string_equal(now, OLD_BYTES);
        free(now);
        assert_int_equal(entries(dir), 1); /* old.png: no temporary file, no new/ */
    }
    /* An unwritable output is found before drawing: nothing is made at all. */
    const char *trailing[] = {"--out", in_dir(dir, "a/b/c/").path, NULL};
    char want[TEXT_MAX];
    snprintf(want, sizeof want, "cannot write %s/a/b/c/: no file name (it ends in '/')", dir);
    expect_run_refused("02_zbuffer", trailing, 1, want, NULL);
    expect_run_refused("01_ybuffer", trailing, 1, want, NULL);
    assert_int_equal(entries(dir), 1);
}

/* ---- 3. signals ---- */

/* Runs program with stdout on stdout_fd and stderr on stderr_fd (-1: /dev/null). */
static pid_t start_to(const char *program, const char *const *args, int stdout_fd,
                      int stderr_fd)
{
    const char *bin = getenv("BIN_DIR") ? getenv("BIN_DIR") : "build/bin";
    char path[TEXT_MAX];
    snprintf(path, sizeof path, "%s/%s", bin, program);
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        /* As from a terminal: a background job's shell ignores SIGINT, and
         * the lesson leaves an ignored signal ignored. */
        const int all[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGUSR1, SIGABRT, SIGPIPE};
        for (size_t k = 0; k < sizeof all / sizeof all[0]; k++)
            signal(all[k], SIG_DFL);
        int null = open("/dev/null", O_WRONLY);
        dup2(stdout_fd >= 0 ? stdout_fd : null, STDOUT_FILENO);
        dup2(stderr_fd >= 0 ? stderr_fd : null, STDERR_FILENO);
        char *argv[32] = {path};
        for (int i = 0; args[i] && i < 30; i++)
            argv[i + 1] = (char *)args[i];
        execv(path, argv);
        _exit(127);
    }
    return pid;
}

static pid_t start(const char *program, const char *const *args, int stdout_fd)
{
    return start_to(program, args, stdout_fd, -1);
}

static int wait_status(pid_t pid)
{
    int status;
    assert_int_equal(waitpid(pid, &status, 0), pid);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

#define POLL_NS 2000000L /* 2 ms */
#define POLL_LIMIT 15000 /* 30 s */

static void signal_during_a_large_write_removes_the_temporary_files(void **state)
{
    (void)state;
    const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGUSR1, SIGABRT};
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
        const char *dir = test_dir("outputs_signal");
        Path out = in_dir(dir, "out.png"), ids = in_dir(dir, "ids.png"),
             overdraw = in_dir(dir, "o.pgm");
        /* Encoding a 2048 x 2048 PNG takes a while; the temporary files of
         * the outputs written first wait for the last one. */
        const char *args[] = {"--width", "2048", "--height", "2048", "--out", out.path,
                              "--overdraw-out", overdraw.path, "--id-out", ids.path, NULL};
        pid_t pid = start("02_zbuffer", args, -1);
        int polls = 0;
        while (!has_temporary(dir) && polls++ < POLL_LIMIT) {
            struct timespec t = {0, POLL_NS};
            nanosleep(&t, NULL);
        }
        assert_true(polls < POLL_LIMIT);
        kill(pid, sigs[i]);
        int status = wait_status(pid);
        if (status == 0)
            fail_msg("the run ended before signal %d arrived", sigs[i]);
        assert_int_equal(status, 128 + sigs[i]);
        if (entries(dir) != 0)
            fail_msg("signal %d left %d files in %s", sigs[i], entries(dir), dir);
    }
}

/* Whether process pid has a handler of its own for sig (SigCgt, Linux). */
static bool catches(pid_t pid, int sig)
{
    char path[64], line[256];
    snprintf(path, sizeof path, "/proc/%d/status", (int)pid);
    FILE *fp = fopen(path, "r");
    bool caught = false;
    while (fp && fgets(line, sizeof line, fp))
        if (strncmp(line, "SigCgt:", 7) == 0)
            caught = (strtoull(line + 7, NULL, 16) >> (sig - 1) & 1) != 0;
    if (fp)
        fclose(fp);
    return caught;
}

/* Starts program with its stderr in err_path, and sends it sig once it is
 * ready for it (before_output) or once its first temporary file exists in
 * dir: its status. */
static int stop_with(const char *program, const char *const *args, int sig, bool before_output,
                     const char *dir, const char *err_path)
{
    int err_fd = open(err_path, O_WRONLY | O_CREAT | O_TRUNC, 0666);
    assert_true(err_fd >= 0);
    pid_t pid = start_to(program, args, -1, err_fd);
    close(err_fd);
    int polls = 0;
    while (!(before_output ? catches(pid, sig) : has_temporary(dir)) && polls++ < POLL_LIMIT) {
        struct timespec t = {0, POLL_NS};
        nanosleep(&t, NULL);
    }
    assert_true(polls < POLL_LIMIT);
    kill(pid, sig);
    return wait_status(pid);
}

/* A signal ends a run with one line that names it, status 128 + the signal,
 * whether it comes while the run loads and draws or while it writes. */
static void a_signal_stops_a_run_with_one_line(void **state)
{
    (void)state;
    Path err = in_dir(test_dir("outputs_signal_line_err"), "stderr.txt");
    struct {
        const char *program;
        int sig;
        bool before_output;
        const char *line;
    } runs[] = {
        {"10_fast_raster", SIGTERM, true, "10_fast_raster: error: stopped by SIGTERM\n"},
        {"10_fast_raster", SIGINT, true, "10_fast_raster: error: stopped by SIGINT\n"},
        {"02_zbuffer", SIGTERM, false, "02_zbuffer: error: stopped by SIGTERM\n"},
        {"01_ybuffer", SIGTERM, true, "01_ybuffer: error: stopped by SIGTERM\n"},
    };
    for (size_t i = 0; i < sizeof runs / sizeof runs[0]; i++) {
        const char *dir = test_dir("outputs_signal_line");
        Path out = in_dir(dir, "out.png"), ids = in_dir(dir, "ids.png");
        const char *args[] = {"--width", "2048", "--height", "2048", "--out", out.path,
                              "--id-out", ids.path, NULL};
        const char *row[] = {"--width", "2048", "--height", "2048", "--out", out.path, NULL};
        const char *const *a = strcmp(runs[i].program, "01_ybuffer") == 0 ? row : args;
        int status = stop_with(runs[i].program, a, runs[i].sig, runs[i].before_output, dir,
                               err.path);
        if (status == 0)
            fail_msg("%s ended before signal %d arrived", runs[i].program, runs[i].sig);
        expect_count(128 + runs[i].sig, status, "exit status");
        char *text = read_text(err.path);
        assert_string_equal(text, runs[i].line);
        free(text);
        if (entries(dir) != 0)
            fail_msg("signal %d left %d files in %s", runs[i].sig, entries(dir), dir);
    }
}

/* A file size limit: the write fails (SIGXFSZ is ignored), one line says
 * so, status 1, and no file of the run is left. */
static void a_file_size_limit_is_a_failure_with_one_line(void **state)
{
    (void)state;
    const char *dir = test_dir("outputs_fsize");
    ShellResult r = run_shell(dir, 60, "ulimit -f 8 && exec %s/02_zbuffer --width 512 "
                              "--height 512 --out out.png --id-out id.png >/dev/null",
                              abs_bin_dir());
    const char *want = "02_zbuffer: error: cannot write ";
    size_t lines = 0;
    for (const char *c = r.output; *c; c++)
        lines += *c == '\n';
    if (r.status != 1 || lines != 1 || strncmp(r.output, want, strlen(want)) != 0 ||
        !strstr(r.output, "File too large"))
        fail_msg("under ulimit -f 8: status %d, wanted 1 and one line \"%s...: File too "
                 "large\":\n%s", r.status, want, r.output);
    if (entries(dir) != 0)
        fail_msg("the failed run left %d files in %s", entries(dir), dir);
    shell_result_free(&r);
}

/* ---- 4. pipes, standard output ---- */

/* A pipe whose reader is there before the run gets the whole picture: the
 * check before drawing leaves it open (closed, the reader saw its end and
 * went, and the run then found nobody reading). */
static void a_pipe_with_a_reader_gets_the_picture(void **state)
{
    (void)state;
    const char *dir = test_dir("outputs_fifo_reader");
    ShellResult r = run_shell(dir, 60, "mkfifo p && { cat p >got & reader=$!; }; sleep 0.3; "
                              "%s/05_clipping --out p >/dev/null; s=$?; wait $reader; "
                              "echo \"status $s\"; od -An -c -N4 got", abs_bin_dir());
    if (r.status != 0 || !strstr(r.output, "status 0") || !strstr(r.output, "P   N   G"))
        fail_msg("--out p, a pipe with a reader: wanted status 0 and a PNG read:\n%s", r.output);
    shell_result_free(&r);
}

static void pipes_are_refused_without_waiting(void **state)
{
    (void)state;
    const char *dir = test_dir("outputs_fifo");
    Path fifo = in_dir(dir, "p"), out = in_dir(dir, "out.png");
    assert_int_equal(mkfifo(fifo.path, 0666), 0);
    char want[TEXT_MAX];
    const char *obj[] = {"--obj", fifo.path, "--out", out.path, NULL};
    snprintf(want, sizeof want, "cannot read %s: not a regular file (a pipe)", fifo.path);
    expect_run_refused("02_zbuffer", obj, 1, want, out.path);
    const char *segments[] = {"--segments", fifo.path, "--out", out.path, NULL};
    expect_run_refused("01_ybuffer", segments, 1, want, out.path);
    const char *compare[] = {"--compare", fifo.path, "--out", out.path, NULL};
    snprintf(want, sizeof want, "--compare: cannot read %s: not a regular file (a pipe)",
             fifo.path);
    expect_failure("03_perspective_z", compare, 1, want);
    snprintf(want, sizeof want, "cannot write %s: a pipe that nobody reads", fifo.path);
    const char *as_out[] = {"--out", fifo.path, NULL};
    expect_run_refused("04_scanline_inverse_z", as_out, 1, want, NULL);
    expect_run_refused("01_ybuffer", as_out, 1, want, NULL);
    const char *as_depth[] = {"--out", out.path, "--depth-out", fifo.path, NULL};
    expect_run_refused("02_zbuffer", as_depth, 1, want, out.path);
}

static void out_dash_writes_the_png_to_standard_output(void **state)
{
    (void)state;
    const char *all[] = {"01_ybuffer", "02_zbuffer"};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) {
        const char *args[] = {"--width", "8", "--height", "8", "--out", "-", NULL};
        RunResult r = run_program(all[i], args);
        assert_int_equal(r.status, 0);
        assert_memory_equal(r.out, "\x89PNG\r\n\x1a\n", 8);
        assert_non_null(strstr(r.err, "drawn") ? r.err : strstr(r.err, "wrote"));
        run_result_free(&r);
    }
    const char *depth[] = {"--out", "out.png", "--depth-out", "-", NULL};
    expect_run_refused("02_zbuffer", depth, 2,
                       "--depth-out: '-' (standard output) is for --out only; name a file", NULL);
}

static void lost_standard_output_is_a_failure(void **state)
{
    (void)state;
    const char *dir = test_dir("outputs_dev_full");
    Path out = in_dir(dir, "out.png");
    int full = open("/dev/full", O_WRONLY);
    assert_true(full >= 0);
    const char *all[] = {"01_ybuffer", "02_zbuffer", "04_scanline_inverse_z"};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) {
        const char *args[] = {"--out", out.path, NULL};
        assert_int_equal(wait_status(start(all[i], args, full)), 1);
        assert_false(file_exists(out.path)); /* all or nothing */
        const char *ascii[] = {"--out", "-", "--width", "8", "--height", "8", NULL};
        assert_int_equal(wait_status(start(all[i], ascii, full)), 1);
    }
    close(full);
    assert_int_equal(entries(dir), 0);
}

/* A reader that has gone (a pipe closed at its end, as `| head -c 10` leaves
 * it): the write fails, one line says so, status 1, and no file of the run
 * is published. It used to end the run silently, killed by SIGPIPE. */
static void a_closed_pipe_is_a_failure_with_one_line(void **state)
{
    (void)state;
    const char *dir = test_dir("outputs_broken_pipe");
    Path out = in_dir(dir, "out.png");
    Path err = in_dir(test_dir("outputs_broken_pipe_err"), "stderr.txt");
    int fds[2];
    assert_int_equal(pipe(fds), 0);
    close(fds[0]); /* nobody reads */
    const char *to_stdout[] = {"--out", "-", "--width", "64", "--height", "48", NULL};
    const char *summary[] = {"--out", out.path, "--width", "64", "--height", "48", NULL};
    const char *const *args[] = {to_stdout, summary};
    const char *programs[] = {"10_fast_raster", "02_zbuffer"};
    for (int i = 0; i < 2; i++) {
        int err_fd = open(err.path, O_WRONLY | O_CREAT | O_TRUNC, 0666);
        assert_true(err_fd >= 0);
        int status = wait_status(start_to(programs[i], args[i], fds[1], err_fd));
        close(err_fd);
        expect_count(1, status, "exit status");
        char *text = read_text(err.path);
        char want[TEXT_MAX];
        snprintf(want, sizeof want, "%s: error: cannot write standard output: Broken pipe\n",
                 programs[i]);
        assert_string_equal(text, want);
        free(text);
    }
    /* A tool as well (build/tools/, beside build/bin/): make_obj's model into the pipe. */
    const char *model[] = {"knot", "/dev/stdout", NULL};
    int err_fd = open(err.path, O_WRONLY | O_CREAT | O_TRUNC, 0666);
    assert_true(err_fd >= 0);
    int status = wait_status(start_to("../tools/make_obj", model, fds[1], err_fd));
    close(err_fd);
    expect_count(1, status, "make_obj's exit status");
    char *text = read_text(err.path);
    assert_string_equal(text, "make_obj: error: cannot write /dev/stdout: Broken pipe\n");
    free(text);
    close(fds[1]);
    assert_int_equal(entries(dir), 0);
}

/* ---- 5. the --compare reader ---- */

static void write_bytes(const char *path, const void *bytes, size_t n)
{
    FILE *fp = fopen(path, "wb");
    assert_non_null(fp);
    assert_int_equal(fwrite(bytes, 1, n, fp), n);
    assert_int_equal(fclose(fp), 0);
}

static void compare_reader_refuses_bad_references(void **state)
{
    (void)state;
    const char *dir = test_dir("outputs_compare_reader");
    Path out = in_dir(dir, "out.png"), pnm = in_dir(dir, "short.pnm"),
         big = in_dir(dir, "bomb.png"), cut = in_dir(dir, "cut.png");
    write_bytes(pnm.path, "P6\n64 48\n255\n", 13); /* a header, no pixels */
    /* A PNG header that claims 16384 x 16384 pixels: refused before decoding. */
    static const unsigned char header[] = {
        0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
        0, 0, 0x40, 0, 0, 0, 0x40, 0, 8, 2, 0, 0, 0, 0, 0, 0, 0};
    write_bytes(big.path, header, sizeof header);
    const char *make[] = {"--width", "40", "--height", "30", "--out", out.path, NULL};
    free(run_ok("02_zbuffer", make));
    char *png = read_text(out.path);
    struct stat st;
    assert_int_equal(stat(out.path, &st), 0);
    write_bytes(cut.path, png, (size_t)st.st_size / 2);
    free(png);

    char want[TEXT_MAX];
    const char *a1[] = {"--width", "64", "--height", "48", "--compare", pnm.path, "--out",
                        out.path, NULL};
    snprintf(want, sizeof want, "--compare: cannot read %s: not a readable PNG (no PNG "
             "signature: not a PNG file)", pnm.path);
    expect_failure("02_zbuffer", a1, 1, want);
    const char *a2[] = {"--compare", big.path, "--out", out.path, NULL};
    snprintf(want, sizeof want, "--compare: %s is 16384x16384 but the picture is 800x600",
             big.path);
    expect_failure("02_zbuffer", a2, 1, want);
    const char *a3[] = {"--width", "40", "--height", "30", "--compare", cut.path, "--out",
                        out.path, NULL};
    RunResult r = run_program("02_zbuffer", a3);
    assert_int_equal(r.status, 1);
    snprintf(want, sizeof want, "02_zbuffer: error: --compare: cannot read %s: not a readable "
             "PNG (", cut.path);
    assert_memory_equal(r.err, want, strlen(want));
    assert_null(strstr(r.err, "(null)"));
    run_result_free(&r);
}

/* ---- 6. the smaller cases ---- */

static void long_names_read_only_files_and_links(void **state)
{
    (void)state;
    const char *dir = test_dir("outputs_small_cases");
    char name[251];
    memset(name, 'n', 246);
    strcpy(name + 246, ".png"); /* 250 characters: legal, though ".NAME.XXXXXX" is not */
    Path longname = in_dir(dir, name);
    const char *a1[] = {"--width", "8", "--height", "8", "--out", longname.path, NULL};
    free(run_ok("02_zbuffer", a1));
    assert_true(file_exists(longname.path));

    Path ro = in_dir(dir, "ro.png");
    write_text(ro.path, OLD_BYTES);
    assert_int_equal(chmod(ro.path, 0444), 0);
    const char *a2[] = {"--width", "8", "--height", "8", "--out", ro.path, NULL};
    char want[TEXT_MAX];
    snprintf(want, sizeof want, "cannot write %s: Permission denied", ro.path);
    expect_run_refused("02_zbuffer", a2, 1, want, NULL);
    char *now = read_text(ro.path);
    assert_string_equal(now, OLD_BYTES);
    free(now);

    Path target = in_dir(dir, "target.png"), sym = in_dir(dir, "link.png");
    write_text(target.path, OLD_BYTES);
    assert_int_equal(symlink("target.png", sym.path), 0);
    const char *a3[] = {"--width", "8", "--height", "8", "--out", sym.path, NULL};
    free(run_ok("01_ybuffer", a3));
    struct stat st;
    assert_int_equal(lstat(sym.path, &st), 0);
    assert_true(S_ISLNK(st.st_mode)); /* still a link, */
    Image im = read_png(target.path); /* and its target holds the picture */
    image_free(&im);
}

static void byte_order_marks_far_models_and_warnings(void **state)
{
    (void)state;
    const char *dir = test_dir("outputs_text_cases");
    Path out = in_dir(dir, "out.png");
    const char *bom = write_text_in(dir, "bom.obj", "\xef\xbb\xbf" TRIANGLE_OBJ);
    const char *a1[] = {"--obj", bom, "--out", out.path, NULL};
    char *o = run_ok("02_zbuffer", a1);
    expect_line(o, "(1 face): 1 triangle drawn");
    free(o);
    const char *seg = write_text_in(dir, "bom.txt", "\xef\xbb\xbf" "0 5 20 5 0 255 0\n");
    const char *a2[] = {"--segments", seg, "--out", out.path, NULL};
    free(run_ok("01_ybuffer", a2));

    const char *far = write_text_in(dir, "far.obj", "v 1e17 0 0\nv 1.0000000000000001e17 0 0\n"
                                                    "v 1e17 1 0\nf 1 2 3\n");
    const char *a3[] = {"--obj", far, "--out", out.path, NULL};
    free(run_ok("03_perspective_z", a3));

    const char *warn = write_text_in(dir, "warn.obj", "frob\x1b[31m x\n" TRIANGLE_OBJ);
    const char *a4[] = {"--obj", warn, "--out", out.path, NULL};
    RunResult r = run_program("04_scanline_inverse_z", a4);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.err, "warning"));
    for (const char *c = r.err; *c; c++)
        assert_true(*c == '\n' || (unsigned char)*c >= 0x20);
    run_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(outputs_and_inputs_are_compared_by_identity),
        cmocka_unit_test(a_default_output_is_checked_as_a_given_one),
        cmocka_unit_test(every_output_is_listed_in_the_summary),
        cmocka_unit_test(failed_output_leaves_no_output_of_the_run),
        cmocka_unit_test(signal_during_a_large_write_removes_the_temporary_files),
        cmocka_unit_test(a_signal_stops_a_run_with_one_line),
        cmocka_unit_test(a_file_size_limit_is_a_failure_with_one_line),
        cmocka_unit_test(a_pipe_with_a_reader_gets_the_picture),
        cmocka_unit_test(pipes_are_refused_without_waiting),
        cmocka_unit_test(out_dash_writes_the_png_to_standard_output),
        cmocka_unit_test(lost_standard_output_is_a_failure),
        cmocka_unit_test(a_closed_pipe_is_a_failure_with_one_line),
        cmocka_unit_test(compare_reader_refuses_bad_references),
        cmocka_unit_test(long_names_read_only_files_and_links),
        cmocka_unit_test(byte_order_marks_far_models_and_warnings),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
