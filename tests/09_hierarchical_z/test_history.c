/* test_history.c: the tile buffer never skips a tile where a fragment would
 * have passed. Each scene is drawn through HIERARCHICAL_ZBUFFER twice, with
 * the tile buffer and without it (no tile buffer: every covered pixel tested,
 * lesson 08's pixels, as test_program.c shows); after every face both
 * depth and face buffers must be the same, so every pixel has the same
 * history of winners, while the run with tiles tests fewer fragments and
 * no pixel more often (on city, behind its wall, many fewer). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expect.h"
#include "hierarchical_z.h"
#include "state.h"
#include "harness/image_io.h"
#include "harness/render.h"
#include "harness/scene.h"
#include "test_support.h"

#define W 160
#define H 120

typedef struct { uint64_t *hash; int n, cap, stop; } History; /* stop: after that face */

/* After each face: one hash of both buffers (FNV-1a's steps, a pixel's
 * depth bits and face at a time); false (the drawing stops) once face
 * h->stop is drawn, when h->stop >= 0. */
static bool remember(void *data, const Target *t, const ScreenFace *f, Error *err)
{
    (void)f, (void)err;
    History *h = data;
    uint64_t x = 0xcbf29ce484222325u;
    for (size_t k = 0; k < (size_t)W * H; k++) {
        uint32_t depth_bits;
        memcpy(&depth_bits, &t->depth[k], sizeof depth_bits);
        x = (x ^ depth_bits ^ (uint64_t)(uint32_t)t->face[k] << 32) * 0x100000001b3u;
    }
    if (h->n == h->cap) {
        h->cap = h->cap ? 2 * h->cap : 256;
        h->hash = realloc(h->hash, (size_t)h->cap * sizeof *h->hash);
        assert_non_null(h->hash);
    }
    h->hash[h->n++] = x;
    return h->stop < 0 || h->n <= h->stop;
}

/* The buffers where a drawing stopped (History.stop). */
static float stopped_depth[W * H];
static int32_t stopped_face[W * H];

/* scene drawn at W x H, tiles of side tile or none (tile 0), up to face stop
 * (or every face: -1): its history, the fragments tested at each pixel, and
 * the buffers in stopped_depth and stopped_face. */
static History draw(const char *scene, int tile, uint32_t *tests, DepthMapping mapping, int stop)
{
    const SceneInfo *info = scene_find(scene);
    assert_non_null(info);
    Mesh m;
    Error err;
    mesh_init(&m);
    assert_true(info->build(&m, &err));
    Camera cam;
    camera_init(&cam, info->eye, info->target, info->up, info->fovy, info->near, info->far, W, H);
    Render r;
    assert_true(render_from_mesh(&r, &m, &cam, scene, &err));
    Target t;
    assert_true(target_init(&t, W, H, &err));
    /* Lesson 06's buffer; lesson 08's fragment step with depth only (no shader). */
    LessonState s = {.depth = depth_setup(UNORM24, mapping, info->near, info->far),
                     .early_z = {.pass = 1}};
    HierarchicalZ hz = {0};
    if (tile > 0)
        assert_true(hiz_begin(&hz, &t, tile, &err));
    s.hiz = tile > 0 ? &hz : NULL;
    Rasterizer rz = HIERARCHICAL_ZBUFFER;
    rz.state = &s;
    rz.clear(&t, &s);
    History h = {.stop = stop};
    bool all = render_faces(&r, &t, &rz, NULL, 0, remember, &h, &err);
    assert_true(all || stop >= 0);
    memcpy(tests, t.overdraw, (size_t)W * H * sizeof *tests);
    memcpy(stopped_depth, t.depth, sizeof stopped_depth);
    memcpy(stopped_face, t.face, sizeof stopped_face);
    hiz_free(&hz);
    target_free(&t);
    render_free(&r);
    return h;
}

/* After face k the buffers with tiles and without differ: the first pixel
 * that does, its tile, the faces there, and a picture of them all (magenta
 * where they differ, grey where they agree) for the student to open. */
