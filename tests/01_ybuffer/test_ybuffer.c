/* test_ybuffer.c: lesson 01's y-buffer against values worked out by hand.
 *
 * The three segments of the lesson, as functions of the column x:
 *
 *   red    R(x) = 34 + 366 (x - 20) / 724  = 34 + 183 (x - 20) / 362    x in 20..744
 *   green  G(x) = 434 - 34 (x - 120) / 324 = 434 - 17 (x - 120) / 162   x in 120..444
 *   blue   B(x) = 463 - 263 (x - 330) / 264                              x in 330..594
 *
 * Each is rounded to the nearest integer, halves up, and a column keeps the
 * largest rounded y; on a tie (strict test y > stored) the first drawn stays.
 * Drawn red, green, blue, the row comes out as (boundaries derived below):
 *
 *   0..19     black  red starts at 20
 *   20..119   red    the only segment there; green starts at 120
 *   120..329  green  green is at least G(444) = 400 on 120..444, red at most
 *                    R(444) = 34 + 183*424/362 = 248.3: green beats red throughout
 *   330..386  blue   B(330) = 463 > G(330) = 411.96. Green and blue cross at
 *                    x = 2460282/6353 = 387.26:
 *                    x=386: B = 463 - 263*56/264 = 407.21 -> 407, G = 434 - 17*266/162 = 406.09 -> 406
 *   387..444  green  x=387: B = 463 - 263*57/264 = 406.22 -> 406, G = 434 - 17*267/162 = 405.98 -> 406:
 *                    a TIE after rounding; green was drawn first and the strict test keeps it.
 *                    x=388: B = 405.22 -> 405, G = 405.88 -> 406. Green ends at 444 (G = 400, B = 349.4).
 *   445..511  blue   x=445: B = 463 - 263*115/264 = 348.44 -> 348 > R = 34 + 183*425/362 = 248.85 -> 249.
 *                    Red and blue cross at x = 36691446/71759 = 511.31:
 *                    x=511: R = 34 + 183*491/362 = 282.21 -> 282, B = 463 - 263*181/264 = 282.69 -> 283
 *   512..744  red    x=512: R = 34 + 183*492/362 = 282.72 -> 283, B = 463 - 263*182/264 = 281.69 -> 282.
 *                    Blue ends at 594 (B = 200 < R = 324.17); red ends at 744.
 *   745..799  black
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>

#include "test_support.h"
#include "ybuffer.h"

#define WIDTH 800
enum { RED, GREEN, BLUE, SEGMENT_COUNT };

static const Segment SCENE[SEGMENT_COUNT] = {
    [RED] = {20, 34, 744, 400, {255, 0, 0}},
    [GREEN] = {120, 434, 444, 400, {0, 255, 0}},
    [BLUE] = {330, 463, 594, 200, {0, 0, 255}},
};
static const char *const NAMES[SEGMENT_COUNT] = {"red", "green", "blue"};

static const char *owner_name(int owner)
{
    return owner == NO_SEGMENT ? "nothing" : NAMES[owner];
}

/* Clears yb, then draws SCENE in the given order (indices from 0). */
static void draw_scene(YBuffer *yb, const int order[SEGMENT_COUNT])
{
    clear_ybuffer(yb);
    for (int k = 0; k < SEGMENT_COUNT; k++)
        draw_segment(yb, &SCENE[order[k]], order[k]);
}

static void init_ybuffer(YBuffer *yb, int width)
{
    Error err;
    if (!ybuffer_init(yb, width, &err))
        fail_msg("ybuffer_init(%d): %s", width, err.msg);
}

typedef struct {
    int first, last, owner;
} Run;

/* Every column of every run, so that each boundary column is pinned. */
static void expect_runs(const YBuffer *yb, const Run *runs, int n)
{
    observe_data("owners", yb->owner, (size_t)yb->width * sizeof *yb->owner);
    int x = 0;
    for (int r = 0; r < n; r++) {
        assert_int_equal(runs[r].first, x); /* the runs of a test must tile the row */
        for (; x <= runs[r].last; x++)
            if (yb->owner[x] != runs[r].owner)
                fail_msg("column %d: won by %s, expected %s (run %d..%d)", x,
                         owner_name(yb->owner[x]), owner_name(runs[r].owner), runs[r].first,
                         runs[r].last);
    }
    assert_int_equal(x, yb->width);
}

