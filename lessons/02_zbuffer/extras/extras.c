/* extras.c: lesson 02's flags that are not its lesson (see extras.h). */
#include "extras.h"

#include <string.h>

#include "bugs.h"
#include "painter.h"

enum { FLAG_PAINTER, FLAG_BUG, FLAG_COUNT };

static const LessonFlag FLAGS[FLAG_COUNT] = {
    [FLAG_PAINTER] = {"--painter", NULL, "draw back to front by mean depth, no depth buffer"},
    [FLAG_BUG] = {"--bug", "NAME", "make a classic mistake: separate-buffers or clear-zero"},
};

static bool draw_by_painter(Run *run, Error *err)
{
    return draw_painter(&run->render, &run->target, run->rz, err);
}

static bool draw_in_separate_buffers(Run *run, Error *err)
{
    return draw_separate_buffers(&run->render, &run->target, run->rz, err);
}

static bool choose(Run *run, Error *err)
{
    const char *painter = run->opt.extra[FLAG_PAINTER], *bug = run->opt.extra[FLAG_BUG];
    if (painter && bug)
        return error_set(err, "--painter and --bug cannot be used together");
    if (painter) {
        run->draw = draw_by_painter;
        run_note(run, "  painter's algorithm: faces back to front by mean depth, no depth buffer");
    } else if (bug && strcmp(bug, "separate-buffers") == 0) {
        run->draw = draw_in_separate_buffers;
        run_note(run, "  bug separate-buffers: each object had a depth buffer of its own");
    } else if (bug && strcmp(bug, "clear-zero") == 0) {
        run->rz = &CLEAR_ZERO_BUG;
        run_note(run, "  bug clear-zero: the depth buffer was cleared to 0, so no fragment passed");
    } else if (bug) {
        return error_set(err, "--bug: '%s' is not one of separate-buffers, clear-zero", bug);
    }
    if (run->draw && run->opt.steps_dir)
        return error_set(err, "--steps follows one depth buffer face by face; it cannot be "
                              "used with --painter or --bug separate-buffers");
    return true;
}

const Extras EXTRAS = {.flags = FLAGS, .n_flags = FLAG_COUNT, .choose = choose};
