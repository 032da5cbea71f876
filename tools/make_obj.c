/* make_obj: writes a built-in scene as an OBJ file (and its .mtl beside it).
 *
 *   make_obj SCENE OUT.obj
 *   make_obj knot OUT.obj [RINGS SIDES]     a finer or coarser torus knot
 *
 * The files read back with --obj give the same faces in the same order as
 * --scene SCENE, in the same objects and groups (`g decal` ...). OUT.obj may
 * be "-" (standard output), a device or a pipe: the OBJ then goes there
 * without its materials, with a warning, since a .mtl has no place beside
 * it; the summary line goes to standard error when the OBJ is on standard
 * output. Exit status: 0 written, 1 could not write, 2 bad usage. */
#include <errno.h>
#include <stdarg.h>
#include <sys/stat.h>
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "harness/file.h"
#include "harness/mesh_build.h"
#include "harness/scene.h"

#define PROGRAM "make_obj"
#define KNOT_TUBE_RADIUS 0.35 /* as the knot scene's */
#define MAX_RINGS 1000000
#define MAX_SIDES 4096

static void usage(FILE *out)
{
    fprintf(out, "usage: " PROGRAM " SCENE OUT.obj\n"
                 "       " PROGRAM " knot OUT.obj [RINGS SIDES]\n"
                 "Writes a built-in scene as OBJ, with its materials in a .mtl beside it.\n"
                 "Scenes:\n");
    for (int i = 0; i < scene_count(); i++)
        fprintf(out, "  %-15s %s\n", scene_at(i)->name, scene_at(i)->about);
}

static int usage_error(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* "make_obj: error: <what> (try --help)", exit status 2. */
static int usage_error(const char *fmt, ...)
{
    char what[ERROR_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    fprintf(stderr, PROGRAM ": error: %s (try --help)\n", what);
    return EXIT_USAGE;
}

/* A whole decimal integer in [lo, hi]. */
static bool parse_count(const char *s, long lo, long hi, int *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE || v < lo || v > hi)
        return false;
    *out = (int)v;
    return true;
}

int main(int argc, char **argv)
{
    signals_begin(PROGRAM); /* a signal from now on prints one line */
    if (argc == 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
        usage(stdout);
        return EXIT_OK;
    }
    if (argc != 3 && argc != 5)
        return usage_error("expected SCENE OUT.obj, or knot OUT.obj RINGS SIDES");
    const SceneInfo *scene = scene_find(argv[1]);
    if (!scene)
        return usage_error("no scene named '%s'", argv[1]);
    int rings = 0, sides = 0;
    if (argc == 5) {
        if (strcmp(scene->name, "knot") != 0)
            return usage_error("RINGS and SIDES are for the knot only, not '%s'", argv[1]);
        if (!parse_count(argv[3], 3, MAX_RINGS, &rings))
            return usage_error("RINGS must be an integer from 3 to %d, not '%s'", MAX_RINGS,
                               argv[3]);
        if (!parse_count(argv[4], 3, MAX_SIDES, &sides))
            return usage_error("SIDES must be an integer from 3 to %d, not '%s'", MAX_SIDES,
                               argv[4]);
    }

    Mesh m;
    mesh_init(&m);
    Error err;
    bool ok = argc == 5 ? torus_knot_mesh(&m, rings, sides, KNOT_TUBE_RADIUS, &err)
                        : scene->build(&m, &err);
    if (!ok) {
        mesh_free(&m);
        return error_report(PROGRAM, &err, argc == 5 ? EXIT_USAGE : EXIT_RUN_FAILED);
    }
    /* Standard output by any name ("-", /dev/stdout, the file it was sent
     * to): what it holds is the OBJ alone. */
    struct stat out_st, path_st;
    bool on_stdout = is_stdout_name(argv[2]) ||
                     (fstat(STDOUT_FILENO, &out_st) == 0 && stat(argv[2], &path_st) == 0 &&
                      out_st.st_dev == path_st.st_dev && out_st.st_ino == path_st.st_ino);
    bool stream = obj_path_is_stream(argv[2]);
    ok = mesh_write_obj(&m, argv[2], &err);
    if (ok && stream && m.nmaterials > 0)
        fprintf(stderr, PROGRAM ": warning: %s is not a file: the OBJ is written without its %d "
                        "materials (a .mtl has no place beside it)\n",
                argv[2], m.nmaterials);
    if (ok)
        fprintf(on_stdout ? stderr : stdout, "%s: %d vertices, %d faces, %d materials\n", argv[2],
                m.nverts, m.nfaces, stream ? 0 : m.nmaterials);
    mesh_free(&m);
    return ok ? EXIT_OK : error_report(PROGRAM, &err, EXIT_RUN_FAILED);
}
