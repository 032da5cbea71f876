/* bias_flags.c: see bias_flags.h. */
#include "bias_flags.h"

#include <stdlib.h>
#include <string.h>

#include "harness/cli.h"

/* "FACTOR,UNITS": two finite numbers. */
static bool parse_offset(const char *s, double *factor, double *units, Error *err)
{
    const char *comma = s ? strchr(s, ',') : NULL;
    if (!comma)
        return error_set(err, "--polygon-offset: '%.40s' is not two numbers FACTOR,UNITS",
                         s ? s : "");
    char *first = strndup(s, (size_t)(comma - s)); /* a number of any length */
    if (!first)
        return error_set(err, "--polygon-offset: out of memory");
    bool ok = parse_double("--polygon-offset (FACTOR)", first, factor, err) &&
              parse_double("--polygon-offset (UNITS)", comma + 1, units, err);
    free(first);
    return ok;
}

bool bias_flags_ok(const char *offset, const char *clamp, Error *err)
{
    double factor, units, c;
    return (!offset || parse_offset(offset, &factor, &units, err)) &&
           (!clamp || parse_double("--offset-clamp", clamp, &c, err));
}

DepthBias bias_flags_chosen(const char *offset, const char *clamp, const Mesh *mesh)
{
    DepthBias b = {.mesh = mesh};
    Error ignored; /* bias_flags_ok has checked both */
    if (offset)
        parse_offset(offset, &b.factor, &b.units, &ignored);
    if (clamp)
        parse_double("--offset-clamp", clamp, &b.clamp, &ignored);
    return b;
}
