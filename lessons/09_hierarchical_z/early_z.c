/* early_z.c: lesson 08, where the fragment shader runs (early_z.h): lesson 07
 * draws and tests each face, extras/ hands each fragment to fragment(). */
#include "early_z.h"

#include <stdlib.h>

#include "extras/extras.h"

/* A cutout's holes: squares of 4 x 4 pixels, every other one kept. */
bool cutout_keeps(int x, int y)
{
    return (((x >> 2) ^ (y >> 2)) & 1) == 0;
}

static void run_shader(EarlyZ *z, size_t i, Rgb lit, int x, int y, bool write)
{
    Rgb c = shade_fragment(lit, x, y);
    z->shaded++, z->shade_count[i]++;
    if (write)
        z->colour[i] = c;
}

/* Lesson 07's test just passed (won) or not; saved_*: pixel i before it. */
void fragment(EarlyZ *z, Target *t, size_t i, int x, int y, int face, bool cutout, Rgb lit)
{
    bool won = t->face[i] == face, kept = !cutout || cutout_keeps(x, y);
    if (z->pass == 2) {
        t->depth[i] = z->saved_depth[i];
        t->face[i] = z->saved_face[i];
        z->tested++;
        if (z->saved_face[i] == face)
            run_shader(z, i, lit, x, y, true);
    } else if (z->pass == 1 || z->mode == Z_LATE || (cutout && !z->bug_discard)) {
        if (z->pass != 1)
            run_shader(z, i, lit, x, y, won && kept);
        if (!kept && won) {
            t->depth[i] = z->saved_depth[i];
            t->face[i] = z->saved_face[i];
        }
        z->tested += kept;
    } else {
        z->tested++;
        if (won)
            run_shader(z, i, lit, x, y, kept);
        if (won && !kept) /* --bug: the discard comes too late, the depth stays */
            t->face[i] = z->saved_face[i];
    }
}

/* Every face in --sort's order; a prepass draws them all twice. */
bool draw_scene(Run *run, Error *err)
{
    Render *r = &run->render;
    Target *t = &run->target;
    EarlyZ *z = (EarlyZ *)t->depth_setup;
    int n = r->mesh.nfaces, *order = malloc((size_t)(n > 0 ? n : 1) * sizeof *order);
    if (!order)
        return error_set(err, "out of memory for the order of %d faces", n);
    sort_faces(r, z->sort, order);
    z->pass = z->mode == Z_PREPASS ? 1 : 0;
    bool ok = render_faces(r, t, run->rz, order, n, inspect_after_face, &run->inspection, err);
    if (ok && z->mode == Z_PREPASS) {
        FaceCounts once = r->counts; /* the summary counts each face once */
        z->pass = 2;
        ok = render_faces(r, t, run->rz, order, n, NULL, NULL, err);
        r->counts = once;
    }
    for (size_t i = 0; i < (size_t)t->width * (size_t)t->height; i++)
        z->covered += t->face[i] != NO_FACE;
    free(order);
    return ok;
}