static void expect_y(const YBuffer *yb, int x, int y, int owner, const char *why)
{
    observe_value("y", yb->y[x]);
    observe_value("owner", yb->owner[x]);
    if (yb->y[x] != y || yb->owner[x] != owner)
        fail_msg("column %d (%s): y-buffer holds %d won by %s, expected %d won by %s", x, why,
                 yb->y[x], owner_name(yb->owner[x]), y, owner_name(owner));
}

static void default_render_has_the_derived_runs(void **state)
{
    (void)state;
    static const Run RUNS[] = {
        {0, 19, NO_SEGMENT}, {20, 119, RED},   {120, 329, GREEN}, {330, 386, BLUE},
        {387, 444, GREEN},   {445, 511, BLUE}, {512, 744, RED},   {745, 799, NO_SEGMENT},
    };
    static const int ORDER[SEGMENT_COUNT] = {RED, GREEN, BLUE};
    YBuffer yb;
    init_ybuffer(&yb, WIDTH);
    draw_scene(&yb, ORDER);
    expect_runs(&yb, RUNS, (int)(sizeof RUNS / sizeof RUNS[0]));
    ybuffer_free(&yb);
}

static void ybuffer_after_each_step(void **state)
{
    (void)state;
    YBuffer yb;
    init_ybuffer(&yb, WIDTH);
    clear_ybuffer(&yb);
    for (int x = 0; x < WIDTH; x++)
        expect_y(&yb, x, YBUFFER_CLEARED, NO_SEGMENT, "cleared");

    /* Step 1, red: R(20) = 34, R(744) = 400, nothing outside 20..744.
     * R(201) = 34 + 183*181/362 = 125.5 -> 126 and R(563) = 34 + 183*543/362 = 308.5 -> 309:
     * exact halves, rounded up. */
    draw_segment(&yb, &SCENE[RED], RED);
    expect_y(&yb, 19, YBUFFER_CLEARED, NO_SEGMENT, "left of red");
    expect_y(&yb, 20, 34, RED, "red's left end");
    expect_y(&yb, 201, 126, RED, "R = 125.5, halves up");
    expect_y(&yb, 563, 309, RED, "R = 308.5, halves up");
    expect_y(&yb, 744, 400, RED, "red's right end");
    expect_y(&yb, 745, YBUFFER_CLEARED, NO_SEGMENT, "right of red");

    /* Step 2, green over 120..444, nearer than red everywhere there.
     * R(119) = 34 + 183*99/362 = 84.05 -> 84 is left alone;
     * G(201) = 434 - 17*81/162 = 425.5 -> 426 (truncating would give 425);
     * R(445) = 34 + 183*425/362 = 248.85 -> 249 is left alone. */
    draw_segment(&yb, &SCENE[GREEN], GREEN);
    expect_y(&yb, 119, 84, RED, "left of green");
    expect_y(&yb, 120, 434, GREEN, "green's left end beats R = 85");
    expect_y(&yb, 201, 426, GREEN, "G = 425.5, halves up");
    expect_y(&yb, 444, 400, GREEN, "green's right end");
    expect_y(&yb, 445, 249, RED, "right of green");

    /* Step 3, blue over 330..594.
     * B(462) = 463 - 263*132/264 = 331.5 -> 332 beats R(462) = 257.4 -> 257;
     * B(594) = 200 loses to R(594) = 34 + 183*574/362 = 324.17 -> 324. */
    draw_segment(&yb, &SCENE[BLUE], BLUE);
    expect_y(&yb, 330, 463, BLUE, "blue's left end beats G = 412");
    expect_y(&yb, 386, 407, BLUE, "B = 407.21 beats G = 406.09");
    expect_y(&yb, 387, 406, GREEN, "tie 406 = 406: the strict test keeps green");
    expect_y(&yb, 388, 406, GREEN, "G = 405.88 beats B = 405.22");
    expect_y(&yb, 462, 332, BLUE, "B = 331.5, halves up");
    expect_y(&yb, 511, 283, BLUE, "B = 282.69 beats R = 282.21");
    expect_y(&yb, 512, 283, RED, "R = 282.72 beats B = 281.69");
    expect_y(&yb, 594, 324, RED, "blue's right end loses");

    /* Tests made: one per column walked, 725 + 325 + 265 = 1315. Red and green
     * pass everywhere; blue passes on 330..386 (57) and 445..511 (67) = 124,
     * fails on 387..444 (58) and 512..594 (83) = 141. */
    expect_count(1315, yb.stats.tested, "column tests made");
    expect_count(725 + 325 + 124, yb.stats.passed, "column tests passed");
    expect_count(141, yb.stats.failed, "column tests failed");
    ybuffer_free(&yb);
}

