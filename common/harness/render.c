/* render.c: see render.h. */
#include "render.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "file.h"
#include "shade.h"
#include "world_view.h"

/* render_fit_camera: the view of an OBJ model. */
#define FIT_FOVY 40.0
#define FIT_MARGIN 1.05        /* the bounding sphere fills 1 / 1.05 of the view */
#define FIT_NEAR_FRACTION 0.5  /* near: half the distance to the sphere's front */
#define FIT_FAR_FACTOR 1.5     /* far: well behind the sphere's back */
#define FIT_BACK_OFF_STEPS 2100 /* doublings: enough to span every double */
#define FIT_INSIDE_NEAR 1e-3   /* near for an eye inside the sphere: this much of its radius */
#define FAR_MODEL_RATIO 1048576.0 /* 2^20: see model_origin */

static void render_clear(Render *r)
{
    memset(r, 0, sizeof *r);
    mesh_init(&r->mesh);
}

void render_free(Render *r)
{
    mesh_free(&r->mesh);
    free(r->corners);
    free(r->clip);
    render_clear(r);
}

/* Every face corner, projected once: corner k of the mesh is corners[k]. */
static bool project_corners(Render *r, Error *err)
{
    int n = r->mesh.ncorners;
    r->corners = malloc((n > 0 ? (size_t)n : 1) * sizeof *r->corners);
    r->clip = malloc((n > 0 ? (size_t)n : 1) * sizeof *r->clip);
    if (!r->corners || !r->clip)
        return error_set(err, "out of memory projecting %d face corners", n);
    for (int k = 0; k < n; k++) {
        Vec3 p = r->mesh.verts[r->mesh.corners[k]];
        r->corners[k] = camera_project(&r->camera, p);
        r->clip[k] = camera_to_clip(&r->camera, p);
    }
    return true;
}

bool render_from_mesh(Render *r, Mesh *mesh, const Camera *camera, const char *source,
                      Error *err)
{
    render_clear(r);
    r->mesh = *mesh;
    mesh_init(mesh);
    r->camera = *camera;
    snprintf(r->source, sizeof r->source, "%s", source);
    if (!project_corners(r, err)) {
        render_free(r);
        return false;
    }
    return true;
}

/* "triangles3, interpenetrate, ...": for the message about an unknown scene. */
static void scene_names(char *buf, size_t size)
{
    buf[0] = '\0';
    for (int i = 0; i < scene_count(); i++) {
        size_t used = strlen(buf);
        snprintf(buf + used, size - used, "%s%s", i ? ", " : "", scene_at(i)->name);
    }
}

static void fit_planes_to_eye(const Mesh *m, Vec3 eye, SceneInfo *s); /* below */
static void fit_sphere(const Mesh *m, Vec3 *centre, double *radius); /* below */

/* Where a model is drawn from. Doubles near 1e17 are 16 apart: a camera
 * fitted to a small model there cannot stand near it (its eye rounds into
 * the plane of the model's faces, or onto the model), and look_at's
 * translation, -dot(axis, eye), rounds by as much. So a model whose centre
 * is more than 2^20 times its radius from the origin is moved to the
 * origin before anything is framed or projected: a vertex minus a centre
 * that near is exact (Sterbenz), and the picture is the one the model's own
 * coordinates give. Any other model stays where it is, to the bit. */
static Vec3 model_origin(const Mesh *m)
{
    Vec3 centre;
    double radius;
    fit_sphere(m, &centre, &radius);
    return vec3_length(centre) > FAR_MODEL_RATIO * radius ? centre : vec3(0, 0, 0);
}

/* Fills r->mesh from --obj or --scene and tells which camera frames it. A
 * model far from the origin is moved (model_origin), and the --eye and
 * --target given with it too. */
