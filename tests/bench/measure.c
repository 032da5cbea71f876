/* measure.c: see measure.h. */
#include "measure.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

double now_wall_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

void target_reset(Target *t, const Rasterizer *rz)
{
    size_t n = (size_t)t->width * (size_t)t->height;
    rz->clear(t, rz->state);
    memset(t->overdraw, 0, n * sizeof *t->overdraw);
    FragmentStats none = {0};
    t->stats = none;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

void summarise_times(double *times, int n, double *median, double *min, double *max)
{
    qsort(times, (size_t)n, sizeof *times, compare_doubles);
    *min = times[0];
    *max = times[n - 1];
    *median = n % 2 ? times[n / 2] : (times[n / 2 - 1] + times[n / 2]) / 2;
}

void measure_print(FILE *out, const Measurement *m)
{
    fprintf(out, "%s,%s,%d,%d,%d,%ld,%llu,%.6f,%.6f,%.6f,%016llx\n", m->lesson, m->workload,
            m->width, m->height, m->reps, m->triangles, (unsigned long long)m->fragments,
            m->median_s, m->min_s, m->max_s, (unsigned long long)m->checksum);
}

static int usage_error(const char *program, const char *what)
{
    fprintf(stderr, "%s: error: %s (usage: %s [--reps 1..%d] [WORKLOAD ...])\n", program, what,
            program, MAX_REPS);
    return 2;
}

static bool find_workload(const char *name, WorkloadKind *kind)
{
    for (int k = 0; k < WORKLOAD_COUNT; k++)
        if (strcmp(name, workload_name((WorkloadKind)k)) == 0) {
            *kind = (WorkloadKind)k;
            return true;
        }
    return false;
}

int bench_parse_args(int argc, char **argv, const char *program, int *reps,
                     bool chosen[WORKLOAD_COUNT], bool *any)
{
    *reps = BENCH_REPS;
    *any = false;
    for (int k = 0; k < WORKLOAD_COUNT; k++)
        chosen[k] = false;
    for (int i = 1; i < argc; i++) {
        WorkloadKind kind;
        if (strcmp(argv[i], "--reps") == 0) {
            char *end;
            long n = i + 1 < argc ? strtol(argv[i + 1], &end, 10) : 0;
            if (i + 1 >= argc || *end != '\0' || n < 1 || n > MAX_REPS)
                return usage_error(program, "--reps needs a number from 1 to 100");
            *reps = (int)n;
            i++;
        } else if (find_workload(argv[i], &kind)) {
            chosen[kind] = *any = true;
        } else {
            char what[128];
            snprintf(what, sizeof what, "unknown workload '%s'", argv[i]);
            return usage_error(program, what);
        }
    }
    return 0;
}

int bench_parse_reps(int argc, char **argv, const char *program, int *reps)
{
    *reps = BENCH_REPS;
    if (argc == 3 && strcmp(argv[1], "--reps") == 0) {
        char *end;
        long n = strtol(argv[2], &end, 10);
        if (*end != '\0' || n < 1 || n > MAX_REPS) {
            fprintf(stderr, "%s: error: --reps needs a number from 1 to %d\n", program, MAX_REPS);
            return 2;
        }
        *reps = (int)n;
    } else if (argc != 1) {
        fprintf(stderr, "%s: error: unexpected '%s' (usage: %s [--reps N])\n", program, argv[1],
                program);
        return 2;
    }
    return 0;
}
