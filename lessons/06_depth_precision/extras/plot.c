/* plot.c: the precision plot (see plot.h). */
#include "plot.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "depth_format.h"
#include "extras.h"
#include "harness/font.h"
#include "harness/image_io.h"
#include "harness/ladder.h"
#include "harness/render.h"

#define PICTURE_W 900
#define PICTURE_H 600
#define LEFT 80 /* the chart's box inside the picture */
#define RIGHT 700
#define TOP 40
#define BOTTOM 540
#define FAR_IF_INFINITE 1e4 /* x axis end when far is infinite: 10^5 near */

typedef struct {
    double lx0, lx1, ly0, ly1; /* log10 of the axes' ends */
} Axes;

static int to_x(const Axes *a, double d)
{
    return LEFT + (int)lround((log10(d) - a->lx0) / (a->lx1 - a->lx0) * (RIGHT - LEFT));
}

static int to_y(const Axes *a, double step)
{
    return BOTTOM - (int)lround((log10(step) - a->ly0) / (a->ly1 - a->ly0) * (BOTTOM - TOP));
}

static void dot(Image *im, int x, int y, int r, Rgb c)
{
    for (int dy = -r; dy <= r; dy++)
        for (int dx = -r; dx <= r; dx++)
            if (x + dx >= 0 && x + dx < im->width && y + dy >= 0 && y + dy < im->height)
                image_set(im, x + dx, y + dy, c);
}

/* A line of dots from (x0, y0) to (x1, y1); dashed skips every other 6 pixels. */
static void line(Image *im, int x0, int y0, int x1, int y1, int r, Rgb c, bool dashed)
{
    int n = abs(x1 - x0) > abs(y1 - y0) ? abs(x1 - x0) : abs(y1 - y0);
    for (int i = 0; i <= n; i++) {
        if (dashed && (i / 6) % 2)
            continue;
        double t = n ? (double)i / n : 0;
        dot(im, (int)lround(x0 + t * (x1 - x0)), (int)lround(y0 + t * (y1 - y0)), r, c);
    }
}

/* Every how many decades a grid line and label goes, so that labels at
 * least min_gap pixels apart fit in length pixels: 1 but for a huge range
 * (a near plane of 1e-200 spans 203 decades). */
static int decade_stride(double l0, double l1, int length, int min_gap)
{
    double per = (l1 - l0) * min_gap / length;
    return per <= 1 ? 1 : (int)ceil(per);
}

static bool on_stride(int e, int stride)
{
    return ((e % stride) + stride) % stride == 0;
}

static void axes(Image *im, const Axes *a)
{
    const Rgb grid = {225, 225, 225}, ink = {0, 0, 0};
    char label[32];
    int sx = decade_stride(a->lx0, a->lx1, RIGHT - LEFT, 48);
    int sy = decade_stride(a->ly0, a->ly1, BOTTOM - TOP, 14);
    for (int e = (int)ceil(a->lx0); e <= (int)floor(a->lx1); e++) {
        if (!on_stride(e, sx))
            continue;
        int x = to_x(a, pow(10, e));
        line(im, x, TOP, x, BOTTOM, 0, grid, false);
        snprintf(label, sizeof label, "%g", pow(10, e));
        draw_text(im, x - text_width(label) / 2, BOTTOM + 6, label, ink);
    }
    for (int e = (int)ceil(a->ly0); e <= (int)floor(a->ly1); e++) {
        if (!on_stride(e, sy))
            continue;
        int y = to_y(a, pow(10, e));
        line(im, LEFT, y, RIGHT, y, 0, grid, false);
        snprintf(label, sizeof label, "1e%d", e);
        draw_text(im, LEFT - 6 - text_width(label), y - 3, label, ink);
    }
    line(im, LEFT, BOTTOM, RIGHT, BOTTOM, 0, ink, false);
    line(im, LEFT, TOP, LEFT, BOTTOM, 0, ink, false);
    draw_text(im, (LEFT + RIGHT) / 2 - 90, BOTTOM + 22, "view distance d (world units)", ink);
    draw_text(im, 8, TOP - 24, "depth step: smallest difference in d the buffer tells apart",
              ink);
    draw_text(im, 8, TOP - 12, "(world units, log scale)", ink);
}

/* A step the log axis can show: finite and above 0. Near 1e-200 a step
 * underflows to 0, whose log10 is -inf: such a point is left out. */
