/* extras.c: lesson 06's flags that are not its lesson (see extras.h). */
#include "extras.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness/compare_naive.h"
#include "harness/ladder.h"
#include "plot.h"
#include "state.h"

enum { FLAG_FORMAT, FLAG_MAPPING, FLAG_PLOT, FLAG_COUNT };

static const LessonFlag FLAGS[FLAG_COUNT] = {
    [FLAG_FORMAT] = {"--depth-format", "F", "what the depth buffer stores: unorm16, unorm24 "
                                            "(the default) or float32"},
    [FLAG_MAPPING] = {"--depth-mapping", "M", "standard (the default: 0 at near, 1 at far) or "
                                              "reversed (1 at near, 0 at far; takes --far inf)"},
    [FLAG_PLOT] = {"--precision-plot", "FILE.png",
                   "also draw the depth step against distance, every format and mapping",
                   .output = true},
};

static const char *const FORMAT_NAMES[] = {[UNORM16] = "unorm16", [UNORM24] = "unorm24",
                                           [FLOAT32] = "float32"};
static const char *const MAPPING_NAMES[] = {[STANDARD] = "standard", [REVERSED] = "reversed"};

/* A finite stand-in for the camera and the clipper when --far is inf: clip
 * space needs a number there; the depth mapping uses infinity itself. */
#define FAR_AT_INFINITY 1e30

static const DepthRule REVERSED_RULE = {"depth buffer", "z_w", "face", LARGER_IS_NEARER};

const char *format_name(DepthFormat format)
{
    return FORMAT_NAMES[format];
}

const char *mapping_name(DepthMapping mapping)
{
    return MAPPING_NAMES[mapping];
}

/* The index of name in names[0 .. n-1], or -1. */
static int find_name(const char *name, const char *const *names, int n)
{
    for (int i = 0; i < n; i++)
        if (strcmp(name, names[i]) == 0)
            return i;
    return -1;
}

DepthSetup depth_chosen(const Run *run)
{
    const char *f = run->opt.extra[FLAG_FORMAT], *m = run->opt.extra[FLAG_MAPPING];
    int format = f ? find_name(f, FORMAT_NAMES, 3) : UNORM24;
    int mapping = m ? find_name(m, MAPPING_NAMES, 2) : STANDARD;
    /* --far inf, which only the reversed mapping takes, stands as FAR_AT_INFINITY
     * in clip space; a finite far that large is finite in the standard one. */
    double far = mapping == REVERSED && run->opt.far >= FAR_AT_INFINITY ? INFINITY : run->opt.far;
    return depth_setup((DepthFormat)format, (DepthMapping)mapping, run->opt.near, far);
}

/* On the ladder: the fraction of each band's pixels where the back plate won. */
static void note_ladder_bands(Run *run)
{
    LadderScore s;
    Target *t = &run->target;
    ladder_score_faces(t->face, (size_t)t->width * (size_t)t->height, &s);
    char line[256];
    int used = snprintf(line, sizeof line, "  back plate wins (gap %g):", LADDER_GAP);
    for (int k = 0; k < LADDER_BANDS && used > 0 && (size_t)used < sizeof line; k++)
        used += snprintf(line + used, sizeof line - (size_t)used, "%s d = %g: %.3f",
                         k ? "," : "", LADDER_DISTANCE[k], ladder_wrong_fraction(&s, k));
    run_note(run, "%s", line);
}

static bool after_write(Run *run, Error *err)
{
    const char *plot = run->opt.extra[FLAG_PLOT];
    if (run->opt.scene && strcmp(run->opt.scene, "ladder") == 0)
        note_ladder_bands(run);
    if (!plot)
        return true;
    const DepthSetup *s = &run->rz->state->depth;
    return precision_plot(plot, s->near, s->far, err);
}

static bool choose(Run *run, Error *err)
{
    const char *f = run->opt.extra[FLAG_FORMAT], *m = run->opt.extra[FLAG_MAPPING];
    if (f && find_name(f, FORMAT_NAMES, 3) < 0)
        return error_set(err, "--depth-format: '%s' is not one of unorm16, unorm24, float32", f);
    if (m && find_name(m, MAPPING_NAMES, 2) < 0)
        return error_set(err, "--depth-mapping: '%s' is not one of standard, reversed", m);
    bool reversed = m && strcmp(m, "reversed") == 0;
    if (isinf(run->opt.far)) {
        if (!reversed)
            return error_set(err, "--far inf needs --depth-mapping reversed (the standard "
                                  "mapping divides by far - near)");
        run->opt.far = FAR_AT_INFINITY;
    }
    if (reversed)
        run->rule = &REVERSED_RULE;
    run->after_write = after_write;
    return true;
}

const Extras EXTRAS = {.flags = FLAGS, .n_flags = FLAG_COUNT, .choose = choose};
