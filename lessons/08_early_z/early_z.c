/* early_z.c: lesson 08, where the fragment shader runs: after the depth test
 * or before it, and in how many passes (early_z.h, docs/08_early_z.md).
 * Lesson 07's draw_biased_face draws each face, tests and writes depth; this
 * file looks at what it did to the face's box, fragment by fragment, and
 * runs the shader where the mode says, undoing the test for a discard. */
#include "early_z.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clip.h"
#include "shade.h"

/* ---- The fragment shader ---------------------------------------------------- */

/* A cutout's holes: squares of 4 x 4 pixels, every other one kept. */
bool cutout_keeps(int x, int y)
{
    return (((x >> 2) ^ (y >> 2)) & 1) == 0;
}

static uint32_t hash2(int32_t x, int32_t y)
{
    uint32_t h = (uint32_t)x * 0x8da6b343u ^ (uint32_t)y * 0xd8163841u;
    h ^= h >> 13;
    h *= 0x165667b1u;
    return h ^ (h >> 16);
}

/* Value noise: random values on the integer lattice, blended smoothly. */
static double value_noise(double x, double y)
{
    double fx = floor(x), fy = floor(y), u = x - fx, v = y - fy;
    int32_t ix = (int32_t)fx, iy = (int32_t)fy;
    double a = hash2(ix, iy) & 0xffff, b = hash2(ix + 1, iy) & 0xffff;
    double c = hash2(ix, iy + 1) & 0xffff, d = hash2(ix + 1, iy + 1) & 0xffff;
    u = u * u * (3 - 2 * u);
    v = v * v * (3 - 2 * v);
    double top = a + (b - a) * u, bottom = c + (d - c) * u;
    return (top + (bottom - top) * v) / 65535.0;
}

/* lit: the face's flat colour (common/shade.h: Lambert from its normal).
 * The pattern, SHADER_OCTAVES octaves of value noise, darkens it by up to 30%. */
Rgb shade_fragment(Rgb lit, int x, int y)
{
    double sum = 0, weight = 0, amplitude = 1, scale = 1.0 / 64;
    for (int k = 0; k < SHADER_OCTAVES; k++) {
        sum += amplitude * value_noise((x + 0.5) * scale, (y + 0.5) * scale);
        weight += amplitude;
        amplitude *= 0.5;
        scale *= 2;
    }
    double g = 0.7 + 0.3 * sum / weight;
    Rgb c = {(uint8_t)(lit.r * g + 0.5), (uint8_t)(lit.g * g + 0.5), (uint8_t)(lit.b * g + 0.5)};
    return c;
}

/* ---- The order of the faces --------------------------------------------------- */

typedef struct { double d; int face; } Key;

static int nearer_first(const void *a, const void *b)
{
    const Key *p = a, *q = b;
    return p->d < q->d ? -1 : p->d > q->d ? 1 : p->face - q->face;
}

/* By the view depth of the face's centre, the mean d of its corners. */
void sort_faces(const Render *r, SortOrder sort, int *order)
{
    int n = r->mesh.nfaces;
    Key *keys = sort == SORT_NONE ? NULL : malloc((size_t)(n > 0 ? n : 1) * sizeof *keys);
    for (int f = 0; f < n; f++)
        order[f] = f;
    if (!keys)
        return; /* mesh order (also when out of memory: the picture is the same) */
    for (int f = 0; f < n; f++) {
        const Face *face = &r->mesh.faces[f];
        double sum = 0;
        for (int k = 0; k < face->count; k++)
            sum += r->corners[face->first + k].d;
        keys[f] = (Key){sum / face->count, f};
    }
    qsort(keys, (size_t)n, sizeof *keys, nearer_first);
    for (int k = 0; k < n; k++)
        order[k] = keys[sort == SORT_FRONT_TO_BACK ? k : n - 1 - k].face;
    free(keys);
}

/* ---- One face, fragment by fragment ------------------------------------------ */

typedef struct { int x0, y0, x1, y1; } Box; /* pixels x0 .. x1 - 1, y0 .. y1 - 1 */

