/* test_program.c: build/bin/10_fast_raster run end to end. Its pictures are
 * lesson 09's, exactly: the face of every pixel (--id-out) and its depth
 * (--depth-out, the same float bits) on every built-in scene at 400 x 300,
 * with every --simd this machine runs (and pixels, without blocks) and 1, 2
 * and 3 threads; lesson 07's in the other depth formats and mappings, with a
 * polygon offset, and with a far plane that cuts the scene; the fragments
 * it counts when asked to count (lesson 08's: no block skipped); bad input. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/image_io.h"
#include "test_support.h"

#define PROGRAM "10_fast_raster"
#define NSCENES 11
#define MAX_ARGS 24
/* The size the comparisons draw at: 35 tiles of 64 x 64 (the last row and
 * column cut), enough for three threads, at a quarter of the default's
 * pixels, so that each test keeps within make grade's time per test. */
#define SIZE "--width", "400", "--height", "300"

static const char *const SCENES[NSCENES] = {"triangles3", "interpenetrate", "cubes", "grazing",
                                            "walls", "knot", "inside", "ladder", "decals",
                                            "crowd", "city"};

typedef struct { Image id; float *depth; int width, height; } Pictures;

/* program on scene with args (NULL-terminated, may be NULL), its pictures. */
static Pictures draw(const char *program, const char *scene, const char *const *args)
{
    const char *dir = test_dir("l10_draw");
    Path id = in_dir(dir, "id.png"), depth = in_dir(dir, "d.pfm"), out = in_dir(dir, "x.png");
    const char *all[MAX_ARGS] = {"--scene", scene, "--out", out.path, "--id-out", id.path,
                                 "--depth-out", depth.path};
    int n = 8;
    for (int k = 0; args && args[k] && n < MAX_ARGS - 1; k++)
        all[n++] = args[k];
    all[n] = NULL;
    free(run_ok(program, all));
    Pictures p = {.id = read_png(id.path)};
    Error err;
    if (!read_pfm(&p.depth, &p.width, &p.height, depth.path, &err))
        fail_msg("%s", err.msg);
    /* The depths are compared to the bit: what the judge sees too. */
    observe_data("depth", p.depth, (size_t)p.width * (size_t)p.height * sizeof *p.depth);
    return p;
}

static void pictures_free(Pictures *p)
{
    image_free(&p->id);
    free(p->depth);
}

/* got drawn (expect_drawn), and every pixel the same face and the same
 * depth as want, to the bit. */
static void expect_same_pictures(const Pictures *want, const Pictures *got, const char *what)
{
    assert_int_equal(want->width, got->width);
    assert_int_equal(want->height, got->height);
    expect_drawn(&got->id, what);
    if (want->id.width != want->width || want->id.height != want->height ||
        got->id.width != got->width || got->id.height != got->height)
        fail_msg("%s: the --id-out picture is not the size of the --depth-out one", what);
    size_t n = (size_t)want->width * (size_t)want->height;
    if (memcmp(want->id.rgb, got->id.rgb, n * IMAGE_CHANNELS) == 0 &&
        memcmp(want->depth, got->depth, n * sizeof *want->depth) == 0)
        return; /* the same bytes: the same faces, the same depths to the bit */
    long faces = 0, depths = 0;
    int first_x = -1, first_y = -1;
    for (int y = 0; y < want->height; y++)
        for (int x = 0; x < want->width; x++) {
            size_t i = (size_t)y * (size_t)want->width + (size_t)x;
            bool face = face_at(&want->id, x, y) != face_at(&got->id, x, y);
            bool depth = memcmp(&want->depth[i], &got->depth[i], sizeof(float)) != 0;
            faces += face, depths += depth;
            if ((face || depth) && first_x < 0)
                first_x = x, first_y = y;
        }
    if (faces || depths)
        fail_msg("%s: %ld pixels show another face and %ld another depth than the reference, "
                 "the first at (%d,%d)", what, faces, depths, first_x, first_y);
}

/* Whether this machine runs --simd simd (the program refuses it otherwise). */
static bool machine_runs(const char *simd)
{
    const char *args[] = {"--simd", simd, "--width", "8", "--height", "8", "--out",
                          path_join(test_dir("l10_probe"), "x.png"), NULL};
    RunResult r = run_program(PROGRAM, args);
    bool ok = r.status == 0;
    run_result_free(&r);
    return ok;
}

/* Lesson 09's pictures of each scene, drawn once for the four tests below
 * when they run in one process (make test; make grade runs each alone). */
static Pictures lesson_09[NSCENES];

