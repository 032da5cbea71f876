/* fragments.c: lesson 08's plumbing, shown but not taught: the order of
 * --sort (a qsort by each face's mean d), the two passes of the prepass
 * (pass 1, then pass 2: early_z.c's fragment() does what each means), and
 * the shader's buffers. */
#include "extras.h"

#include <stdlib.h>

#include "harness/shade.h"
#include "state.h"

typedef struct { double d; int face; } Key;

static int nearer_first(const void *a, const void *b)
{
    const Key *p = a, *q = b;
    return p->d < q->d ? -1 : p->d > q->d ? 1 : p->face - q->face;
}

/* By the face's centre: the mean view depth d of its corners. */
void sort_faces(const Render *r, SortOrder sort, int *order)
{
    int n = r->mesh.nfaces;
    Key *keys = sort == SORT_NONE ? NULL : malloc((size_t)(n > 0 ? n : 1) * sizeof *keys);
    for (int f = 0; f < n; f++)
        order[f] = f; /* mesh order (also out of memory: the same picture) */
    for (int f = 0; keys && f < n; f++) {
        const Face *face = &r->mesh.faces[f];
        double sum = 0;
        for (int k = 0; k < face->count; k++)
            sum += r->corners[face->first + k].d;
        keys[f] = (Key){sum / face->count, f};
    }
    if (keys)
        qsort(keys, (size_t)n, sizeof *keys, nearer_first);
    for (int k = 0; keys && k < n; k++)
        order[k] = keys[sort == SORT_FRONT_TO_BACK ? k : n - 1 - k].face;
    free(keys);
}

/* Every face in --sort's order; a prepass draws them all twice. */
bool draw_scene(Run *run, Error *err)
{
    Render *r = &run->render;
    Target *t = &run->target;
    EarlyZ *z = &run->rz->state->early_z;
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

/* The run draws through state: lesson 07's rasterizer with the shader's
 * state, draw_scene; the shader's buffers, of the target's size, and its
 * per-face inputs, of the mesh's. */
bool early_z_begin(LessonState *state, Run *run, Error *err)
{
    EarlyZ *z = &state->early_z;
    size_t n = (size_t)run->target.width * (size_t)run->target.height;
    int nfaces = run->render.mesh.nfaces;
    size_t faces = nfaces > 0 ? (size_t)nfaces : 1;
    run->rasterizer.state = state;
    run->draw = draw_scene;
    bool *cutout = malloc(faces * sizeof *cutout);
    Rgb *lit = malloc(faces * sizeof *lit);
    z->cutout = cutout, z->lit = lit;
    z->colour = calloc(n, sizeof *z->colour);
    z->shade_count = calloc(n, sizeof *z->shade_count);
    if (cutout && lit && z->colour && z->shade_count) {
        for (int f = 0; f < nfaces; f++) {
            cutout[f] = mesh_face_in(&run->render.mesh, f, "cutout");
            lit[f] = face_flat_colour(&run->render.mesh, &run->render.camera, f);
        }
        for (size_t i = 0; i < n; i++)
            z->colour[i] = FLAT_BACKGROUND;
        return true;
    }
    early_z_free(z);
    return error_set(err, "out of memory for the shader's buffers (%zu pixels)", n);
}

void early_z_free(EarlyZ *z)
{
    free(z->colour);
    free(z->shade_count);
    free((void *)z->cutout);
    free((void *)z->lit);
    z->colour = NULL, z->shade_count = NULL, z->cutout = NULL, z->lit = NULL;
}