/* The y-buffer ends up holding, per column, the largest rounded y of all the
 * segments there: the same in every order. The picture too, but for column 387,
 * where green and blue tie at 406 and the strict test keeps the one drawn first. */
static void all_six_orders_agree_except_the_tie(void **state)
{
    (void)state;
    static const int ORDERS[6][SEGMENT_COUNT] = {
        {RED, GREEN, BLUE}, {RED, BLUE, GREEN}, {GREEN, RED, BLUE},
        {GREEN, BLUE, RED}, {BLUE, RED, GREEN}, {BLUE, GREEN, RED},
    };
    enum { TIE_COLUMN = 387 };
    YBuffer first, other;
    init_ybuffer(&first, WIDTH);
    init_ybuffer(&other, WIDTH);
    draw_scene(&first, ORDERS[0]);
    for (int o = 1; o < 6; o++) {
        draw_scene(&other, ORDERS[o]);
        observe_data("y", other.y, WIDTH * sizeof *other.y);
        observe_data("owners", other.owner, WIDTH * sizeof *other.owner);
        for (int x = 0; x < WIDTH; x++) {
            if (other.y[x] != first.y[x])
                fail_msg("order %d%d%d, column %d: y-buffer %d, order 123 gives %d",
                         ORDERS[o][0] + 1, ORDERS[o][1] + 1, ORDERS[o][2] + 1, x, other.y[x],
                         first.y[x]);
            if (x != TIE_COLUMN && other.owner[x] != first.owner[x])
                fail_msg("order %d%d%d, column %d: won by %s, order 123 gives %s",
                         ORDERS[o][0] + 1, ORDERS[o][1] + 1, ORDERS[o][2] + 1, x,
                         owner_name(other.owner[x]), owner_name(first.owner[x]));
        }
        /* At the tie, whichever of green and blue comes first in the order. */
        int k_green = 0, k_blue = 0;
        for (int k = 0; k < SEGMENT_COUNT; k++) {
            k_green = ORDERS[o][k] == GREEN ? k : k_green;
            k_blue = ORDERS[o][k] == BLUE ? k : k_blue;
        }
        expect_y(&other, TIE_COLUMN, 406, k_green < k_blue ? GREEN : BLUE,
                 "green/blue tie: first drawn keeps it");
    }
    ybuffer_free(&first);
    ybuffer_free(&other);
}

static void round_half_up_rounds_exact_halves_up(void **state)
{
    (void)state;
    assert_int_equal(round_half_up(5, 2), 3);   /* 2.5 -> 3 */
    assert_int_equal(round_half_up(7, 2), 4);   /* 3.5 -> 4 */
    assert_int_equal(round_half_up(-5, 2), -2); /* -2.5 -> -2: up, not away from zero */
    assert_int_equal(round_half_up(-7, 2), -3); /* -3.5 -> -3 */
    assert_int_equal(round_half_up(1, 3), 0);   /* 0.33 -> 0 */
    assert_int_equal(round_half_up(2, 3), 1);   /* 0.67 -> 1 */
    assert_int_equal(round_half_up(-1, 3), 0);  /* -0.33 -> 0 */
    assert_int_equal(round_half_up(-2, 3), -1); /* -0.67 -> -1 */
    assert_int_equal(round_half_up(-6, 3), -2); /* exact */
    /* 2e12 + 0.5, beyond what a float would hold exactly */
    assert_int_equal(round_half_up(4000000000001LL, 2), 2000000000001LL);
}