static int load_mesh(Render *r, Options *opt, SceneInfo *framing, Error *err)
{
    if (opt->obj) {
        if (!mesh_load_obj(&r->mesh, opt->obj, err))
            return EXIT_RUN_FAILED;
        snprintf(r->source, sizeof r->source, "%s", opt->obj);
        Vec3 origin = model_origin(&r->mesh);
        if (origin.x != 0 || origin.y != 0 || origin.z != 0) {
            for (int i = 0; i < r->mesh.nverts; i++)
                r->mesh.verts[i] = vec3_sub(r->mesh.verts[i], origin);
            if (opt->eye_set)
                opt->eye = vec3_sub(opt->eye, origin);
            if (opt->target_set)
                opt->target = vec3_sub(opt->target, origin);
        }
        *framing = render_fit_camera(&r->mesh, opt->width, opt->height);
        if (opt->eye_set)
            fit_planes_to_eye(&r->mesh, opt->eye, framing);
        return EXIT_OK;
    }
    const SceneInfo *scene = scene_find(opt->scene ? opt->scene : "");
    if (!scene) {
        char names[ERROR_MSG_MAX / 2];
        scene_names(names, sizeof names);
        error_set(err, "--scene: unknown scene '%s' (scenes: %s)", opt->scene ? opt->scene : "",
                  names);
        return EXIT_USAGE;
    }
    if (!scene->build(&r->mesh, err))
        return EXIT_RUN_FAILED;
    snprintf(r->source, sizeof r->source, "scene %s", scene->name);
    *framing = *scene;
    return EXIT_OK;
}

int render_load(Render *r, Options *opt, Error *err)
{
    render_clear(r);
    SceneInfo framing;
    int status = load_mesh(r, opt, &framing, err);
    if (status == EXIT_OK && !cli_resolve_camera(opt, &framing, err))
        status = EXIT_USAGE;
    if (status == EXIT_OK) {
        camera_init(&r->camera, opt->eye, opt->target, opt->up, opt->fovy, opt->near, opt->far,
                    opt->width, opt->height);
        if (!project_corners(r, err))
            status = EXIT_RUN_FAILED;
    }
    if (status != EXIT_OK)
        render_free(r);
    return status;
}

ScreenFace render_screen_face(const Render *r, int i)
{
    const Face *f = &r->mesh.faces[i];
    ScreenFace sf = {.face = i, .n = f->count, .v = r->corners + f->first,
                     .tris = r->mesh.tris + f->first_tri, .convex = f->convex,
                     .clip = r->clip ? r->clip + f->first : NULL};
    return sf;
}

bool render_target_init(Target *t, const Rasterizer *rz, int width, int height, Error *err)
{
    if (!target_init(t, width, height, err))
        return false;
    rz->clear(t, rz->state);
    return true;
}

typedef enum { KEEP, BEHIND_NEAR, NOT_FINITE } DropReason;

/* docs/conventions.md: lessons 02-04 drop a whole face if any vertex has d <= near. */
static DropReason drop_reason(const Render *r, const ScreenFace *f)
{
    for (int k = 0; k < f->n; k++)
        if (!(f->v[k].d > r->camera.near)) /* also catches a d that is NaN */
            return BEHIND_NEAR;
    if (!screen_face_is_finite(f))
        return NOT_FINITE;
    return KEEP;
}

/* Lesson 05's rasterizer clips: only a face wholly behind the near plane
 * (z_c < -w_c at every corner) is dropped, since clipping leaves nothing. */
static DropReason clipping_drop_reason(const ScreenFace *f)
{
    bool behind = true;
    for (int k = 0; k < f->n; k++) {
        Vec4 c = f->clip[k];
        if (!isfinite(c.x) || !isfinite(c.y) || !isfinite(c.z) || !isfinite(c.w))
            return NOT_FINITE;
        behind = behind && c.z < -c.w;
    }
    return behind ? BEHIND_NEAR : KEEP;
}

bool render_face_clippable(const ScreenFace *f)
{
    return clipping_drop_reason(f) == KEEP;
}

