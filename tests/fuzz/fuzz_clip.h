/* fuzz_clip.h: the harness the fuzz targets of lessons 05-10 share, whose
 * rasterizers clip (fuzz_raster.h is that of lessons 02-04, whose faces come
 * on the screen). A target includes its lesson's headers, fills a FuzzScene
 * from the bytes and draws it with its lesson's state:
 *
 *     FuzzBytes b = {data, size};
 *     FuzzScene s;
 *     fuzz_scene(&s, &b);
 *     ... the lesson's state, from more bytes ...
 *     fuzz_draw(&s, &rasterizer, &target);
 *
 * The faces (3 to 8 corners, fan triangles, either convex flag) are given in
 * clip space, each coordinate anything fuzz_double gives (ordinary values,
 * fixed-point and guard-band limits, 1e30, the largest double, infinities,
 * NaN, raw bit patterns); their screen corners are lesson 05's
 * clip_to_screen of them, as the pipeline projects them. As the pipeline
 * does (render_faces), a face with a clip coordinate that is not finite, or
 * with every corner behind the near plane, is not drawn. Each face also
 * carries a byte of flags a lesson may use (decal, cutout).
 *
 * fuzz_draw checks what fuzz_raster.h checks: no crash, hang or undefined
 * behaviour; at most (corners + 6) x 5 x width x height fragments per face
 * (cut at the near and far planes, a face gains up to 2 corners, at the
 * guard band up to 4 more, and each triangle of the cut is drawn as at most
 * 5); the books (tested = passed + failed = the overdraw counts; a pixel
 * holds a face exactly when its depth is no longer the clear value). */
#ifndef FUZZ_CLIP_H
#define FUZZ_CLIP_H

#include "clip.h"
#include "fuzz_raster.h"
#include "harness/render.h"
#include "mesh.h"

#define FUZZ_DECAL 1  /* the face is in group `decal` (lesson 07 on) */
#define FUZZ_CUTOUT 2 /* the face is in group `cutout` (lesson 08 on) */

typedef struct {
    int width, height, nfaces;
    DrawContext ctx;
    Vec4 clip[FUZZ_MAX_FACES][FUZZ_MAX_CORNERS];
    ScreenVertex v[FUZZ_MAX_FACES][FUZZ_MAX_CORNERS];
    Tri tris[FUZZ_MAX_FACES][FUZZ_MAX_CORNERS - 2];
    ScreenFace face[FUZZ_MAX_FACES];
    uint8_t flags[FUZZ_MAX_FACES];
    /* The faces' names, as a mesh holds them: for mesh_face_in. */
    Mesh mesh;
    Face mesh_face[FUZZ_MAX_FACES];
    NameSet sets[3];
    char *decal[1], *cutout[1], *both[2];
} FuzzScene;

/* A positive, finite number from the bytes: near and far planes. */
static inline double fuzz_positive(FuzzBytes *b, double fallback)
{
    double x = fuzz_double(b);
    return isfinite(x) && x > 0 ? x : fallback;
}

static inline void fuzz_scene(FuzzScene *s, FuzzBytes *b)
{
    memset(s, 0, sizeof *s);
    uint8_t shape = fuzz_u8(b);
    s->width = 1 + (shape & 1 ? fuzz_u16(b) % FUZZ_STRIP_SIDE : fuzz_u8(b) % FUZZ_SMALL_SIDE);
    s->height = 1 + (shape & 1 ? fuzz_u8(b) % 4 : fuzz_u8(b) % FUZZ_SMALL_SIDE);
    double near = fuzz_positive(b, 0.5), far = fuzz_positive(b, 100.0);
    if (!(far > near))
        far = (shape & 2) ? INFINITY : near * 200.0;
    s->ctx = (DrawContext){near, far, s->width, s->height};
    s->nfaces = 1 + fuzz_u8(b) % FUZZ_MAX_FACES;
    static char decal[] = "decal", cutout[] = "cutout";
    s->decal[0] = decal, s->cutout[0] = cutout, s->both[0] = decal, s->both[1] = cutout;
    s->sets[0] = (NameSet){NULL, s->decal, 1};
    s->sets[1] = (NameSet){NULL, s->cutout, 1};
    s->sets[2] = (NameSet){NULL, s->both, 2};
    s->mesh.faces = s->mesh_face, s->mesh.nfaces = s->nfaces;
    s->mesh.sets = s->sets, s->mesh.nsets = 3;
    for (int f = 0; f < s->nfaces; f++) {
        uint8_t head = fuzz_u8(b);
        int n = 3 + head % (FUZZ_MAX_CORNERS - 2);
        s->flags[f] = fuzz_u8(b) & 3;
        for (int k = 0; k < n; k++) {
            Vec4 c;
            c.x = fuzz_double(b), c.y = fuzz_double(b), c.z = fuzz_double(b), c.w = fuzz_double(b);
            s->clip[f][k] = c;
            s->v[f][k] = clip_to_screen(c, s->width, s->height);
        }
        for (int k = 0; k < n - 2; k++)
            s->tris[f][k] = (Tri){{0, k + 1, k + 2}};
        s->face[f] = (ScreenFace){f, n, s->v[f], s->tris[f], (head & 0x80) != 0, s->clip[f]};
        s->mesh_face[f] = (Face){.count = n, .material = -1, .names = s->flags[f] - 1};
    }
}

/* Clears t (a target of the scene's size, counting) with rz and draws the
 * scene's faces; the checks above. finish: a rasterizer that holds faces
 * back draws them there (NULL: none). */
static inline void fuzz_draw(const FuzzScene *s, const Rasterizer *rz, Target *t,
                      void (*finish)(Target *t, LessonState *state))
{
    rz->clear(t, rz->state);
    t->counting = true;
    for (int f = 0; f < s->nfaces; f++) {
        const ScreenFace *face = &s->face[f];
        if (!render_face_clippable(face))
            continue;
        uint64_t before = t->stats.tested;
        rz->draw_face(t, rz->state, face, &s->ctx);
        if (finish)
            finish(t, rz->state);
        uint64_t most = (uint64_t)(face->n + 6) * (GUARD_BAND_MAX_OUT(3) - 2) *
                        (uint64_t)s->width * (uint64_t)s->height;
        fuzz_check(t->stats.tested - before <= most,
                   "cost bounded by the screen: at most (n + 6) x 5 x W x H fragments per face");
    }
    fuzz_check_books(t, rz, s->nfaces);
}

/* Whether a and b hold the same depth (to the bit) and face in every pixel. */
static inline bool fuzz_same_buffers(const Target *a, const Target *b)
{
    size_t n = (size_t)a->width * (size_t)a->height;
    return memcmp(a->depth, b->depth, n * sizeof *a->depth) == 0 &&
           memcmp(a->face, b->face, n * sizeof *a->face) == 0;
}

/* A target of the scene's size, or an abort (a fuzz run has the memory). */
static inline void fuzz_target(Target *t, const FuzzScene *s)
{
    Error err;
    fuzz_check(target_init(t, s->width, s->height, &err), "target_init");
}

#endif