static void interpolation_rounds_halves_up_on_both_sides_of_zero(void **state)
{
    (void)state;
    const Segment up = {0, 0, 2, 1, {255, 255, 255}};    /* y(1) = 0.5 -> 1 */
    const Segment down = {0, 0, 2, -1, {255, 255, 255}}; /* y(1) = -0.5 -> 0 */
    const Segment below = {0, -1, 2, -2, {255, 255, 255}}; /* y(1) = -1.5 -> -1 */
    assert_int_equal(segment_y_at(&up, 1), 1);
    assert_int_equal(segment_y_at(&down, 1), 0);
    assert_int_equal(segment_y_at(&below, 1), -1);
    /* y(1) = 7 + 6/12 = 7.5 -> 8, where the float lerp 7 (1 - t) + 13 t,
     * t = 1/12, gives 7.499999999999999 and would round to 7. */
    const Segment lerp_trap = {0, 7, 12, 13, {255, 255, 255}};
    assert_int_equal(segment_y_at(&lerp_trap, 1), 8);
    /* Ends are exact. */
    assert_int_equal(segment_y_at(&SCENE[BLUE], 330), 463);
    assert_int_equal(segment_y_at(&SCENE[BLUE], 594), 200);
}

static void endpoints_in_either_order_give_the_same_walk(void **state)
{
    (void)state;
    const Segment red_backwards = {744, 400, 20, 34, {255, 0, 0}};
    for (int x = 20; x <= 744; x++) {
        observe_value("backwards", segment_y_at(&red_backwards, x));
        observe_value("forwards", segment_y_at(&SCENE[RED], x));
    }
    for (int x = 20; x <= 744; x++)
        if (segment_y_at(&red_backwards, x) != segment_y_at(&SCENE[RED], x))
            fail_msg("column %d: right-to-left red gives %d, left-to-right %d", x,
                     segment_y_at(&red_backwards, x), segment_y_at(&SCENE[RED], x));
}

static void depth_test_is_strict_larger_y_wins(void **state)
{
    (void)state;
    assert_true(depth_test(6, 5));
    assert_false(depth_test(5, 5)); /* a tie keeps what is stored */
    assert_false(depth_test(4, 5));
    assert_true(depth_test(-COORD_LIMIT, YBUFFER_CLEARED)); /* anything beats "cleared" */
}

static void equal_segments_first_drawn_keeps_every_column(void **state)
{
    (void)state;
    const Segment a = {10, 5, 20, 5, {255, 0, 0}}, b = {10, 5, 20, 5, {0, 0, 255}};
    YBuffer yb;
    init_ybuffer(&yb, 30);
    clear_ybuffer(&yb);
    draw_segment(&yb, &a, 0);
    draw_segment(&yb, &b, 1);
    for (int x = 10; x <= 20; x++)
        expect_y(&yb, x, 5, 0, "same y: the first drawn stays");
    expect_count(11, yb.stats.failed, "column tests failed"); /* all of b's 11 columns */
    ybuffer_free(&yb);
}

/* x0 == x1: seen from above the segment is a single column, and what the
 * viewer sees there is its nearest point, max(y0, y1). */
static void vertical_segment_is_one_column_at_its_nearest_y(void **state)
{
    (void)state;
    const Segment up = {100, 10, 100, 50, {255, 255, 0}};
    const Segment down = {100, 50, 100, 10, {255, 255, 0}};
    const Segment point = {5, 7, 5, 7, {255, 255, 0}};
    YBuffer yb;
    init_ybuffer(&yb, WIDTH);
    for (int variant = 0; variant < 2; variant++) {
        clear_ybuffer(&yb);
        draw_segment(&yb, variant ? &down : &up, 0);
        expect_y(&yb, 99, YBUFFER_CLEARED, NO_SEGMENT, "left of the vertical segment");
        expect_y(&yb, 100, 50, 0, "vertical: max(y0, y1)");
        expect_y(&yb, 101, YBUFFER_CLEARED, NO_SEGMENT, "right of the vertical segment");
        expect_count(1, yb.stats.tested, "column tests made");
    }
    clear_ybuffer(&yb);
    draw_segment(&yb, &point, 0);
    expect_y(&yb, 5, 7, 0, "a single point");
    expect_count(1, yb.stats.tested, "column tests made");
    ybuffer_free(&yb);
}

