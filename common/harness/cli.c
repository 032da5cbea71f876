/* cli.c: see cli.h.
 *
 * The arguments are read left to right, once. Each shared flag has a row in
 * SHARED_FLAGS saying which group it belongs to; a lesson takes a flag only when
 * it names that group. Checks that need two flags (--trace against the image
 * size) wait until every flag has been read. */
#include "cli.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ascii.h"
#include "camera.h"
#include "compare.h"
#include "file.h"
#include "image_io.h"

/* The camera that frames a mesh when the lesson has no scene to borrow one from:
 * three units back along +Z, looking at the origin. */
#define DEFAULT_EYE vec3(0, 0, 3)
#define DEFAULT_TARGET vec3(0, 0, 0)
#define DEFAULT_UP vec3(0, 1, 0)
#define DEFAULT_FOVY 60.0
#define DEFAULT_NEAR 0.1
#define DEFAULT_FAR 100.0

/* A value quoted in a message is cut to this many characters. */
#define QUOTE_MAX 48

typedef enum {
    FLAG_OUT, FLAG_WIDTH, FLAG_HEIGHT,
    FLAG_SCENE, FLAG_OBJ,
    FLAG_EYE, FLAG_TARGET, FLAG_UP, FLAG_FOVY, FLAG_NEAR, FLAG_FAR,
    FLAG_SHADE, FLAG_DEPTH_OUT, FLAG_ID_OUT, FLAG_OVERDRAW_OUT, FLAG_TRACE, FLAG_ASCII,
    FLAG_COMPARE, FLAG_STEPS, FLAG_WORLD_OUT,
    FLAG_HELP, FLAG_VERSION,
    SHARED_FLAG_COUNT
} SharedFlagId;

typedef struct {
    const char *flag;
    unsigned group;      /* CLI_* group; 0 for the flags every lesson takes */
    const char *metavar; /* NULL for a switch */
    const char *help;
} SharedFlag;

static const SharedFlag SHARED_FLAGS[SHARED_FLAG_COUNT] = {
    [FLAG_OUT] = {.flag = "--out", .group = 0, .metavar = "FILE.png",
                  .help = "where the picture goes"},
    [FLAG_WIDTH] = {.flag = "--width", .group = 0, .metavar = "N",
                    .help = "image width in pixels, 1 to 16384"},
    [FLAG_HEIGHT] = {.flag = "--height", .group = 0, .metavar = "N",
                     .help = "image height in pixels, 1 to 16384"},
    [FLAG_SCENE] = {.flag = "--scene", .group = CLI_SCENE, .metavar = "NAME",
                    .help = "a built-in scene to draw, listed below"},
    [FLAG_OBJ] = {.flag = "--obj", .group = CLI_SCENE, .metavar = "FILE.obj",
                  .help = "draw the mesh of an OBJ file instead"},
    [FLAG_EYE] = {.flag = "--eye", .group = CLI_CAMERA, .metavar = "X,Y,Z",
                  .help = "where the camera is"},
    [FLAG_TARGET] = {.flag = "--target", .group = CLI_CAMERA, .metavar = "X,Y,Z",
                     .help = "the point it looks at"},
    [FLAG_UP] = {.flag = "--up", .group = CLI_CAMERA, .metavar = "X,Y,Z",
                 .help = "which way is up on the screen"},
    [FLAG_FOVY] = {.flag = "--fovy", .group = CLI_CAMERA, .metavar = "DEG",
                   .help = "vertical field of view, between 0 and 180"},
    [FLAG_NEAR] = {.flag = "--near", .group = CLI_CAMERA, .metavar = "N",
                   .help = "distance of the near plane, above 0"},
    [FLAG_FAR] = {.flag = "--far", .group = CLI_CAMERA, .metavar = "F",
                  .help = "distance of the far plane, beyond the near one"},
    [FLAG_SHADE] = {.flag = "--shade", .group = CLI_SHADE, .metavar = "MODE",
                    .help = "flat, id (a distinct colour per face) or depth (greys, near bright)"},
    [FLAG_DEPTH_OUT] = {.flag = "--depth-out", .group = CLI_DEPTH_OUT, .metavar = "FILE.pfm",
                        .help = "also write the depth buffer, as view depth d"},
    [FLAG_ID_OUT] = {.flag = "--id-out", .group = CLI_ID_OUT, .metavar = "FILE.png",
                     .help = "also write each pixel's face index + 1, as 24-bit RGB"},
    [FLAG_OVERDRAW_OUT] = {.flag = "--overdraw-out", .group = CLI_OVERDRAW_OUT,
                           .metavar = "FILE.pgm",
                           .help = "also write how many fragments each pixel tested"},
    [FLAG_TRACE] = {.flag = "--trace", .group = CLI_TRACE, .metavar = "X,Y",
                    .help = "log every fragment tested at pixel (X, Y)"},
    [FLAG_ASCII] = {.flag = "--ascii", .group = CLI_ASCII, .metavar = NULL,
                    .help = "also print the depth buffer as digits, 0 = nearest (up to 120x60)"},
    [FLAG_COMPARE] = {.flag = "--compare", .group = CLI_COMPARE, .metavar = "REF.png",
                      .help = "compare the picture with REF.png, exit 3 if they differ; the diff "
                              "picture goes next to --out as NAME.diff.png"},
    [FLAG_STEPS] = {.flag = "--steps", .group = CLI_STEPS, .metavar = "DIR",
                    .help = "save step_NNNN.png and step_NNNN_depth.png into DIR after every face"},
    [FLAG_WORLD_OUT] = {.flag = "--world-out", .group = CLI_WORLD_OUT, .metavar = "FILE.png",
                        .help = "also draw the camera, its frustum and the scene from the side "
                                "and from above (804 x 416)"},
    [FLAG_HELP] = {.flag = "--help", .group = 0, .metavar = NULL,
                   .help = "print this help and exit"},
    [FLAG_VERSION] = {.flag = "--version", .group = 0, .metavar = NULL,
                      .help = "print the version and exit"},
};

