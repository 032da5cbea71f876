/* test_clip_diagram.c: the page's diagram of the four clipping cases
 * (docs/images/05_clipping_cases.png, drawn by tools/diagrams) shows what
 * lesson 05's clip_to_plane keeps. The test clips the diagram's triangles
 * itself and finds, in each panel, one corner dot for each corner kept,
 * where that corner lies. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "clip.h"
#include "test_support.h"

/* The diagram's layout and triangles (tools/diagrams.c, "read by the test"). */
#define PANELS 4
#define PANEL_LEFT 20
#define PANEL_STEP 225
#define PANEL_WIDTH 215
#define PANEL_TOP 70
#define PANEL_BOTTOM 330
#define NEAR 1.0
#define X_RANGE 2.2
#define D_RANGE 4.0
#define MAX_DOTS 8
static const double TRIANGLE[PANELS][3][2] = {
    {{-1.2, 1.8}, {1.3, 2.3}, {0.1, 3.6}},
    {{-1.4, 0.4}, {1.3, 1.8}, {-0.2, 3.4}},
    {{-1.4, 0.3}, {1.5, 0.5}, {0.2, 3.0}},
    {{-1.2, 0.2}, {1.3, 0.6}, {0.1, 0.85}},
};
static const Rgb CORNER_COLOUR = {255, 120, 200};

static bool is_corner(const Image *im, int x, int y)
{
    Rgb c = image_get(im, x, y);
    return c.r == CORNER_COLOUR.r && c.g == CORNER_COLOUR.g && c.b == CORNER_COLOUR.b;
}

/* The centres of the corner dots of panel k: each dot's pixels, gathered by
 * a flood fill from its first one (the dots lie apart). */
static int dots_in_panel(const Image *im, int k, double cx[MAX_DOTS], double cy[MAX_DOTS])
{
    enum { W = 1000, H = 500 };
    static bool seen[H][W];
    static int stack[W * H][2];
    memset(seen, 0, sizeof seen);
    int left = PANEL_LEFT + PANEL_STEP * k, n = 0;
    for (int y = PANEL_TOP - 10; y < PANEL_BOTTOM + 10; y++)
        for (int x = left - 6; x < left + PANEL_WIDTH + 6; x++) {
            if (seen[y][x] || !is_corner(im, x, y))
                continue;
            double sx = 0, sy = 0;
            int count = 0, top = 0;
            seen[y][x] = true, stack[top][0] = x, stack[top++][1] = y;
            while (top > 0) {
                int u = stack[--top][0], v = stack[top][1];
                sx += u + 0.5, sy += v + 0.5, count++;
                const int step[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
                for (int s = 0; s < 4; s++) {
                    int a = u + step[s][0], b = v + step[s][1];
                    if (a >= 0 && b >= 0 && a < im->width && b < im->height && !seen[b][a] &&
                        is_corner(im, a, b))
                        seen[b][a] = true, stack[top][0] = a, stack[top++][1] = b;
                }
            }
            if (n == MAX_DOTS)
                fail_msg("panel %d: more than %d corner dots", k + 1, MAX_DOTS);
            cx[n] = sx / count, cy[n] = sy / count, n++;
        }
    return n;
}

static void clipping_diagram_shows_what_clip_to_plane_keeps(void **state)
{
    (void)state;
    const char *dir = test_dir("clip_diagram");
    const char *args[] = {dir, NULL};
    RunResult r = run_tool("diagrams", args);
    if (r.status != 0)
        fail_msg("diagrams: exit status %d: %s", r.status, r.err);
    run_result_free(&r);
    Image im = read_png(path_join(dir, "05_clipping_cases.png"));
    for (int k = 0; k < PANELS; k++) {
        /* (x, d) in view space as clip space: w = d, and z = d - 2 near puts
         * the near plane z = -w at d = near (the far plane out of reach). */
        Vec4 in[3], out[8];
        for (int i = 0; i < 3; i++)
            in[i] = vec4(TRIANGLE[k][i][0], 0, TRIANGLE[k][i][1] - 2 * NEAR, TRIANGLE[k][i][1]);
        int m = clip_to_plane(in, 3, NEAR_PLANE, out);
        double cx[MAX_DOTS], cy[MAX_DOTS];
        int dots = dots_in_panel(&im, k, cx, cy);
        observe_value("corners kept", m);
        if (dots != m)
            fail_msg("panel %d shows %d corners; clip_to_plane keeps %d", k + 1, dots, m);
        for (int i = 0; i < m; i++) {
            double x = PANEL_LEFT + PANEL_STEP * k + (out[i].x / X_RANGE + 1) / 2 * PANEL_WIDTH;
            double y = PANEL_BOTTOM - out[i].w / D_RANGE * (PANEL_BOTTOM - PANEL_TOP);
            double nearest = INFINITY;
            for (int j = 0; j < dots; j++)
                nearest = fmin(nearest, hypot(cx[j] - x, cy[j] - y));
            observe_near(nearest, 0.0, 1.0);
            if (nearest > 1.0)
                fail_msg("panel %d: clip_to_plane's corner %d, (x %.3f, d %.3f), has no dot "
                         "within a pixel (nearest %.2f away)", k + 1, i, out[i].x, out[i].w, nearest);
        }
    }
    image_free(&im);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(clipping_diagram_shows_what_clip_to_plane_keeps),
    };
    return cmocka_run_group_tests_name("05_clipping diagram", tests, NULL, NULL);
}
