/* ybuffer.c: lesson 01, the y-buffer. Read top to bottom: clear, interpolate,
 * test, walk. See ybuffer.h for the conventions and docs/01_ybuffer.md. */
#include "ybuffer.h"

#include <stdlib.h>

#include "intmath.h"

bool ybuffer_init(YBuffer *yb, int width, Error *err)
{
    TraceLog no_trace = {-1, NULL, 0, 0, false};
    yb->trace = no_trace;
    yb->width = width;
    yb->y = calloc((size_t)width, sizeof *yb->y);
    yb->owner = calloc((size_t)width, sizeof *yb->owner);
    if (!yb->y || !yb->owner) {
        ybuffer_free(yb);
        return error_set(err, "out of memory for a y-buffer of %d columns", width);
    }
    return true; /* not cleared: clear_ybuffer is step 1 */
}

void ybuffer_free(YBuffer *yb)
{
    free(yb->y);
    free(yb->owner);
    free(yb->trace.entries);
    yb->y = NULL;
    yb->owner = NULL;
    yb->trace.entries = NULL;
}

void clear_ybuffer(YBuffer *yb)
{
    for (int x = 0; x < yb->width; x++) {
        /* SOLUTION BEGIN: the value every column starts at: a y that any segment
         * is nearer than, so that the first segment drawn always wins. */
        yb->y[x] = YBUFFER_CLEARED; /* any segment is nearer than this */
        /* SOLUTION STUB
        yb->y[x] = 0;
        */
        /* SOLUTION END */
        yb->owner[x] = NO_SEGMENT;
    }
    yb->stats = (FragmentStats){0, 0, 0};
    yb->trace.count = 0;
    yb->trace.overflowed = false;
}

void ybuffer_trace_column(YBuffer *yb, int x)
{
    yb->trace.pixel = x;
}

int64_t round_half_up(int64_t p, int64_t q)
{
    /* floor(p/q + 1/2) = floor((2p + q) / 2q), all in integers. In floating
     * point an exact half can come out a hair low and round down: for the
     * segment (0,7)-(12,13) at x = 1, 7 (1 - t) + 13 t with t = 1/12 gives
     * 7.499999999999999, not 7.5. */
    return floor_div(2 * p + q, 2 * q);
}

int segment_y_at(const Segment *s, int x)
{
    /* SOLUTION BEGIN: the segment's y at column x: the y of the straight
     * line through its two ends, in exact integers (only the fraction needs
     * rounding: halves up, with round_half_up); a vertical segment shows
     * only its nearest point. */
    if (s->x0 == s->x1) /* seen from above, a vertical segment shows its nearest point */
        return s->y0 > s->y1 ? s->y0 : s->y1;
    /* Take the left end as (x0, y0), so that the denominator x1 - x0 is positive. */
    int xl = s->x0, yl = s->y0, xr = s->x1, yr = s->y1;
    if (xl > xr) {
        xl = s->x1; yl = s->y1;
        xr = s->x0; yr = s->y0;
    }
    /* y = y0 + (y1 - y0) * (x - x0) / (x1 - x0); y0 is an integer, so only the
     * fraction needs rounding. */
    int64_t num = (int64_t)(yr - yl) * (int64_t)(x - xl);
    int64_t den = (int64_t)xr - xl;
    return yl + (int)round_half_up(num, den);
    /* SOLUTION STUB
    (void)x;
    return s->y0;
    */
    /* SOLUTION END */
}

/* Counts the test, and logs it when x is the traced column (--trace): what
 * target_record does for the z-buffer. Segments are numbered from 1 there, as
 * in the summary and in --order. */
static void record_test(YBuffer *yb, int x, int index, int y, bool passed)
{
    yb->stats.tested++;
    if (passed)
        yb->stats.passed++;
    else
        yb->stats.failed++;
    if (x == yb->trace.pixel)
        trace_log_append(&yb->trace, index + 1, (float)y, y_as_stored(yb->y[x]), passed);
}

void draw_segment(YBuffer *yb, const Segment *s, int index)
{
    int left = s->x0 < s->x1 ? s->x0 : s->x1;
    int right = s->x0 < s->x1 ? s->x1 : s->x0;
    /* Clip the range first, then walk: a segment a million columns long still
     * costs at most one step per column of the screen. */
    if (left < 0)
        left = 0;
    if (right > yb->width - 1)
        right = yb->width - 1;
    for (int x = left; x <= right; x++) {
        int y = segment_y_at(s, x);            /* where the segment is in this column */
        bool nearer = depth_test(y, yb->y[x]); /* nearer than all seen here so far? */
        record_test(yb, x, index, y, nearer);  /* counted, and logged for --trace */
        /* SOLUTION BEGIN: where the depth test passes, the column keeps this
         * segment: its y, and its index as the owner (which gives the colour). */
        if (nearer) {
            yb->y[x] = y;                      /* keep its y, */
            yb->owner[x] = index;              /* and the column takes its colour */
        }
        /* SOLUTION END */
    }
}
