/* ybuffer.h: lesson 01, the depth test in one dimension.
 *
 * The world is a flat 2-D plane seen from above; the screen is one row of
 * pixels along x. Each segment is walked column by column, its y interpolated
 * at every integer x and rounded, and a column keeps the nearest y seen so far:
 * a larger y is nearer the viewer. That array of one int per column is the
 * y-buffer, the 1-D ancestor of the z-buffer (docs/01_ybuffer.md).
 *
 * Conventions (docs/conventions.md, the row of lesson 01):
 *   stored value   the rounded y of the segment that won the column
 *   cleared to     YBUFFER_CLEARED (INT_MIN): every y is nearer than that
 *   a fragment wins when  its y is nearer (strict: on a tie the first drawn stays)
 *   interpolation  linear along x, rounded to the nearest integer, halves up */
#ifndef YBUFFER_H
#define YBUFFER_H

#include <limits.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "error.h"
#include "image.h"
#include "fragments.h"

/* "Nothing seen here yet": smaller than any y a segment can bring. */
#define YBUFFER_CLEARED INT_MIN
/* The owner of a column no segment has won. */
#define NO_SEGMENT (-1)
/* Endpoints are integers with |x|, |y| <= COORD_LIMIT, so that
 * (y1 - y0) * (x - x0) stays far inside 64 bits and every y far above INT_MIN. */
#define COORD_LIMIT 1000000

typedef struct {
    int x0, y0, x1, y1; /* endpoints in the world, y larger = nearer */
    Rgb colour;
} Segment;

typedef struct {
    int width;          /* columns of the screen */
    int *y;             /* the y-buffer: nearest y seen per column */
    int *owner;         /* the segment that won each column (index), NO_SEGMENT if none */
    FragmentStats stats; /* column tests made, passed, failed */
    TraceLog trace;      /* --trace: every test made at one column (fragments.h) */
} YBuffer;

/* The buffer of width columns, not yet cleared (clear_ybuffer does that). */
bool ybuffer_init(YBuffer *yb, int width, Error *err);
void ybuffer_free(YBuffer *yb);

/* Step 1: every column back to "nothing seen", no owner, counts to zero. */
void clear_ybuffer(YBuffer *yb);

/* --trace X: log every test made at column x from now on. */
void ybuffer_trace_column(YBuffer *yb, int x);

/* A stored y as the trace shows it: a cleared column holds minus infinity. */
static inline float y_as_stored(int y)
{
    return y == YBUFFER_CLEARED ? -INFINITY : (float)y;
}

/* floor(p / q + 1/2) for q > 0: p / q rounded to the nearest integer, halves
 * up (2.5 -> 3, -2.5 -> -2), in exact integer arithmetic. */
int64_t round_half_up(int64_t p, int64_t q);

/* Step 2: the segment's y at column x (x between its ends): the y of the
 * line through its ends there, rounded halves up. A vertical segment
 * (x0 == x1) shows only its nearest point. */
int segment_y_at(const Segment *s, int x);

/* Step 3: the depth test. Nearer means larger y, and a tie keeps what was
 * drawn first (docs/conventions.md). */
static inline bool depth_test(int y, int stored)
{
    /* SOLUTION BEGIN: the depth test: does a segment at y hide what the
     * column holds (stored)? A larger y is nearer; a tie keeps what was
     * drawn first. */
    return y > stored;
    /* SOLUTION STUB
    (void)y; (void)stored;
    return false;
    */
    /* SOLUTION END */
}

/* Step 4: walk the segment over every column from its left end to its right
 * end, both included, clipped to the screen [0, width); where the depth test
 * passes, the column takes this segment (index) and stores its y. */
void draw_segment(YBuffer *yb, const Segment *s, int index);

#endif
