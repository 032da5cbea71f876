/* fuzz_flags_05_clipping.c: lesson 05's flags (--bug, --compare-drop) with
 * any arguments (make fuzz FUZZ=flags_05). See fuzz_flags.h. */
#include "fuzz_flags.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    Run run;
    char *text = NULL;
    if (fuzz_flags_read(data, size, "05_clipping", &run, &text))
        fuzz_flags_check(run.opt.near > 0 && run.opt.near < run.opt.far,
                         "0 < near < far once accepted");
    free(text);
    return 0;
}
