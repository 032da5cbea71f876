/* extras.c: lesson 07's flags that are not its lesson, and the decals' score
 * (see extras.h). */
#include "extras.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/cli.h"
#include "state.h"

enum { FLAG_FORMAT, FLAG_MAPPING, FLAG_OFFSET, FLAG_CLAMP, FLAG_COUNT };

static const LessonFlag FLAGS[FLAG_COUNT] = {
    [FLAG_FORMAT] = {"--depth-format", "F", "what the depth buffer stores: unorm16, unorm24 "
                                            "(the default) or float32"},
    [FLAG_MAPPING] = {"--depth-mapping", "M", "standard (the default: 0 at near, 1 at far) or "
                                              "reversed (1 at near, 0 at far; takes --far inf)"},
    [FLAG_OFFSET] = {"--polygon-offset", "FACTOR,UNITS",
                     "depth bias of the faces in group or object `decal`: o = m * FACTOR + "
                     "r * UNITS added to z_w (negative is nearer when standard; default 0,0)"},
    [FLAG_CLAMP] = {"--offset-clamp", "C", "limit o to C as Direct3D and Vulkan do (0, the "
                                           "default: no limit)"},
};


/* How many decal shares the summary puts on one line. */
#define SHARES_PER_LINE 6



LessonState depth_chosen(const Run *run)
{
    const char *const *x = run->opt.extra;
    return (LessonState){.depth = depth_flags_setup(run, x[FLAG_FORMAT], x[FLAG_MAPPING]),
                         .bias = bias_flags_chosen(x[FLAG_OFFSET], x[FLAG_CLAMP],
                                                   &run->render.mesh)};
}

/* ---- Each decal's share of its pixels --------------------------------------
 * A decal's pixels are those it would show if it never lost to its base: the
 * pixels it wins in the same picture drawn without bias and without its
 * base, every face that is not a decal and lies in a decal's plane. */

/* Does every corner of face g lie in the plane of face f (world space)? */
static bool face_in_plane_of(const Mesh *m, int g, int f)
{
    Vec3 pts[64];
    const Face *ff = &m->faces[f], *gf = &m->faces[g];
    int n = ff->count < 64 ? ff->count : 64;
    for (int k = 0; k < n; k++)
        pts[k] = m->verts[m->corners[ff->first + k]];
    Vec3 normal = polygon_normal(pts, n);
    double size = sqrt(vec3_dot(normal, normal));
    for (int k = 0; k < gf->count; k++) {
        Vec3 p = m->verts[m->corners[gf->first + k]];
        double scale = 1 + fabs(p.x) + fabs(p.y) + fabs(p.z);
        if (!(fabs(vec3_dot(normal, vec3_sub(p, pts[0]))) <= 1e-9 * size * scale))
            return false;
    }
    return size > 0;
}

static bool is_base(const Mesh *m, int g)
{
    if (mesh_face_in(m, g, "decal"))
        return false;
    for (int f = 0; f < m->nfaces; f++)
        if (mesh_face_in(m, f, "decal") && face_in_plane_of(m, g, f))
            return true;
    return false;
}

/* The picture without bias and without the decals' bases, in ref. */
static bool draw_without_bases(Run *run, Target *ref, Error *err)
{
    Render *r = &run->render;
    int *order = malloc((size_t)(r->mesh.nfaces > 0 ? r->mesh.nfaces : 1) * sizeof *order);
    if (!order || !target_init(ref, run->target.width, run->target.height, err)) {
        free(order);
        return order ? false : error_set(err, "out of memory for the decals' score");
    }
    int count = 0;
    for (int g = 0; g < r->mesh.nfaces; g++)
        if (!is_base(&r->mesh, g))
            order[count++] = g;
    LessonState plain = *run->rz->state;
    plain.bias.mesh = NULL; /* no face is offset */
    Rasterizer unbiased = *run->rz;
    unbiased.state = &plain;
    unbiased.clear(ref, &plain);
    FaceCounts saved = r->counts; /* the summary counts the picture's faces only */
    bool ok = render_faces(r, ref, &unbiased, order, count, NULL, NULL, err);
    r->counts = saved;
    free(order);
    return ok;
}

static void note_decals(Run *run, const Target *ref)
{
    const Mesh *m = &run->render.mesh;
    const int32_t *won = run->target.face, *own = ref->face;
    size_t npix = (size_t)ref->width * (size_t)ref->height;
    long all = 0, all_won = 0, beyond = 0;
    int shown = 0;
    char line[256] = "";
    for (int f = 0; f < m->nfaces; f++) {
        if (!mesh_face_in(m, f, "decal"))
            continue;
        long mine = 0, kept = 0;
        for (size_t i = 0; i < npix; i++) {
            mine += own[i] == f;
            kept += own[i] == f && won[i] == f;
            beyond += own[i] != f && won[i] == f;
        }
        all += mine;
        all_won += kept;
        if (mine == 0)
            continue;
        size_t used = strlen(line);
        snprintf(line + used, sizeof line - used, "%s %d: %.3f", shown % SHARES_PER_LINE ? "," : "",
                 f, (double)kept / (double)mine);
        if (++shown % SHARES_PER_LINE == 0) {
            run_note(run, "   %s", line);
            line[0] = '\0';
        }
    }
    if (line[0])
        run_note(run, "   %s", line);
    run_note(run, "  decals: win %ld of their %ld pixels (%.4f), and %ld pixels beyond them",
             all_won, all, all ? (double)all_won / (double)all : 1.0, beyond);
}

static bool after_write(Run *run, Error *err)
{
    const Mesh *m = &run->render.mesh;
    bool any = false;
    for (int f = 0; f < m->nfaces && !any; f++)
        any = mesh_face_in(m, f, "decal");
    if (!any) {
        run_note(run, "  no face in group or object `decal`: nothing is offset");
        return true;
    }
    Target ref;
    if (!draw_without_bases(run, &ref, err))
        return false;
    const DepthBias *b = &run->rz->state->bias;
    run_note(run, "  polygon offset on the faces in `decal`: factor %g, units %g, clamp %g",
             b->factor, b->units, b->clamp);
    run_note(run, "  each decal's share of its pixels (face: share; its pixels: where it "
                  "shows without its base):");
    note_decals(run, &ref);
    target_free(&ref);
    return true;
}

static bool choose(Run *run, Error *err)
{
    const char *const *x = run->opt.extra;
    if (!depth_flags_ok(run, x[FLAG_FORMAT], x[FLAG_MAPPING], false, err) ||
        !bias_flags_ok(x[FLAG_OFFSET], x[FLAG_CLAMP], err))
        return false;
    run->after_write = after_write;
    return true;
}

const Extras EXTRAS = {.flags = FLAGS, .n_flags = FLAG_COUNT, .choose = choose};