/* Why a lesson that does not take a group's flags refuses them. */
static const char *group_reason(unsigned group)
{
    switch (group) {
    case CLI_SCENE: return "it draws its own scene only";
    case CLI_CAMERA: return "it has no camera";
    case CLI_SHADE: return "it has one way of shading";
    case CLI_DEPTH_OUT: return "it writes no depth buffer";
    case CLI_ID_OUT: return "it has no faces";
    case CLI_OVERDRAW_OUT: return "it counts no overdraw";
    case CLI_TRACE: return "it traces no pixel";
    case CLI_ASCII: return "it prints no text picture";
    case CLI_COMPARE: return "it compares no pictures";
    case CLI_STEPS: return "it saves no steps";
    case CLI_WORLD_OUT: return "it draws no 3-D world";
    default: return "see --help";
    }
}

static const char *const SHADE_NAMES[] = {[SHADE_FLAT] = "flat", [SHADE_ID] = "id",
                                          [SHADE_DEPTH] = "depth"};
#define SHADE_COUNT ((int)(sizeof SHADE_NAMES / sizeof SHADE_NAMES[0]))

/* Lesson 01 draws one row of pixels: its --trace names a column only. */
static bool trace_is_column(const LessonCli *spec)
{
    return !(spec->groups & CLI_SCENE);
}

static const char *flag_metavar(const LessonCli *spec, SharedFlagId id)
{
    return id == FLAG_TRACE && trace_is_column(spec) ? "X" : SHARED_FLAGS[id].metavar;
}

/* ---- Values ---------------------------------------------------------------- */

/* s as it may appear in a message: a very long argument is cut, so that the
 * message still ends with what is wrong with it, and a control character (a
 * newline, an escape) shows as '?', so that the message stays one line. */
static const char *quoted(const char *s, char buf[QUOTE_MAX + 4])
{
    size_t n = 0;
    for (; s[n] != '\0' && n < QUOTE_MAX; n++)
        buf[n] = iscntrl((unsigned char)s[n]) ? '?' : s[n];
    strcpy(buf + n, s[n] != '\0' ? "..." : "");
    return buf;
}

/* strtol/strtod skip leading blanks; a value that starts with one is refused. */
static bool starts_like_number(const char *s)
{
    return *s != '\0' && !isspace((unsigned char)*s);
}