bool render_face_dropped(const Render *r, int i)
{
    ScreenFace f = render_screen_face(r, i);
    return drop_reason(r, &f) != KEEP;
}

bool render_faces(Render *r, Target *t, const Rasterizer *rz, const int *order, int count,
                  FaceDrawnFn after_face, void *data, Error *err)
{
    DrawContext ctx = {.near = r->camera.near, .far = r->camera.far, .width = t->width,
                       .height = t->height};
    int n = order ? count : r->mesh.nfaces, k;
    for (k = 0; k < n; k++) {
        int i = order ? order[k] : k;
        if (i < 0 || i >= r->mesh.nfaces)
            continue;
        ScreenFace f = render_screen_face(r, i);
        int ntris = f.n - 2;
        switch (rz->clips && f.clip ? clipping_drop_reason(&f) : drop_reason(r, &f)) {
        case BEHIND_NEAR:
            r->counts.faces_behind_near++;
            r->counts.tris_behind_near += ntris;
            continue;
        case NOT_FINITE:
            r->counts.faces_not_finite++;
            r->counts.tris_not_finite += ntris;
            continue;
        case KEEP:
            break;
        }
        rz->draw_face(t, rz->state, &f, &ctx);
        r->counts.faces_drawn++;
        r->counts.tris_drawn += ntris;
        if (after_face && !after_face(data, t, &f, err))
            break;
    }
    return k == n;
}

float *render_view_depth(const Target *t, const Rasterizer *rz)
{
    size_t n = (size_t)t->width * (size_t)t->height;
    float *d = malloc(n * sizeof *d);
    if (!d)
        return NULL;
    for (size_t i = 0; i < n; i++) {
        if (t->face[i] == NO_FACE)
            d[i] = INFINITY; /* docs/conventions.md: the background is +infinity */
        else
            d[i] = rz->stored_to_depth ? (float)rz->stored_to_depth(rz->state, t->depth[i]) : t->depth[i];
    }
    return d;
}

bool render_image(const Render *r, const Target *t, const Rasterizer *rz, ShadeMode shade,
                  Image *out, Error *err)
{
    float *depth = NULL;
    if (shade == SHADE_DEPTH && !(depth = render_view_depth(t, rz)))
        return error_set(err, "out of memory for the depth picture");
    bool ok = shade_image(&r->mesh, &r->camera, t->face, depth, t->width, t->height, shade,
                          out, err);
    free(depth);
    return ok;
}

/* docs/conventions.md: `make run` writes into out/, which may not exist yet. */
static bool make_parent_dirs(const char *path, Error *err)
{
    const char *slash = strrchr(path, '/');
    if (!slash || slash == path)
        return true;
    size_t len = (size_t)(slash - path);
    char *dir = malloc(len + 1);
    if (!dir)
        return error_set(err, "out of memory");
    memcpy(dir, path, len);
    dir[len] = '\0';
    bool ok = make_dirs(dir, err);
    free(dir);
    return ok;
}

static bool write_colour(const Render *r, const Target *t, const Rasterizer *rz,
                         const Options *opt, Error *err)
{
    Image im;
    if (!render_image(r, t, rz, opt->shade, &im, err))
        return false;
    bool ok = image_write_png(&im, opt->out, err);
    image_free(&im);
    return ok;
}

/* --id-out: face + 1 per pixel, whatever --shade says (shade.h face_id_colour). */
static bool write_ids(const Target *t, const char *path, Error *err)
{
    Image im;
    if (!face_id_image(t->face, t->width, t->height, &im, err))
        return false;
    bool ok = image_write_png(&im, path, err);
    image_free(&im);
    return ok;
}

static bool write_depth(const Target *t, const Rasterizer *rz, const char *path, Error *err)
{
    float *d = render_view_depth(t, rz);
    if (!d)
        return error_set(err, "out of memory writing %s", path);
    bool ok = write_pfm(d, t->width, t->height, path, err);
    free(d);
    return ok;
}

