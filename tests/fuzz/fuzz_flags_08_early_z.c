/* fuzz_flags_08_early_z.c: lesson 08's flags (--z-mode, --sort, --bug, its
 * pictures) with any arguments (make fuzz FUZZ=flags_08). Accepted, they give
 * a mode and an order that exist, on lesson 06's unorm24 standard buffer.
 * See fuzz_flags.h. */
#include "fuzz_flags.h"
#include "state.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    Run run;
    char *text = NULL;
    if (fuzz_flags_read(data, size, "08_early_z", &run, &text)) {
        LessonState s = early_z_chosen(&run);
        fuzz_flags_check(s.early_z.mode <= Z_PREPASS && s.early_z.sort <= SORT_BACK_TO_FRONT,
                         "a mode and an order");
        fuzz_flags_check(s.depth.format == UNORM24 && s.depth.mapping == STANDARD,
                         "unorm24, standard");
    }
    free(text);
    return 0;
}