/* One finite number at the start of s; *end is where it stops. */
static bool read_finite(const char *s, double *v, const char **end)
{
    if (!starts_like_number(s))
        return false;
    char *e;
    double x = strtod(s, &e);
    if (e == s || !isfinite(x))
        return false;
    *v = x;
    *end = e;
    return true;
}

/* One whole number at the start of s; out of the range of long it is clamped
 * (*clamped set), so that a range check can still name it. */
static bool read_whole(const char *s, long *v, const char **end, bool *clamped)
{
    if (!starts_like_number(s))
        return false;
    char *e;
    errno = 0;
    long x = strtol(s, &e, 10);
    if (e == s)
        return false;
    *clamped = errno == ERANGE;
    *v = x;
    *end = e;
    return true;
}

bool parse_int(const char *flag, const char *s, long lo, long hi, long *out, Error *err)
{
    char q[QUOTE_MAX + 4];
    long v;
    const char *end;
    bool clamped;
    if (!read_whole(s, &v, &end, &clamped) || *end != '\0')
        return error_set(err, "%s: '%s' is not a whole number", flag, quoted(s, q));
    if (clamped || v < lo || v > hi)
        return error_set(err, "%s: %s is out of range (%ld to %ld)", flag, quoted(s, q), lo, hi);
    *out = v;
    return true;
}

bool parse_double(const char *flag, const char *s, double *out, Error *err)
{
    char q[QUOTE_MAX + 4];
    double v;
    const char *end;
    if (!read_finite(s, &v, &end) || *end != '\0')
        return error_set(err, "%s: '%s' is not a finite number", flag, quoted(s, q));
    *out = v;
    return true;
}

bool parse_vec3(const char *flag, const char *s, Vec3 *out, Error *err)
{
    char q[QUOTE_MAX + 4];
    double c[3];
    const char *p = s;
    for (int k = 0; k < 3; k++) {
        const char *end;
        char separator = k < 2 ? ',' : '\0';
        if (!read_finite(p, &c[k], &end) || *end != separator)
            return error_set(err, "%s: '%s' is not three finite numbers X,Y,Z", flag,
                             quoted(s, q));
        p = end + 1;
    }
    *out = vec3(c[0], c[1], c[2]);
    return true;
}

/* ---- Reading the command line ----------------------------------------------- */

static void print_help(const LessonCli *spec, FILE *out); /* --help, below */

typedef struct {
    const LessonCli *spec;
    Options *opt;
    Error *err;
    int argc;
    char **argv;
    int next;                          /* index of the next argument to read */
    bool seen[SHARED_FLAG_COUNT];
    bool extra_seen[CLI_MAX_EXTRA];
    long trace_x, trace_y;             /* as given; checked against the image size last */
} Parser;

static int shared_flag_id(const char *arg)
{
    for (int id = 0; id < SHARED_FLAG_COUNT; id++)
        if (strcmp(arg, SHARED_FLAGS[id].flag) == 0)
            return id;
    return -1;
}

static int extra_count(const LessonCli *spec)
{
    return spec->n_extra < CLI_MAX_EXTRA ? spec->n_extra : CLI_MAX_EXTRA;
}

static int extra_flag_index(const LessonCli *spec, const char *arg)
{
    for (int i = 0; i < extra_count(spec); i++)
        if (strcmp(arg, spec->extra[i].flag) == 0)
            return i;
    return -1;
}

/* Marks flag as seen (refusing a second time) and, for a flag with a value,
 * takes the next argument. A value may start with '-' (--eye -1,2,3) but not
 * with "--": that is the next flag, and this one's value is missing. */
static bool take_flag(Parser *p, const char *flag, bool *seen, bool has_value, const char **value)
{
    if (*seen)
        return error_set(p->err, "%s given twice", flag);
    *seen = true;
    *value = "";
    if (!has_value)
        return true;
    if (p->next >= p->argc || strncmp(p->argv[p->next], "--", 2) == 0)
        return error_set(p->err, "%s needs a value", flag);
    *value = p->argv[p->next++];
    return true;
}

static bool set_path(const char *flag, const char *value, const char *what, const char **out,
                     Error *err)
{
    if (*value == '\0')
        return error_set(err, "%s: the %s name is empty", flag, what);
    *out = value;
    return true;
}

