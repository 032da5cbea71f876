/* early_z.c: times lesson 08's z-modes and sorts on the crowd scene
 * (make bench; docs/08_early_z.md).
 *
 *     bench_early_z [--reps N]
 *
 * One row per mode and sort: the lesson "08_<mode>", the workload
 * "crowd_<sort>", 800 x 600, and as fragments the fragments SHADED (so that
 * ns/frag is the time per shaded fragment). Each repetition loads the scene
 * afresh as build/bin/08_early_z does; only the clear and the drawing (both
 * passes for the prepass, the shader included) are timed. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "early_z.h"
#include "extras.h"
#include "measure.h"

static const Lesson LESSON = {
    .program = "bench_early_z",
    .purpose = "lesson 08's modes timed",
    .scene = "crowd",
    .rasterizer = &DEPTH_BIAS_ZBUFFER,
    .depth_rule = {"depth buffer", "z_w", "face", SMALLER_IS_NEARER},
    .extras = &EXTRAS,
};

/* One repetition: the time of clear and draw; shaded and the picture's sum. */
static bool one_run(const char *mode, const char *sort, double *seconds, uint64_t *shaded,
                    uint64_t *sum)
{
    char *argv[] = {(char *)"bench_early_z", (char *)"--z-mode", (char *)mode,
                    (char *)"--sort", (char *)sort, NULL};
    Run run;
    if (run_load(&run, &LESSON, 5, argv) != RUN_GO)
        return false;
    LessonState state = early_z_chosen(&run);
    if (!early_z_begin(&state, &run, &run.err))
        return run_end(&run), false;
    double start = now_seconds();
    run.rz->clear(&run.target, run.rz->state);
    bool ok = run_draw(&run);
    *seconds = now_seconds() - start;
    *shaded = state.early_z.shaded;
    *sum = 0;
    for (size_t i = 0; i < (size_t)run.target.width * (size_t)run.target.height; i++)
        *sum = *sum * 31 + (uint64_t)(run.target.face[i] + 1);
    if (ok)
        run.status = EXIT_OK; /* drawn: the benchmark writes and reports nothing */
    ok = run_end(&run) == 0 && ok;
    early_z_free(&state.early_z);
    return ok;
}

int main(int argc, char **argv)
{
    static const char *const MODES[] = {"late", "early", "prepass"};
    static const char *const SORTS[] = {"none", "front-to-back", "back-to-front"};
    int reps = 5;
    if (argc == 3 && strcmp(argv[1], "--reps") == 0)
        reps = atoi(argv[2]);
    if (argc != 1 && (argc != 3 || reps < 1 || reps > MAX_REPS)) {
        fprintf(stderr, "usage: bench_early_z [--reps N]   (N from 1 to %d)\n", MAX_REPS);
        return 2;
    }
    for (int m = 0; m < 3; m++)
        for (int s = 0; s < 3; s++) {
            double times[MAX_REPS];
            uint64_t shaded = 0, sum = 0, first = 0;
            char lesson[32], workload[32];
            for (int k = -BENCH_WARMUP; k < reps; k++) {
                double t;
                if (!one_run(MODES[m], SORTS[s], &t, &shaded, &sum))
                    return 1;
                if (k < 0)
                    first = sum;
                else if (sum != first) {
                    fprintf(stderr, "bench_early_z: repetitions drew different pictures\n");
                    return 1;
                } else
                    times[k] = t;
            }
            snprintf(lesson, sizeof lesson, "08_%s", MODES[m]);
            snprintf(workload, sizeof workload, "crowd_%s", SORTS[s]);
            Measurement me = {.lesson = lesson, .workload = workload, .width = 800,
                              .height = 600, .reps = reps, .fragments = shaded,
                              .checksum = first};
            summarise_times(times, reps, &me.median_s, &me.min_s, &me.max_s);
            measure_print(stdout, &me);
            fflush(stdout);
        }
    return 0;
}