/* Every scene, lesson 09's picture, against --simd simd with 1, 2, 3 threads. */
static void expect_every_scene_like_lesson_09(const char *simd)
{
    if (!machine_runs(simd))
        skip();
    const char *size[] = {SIZE, NULL};
    for (int s = 0; s < NSCENES; s++) {
        if (!lesson_09[s].depth)
            lesson_09[s] = draw("09_hierarchical_z", SCENES[s], size);
        const Pictures want = lesson_09[s];
        for (int threads = 1; threads <= 3; threads++) {
            char n[8], what[96];
            snprintf(n, sizeof n, "%d", threads);
            snprintf(what, sizeof what, "scene %s, --simd %s, --threads %d", SCENES[s], simd, threads);
            const char *args[] = {"--simd", simd, "--threads", n, SIZE, NULL};
            Pictures got = draw(PROGRAM, SCENES[s], args);
            expect_same_pictures(&want, &got, what);
            pictures_free(&got);
        }
    }
}

static void plain_c_draws_lesson_09s_pictures(void **state)
{
    (void)state;
    expect_every_scene_like_lesson_09("none");
}

static void pixels_without_blocks_draw_lesson_09s_pictures(void **state)
{
    (void)state;
    expect_every_scene_like_lesson_09("pixels");
}

static void sse2_draws_lesson_09s_pictures(void **state)
{
    (void)state;
    expect_every_scene_like_lesson_09("sse2");
}

static void avx2_draws_lesson_09s_pictures(void **state)
{
    (void)state;
    expect_every_scene_like_lesson_09("avx2");
}

static void avx512_draws_lesson_09s_pictures(void **state) /* skipped without AVX-512 */
{
    (void)state;
    expect_every_scene_like_lesson_09("avx512");
}

/* Lesson 07 has no cutouts (crowd's fences): every other scene, in the
 * depth buffers lesson 08 does not offer, and where --far 12 cuts walls and
 * inside (lesson 05 clips them: no fragment lies beyond the far plane). */
static void other_depth_buffers_draw_lesson_07s_pictures(void **state)
{
    (void)state;
    static const char *const SETUPS[][7] = {
        {"--depth-format", "unorm16", NULL},
        {"--depth-format", "float32", "--depth-mapping", "reversed", NULL},
        {"--depth-mapping", "reversed", "--far", "inf", NULL},
        {"--polygon-offset", "-1,-1", NULL},
        {"--far", "12", "--depth-format", "float32", NULL},
    };
    for (size_t k = 0; k < sizeof SETUPS / sizeof SETUPS[0]; k++)
        for (int s = 0; s < NSCENES; s++) {
            if (strcmp(SCENES[s], "crowd") == 0)
                continue;
            const char *args[MAX_ARGS] = {"--threads", "3", SIZE};
            int n = 6;
            for (int j = 0; SETUPS[k][j]; j++)
                args[n++] = SETUPS[k][j];
            args[n] = NULL;
            char what[128];
            snprintf(what, sizeof what, "scene %s with %s %s", SCENES[s], SETUPS[k][0],
                     SETUPS[k][1]);
            Pictures want = draw("07_depth_bias", SCENES[s], args + 2); /* not --threads */
            Pictures got = draw(PROGRAM, SCENES[s], args);
            expect_same_pictures(&want, &got, what);
            pictures_free(&want);
            pictures_free(&got);
        }
}

/* A far plane through decals' wall, at d = 8: lesson 04's walk (lessons
 * 04-08) discards a few fragments whose stepped 1/d falls below the far
 * plane's; lessons 09 and 10 step no 1/d and keep them, as a GPU does
 * after clipping. */
static void a_far_plane_through_a_face_draws_lesson_09s_picture(void **state)
{
    (void)state;
    const char *args[] = {"--far", "8", SIZE, NULL};
    Pictures want = draw("09_hierarchical_z", "decals", args);
    Pictures got = draw(PROGRAM, "decals", args);
    expect_same_pictures(&want, &got, "scene decals with --far 8");
    pictures_free(&want);
    pictures_free(&got);
}

/* The summary's "fragments: N tested, P passed, F failed" line, up to ';'. */
static char *fragments_line(const char *program, const char *scene, const char *const *more)
{
    const char *args[MAX_ARGS] = {"--scene", scene, "--out",
                                  path_join(test_dir("l10_counts"), "x.png"), SIZE};
    int n = 8;
    for (int k = 0; more && more[k]; k++)
        args[n++] = more[k];
    args[n] = NULL;
    char *out = run_ok(program, args);
    char *line = strstr(out, "  fragments: "), *end = line ? strchr(line, ';') : NULL;
    if (!end)
        fail_msg("no fragments line in:\n%s", out);
    *end = '\0';
    char *copy = strdup(line);
    free(out);
    return copy;
}

/* Asked to count (--overdraw-out, --trace), lesson 10 tests every fragment
 * one by one, no block skipped: the counts are lesson 08's, which has no
 * tile buffer either. */
