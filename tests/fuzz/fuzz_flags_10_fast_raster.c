/* fuzz_flags_10_fast_raster.c: lesson 10's flags (--simd, --threads, and
 * lesson 07's depth and bias flags) with any arguments (make fuzz
 * FUZZ=flags_10). Accepted, they give a SIMD path this machine has, 1 to 256
 * threads, a standard or reversed mapping and a finite bias. See
 * fuzz_flags.h. */
#include <math.h>

#include "fuzz_flags.h"
#include "engine.h" /* the lesson's extras/: simd_best */
#include "state.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    Run run;
    char *text = NULL;
    if (fuzz_flags_read(data, size, "10_fast_raster", &run, &text)) {
        LessonState s = fast_chosen(&run);
        fuzz_flags_check(s.fast.simd == SIMD_PIXELS || s.fast.simd <= simd_best(),
                         "a SIMD path this machine has");
        fuzz_flags_check(s.fast.threads >= 1 && s.fast.threads <= 256, "1 to 256 threads");
        fuzz_flags_check(s.depth.mapping == STANDARD || s.depth.mapping == REVERSED,
                         "standard or reversed");
        fuzz_flags_check(isfinite(s.bias.factor) && isfinite(s.bias.units) &&
                             isfinite(s.bias.clamp),
                         "a finite bias");
        fast_raster_free(&s.fast);
    }
    free(text);
    return 0;
}
