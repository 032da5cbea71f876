/* gpu_reference: the lessons' scene drawn by a real GPU rasterizer, Mesa's
 * llvmpipe, through EGL (surfaceless, no window) and OpenGL 4.5 core, so that
 * tests can measure how far the lessons agree with a GPU (docs/tools.md).
 *
 *   gpu_reference [--scene NAME | --obj FILE.obj] [camera flags] [--width N]
 *                 [--height N] [--id-out FILE.png] [--depth-out FILE.pfm]
 *                 [--out FILE.png] [--depth-format unorm16|unorm24|float32]
 *                 [--depth-mapping standard|reversed|gl] [--far inf] [--repeat N]
 *                 [--orientation HOW] [--snap] [--agree-id F.png [--agree-depth F.pfm]]
 *                 [--polygon-offset FACTOR,UNITS [--offset-clamp C]]
 *
 * The geometry is the lessons' own: common/harness/render.c loads the scene and puts
 * every corner in clip space in double, P V (x, y, z, 1) with gluPerspective's
 * P, as lesson 05 clips it; the GPU gets those four numbers as floats (the
 * vertex shader passes them on unchanged), and each triangle of a face carries
 * the face's index. The GPU clips, divides, snaps and fills; the fragment
 * shader writes face + 1 as 24-bit RGB, which is --id-out exactly.
 *
 *   standard   glClipControl(.., GL_ZERO_TO_ONE) and z_c = f (w_c - n) / (f - n),
 *              so z_w = f/(f-n) (1 - n/d), as the lessons, Direct3D and Vulkan
 *              map it; cleared to 1, LESS
 *   reversed   glClipControl(.., GL_ZERO_TO_ONE) and z_c = n (f - w_c) / (f - n),
 *              so z_w = n/(f-n) (f/d - 1) (exactly n/d when --far inf),
 *              cleared to 0, GREATER
 *   gl         OpenGL's default: z_w = (z_c / w_c + 1) / 2 with gluPerspective's
 *              z_c; the same z_w on paper, less precise in float (lesson 06)
 * Either way a tie keeps the fragment drawn first, as in the lessons.
 *
 * Rows: the lessons' screen has y down with row 0 at the top. OpenGL's window
 * has y up. Negating y_c puts the lessons' row r in the framebuffer's row r,
 * and then llvmpipe's fill rule is the lessons' top-left; --orientation shows
 * the other ways (gl.h).
 *
 * --agree-id and --agree-depth compare a lesson's --id-out and --depth-out
 * with the GPU's pictures and print the agreement (several lessons' at once:
 * files separated by commas, the k-th depth file with the k-th picture,
 * each agreement after a line naming its picture); --snap first moves each
 * corner onto the lessons' 1/256-pixel grid (docs/tools.md says why).
 * --polygon-offset and --offset-clamp: lesson 07's depth bias, on the faces in
 * group or object `decal`: glPolygonOffset (glPolygonOffsetClamp) with
 * GL_POLYGON_OFFSET_FILL enabled while they are drawn, in mesh order.
 * --repeat N draws N times and prints the time of the fastest draw (clear,
 * draw, glFinish; not the context, the shader compile or the upload).
 * Exit status: 0 drawn, 1 no GPU context or an output not written, 2 usage. */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "harness/cli.h"
#include "error.h"
#include "harness/file.h"
#include "gl.h"
#include "harness/image_io.h"
#include "harness/render.h"
#include "harness/shade.h"

#define PROGRAM "gpu_reference"
#define ID_MAX ((1 << 24) - 1) /* faces --id-out can number: face + 1 in 24 bits */


enum { FLAG_FORMAT, FLAG_MAPPING, FLAG_ORIENT, FLAG_REPEAT, FLAG_SNAP, FLAG_AGREE_ID,
       FLAG_AGREE_DEPTH, FLAG_OFFSET, FLAG_CLAMP, N_FLAGS };
