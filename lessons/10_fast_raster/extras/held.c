/* held.c: lesson 10's set-up on threads (engine.h). With more than one
 * thread, lesson 07's set-up of each face (clip, plane, snap, edges, bins)
 * would leave the other threads waiting: so draw_fast_face only copies the
 * face, and fast_finish hands the faces held back to the threads in as many
 * runs, in order. Each run is set up, by the first thread free, with a copy
 * of the engine (lesson 07's code keeps the plane of the triangle being
 * drawn in it) into bins of its own; the tiles then take the bins one run
 * after the other, so every polygon is drawn in the order the faces came. */
#include "engine.h"

#include <stdlib.h>
#include <string.h>

#include "state.h"

/* Triangles held before they are drawn: HOLD_EACH per thread, so that each
 * run's bins hold about as many as one thread's hold at the least before a
 * finish (bins_full, engine.c), in its core's cache while the tiles read
 * them; and never more than HOLD_MAX, so that memory stays small whatever
 * the threads. */
#define HOLD_EACH (1 << 13)
#define HOLD_MAX (1 << 16)
#define RUNS_MAX 64

typedef struct { int face, n; bool convex, clipped; size_t first, first_tri; } HeldFace;

struct Held {
    HeldFace *face; size_t nface, cap_face;
    ScreenVertex *v; Vec4 *clip; size_t nv, cap_v, cap_clip; /* the corners */
    Tri *tri; size_t ntri, cap_tri;
    size_t hold; /* triangles held before a finish (HOLD_MAX at most): more while they spread thin */
    DrawContext ctx;
    Bins *run[RUNS_MAX]; /* each run's bins, kept from one finish to the next */
};

typedef struct { Target *t; LessonState *s; Held *h; size_t lo, hi; int k; bool lost; } Run;

/* Triangles held before a finish at the least: HOLD_EACH a thread, HOLD_MAX at most. */
static size_t least_hold(const FastRaster *fr)
{
    size_t least = (size_t)HOLD_EACH * (size_t)fr->threads; /* threads: 256 at most */
    return least < HOLD_MAX ? least : HOLD_MAX;
}

/* False: it cannot be held (set up now). */
bool hold_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx)
{
    FastRaster *fr = &s->fast;
    if (!fr->held && !(fr->held = calloc(1, sizeof *fr->held)))
        return false;
    Held *h = fr->held;
    h->hold = h->hold ? h->hold : least_hold(fr); /* the first face held: the least */
    if (h->ntri >= h->hold)
        fast_finish(t, s, NULL);
    void *face = h->face, *v = h->v, *clip = h->clip, *tri = h->tri;
    size_t n = (size_t)f->n;
    bool ok = grow_array(&face, &h->cap_face, h->nface + 1, sizeof *h->face) &&
              grow_array(&v, &h->cap_v, h->nv + n, sizeof *h->v) &&
              grow_array(&clip, &h->cap_clip, h->nv + n, sizeof *h->clip) &&
              grow_array(&tri, &h->cap_tri, h->ntri + n - 2, sizeof *h->tri);
    h->face = face, h->v = v, h->clip = clip, h->tri = tri;
    if (!ok) {
        fast_finish(t, s, NULL); /* what was held, first: then this face is set up now */
        return false;
    }
    memcpy(h->v + h->nv, f->v, n * sizeof *f->v);
    if (f->clip)
        memcpy(h->clip + h->nv, f->clip, n * sizeof *f->clip);
    memcpy(h->tri + h->ntri, f->tris, (n - 2) * sizeof *f->tris);
    h->face[h->nface++] = (HeldFace){f->face, f->n, f->convex, f->clip != NULL, h->nv, h->ntri};
    h->nv += n, h->ntri += n - 2;
    h->ctx = *ctx;
    return true;
}

/* Faces lo .. hi - 1, set up by a copy of the engine into run k's bins. */
static void *set_up_run(void *arg)
{
    Run *r = arg;
    Held *h = r->h;
    LessonState sub = *r->s;
    sub.fast.bins = h->run[r->k], sub.fast.held = NULL, sub.fast.set_up_only = true;
    for (size_t i = r->lo; i < r->hi; i++) {
        const HeldFace *g = &h->face[i];
        ScreenFace f = {.face = g->face, .n = g->n, .v = h->v + g->first,
                        .tris = h->tri + g->first_tri, .convex = g->convex,
                        .clip = g->clipped ? h->clip + g->first : NULL};
        set_up_face(r->t, &sub, &f, &h->ctx);
    }
    h->run[r->k] = sub.fast.bins;
    r->lost = sub.fast.out_of_memory; /* a face it could not bin */
    return NULL;
}

void set_up_held_faces(Target *t, LessonState *s)
{
    FastRaster *fr = &s->fast;
    Held *h = fr->held;
    if (!h || h->nface == 0)
        return;
    if (!bins_of(t, s)) {
        fr->out_of_memory = true; /* the held faces are lost */
        h->nface = h->nv = h->ntri = 0;
        return;
    }
    int runs = fr->threads < RUNS_MAX ? fr->threads : RUNS_MAX;
    Run r[RUNS_MAX];
    for (int k = 0; k < runs; k++)
        r[k] = (Run){t, s, h, h->nface * (size_t)k / (size_t)runs,
                     h->nface * (size_t)(k + 1) / (size_t)runs, k, false};
    run_threads(&fr->pool, runs, set_up_run, r, sizeof *r);
    Bins *last = fr->bins, *filled[RUNS_MAX];
    int n = 0;
    bool lost = false;
    for (int k = 0; k < runs; k++) { /* in order: run k's bins after run k - 1's */
        if (h->run[k] && h->run[k]->npoly > 0) /* else empty, maybe another target's */
            last->next = h->run[k], last = h->run[k], filled[n++] = h->run[k];
        lost = lost || r[k].lost;
    }
    /* The next finish, as bins_full weighs the bins: after least_hold when
     * these faces were heaped on few tiles, else after twice as many as now
     * (up to HOLD_MAX): fewer passes over the tiles. */
    size_t more = 2 * h->hold;
    bool heaped = bins_heaped(fr->bins->tiles_x * fr->bins->tiles_y, filled, n);
    h->hold = heaped ? least_hold(fr) : more < HOLD_MAX ? more : HOLD_MAX;
    /* Only now: the runs still going copied the engine, this flag with it. */
    fr->out_of_memory = fr->out_of_memory || lost;
    h->nface = h->nv = h->ntri = 0;
}

void held_free(FastRaster *fr)
{
    Held *h = fr->held;
    for (int k = 0; h && k < RUNS_MAX; k++)
        bins_free(h->run[k]);
    if (h)
        free(h->face), free(h->v), free(h->clip), free(h->tri);
    free(h);
    fr->held = NULL;
}
