/* modes.c: lesson 08's words for --z-mode, --sort and --bug, the state they
 * choose, and the shader's picture (extras.h). Lesson 09 takes them too. */
#include "modes.h"

#include <string.h>

static const char *const MODE_NAMES[] = {[Z_LATE] = "late", [Z_EARLY] = "early",
                                         [Z_PREPASS] = "prepass"};
static const char *const SORT_NAMES[] = {[SORT_NONE] = "none",
                                         [SORT_FRONT_TO_BACK] = "front-to-back",
                                         [SORT_BACK_TO_FRONT] = "back-to-front"};

const char *z_mode_name(ZMode mode)
{
    return MODE_NAMES[mode];
}

const char *sort_name(SortOrder sort)
{
    return SORT_NAMES[sort];
}

static int find_name(const char *name, const char *const *names, int n)
{
    for (int i = 0; i < n; i++)
        if (strcmp(name, names[i]) == 0)
            return i;
    return -1;
}

bool early_z_flags_ok(Run *run, const char *mode, const char *sort, const char *bug, Error *err)
{
    if (run->opt.steps_dir) /* crowd has more faces than --steps takes, and a prepass draws twice */
        return error_set(err, "--steps does not apply to %s (the work it counts is per "
                              "fragment, not per face: see --shade-count-out)", run->lesson->program);
    if (mode && find_name(mode, MODE_NAMES, 3) < 0)
        return error_set(err, "--z-mode: '%s' is not one of late, early, prepass", mode);
    if (sort && find_name(sort, SORT_NAMES, 3) < 0)
        return error_set(err, "--sort: '%s' is not one of none, front-to-back, back-to-front",
                         sort);
    if (bug && strcmp(bug, "early-z-with-discard") != 0)
        return error_set(err, "--bug: '%s' is not one of early-z-with-discard", bug);
    if (bug)
        run_note(run, "  bug early-z-with-discard: cutouts were tested and wrote depth before "
                      "their shader discarded, so their holes hide what is behind them");
    return true;
}

LessonState early_z_state(const Run *run, const char *mode, const char *sort, const char *bug)
{
    LessonState s = {.depth = depth_setup(UNORM24, STANDARD, run->opt.near, run->opt.far)};
    EarlyZ *z = &s.early_z;
    z->mode = mode ? (ZMode)find_name(mode, MODE_NAMES, 3) : Z_EARLY;
    z->sort = sort ? (SortOrder)find_name(sort, SORT_NAMES, 3) : SORT_NONE;
    z->bug_discard = bug != NULL;
    return s;
}

bool write_colour(const EarlyZ *z, int width, int height, const char *path, Error *err)
{
    Image im;
    if (!image_init(&im, width, height, err))
        return false;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++)
            image_set(&im, x, y, z->colour[(size_t)y * (size_t)width + (size_t)x]);
    bool ok = render_make_parent_dirs(path, err) && image_write_png(&im, path, err);
    image_free(&im);
    return ok;
}