/* The pixels the face can touch: its clipped corners' box, a pixel wider. */
static Box face_box(const Target *t, const ScreenFace *f)
{
    Vec4 kept[CLIP_MAX_OUT(CLIP_MAX_IN)];
    ScreenVertex v[CLIP_MAX_OUT(CLIP_MAX_IN)];
    Box all = {0, 0, t->width, t->height}, b = {t->width, t->height, 0, 0};
    int n = f->n;
    if (f->clip && f->n > CLIP_MAX_IN)
        return all;
    if (f->clip)
        n = clip_polygon(f->clip, f->n, kept);
    for (int k = 0; k < n; k++) {
        v[k] = f->clip ? clip_to_screen(kept[k], t->width, t->height) : f->v[k];
        if (!(fabs(v[k].x) < 1e9 && fabs(v[k].y) < 1e9))
            return all;
        b.x0 = (int)fmin(b.x0, floor(v[k].x) - 1), b.y0 = (int)fmin(b.y0, floor(v[k].y) - 1);
        b.x1 = (int)fmax(b.x1, ceil(v[k].x) + 1), b.y1 = (int)fmax(b.y1, ceil(v[k].y) + 1);
    }
    b.x0 = b.x0 < 0 ? 0 : b.x0, b.y0 = b.y0 < 0 ? 0 : b.y0;
    b.x1 = b.x1 > t->width ? t->width : b.x1, b.y1 = b.y1 > t->height ? t->height : b.y1;
    return b;
}

static void run_shader(EarlyZ *z, size_t i, Rgb lit, int x, int y, bool write)
{
    Rgb c = shade_fragment(lit, x, y);
    z->counts.shaded++;
    z->shade_count[i]++;
    if (write)
        z->colour[i] = c;
}

/* Fragment at pixel i of face f, which lesson 07's test has just passed
 * (won) or failed; saved_* hold the pixel as it was before. Run in the order
 * the mode says, with its counts. */
static void fragment(EarlyZ *z, Target *t, size_t i, int x, int y, const ScreenFace *f,
                     bool cutout, Rgb lit)
{
    bool won = t->face[i] == f->face, kept = !cutout || cutout_keeps(x, y);
    if (z->pass == 2) {
        /* SOLUTION BEGIN: the prepass's second pass: depth writes off, so
         * the pixel is put back; the equal test passes where pass 1 left f. */
        bool equal = z->saved_face[i] == f->face;
        t->depth[i] = z->saved_depth[i];
        t->face[i] = z->saved_face[i];
        z->counts.tested++;
        if (equal)
            run_shader(z, i, lit, x, y, true);
        /* SOLUTION STUB
        (void)won; (void)lit;
        */
        /* SOLUTION END */
        return;
    }
    if (z->pass == 1 || z->mode == Z_LATE || (cutout && !z->bug_discard)) {
        /* SOLUTION BEGIN: late-Z (and pass 1, which runs only the cheap
         * discard): the shader first; a discarded fragment never reaches
         * the test, so what the test did is undone. */
        if (z->pass != 1)
            run_shader(z, i, lit, x, y, won && kept);
        if (!kept && won) {
            t->depth[i] = z->saved_depth[i];
            t->face[i] = z->saved_face[i];
        }
        z->counts.tested += kept;
        /* SOLUTION STUB
        (void)won; (void)kept; (void)lit;
        */
        /* SOLUTION END */
        return;
    }
    /* SOLUTION BEGIN: early-Z: the test first, the shader only if it passed. */
    z->counts.tested++;
    if (won)
        run_shader(z, i, lit, x, y, kept);
    if (won && !kept) /* --bug: the discard comes too late, the depth stays */
        t->face[i] = z->saved_face[i];
    /* SOLUTION STUB
    (void)won; (void)kept; (void)lit;
    */
    /* SOLUTION END */
}

/* One face: its box saved, drawn by lesson 07, then each fragment it made
 * (each pixel whose count of tests went up) handed to fragment(). */
void draw_shaded_face(Target *t, const ScreenFace *f, const DrawContext *ctx)
{
    EarlyZ *z = (EarlyZ *)t->depth_setup;
    Box b = face_box(t, f);
    for (int y = b.y0; y < b.y1; y++) {
        size_t row = (size_t)y * (size_t)t->width, at = row + (size_t)b.x0;
        size_t len = b.x1 > b.x0 ? (size_t)(b.x1 - b.x0) : 0;
        memcpy(z->saved_depth + at, t->depth + at, len * sizeof *t->depth);
        memcpy(z->saved_face + at, t->face + at, len * sizeof *t->face);
        memcpy(z->saved_tests + at, t->overdraw + at, len * sizeof *t->overdraw);
    }
    draw_biased_face(t, f, ctx);
    bool cutout = mesh_face_in(z->mesh, f->face, "cutout");
    Rgb lit = face_flat_colour(z->mesh, z->camera, f->face);
    for (int y = b.y0; y < b.y1; y++)
        for (int x = b.x0; x < b.x1; x++) {
            size_t i = (size_t)y * (size_t)t->width + (size_t)x;
            if (t->overdraw[i] != z->saved_tests[i])
                fragment(z, t, i, x, y, f, cutout, lit);
        }
}

/* Every face in the order --sort asks for; a prepass draws them all twice. */
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
    size_t npix = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < npix; i++)
        z->counts.covered += t->face[i] != NO_FACE;
    free(order);
    return ok;
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
