/* fuzz_flags_07_depth_bias.c: lesson 07's flags (--polygon-offset,
 * --offset-clamp, the depth flags; --depth-mapping log refused) with any
 * arguments (make fuzz FUZZ=flags_07). Accepted, they give a standard or
 * reversed mapping, 0 < near < far, and a bias of finite numbers. See
 * fuzz_flags.h. */
#include <math.h>

#include "fuzz_flags.h"
#include "state.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    Run run;
    char *text = NULL;
    if (fuzz_flags_read(data, size, "07_depth_bias", &run, &text)) {
        LessonState s = depth_chosen(&run);
        fuzz_flags_check(s.depth.mapping == STANDARD || s.depth.mapping == REVERSED,
                         "standard or reversed");
        fuzz_flags_check(s.depth.near > 0 && s.depth.near < s.depth.far, "0 < near < far");
        fuzz_flags_check(isfinite(s.bias.factor) && isfinite(s.bias.units) &&
                             isfinite(s.bias.clamp),
                         "a finite bias");
    }
    free(text);
    return 0;
}
