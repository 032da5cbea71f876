/* depth_flags.c: see depth_flags.h. */
#include "depth_flags.h"

#include <math.h>
#include <string.h>

static const char *const FORMAT_NAMES[] = {[UNORM16] = "unorm16", [UNORM24] = "unorm24",
                                           [FLOAT32] = "float32"};
static const char *const MAPPING_NAMES[] = {[STANDARD] = "standard", [REVERSED] = "reversed",
                                            [LOGARITHMIC] = "log"};

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

bool depth_flags_ok(Run *run, const char *format, const char *mapping, bool log_ok, Error *err)
{
    if (format && find_name(format, FORMAT_NAMES, 3) < 0)
        return error_set(err, "--depth-format: '%s' is not one of unorm16, unorm24, float32",
                         format);
    int m = mapping ? find_name(mapping, MAPPING_NAMES, 3) : STANDARD;
    if (m < 0)
        return error_set(err, "--depth-mapping: '%s' is not one of standard, reversed%s", mapping,
                         log_ok ? ", log" : "");
    if (m == LOGARITHMIC && !log_ok)
        return error_set(err, "--depth-mapping log is lesson 06's: a depth written per fragment "
                              "has no plane to offset or to test early; here standard or reversed");
    bool reversed = mapping && strcmp(mapping, "reversed") == 0;
    if (isinf(run->opt.far)) {
        if (!reversed)
            return error_set(err, "--far inf needs --depth-mapping reversed (standard divides "
                                  "by far - near, log by log(far / near))");
        /* The stand-in must lie beyond near, or the camera would blame --far. */
        if (run->opt.near_set && !(run->opt.near < FAR_AT_INFINITY))
            return error_set(err, "--near: %g is out of range: with --far inf, near must be "
                                  "below %g", run->opt.near, FAR_AT_INFINITY);
        run->opt.far = FAR_AT_INFINITY;
    }
    if (reversed)
        run->rule = &REVERSED_RULE;
    return true;
}

DepthSetup depth_flags_setup(const Run *run, const char *format, const char *mapping)
{
    int f = format ? find_name(format, FORMAT_NAMES, 3) : UNORM24;
    int m = mapping ? find_name(mapping, MAPPING_NAMES, 3) : STANDARD;
    /* --far inf, which only the reversed mapping takes, stands as FAR_AT_INFINITY
     * in clip space; a finite far that large is finite in the standard one. */
    double far = m == REVERSED && run->opt.far >= FAR_AT_INFINITY ? INFINITY : run->opt.far;
    return depth_setup((DepthFormat)f, (DepthMapping)m, run->opt.near, far);
}
