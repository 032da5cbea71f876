/* test_trace.c: lesson 04's --trace names the face the picture shows, on 1000
 * random pixels (tests/shared/trace_suite.inc). Lesson 04 keeps 1/d, larger is
 * nearer (docs/conventions.md), and the trace prints what the buffer holds. */
#include "scanline.h"

#define TRACE_RASTERIZER SCANLINE_ZBUFFER
#define TRACE_RULE {"depth buffer", "1/d", "face", LARGER_IS_NEARER}
#include "../shared/trace_suite.inc"

int main(void)
{
    return run_trace_suite("04_scanline_inverse_z trace");
}