static const LessonFlag FLAGS[N_FLAGS] = {
    [FLAG_FORMAT] = {"--depth-format", "FMT", "unorm16, unorm24 (default) or float32"},
    [FLAG_MAPPING] = {"--depth-mapping", "MAP",
                      "standard (1 at far, default), reversed (1 at near; --far inf allowed) or gl ([-1, 1])"},
    [FLAG_ORIENT] = {"--orientation", "HOW",
                     "flip-y (default), upper-left, both or rows: how y-down rows reach the GPU"},
    [FLAG_REPEAT] = {"--repeat", "N", "draw N times (1 to 10000) and print the time of one draw"},
    [FLAG_SNAP] = {"--snap", NULL,
                   "move each corner to the lessons' 1/256-pixel grid before the GPU sets up "
                   "depth: its planes then start from the lessons' snapped corners"},
    [FLAG_AGREE_ID] = {"--agree-id", "FILE.png",
                       "a lesson's --id-out: print how many covered pixels show the same face "
                       "(several: separated by commas)"},
    [FLAG_AGREE_DEPTH] = {"--agree-depth", "FILE.pfm",
                          "a lesson's --depth-out: the largest relative depth difference where "
                          "both show the same face (with --agree-id; one per picture)"},
    [FLAG_OFFSET] = {"--polygon-offset", "FACTOR,UNITS",
                     "glPolygonOffset(FACTOR, UNITS) on the faces in group or object `decal`"},
    [FLAG_CLAMP] = {"--offset-clamp", "C",
                    "with --polygon-offset: glPolygonOffsetClamp(FACTOR, UNITS, C)"},
};

typedef struct {
    GpuSetup setup;
    bool far_inf, snap, offset;
    long repeat;
    double factor, units, clamp; /* --polygon-offset, --offset-clamp */
} GpuOptions;

/* How many files a comma-separated list names. */
static int count_items(const char *list)
{
    int n = 1;
    for (const char *c = list; *c; c++)
        n += *c == ',';
    return n;
}

/* The k-th file (from 0) of a comma-separated list, into buf: false past
 * the end, or when it does not fit (err set). */
static bool list_item(const char *list, int k, char *buf, size_t size, Error *err)
{
    for (; k > 0 && list; k--) {
        list = strchr(list, ',');
        list = list ? list + 1 : NULL;
    }
    if (!list)
        return false;
    size_t n = strcspn(list, ",");
    if (n >= size)
        return error_set(err, "a file name of %zu characters: at most %zu", n, size - 1);
    memcpy(buf, list, n);
    buf[n] = '\0';
    return true;
}

/* One of names[0 .. n-1], by name: its index, or -1 with err set. */
static int pick(const char *flag, const char *value, const char *const *names, int n,
                Error *err)
{
    for (int i = 0; i < n; i++)
        if (strcmp(value, names[i]) == 0)
            return i;
    error_set(err, "%s: '%s' is not one of %s%s%s%s%s%s%s", flag, value, names[0],
              n > 1 ? ", " : "", n > 1 ? names[1] : "", n > 2 ? ", " : "", n > 2 ? names[2] : "",
              n > 3 ? ", " : "", n > 3 ? names[3] : "");
    return -1;
}

static bool read_gpu_options(const Options *o, GpuOptions *g, Error *err)
{
    int f = 1, m = 0, r = 0;
    const char *const *x = o->extra;
    if (x[FLAG_FORMAT] && (f = pick("--depth-format", x[FLAG_FORMAT], FORMAT_NAMES, 3, err)) < 0)
        return false;
    if (x[FLAG_MAPPING] &&
        (m = pick("--depth-mapping", x[FLAG_MAPPING], MAPPING_NAMES, 3, err)) < 0)
        return false;
    if (x[FLAG_ORIENT] && (r = pick("--orientation", x[FLAG_ORIENT], ORIENT_NAMES, 4, err)) < 0)
        return false;
    g->setup = (GpuSetup){(DepthFormat)f, (DepthMapping)m, (Orientation)r};
    g->repeat = 1;
    g->snap = x[FLAG_SNAP] != NULL;
    if (x[FLAG_REPEAT] && !parse_int("--repeat", x[FLAG_REPEAT], 1, 10000, &g->repeat, err))
        return false;
    g->offset = x[FLAG_OFFSET] != NULL;
    if (g->offset) {
        Vec3 two; /* FACTOR,UNITS read as X,Y,Z with Z = 0 appended */
        char buf[256];
        snprintf(buf, sizeof buf, "%s,0", x[FLAG_OFFSET]);
        if (strlen(x[FLAG_OFFSET]) > 200 || !strchr(x[FLAG_OFFSET], ',') ||
            !parse_vec3("--polygon-offset", buf, &two, err))
            return error_set(err, "--polygon-offset: '%.40s' is not two finite numbers "
                                  "FACTOR,UNITS", x[FLAG_OFFSET]);
        g->factor = two.x;
        g->units = two.y;
    }
    if (x[FLAG_CLAMP] && !g->offset)
        return error_set(err, "--offset-clamp needs --polygon-offset");
    if (x[FLAG_CLAMP] && !parse_double("--offset-clamp", x[FLAG_CLAMP], &g->clamp, err))
        return false;
    if (x[FLAG_AGREE_DEPTH] && !x[FLAG_AGREE_ID])
        return error_set(err, "--agree-depth needs --agree-id (depths are compared where the "
                              "faces agree)");
    if (x[FLAG_AGREE_DEPTH] && count_items(x[FLAG_AGREE_DEPTH]) != count_items(x[FLAG_AGREE_ID]))
        return error_set(err, "--agree-depth and --agree-id name different numbers of files "
                              "(%d and %d): one depth file per picture",
                         count_items(x[FLAG_AGREE_DEPTH]), count_items(x[FLAG_AGREE_ID]));
    if (g->far_inf && g->setup.mapping != MAP_REVERSED)
        return error_set(err, "--far inf needs --depth-mapping reversed (the standard mapping "
                              "puts the far plane at 1)");
    return true;
}

