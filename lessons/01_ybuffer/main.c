/* main.c: lesson 01, the depth test in one dimension (docs/01_ybuffer.md).
 *
 * Segments of a flat 2-D world, seen from above, are drawn into one row of
 * pixels. Each column keeps the nearest y seen so far, in the y-buffer, so the
 * picture no longer depends on the order the segments are drawn in.
 *
 * The outline of the program. What the lesson teaches is in ybuffer.c; the
 * rest (the command line, the segments, the pictures and the tools) is in
 * extras/row.c. */
#include "extras/row.h"
#include "ybuffer.h"

int main(int argc, char **argv)
{
    Row row;
    int status = row_load(&row, argc, argv);    /* load: the command line, the segments */
    if (status != ROW_GO)
        return status;
    clear_ybuffer(&row.yb);                      /* clear: every column "nothing seen" */
    bool ok = row_step(&row, 0);                 /* --steps: the cleared buffer */
    for (int k = 0; ok && k < row.count; k++) {  /* draw: each segment in turn */
        int s = row.order[k];
        draw_segment(&row.yb, &row.segs[s], s);
        ok = row_step(&row, k + 1);
    }
    if (ok && row_write(&row))                   /* write: the pictures asked for */
        row_report(&row);                        /* report: who won which columns */
    return row_end(&row);
}