/* Every output is complete before any is published (lesson.c run_end, file.h
 * output_set_publish); --out - goes to standard output last, once the files
 * are written, since bytes sent there cannot be taken back. */
bool render_write(const Render *r, const Target *t, const Rasterizer *rz, const Options *opt,
                  Error *err)
{
    bool to_stdout = is_stdout_name(opt->out);
    if (opt->out && !to_stdout &&
        !(make_parent_dirs(opt->out, err) && write_colour(r, t, rz, opt, err)))
        return false;
    if (opt->depth_out &&
        !(make_parent_dirs(opt->depth_out, err) && write_depth(t, rz, opt->depth_out, err)))
        return false;
    if (opt->id_out &&
        !(make_parent_dirs(opt->id_out, err) && write_ids(t, opt->id_out, err)))
        return false;
    if (opt->overdraw_out &&
        !(make_parent_dirs(opt->overdraw_out, err) &&
          write_pgm16(t->overdraw, t->width, t->height, opt->overdraw_out, err)))
        return false;
    if (opt->world_out && !(make_parent_dirs(opt->world_out, err) &&
                            world_view_write(&r->mesh, &r->camera, opt->world_out, err)))
        return false;
    return !to_stdout || write_colour(r, t, rz, opt, err);
}

bool render_make_parent_dirs(const char *path, Error *err)
{
    return make_parent_dirs(path, err);
}

/* One line each, as error_report prints errors: a control character that came
 * in with a file name or a line of the file prints as '?'. */
void render_print_warnings(const Render *r, const char *program)
{
    for (int i = 0; i < r->mesh.nwarnings; i++) {
        fprintf(stderr, "%s: warning: ", program);
        for (const char *c = r->mesh.warnings[i]; *c; c++)
            fputc(iscntrl((unsigned char)*c) ? '?' : *c, stderr);
        fputc('\n', stderr);
    }
}

void render_print_summary(FILE *out, const char *program, const Render *r, const Target *t,
                          const Options *opt)
{
    const FaceCounts *c = &r->counts;
    fprintf(out, "%s: %s (%d face%s): %d triangle%s drawn, %d dropped at the near plane",
            program, r->source, r->mesh.nfaces, r->mesh.nfaces == 1 ? "" : "s",
            c->tris_drawn, c->tris_drawn == 1 ? "" : "s", c->tris_behind_near);
    if (c->tris_not_finite)
        fprintf(out, ", %d dropped with screen positions too large to represent",
                c->tris_not_finite);
    fprintf(out, "\n");

    size_t n = (size_t)t->width * (size_t)t->height;
    long covered = 0;
    for (size_t i = 0; i < n; i++)
        covered += t->overdraw[i] > 0;
    const FragmentStats *s = &t->stats;
    fprintf(out, "  fragments: %llu tested, %llu passed, %llu failed; ",
            (unsigned long long)s->tested, (unsigned long long)s->passed,
            (unsigned long long)s->failed);
    if (covered)
        fprintf(out, "average overdraw %.2f over %ld covered pixel%s\n",
                (double)s->tested / (double)covered, covered, covered == 1 ? "" : "s");
    else if (s->tested) /* a rasterizer that keeps no count per pixel unless asked */
        fprintf(out, "overdraw per pixel not counted (--overdraw-out counts it)\n");
    else
        fprintf(out, "no pixel covered\n");

    const char *written[] = {opt->out, opt->depth_out, opt->id_out, opt->overdraw_out,
                             opt->world_out};
    for (size_t k = 0; k < sizeof written / sizeof written[0]; k++)
        if (written[k])
            fprintf(out, "  wrote %s\n", written[k]);
}

/* Half the diagonal of the bounding box, and its centre; false for an empty
 * mesh or one whose extent is not a finite number. Halves first, so that
 * coordinates near the largest double do not overflow. */
