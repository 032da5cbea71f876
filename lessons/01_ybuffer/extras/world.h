/* world.h: the segments lesson 01 draws, where they come from, and the report
 * of who won which columns.
 *
 * A segments file has one segment per line, seven integers
 *     x0 y0 x1 y1 r g b
 * (endpoints in the world, |v| <= COORD_LIMIT; colour channels 0..255).
 * Blank lines and everything after a '#' are ignored. Any other line is an
 * error that names the file and the line. */
#ifndef WORLD_H
#define WORLD_H

#include <stddef.h>
#include <stdio.h>

#include "error.h"
#include "ybuffer.h"

#define SEGMENT_FIELDS 7
/* A segments file larger than this is refused (about 70 000 segments). */
#define SEGMENTS_MAX_BYTES ((size_t)1 << 20)
#define SEGMENT_NAME_MAX 16

/* The scene of the lesson: red, green and blue, as in tinyrenderer's lesson 3.
 * *segs is allocated; the caller frees it. */
bool default_segments(Segment **segs, int *count, Error *err);

/* Parses a whole segments file held in text (len bytes; NULs and other
 * control bytes are refused); source names it in messages ("segments.txt:3: ..."). */
bool parse_segments(const char *text, size_t len, const char *source,
                    Segment **segs, int *count, Error *err);
bool read_segments(const char *path, Segment **segs, int *count, Error *err);

/* --order: a permutation of 1..count, as digits ("312") or separated by
 * commas ("3,1,2"). order[k] becomes the index (from 0) of the k-th segment to
 * draw. Without --order (s == NULL) the segments are drawn as listed. */
bool parse_order(const char *s, int count, int *order, Error *err);

/* "red", "green", ... for the plain colours, "#rrggbb" otherwise. */
void segment_name(Rgb c, char name[SEGMENT_NAME_MAX]);

/* One line per segment with the columns it won, as runs ("20-119, 512-744"),
 * then the columns nobody won and the column tests made. */
void print_summary(FILE *out, const YBuffer *yb, const Segment *segs, int count,
                   const int *order);

#endif