static bool set_size(const char *flag, const char *value, int *out, Error *err)
{
    long n;
    if (!parse_int(flag, value, 1, IMAGE_MAX_SIDE, &n, err))
        return false;
    *out = (int)n;
    return true;
}

static bool set_double(const char *flag, const char *value, double *out, bool *set, Error *err)
{
    *set = true;
    return parse_double(flag, value, out, err);
}

static bool set_vec3(const char *flag, const char *value, Vec3 *out, bool *set, Error *err)
{
    *set = true;
    return parse_vec3(flag, value, out, err);
}

/* "--scene: no scene named 'x' (known: a, b, c)" */
static bool set_scene(Parser *p, const char *value)
{
    if (p->seen[FLAG_OBJ])
        return error_set(p->err, "--scene and --obj cannot be used together");
    const SceneInfo *scene = scene_find(value);
    if (scene) {
        p->opt->scene = scene->name;
        p->opt->obj = NULL;
        return true;
    }
    char known[ERROR_MSG_MAX] = "", q[QUOTE_MAX + 4];
    size_t used = 0;
    for (int i = 0; i < scene_count() && used < sizeof known; i++) {
        int n = snprintf(known + used, sizeof known - used, "%s%s", i ? ", " : "",
                         scene_at(i)->name);
        used += n > 0 ? (size_t)n : 0;
    }
    return error_set(p->err, "--scene: no scene named '%s' (known: %s)", quoted(value, q), known);
}

static bool set_obj(Parser *p, const char *value)
{
    if (p->seen[FLAG_SCENE])
        return error_set(p->err, "--scene and --obj cannot be used together");
    if (!set_path("--obj", value, "file", &p->opt->obj, p->err))
        return false;
    p->opt->scene = NULL; /* the mesh replaces the lesson's default scene */
    return true;
}

static bool set_shade(Parser *p, const char *value)
{
    for (int mode = 0; mode < SHADE_COUNT; mode++)
        if (strcmp(value, SHADE_NAMES[mode]) == 0) {
            p->opt->shade = (ShadeMode)mode;
            return true;
        }
    char q[QUOTE_MAX + 4];
    return error_set(p->err, "--shade: '%s' is not one of flat, id, depth", quoted(value, q));
}

/* "X,Y", or "X" alone for a lesson that draws one row. The range is checked
 * once --width and --height are known (check_trace). */
static bool set_trace(Parser *p, const char *value)
{
    char q[QUOTE_MAX + 4];
    bool column = trace_is_column(p->spec), clamped;
    const char *end;
    p->opt->trace_set = true;
    p->trace_y = 0;
    if (column) {
        if (!read_whole(value, &p->trace_x, &end, &clamped) || *end != '\0')
            return error_set(p->err, "--trace: '%s' is not a column X (a whole number)",
                             quoted(value, q));
        return true;
    }
    if (!read_whole(value, &p->trace_x, &end, &clamped) || *end != ',' ||
        !read_whole(end + 1, &p->trace_y, &end, &clamped) || *end != '\0')
        return error_set(p->err, "--trace: '%s' is not a pixel X,Y (two whole numbers)",
                         quoted(value, q));
    return true;
}

/* --far F, or --far inf for a lesson with reversed depth (it takes
 * --depth-mapping, lesson 06 on): the far plane at infinity, which that
 * lesson accepts with --depth-mapping reversed only. Any other lesson, and
 * any other non-finite text, gets "not a finite number". */
static bool set_far(Parser *p, const char *value)
{
    bool takes_mapping = false;
    for (int i = 0; i < p->spec->n_extra; i++)
        takes_mapping = takes_mapping || strcmp(p->spec->extra[i].flag, "--depth-mapping") == 0;
    if (takes_mapping && strcmp(value, "inf") == 0) {
        p->opt->far = INFINITY;
        p->opt->far_set = true;
        return true;
    }
    return set_double("--far", value, &p->opt->far, &p->opt->far_set, p->err);
}

