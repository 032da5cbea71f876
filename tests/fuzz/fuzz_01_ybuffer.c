/* fuzz_01_ybuffer.c: lesson 01 against any segments file and any --order
 * (make fuzz FUZZ=01).
 *
 * The first two bytes give the width of the row (1 to 512); the rest, up to
 * the first NUL, is a segments file, and what follows the NUL is --order.
 * Whatever the bytes, the reader either refuses them with a one-line message
 * that names the file (a bad --order gets a message too), or gives segments inside the limits of world.h. Then
 * the segments are drawn in that order, and the y-buffer must hold, in every
 * column, the largest y of the segments covering it (the first one drawn on a
 * tie), with counts that add up and a cost of at most one test per segment
 * and column, however long the segments are. The three pictures are made too
 * (render, y-buffer strip, the world from above), which must not crash on
 * segments a million units long. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pictures.h"
#include "world.h"
#include "ybuffer.h"

#define MAX_WIDTH 512
#define PICTURE_HEIGHT 4

static FILE *sink;

static void check(bool ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "fuzz_01: broken invariant: %s\n", what);
        abort();
    }
}

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    sink = fopen("/dev/null", "w");
    return sink ? 0 : 1;
}

static bool one_line(const char *msg)
{
    return msg[0] != '\0' && strchr(msg, '\n') == NULL;
}

/* Column x as the y-buffer must leave it: the largest y of the segments
 * that reach it, the first drawn of those on a tie. */
static void expected_column(const Segment *segs, const int *order, int count, int x,
                            int *y, int *owner)
{
    *y = YBUFFER_CLEARED;
    *owner = NO_SEGMENT;
    for (int k = 0; k < count; k++) {
        const Segment *s = &segs[order[k]];
        int left = s->x0 < s->x1 ? s->x0 : s->x1, right = s->x0 < s->x1 ? s->x1 : s->x0;
        if (x < left || x > right)
            continue;
        int sy = segment_y_at(s, x);
        if (sy > *y) {
            *y = sy;
            *owner = order[k];
        }
    }
}

static void check_pictures(const YBuffer *yb, const Segment *segs, int count)
{
    Image im;
    Error err;
    GreyScale scale = grey_scale_of(segs, count, yb->width);
    check(render_picture(yb, segs, PICTURE_HEIGHT, &im, &err), "render picture");
    image_free(&im);
    check(ybuffer_picture(yb, scale, PICTURE_HEIGHT, &im, &err), "y-buffer picture");
    image_free(&im);
    check(scene_picture(segs, count, yb, &im, &err), "scene picture");
    image_free(&im);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2)
        return 0;
    int width = 1 + (data[0] << 8 | data[1]) % MAX_WIDTH;
    const char *text = (const char *)data + 2;
    size_t len = size - 2;
    const char *nul = memchr(text, '\0', len);
    size_t text_len = nul ? (size_t)(nul - text) : len;
    char *order_text = NULL;
    if (nul) { /* --order: the bytes after the NUL, as a string */
        size_t n = len - text_len - 1;
        order_text = malloc(n + 1);
        if (!order_text)
            return 0;
        memcpy(order_text, nul + 1, n);
        order_text[n] = '\0';
    }

    Segment *segs = NULL;
    int count = 0, *order = NULL;
    Error err = {""};
    if (!parse_segments(text, text_len, "s.txt", &segs, &count, &err)) {
        check(one_line(err.msg) && strncmp(err.msg, "s.txt", 5) == 0,
              "a refused file gets one line naming it");
        free(order_text);
        return 0;
    }
    for (int i = 0; i < count; i++) {
        const Segment *s = &segs[i];
        check(abs(s->x0) <= COORD_LIMIT && abs(s->y0) <= COORD_LIMIT &&
                  abs(s->x1) <= COORD_LIMIT && abs(s->y1) <= COORD_LIMIT,
              "segments within COORD_LIMIT");
    }
    order = malloc(((size_t)count + 1) * sizeof *order);
    check(order != NULL, "memory for the order");
    if (!parse_order(order_text, count, order, &err)) {
        /* The message quotes --order as given, control characters too: it is
         * error_report that prints them as '?', keeping the line one line. */
        check(order_text != NULL && err.msg[0] != '\0', "a refused --order gets a message");
    } else {
        bool *seen = calloc((size_t)count + 1, 1);
        for (int k = 0; k < count; k++) {
            check(order[k] >= 0 && order[k] < count && !seen[order[k]],
                  "--order is a permutation");
            seen[order[k]] = true;
        }
        free(seen);

        YBuffer yb = {0};
        check(ybuffer_init(&yb, width, &err), "ybuffer_init");
        clear_ybuffer(&yb);
        for (int k = 0; k < count; k++)
            draw_segment(&yb, &segs[order[k]], order[k]);
        check(yb.stats.tested == yb.stats.passed + yb.stats.failed, "tested = passed + failed");
        check(yb.stats.tested <= (uint64_t)count * (uint64_t)width,
              "at most one test per segment and column");
        for (int x = 0; x < width; x++) {
            int y, owner;
            expected_column(segs, order, count, x, &y, &owner);
            check(yb.y[x] == y && yb.owner[x] == owner,
                  "each column holds the nearest segment, the first drawn on a tie");
        }
        check_pictures(&yb, segs, count);
        print_summary(sink, &yb, segs, count, order);
        ybuffer_free(&yb);
    }
    free(order);
    free(segs);
    free(order_text);
    return 0;
}
