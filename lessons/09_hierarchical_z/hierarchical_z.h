/* hierarchical_z.h: lesson 09, hierarchical Z (docs/09_hierarchical_z.md).
 *
 *   tile buffer  per tile of T x T pixels (--tile T, 8 by default): a bound
 *                on the farthest value stored in it; a triangle covering a
 *                tile whole brings it to the plane's farthest value there
 *                (--hiz-update exact: any tile drawn into is read again)
 *   skipped      a tile where the triangle's nearest value is farther than
 *                the tile's farthest: no fragment there could pass (tiles.c) */
#ifndef HIERARCHICAL_Z_H
#define HIERARCHICAL_Z_H

#include "depth_buffer.h"

typedef struct HierarchicalZ {
    int tile, tiles_x, tiles_y; /* tile side in pixels; tiles across and down */
    float *far;                 /* per tile: the farthest value stored in it, or a bound */
    unsigned *skipped_at;       /* per tile: the triangles skipped there (for a picture) */
    bool exact;                 /* --hiz-update exact: every tile drawn into read again */
    bool count_skipped;         /* count the fragments of skipped tiles (the summary) */
    unsigned long long tiles_tested, tiles_skipped, fragments_skipped, faces_skipped;
} HierarchicalZ;

/* The steps, in the order hierarchical_z.c takes them (each is explained there). */
bool hiz_begin(HierarchicalZ *h, const Target *t, int tile, Error *err); /* t's tiles */
void hiz_read_tile(HierarchicalZ *h, const DepthSetup *s, const Target *t, int tile);
void hiz_clear(Target *t, LessonState *s);                   /* clear_depth, every tile too */
float hiz_bound(const Primitive *p, int x0, int y0, int x1, int y1, bool nearest); /* plane's */
bool hiz_skips(HierarchicalZ *h, const DepthSetup *s, int tile, float nearest);
void hiz_covered(HierarchicalZ *h, const DepthSetup *s, int tile, float farthest);
void hiz_free(HierarchicalZ *h);

/* Lesson 07's faces (decals biased) drawn by tiles.c, with the tile buffer. */
extern const Rasterizer HIERARCHICAL_ZBUFFER;

#endif
