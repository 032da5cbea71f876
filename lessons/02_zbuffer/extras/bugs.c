/* bugs.c: two classic z-buffer mistakes (see bugs.h). */
#include "bugs.h"

#include "raster.h"

#include <math.h>
#include <stdlib.h>

/* Union-find over vertices: faces that share a vertex join one object. */
static int find_root(int *parent, int v)
{
    while (parent[v] != v) {
        parent[v] = parent[parent[v]]; /* halve the path as we go */
        v = parent[v];
    }
    return v;
}

int find_objects(const Mesh *m, int *object_of_face)
{
    int *parent = malloc((m->nverts > 0 ? (size_t)m->nverts : 1) * sizeof *parent);
    int *number = malloc((m->nverts > 0 ? (size_t)m->nverts : 1) * sizeof *number);
    if (!parent || !number) {
        free(parent);
        free(number);
        return -1;
    }
    for (int v = 0; v < m->nverts; v++) {
        parent[v] = v;
        number[v] = -1;
    }
    for (int i = 0; i < m->nfaces; i++) {
        const Face *f = &m->faces[i];
        int first = find_root(parent, m->corners[f->first]);
        for (int k = 1; k < f->count; k++)
            parent[find_root(parent, m->corners[f->first + k])] = first;
    }
    int objects = 0;
    for (int i = 0; i < m->nfaces; i++) {
        int root = find_root(parent, m->corners[m->faces[i].first]);
        if (number[root] < 0)
            number[root] = objects++;
        object_of_face[i] = number[root];
    }
    free(parent);
    free(number);
    return objects;
}

/* The pixels faces[0 .. n-1] can touch, clamped to the screen (x0 > x1 when none):
 * only there does a group's own buffer need clearing and copying. */
typedef struct { int x0, y0, x1, y1; } Box;

static int clamp_to(double v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : (int)v;
}

static Box faces_box(const Render *r, const int *faces, int n, int width, int height)
{
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (int k = 0; k < n; k++) {
        if (faces[k] < 0 || faces[k] >= r->mesh.nfaces || render_face_dropped(r, faces[k]))
            continue;
        ScreenFace f = render_screen_face(r, faces[k]);
        for (int c = 0; c < f.n; c++) {
            x0 = fmin(x0, f.v[c].x);
            y0 = fmin(y0, f.v[c].y);
            x1 = fmax(x1, f.v[c].x);
            y1 = fmax(y1, f.v[c].y);
        }
    }
    Box box = {clamp_to(floor(x0), 0, width), clamp_to(floor(y0), 0, height),
               clamp_to(ceil(x1), -1, width - 1), clamp_to(ceil(y1), -1, height - 1)};
    return box;
}

/* What rz->clear puts in every pixel: read off a cleared 1 x 1 target. */
static float cleared_value(const Rasterizer *rz, Error *err, bool *ok)
{
    Target one;
    *ok = render_target_init(&one, rz, 1, 1, err);
    float v = *ok ? one.depth[0] : 0.0f;
    target_free(&one);
    return v;
}

bool draw_in_own_buffers(Render *r, Target *t, const Rasterizer *rz, const int *order,
                         const int *group, int n, Error *err)
{
    bool cleared_ok;
    float cleared = cleared_value(rz, err, &cleared_ok);
    if (!cleared_ok)
        return false;
    size_t pixels = (size_t)t->width * (size_t)t->height;
    float *own = malloc(pixels * sizeof *own);
    if (!own)
        return error_set(err, "out of memory for a second depth buffer");
    float *shared = t->depth;
    bool ok = true;
    for (int start = 0, end; ok && start < n; start = end) {
        for (end = start; end < n && group[end] == group[start]; end++)
            ;
        Box box = faces_box(r, order + start, end - start, t->width, t->height);
        for (int y = box.y0; y <= box.y1; y++)
            for (int x = box.x0; x <= box.x1; x++)
                own[(size_t)y * (size_t)t->width + (size_t)x] = cleared;
        t->depth = own; /* the group sees only its own buffer */
        ok = render_faces(r, t, rz, order + start, end - start, NULL, NULL, err);
        t->depth = shared;
        /* Where the group drew, its face is now on screen: keep its depth
         * there so that --depth-out shows what the picture shows. */
        for (int y = box.y0; y <= box.y1; y++)
            for (int x = box.x0; x <= box.x1; x++) {
                size_t i = (size_t)y * (size_t)t->width + (size_t)x;
                if (own[i] != cleared)
                    shared[i] = own[i];
            }
    }
    free(own);
    return ok;
}

/* order[]: object by object, each object's faces in mesh order (a counting
 * sort); group[k]: the object of order[k]. False when out of memory. */
static bool sort_by_object(const int *object, int objects, int n, int *order, int *group)
{
    int *start = calloc((size_t)objects + 1, sizeof *start);
    if (!start)
        return false;
    for (int i = 0; i < n; i++)
        start[object[i] + 1]++;          /* faces per object ... */
    for (int o = 1; o <= objects; o++)
        start[o] += start[o - 1];        /* ... add up to where each object's run starts */
    for (int i = 0; i < n; i++) {
        int k = start[object[i]]++;
        order[k] = i;
        group[k] = object[i];
    }
    free(start);
    return true;
}

/* --bug clear-zero: every pixel to 0, the nearest depth there is. */
static void clear_to_zero(Target *t, LessonState *s)
{
    (void)s;
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++) {
        t->depth[i] = 0.0f;
        t->face[i] = NO_FACE;
    }
}

const Rasterizer CLEAR_ZERO_BUG = {.clear = clear_to_zero, .draw_face = draw_face};

bool draw_separate_buffers(Render *r, Target *t, const Rasterizer *rz, Error *err)
{
    int n = r->mesh.nfaces;
    size_t size = (n > 0 ? (size_t)n : 1) * sizeof(int);
    int *object = malloc(size), *order = malloc(size), *group = malloc(size);
    int objects = object && order && group ? find_objects(&r->mesh, object) : -1;
    bool ok = objects >= 0 && sort_by_object(object, objects, n, order, group);
    if (!ok)
        error_set(err, "out of memory finding the objects of %d faces", n);
    else
        ok = draw_in_own_buffers(r, t, rz, order, group, n, err);
    free(object);
    free(order);
    free(group);
    return ok;
}