static void segment_wider_than_the_screen_is_clipped_to_it(void **state)
{
    (void)state;
    const Segment wide = {-50, 10, 900, 10, {255, 255, 255}};
    YBuffer yb;
    init_ybuffer(&yb, WIDTH);
    clear_ybuffer(&yb);
    draw_segment(&yb, &wide, 0);
    for (int x = 0; x < WIDTH; x++)
        expect_y(&yb, x, 10, 0, "wide segment covers every column");
    /* columns -50..-1 and 800..900 not walked */
    expect_count(WIDTH, yb.stats.tested, "column tests made");
    ybuffer_free(&yb);
}

static void segment_outside_the_screen_wins_nothing(void **state)
{
    (void)state;
    const Segment left = {-300, 5, -1, 5, {255, 255, 255}};
    const Segment right = {800, 5, 1000, 99, {255, 255, 255}};
    YBuffer yb;
    init_ybuffer(&yb, WIDTH);
    clear_ybuffer(&yb);
    draw_segment(&yb, &left, 0);
    draw_segment(&yb, &right, 1);
    for (int x = 0; x < WIDTH; x++)
        expect_y(&yb, x, YBUFFER_CLEARED, NO_SEGMENT, "segments off screen");
    expect_count(0, yb.stats.tested, "column tests made");
    ybuffer_free(&yb);
}

/* The widest segment the file format allows: a million columns each side,
 * still only 800 steps, and (y1 - y0) * (x - x0) = 1e6 * 2e6 does not overflow.
 * y(x) = 0 + 1e6 (x + 1e6) / 2e6 = 500000 + x / 2:
 * y(0) = 500000, y(1) = 500000.5 -> 500001, y(799) = 500399.5 -> 500400. */
static void segment_at_the_coordinate_limit(void **state)
{
    (void)state;
    const Segment huge = {-COORD_LIMIT, 0, COORD_LIMIT, COORD_LIMIT, {255, 255, 255}};
    YBuffer yb;
    init_ybuffer(&yb, WIDTH);
    clear_ybuffer(&yb);
    draw_segment(&yb, &huge, 0);
    expect_y(&yb, 0, 500000, 0, "y(0)");
    expect_y(&yb, 1, 500001, 0, "y(1) = 500000.5, halves up");
    expect_y(&yb, 799, 500400, 0, "y(799) = 500399.5, halves up");
    expect_count(WIDTH, yb.stats.tested, "column tests made");
    ybuffer_free(&yb);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(default_render_has_the_derived_runs),
        cmocka_unit_test(ybuffer_after_each_step),
        cmocka_unit_test(all_six_orders_agree_except_the_tie),
        cmocka_unit_test(round_half_up_rounds_exact_halves_up),
        cmocka_unit_test(interpolation_rounds_halves_up_on_both_sides_of_zero),
        cmocka_unit_test(endpoints_in_either_order_give_the_same_walk),
        cmocka_unit_test(depth_test_is_strict_larger_y_wins),
        cmocka_unit_test(equal_segments_first_drawn_keeps_every_column),
        cmocka_unit_test(vertical_segment_is_one_column_at_its_nearest_y),
        cmocka_unit_test(segment_wider_than_the_screen_is_clipped_to_it),
        cmocka_unit_test(segment_outside_the_screen_wins_nothing),
        cmocka_unit_test(segment_at_the_coordinate_limit),
    };
    return cmocka_run_group_tests_name("01_ybuffer: y-buffer", tests, NULL, NULL);
}