/* "--far inf" is taken out of the arguments before cli_parse (which takes
 * finite numbers only); the camera then keeps the scene's far plane, which
 * changes nothing but the reversed z_c, computed here with f infinite. */
static int strip_far_inf(int argc, char **argv, char **kept, bool *far_inf)
{
    int n = 0;
    *far_inf = false;
    for (int i = 0; i < argc; i++) {
        if (i > 0 && strcmp(argv[i], "--far") == 0 && i + 1 < argc &&
            (strcmp(argv[i + 1], "inf") == 0 || strcmp(argv[i + 1], "infinity") == 0)) {
            *far_inf = true;
            i++;
            continue;
        }
        kept[n++] = argv[i];
    }
    return n;
}

/* ---- The vertices: the lessons' clip space, as floats ----------------------- */


/* --snap: x_c (or y_c) moved so that the screen coordinate lands on the
 * lessons' 1/256-pixel grid, as lessons 03-05 round it (side: W or H). Only a
 * corner in front of the eye moves; the GPU still clips the others. */
static double snapped(double c, double w, int side, bool down)
{
    if (!(w > 0))
        return c;
    double ndc = c / w, s = down ? (1 - ndc) * side / 2 : (ndc + 1) * side / 2;
    double q = floor(s * 256 + 0.5) / 256;
    return (down ? 1 - 2 * q / side : 2 * q / side - 1) * w;
}

/* Every triangle of every face, in mesh order; z_c from w_c = d but for gl. */
static bool make_vertices(const Render *r, const GpuOptions *g, Vertices *v, Error *err)
{
    const Mesh *m = &r->mesh;
    double n = r->camera.near, f = r->camera.far;
    v->n = 3 * m->ntris;
    v->pos = malloc((size_t)(v->n > 0 ? v->n : 1) * 4 * sizeof *v->pos);
    v->id = malloc((size_t)(v->n > 0 ? v->n : 1) * sizeof *v->id);
    if (!v->pos || !v->id)
        return error_set(err, "out of memory for %d vertices", v->n);
    int k = 0;
    for (int i = 0; i < m->nfaces; i++) {
        const Face *face = &m->faces[i];
        for (int t = 0; t < face->count - 2; t++)
            for (int c = 0; c < 3; c++, k++) {
                Vec4 p = r->clip[face->first + m->tris[face->first_tri + t].c[c]];
                double z = p.z;
                if (g->snap) {
                    p.x = snapped(p.x, p.w, r->camera.width, false);
                    p.y = snapped(p.y, p.w, r->camera.height, true);
                }
                if (g->setup.mapping == MAP_REVERSED)
                    z = g->far_inf ? n : n * (f - p.w) / (f - n);
                else if (g->setup.mapping == MAP_STANDARD)
                    z = f * (p.w - n) / (f - n);
                bool flip = g->setup.orient == ORIENT_FLIP_Y || g->setup.orient == ORIENT_BOTH;
                v->pos[4 * k + 0] = (float)p.x;
                v->pos[4 * k + 1] = (float)(flip ? -p.y : p.y);
                v->pos[4 * k + 2] = (float)z;
                v->pos[4 * k + 3] = (float)p.w;
                v->id[k] = i;
            }
    }
    v->n = k;
    return true;
}

