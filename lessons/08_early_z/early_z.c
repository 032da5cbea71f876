/* early_z.c: lesson 08, where the fragment shader runs (early_z.h): every
 * fragment of a span comes to fragment(), which runs the shader and lesson
 * 06's depth test in the order the mode says. */
#include "early_z.h"

#include "extras/shader.h"
#include "state.h"

/* A cutout's holes: squares of 4 x 4 pixels, every other one kept. */
bool cutout_keeps(int x, int y)
{
    return (((x >> 2) ^ (y >> 2)) & 1) == 0;
}

/* The shader at pixel i (x, y): counted, its colour written if write. */
static Rgb run_shader(EarlyZ *z, size_t i, int face, int x, int y, bool write)
{
    Rgb c = shade_fragment(z->lit[face], x, y);
    z->shaded++, z->shade_count[i]++;
    if (write)
        z->colour[i] = c;
    return c;
}

/* The prepass's second pass: depth writes off, the equal test. Where two
 * faces store the same value the one pass 1 kept passes (the first drawn,
 * as everywhere in the series): the fragment passes where it left its face. */
static bool depth_equal(const Primitive *p, int x, int y)
{
    Target *t = p->target;
    size_t i = (size_t)y * (size_t)t->width + (size_t)x;
    bool passed = t->face[i] == p->face;
    target_record(t, i, p->face, fragment_depth(p, x, y), t->depth[i], passed);
    return passed;
}

void fragment(const Primitive *p, int x, int y, float inv_d)
{
    EarlyZ *z = &p->state->early_z;
    size_t i = (size_t)y * (size_t)p->target->width + (size_t)x;
    bool cutout = is_cutout(z, p->face), kept = !cutout || cutout_keeps(x, y);
    if (z->pass == 2) {
        /* SOLUTION BEGIN: the equal test, then the shader where it passed
         * (a cutout still discards its holes). */
        z->tested++;
        if (depth_equal(p, x, y))
            run_shader(z, i, p->face, x, y, kept);
        /* SOLUTION STUB
        (void)kept; (void)i; (void)depth_equal;
        */
        /* SOLUTION END */
    } else if (z->pass == 1 || z->mode == Z_LATE || (cutout && !z->bug_discard)) {
        /* SOLUTION BEGIN: late-Z (pass 1 runs only the cheap discard): the
         * shader first; a discarded fragment never reaches the test. */
        Rgb c = z->pass == 1 ? (Rgb){0, 0, 0} : run_shader(z, i, p->face, x, y, false);
        if (!kept)
            return;
        z->tested++;
        if (depth_test(p, x, y, inv_d) && z->pass != 1)
            z->colour[i] = c;
        /* SOLUTION STUB
        (void)kept; (void)inv_d;
        */
        /* SOLUTION END */
    } else {
        /* SOLUTION BEGIN: early-Z: the test first, the shader if it passed.
         * (--bug early-z-with-discard sends a cutout here too: a fragment
         * its shader discards leaves its depth, but the pixel keeps the
         * face it had.) */
        int32_t before = p->target->face[i];
        z->tested++;
        if (depth_test(p, x, y, inv_d)) {
            run_shader(z, i, p->face, x, y, kept);
            if (!kept) /* --bug: the discard comes too late, the depth stays */
                p->target->face[i] = before;
        }
        /* SOLUTION STUB
        (void)kept; (void)inv_d; (void)run_shader;
        */
        /* SOLUTION END */
    }
}
