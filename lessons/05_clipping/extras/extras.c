/* extras.c: lesson 05's flags that are not its lesson (see extras.h). */
#include "extras.h"

#include <string.h>

#include "bugs.h"
#include "clipping.h"
#include "harness/compare_naive.h"
#include "scanline.h"

enum { FLAG_COMPARE_DROP, FLAG_BUG, FLAG_COUNT };

static const LessonFlag FLAGS[FLAG_COUNT] = {
    [FLAG_COMPARE_DROP] = {"--compare-drop", "FILE.png",
                           "also write where lesson 04's drop rule shows another face (magenta)",
                           .output = true},
    [FLAG_BUG] = {"--bug", "NAME", "make a classic mistake: no-clip"},
};

/* Lesson 04's rule is lesson 04's rasterizer: SCANLINE_ZBUFFER does not clip,
 * so render_faces drops every face with a corner at d <= near. */
static const Rasterizer *const DROP_RULE = &SCANLINE_ZBUFFER;

static bool write_compare_drop(Run *run, Error *err)
{
    const char *path = run->opt.extra[FLAG_COMPARE_DROP];
    long differing = 0;
    if (!compare_with_naive(&run->render, &run->opt, &CLIPPING_ZBUFFER, DROP_RULE, path,
                            &differing, err))
        return false;
    run_note(run, "  lesson 04's drop rule shows another face at %ld pixels", differing);
    return true;
}

static bool choose(Run *run, Error *err)
{
    const char *bug = run->opt.extra[FLAG_BUG], *compare = run->opt.extra[FLAG_COMPARE_DROP];
    if (bug && strcmp(bug, "no-clip") == 0) {
        run->rz = &NO_CLIP_BUG;
        run_note(run, "  bug no-clip: corners with w <= 0 were divided anyway, so faces "
                      "behind the eye were drawn mirrored through it");
    } else if (bug) {
        return error_set(err, "--bug: '%s' is not one of no-clip", bug);
    }
    if (compare)
        run->after_write = write_compare_drop;
    return true;
}

const Extras EXTRAS = {.flags = FLAGS, .n_flags = FLAG_COUNT, .choose = choose};