/* ---- Reading back: faces and view depth, the lessons' way ------------------ */

/* z_w back to the view depth d. */
static double window_to_view_depth(double z, const GpuOptions *g, double n, double f)
{
    if (g->setup.mapping == MAP_REVERSED)
        return g->far_inf ? n / z : f / (1 + z * (f - n) / n); /* z = n/(f-n) (f/d - 1) */
    return n / (1 - z * (f - n) / f);                          /* z = f/(f-n) (1 - n/d) */
}

/* face[] (NO_FACE where nothing was drawn) and depth[] (d, +inf there), top row first. */
static bool gpu_read(const GpuOptions *g, int width, int height, double near, double far,
                     int32_t *face, float *depth, Error *err)
{
    size_t npix = (size_t)width * (size_t)height;
    uint8_t *rgba = malloc(npix * 4);
    float *z = malloc(npix * sizeof *z);
    if (!rgba || !z) {
        free(rgba);
        free(z);
        return error_set(err, "out of memory reading back %dx%d pixels", width, height);
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, z);
    bool reversed_rows = g->setup.orient == ORIENT_BOTH || g->setup.orient == ORIENT_ROWS;
    for (int y = 0; y < height; y++) {
        size_t from = (size_t)(reversed_rows ? height - 1 - y : y) * (size_t)width;
        for (int x = 0; x < width; x++) {
            size_t i = (size_t)y * (size_t)width + (size_t)x, j = from + (size_t)x;
            Rgb c = {rgba[4 * j], rgba[4 * j + 1], rgba[4 * j + 2]};
            face[i] = id_colour_face(c);
            depth[i] = face[i] == NO_FACE ? INFINITY
                                          : (float)window_to_view_depth(z[j], g, near, far);
        }
    }
    free(rgba);
    free(z);
    return glGetError() == GL_NO_ERROR ||
           error_set(err, "reading the framebuffer back failed");
}

static bool write_outputs(const Render *r, const Options *o, const int32_t *face,
                          const float *depth, Error *err)
{
    int w = o->width, h = o->height;
    Image im = {0};
    bool ok = true;
    const char *outs[3] = {o->out, o->id_out, o->depth_out};
    for (int i = 0; i < 3 && ok; i++)
        ok = !outs[i] || render_make_parent_dirs(outs[i], err);
    if (ok && o->id_out) {
        ok = face_id_image(face, w, h, &im, err) && image_write_png(&im, o->id_out, err);
        image_free(&im);
    }
    if (ok && o->out) {
        ok = shade_image(&r->mesh, &r->camera, face, depth, w, h, SHADE_ID, &im, err) &&
             image_write_png(&im, o->out, err);
        image_free(&im);
    }
    if (ok && o->depth_out)
        ok = write_pfm(depth, w, h, o->depth_out, err);
    return ok;
}

/* ---- Agreement with a lesson ------------------------------------------------- */

typedef struct {
    long covered;   /* pixels that the lesson or the GPU (or both) covers */
    long same;      /* of those, the pixels where both show the same face */
    long depth_n;   /* pixels of the same face with both depths compared */
    double max_rel; /* the largest |d_lesson - d_gpu| / d_gpu among them */
    int max_x, max_y, max_face; /* where it is, and the face there */
    double max_lesson, max_gpu; /* the two depths there */
    double lesson_exact, gpu_exact; /* each one's largest relative error to exact_depth */
} Agreement;

/* The exact view depth of face at the centre of pixel (x, y): where the ray
 * through it meets the face's plane, in double. NaN when the ray runs along it. */
static double exact_depth(const Render *r, int face, int x, int y)
{
    const Mesh *m = &r->mesh;
    const Face *f = &m->faces[face];
    Vec3 pts[MESH_MAX_FACE_VERTICES < 64 ? MESH_MAX_FACE_VERTICES : 64];
    int n = f->count < 64 ? f->count : 64;
    for (int k = 0; k < n; k++)
        pts[k] = camera_to_view(&r->camera, m->verts[m->corners[f->first + k]]);
    Vec3 normal = polygon_normal(pts, n);
    const Camera *c = &r->camera;
    double x_ndc = 2 * (x + 0.5) / c->width - 1, y_ndc = 1 - 2 * (y + 0.5) / c->height;
    Vec3 dir = vec3(x_ndc / c->proj.m[0][0], y_ndc / c->proj.m[1][1], -1);
    double across = vec3_dot(normal, dir);
    return across != 0 ? vec3_dot(normal, pts[0]) / across : NAN;
}

