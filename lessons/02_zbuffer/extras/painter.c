/* painter.c: the painter's algorithm (see painter.h). */
#include "painter.h"

#include <stdlib.h>

#include "bugs.h"

typedef struct {
    double mean_depth;
    int face;
} SortKey;

/* Farthest first; a tie keeps mesh order, so the result does not depend on qsort. */
static int farther_first(const void *a, const void *b)
{
    const SortKey *p = a, *q = b;
    if (p->mean_depth != q->mean_depth)
        return p->mean_depth > q->mean_depth ? -1 : 1;
    return (p->face > q->face) - (p->face < q->face);
}

static double mean_depth(const Render *r, int i)
{
    ScreenFace f = render_screen_face(r, i);
    double sum = 0;
    for (int k = 0; k < f.n; k++)
        sum += f.v[k].d;
    return sum / f.n;
}

void painter_order(const Render *r, int *order)
{
    int n = r->mesh.nfaces;
    SortKey *keys = malloc((n > 0 ? (size_t)n : 1) * sizeof *keys);
    for (int i = 0; i < n; i++) {
        if (keys) {
            keys[i].mean_depth = mean_depth(r, i);
            keys[i].face = i;
        }
        order[i] = i; /* out of memory: mesh order */
    }
    if (!keys)
        return;
    qsort(keys, (size_t)n, sizeof *keys, farther_first);
    for (int i = 0; i < n; i++)
        order[i] = keys[i].face;
    free(keys);
}

/* The painter has no depth buffer. Our rasterizer always tests depth, so each
 * face gets a freshly cleared buffer of its own (draw_in_own_buffers, one face
 * per group): every fragment passes, and the face painted last wins. A face's
 * own triangles never overlap (the fill rule), so that is exactly painting. */
bool draw_painter(Render *r, Target *t, const Rasterizer *rz, Error *err)
{
    int n = r->mesh.nfaces;
    int *order = malloc((n > 0 ? (size_t)n : 1) * sizeof *order);
    int *group = malloc((n > 0 ? (size_t)n : 1) * sizeof *group);
    bool ok = order && group;
    if (!ok)
        error_set(err, "out of memory sorting %d faces", n);
    if (ok) {
        painter_order(r, order);
        for (int k = 0; k < n; k++)
            group[k] = k; /* every face alone */
        ok = draw_in_own_buffers(r, t, rz, order, group, n, err);
    }
    free(order);
    free(group);
    return ok;
}
