/* workloads.c: see workloads.h. */
#include "workloads.h"

#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "harness/mesh_build.h"
#include "harness/scene.h"

#define SCREEN_SIDE 1024
#define SEED_SMALL 0x5eed0001u
#define SEED_MEDIUM 0x5eed0002u

static const char *const NAMES[WORKLOAD_COUNT] = {
    [WORKLOAD_SMALL] = "small",
    [WORKLOAD_MEDIUM] = "medium",
    [WORKLOAD_FILL_BACK_TO_FRONT] = "fill_back_to_front",
    [WORKLOAD_FILL_FRONT_TO_BACK] = "fill_front_to_back",
    [WORKLOAD_MESH] = "mesh",
    [WORKLOAD_CITY] = "city",
};

const char *workload_name(WorkloadKind kind)
{
    return (int)kind >= 0 && kind < WORKLOAD_COUNT ? NAMES[kind] : "?";
}

/* ---- Random numbers: SplitMix64, the same sequence on every machine ------- */

typedef struct { uint64_t state; } Random;

static uint64_t random_next(Random *r)
{
    uint64_t z = (r->state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

/* Uniform in [lo, hi): the top 53 bits make a double in [0, 1). */
static double random_uniform(Random *r, double lo, double hi)
{
    double u = (double)(random_next(r) >> 11) * (1.0 / 9007199254740992.0);
    return lo + (hi - lo) * u;
}

/* ---- Screen-space workloads: triangles given corner by corner ------------- */

static bool alloc_triangles(Workload *w, int ntris, Error *err)
{
    w->verts = malloc((size_t)ntris * 3 * sizeof *w->verts);
    w->verts_clip = malloc((size_t)ntris * 3 * sizeof *w->verts_clip);
    w->faces = malloc((size_t)ntris * sizeof *w->faces);
    if (!w->verts || !w->verts_clip || !w->faces) {
        workload_free(w);
        return error_set(err, "out of memory for %d triangles", ntris);
    }
    w->nfaces = ntris;
    w->ntris = ntris;
    for (int i = 0; i < ntris; i++) {
        w->faces[i] = screen_triangle(&w->verts[3 * i], i);
        w->faces[i].clip = &w->verts_clip[3 * i];
    }
    return true;
}

/* The screen corners laid out: each made the clip-space corner that a camera
 * with the workload's near and far puts there (x_c and y_c from the viewport
 * backwards, z_c as perspective's matrix makes it, w_c = d), and put back on
 * the screen as each frame will (the layout's x and y, to a rounding). */
static void screen_to_clip(Workload *w)
{
    double n = w->ctx.near, f = w->ctx.far;
    for (long k = 0; k < 3 * w->ntris; k++) {
        ScreenVertex s = w->verts[k];
        w->verts_clip[k] = vec4((2 * s.x / w->width - 1) * s.d, (1 - 2 * s.y / w->height) * s.d,
                                ((f + n) * s.d - 2 * f * n) / (f - n), s.d);
        w->verts[k] = camera_divide(w->verts_clip[k], w->width, w->height);
    }
}

/* Right triangles with both legs `leg` pixels long, along the axes: the
 * corners of a leg x leg square at a random place on the screen, minus one
 * random corner, so that the right angle is in any of the four corners. */
static bool build_right_triangles(Workload *w, int count, double leg, uint64_t seed, Error *err)
{
    if (!alloc_triangles(w, count, err))
        return false;
    Random r = {seed};
    for (int i = 0; i < count; i++) {
        double x0 = random_uniform(&r, 0, w->width - leg);
        double y0 = random_uniform(&r, 0, w->height - leg);
        double square[4][2] = {{x0, y0}, {x0 + leg, y0}, {x0 + leg, y0 + leg}, {x0, y0 + leg}};
        int right = (int)(random_next(&r) >> 62); /* 0 .. 3: the corner of the right angle */
        for (int k = 0; k < 3; k++) {
            const double *p = square[(right + 3 + k) % 4]; /* the corners before, at, after it */
            ScreenVertex v = {p[0], p[1], random_uniform(&r, WORKLOAD_D_MIN, WORKLOAD_D_MAX)};
            w->verts[3 * i + k] = v;
        }
    }
    screen_to_clip(w);
    return true;
}

/* FILL_LAYERS copies of the whole screen, each as 2 triangles at one depth.
 * Layer j in drawing order has d evenly spaced from WORKLOAD_D_MAX (first,
 * back to front) or WORKLOAD_D_MIN (first, front to back). */
static bool build_fill(Workload *w, bool back_to_front, Error *err)
{
    if (!alloc_triangles(w, 2 * FILL_LAYERS, err))
        return false;
    double W = w->width, H = w->height;
    for (int j = 0; j < FILL_LAYERS; j++) {
        double step = (WORKLOAD_D_MAX - WORKLOAD_D_MIN) * j / (FILL_LAYERS - 1);
        double d = back_to_front ? WORKLOAD_D_MAX - step : WORKLOAD_D_MIN + step;
        ScreenVertex *v = &w->verts[6 * j];
        /* Two halves of the screen rectangle, split along its diagonal, which
         * the fill rule gives to exactly one of them. */
        ScreenVertex corners[6] = {{0, 0, d}, {W, 0, d}, {W, H, d},
                                   {0, 0, d}, {W, H, d}, {0, H, d}};
        memcpy(v, corners, sizeof corners);
    }
    screen_to_clip(w);
    return true;
}

/* ---- The mesh and city workloads: a mesh through a scene's camera --------- */

/* m (built; freed here on failure) seen by the camera of the built-in scene
 * `scene`, projected, its faces listed as render_faces would draw them. */
static bool build_projected(Workload *w, const char *scene, Mesh *m, Error *err)
{
    const SceneInfo *info = scene_find(scene);
    if (!info) {
        mesh_free(m);
        return error_set(err, "the built-in scene '%s' is missing", scene);
    }
    Camera cam;
    camera_init(&cam, info->eye, info->target, info->up, info->fovy, info->near, info->far,
                w->width, w->height);
    if (!render_from_mesh(&w->render, m, &cam, scene, err)) {
        mesh_free(m);
        return false;
    }
    w->has_render = true;
    w->ctx.near = cam.near;
    w->ctx.far = cam.far;

    /* The faces render_faces would draw, in mesh order (none is dropped
     * with this camera, but the rule is the pipeline's, not ours). */
    const Render *r = &w->render;
    w->faces = malloc((size_t)r->mesh.nfaces * sizeof *w->faces);
    if (!w->faces) {
        workload_free(w);
        return error_set(err, "out of memory for %d faces", r->mesh.nfaces);
    }
    for (int i = 0; i < r->mesh.nfaces; i++) {
        if (render_face_dropped(r, i))
            continue;
        w->faces[w->nfaces] = render_screen_face(r, i);
        if (w->faces[w->nfaces].n > WORKLOAD_MAX_CORNERS) {
            workload_free(w);
            return error_set(err, "face %d of '%s' has more than %d corners", i, scene,
                             WORKLOAD_MAX_CORNERS);
        }
        w->ntris += w->faces[w->nfaces].n - 2;
        w->nfaces++;
    }
    return true;
}

static bool build_mesh(Workload *w, Error *err)
{
    Mesh m;
    mesh_init(&m);
    if (!torus_knot_mesh(&m, MESH_RINGS, MESH_SIDES, MESH_TUBE_RADIUS, err)) {
        mesh_free(&m);
        return false;
    }
    return build_projected(w, "knot", &m, err);
}

static bool build_city(Workload *w, Error *err)
{
    const SceneInfo *city = scene_find("city");
    Mesh m;
    mesh_init(&m);
    if (city && !city->build(&m, err)) {
        mesh_free(&m);
        return false;
    }
    return build_projected(w, "city", &m, err);
}

bool workload_build(Workload *w, WorkloadKind kind, Error *err)
{
    Workload empty = {0};
    *w = empty;
    w->kind = kind;
    w->name = workload_name(kind);
    w->width = SCREEN_SIDE;
    w->height = SCREEN_SIDE;
    w->ctx.near = WORKLOAD_NEAR;
    w->ctx.far = WORKLOAD_FAR;
    switch (kind) {
    case WORKLOAD_SMALL:
        return build_right_triangles(w, SMALL_COUNT, SMALL_LEG, SEED_SMALL, err);
    case WORKLOAD_MEDIUM:
        return build_right_triangles(w, MEDIUM_COUNT, MEDIUM_LEG, SEED_MEDIUM, err);
    case WORKLOAD_FILL_BACK_TO_FRONT:
        return build_fill(w, true, err);
    case WORKLOAD_FILL_FRONT_TO_BACK:
        return build_fill(w, false, err);
    case WORKLOAD_MESH:
        w->width = MESH_WIDTH;
        w->height = MESH_HEIGHT;
        return build_mesh(w, err);
    case WORKLOAD_CITY:
        w->width = CITY_WIDTH;
        w->height = CITY_HEIGHT;
        return build_city(w, err);
    case WORKLOAD_COUNT:
        break;
    }
    return error_set(err, "no workload number %d", (int)kind);
}

void workload_free(Workload *w)
{
    free(w->verts);
    free(w->verts_clip);
    free(w->faces);
    if (w->has_render)
        render_free(&w->render);
    Workload empty = {0};
    *w = empty;
}

void workload_draw(Workload *w, Target *t, const Rasterizer *rz)
{
    DrawContext ctx = w->ctx;
    ctx.width = t->width, ctx.height = t->height;
    ScreenVertex v[WORKLOAD_MAX_CORNERS];
    for (int i = 0; i < w->nfaces; i++) {
        ScreenFace f = w->faces[i];
        for (int k = 0; k < f.n; k++) /* as corners[] holds them */
            v[k] = camera_divide(f.clip[k], t->width, t->height);
        f.v = v;
        if (!rz->clips)
            f.clip = NULL;
        rz->draw_face(t, rz->state, &f, &ctx);
    }
}

uint64_t depth_checksum(const Target *t)
{
    const unsigned char *bytes = (const unsigned char *)t->depth;
    size_t n = (size_t)t->width * (size_t)t->height * sizeof *t->depth;
    uint64_t h = 0xcbf29ce484222325u; /* FNV-1a offset basis and prime */
    for (size_t k = 0; k < n; k++) {
        h ^= bytes[k];
        h *= 0x100000001b3u;
    }
    return h;
}
