/* lesson.h: the program around a lesson of the 3-D series (02 on). A
 * lesson's main.c is its outline, one call per step:
 *     run_load      the command line, the scene, the camera, the buffers
 *     rz->clear     the lesson's clear_depth (rz->state: the lesson's own, 06 on)
 *     run_draw      every face in mesh order through the lesson's draw_face
 *     run_write     the pictures asked for (--out, --depth-out, ...)
 *     run_report    the summary, then --trace, --ascii and --compare
 *     run_end       publishes every output (or none), frees; returns the status
 * A lesson's extras/ (bugs on purpose, comparisons) plug in through Extras. */
#ifndef LESSON_H
#define LESSON_H

#include "inspect.h"
#include "rasterizer.h"
#include "render.h"

#define RUN_GO (-1) /* run_load: go on and draw */
typedef struct Run Run;

typedef struct {
    const LessonFlag *flags; /* the extras' own flags */
    int n_flags;
    bool (*choose)(Run *run, Error *err); /* once they are read; false: a usage error */
} Extras;

typedef struct {
    const char *program, *purpose;   /* "02_zbuffer"; one line for --help */
    const char *scene;               /* drawn when no --scene or --obj is given */
    const Rasterizer *rasterizer;    /* the lesson's depth buffer */
    DepthRule depth_rule;            /* its words for --trace and --ascii */
    const Extras *extras;            /* NULL when there are none */
    void (*report)(const Target *t, const LessonState *s); /* lines under the summary, or NULL */
} Lesson;

struct Run {
    const Lesson *lesson;
    Options opt;
    Render render;
    Target target;
    Inspection inspection;
    Rasterizer rasterizer; /* the lesson's: its state set by main.c (06 on) */
    const Rasterizer *rz;  /* &rasterizer, unless an extra chose another */
    const DepthRule *rule; /* likewise */
    bool (*draw)(Run *run, Error *err);        /* an extra's way to draw, or NULL */
    bool (*after_write)(Run *run, Error *err); /* an extra's output, or NULL */
    char note[2048];                           /* extras' lines under the summary */
    char default_out[64];                      /* "out/<program>.png" */
    Error err;
    int status; /* RUN_GO until run_report, or a failure, gives the exit status */
};

int run_load(Run *run, const Lesson *lesson, int argc, char **argv); /* RUN_GO or a status */
bool run_draw(Run *run);
bool run_write(Run *run);
bool run_report(Run *run);
int run_end(Run *run);
void run_note(Run *run, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif
