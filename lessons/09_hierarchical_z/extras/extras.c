/* extras.c: lesson 09's flags (lesson 08's and its own), the shader's
 * picture and the heat map (see extras.h). */
#include "extras.h"
#include "modes.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/cli.h"
#include "harness/compare_naive.h"
#include "harness/font.h"

enum { FLAG_TILE, FLAG_HIZ_UPDATE, FLAG_HIZ_OUT, FLAG_SKIP_OUT, FLAG_Z_MODE, FLAG_SORT, FLAG_BUG,
       FLAG_COLOUR_OUT, FLAG_HEAT_OUT, FLAG_COUNT };

/* Where the default run (no --out) also puts --skip-out's picture. */
#define DEFAULT_SKIP_OUT "out/09_hierarchical_z_skips.png"

static const LessonFlag FLAGS[FLAG_COUNT] = {
    [FLAG_TILE] = {"--tile", "N", "the side of a tile of the hierarchical Z, in pixels, 1 to 64 "
                                  "(default: 8)"},
    [FLAG_HIZ_UPDATE] = {"--hiz-update", "U", "conservative (the default: a tile takes a new "
                                              "farthest value only from a triangle that covers it "
                                              "whole) or exact (every tile drawn into is read again)"},
    [FLAG_HIZ_OUT] = {"--hiz-out", "FILE.png", "the tile buffer: each tile in the grey of the "
                                               "farthest depth it holds, with a legend",
                      .output = true},
    [FLAG_SKIP_OUT] = {"--skip-out", "FILE.png",
                       "the picture, each tile tinted by how many triangles it skipped, with a "
                       "legend (the default run: " DEFAULT_SKIP_OUT ")",
                       .output = true, .default_run = DEFAULT_SKIP_OUT},
    EARLY_Z_FLAGS,
};

LessonState early_z_chosen(const Run *run)
{
    const char *const *x = run->opt.extra;
    return early_z_state(run, x[FLAG_Z_MODE], x[FLAG_SORT], x[FLAG_BUG]);
}

int tile_chosen(const Run *run)
{
    const char *tile = run->opt.extra[FLAG_TILE];
    return tile ? atoi(tile) : 8; /* checked by choose() */
}

bool exact_chosen(const Run *run)
{
    const char *update = run->opt.extra[FLAG_HIZ_UPDATE];
    return update && strcmp(update, "exact") == 0;
}

static bool after_write(Run *run, Error *err)
{
    const EarlyZ *z = &run->rz->state->early_z;
    const char *colour = run->opt.extra[FLAG_COLOUR_OUT], *heat = run->opt.extra[FLAG_HEAT_OUT];
    const char *hiz = run->opt.extra[FLAG_HIZ_OUT], *skips = run->opt.extra[FLAG_SKIP_OUT];
    int w = run->target.width, h = run->target.height;
    return (!colour || write_colour(z, w, h, colour, err)) &&
           (!heat || write_heat_map(z->shade_count, w, h, heat, err)) &&
           (!hiz || write_hiz_picture(&run->target, run->rz->state, hiz, err)) &&
           (!skips || write_skip_picture(&run->render, &run->target, run->rz->state, skips, err));
}

static bool choose(Run *run, Error *err)
{
    const char *const *x = run->opt.extra;
    long tile;
    if (x[FLAG_TILE] && !parse_int("--tile", x[FLAG_TILE], 1, 64, &tile, err))
        return false;
    if (x[FLAG_HIZ_UPDATE] && strcmp(x[FLAG_HIZ_UPDATE], "exact") != 0 &&
        strcmp(x[FLAG_HIZ_UPDATE], "conservative") != 0)
        return error_set(err, "--hiz-update: '%s' is not one of conservative, exact",
                         x[FLAG_HIZ_UPDATE]);
    if (!early_z_flags_ok(run, x[FLAG_Z_MODE], x[FLAG_SORT], x[FLAG_BUG], err))
        return false;
    run->after_write = after_write;
    return true;
}

const Extras EXTRAS = {.flags = FLAGS, .n_flags = FLAG_COUNT, .choose = choose};