static bool apply_shared_flag(Parser *p, SharedFlagId id, const char *value)
{
    Options *o = p->opt;
    Error *err = p->err;
    const char *flag = SHARED_FLAGS[id].flag;
    switch (id) {
    case FLAG_OUT: return set_path(flag, value, "file", &o->out, err);
    case FLAG_WIDTH: return set_size(flag, value, &o->width, err);
    case FLAG_HEIGHT: return set_size(flag, value, &o->height, err);
    case FLAG_SCENE: return set_scene(p, value);
    case FLAG_OBJ: return set_obj(p, value);
    case FLAG_EYE: return set_vec3(flag, value, &o->eye, &o->eye_set, err);
    case FLAG_TARGET: return set_vec3(flag, value, &o->target, &o->target_set, err);
    case FLAG_UP: return set_vec3(flag, value, &o->up, &o->up_set, err);
    case FLAG_FOVY: return set_double(flag, value, &o->fovy, &o->fovy_set, err);
    case FLAG_NEAR: return set_double(flag, value, &o->near, &o->near_set, err);
    case FLAG_FAR: return set_far(p, value);
    case FLAG_SHADE: return set_shade(p, value);
    case FLAG_DEPTH_OUT: return set_path(flag, value, "file", &o->depth_out, err);
    case FLAG_ID_OUT: return set_path(flag, value, "file", &o->id_out, err);
    case FLAG_OVERDRAW_OUT: return set_path(flag, value, "file", &o->overdraw_out, err);
    case FLAG_TRACE: return set_trace(p, value);
    case FLAG_ASCII: o->ascii = true; return true;
    case FLAG_COMPARE: return set_path(flag, value, "file", &o->compare, err);
    case FLAG_STEPS: return set_path(flag, value, "directory", &o->steps_dir, err);
    case FLAG_WORLD_OUT: return set_path(flag, value, "file", &o->world_out, err);
    case FLAG_HELP: case FLAG_VERSION: case SHARED_FLAG_COUNT: break;
    }
    return true;
}

/* "--trace: pixel (900,3) is outside the 800x600 image" */
static bool check_trace(Parser *p)
{
    Options *o = p->opt;
    if (!o->trace_set)
        return true;
    bool inside = p->trace_x >= 0 && p->trace_x < o->width && p->trace_y >= 0 &&
                  p->trace_y < o->height;
    if (!inside) {
        if (trace_is_column(p->spec))
            return error_set(p->err, "--trace: column %ld is outside the %d-pixel-wide image",
                             p->trace_x, o->width);
        return error_set(p->err, "--trace: pixel (%ld,%ld) is outside the %dx%d image",
                         p->trace_x, p->trace_y, o->width, o->height);
    }
    o->trace_x = (int)p->trace_x;
    o->trace_y = (int)p->trace_y;
    return true;
}

/* --ascii is read by eye: one character per pixel, so a small buffer only. */
static bool check_ascii(Parser *p)
{
    const Options *o = p->opt;
    if (!o->ascii)
        return true;
    if (trace_is_column(p->spec)) {
        if (o->width > ASCII_MAX_WIDTH)
            return error_set(p->err, "--ascii: the row is %d pixels wide; --ascii prints at "
                                     "most %d (use --width)", o->width, ASCII_MAX_WIDTH);
        return true;
    }
    if (o->width > ASCII_MAX_WIDTH || o->height > ASCII_MAX_HEIGHT)
        return error_set(p->err, "--ascii: the image is %dx%d; --ascii prints at most %dx%d "
                                 "(use --width and --height)", o->width, o->height,
                         ASCII_MAX_WIDTH, ASCII_MAX_HEIGHT);
    return true;
}

/* The diff picture of --compare is written next to --out: it may not be REF
 * itself (check_paths sees to --out), or the reference would be overwritten.
 * A diff name that does not fit in PATH_TEXT_MAX is not checked. */
static bool check_compare(Parser *p)
{
    const Options *o = p->opt;
    if (!o->compare || !o->out)
        return true;
    char diff[PATH_TEXT_MAX];
    if (compare_diff_path(o->out, diff, sizeof diff) &&
        same_file(o->compare, diff))
        return error_set(p->err, "--compare names %s, where the diff picture of --out goes",
                         diff);
    return true;
}

/* "-" is standard output, for --out only; the diff picture of --compare is
 * written beside --out, so --compare needs --out to name a file. */
