/* cli.h: the command line every lesson shares (docs/conventions.md), and the way a
 * lesson adds flags of its own.
 *
 *   --out FILE.png  --width N  --height N
 *   --scene NAME | --obj FILE.obj
 *   --eye X,Y,Z  --target X,Y,Z  --up X,Y,Z  --fovy DEG  --near N  --far F
 *   --shade flat|id|depth
 *   --depth-out FILE.pfm  --overdraw-out FILE.pgm  --id-out FILE.png  --world-out FILE.png
 *   --trace X,Y  --ascii  --compare REF.png  --steps DIR
 *   --help  --version
 *
 * Rules: sizes 1 .. 16384; numbers finite; a flag given twice, an unknown flag,
 * a missing value, a stray argument or a flag the lesson does not take is a
 * usage error: one line "<program>: error: ..." on stderr and exit status 2. */
#ifndef CLI_H
#define CLI_H

#include <stdbool.h>
#include <stdio.h>

#include "error.h"
#include "scene.h"
#include "shade.h"
#include "vecmath.h"

#define SERIES_VERSION "0.1.0"
#define CLI_CONTINUE (-1)
#define CLI_MAX_EXTRA 16

/* Groups of shared flags; a lesson names the groups it takes. --out, --width,
 * --height, --help and --version are always taken. */
enum {
    CLI_SCENE = 1 << 0,        /* --scene --obj */
    CLI_CAMERA = 1 << 1,       /* --eye --target --up --fovy --near --far */
    CLI_SHADE = 1 << 2,        /* --shade */
    CLI_DEPTH_OUT = 1 << 3,    /* --depth-out */
    CLI_OVERDRAW_OUT = 1 << 4, /* --overdraw-out */
    CLI_TRACE = 1 << 5,        /* --trace X,Y (lesson 01: --trace X) */
    CLI_ASCII = 1 << 6,        /* --ascii */
    CLI_COMPARE = 1 << 7,      /* --compare REF.png */
    CLI_STEPS = 1 << 8,        /* --steps DIR */
    CLI_WORLD_OUT = 1 << 9,    /* --world-out */
    CLI_ID_OUT = 1 << 10,      /* --id-out */
    CLI_ALL_3D = 0x7ff
};

/* A flag of one lesson's own, e.g. {"--painter", NULL, "draw back to front, no depth buffer"}.
 * An output ({"--colour-out", "FILE.png", "...", .output = true}) is checked as
 * the shared ones are, before anything is drawn: a name that is not empty nor
 * "-", and no other output or input of the run under any spelling. An output
 * the default run writes too (.default_run = "out/x.png") takes that value
 * when neither it nor --out is given, before the checks: it is checked as
 * if it had been given. */
typedef struct {
    const char *flag;
    const char *metavar; /* NULL for a switch; the value's name otherwise */
    const char *help;
    bool output;         /* its value names a file the run writes */
    const char *default_run; /* an output's file when neither it nor --out is given, or NULL */
} LessonFlag;

typedef struct {
    const char *out;
    int width, height;
    const char *scene; /* NULL when --obj is used */
    const char *obj;
    Vec3 eye, target, up;
    double fovy, near, far;
    bool eye_set, target_set, up_set, fovy_set, near_set, far_set;
    ShadeMode shade;
    const char *depth_out, *overdraw_out;
    const char *world_out; /* the scene from the side and from above (world_view.h) */
    const char *id_out; /* --id-out: face index + 1 per pixel (shade.h face_id_colour) */
    bool trace_set;
    int trace_x, trace_y; /* lesson 01 takes --trace X alone: trace_y = 0 */
    bool ascii;
    const char *compare;
    const char *steps_dir;
    /* The lesson's own flags, in the order it declared them: NULL when absent,
     * "" for a switch that was given, the value otherwise. */
    const char *extra[CLI_MAX_EXTRA];
} Options;

typedef struct {
    const char *program;        /* "02_zbuffer": messages start with it */
    const char *purpose;        /* one line for --help */
    unsigned groups;            /* CLI_* groups taken */
    const LessonFlag *extra;    /* the lesson's own flags */
    int n_extra;
    Options defaults;           /* out, width, height, scene, shade, ... */
} LessonCli;

/* Fills opt from spec->defaults and argv. Returns CLI_CONTINUE when the lesson
 * should run; otherwise the status to exit with at once: EXIT_OK after --help or
 * --version (printed on stdout), EXIT_USAGE after an error (already printed).
 *
 * A flag's value is the next argument, even when it starts with '-' (--eye -1,2,3,
 * --near -0.5 reaches the range check), but never one that starts with "--":
 * `--out --width 5` says "--out needs a value". */
int cli_parse(const LessonCli *spec, int argc, char **argv, Options *opt);

/* cli_parse without printing the error: EXIT_USAGE with err set, for tests and
 * for callers that print it themselves. --help and --version still print on stdout. */
int cli_parse_quiet(const LessonCli *spec, int argc, char **argv, Options *opt, Error *err);

/* Camera flags not given on the command line are taken from the scene; then the
 * camera is checked by camera_check (camera.h): eye != target, up not parallel to
 * the view direction, 0 < near < far, 0 < fovy < 180. False with err set
 * otherwise (a usage error). */
bool cli_resolve_camera(Options *opt, const SceneInfo *scene, Error *err);

/* Value parsers, for the lessons' own flags too. Each rejects trailing junk,
 * non-finite numbers and out-of-range values, naming the flag in err. */
bool parse_int(const char *flag, const char *s, long lo, long hi, long *out, Error *err);
bool parse_double(const char *flag, const char *s, double *out, Error *err);
bool parse_vec3(const char *flag, const char *s, Vec3 *out, Error *err);

#endif
