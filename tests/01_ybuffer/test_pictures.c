/* test_pictures.c: lesson 01's three pictures, pixel by pixel where it matters
 * and against the expected images (tests/expected/01_ybuffer/). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>

#include "pictures.h"
#include "test_support.h"
#include "world.h"
#include "ybuffer.h"

#define GROUP "01_ybuffer"
#define WIDTH 800
#define RENDER_HEIGHT 16

static const Rgb RED = {255, 0, 0}, GREEN = {0, 255, 0}, BLUE = {0, 0, 255};
static const Rgb BLACK = {0, 0, 0};

static Rgb grey(int g)
{
    return (Rgb){(uint8_t)g, (uint8_t)g, (uint8_t)g};
}

/* The lesson's scene drawn red, green, blue into a fresh y-buffer. */
static Segment *draw_default(YBuffer *yb, int *count)
{
    Segment *segs;
    Error err;
    assert_true(default_segments(&segs, count, &err));
    assert_true(ybuffer_init(yb, WIDTH, &err));
    clear_ybuffer(yb);
    for (int i = 0; i < *count; i++)
        draw_segment(yb, &segs[i], i);
    return segs;
}

static void render_shows_the_runs_on_every_row(void **state)
{
    (void)state;
    YBuffer yb;
    int count;
    Segment *segs = draw_default(&yb, &count);
    Image im;
    Error err;
    assert_true(render_picture(&yb, segs, RENDER_HEIGHT, &im, &err));
    expect_count(WIDTH, im.width, "picture width");
    expect_count(RENDER_HEIGHT, im.height, "picture height");
    /* The boundary columns of test_ybuffer.c, on the top and the bottom row. */
    static const struct { int x; Rgb c; } COLUMNS[] = {
        {0, {0, 0, 0}},       {19, {0, 0, 0}},      {20, {255, 0, 0}},  {119, {255, 0, 0}},
        {120, {0, 255, 0}},   {329, {0, 255, 0}},   {330, {0, 0, 255}}, {386, {0, 0, 255}},
        {387, {0, 255, 0}},   {444, {0, 255, 0}},   {445, {0, 0, 255}}, {511, {0, 0, 255}},
        {512, {255, 0, 0}},   {744, {255, 0, 0}},   {745, {0, 0, 0}},   {799, {0, 0, 0}},
    };
    for (size_t i = 0; i < sizeof COLUMNS / sizeof COLUMNS[0]; i++) {
        expect_pixel(&im, COLUMNS[i].x, 0, COLUMNS[i].c, "top row");
        expect_pixel(&im, COLUMNS[i].x, RENDER_HEIGHT - 1, COLUMNS[i].c, "bottom row");
    }
    expect_image(&im, GROUP, "default_render");
    image_free(&im);
    ybuffer_free(&yb);
    free(segs);
}

/* Grey = 48 + 207 (y - 34) / (463 - 34), rounded: the scale runs from the
 * farthest y on screen, red's left end R(20) = 34, to the nearest, blue's left
 * end B(330) = 463. */
static void ybuffer_strip_is_brightest_where_nearest(void **state)
{
    (void)state;
    YBuffer yb;
    int count;
    Segment *segs = draw_default(&yb, &count);
    GreyScale scale = grey_scale_of(segs, count, WIDTH);
    assert_int_equal(scale.nearest, 463);
    assert_int_equal(scale.farthest, 34);
    Image im;
    Error err;
    assert_true(ybuffer_picture(&yb, scale, RENDER_HEIGHT, &im, &err));
    expect_pixel(&im, 0, 0, DEPTH_BACKGROUND, "cleared column");
    expect_pixel(&im, 799, RENDER_HEIGHT - 1, DEPTH_BACKGROUND, "cleared column");
    expect_pixel(&im, 20, 0, grey(48), "y = 34, the farthest");
    expect_pixel(&im, 330, 0, grey(255), "y = 463, the nearest");
    expect_pixel(&im, 120, 0, grey(241), "y = 434: 48 + 207*400/429 = 241.0");
    expect_pixel(&im, 744, 0, grey(225), "y = 400: 48 + 207*366/429 = 224.6");
    expect_image(&im, GROUP, "default_ybuffer");
    image_free(&im);
    ybuffer_free(&yb);
    free(segs);
}

