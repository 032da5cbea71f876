/* fuzz_flags.h: a lesson's own flags (its extras/) against any arguments,
 * for the targets fuzz_flags_NN_*.c (make fuzz FUZZ=flags).
 *
 * The bytes are split at NUL bytes into argv. The shared command line reads
 * them with the lesson's flags (EXTRAS.flags), as run_load does; when it goes
 * on, the lesson's choose() must accept them or refuse them with a message,
 * and the camera then taken from the scene in one line. What is
 * accepted, the lesson's own reading (its *_chosen)
 * turns into the lesson's state, whose numbers each target checks are in
 * range. No scene is loaded and nothing is drawn: the rasterizers have
 * targets of their own (fuzz_NN_*.c). */
#ifndef FUZZ_FLAGS_H
#define FUZZ_FLAGS_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "extras.h"
#include "fuzz_quiet.h"
#include "harness/cli.h"
#include "harness/lesson.h"
#include "harness/scene.h"

#define FUZZ_FLAGS_MAX_ARGS 32

static inline void fuzz_flags_check(bool ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "fuzz_flags: broken invariant: %s\n", what);
        abort();
    }
}

static inline bool one_line(const char *msg)
{
    return msg[0] != '\0' && strchr(msg, '\n') == NULL;
}

/* A lesson's own message may quote an argument whole, a newline too:
 * error_report prints a control character as '?', so it is one line as
 * printed. It must say something, and not be cut short. */
static inline bool a_message(const char *msg)
{
    return msg[0] != '\0' && strlen(msg) < ERROR_MSG_MAX - 1;
}

/* run read from the bytes, as run_load reads a command line, up to and with
 * the lesson's choose(): true when that accepted it. *text holds the
 * arguments the options point into; the caller frees it. */
static inline bool fuzz_flags_read(const uint8_t *data, size_t size, const char *program,
                                   Run *run, char **text)
{
    static Lesson lesson; /* what choose() may read: the program's name, its extras */
    lesson = (Lesson){.program = program, .purpose = "fuzz", .scene = "triangles3",
                      .extras = &EXTRAS};
    memset(run, 0, sizeof *run);
    run->lesson = &lesson;
    if (!(*text = malloc(size + 1)))
        return false;
    memcpy(*text, data, size);
    (*text)[size] = '\0';
    char *argv[FUZZ_FLAGS_MAX_ARGS + 2];
    int argc = 0;
    argv[argc++] = (char *)program;
    for (char *s = *text; s < *text + size && argc <= FUZZ_FLAGS_MAX_ARGS; s += strlen(s) + 1)
        argv[argc++] = s;
    argv[argc] = NULL;
    snprintf(run->default_out, sizeof run->default_out, "out/%s.png", program);
    LessonCli cli = {
        .program = program,
        .purpose = "fuzz",
        .groups = CLI_ALL_3D,
        .extra = EXTRAS.flags,
        .n_extra = EXTRAS.n_flags,
        .defaults = {.out = run->default_out, .width = 800, .height = 600,
                     .scene = "triangles3", .shade = SHADE_FLAT},
    };
    Error err;
    err.msg[0] = '\0';
    int status = cli_parse_quiet(&cli, argc, argv, &run->opt, &err);
    if (status != CLI_CONTINUE) {
        fuzz_flags_check(status == EXIT_OK || (status == EXIT_USAGE && one_line(err.msg)),
                         "the command line goes on, prints help, or refuses in one line");
        return false;
    }
    run->err.msg[0] = '\0';
    bool ok = !EXTRAS.choose || EXTRAS.choose(run, &run->err);
    fuzz_flags_check(ok || a_message(run->err.msg), "choose() refuses with a message");
    if (!ok)
        return false;
    /* Then, as render_load does, the camera flags not given come from the
     * scene (an OBJ's framing: the default scene's camera here). */
    const SceneInfo *scene = run->opt.scene ? scene_find(run->opt.scene) : NULL;
    ok = cli_resolve_camera(&run->opt, scene ? scene : scene_find("triangles3"), &run->err);
    fuzz_flags_check(ok || one_line(run->err.msg), "the camera is refused in one line");
    return ok;
}

#endif
