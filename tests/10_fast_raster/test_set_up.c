/* test_set_up.c: lesson 10 draws the same bits whoever sets its faces up,
 * and whether it counts or not. With two threads its faces are held back and
 * set up by both threads at fast_finish (extras/held.c); with FastRaster.hold
 * false (the benchmark's FAST_RASTER_SET_UP=one) each is set up by the
 * calling thread as it comes, and the threads only draw. Both must give the
 * depth and face buffers of one thread, to the bit: random triangles and
 * quads of every size, some across the screen's edges, in more polygons than
 * the bins take at once. With lesson 09's tile buffer and counting off (the
 * benchmark's frames), a block behind a polygon's nearest value over the tile
 * is skipped before its coverage is found: the same bits again. The threads
 * themselves are kept from one finish to the next (extras/pool.c). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <pthread.h>
#include <stdatomic.h>
#include <string.h>
#include <time.h>

#include "engine.h" /* extras/: simd_best */
#include "fast_raster.h"
#include "state.h"
#include "test_support.h"

#define WIDTH 320
#define HEIGHT 240
/* Over 8,192 polygons heaped on 20 tiles, and about 18,700 triangles, over
 * the 16,384 two threads hold (extras/held.c): the bins (full, by
 * bins_full's measure), and the faces held, are drawn on the way. */
#define FACES 14000

static uint64_t state = 88172645463325252ull;

static double unit(void) /* xorshift64 in [0, 1): the same faces on every machine */
{
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return (double)(state >> 11) / 9007199254740992.0;
}

/* The same FACES faces, drawn by an engine of threads threads that holds its
 * faces back for them (hold) or sets each up as it comes; with a tile buffer
 * (tiles, when not NULL: its counts added up there), counting or not. */
static Target draw_counting(int threads, bool hold, HierarchicalZ *tiles, bool counting)
{
    Target t;
    Error err;
    if (!target_init(&t, WIDTH, HEIGHT, &err))
        fail_msg("target_init: %s", err.msg);
    if (tiles && !hiz_begin(tiles, &t, BLOCK_SIZE, &err))
        fail_msg("hiz_begin: %s", err.msg);
    t.counting = counting;
    LessonState s = fast_raster(depth_setup(UNORM24, STANDARD, 0.1, 1000.0), simd_best(),
                                threads, false);
    s.fast.hold = hold, s.hiz = tiles;
    FAST_ZBUFFER.clear(&t, &s);
    state = 88172645463325252ull;
    DrawContext ctx = {0.1, 1000.0, WIDTH, HEIGHT};
    static const Tri tris[2] = {{{0, 1, 2}}, {{0, 2, 3}}};
    for (int i = 0; i < FACES; i++) {
        double size = i % 100 == 0 ? 200 : i % 10 == 0 ? 40 : 6; /* a few large, most small */
        double x = unit() * (WIDTH + 40) - 20, y = unit() * (HEIGHT + 40) - 20;
        double w = 1 + unit() * size, h = 1 + unit() * size, slant = (unit() - 0.5) * size;
        ScreenVertex v[4] = {{x, y, 1 + 99 * unit()}, {x + w, y + slant, 1 + 99 * unit()},
                             {x + w, y + slant + h, 1 + 99 * unit()}, {x, y + h, 0}};
        v[3].d = v[0].d + v[2].d - v[1].d > 0.5 ? v[0].d + v[2].d - v[1].d : 0.5; /* about a plane */
        ScreenFace f = {i, i % 3 == 0 ? 4 : 3, v, tris, true, NULL}; /* a parallelogram, or half */
        FAST_ZBUFFER.draw_face(&t, &s, &f, &ctx);
    }
    if (!fast_finish(&t, &s, &err))
        fail_msg("fast_finish: %s", err.msg);
    fast_raster_free(&s.fast);
    return t;
}

static Target draw(int threads, bool hold) { return draw_counting(threads, hold, NULL, true); }

static void expect_same_buffers(const Target *want, const Target *got, const char *what)
{
    size_t n = (size_t)WIDTH * HEIGHT;
    for (size_t i = 0; i < n; i++)
        if (memcmp(&want->depth[i], &got->depth[i], sizeof *got->depth) != 0 ||
            want->face[i] != got->face[i])
            fail_msg("%s: pixel (%zu, %zu) has face %d at %.9g, one thread face %d at %.9g", what,
                     i % WIDTH, i / WIDTH, (int)got->face[i], (double)got->depth[i],
                     (int)want->face[i], (double)want->depth[i]);
}