/* Compares the lesson's pictures (id, and depth when given) with face[] and depth[]. */
static bool agree(const Render *r, const char *id_path, const char *depth_path, const int32_t *face,
                  const float *depth, int width, int height, Agreement *a, Error *err)
{
    Image im = {0};
    float *d = NULL;
    int dw = 0, dh = 0;
    if (!image_read_png_sized(&im, id_path, width, height, err))
        return false;
    if (depth_path && !read_pfm(&d, &dw, &dh, depth_path, err)) {
        image_free(&im);
        return false;
    }
    if (d && (dw != width || dh != height)) {
        image_free(&im);
        free(d);
        return error_set(err, "%s is %dx%d, the picture %dx%d", depth_path, dw, dh, width,
                         height);
    }
    *a = (Agreement){0};
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            size_t i = (size_t)y * (size_t)width + (size_t)x;
            int32_t lesson = id_colour_face(image_get(&im, x, y));
            if (lesson == NO_FACE && face[i] == NO_FACE)
                continue;
            a->covered++;
            if (lesson != face[i])
                continue;
            a->same++;
            if (d && isfinite(d[i]) && isfinite(depth[i]) && depth[i] > 0) {
                double rel = fabs((double)d[i] - (double)depth[i]) / (double)depth[i];
                double e = exact_depth(r, lesson, x, y);
                double le = fabs((double)d[i] - e) / e, ge = fabs((double)depth[i] - e) / e;
                a->lesson_exact = le > a->lesson_exact ? le : a->lesson_exact;
                a->gpu_exact = ge > a->gpu_exact ? ge : a->gpu_exact;
                if (rel > a->max_rel)
                    *a = (Agreement){a->covered, a->same, a->depth_n, rel, x, y, lesson,
                                     (double)d[i], (double)depth[i], a->lesson_exact,
                                     a->gpu_exact};
                a->depth_n++;
            }
        }
    image_free(&im);
    free(d);
    return true;
}

static void print_agreement(const Agreement *a, bool with_depth)
{
    printf("  agreement: %ld covered pixels, %ld with the same face (%.4f%%), %ld differ\n",
           a->covered, a->same, a->covered ? 100.0 * (double)a->same / (double)a->covered : 100.0,
           a->covered - a->same);
    if (with_depth)
        printf("  depth: largest relative difference %.3g over %ld pixels of the same face, "
               "at (%d,%d) on face %d: d = %.9g (lesson), %.9g (GPU)\n",
               a->max_rel, a->depth_n, a->max_x, a->max_y, a->max_face, a->max_lesson,
               a->max_gpu);
    if (with_depth)
        printf("  exact depth (the ray through the pixel centre): largest relative error "
               "%.3g (lesson), %.3g (GPU)\n", a->lesson_exact, a->gpu_exact);
}

/* ---- The run --------------------------------------------------------------------- */

/* Every triangle of a face in `decal` offset, the others not (lesson 07). */
static bool draw_with_offset(const Render *r, const GpuOptions *g, const Vertices *v,
                             double *seconds, Error *err)
{
    int ntris = v->n / 3;
    bool *biased = malloc((size_t)(ntris > 0 ? ntris : 1) * sizeof *biased);
    if (!biased)
        return error_set(err, "out of memory for %d triangles", ntris);
    for (int t = 0; t < ntris; t++)
        biased[t] = mesh_face_in(&r->mesh, v->id[3 * t], "decal");
    GpuOffset o = {biased, g->factor, g->units, g->clamp};
    bool ok = gpu_draw_offset(v->n, &o, seconds, err);
    free(biased);
    return ok;
}

