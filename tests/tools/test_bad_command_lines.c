/* test_bad_command_lines.c: every lesson, run as a student would run it, with
 * command lines that are wrong. Each must be refused with exactly one line on
 * stderr, "<program>: error: <what and where>", nothing on stdout, exit status
 * 2 for a usage error and 1 for a failure while running, and no file written:
 * no --out picture, no temporary file left behind, every existing file keeping
 * its bytes (even one named as the output).
 *
 * A row for ALL_3D runs against each 3-D lesson (02, 03, 04). In arguments and
 * messages "{D}" stands for this test's directory, which holds the input files
 * set up below, and "{SCENES}" for the list of built-in scenes. Unless a row
 * names its own --out, "--out {D}/out.png" is added at the end, so that the
 * check "{D}/out.png does not exist" means "nothing was written". */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include "harness/scene.h"
#include "test_support.h"

#define ALL_3D "3-D"
#define MAX_ARGS 10
#define TEXT_MAX 1024

static const char *const LESSONS_3D[] = {"02_zbuffer", "03_perspective_z",
                                         "04_scanline_inverse_z"};
#define LESSON_3D_COUNT ((int)(sizeof LESSONS_3D / sizeof LESSONS_3D[0]))

/* The files every run sees in {D}: none may change or disappear, nothing may
 * be added. */
typedef struct {
    const char *name;
    const char *bytes;
} Fixture;

