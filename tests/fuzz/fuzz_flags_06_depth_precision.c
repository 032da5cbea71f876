/* fuzz_flags_06_depth_precision.c: lesson 06's flags (--depth-format,
 * --depth-mapping, --precision-plot, --ladder-out, and --far inf) with any arguments
 * (make fuzz FUZZ=flags_06). Accepted, they give a format and a mapping
 * that exist, 0 < near < far, and a setup of finite numbers: z_w at near
 * is 0 (standard, log) or 1 (reversed), within rounding. See fuzz_flags.h. */
#include <math.h>

#include "fuzz_flags.h"
#include "state.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    Run run;
    char *text = NULL;
    if (fuzz_flags_read(data, size, "06_depth_precision", &run, &text)) {
        DepthSetup s = depth_chosen(&run);
        fuzz_flags_check(s.format <= FLOAT32 && s.mapping <= LOGARITHMIC, "a format and mapping");
        fuzz_flags_check(s.near > 0 && s.near < s.far, "0 < near < far");
        fuzz_flags_check(isfinite(s.far) || s.mapping == REVERSED, "far at infinity: reversed");
        fuzz_flags_check(isfinite(s.a) && isfinite(s.b), "a and b finite");
        double at_near = window_depth(&s, s.near);
        fuzz_flags_check(fabs(at_near - (s.mapping == REVERSED ? 1.0 : 0.0)) < 1e-6,
                         "z_w at the near plane");
    }
    free(text);
    return 0;
}
