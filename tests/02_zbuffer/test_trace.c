/* test_trace.c: lesson 02's --trace names the face the picture shows, on 1000
 * random pixels (tests/shared/trace_suite.inc). Lesson 02 keeps view depth d,
 * smaller is nearer (docs/conventions.md). */
#include "raster.h"

#define TRACE_RASTERIZER ZBUFFER
#define TRACE_RULE {"depth buffer", "d", "face", SMALLER_IS_NEARER}
#include "../shared/trace_suite.inc"

int main(void)
{
    return run_trace_suite("02_zbuffer trace");
}
