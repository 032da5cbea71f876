/* extras.c: lesson 08's flags, the shader's picture and the heat map (see
 * extras.h). */
#include "extras.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/cli.h"
#include "harness/compare_naive.h"
#include "harness/font.h"

enum { FLAG_Z_MODE, FLAG_SORT, FLAG_BUG, FLAG_COLOUR_OUT, FLAG_HEAT_OUT, FLAG_COUNT };

static const LessonFlag FLAGS[FLAG_COUNT] = {
    [FLAG_Z_MODE] = {"--z-mode", "M", "late (shade, then test), early (the default: test, then "
                                      "shade what passed) or prepass (depth first, then shade "
                                      "where equal)"},
    [FLAG_SORT] = {"--sort", "S", "none (mesh order, the default), front-to-back or "
                                  "back-to-front, by the view depth of each face's centre"},
    [FLAG_BUG] = {"--bug", "NAME", "make a classic mistake: early-z-with-discard"},
    [FLAG_COLOUR_OUT] = {"--colour-out", "FILE.png", "the picture the fragment shader wrote",
                         .output = true},
    [FLAG_HEAT_OUT] = {"--shade-count-out", "FILE.png",
                       "heat map of how many times each pixel was shaded, with a legend",
                       .output = true},
};

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

LessonState early_z_chosen(const Run *run)
{
    const char *const *x = run->opt.extra;
    LessonState s = {.depth = depth_setup(UNORM24, STANDARD, run->opt.near, run->opt.far)};
    EarlyZ *z = &s.early_z;
    z->mode = x[FLAG_Z_MODE] ? (ZMode)find_name(x[FLAG_Z_MODE], MODE_NAMES, 3) : Z_EARLY;
    z->sort = x[FLAG_SORT] ? (SortOrder)find_name(x[FLAG_SORT], SORT_NAMES, 3) : SORT_NONE;
    z->bug_discard = x[FLAG_BUG] != NULL;
    return s;
}

static bool write_colour(const EarlyZ *z, int width, int height, const char *path, Error *err)
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

static bool after_write(Run *run, Error *err)
{
    const EarlyZ *z = &run->rz->state->early_z;
    const char *colour = run->opt.extra[FLAG_COLOUR_OUT], *heat = run->opt.extra[FLAG_HEAT_OUT];
    int w = run->target.width, h = run->target.height;
    return (!colour || write_colour(z, w, h, colour, err)) &&
           (!heat || write_heat_map(z->shade_count, w, h, heat, err));
}

static bool choose(Run *run, Error *err)
{
    const char *const *x = run->opt.extra;
    if (run->opt.steps_dir) /* crowd has more faces than --steps takes, and a prepass draws twice */
        return error_set(err, "--steps does not apply to 08_early_z (the work it counts is per "
                              "fragment, not per face: see --shade-count-out)");
    if (x[FLAG_Z_MODE] && find_name(x[FLAG_Z_MODE], MODE_NAMES, 3) < 0)
        return error_set(err, "--z-mode: '%s' is not one of late, early, prepass", x[FLAG_Z_MODE]);
    if (x[FLAG_SORT] && find_name(x[FLAG_SORT], SORT_NAMES, 3) < 0)
        return error_set(err, "--sort: '%s' is not one of none, front-to-back, back-to-front",
                         x[FLAG_SORT]);
    if (x[FLAG_BUG] && strcmp(x[FLAG_BUG], "early-z-with-discard") != 0)
        return error_set(err, "--bug: '%s' is not one of early-z-with-discard", x[FLAG_BUG]);
    if (x[FLAG_BUG])
        run_note(run, "  bug early-z-with-discard: cutouts were tested and wrote depth before "
                      "their shader discarded, so their holes hide what is behind them");
    run->after_write = after_write;
    return true;
}

const Extras EXTRAS = {.flags = FLAGS, .n_flags = FLAG_COUNT, .choose = choose};