static bool check_stdout(Parser *p)
{
    const Options *o = p->opt;
    const char *name[] = {"--depth-out", "--overdraw-out", "--id-out", "--world-out", "--obj",
                          "--compare", "--steps"};
    const char *path[] = {o->depth_out, o->overdraw_out, o->id_out, o->world_out, o->obj,
                          o->compare, o->steps_dir};
    for (size_t i = 0; i < sizeof name / sizeof name[0]; i++)
        if (is_stdout_name(path[i]))
            return error_set(p->err, "%s: '-' (standard output) is for --out only; name a file",
                             name[i]);
    if (o->compare && is_stdout_name(o->out))
        return error_set(p->err, "--compare writes its diff picture beside --out, which is "
                                 "standard output here: name a file with --out");
    return true;
}

/* An output must not replace an input, nor another output: "--obj and --out
 * both name m.obj". Files are compared by identity (file.h same_file): a.png,
 * ./a.png, sub/../a.png, a symbolic link to it (dangling or not) and a hard
 * link to it are one file, whether or not it exists yet. The diff picture
 * --compare writes beside --out counts as an output too, and so does every
 * picture --steps DIR may write (DIR/step_NNNN.png, DIR/step_NNNN_depth.png). */
static bool check_paths(Parser *p)
{
    enum { FIRST_OUTPUT = 2, DIFF = 7, SHARED_PATHS = 8, PATH_MAX_COUNT = 8 + CLI_MAX_EXTRA };
    const Options *o = p->opt;
    if (!check_stdout(p))
        return false;
    char diff[PATH_TEXT_MAX];
    bool has_diff = o->compare && o->out && compare_diff_path(o->out, diff, sizeof diff);
    const char *name[PATH_MAX_COUNT] = {"--obj", "--compare", "--out", "--depth-out",
                                        "--overdraw-out", "--id-out", "--world-out",
                                        "the diff picture of --out"};
    const char *path[PATH_MAX_COUNT] = {o->obj, o->compare, o->out, o->depth_out,
                                        o->overdraw_out, o->id_out, o->world_out,
                                        has_diff ? diff : NULL};
    int count = SHARED_PATHS;
    for (int i = 0; i < extra_count(p->spec); i++)
        if (p->spec->extra[i].output && o->extra[i]) {
            if (is_stdout_name(o->extra[i]))
                return error_set(p->err, "%s: '-' (standard output) is for --out only; name "
                                         "a file", p->spec->extra[i].flag);
            name[count] = p->spec->extra[i].flag;
            path[count++] = o->extra[i];
        }
    if (is_stdout_name(o->out))
        path[FIRST_OUTPUT] = NULL;
    for (int j = FIRST_OUTPUT; j < count; j++)
        for (int i = 0; i < j; i++)
            if (path[i] && path[j] && same_file(path[i], path[j])) {
                if (j == DIFF || i == DIFF)
                    return error_set(p->err, "%s names %s, where the diff picture of --out goes",
                                     name[j == DIFF ? i : j], path[j]);
                return error_set(p->err, "%s and %s both name %s", name[i], name[j], path[j]);
            }
    for (int i = 0; o->steps_dir && i < count; i++) {
        if (!path[i])
            continue;
        if (same_file(path[i], o->steps_dir))
            return error_set(p->err, "%s and --steps both name %s", name[i], path[i]);
        if (is_step_picture(path[i], o->steps_dir))
            return error_set(p->err, "%s names %s, where --steps writes its pictures", name[i],
                             path[i]);
    }
    return true;
}

static void print_version(const LessonCli *spec)
{
    printf("%s (hidden-surface lessons) %s\n", spec->program, SERIES_VERSION);
}