static void faces_set_up_by_one_thread_or_by_both_draw_the_same_bits(void **unused)
{
    (void)unused;
    Target one = draw(1, true), held = draw(2, true), by_caller = draw(2, false);
    size_t drawn = 0, faces = 0; /* not a blank picture: most pixels, many faces */
    bool seen[FACES] = {false};
    for (size_t i = 0; i < (size_t)WIDTH * HEIGHT; i++)
        if (one.face[i] != NO_FACE)
            drawn++, faces += !seen[one.face[i]], seen[one.face[i]] = true;
    assert_true(drawn > (size_t)WIDTH * HEIGHT * 9 / 10);
    assert_true(faces > FACES / 8);
    expect_same_buffers(&one, &held, "2 threads, faces held and set up by both");
    expect_same_buffers(&one, &by_caller, "2 threads, faces set up by the caller");
    target_free(&one), target_free(&held), target_free(&by_caller);
}

static void blocks_skipped_uncounted_draw_the_same_bits(void **unused)
{
    (void)unused;
    HierarchicalZ h[4] = {{0}};
    Target t[5] = {draw(1, true), draw_counting(1, true, &h[0], true),
                   draw_counting(1, true, &h[1], false), draw_counting(2, true, &h[2], false),
                   draw_counting(2, false, &h[3], false)};
    static const char *const what[5] = {
        "no tile buffer, 1 thread", "the tile buffer, counted",
        "the tile buffer, uncounted, 1 thread", "the tile buffer, uncounted, 2 threads, faces held",
        "the tile buffer, uncounted, 2 threads"};
    /* Counted, the tile buffer skips blocks: there is something to skip.
     * Uncounted, fewer are counted: the blocks skipped first are not. Bounds,
     * not values: a bound of the plane looser than lesson 09's (still safe)
     * skips fewer blocks, and draws the same bits. */
    expect_at_least(1001, (long)h[0].tiles_skipped, "blocks skipped, counted");
    expect_at_most((long)(h[0].tiles_skipped / 2) - 1, (long)h[1].tiles_skipped,
                   "blocks skipped uncounted, against half of those counted");
    for (int k = 0; k < 5; k++) {
        observe_target(&t[k]);
        observe_data("depth", t[k].depth, (size_t)WIDTH * HEIGHT * sizeof *t[k].depth);
        expect_same_buffers(&t[0], &t[k], what[k]);
    }
    for (int k = 0; k < 4; k++)
        hiz_free(&h[k]);
    for (int k = 0; k < 5; k++)
        target_free(&t[k]);
}

/* run_threads (extras/pool.c): every share once, each by the first thread
 * to take it, share 0 by the calling thread; the pool's threads, kept from
 * one call to the next (more started when a call has more shares, none when
 * it has one, 255 at most: --threads 1 to 256), take the others at once.
 * Share 0 waits till every other share has started: so they ran on the
 * pool's threads, beside it, whichever took which. */
typedef struct { pthread_t caller, ran_on; int runs; int n; atomic_int *started; } Share;

static void *note_share(void *arg)
{
    Share *sh = arg;
    sh->runs++;
    sh->ran_on = pthread_self();
    atomic_fetch_add(sh->started, 1);
    for (int ms = 0; sh->n > 0 && atomic_load(sh->started) < sh->n && ms < 10000; ms++)
        nanosleep(&(struct timespec){0, 1000000}, NULL); /* share 0: 10 s at most */
    return NULL;
}

static void threads_are_kept_and_run_each_share_once(void **unused)
{
    (void)unused;
    Pool *pool = NULL;
    static const int shares[] = {3, 5, 2, 5, 1, 300};
    for (size_t c = 0; c < sizeof shares / sizeof *shares; c++) {
        int n = shares[c];
        static Share sh[300];
        atomic_int started;
        atomic_init(&started, 0);
        for (int k = 0; k < n; k++)
            sh[k] = (Share){pthread_self(), pthread_self(), 0, k == 0 ? n : 0, &started};
        run_threads(&pool, n, note_share, sh, sizeof *sh);
        if (n > 1 && atomic_load(&started) != n)
            fail_msg("%d shares: %d started", n, atomic_load(&started));
        for (int k = 0; k < n; k++) {
            if (sh[k].runs != 1)
                fail_msg("%d shares: share %d ran %d times", n, k, sh[k].runs);
            if (pthread_equal(sh[k].ran_on, sh[k].caller) != (k == 0))
                fail_msg("%d shares: share %d ran on %s", n, k,
                         k == 0 ? "another thread" : "the calling thread, after share 0");
        }
        if (c == 0 && !pool)
            fail_msg("3 shares: no pool was made");
    }
    pool_free(pool);
    Pool *none = NULL; /* one share: no pool, no thread */
    atomic_int started;
    atomic_init(&started, 0);
    Share one = {pthread_self(), pthread_self(), 0, 0, &started};
    run_threads(&none, 1, note_share, &one, sizeof one);
    assert_null(none);
    assert_true(one.runs == 1 && pthread_equal(one.ran_on, one.caller));
}

/* bins_full (extras/engine.c): the bins are drawn before the next polygon
 * never below 8,192 polygons and always at 65,536; in between, at each
 * 1,024th, when their boxes hold 4 times the pixels of the tiles they touch:
 * polygons heaped on few tiles are drawn soon, those spread over the screen
 * wait for more (each finish passes over every busy tile). */
