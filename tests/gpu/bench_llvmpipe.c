/* bench_llvmpipe: Mesa's llvmpipe on the benchmark's workloads
 * (tests/bench/workloads.h), for make bench's rows "llvmpipe_0t" (no
 * rasterizer thread: llvmpipe rasterizes in the calling thread,
 * LP_NUM_THREADS=0), "llvmpipe_1t" (one rasterizer thread of its own,
 * LP_NUM_THREADS=1) and "llvmpipe_Nt" (all N cores). On one core the peer is
 * the faster of the first two on each workload (run-bench.sh).
 *
 *     bench_llvmpipe [--reps N] [WORKLOAD ...]
 *
 * Without LP_NUM_THREADS in the environment it runs itself three times,
 * with LP_NUM_THREADS=0, 1 and the number of cores, since llvmpipe reads it
 * once, when its screen is made. Each workload's corners go to the GPU in
 * clip space, as the lessons' frames take them (workload_draw), y_c negated
 * (gl.h, flip-y), through a vertex shader that passes them on; the depth
 * buffer is unorm24 with the standard mapping, as a GL default framebuffer;
 * the shader writes the face index, as --id-out. Timed: the clear, the draw
 * and glFinish; not timed: the context, the shaders, the upload. With one
 * thread the time is the CPU time of the whole process (with
 * LP_NUM_THREADS=1 llvmpipe rasterizes in a thread of its own): the lessons'
 * measure, which other programs on the machine do not inflate; with all
 * cores it is the wall clock, the only one that shows threads working
 * together. The CSV
 * lines are measure.h's; the fragment count is the GPU's own, an occlusion
 * query over one draw with the depth test passing everything. */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "gl.h"
#include "measure.h"
#include "workloads.h"

/* The workload's triangles in clip space, y_c negated (gl.h, flip-y). */
static bool workload_vertices(const Workload *w, Vertices *v, Error *err)
{
    v->n = (int)(3 * w->ntris);
    v->pos = malloc((size_t)v->n * 4 * sizeof *v->pos);
    v->id = malloc((size_t)v->n * sizeof *v->id);
    if (!v->pos || !v->id)
        return error_set(err, "out of memory for %d vertices", v->n);
    int k = 0;
    for (int i = 0; i < w->nfaces; i++) {
        const ScreenFace *face = &w->faces[i];
        for (int t = 0; t < face->n - 2; t++)
            for (int c = 0; c < 3; c++, k++) {
                Vec4 q = face->clip[face->tris[t].c[c]];
                v->pos[4 * k + 0] = (float)q.x;
                v->pos[4 * k + 1] = (float)-q.y;
                v->pos[4 * k + 2] = (float)q.z;
                v->pos[4 * k + 3] = (float)q.w;
                v->id[k] = face->face;
            }
    }
    return true;
}

/* Fragments the GPU rasterizes in one draw: all pass with GL_ALWAYS. */
static uint64_t fragments_of(int nverts)
{
    GLuint query;
    GLuint64 samples = 0;
    glGenQueries(1, &query);
    glDepthFunc(GL_ALWAYS);
    glBeginQuery(GL_SAMPLES_PASSED, query);
    gpu_draw(nverts);
    glEndQuery(GL_SAMPLES_PASSED);
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &samples);
    glDeleteQueries(1, &query);
    glDepthFunc(GL_LESS);
    return samples;
}

/* The seconds one draw takes: process CPU time for one thread, else the wall clock. */
static double timed_draw(int nverts, bool cpu_time)
{
    if (!cpu_time)
        return gpu_draw(nverts);
    struct timespec a, b;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &a);
    gpu_draw(nverts);
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &b);
    return (double)(b.tv_sec - a.tv_sec) + (double)(b.tv_nsec - a.tv_nsec) * 1e-9;
}

static bool measure_workload(const char *name, const Workload *w, int reps, bool cpu_time,
                             Measurement *m, Error *err)
{
    Vertices v = {0};
    Gpu gpu = {0};
    GpuSetup setup = {DEPTH_UNORM24, MAP_GL, ORIENT_FLIP_Y}; /* gluPerspective z_c */
    bool ok = workload_vertices(w, &v, err) && gpu_open(&gpu, err) &&
              gpu_prepare(&gpu, &setup, w->width, w->height, &v, err);
    if (ok) {
        double times[MAX_REPS];
        for (int k = -BENCH_WARMUP; k < reps; k++) {
            double t = timed_draw(v.n, cpu_time);
            if (k >= 0)
                times[k] = t;
        }
        *m = (Measurement){.lesson = name, .workload = w->name, .width = w->width,
                           .height = w->height, .reps = reps, .triangles = w->ntris};
        summarise_times(times, reps, &m->median_s, &m->min_s, &m->max_s);
        m->fragments = fragments_of(v.n);
    }
    gpu_close(&gpu);
    free(v.pos);
    free(v.id);
    return ok;
}

/* Runs this program again with LP_NUM_THREADS=threads; its lines go to ours. */
static int run_with_threads(char **argv, long threads)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid < 0)
        return 1;
    if (pid == 0) {
        char value[32];
        snprintf(value, sizeof value, "%ld", threads);
        setenv("LP_NUM_THREADS", value, 1);
        execv("/proc/self/exe", argv);
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

int main(int argc, char **argv)
{
    const char *program = argc > 0 ? argv[0] : "bench_llvmpipe";
    int reps;
    bool chosen[WORKLOAD_COUNT], any;
    int usage = bench_parse_args(argc, argv, program, &reps, chosen, &any);
    if (usage != 0)
        return usage;
    const char *threads = getenv("LP_NUM_THREADS");
    if (!threads) {
        long cores = sysconf(_SC_NPROCESSORS_ONLN);
        int status = run_with_threads(argv, 0);
        status = status != 0 ? status : run_with_threads(argv, 1);
        return status != 0 ? status : run_with_threads(argv, cores > 0 ? cores : 1);
    }
    char name[64];
    snprintf(name, sizeof name, "llvmpipe_%st", threads);
    for (int k = 0; k < WORKLOAD_COUNT; k++) {
        if (any && !chosen[k])
            continue;
        Workload w;
        Measurement m;
        Error err;
        bool ok = workload_build(&w, (WorkloadKind)k, &err);
        if (ok) {
            ok = measure_workload(name, &w, reps, atoi(threads) <= 1, &m, &err);
            workload_free(&w);
        }
        if (!ok) {
            fprintf(stderr, "%s: error: %s\n", program, err.msg);
            return 1;
        }
        measure_print(stdout, &m);
        fflush(stdout);
    }
    return 0;
}
