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
#include "harness/render.h"
#include "harness/scene.h"

#define W 160
#define H 120

typedef struct { uint64_t *hash; int n, cap; } History;

/* After each face: one hash of both buffers (FNV-1a over their bytes). */
static bool remember(void *data, const Target *t, const ScreenFace *f, Error *err)
{
    (void)f, (void)err;
    History *h = data;
    uint64_t x = 0xcbf29ce484222325u;
    const unsigned char *d = (const unsigned char *)t->depth, *g = (const unsigned char *)t->face;
    for (size_t k = 0; k < (size_t)W * H * 4; k++)
        x = (x ^ d[k] ^ ((uint64_t)g[k] << 8)) * 0x100000001b3u;
    if (h->n == h->cap) {
        h->cap = h->cap ? 2 * h->cap : 256;
        h->hash = realloc(h->hash, (size_t)h->cap * sizeof *h->hash);
        assert_non_null(h->hash);
    }
    h->hash[h->n++] = x;
    return true;
}

/* scene drawn at W x H, tiles of side tile or none (tile 0): its history,
 * and the fragments tested at each pixel. */
static History draw(const char *scene, int tile, uint32_t *tests, DepthMapping mapping)
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
    History h = {0};
    assert_true(render_faces(&r, &t, &rz, NULL, 0, remember, &h, &err));
    memcpy(tests, t.overdraw, (size_t)W * H * sizeof *tests);
    hiz_free(&hz);
    target_free(&t);
    render_free(&r);
    return h;
}

static void same_history_with_and_without_tiles(const char *scene, int tile,
                                                DepthMapping mapping)
{
    static uint32_t with[W * H], without[W * H];
    History a = draw(scene, tile, with, mapping), b = draw(scene, 0, without, mapping);
    expect_count(b.n, a.n, "faces drawn");
    for (int k = 0; k < a.n; k++)
        if (a.hash[k] != b.hash[k])
            fail_msg("%s, tiles of %d: the buffers differ after face %d", scene, tile, k);
    long fewer = 0;
    for (int i = 0; i < W * H; i++) {
        if (with[i] > without[i])
            fail_msg("%s: pixel %d tested more often with tiles", scene, i);
        fewer += without[i] - with[i];
    }
    printf("  %s, tiles of %d: %ld fragments never tested\n", scene, tile, fewer);
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