static void bins_are_full_when_boxes_hold_4_times_their_tiles(void **unused)
{
    (void)unused;
    Bin bin[4] = {{0}};
    Bins b = {.tiles_x = 2, .tiles_y = 2, .bin = bin};
    const long tile = (long)TILE_SIZE * TILE_SIZE;
    bin[0].n = 3, bin[0].work = 100 * tile; /* one busy tile, boxes of 100 times it */
    b.npoly = 8191;
    assert_false(bins_full(&b));
    b.npoly = 8192;
    assert_true(bins_full(&b));
    bin[0].work = 4 * tile - 1; /* just under 4 times */
    assert_false(bins_full(&b));
    bin[0].work = 4 * tile;
    assert_true(bins_full(&b));
    bin[3].n = 1; /* two busy tiles: 8 tiles' pixels now */
    assert_false(bins_full(&b));
    bin[3].work = 4 * tile;
    assert_true(bins_full(&b));
    b.npoly = 8193; /* weighed at each 1,024th polygon only */
    assert_false(bins_full(&b));
    b.npoly = 9216;
    assert_true(bins_full(&b));
    bin[0].work = bin[3].work = 1; /* spread thin: it waits, till 65,536 */
    assert_false(bins_full(&b));
    b.npoly = 65535;
    assert_false(bins_full(&b));
    b.npoly = 65536;
    assert_true(bins_full(&b));
}

/* One engine of two threads drawing on a target of one tile, then on one of
 * 16 tiles with a single face: the second finish has a run of no face, whose
 * bins, kept from the first target, must not be read as the second's. The
 * face is drawn as an engine of its own draws it. */
static void one_engine_draws_on_targets_of_two_sizes(void **unused)
{
    (void)unused;
    LessonState s = fast_raster(depth_setup(UNORM24, STANDARD, 0.1, 1000.0), simd_best(), 2,
                                false);
    LessonState fresh = fast_raster(depth_setup(UNORM24, STANDARD, 0.1, 1000.0), simd_best(),
                                    2, false);
    static const Tri tri[1] = {{{0, 1, 2}}};
    DrawContext ctx = {0.1, 1000.0, 64, 64};
    Target small, big, want;
    Error err;
    if (!target_init(&small, 64, 64, &err) || !target_init(&big, 256, 256, &err) ||
        !target_init(&want, 256, 256, &err))
        fail_msg("target_init: %s", err.msg);
    FAST_ZBUFFER.clear(&small, &s);
    for (int i = 0; i < 4; i++) { /* a face for each run */
        ScreenVertex v[3] = {{2.0 + i, 2, 5}, {60, 10.0 + i, 5}, {10, 60, 5}};
        ScreenFace f = {i, 3, v, tri, true, NULL};
        FAST_ZBUFFER.draw_face(&small, &s, &f, &ctx);
    }
    if (!fast_finish(&small, &s, &err))
        fail_msg("fast_finish: %s", err.msg);
    ctx.width = ctx.height = 256;
    ScreenVertex v[3] = {{10, 10, 5}, {250, 30, 5}, {40, 240, 5}};
    ScreenFace f = {7, 3, v, tri, true, NULL};
    Target *t[2] = {&big, &want};
    LessonState *st[2] = {&s, &fresh};
    for (int k = 0; k < 2; k++) {
        FAST_ZBUFFER.clear(t[k], st[k]);
        FAST_ZBUFFER.draw_face(t[k], st[k], &f, &ctx);
        if (!fast_finish(t[k], st[k], &err))
            fail_msg("fast_finish: %s", err.msg);
    }
    size_t drawn = 0;
    for (size_t i = 0; i < 256 * 256; i++)
        drawn += want.face[i] == 7;
    assert_true(drawn > 20000);
    for (size_t i = 0; i < 256 * 256; i++)
        if (big.face[i] != want.face[i] || memcmp(&big.depth[i], &want.depth[i], sizeof *big.depth))
            fail_msg("pixel (%zu, %zu): face %d, as drawn alone %d", i % 256, i / 256,
                     (int)big.face[i], (int)want.face[i]);
    fast_raster_free(&s.fast), fast_raster_free(&fresh.fast);
    target_free(&small), target_free(&big), target_free(&want);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(faces_set_up_by_one_thread_or_by_both_draw_the_same_bits),
        cmocka_unit_test(blocks_skipped_uncounted_draw_the_same_bits),
        cmocka_unit_test(threads_are_kept_and_run_each_share_once),
        cmocka_unit_test(bins_are_full_when_boxes_hold_4_times_their_tiles),
        cmocka_unit_test(one_engine_draws_on_targets_of_two_sizes),
    };
    return cmocka_run_group_tests_name("10_fast_raster set-up", tests, NULL, NULL);
}