static void report_difference(const char *scene, int tile, int k, DepthMapping mapping)
{
    static uint32_t tests[W * H];
    static float depth[W * H];
    static int32_t face[W * H];
    History a = draw(scene, tile, tests, mapping, k);
    memcpy(depth, stopped_depth, sizeof depth), memcpy(face, stopped_face, sizeof face);
    History b = draw(scene, 0, tests, mapping, k);
    free(a.hash), free(b.hash);
    Image im;
    Error err;
    assert_true(image_init(&im, W, H, &err));
    long differ = 0;
    int first = -1;
    for (int i = 0; i < W * H; i++) {
        bool same = face[i] == stopped_face[i] &&
                    memcmp(&depth[i], &stopped_depth[i], sizeof depth[i]) == 0;
        image_set(&im, i % W, i / W, same ? (Rgb){70, 70, 70} : (Rgb){255, 0, 255});
        if (!same && first < 0)
            first = i;
        differ += !same;
    }
    char name[64];
    snprintf(name, sizeof name, "l09_history_%s_%d", scene, tile);
    const char *path = path_join(test_dir(name), "differ.png");
    assert_true(image_write_png(&im, path, &err));
    image_free(&im);
    int x = first % W, y = first / W;
    fail_msg("%s, tiles of %d: after face %d, %ld pixels differ from the drawing without "
             "tiles; the first is (%d,%d), in tile (%d,%d): face %d there with tiles, %d "
             "without (NO_FACE = -1). A tile that was skipped held a pixel the face wins, "
             "or a tile's bound was set too near. Magenta in %s", scene, tile, k, differ, x, y,
             x / tile, y / tile, face[first], stopped_face[first], path);
}

static void same_history_with_and_without_tiles(const char *scene, int tile,
                                                DepthMapping mapping)
{
    static uint32_t with[W * H], without[W * H];
    History a = draw(scene, tile, with, mapping, -1), b = draw(scene, 0, without, mapping, -1);
    expect_count(b.n, a.n, "faces drawn");
    observe_data("history with tiles", a.hash, (size_t)a.n * sizeof *a.hash);
    observe_data("history without", b.hash, (size_t)b.n * sizeof *b.hash);
    long excess = 0;
    for (int i = 0; i < W * H; i++)
        excess = with[i] > without[i] && (long)(with[i] - without[i]) > excess
                     ? (long)(with[i] - without[i]) : excess;
    observe_near((double)excess, 0.0, 0.0);
    for (int k = 0; k < a.n; k++)
        if (a.hash[k] != b.hash[k])
            report_difference(scene, tile, k, mapping);
    long fewer = 0;
    for (int i = 0; i < W * H; i++) {
        if (with[i] > without[i])
            fail_msg("%s: pixel (%d,%d), in tile (%d,%d), tested %u times with tiles, %u "
                     "without", scene, i % W, i / W, i % W / tile, i / W / tile, with[i],
                     without[i]);
        fewer += without[i] - with[i];
    }
    printf("  %s, tiles of %d: %ld fragments never tested\n", scene, tile, fewer);
    if (strcmp(scene, "city") == 0)
        observe_near(fewer > 0 ? 1.0 : 0.0, 1.0, 0.0);
    if (strcmp(scene, "city") == 0 && fewer == 0)
        fail_msg("city: no fragment skipped: the check above proved nothing");
    free(a.hash);
    free(b.hash);
}

static void every_pixel_has_the_same_history(void **state)
{
    (void)state;
    static const char *const SCENES[] = {"cubes", "walls", "knot", "inside", "decals",
                                         "crowd", "city"};
    for (int k = 0; k < 7; k++)
        same_history_with_and_without_tiles(SCENES[k], 8, STANDARD);
    same_history_with_and_without_tiles("city", 3, STANDARD);
    same_history_with_and_without_tiles("knot", 16, STANDARD);
}

static void reversed_depth_too(void **state)
{
    (void)state;
    same_history_with_and_without_tiles("city", 8, REVERSED);
    same_history_with_and_without_tiles("knot", 8, REVERSED);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_pixel_has_the_same_history),
        cmocka_unit_test(reversed_depth_too),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
