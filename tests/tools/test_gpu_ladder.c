/* test_gpu_ladder.c: issue 18's quality bar, lesson 06 against a GPU (Mesa's
 * llvmpipe through build/tools/gpu_reference, docs/tools.md).
 *
 * On the ladder (common/harness/ladder.h: pairs of plates 0.05 apart, one pair per
 * distance band), in every depth format and mapping, the fraction of each
 * band's pixels where the back plate wins is within 0.1 of what the GPU shows
 * with the same format and mapping, and 0 for reversed float32 where the
 * GPU's is 0. Both pictures are scored by the same code (ladder_score_id_png).
 *
 * Measured: the two pictures show the same face on every pixel, in all six,
 * at the default size (and at 400 x 300 and 320 x 240 in unorm16). Lesson 06
 * computes z_w as llvmpipe does, in float32: a triangle's plane from its
 * corners' z_c * (1 / w_c), its slopes and its value at pixel (0, 0) in the
 * same order of operations, and a unorm code rounded from a float32 product.
 * The test holds them to the same face on all but 0.5% of the covered
 * pixels, leaving room for another Mesa version. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/image_io.h"
#include "harness/ladder.h"
#include "harness/shade.h"
#include "test_support.h"

static const char *const FORMATS[3] = {"unorm16", "unorm24", "float32"};
static const char *const MAPPINGS[2] = {"standard", "reversed"};

static void score(const char *path, LadderScore *s)
{
    Error err;
    if (!ladder_score_id_png(path, s, &err))
        fail_msg("%s", err.msg);
}

/* Pixels drawn in either picture, and those where the faces differ. */
static void compare_faces(const char *a, const char *b, long *covered, long *differ)
{
    Image ia = read_png(a), ib = read_png(b);
    *covered = *differ = 0;
    for (int y = 0; y < ia.height; y++)
        for (int x = 0; x < ia.width; x++) {
            int32_t fa = id_colour_face(image_get(&ia, x, y));
            int32_t fb = id_colour_face(image_get(&ib, x, y));
            *covered += fa != NO_FACE || fb != NO_FACE;
            *differ += fa != fb;
        }
    image_free(&ia);
    image_free(&ib);
}

static void ladder_bands_agree_with_the_gpu(void **state)
{
    (void)state;
    const char *dir = test_dir("gpu_ladder_test");
    Path lid = in_dir(dir, "lesson_id.png"), gid = in_dir(dir, "gpu_id.png");
    Path out = in_dir(dir, "lesson.png");
    for (int f = 0; f < 3; f++)
        for (int m = 0; m < 2; m++) {
            const char *largs[] = {"--scene", "ladder",
                                   "--depth-format", FORMATS[f], "--depth-mapping",
                                   MAPPINGS[m], "--out", out.path, "--id-out", lid.path, NULL};
            const char *gargs[] = {"--scene", "ladder",
                                   "--depth-format", FORMATS[f], "--depth-mapping",
                                   MAPPINGS[m], "--id-out", gid.path, NULL};
            free(run_ok("06_depth_precision", largs));
            RunResult r = run_tool("gpu_reference", gargs);
            if (r.status != 0)
                fail_msg("gpu_reference %s %s: exit %d: %s", FORMATS[f], MAPPINGS[m], r.status,
                         r.err);
            run_result_free(&r);
            LadderScore ls, gs;
            score(lid.path, &ls);
            score(gid.path, &gs);
            printf("  %s %s, back plate wins (lesson / GPU):", FORMATS[f], MAPPINGS[m]);
            for (int k = 0; k < LADDER_BANDS; k++) {
                double lw = ladder_wrong_fraction(&ls, k), gw = ladder_wrong_fraction(&gs, k);
                printf(" d = %g: %.3f / %.3f", LADDER_DISTANCE[k], lw, gw);
                if (ls.front[k] + ls.back[k] < 2000 || gs.front[k] + gs.back[k] < 2000)
                    fail_msg("band d = %g draws too few pixels to score", LADDER_DISTANCE[k]);
                if (fabs(lw - gw) > 0.1)
                    fail_msg("%s %s, band d = %g: lesson %.3f, GPU %.3f, more than 0.1 apart",
                             FORMATS[f], MAPPINGS[m], LADDER_DISTANCE[k], lw, gw);
                if (f == 2 && m == 1 && gw == 0 && lw != 0)
                    fail_msg("reversed float32, band d = %g: the GPU shows no back plate, the "
                             "lesson %.4f", LADDER_DISTANCE[k], lw);
            }
            long covered, differ;
            compare_faces(lid.path, gid.path, &covered, &differ);
            printf("; %ld of %ld pixels differ\n", differ, covered);
            expect_at_most(covered / 200, differ, "pixels where lesson and GPU differ");
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ladder_bands_agree_with_the_gpu),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