static bool plottable(double step)
{
    return isfinite(step) && step > 0;
}

bool precision_plot(const char *path, double near, double far, Error *err)
{
    static const Rgb COLOUR[3] = {{240, 130, 0}, {60, 150, 255}, {220, 0, 140}};
    static const int WIDTH[3] = {1, 3, 1}; /* unorm24 wide: float32 standard runs on it */
    double x_end = isinf(far) ? FAR_IF_INFINITE : far;
    Axes a = {log10(near), log10(x_end), INFINITY, -INFINITY};
    for (int f = 0; f < 3; f++) /* the y axis: every curve's range, in whole decades */
        for (int m = 0; m < 3; m++) {
            if (m != REVERSED && isinf(far))
                continue;
            DepthSetup s = depth_setup((DepthFormat)f, (DepthMapping)m, near, far);
            for (int x = LEFT; x <= RIGHT; x++) {
                double d = pow(10, a.lx0 + (a.lx1 - a.lx0) * (x - LEFT) / (RIGHT - LEFT));
                double step = depth_step(&s, d);
                if (!plottable(step))
                    continue;
                a.ly0 = fmin(a.ly0, floor(log10(step)));
                a.ly1 = fmax(a.ly1, ceil(log10(step)));
            }
        }
    if (!(a.ly0 < a.ly1)) /* no point to show: one decade, 0.1 to 1 */
        a.ly0 = -1, a.ly1 = 0;
    Image im;
    if (!image_init(&im, PICTURE_W, PICTURE_H, err))
        return false;
    image_fill(&im, (Rgb){255, 255, 255});
    axes(&im, &a);
    int gy = to_y(&a, LADDER_GAP), ly = TOP + 10;
    line(&im, LEFT, gy, RIGHT, gy, 0, (Rgb){0, 0, 0}, true);
    draw_text(&im, LEFT + 8, gy - 12, "the ladder's gap: 0.05", (Rgb){0, 0, 0});
    for (int m = 0; m < 3; m++)
        for (int f = 0; f < 3; f++) {
            char label[48];
            Rgb c = COLOUR[f];
            if (m == REVERSED) /* darker, dashed, over the standard curve */
                c = (Rgb){(uint8_t)(c.r / 2), (uint8_t)(c.g / 2), (uint8_t)(c.b / 2)};
            snprintf(label, sizeof label, "%s %s%s", format_name((DepthFormat)f),
                     mapping_name((DepthMapping)m),
                     m == REVERSED && f != FLOAT32 ? " (same)" : "");
            if (m != REVERSED && isinf(far)) {
                snprintf(label, sizeof label, "%s %s: no far", format_name((DepthFormat)f),
                         mapping_name((DepthMapping)m));
            } else {
                DepthSetup s = depth_setup((DepthFormat)f, (DepthMapping)m, near, far);
                int px = -1, py = 0;
                for (int x = LEFT; x <= RIGHT; x++) {
                    double d = pow(10, a.lx0 + (a.lx1 - a.lx0) * (x - LEFT) / (RIGHT - LEFT));
                    double step = depth_step(&s, d);
                    if (!plottable(step)) { /* a gap in the curve */
                        px = -1;
                        continue;
                    }
                    int y = to_y(&a, step);
                    if (m == LOGARITHMIC && x % 10 == 0) /* dots */
                        dot(&im, x, y, WIDTH[f] + 1, c);
                    if (px >= 0 && (m == STANDARD || (m == REVERSED && (x / 8) % 2 == 0)))
                        line(&im, px, py, x, y, WIDTH[f], c, false);
                    px = x, py = y;
                }
            }
            if (m == LOGARITHMIC)
                for (int x = RIGHT + 14; x <= RIGHT + 40; x += 10)
                    dot(&im, x, ly + 3, WIDTH[f] + 1, c);
            else
                line(&im, RIGHT + 12, ly + 3, RIGHT + 40, ly + 3, WIDTH[f], c, m == REVERSED);
            draw_text(&im, RIGHT + 46, ly, label, c);
            ly += 2 * FONT_LINE_HEIGHT;
        }
    char range[64];
    snprintf(range, sizeof range, "near %g, far %g", near, far);
    draw_text(&im, RIGHT + 12, ly + 8, range, (Rgb){0, 0, 0});
    bool ok = render_make_parent_dirs(path, err) && image_write_png(&im, path, err);
    image_free(&im);
    return ok;
}
