/* extras.c: lesson 08's flags, the shader's picture and the heat map (see
 * extras.h). */
#include "extras.h"
#include "modes.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/cli.h"
#include "harness/compare_naive.h"
#include "harness/font.h"

enum { FLAG_Z_MODE, FLAG_SORT, FLAG_BUG, FLAG_COLOUR_OUT, FLAG_HEAT_OUT, FLAG_COUNT };

static const LessonFlag FLAGS[FLAG_COUNT] = {
    EARLY_Z_FLAGS,
};

LessonState early_z_chosen(const Run *run)
{
    const char *const *x = run->opt.extra;
    return early_z_state(run, x[FLAG_Z_MODE], x[FLAG_SORT], x[FLAG_BUG]);
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
    if (!early_z_flags_ok(run, x[FLAG_Z_MODE], x[FLAG_SORT], x[FLAG_BUG], err))
        return false;
    run->after_write = after_write;
    return true;
}

const Extras EXTRAS = {.flags = FLAGS, .n_flags = FLAG_COUNT, .choose = choose};
