/* fragments.c: lesson 08's plumbing, shown but not taught: the order of
 * --sort (a qsort by each face's mean d), and the fragments. Lesson 09's
 * rasterizer (HIERARCHICAL_ZBUFFER) tests and writes each fragment of a face itself; to run
 * the shader per fragment around it, unchanged, the face's box of the
 * buffers is saved first, and each pixel whose count of tests went up is a
 * fragment of the face, handed to fragment() (early_z.c). Where fragment()
 * puts a pixel back (a discard, the prepass's second pass), the pixel may
 * be farther again: the tiles of the box are read again. */
#include "extras.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clip.h"
#include "harness/shade.h"

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

typedef struct { int x0, y0, x1, y1; } Box; /* pixels x0 .. x1 - 1, y0 .. y1 - 1 */

/* The pixels the face can touch: its clipped corners' box, a pixel wider. */
static Box face_box(const Target *t, const ScreenFace *f)
{
    Vec4 kept[CLIP_MAX_OUT(CLIP_MAX_IN)];
    Box all = {0, 0, t->width, t->height}, b = {t->width, t->height, 0, 0};
    if (f->clip && f->n > CLIP_MAX_IN)
        return all;
    int n = f->clip ? clip_polygon(f->clip, f->n, kept) : f->n;
    for (int k = 0; k < n; k++) {
        ScreenVertex v = f->clip ? clip_to_screen(kept[k], t->width, t->height) : f->v[k];
        if (!(fabs(v.x) < 1e9 && fabs(v.y) < 1e9))
            return all;
        b.x0 = (int)fmin(b.x0, floor(v.x) - 1), b.y0 = (int)fmin(b.y0, floor(v.y) - 1);
        b.x1 = (int)fmax(b.x1, ceil(v.x) + 1), b.y1 = (int)fmax(b.y1, ceil(v.y) + 1);
    }
    b.x0 = b.x0 < 0 ? 0 : b.x0, b.y0 = b.y0 < 0 ? 0 : b.y0;
    b.x1 = b.x1 > t->width ? t->width : b.x1, b.y1 = b.y1 > t->height ? t->height : b.y1;
    return b;
}

void draw_shaded_face(Target *t, const ScreenFace *f, const DrawContext *ctx)
{
    EarlyZ *z = (EarlyZ *)t->depth_setup;
    Box b = face_box(t, f);
    size_t len = b.x1 > b.x0 ? (size_t)(b.x1 - b.x0) : 0;
    for (int y = b.y0; y < b.y1; y++) {
        size_t at = (size_t)y * (size_t)t->width + (size_t)b.x0;
        memcpy(z->saved_depth + at, t->depth + at, len * sizeof *t->depth);
        memcpy(z->saved_face + at, t->face + at, len * sizeof *t->face);
        memcpy(z->saved_tests + at, t->overdraw + at, len * sizeof *t->overdraw);
    }
    HierarchicalZ *h = t->hiz;
    unsigned long long tested = h->tiles_tested, skipped = h->tiles_skipped;
    HIERARCHICAL_ZBUFFER.draw_face(t, f, ctx); /* lesson 09 draws the face */
    if (h->tiles_tested > tested && h->tiles_tested - tested == h->tiles_skipped - skipped)
        h->faces_skipped++; /* every tile it asked was skipped */
    bool cutout = mesh_face_in(z->mesh, f->face, "cutout");
    Rgb lit = face_flat_colour(z->mesh, z->camera, f->face);
    for (int y = b.y0; y < b.y1; y++)
        for (int x = b.x0; x < b.x1; x++) {
            size_t i = (size_t)y * (size_t)t->width + (size_t)x;
            if (t->overdraw[i] != z->saved_tests[i])
                fragment(z, t, i, x, y, f->face, cutout, lit);
        }
    for (int ty = b.y0 / h->tile; (cutout || z->pass == 2) && ty * h->tile < b.y1; ty++)
        for (int tx = b.x0 / h->tile; tx * h->tile < b.x1; tx++)
            hiz_read_tile(h, t, ty * h->tiles_x + tx);
}

/* The run draws through z: the target's depth setup, lesson 07's rasterizer
 * with draw_shaded_face, draw_scene; and z's buffers, of the target's size. */
bool early_z_begin(EarlyZ *z, Run *run, Error *err)
{
    size_t n = (size_t)run->target.width * (size_t)run->target.height;
    run->target.depth_setup = &z->depth;
    z->rasterizer = *run->rz;
    z->rasterizer.draw_face = draw_shaded_face;
    run->rz = &z->rasterizer;
    run->draw = draw_scene;
    z->mesh = &run->render.mesh;
    z->camera = &run->render.camera;
    z->colour = calloc(n, sizeof *z->colour);
    z->shade_count = calloc(n, sizeof *z->shade_count);
    z->saved_depth = malloc(n * sizeof *z->saved_depth);
    z->saved_face = malloc(n * sizeof *z->saved_face);
    z->saved_tests = malloc(n * sizeof *z->saved_tests);
    if (z->colour && z->shade_count && z->saved_depth && z->saved_face && z->saved_tests) {
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
    free(z->saved_depth);
    free(z->saved_face);
    free(z->saved_tests);
    z->colour = NULL, z->shade_count = NULL, z->saved_depth = NULL;
    z->saved_face = NULL, z->saved_tests = NULL;
}
