/* inspect.h: the tools to watch the z-buffer decide, around one render of the
 * pipeline (render.h), for every lesson from 02 on:
 *
 *   --trace X,Y     every fragment that reached pixel (X, Y), in order (trace.h)
 *   --ascii         the depth buffer as digits (ascii.h)
 *   --compare REF   this run's picture against REF.png, exit 3 if they differ (compare.h)
 *   --steps DIR     a picture and a depth picture after each face (steps.h)
 *
 * The lesson plugs in its Rasterizer and its DepthRule (depth_rule.h), and
 * adds three calls to its main.c:
 *
 *     inspect_begin(&ins, &r, &t, &RZ, &RULE, &opt, &err)        before drawing
 *     render_faces(&r, &t, &RZ, NULL, 0, inspect_after_face, &ins, &err)
 *     status = inspect_report(stdout, &ins, &t, &err)            after render_write
 *
 * Each does nothing for a flag that was not given. */
#ifndef INSPECT_H
#define INSPECT_H

#include <stdbool.h>
#include <stdio.h>

#include "cli.h"
#include "depth_rule.h"
#include "render.h"
#include "target.h"

typedef struct {
    const Render *r;
    const Rasterizer *rz;
    const DepthRule *rule;
    const Options *opt;
    int step;                 /* --steps: the number of the next frame */
    double depth_near, depth_far; /* --steps: the grey scale of every depth frame */
} Inspection;

/* Before drawing: --trace marks its pixel in t; --steps refuses a mesh of
 * more than STEPS_MAX_FACES faces and writes step 0, the cleared buffer.
 * False with err set when that fails (exit status 1). */
bool inspect_begin(Inspection *in, const Render *r, Target *t, const Rasterizer *rz,
                   const DepthRule *rule, const Options *opt, Error *err);

/* A FaceDrawnFn (render.h), data = the Inspection: with --steps, the next frame. */
bool inspect_after_face(void *inspection, const Target *t, const ScreenFace *f, Error *err);

/* After the outputs are written: prints the --trace history and the --ascii
 * picture on out, then runs --compare. Returns EXIT_OK, EXIT_IMAGES_DIFFER
 * when --compare found a difference, or EXIT_RUN_FAILED with err set. */
int inspect_report(FILE *out, const Inspection *in, const Target *t, Error *err);

#endif