static bool bounding_sphere(const Mesh *m, Vec3 *centre, double *radius)
{
    if (m->nverts == 0)
        return false;
    Vec3 lo = m->verts[0], hi = m->verts[0];
    for (int i = 1; i < m->nverts; i++) {
        Vec3 p = m->verts[i];
        lo = vec3(fmin(lo.x, p.x), fmin(lo.y, p.y), fmin(lo.z, p.z));
        hi = vec3(fmax(hi.x, p.x), fmax(hi.y, p.y), fmax(hi.z, p.z));
    }
    *centre = vec3(lo.x / 2 + hi.x / 2, lo.y / 2 + hi.y / 2, lo.z / 2 + hi.z / 2);
    *radius = vec3_length(vec3(hi.x / 2 - lo.x / 2, hi.y / 2 - lo.y / 2, hi.z / 2 - lo.z / 2));
    return isfinite(*radius) && isfinite(centre->x) && isfinite(centre->y) &&
           isfinite(centre->z);
}

/* The bounding sphere as the fitted camera takes it: a single point has
 * radius 1, and a mesh that has none (empty, or too big for a double) gets
 * the unit sphere at the origin. */
static void fit_sphere(const Mesh *m, Vec3 *centre, double *radius)
{
    if (!bounding_sphere(m, centre, radius) || !isfinite(*radius)) {
        *centre = vec3(0, 0, 0);
        *radius = 1;
    } else if (*radius == 0) {
        *radius = 1;
    }
}

/* An eye given on the command line (--eye, no --near or --far) gets the
 * planes render_fit_camera gives its own eye, measured from that eye: near
 * half-way to the sphere's front, far beyond its back, so that the whole
 * model lies between them. From inside the sphere, near is a thousandth
 * of its radius. */
static void fit_planes_to_eye(const Mesh *m, Vec3 eye, SceneInfo *s)
{
    Vec3 centre;
    double radius;
    fit_sphere(m, &centre, &radius);
    double distance = vec3_length(vec3_sub(eye, centre));
    s->near = fmax((distance - radius) * FIT_NEAR_FRACTION, radius * FIT_INSIDE_NEAR);
    s->far = (distance + radius) * FIT_FAR_FACTOR;
}

SceneInfo render_fit_camera(const Mesh *m, int width, int height)
{
    /* The narrower of the two fields of view decides the distance. */
    double half_fovy = FIT_FOVY / 2 * PI / 180;
    double half_fovx = atan(tan(half_fovy) * width / height);
    double half = fmin(half_fovy, half_fovx);

    Vec3 centre;
    double radius = 0, distance = 0;
    if (bounding_sphere(m, &centre, &radius)) {
        if (radius == 0)
            radius = 1; /* a single point: any view of it will do */
        distance = radius / sin(half) * FIT_MARGIN;
    }
    if (!(isfinite(distance) && distance > 0)) { /* empty, or too big for a double */
        centre = vec3(0, 0, 0);
        radius = 1;
        distance = radius / sin(half) * FIT_MARGIN;
    }
    Vec3 towards_eye = vec3_normalize(vec3(0.35, 0.3, 1.0)); /* front, right, above */
    /* Far from the origin a small model's distance can vanish in rounding
     * (1e17 + 3 == 1e17): step back until the eye is really that far from
     * the target, so that the camera is one, whatever the model. */
    for (int k = 0; k < FIT_BACK_OFF_STEPS; k++) {
        Vec3 eye = vec3_add(centre, vec3_scale(towards_eye, distance));
        if (vec3_length(vec3_sub(eye, centre)) >= distance / 2)
            break;
        distance *= 2;
    }

    SceneInfo s = {0};
    s.name = "obj";
    s.about = "an OBJ file, framed to its bounds";
    s.target = centre;
    s.eye = vec3_add(centre, vec3_scale(towards_eye, distance));
    s.up = vec3(0, 1, 0);
    s.fovy = FIT_FOVY;
    s.near = (distance - radius) * FIT_NEAR_FRACTION;
    s.far = (distance + radius) * FIT_FAR_FACTOR;
    return s;
}

