/* test_trace.c: lesson 05's --trace names the face the picture shows, on 1000
 * random pixels (tests/shared/trace_suite.inc). Lesson 05 keeps lesson 04's 1/d, larger is
 * nearer (docs/conventions.md), and the trace prints what the buffer holds. */
#include "clipping.h"

#define TRACE_RASTERIZER CLIPPING_ZBUFFER
#define TRACE_RULE {"depth buffer", "1/d", "face", LARGER_IS_NEARER}
#include "../shared/trace_suite.inc"

int main(void)
{
    return run_trace_suite("05_clipping trace");
}
