/* fuzz_flags_09_hierarchical_z.c: lesson 09's flags (--tile, --hiz-update,
 * --hiz-out, --skip-out, and lesson 08's) with any arguments (make fuzz
 * FUZZ=flags_09). Accepted, they give a tile of 1 to 64 pixels and lesson
 * 08's mode and order; with no --out, --skip-out has its default. See
 * fuzz_flags.h. */
#include "fuzz_flags.h"
#include "state.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    Run run;
    char *text = NULL;
    if (fuzz_flags_read(data, size, "09_hierarchical_z", &run, &text)) {
        LessonState s = early_z_chosen(&run);
        fuzz_flags_check(s.early_z.mode <= Z_PREPASS && s.early_z.sort <= SORT_BACK_TO_FRONT,
                         "a mode and an order");
        int tile = tile_chosen(&run);
        fuzz_flags_check(tile >= 1 && tile <= 64, "a tile of 1 to 64 pixels");
        (void)exact_chosen(&run);
    }
    free(text);
    return 0;
}
