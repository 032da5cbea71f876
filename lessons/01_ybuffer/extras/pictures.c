/* pictures.c: the render, the y-buffer strip and the scene from above. */
#include "pictures.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/file.h"
#include "harness/steps.h"

const Rgb RENDER_BACKGROUND = {0, 0, 0};
const Rgb SCREEN_EMPTY = {64, 64, 64};

/* The grey scale of every depth picture of the series (image.h depth_to_grey):
 * nearest white, farthest a dark grey that still differs from black. */
#define GREY_NEAR 255
#define GREY_FAR 48

static void fill_column(Image *im, int x, Rgb c)
{
    for (int row = 0; row < im->height; row++)
        image_set(im, x, row, c);
}

bool render_picture(const YBuffer *yb, const Segment *segs, int height, Image *out, Error *err)
{
    if (!image_init(out, yb->width, height, err))
        return false;
    for (int x = 0; x < yb->width; x++) {
        int who = yb->owner[x];
        fill_column(out, x, who == NO_SEGMENT ? RENDER_BACKGROUND : segs[who].colour);
    }
    return true;
}

GreyScale grey_scale_of(const Segment *segs, int count, int width)
{
    GreyScale scale = {0, 0};
    bool any = false;
    for (int i = 0; i < count; i++) {
        const Segment *s = &segs[i];
        int left = s->x0 < s->x1 ? s->x0 : s->x1;
        int right = s->x0 < s->x1 ? s->x1 : s->x0;
        left = left < 0 ? 0 : left;
        right = right > width - 1 ? width - 1 : right;
        if (left > right)
            continue; /* off screen */
        int ends[2] = {segment_y_at(s, left), segment_y_at(s, right)};
        for (int e = 0; e < 2; e++) {
            scale.nearest = any && scale.nearest > ends[e] ? scale.nearest : ends[e];
            scale.farthest = any && scale.farthest < ends[e] ? scale.farthest : ends[e];
            any = true;
        }
    }
    return scale;
}

bool ybuffer_picture(const YBuffer *yb, GreyScale scale, int height, Image *out, Error *err)
{
    if (!image_init(out, yb->width, height, err))
        return false;
    int64_t range = (int64_t)scale.nearest - scale.farthest;
    for (int x = 0; x < yb->width; x++) {
        int y = yb->y[x];
        if (y == YBUFFER_CLEARED) {
            fill_column(out, x, DEPTH_BACKGROUND);
            continue;
        }
        /* grey = GREY_FAR + (GREY_NEAR - GREY_FAR) * (y - farthest) / (nearest - farthest),
         * rounded: linear in y, the nearest (largest) y white. */
        int64_t grey = GREY_NEAR;
        if (range > 0)
            grey = GREY_FAR + round_half_up((int64_t)(GREY_NEAR - GREY_FAR) *
                                                ((int64_t)y - scale.farthest), range);
        grey = grey < GREY_FAR ? GREY_FAR : grey > GREY_NEAR ? GREY_NEAR : grey;
        Rgb c = {(uint8_t)grey, (uint8_t)grey, (uint8_t)grey};
        fill_column(out, x, c);
    }
    return true;
}

int world_to_row(int y)
{
    return SCENE_HEIGHT - 1 - y; /* world y up, picture rows down */
}

static void plot_world(Image *im, int x, int y, Rgb c)
{
    int row = world_to_row(y);
    if (x >= 0 && x < im->width && row >= 0 && row < im->height)
        image_set(im, x, row, c);
}

/* A one-pixel line is hard to see at 800x500: each point of a line is drawn
 * LINE_HALF_WIDTH pixels thicker on both sides, across the line's direction. */
#define LINE_HALF_WIDTH 1

static void plot_thick(Image *im, int x, int y, bool across_is_y, Rgb c)
{
    for (int d = -LINE_HALF_WIDTH; d <= LINE_HALF_WIDTH; d++)
        plot_world(im, across_is_y ? x : x + d, across_is_y ? y + d : y, c);
}

/* A line drawer (DDA with exact rounding): one pixel per step along the longer
 * axis. Along x it uses the very y the column walk computes (segment_y_at), so
 * the picture shows exactly the points the y-buffer tests. The range is clipped
 * to the picture before walking. */
static void draw_world_line(Image *im, const Segment *s)
{
    int dx = abs(s->x1 - s->x0), dy = abs(s->y1 - s->y0);
    if (dx >= dy) {
        int left = s->x0 < s->x1 ? s->x0 : s->x1;
        int right = s->x0 < s->x1 ? s->x1 : s->x0;
        if (left < 0)
            left = 0;
        if (right > im->width - 1)
            right = im->width - 1;
        for (int x = left; x <= right; x++) /* the thickness runs along y */
            plot_thick(im, x, segment_y_at(s, x), true, s->colour);
    } else {
        /* Steep: one pixel per world row, x = x0 + (x1 - x0) * (y - y0) / (y1 - y0). */
        int x0 = s->x0, y0 = s->y0, x1 = s->x1, y1 = s->y1;
        if (y0 > y1) {
            x0 = s->x1; y0 = s->y1;
            x1 = s->x0; y1 = s->y0;
        }
        int bottom = y0 < 0 ? 0 : y0;
        int top = y1 > SCENE_HEIGHT - 1 ? SCENE_HEIGHT - 1 : y1;
        for (int y = bottom; y <= top; y++) { /* the thickness runs along x */
            int64_t x = x0 + round_half_up((int64_t)(x1 - x0) * (y - y0), (int64_t)y1 - y0);
            plot_thick(im, (int)x, y, false, s->colour);
        }
    }
}

bool scene_picture(const Segment *segs, int count, const YBuffer *yb, Image *out, Error *err)
{
    if (!image_init(out, yb->width, SCENE_HEIGHT, err))
        return false;
    for (int i = 0; i < count; i++)
        draw_world_line(out, &segs[i]);
    /* The screen, seen edge-on from above: each column shows what it rendered. */
    for (int x = 0; x < yb->width; x++) {
        int who = yb->owner[x];
        Rgb c = who == NO_SEGMENT ? SCREEN_EMPTY : segs[who].colour;
        for (int y = SCREEN_Y - SCREEN_THICKNESS + 1; y <= SCREEN_Y; y++)
            plot_world(out, x, y, c);
    }
    return true;
}

bool write_picture(const Image *im, const char *path, Error *err)
{
    const char *slash = strrchr(path, '/');
    if (slash && slash != path) {
        size_t n = (size_t)(slash - path);
        char *dir = malloc(n + 1);
        if (!dir)
            return error_set(err, "cannot write %s: out of memory", path);
        memcpy(dir, path, n);
        dir[n] = '\0';
        bool ok = make_dirs(dir, err);
        free(dir);
        if (!ok)
            return false;
    }
    return image_write_png(im, path, err);
}

bool write_step_pictures(const YBuffer *yb, const Segment *segs, GreyScale scale, int height,
                         const char *dir, int step, Error *err)
{
    Image render, strip;
    if (!render_picture(yb, segs, height, &render, err))
        return false;
    bool ok = ybuffer_picture(yb, scale, height, &strip, err);
    if (ok) {
        ok = steps_write(dir, step, &render, &strip, err); /* common/harness/steps.h */
        image_free(&strip);
    }
    image_free(&render);
    return ok;
}