/* Reads one argument (and its value). CLI_CONTINUE to go on, else the status. */
static int read_argument(Parser *p)
{
    const LessonCli *spec = p->spec;
    const char *arg = p->argv[p->next++], *value;
    char q[QUOTE_MAX + 4];
    if (arg[0] != '-' || arg[1] == '\0') {
        error_set(p->err, "unexpected argument '%s'", quoted(arg, q));
        return EXIT_USAGE;
    }

    int id = shared_flag_id(arg);
    if (id == FLAG_HELP) {
        print_help(spec, stdout);
        return EXIT_OK;
    }
    if (id == FLAG_VERSION) {
        print_version(spec);
        return EXIT_OK;
    }
    if (id >= 0) {
        const SharedFlag *f = &SHARED_FLAGS[id];
        if (f->group && !(spec->groups & f->group)) {
            error_set(p->err, "%s does not apply to %s (%s)", f->flag, spec->program,
                      group_reason(f->group));
            return EXIT_USAGE;
        }
        if (!take_flag(p, f->flag, &p->seen[id], f->metavar != NULL, &value) ||
            !apply_shared_flag(p, (SharedFlagId)id, value))
            return EXIT_USAGE;
        return CLI_CONTINUE;
    }

    int i = extra_flag_index(spec, arg);
    if (i >= 0) {
        const LessonFlag *f = &spec->extra[i];
        if (!take_flag(p, f->flag, &p->extra_seen[i], f->metavar != NULL, &value) ||
            (f->output && !set_path(f->flag, value, "file", &value, p->err)))
            return EXIT_USAGE;
        p->opt->extra[i] = value; /* "" for a switch */
        return CLI_CONTINUE;
    }

    error_set(p->err, "unknown flag '%s' (try --help)", quoted(arg, q));
    return EXIT_USAGE;
}

int cli_parse_quiet(const LessonCli *spec, int argc, char **argv, Options *opt, Error *err)
{
    Error local;
    Parser p = {.spec = spec, .opt = opt, .err = err ? err : &local, .argc = argc,
                .argv = argv, .next = 1};
    *opt = spec->defaults;
    while (p.next < argc) {
        int status = read_argument(&p);
        if (status != CLI_CONTINUE)
            return status;
    }
    for (int i = 0; i < extra_count(spec); i++) /* the default run's own outputs */
        if (spec->extra[i].output && spec->extra[i].default_run && !opt->extra[i] &&
            !p.seen[FLAG_OUT])
            opt->extra[i] = spec->extra[i].default_run;
    if (!check_trace(&p) || !check_ascii(&p) || !check_compare(&p) || !check_paths(&p))
        return EXIT_USAGE;
    return CLI_CONTINUE;
}

int cli_parse(const LessonCli *spec, int argc, char **argv, Options *opt)
{
    Error err;
    int status = cli_parse_quiet(spec, argc, argv, opt, &err);
    if (status == EXIT_USAGE)
        return error_report(spec->program, &err, EXIT_USAGE);
    return status;
}

/* ---- --help ----------------------------------------------------------------- */

static bool takes_flag(const LessonCli *spec, SharedFlagId id)
{
    return SHARED_FLAGS[id].group == 0 || (spec->groups & SHARED_FLAGS[id].group);
}

static int flag_column_width(const LessonCli *spec)
{
    int widest = 0;
    for (int id = 0; id < SHARED_FLAG_COUNT; id++) {
        const char *mv = flag_metavar(spec, (SharedFlagId)id);
        int w = (int)strlen(SHARED_FLAGS[id].flag) + (mv ? 1 + (int)strlen(mv) : 0);
        if (takes_flag(spec, (SharedFlagId)id) && w > widest)
            widest = w;
    }
    for (int i = 0; i < extra_count(spec); i++) {
        const LessonFlag *f = &spec->extra[i];
        int w = (int)strlen(f->flag) + (f->metavar ? 1 + (int)strlen(f->metavar) : 0);
        if (w > widest)
            widest = w;
    }
    return widest + 2;
}

static void print_flag(FILE *out, int column, const char *flag, const char *metavar,
                       const char *help, const char *default_text)
{
    char name[128];
    snprintf(name, sizeof name, "%s%s%s", flag, metavar ? " " : "", metavar ? metavar : "");
    fprintf(out, "  %-*s%s%s\n", column, name, help, default_text);
}

/* " (default: ...)" for the flags whose default the lesson chose. */
static const char *default_text(const LessonCli *spec, SharedFlagId id, char buf[160])
{
    const Options *d = &spec->defaults;
    buf[0] = '\0';
    switch (id) {
    case FLAG_OUT:
        if (d->out)
            snprintf(buf, 160, " (default: %s)", d->out);
        break;
    case FLAG_WIDTH: snprintf(buf, 160, " (default: %d)", d->width); break;
    case FLAG_HEIGHT: snprintf(buf, 160, " (default: %d)", d->height); break;
    case FLAG_SCENE:
        if (d->scene)
            snprintf(buf, 160, " (default: %s)", d->scene);
        break;
    case FLAG_EYE:
        if (spec->groups & CLI_SCENE)
            snprintf(buf, 160, " (default: the scene's camera)");
        break;
    case FLAG_SHADE:
        if ((int)d->shade >= 0 && (int)d->shade < SHADE_COUNT)
            snprintf(buf, 160, " (default: %s)", SHADE_NAMES[d->shade]);
        break;
    default: break;
    }
    return buf;
}