/* The scene is flipped in world_to_row only: world y = 0 is the bottom row. */
static void scene_puts_world_y_up(void **state)
{
    (void)state;
    assert_int_equal(world_to_row(0), SCENE_HEIGHT - 1);
    assert_int_equal(world_to_row(SCENE_HEIGHT - 1), 0);
    assert_int_equal(world_to_row(34), 465);

    YBuffer yb;
    int count;
    Segment *segs = draw_default(&yb, &count);
    Image im;
    Error err;
    assert_true(scene_picture(segs, count, &yb, &im, &err));
    expect_count(WIDTH, im.width, "picture width");
    expect_count(SCENE_HEIGHT, im.height, "picture height");
    /* Red's left end (20, 34) at row 499 - 34 = 465, one pixel thicker above and below. */
    expect_pixel(&im, 20, 464, RED, "red's left end, thickened");
    expect_pixel(&im, 20, 465, RED, "red's left end");
    expect_pixel(&im, 20, 466, RED, "red's left end, thickened");
    expect_pixel(&im, 20, 467, BLACK, "below red");
    expect_pixel(&im, 19, 465, BLACK, "left of red");
    /* Green at x = 201: y = 425.5 -> 426, row 73: the very point the walk tests. */
    expect_pixel(&im, 201, 73, GREEN, "green at x = 201");
    /* Blue's upper end (330, 463), row 36. */
    expect_pixel(&im, 330, 36, BLUE, "blue's upper end");
    /* The screen band, world y 487..490 = rows 9..12, shows the render. */
    for (int row = 9; row <= 12; row++) {
        expect_pixel(&im, 0, row, SCREEN_EMPTY, "screen, nothing won");
        expect_pixel(&im, 20, row, RED, "screen, red's column");
        expect_pixel(&im, 387, row, GREEN, "screen, the tie column");
        expect_pixel(&im, 386, row, BLUE, "screen, blue's column");
    }
    expect_pixel(&im, 700, 8, BLACK, "above the screen band");
    expect_pixel(&im, 700, 13, BLACK, "below the screen band");
    expect_image(&im, GROUP, "default_scene");
    image_free(&im);
    ybuffer_free(&yb);
    free(segs);
}

/* A steep segment is drawn one pixel per world row, so it has no gaps:
 * (10,0)-(12,100) has x = 10 + 2y/100 rounded, x(50) = 11, x(25) = 10.5 -> 11. */
static void steep_scene_line_has_no_gaps(void **state)
{
    (void)state;
    const Segment steep = {10, 0, 12, 100, {255, 255, 255}};
    YBuffer yb;
    Error err;
    assert_true(ybuffer_init(&yb, WIDTH, &err));
    Image im;
    assert_true(scene_picture(&steep, 1, &yb, &im, &err));
    const Rgb WHITE = {255, 255, 255};
    for (int y = 0; y <= 100; y++) {
        int x = y < 25 ? 10 : y < 75 ? 11 : 12;
        expect_pixel(&im, x, world_to_row(y), WHITE, "steep line, centre");
    }
    expect_pixel(&im, 11, world_to_row(25), WHITE, "x(25) = 10.5 -> 11");
    expect_pixel(&im, 12, world_to_row(101), BLACK, "past the upper end");
    image_free(&im);
    ybuffer_free(&yb);
}

/* A line a million pixels long each way is clipped, not walked. */
static void scene_line_is_clipped_to_the_picture(void **state)
{
    (void)state;
    const Segment wide = {-COORD_LIMIT, 250, COORD_LIMIT, 250, {255, 255, 255}};
    const Segment tall = {400, -COORD_LIMIT, 401, COORD_LIMIT, {255, 255, 255}};
    YBuffer yb;
    Error err;
    assert_true(ybuffer_init(&yb, WIDTH, &err));
    Image im;
    assert_true(scene_picture(&wide, 1, &yb, &im, &err));
    for (int x = 0; x < WIDTH; x++)
        expect_pixel(&im, x, world_to_row(250), (Rgb){255, 255, 255}, "wide line");
    image_free(&im);
    assert_true(scene_picture(&tall, 1, &yb, &im, &err));
    /* x = 400 + (y + 1e6) / 2e6: 400.5 at y = 0 -> 401, 400.50025 at y = 499 -> 401 */
    expect_pixel(&im, 401, world_to_row(0), (Rgb){255, 255, 255}, "tall line at y = 0");
    expect_pixel(&im, 401, world_to_row(499), (Rgb){255, 255, 255}, "tall line at the top");
    image_free(&im);
    ybuffer_free(&yb);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(render_shows_the_runs_on_every_row),
        cmocka_unit_test(ybuffer_strip_is_brightest_where_nearest),
        cmocka_unit_test(scene_puts_world_y_up),
        cmocka_unit_test(steep_scene_line_has_no_gaps),
        cmocka_unit_test(scene_line_is_clipped_to_the_picture),
    };
    return cmocka_run_group_tests_name("01_ybuffer: pictures", tests, NULL, NULL);
}
