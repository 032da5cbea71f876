/* row.h: the program around lesson 01 (main.c is its outline).
 *
 *   row_load    the command line, the segments (--segments or the lesson's
 *               three), the order to draw them in (--order), the y-buffer
 *   row_step    --steps: the render and the y-buffer after step k
 *   row_write   the render (--out), --ybuffer-out, --scene-out
 *   row_report  who won which columns; --trace, --ascii and --compare
 *   row_end     frees everything and returns the exit status */
#ifndef ROW_H
#define ROW_H

#include <stdbool.h>

#include "harness/cli.h"
#include "ybuffer.h"

#define ROW_GO (-1) /* row_load: go on drawing */

typedef struct {
    Options opt;
    Segment *segs;
    int count;
    int *order; /* order[k]: the index of the k-th segment to draw */
    YBuffer yb;
    Error err;
    int status;
} Row;

int row_load(Row *row, int argc, char **argv); /* ROW_GO or the exit status */
bool row_step(Row *row, int step);
bool row_write(Row *row);
bool row_report(Row *row);
int row_end(Row *row);

#endif