/* The --help text: usage, the lesson's purpose, the flags it takes (its own
 * included), the built-in scenes when it takes --scene, the exit statuses. */
static void print_help(const LessonCli *spec, FILE *out)
{
    int column = flag_column_width(spec);
    char buf[160];
    fprintf(out, "Usage: %s [options]\n", spec->program);
    if (spec->purpose)
        fprintf(out, "%s\n", spec->purpose);

    fprintf(out, "\nOptions:\n");
    for (int id = 0; id < SHARED_FLAG_COUNT; id++) {
        if (!takes_flag(spec, (SharedFlagId)id))
            continue;
        const char *help = SHARED_FLAGS[id].help;
        if (id == FLAG_TRACE && trace_is_column(spec))
            help = "log every fragment tested at column X";
        if (id == FLAG_ASCII && trace_is_column(spec))
            help = "also print the buffer as digits, 0 = nearest (up to 120 columns)";
        if (id == FLAG_STEPS && trace_is_column(spec))
            help = "save step_NNNN.png and step_NNNN_depth.png into DIR after every segment";
        print_flag(out, column, SHARED_FLAGS[id].flag, flag_metavar(spec, (SharedFlagId)id),
                   help, default_text(spec, (SharedFlagId)id, buf));
    }

    if (extra_count(spec) > 0) {
        fprintf(out, "\nOptions of this lesson:\n");
        for (int i = 0; i < extra_count(spec); i++)
            print_flag(out, column, spec->extra[i].flag, spec->extra[i].metavar,
                       spec->extra[i].help ? spec->extra[i].help : "", "");
    }

    if (spec->groups & CLI_SCENE) {
        fprintf(out, "\nScenes:\n");
        for (int i = 0; i < scene_count(); i++)
            print_flag(out, column, scene_at(i)->name, NULL, scene_at(i)->about, "");
    }

    fprintf(out, "\nExit status:\n"
                 "  0  success\n"
                 "  1  failure while running: a missing file, a malformed OBJ line,"
                 " an unwritable output\n"
                 "  2  bad command line\n");
    if (spec->groups & CLI_COMPARE)
        fprintf(out, "  3  --compare found a difference\n");
    fprintf(out, "  128+N  stopped by signal N (130: Ctrl-C, 143: SIGTERM)\n");
}

/* ---- The camera ---------------------------------------------------------------- */

/* Camera flags not given come from the scene, or from the default camera. */
static void fill_camera(Options *o, const SceneInfo *scene)
{
    if (!o->eye_set)
        o->eye = scene ? scene->eye : DEFAULT_EYE;
    if (!o->target_set)
        o->target = scene ? scene->target : DEFAULT_TARGET;
    if (!o->up_set)
        o->up = scene ? scene->up : DEFAULT_UP;
    if (!o->fovy_set)
        o->fovy = scene ? scene->fovy : DEFAULT_FOVY;
    if (!o->near_set)
        o->near = scene ? scene->near : DEFAULT_NEAR;
    if (!o->far_set)
        o->far = scene ? scene->far : DEFAULT_FAR;
}

bool cli_resolve_camera(Options *opt, const SceneInfo *scene, Error *err)
{
    bool near_alone = opt->near_set && !opt->far_set;
    fill_camera(opt, scene);
    /* --near alone past the scene's or the model's far plane: named, not --far. */
    if (near_alone && opt->near > 0 && !(opt->far > opt->near))
        return error_set(err, "--near: %g is out of range (not before the far plane of the "
                              "scene or model, %g: give --far too)", opt->near, opt->far);
    return camera_check(opt->eye, opt->target, opt->up, opt->fovy, opt->near, opt->far,
                        opt->width, opt->height, err);
}