static void fragments_are_counted_as_lesson_08_counts_them(void **state)
{
    (void)state;
    const char *dir = test_dir("l10_overdraw");
    Path want = in_dir(dir, "08.pgm"), got = in_dir(dir, "10.pgm");
    const char *counted[] = {"--overdraw-out", got.path, NULL};
    for (int s = 0; s < NSCENES; s++) {
        char *a = fragments_line("08_early_z", SCENES[s], NULL);
        char *b = fragments_line(PROGRAM, SCENES[s], counted);
        if (strcmp(a, b) != 0)
            fail_msg("scene %s: lesson 08 says '%s', lesson 10 '%s'", SCENES[s], a, b);
        free(a);
        free(b);
    }
    const char *args08[] = {"--overdraw-out", want.path, NULL};
    const char *args10[] = {"--overdraw-out", got.path, "--threads", "3", NULL};
    free(fragments_line("08_early_z", "crowd", args08));
    free(fragments_line(PROGRAM, "crowd", args10));
    if (!files_same_bytes(want.path, got.path))
        fail_msg("crowd: the overdraw counts (--overdraw-out) differ from lesson 08's");
}

/* Not asked to count, lesson 10 keeps no count per pixel: the summary says
 * so, rather than that no pixel was covered. */
static void summary_says_overdraw_was_not_counted(void **state)
{
    (void)state;
    const char *args[] = {"--scene", "crowd", "--out",
                          path_join(test_dir("l10_summary"), "x.png"), NULL};
    char *out = run_ok(PROGRAM, args);
    observe_value("says not counted",
                  strstr(out, "; overdraw per pixel not counted (--overdraw-out counts it)\n") != NULL);
    observe_value("says no pixel covered", strstr(out, "no pixel covered") != NULL);
    if (!strstr(out, "; overdraw per pixel not counted (--overdraw-out counts it)\n") ||
        strstr(out, "no pixel covered"))
        fail_msg("the summary should say the overdraw was not counted:\n%s", out);
    free(out);
}

/* The number after label in the program's summary (-1: none). */
static long long number_after(const char *out, const char *label)
{
    const char *at = strstr(out, label);
    return at ? strtoll(at + strlen(label), NULL, 10) : -1;
}

/* city: a wall in front of 510 buildings. Each block asks the tile buffer
 * first; behind the wall, most blocks asked hold no fragment that could
 * pass. With one thread or three, the same blocks are asked and skipped. */
static void most_blocks_behind_citys_wall_are_skipped(void **state)
{
    (void)state;
    long long tested[2], skipped[2];
    for (int k = 0; k < 2; k++) {
        const char *args[] = {"--scene", "city", "--threads", k ? "3" : "1", "--out",
                              path_join(test_dir("l10_hiz"), "x.png"), NULL};
        char *out = run_ok(PROGRAM, args);
        tested[k] = number_after(out, "tiles tested ");
        skipped[k] = number_after(out, "skipped ");
        free(out);
    }
    if (!(tested[0] > 0 && 2 * skipped[0] > tested[0]))
        fail_msg("city: %lld blocks asked, %lld skipped: not most", tested[0], skipped[0]);
    assert_int_equal(tested[0], tested[1]);
    assert_int_equal(skipped[0], skipped[1]);
}

static void expect_refused(const char *flag, const char *value, const char *message)
{
    const char *dir = test_dir("l10_bad");
    const char *args[] = {flag, value, "--out", path_join(dir, "x.png"), NULL};
    expect_run_refused(PROGRAM, args, 2, message, path_join(dir, "x.png"));
}

static void bad_command_lines_are_refused_with_status_2(void **state)
{
    (void)state;
    expect_refused("--simd", "mmx", "--simd: 'mmx' is not one of none, sse2, avx2, avx512, pixels");
    expect_refused("--threads", "0", "--threads: 0 is out of range (1 to 256)");
    expect_refused("--threads", "257", "--threads: 257 is out of range (1 to 256)");
    expect_refused("--threads", "two", "--threads: 'two' is not a whole number");
    expect_refused("--depth-format", "unorm8",
                   "--depth-format: 'unorm8' is not one of unorm16, unorm24, float32");
    expect_refused("--depth-mapping", "log",
                   "--depth-mapping log is lesson 06's: a depth written per fragment has no "
                   "plane to offset or to test early; here standard or reversed");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(plain_c_draws_lesson_09s_pictures),
        cmocka_unit_test(pixels_without_blocks_draw_lesson_09s_pictures),
        cmocka_unit_test(sse2_draws_lesson_09s_pictures),
        cmocka_unit_test(avx2_draws_lesson_09s_pictures),
        cmocka_unit_test(avx512_draws_lesson_09s_pictures),
        cmocka_unit_test(other_depth_buffers_draw_lesson_07s_pictures),
        cmocka_unit_test(a_far_plane_through_a_face_draws_lesson_09s_picture),
        cmocka_unit_test(fragments_are_counted_as_lesson_08_counts_them),
        cmocka_unit_test(most_blocks_behind_citys_wall_are_skipped),
        cmocka_unit_test(summary_says_overdraw_was_not_counted),
        cmocka_unit_test(bad_command_lines_are_refused_with_status_2),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