static int draw_and_write(const Options *o, const GpuOptions *g, Render *r, Error *err)
{
    Vertices v = {0};
    Gpu gpu = {0};
    size_t npix = (size_t)o->width * (size_t)o->height;
    int32_t *face = malloc(npix * sizeof *face);
    float *depth = malloc(npix * sizeof *depth);
    int status = EXIT_RUN_FAILED;
    if (!face || !depth)
        error_set(err, "out of memory for %dx%d pixels", o->width, o->height);
    else if (r->mesh.nfaces > ID_MAX)
        error_set(err, "%d faces: --id-out numbers at most %d", r->mesh.nfaces, ID_MAX);
    else if (make_vertices(r, g, &v, err) && gpu_open(&gpu, err) &&
             gpu_prepare(&gpu, &g->setup, o->width, o->height, &v, err)) {
        double seconds = INFINITY; /* the fastest of g->repeat draws */
        bool drawn = true;
        for (long i = 0; i < g->repeat && drawn; i++) {
            double s = INFINITY;
            if (g->offset)
                drawn = draw_with_offset(r, g, &v, &s, err);
            else
                s = gpu_draw(v.n);
            seconds = fmin(seconds, s);
        }
        output_set_begin();
        if (drawn && gpu_read(g, o->width, o->height, r->camera.near, r->camera.far, face, depth, err) &&
            write_outputs(r, o, face, depth, err) && output_set_publish(err)) {
            status = EXIT_OK;
            printf(PROGRAM ": %s (%d faces): %d triangles drawn by %s, depth %s %s%s\n",
                   r->source, r->mesh.nfaces, v.n / 3, (const char *)glGetString(GL_RENDERER),
                   FORMAT_NAMES[g->setup.format], MAPPING_NAMES[g->setup.mapping],
                   g->far_inf ? " (far at infinity)" : "");
            if (g->repeat > 1)
                printf("  draw: %.6f s (fastest of %ld, glFinish included)\n", seconds,
                       g->repeat);
            const char *ids = o->extra[FLAG_AGREE_ID], *dps = o->extra[FLAG_AGREE_DEPTH];
            int n = ids ? count_items(ids) : 0;
            for (int k = 0; k < n; k++) {
                char id[4096], dp[4096];
                Agreement a = {0};
                if (!list_item(ids, k, id, sizeof id, err) ||
                    (dps && !list_item(dps, k, dp, sizeof dp, err)) ||
                    !agree(r, id, dps ? dp : NULL, face, depth, o->width, o->height, &a, err)) {
                    status = EXIT_RUN_FAILED;
                    break;
                }
                if (n > 1)
                    printf("  with %s:\n", id);
                print_agreement(&a, dps != NULL);
            }
        } else {
            output_set_abort();
        }
    }
    gpu_close(&gpu);
    free(v.pos);
    free(v.id);
    free(face);
    free(depth);
    return status;
}

int main(int argc, char **argv)
{
    char **kept = malloc((size_t)(argc > 0 ? argc : 1) * sizeof *kept);
    if (!kept)
        return EXIT_RUN_FAILED;
    GpuOptions g = {0};
    int kept_argc = strip_far_inf(argc, argv, kept, &g.far_inf);
    LessonCli cli = {
        .program = PROGRAM,
        .purpose = "The lessons' scene drawn by Mesa's llvmpipe through EGL and OpenGL: the "
                   "GPU reference the tests compare the lessons with.",
        .groups = CLI_SCENE | CLI_CAMERA | CLI_DEPTH_OUT | CLI_ID_OUT,
        .extra = FLAGS,
        .n_extra = N_FLAGS,
        .defaults = {.out = NULL, .width = 800, .height = 600, .scene = "inside"},
    };
    Options opt;
    Error err = {0};
    Render r;
    int status = cli_parse(&cli, kept_argc, kept, &opt);
    free(kept);
    if (status != CLI_CONTINUE)
        return status;
    if (!read_gpu_options(&opt, &g, &err))
        return error_report(PROGRAM, &err, EXIT_USAGE);
    status = render_load(&r, &opt, &err);
    if (status != EXIT_OK)
        return error_report(PROGRAM, &err, status);
    render_print_warnings(&r, PROGRAM);
    const char *outs[3] = {opt.out, opt.id_out, opt.depth_out};
    for (int i = 0; i < 3; i++)
        if (outs[i] && !output_check(outs[i], &err)) {
            render_free(&r);
            return error_report(PROGRAM, &err, EXIT_RUN_FAILED);
        }
    status = draw_and_write(&opt, &g, &r, &err);
    render_free(&r);
    return status == EXIT_OK ? EXIT_OK : error_report(PROGRAM, &err, status);
}
