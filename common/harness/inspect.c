/* inspect.c: see inspect.h. */
#include "inspect.h"

#include <math.h>
#include <stdlib.h>

#include "ascii.h"
#include "compare.h"
#include "steps.h"
#include "trace.h"

/* The grey scale of --steps: from the nearest to the farthest corner of the
 * faces that will be drawn, within the near and far planes. Every fragment's d
 * lies between its face's corners (both interpolations are weighted means), so
 * a face keeps one grey from its first frame to the last. */
static void steps_depth_range(Inspection *in)
{
    const Render *r = in->r;
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < r->mesh.nfaces; i++) {
        if (render_face_dropped(r, i))
            continue;
        ScreenFace f = render_screen_face(r, i);
        for (int k = 0; k < f.n; k++) {
            lo = fmin(lo, f.v[k].d);
            hi = fmax(hi, f.v[k].d);
        }
    }
    in->depth_near = fmax(lo, r->camera.near);
    in->depth_far = fmin(hi, r->camera.far);
}

/* Writes the next frame of --steps: the picture and the depth picture. */
static bool write_frame(Inspection *in, const Target *t, Error *err)
{
    Image picture, grey;
    float *depth = render_view_depth(t, in->rz);
    if (!depth)
        return error_set(err, "--steps: out of memory");
    bool ok = render_image(in->r, t, in->rz, in->opt->shade, &picture, err);
    if (ok && !image_init(&grey, t->width, t->height, err)) {
        image_free(&picture);
        ok = false;
    }
    if (ok) {
        depth_to_grey_between(depth, in->depth_near, in->depth_far, &grey);
        ok = steps_write(in->opt->steps_dir, in->step++, &picture, &grey, err);
        image_free(&picture);
        image_free(&grey);
    }
    free(depth);
    return ok;
}

bool inspect_begin(Inspection *in, const Render *r, Target *t, const Rasterizer *rz,
                   const DepthRule *rule, const Options *opt, Error *err)
{
    Inspection fresh = {.r = r, .rz = rz, .rule = rule, .opt = opt};
    *in = fresh;
    if (opt->trace_set)
        target_trace_pixel(t, opt->trace_x, opt->trace_y);
    if (opt->compare && !opt->out)
        return error_set(err, "--compare: there is no --out picture to compare");
    if (opt->compare && !compare_reference_readable(opt->compare, t->width, t->height, err))
        return false;
    if (!opt->steps_dir)
        return true;
    if (r->mesh.nfaces > STEPS_MAX_FACES)
        return error_set(err, "--steps: the mesh has %d faces; --steps writes two pictures "
                              "per face and takes at most %d faces",
                         r->mesh.nfaces, STEPS_MAX_FACES);
    steps_depth_range(in);
    return write_frame(in, t, err); /* step 0: the cleared buffer */
}

bool inspect_after_face(void *inspection, const Target *t, const ScreenFace *f, Error *err)
{
    Inspection *in = inspection;
    (void)f;
    return !in->opt->steps_dir || write_frame(in, t, err);
}

static void print_trace(FILE *out, const Inspection *in, const Target *t)
{
    int x = in->opt->trace_x, y = in->opt->trace_y;
    size_t i = (size_t)y * (size_t)t->width + (size_t)x;
    char where[64];
    snprintf(where, sizeof where, "pixel (%d,%d)", x, y);
    trace_print(out, &t->trace, in->rule, where, t->face[i], t->depth[i]);
}

/* The stored values --ascii prints: NAN where no face won the pixel. */
static bool print_ascii(FILE *out, const Inspection *in, const Target *t, Error *err)
{
    size_t n = (size_t)t->width * (size_t)t->height;
    float *values = malloc(n * sizeof *values);
    if (!values)
        return error_set(err, "--ascii: out of memory");
    for (size_t i = 0; i < n; i++)
        values[i] = t->face[i] == NO_FACE ? NAN : t->depth[i];
    ascii_print(out, values, t->width, t->height, in->rule);
    free(values);
    return true;
}

static int run_compare(FILE *out, const Inspection *in, const Target *t, Error *err)
{
    Image picture;
    if (!in->opt->out) {
        error_set(err, "--compare: there is no --out picture to compare");
        return EXIT_RUN_FAILED;
    }
    if (!render_image(in->r, t, in->rz, in->opt->shade, &picture, err))
        return EXIT_RUN_FAILED;
    int status = compare_picture(out, &picture, in->opt->compare, in->opt->out, err);
    image_free(&picture);
    return status;
}

int inspect_report(FILE *out, const Inspection *in, const Target *t, Error *err)
{
    const Options *opt = in->opt;
    if (opt->trace_set)
        print_trace(out, in, t);
    if (opt->ascii && !print_ascii(out, in, t, err))
        return EXIT_RUN_FAILED;
    if (opt->compare)
        return run_compare(out, in, t, err);
    return EXIT_OK;
}
