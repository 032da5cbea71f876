/* extras.c: lesson 03's flags that are not its lesson (see extras.h). */
#include "extras.h"

#include <string.h>

#include "raster.h"
#include "bugs.h"
#include "harness/compare_naive.h"
#include "naive.h"

enum { FLAG_DEPTH_INTERP, FLAG_COMPARE_NAIVE, FLAG_BUG, FLAG_COUNT };

static const LessonFlag FLAGS[FLAG_COUNT] = {
    [FLAG_DEPTH_INTERP] = {"--depth-interp", "RULE",
                           "perspective (1/d linear, the default) or naive (d linear, lesson 02)"},
    [FLAG_COMPARE_NAIVE] = {"--compare-naive", "FILE.png",
                            "also write where the naive rule shows another face (magenta)",
                            .output = true},
    [FLAG_BUG] = {"--bug", "NAME", "make a classic mistake: negated-w"},
};

/* Under --bug negated-w the buffer keeps -d, with the same test. */
static const DepthRule NEGATED_DEPTH = {"depth buffer", "-d", "face", SMALLER_IS_NEARER};

static bool write_compare_naive(Run *run, Error *err)
{
    const char *path = run->opt.extra[FLAG_COMPARE_NAIVE];
    long differing = 0;
    if (!compare_with_naive(&run->render, &run->opt, &ZBUFFER, &ZBUFFER_NAIVE, path,
                            &differing, err))
        return false;
    run_note(run, "  the naive rule shows another face at %ld pixels", differing);
    return true;
}

static bool choose(Run *run, Error *err)
{
    const char *interp = run->opt.extra[FLAG_DEPTH_INTERP], *bug = run->opt.extra[FLAG_BUG];
    const char *compare = run->opt.extra[FLAG_COMPARE_NAIVE];
    if (interp && strcmp(interp, "naive") == 0) {
        run->rz = &ZBUFFER_NAIVE;
        run_note(run, "  depth-interp naive: d was interpolated linearly on the screen, "
                      "as in lesson 02");
    } else if (interp && strcmp(interp, "perspective") != 0) {
        return error_set(err, "--depth-interp: '%s' is not one of perspective, naive", interp);
    }
    if (bug && run->rz == &ZBUFFER_NAIVE)
        return error_set(err, "--bug and --depth-interp naive cannot be used together");
    if (bug && strcmp(bug, "negated-w") == 0) {
        run->rz = &NEGATED_W_BUG;
        run->rule = &NEGATED_DEPTH;
        run_note(run, "  bug negated-w: the buffer held -d, so the farthest surface won "
                      "each pixel");
    } else if (bug) {
        return error_set(err, "--bug: '%s' is not one of negated-w", bug);
    }
    if (compare)
        run->after_write = write_compare_naive;
    return true;
}

const Extras EXTRAS = {.flags = FLAGS, .n_flags = FLAG_COUNT, .choose = choose};