static const Fixture FIXTURES[] = {
    {"m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
    {"bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"},
    {"index_zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 0 1 2\n"},
    {"no_faces.obj", "# only vertices\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"},
    {"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"},
    {"two_corners.obj", "v 0 0 0\r\nv 1 0 0\r\nf 1 2\r\n"},
    {"segments.txt", "0 0 10 10 255 0 0\n0 5 20 5 0 255 0\n"},
    {"bad_segments.txt", "0 0 10 10 255 0 0\n5 5 oops\n"},
    {"file.txt", "a file, not a directory\n"},
};
#define FIXTURE_COUNT ((int)(sizeof FIXTURES / sizeof FIXTURES[0]))
#define SUBDIR "sub" /* an empty directory, also in {D} */

typedef struct {
    const char *lesson; /* a lesson directory, or ALL_3D */
    const char *args[MAX_ARGS];
    int status;
    const char *message; /* what follows "<program>: error: " */
} BadLine;

static const BadLine BAD_LINES[] = {
    /* sizes: 1 to 16384 */
    {ALL_3D, {"--width", "0"}, 2, "--width: 0 is out of range (1 to 16384)"},
    {ALL_3D, {"--height", "16385"}, 2, "--height: 16385 is out of range (1 to 16384)"},
    {ALL_3D, {"--width", "12.5"}, 2, "--width: '12.5' is not a whole number"},
    {ALL_3D, {"--width", "99999999999999999999"}, 2,
     "--width: 99999999999999999999 is out of range (1 to 16384)"},
    {ALL_3D, {"--height", "-600"}, 2, "--height: -600 is out of range (1 to 16384)"},
    /* flags: unknown, missing values, repeated, stray arguments */
    {ALL_3D, {"--frobnicate"}, 2, "unknown flag '--frobnicate' (try --help)"},
    {ALL_3D, {"-w", "5"}, 2, "unknown flag '-w' (try --help)"},
    {ALL_3D, {"--width"}, 2, "--width needs a value"}, /* the --out added next is no value */
    {ALL_3D, {"--width", "5", "--width", "6"}, 2, "--width given twice"},
    {ALL_3D, {"extra"}, 2, "unexpected argument 'extra'"},
    {ALL_3D, {"-"}, 2, "unexpected argument '-'"},
    {ALL_3D, {"--width", "5\n6"}, 2, "--width: '5?6' is not a whole number"},
    /* finite numbers only */
    {ALL_3D, {"--eye", "nan,0,0"}, 2, "--eye: 'nan,0,0' is not three finite numbers X,Y,Z"},
    {ALL_3D, {"--eye", "1,2"}, 2, "--eye: '1,2' is not three finite numbers X,Y,Z"},
    {ALL_3D, {"--fovy", "inf"}, 2, "--fovy: 'inf' is not a finite number"},
    {ALL_3D, {"--far", "1e400"}, 2, "--far: '1e400' is not a finite number"},
    /* the camera: a lens that exists, a view direction, an up that is not along it */
    {ALL_3D, {"--fovy", "180"}, 2, "--fovy: 180 is out of range (0 < fovy < 180 degrees)"},
    {ALL_3D, {"--near", "0"}, 2, "--near: 0 is out of range (near must be greater than 0)"},
    {ALL_3D, {"--near", "-0.5"}, 2,
     "--near: -0.5 is out of range (near must be greater than 0)"},
    {ALL_3D, {"--near", "2", "--far", "1"}, 2,
     "--far: 1 is out of range (far must be greater than near, 2)"},
    {ALL_3D, {"--eye", "1,2,3", "--target", "1,2,3"}, 2, "--eye and --target are the same point"},
    {ALL_3D, {"--eye", "0,0,5", "--target", "0,0,0", "--up", "0,0,1"}, 2,
     "--up is parallel to the view direction from --eye to --target"},
    {ALL_3D, {"--up", "0,0,0"}, 2, "--up is the zero vector"},
    /* a length that underflows is not a zero vector */
    {ALL_3D, {"--eye", "1e-300,0,0", "--target", "0,0,0"}, 2,
     "--eye and --target are too close together to give a direction"},
    {ALL_3D, {"--up", "0,1e-300,0"}, 2, "--up is too short to give a direction"},
    {ALL_3D, {"--eye", "1e300,0,0", "--target", "0,0,0"}, 2,
     "--eye and --target are too far apart"},
    /* scenes and shading */
    {ALL_3D, {"--shade", "x"}, 2, "--shade: 'x' is not one of flat, id, depth"},
    {ALL_3D, {"--scene", "nosuch"}, 2, "--scene: no scene named 'nosuch' (known: {SCENES})"},
    {ALL_3D, {"--scene", "walls", "--obj", "{D}/m.obj"}, 2,
     "--scene and --obj cannot be used together"},
    /* OBJ files: missing or malformed, named with file:line */
    {ALL_3D, {"--obj", "{D}/missing.obj"}, 1,
     "cannot read {D}/missing.obj: No such file or directory"},
    {ALL_3D, {"--obj", "{D}/bad_index.obj"}, 1,
     "{D}/bad_index.obj:4: vertex index 9 is out of range (1 to 3, or -1 to -3)"},
    {ALL_3D, {"--obj", "{D}/index_zero.obj"}, 1,
     "{D}/index_zero.obj:5: vertex index 0 is invalid (the first is 1, the last is -1)"},
    {ALL_3D, {"--obj", "{D}/no_faces.obj"}, 1, "{D}/no_faces.obj: no faces"},
    {ALL_3D, {"--obj", "{D}/nan.obj"}, 1,
     "{D}/nan.obj:2: vertex coordinate 'nan' is not a finite number"},
    {ALL_3D, {"--obj", "{D}/two_corners.obj"}, 1,
     "{D}/two_corners.obj:3: face has 2 corners (at least 3 needed)"},
    {ALL_3D, {"--obj", "{D}/sub"}, 1, "cannot read {D}/sub: Is a directory"},
    /* outputs: never over an input, never two in one file, only where writable */
    {ALL_3D, {"--obj", "{D}/m.obj", "--out", "{D}/m.obj"}, 2, "--obj and --out both name {D}/m.obj"},
    {ALL_3D, {"--depth-out", "{D}/d.pfm", "--overdraw-out", "{D}/d.pfm"}, 2,
     "--depth-out and --overdraw-out both name {D}/d.pfm"},
    {ALL_3D, {"--id-out", "{D}/out.png"}, 2, "--out and --id-out both name {D}/out.png"},
    {ALL_3D, {"--depth-out", "{D}/i.png", "--id-out", "{D}/i.png"}, 2,
     "--depth-out and --id-out both name {D}/i.png"},
    {ALL_3D, {"--obj", "{D}/m.obj", "--id-out", "{D}/m.obj"}, 2,
     "--obj and --id-out both name {D}/m.obj"},
    {ALL_3D, {"--id-out", ""}, 2, "--id-out: the file name is empty"},
    {ALL_3D, {"--out", ""}, 2, "--out: the file name is empty"},
    {ALL_3D, {"--out", "{D}/file.txt/out.png"}, 1,
     "cannot create directory {D}/file.txt: a file of that name exists"},
    {ALL_3D, {"--out", "{D}/sub"}, 1, "cannot write {D}/sub: Is a directory"},
    {ALL_3D, {"--out", "/dev/full"}, 1, "cannot write /dev/full: No space left on device"},
    {ALL_3D, {"--steps", "{D}/file.txt"}, 1,
     "cannot create directory {D}/file.txt: a file of that name exists"},
    {ALL_3D, {"--compare", "{D}/out.png"}, 2, "--compare and --out both name {D}/out.png"},
    {ALL_3D, {"--world-out", "{D}/out.png"}, 2, "--out and --world-out both name {D}/out.png"},
    {ALL_3D, {"--obj", "{D}/m.obj", "--world-out", "{D}/m.obj"}, 2,
     "--obj and --world-out both name {D}/m.obj"},
    {ALL_3D, {"--depth-out", "{D}/w.png", "--world-out", "{D}/w.png"}, 2,
     "--depth-out and --world-out both name {D}/w.png"},
    {ALL_3D, {"--compare", "{D}/m.obj", "--depth-out", "{D}/out.diff.png"}, 2,
     "--depth-out names {D}/out.diff.png, where the diff picture of --out goes"},

    /* the tools that watch the depth test: --trace inside the image, --ascii small */
    {ALL_3D, {"--trace", "800,0"}, 2, "--trace: pixel (800,0) is outside the 800x600 image"},
    {ALL_3D, {"--trace", "1,600"}, 2, "--trace: pixel (1,600) is outside the 800x600 image"},
    {ALL_3D, {"--width", "10", "--trace", "3,-1"}, 2,
     "--trace: pixel (3,-1) is outside the 10x600 image"},
    {ALL_3D, {"--trace", "1,2,3"}, 2, "--trace: '1,2,3' is not a pixel X,Y (two whole numbers)"},
    {ALL_3D, {"--ascii"}, 2,
     "--ascii: the image is 800x600; --ascii prints at most 120x60 (use --width and --height)"},
    /* lesson 02's own flags */
    {"02_zbuffer", {"--bug", "nosuch"}, 2,
     "--bug: 'nosuch' is not one of separate-buffers, clear-zero"},
    {"02_zbuffer", {"--painter", "--bug", "clear-zero"}, 2,
     "--painter and --bug cannot be used together"},
    {"02_zbuffer", {"--painter", "--painter"}, 2, "--painter given twice"},
    {"02_zbuffer", {"--depth-interp", "naive"}, 2, "unknown flag '--depth-interp' (try --help)"},
    /* lesson 03: the naive rule, and the picture that compares it */
    {"03_perspective_z", {"--depth-interp", "x"}, 2,
     "--depth-interp: 'x' is not one of perspective, naive"},
    {"03_perspective_z", {"--bug", "x"}, 2, "--bug: 'x' is not one of negated-w"},
    {"03_perspective_z", {"--bug", "negated-w", "--depth-interp", "naive"}, 2,
     "--bug and --depth-interp naive cannot be used together"},
    {"03_perspective_z", {"--compare-naive", "{D}/out.png"}, 2,
     "--out and --compare-naive both name {D}/out.png"},
    {"03_perspective_z", {"--id-out", "{D}/n.png", "--compare-naive", "{D}/n.png"}, 2,
     "--id-out and --compare-naive both name {D}/n.png"},
    {"03_perspective_z", {"--obj", "{D}/m.obj", "--compare-naive", "{D}/m.obj"}, 2,
     "--obj and --compare-naive both name {D}/m.obj"},
    {"03_perspective_z", {"--world-out", "{D}/w.png", "--compare-naive", "{D}/w.png"}, 2,
     "--world-out and --compare-naive both name {D}/w.png"},
    /* the naive comparison is lesson 03's extra: lesson 04 does not carry it */
    {"04_scanline_inverse_z", {"--depth-interp", "x"}, 2,
     "unknown flag '--depth-interp' (try --help)"},
    {"04_scanline_inverse_z", {"--compare-naive", "{D}/out.png"}, 2,
     "unknown flag '--compare-naive' (try --help)"},
    {"04_scanline_inverse_z", {"--bug", "x"}, 2, "unknown flag '--bug' (try --help)"},

    /* lesson 01: one row, no camera, segments from a file */
    {"01_ybuffer", {"--width", "0"}, 2, "--width: 0 is out of range (1 to 16384)"},
    {"01_ybuffer", {"--height", "16385"}, 2, "--height: 16385 is out of range (1 to 16384)"},
    {"01_ybuffer", {"--eye", "0,0,1"}, 2, "--eye does not apply to 01_ybuffer (it has no camera)"},
    {"01_ybuffer", {"--obj", "{D}/m.obj"}, 2,
     "--obj does not apply to 01_ybuffer (it draws its own scene only)"},
    {"01_ybuffer", {"--depth-out", "{D}/d.pfm"}, 2,
     "--depth-out does not apply to 01_ybuffer (it writes no depth buffer)"},
    {"01_ybuffer", {"--world-out", "{D}/w.png"}, 2,
     "--world-out does not apply to 01_ybuffer (it draws no 3-D world)"},
    {"01_ybuffer", {"--id-out", "{D}/i.png"}, 2,
     "--id-out does not apply to 01_ybuffer (it has no faces)"},
    {"01_ybuffer", {"--trace", "800"}, 2, "--trace: column 800 is outside the 800-pixel-wide image"},
    {"01_ybuffer", {"--order", "12"}, 2,
     "--order '12': expected each of 1..3 exactly once, as digits (e.g. 312) or separated by "
     "commas"},
    {"01_ybuffer", {"--order", "112"}, 2,
     "--order '112': expected each of 1..3 exactly once, as digits (e.g. 312) or separated by "
     "commas"},
    {"01_ybuffer", {"--order", "21", "--order", "12"}, 2, "--order given twice"},
    {"01_ybuffer", {"--order"}, 2, "--order needs a value"},
    /* a value quoted as given: error_report prints its newline as '?' */
    {"01_ybuffer", {"--order", "1\n2"}, 2,
     "--order '1?2': expected each of 1..3 exactly once, as digits (e.g. 312) or separated by "
     "commas"},
    {"01_ybuffer", {"--ascii", "--width", "200"}, 2,
     "--ascii: the row is 200 pixels wide; --ascii prints at most 120 (use --width)"},
    {"01_ybuffer", {"--scene-out", "{D}/segments.txt", "--compare", "{D}/segments.txt"}, 2,
     "--scene-out and --compare both name {D}/segments.txt"},
    {"01_ybuffer", {"--compare", "{D}/file.txt", "--ybuffer-out", "{D}/out.diff.png"}, 2,
     "--ybuffer-out and the diff picture of --out both name {D}/out.diff.png"},
    {"01_ybuffer", {"--segments", "{D}/missing.txt"}, 1,
     "cannot read {D}/missing.txt: No such file or directory"},
    {"01_ybuffer", {"--segments", "{D}/bad_segments.txt"}, 1,
     "{D}/bad_segments.txt:2: expected 7 numbers 'x0 y0 x1 y1 r g b', got 3"},
    {"01_ybuffer", {"--segments", "{D}/segments.txt", "--out", "{D}/segments.txt"}, 2,
     "--out and --segments both name {D}/segments.txt"},
    {"01_ybuffer", {"--scene-out", "{D}/out.png"}, 2, "--out and --scene-out both name {D}/out.png"},
    {"01_ybuffer", {"--steps", ""}, 2, "--steps: the directory name is empty"},
    {"01_ybuffer", {"--steps", "{D}/file.txt"}, 1,
     "cannot create directory {D}/file.txt: a file of that name exists"},
    {"01_ybuffer", {"--out", "/dev/full"}, 1, "cannot write /dev/full: No space left on device"},
    {"01_ybuffer", {"--out", "{D}/sub"}, 1, "cannot write {D}/sub: Is a directory"},
};
#define BAD_LINE_COUNT ((int)(sizeof BAD_LINES / sizeof BAD_LINES[0]))

/* ---- Text with {D} and {SCENES} ------------------------------------------- */

static void scene_list(char *out, size_t size)
{
    out[0] = '\0';
    for (int i = 0; i < scene_count(); i++) {
        size_t used = strlen(out);
        snprintf(out + used, size - used, "%s%s", i ? ", " : "", scene_at(i)->name);
    }
}

static void expand(const char *text, const char *dir, char out[TEXT_MAX])
{
    char scenes[TEXT_MAX];
    scene_list(scenes, sizeof scenes);
    size_t n = 0;
    out[0] = '\0';
    while (*text && n < TEXT_MAX - 1) {
        const char *with = NULL;
        if (strncmp(text, "{D}", 3) == 0) {
            with = dir;
            text += 3;
        } else if (strncmp(text, "{SCENES}", 8) == 0) {
            with = scenes;
            text += 8;
        }
        if (with) {
            n += (size_t)snprintf(out + n, TEXT_MAX - n, "%s", with);
            if (n >= TEXT_MAX)
                fail_msg("expanded text too long: %s", text);
        } else {
            out[n++] = *text++;
            out[n] = '\0';
        }
    }
}

/* ---- The directory of inputs ---------------------------------------------- */

static void write_bytes(const char *path, const char *bytes)
{
    FILE *fp = fopen(path, "wb");
    assert_non_null(fp);
    assert_int_equal(fwrite(bytes, 1, strlen(bytes), fp), strlen(bytes));
    assert_int_equal(fclose(fp), 0);
}

static char *read_bytes(const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    char *buf = calloc(TEXT_MAX, 1);
    assert_non_null(buf);
    size_t n = fread(buf, 1, TEXT_MAX - 1, fp);
    buf[n] = '\0';
    fclose(fp);
    return buf;
}

static const char *make_inputs(const char *name)
{
    const char *dir = test_dir(name);
    for (int i = 0; i < FIXTURE_COUNT; i++)
        write_bytes(path_join(dir, FIXTURES[i].name), FIXTURES[i].bytes);
    assert_int_equal(mkdir(path_join(dir, SUBDIR), 0777), 0);
    return dir;
}

static int count_entries(const char *dir)
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

/* Every input still holds its bytes, and nothing was added to {D} or {D}/sub.
 * Returns a description of the first difference, or NULL. */
static const char *inputs_changed(const char *dir, char why[TEXT_MAX])
{
    for (int i = 0; i < FIXTURE_COUNT; i++) {
        char *now = read_bytes(path_join(dir, FIXTURES[i].name));
        bool same = now && strcmp(now, FIXTURES[i].bytes) == 0;
        free(now);
        if (!same) {
            snprintf(why, TEXT_MAX, "%s no longer holds its bytes", FIXTURES[i].name);
            return why;
        }
    }
    int entries = count_entries(dir), sub_entries = count_entries(path_join(dir, SUBDIR));
    if (entries != FIXTURE_COUNT + 1 || sub_entries != 0) {
        snprintf(why, TEXT_MAX,
                 "a file was left behind: %d entries in %s (wanted %d), %d in %s/ (wanted 0)",
                 entries, dir, FIXTURE_COUNT + 1, sub_entries, SUBDIR);
        return why;
    }
    return NULL;
}

/* ---- Running one bad line --------------------------------------------------- */

typedef struct {
    char text[MAX_ARGS + 2][TEXT_MAX];
    const char *argv[MAX_ARGS + 3];
} Args;

static void build_args(const BadLine *b, const char *dir, Args *a)
{
    int n = 0;
    bool has_out = false;
    for (int i = 0; i < MAX_ARGS && b->args[i]; i++) {
        expand(b->args[i], dir, a->text[n]);
        has_out = has_out || strcmp(b->args[i], "--out") == 0;
        a->argv[n] = a->text[n];
        n++;
    }
    if (!has_out) {
        a->argv[n++] = "--out";
        expand("{D}/out.png", dir, a->text[n]);
        a->argv[n] = a->text[n];
        n++;
    }
    a->argv[n] = NULL;
}

static void print_command(const char *lesson, const Args *a)
{
    print_error("  %s", lesson);
    for (int i = 0; a->argv[i]; i++)
        print_error(" '%s'", a->argv[i]);
    print_error("\n");
}

/* True when the run went as the row says; otherwise prints what went wrong. */
static bool refused_as_expected(const char *lesson, const BadLine *b, const char *dir)
{
    Args a;
    build_args(b, dir, &a);
    char message[TEXT_MAX], want_err[TEXT_MAX + 64], why[TEXT_MAX];
    expand(b->message, dir, message);
    snprintf(want_err, sizeof want_err, "%s: error: %s\n", lesson, message);

    RunResult r = run_program(lesson, a.argv);
    const char *changed = inputs_changed(dir, why);
    bool out_written = file_exists(path_join(dir, "out.png"));
    bool ok = r.status == b->status && strcmp(r.err, want_err) == 0 && r.out[0] == '\0' &&
              !out_written && !changed;
    if (!ok) {
        print_command(lesson, &a);
        print_error("    status %d (wanted %d)\n    stderr \"%s\"\n    wanted \"%s\"\n",
                    r.status, b->status, r.err, want_err);
        if (r.out[0])
            print_error("    stdout was not empty: \"%s\"\n", r.out);
        if (out_written)
            print_error("    %s/out.png was written\n", dir);
        if (changed)
            print_error("    %s\n", changed);
    }
    run_result_free(&r);
    /* Put the directory back as it was, so that one failure does not cascade. */
    remove(path_join(dir, "out.png"));
    for (int i = 0; i < FIXTURE_COUNT; i++)
        write_bytes(path_join(dir, FIXTURES[i].name), FIXTURES[i].bytes);
    return ok;
}

static void every_bad_command_line_is_refused_with_one_line_and_no_file(void **state)
{
    (void)state;
    const char *dir = make_inputs("bad_command_lines");
    int runs = 0, failures = 0;
    for (int k = 0; k < BAD_LINE_COUNT; k++) {
        const BadLine *b = &BAD_LINES[k];
        bool all_3d = strcmp(b->lesson, ALL_3D) == 0;
        int n = all_3d ? LESSON_3D_COUNT : 1;
        for (int i = 0; i < n; i++) {
            const char *lesson = all_3d ? LESSONS_3D[i] : b->lesson;
            runs++;
            if (!refused_as_expected(lesson, b, dir)) {
                print_error("    (BAD_LINES[%d])\n", k);
                failures++;
            }
        }
    }
    if (failures)
        fail_msg("%d of %d bad command lines were not refused as expected (listed above)",
                 failures, runs);
    assert_true(runs >= 30);
}

/* ---- A disk that fills up while the picture is written ---------------------- */

/* Far smaller than any lesson's default picture (the smallest, lesson 01's
 * 800x16 strip, is about 200 bytes as PNG), but room enough for the one
 * line of error the lesson prints into its captured stderr. */
#define FILE_SIZE_LIMIT 128
#define OLD_BYTES "the bytes of an earlier picture\n"

static void full_disk_keeps_the_existing_picture(void **state)
{
    (void)state;
    /* A file size limit makes the kernel refuse writes past FILE_SIZE_LIMIT
     * bytes (EFBIG), in the lesson run here too (limits are inherited): the
     * closest thing to a full disk that needs no privileges. The lesson must
     * fail, say so, and leave the picture that was there before untouched. */
    const char *all[] = {"01_ybuffer", "02_zbuffer", "03_perspective_z",
                         "04_scanline_inverse_z"};
    const char *dir = test_dir("full_disk");
    const char *path = path_join(dir, "picture.png");
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) {
        write_bytes(path, OLD_BYTES);
        const char *args[] = {"--out", path, NULL};
        struct rlimit old_limit, limit;
        assert_int_equal(getrlimit(RLIMIT_FSIZE, &old_limit), 0);
        limit = old_limit;
        limit.rlim_cur = FILE_SIZE_LIMIT;
        void (*old_handler)(int) = signal(SIGXFSZ, SIG_IGN); /* else it kills the lesson */
        assert_int_equal(setrlimit(RLIMIT_FSIZE, &limit), 0);
        RunResult r = run_program(all[i], args);
        setrlimit(RLIMIT_FSIZE, &old_limit);
        signal(SIGXFSZ, old_handler);

        char want[TEXT_MAX];
        snprintf(want, sizeof want, "%s: error: cannot write %s: File too large\n", all[i], path);
        assert_string_equal(r.err, want);
        assert_int_equal(r.status, 1);
        char *now = read_bytes(path);
        assert_non_null(now);
        assert_string_equal(now, OLD_BYTES);
        free(now);
        assert_int_equal(count_entries(dir), 1); /* no temporary file left */
        run_result_free(&r);
    }
}

/* /dev/full accepts the open and refuses every byte, as a full disk does: the
 * lesson fails, and /dev/full is still the device (not replaced by a file). */
static void dev_full_is_a_clean_failure(void **state)
{
    (void)state;
    const char *args[] = {"--width", "8", "--height", "8", "--out", "/dev/full", NULL};
    const char *all[] = {"01_ybuffer", "02_zbuffer", "03_perspective_z",
                         "04_scanline_inverse_z"};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) {
        RunResult r = run_program(all[i], args);
        char want[TEXT_MAX];
        snprintf(want, sizeof want, "%s: error: cannot write /dev/full: No space left on device\n",
                 all[i]);
        assert_string_equal(r.err, want);
        assert_int_equal(r.status, 1);
        run_result_free(&r);
        struct stat st;
        assert_int_equal(stat("/dev/full", &st), 0);
        assert_true(S_ISCHR(st.st_mode));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_bad_command_line_is_refused_with_one_line_and_no_file),
        cmocka_unit_test(full_disk_keeps_the_existing_picture),
        cmocka_unit_test(dev_full_is_a_clean_failure),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
