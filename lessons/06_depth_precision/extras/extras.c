/* extras.c: lesson 06's flags that are not its lesson (see extras.h). */
#include "extras.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness/compare_naive.h"
#include "harness/ladder.h"
#include "ladder_picture.h"
#include "plot.h"
#include "state.h"

enum { FLAG_FORMAT, FLAG_MAPPING, FLAG_PLOT, FLAG_LADDER_OUT, FLAG_COUNT };

static const LessonFlag FLAGS[FLAG_COUNT] = {
    [FLAG_FORMAT] = {"--depth-format", "F", "what the depth buffer stores: unorm16, unorm24 "
                                            "(the default) or float32"},
    [FLAG_MAPPING] = {"--depth-mapping", "M",
                      "standard (the default: 0 at near, 1 at far), reversed (1 at near, 0 at "
                      "far; takes --far inf) or log (log(d/n) / log(f/n), per fragment)"},
    [FLAG_PLOT] = {"--precision-plot", "FILE.png",
                   "also draw the depth step against distance, every format and mapping",
                   .output = true},
    [FLAG_LADDER_OUT] = {"--ladder-out", "FILE.png",
                         "on the ladder: the picture with each band's d and a key (the back "
                         "plate's colour: a failure)",
                         .output = true},
};


DepthSetup depth_chosen(const Run *run)
{
    return depth_flags_setup(run, run->opt.extra[FLAG_FORMAT], run->opt.extra[FLAG_MAPPING]);
}

/* On the ladder: the fraction of each band's pixels where the back plate
 * won; "not drawn" for a band with no pixel (beyond the far plane, or off
 * the screen), not a fraction of nothing. */
static void note_ladder_bands(Run *run)
{
    LadderScore s;
    Target *t = &run->target;
    ladder_score_faces(t->face, (size_t)t->width * (size_t)t->height, &s);
    char line[320], share[16];
    int used = snprintf(line, sizeof line, "  back plate wins (gap %g):", LADDER_GAP);
    for (int k = 0; k < LADDER_BANDS && used > 0 && (size_t)used < sizeof line; k++) {
        if (s.back[k] + s.front[k] > 0)
            snprintf(share, sizeof share, "%.3f", ladder_wrong_fraction(&s, k));
        else
            snprintf(share, sizeof share, "not drawn");
        used += snprintf(line + used, sizeof line - (size_t)used, "%s d = %g: %s",
                         k ? "," : "", LADDER_DISTANCE[k], share);
    }
    run_note(run, "%s", line);
}

static bool on_the_ladder(const Run *run)
{
    return run->opt.scene && strcmp(run->opt.scene, "ladder") == 0;
}

static bool after_write(Run *run, Error *err)
{
    const char *plot = run->opt.extra[FLAG_PLOT], *ladder = run->opt.extra[FLAG_LADDER_OUT];
    if (on_the_ladder(run))
        note_ladder_bands(run);
    if (ladder && !write_ladder_picture(&run->render, &run->target, run->rz, ladder, err))
        return false;
    if (!plot)
        return true;
    const DepthSetup *s = &run->rz->state->depth;
    return precision_plot(plot, s->near, s->far, err);
}

static bool choose(Run *run, Error *err)
{
    if (!depth_flags_ok(run, run->opt.extra[FLAG_FORMAT], run->opt.extra[FLAG_MAPPING], true,
                        err))
        return false;
    if (run->opt.extra[FLAG_LADDER_OUT] && !on_the_ladder(run))
        return error_set(err, "--ladder-out labels the ladder's bands: it needs --scene ladder");
    run->after_write = after_write;
    return true;
}

const Extras EXTRAS = {.flags = FLAGS, .n_flags = FLAG_COUNT, .choose = choose};
