/* replay.c: a fuzz target without libFuzzer: calls its
 * LLVMFuzzerTestOneInput once on each file named on the command line (and
 * its LLVMFuzzerInitialize first, if it has one). make test builds every
 * target of tests/fuzz/ this way, with the ordinary compiler (and make
 * sanitize with the sanitizers), and runs it on the target's committed seeds
 * (tests/tools/test_fuzz_seeds.c): an input a fix once made pass keeps
 * passing. A broken invariant aborts; exit status 0: every file ran. */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv) __attribute__((weak));

int main(int argc, char **argv)
{
    if (LLVMFuzzerInitialize)
        LLVMFuzzerInitialize(&argc, &argv);
    for (int k = 1; k < argc; k++) {
        FILE *f = fopen(argv[k], "rb");
        if (!f) {
            fprintf(stderr, "replay: error: cannot read %s\n", argv[k]);
            return 1;
        }
        size_t cap = 4096, n = 0;
        uint8_t *data = malloc(cap);
        for (size_t got; data && (got = fread(data + n, 1, cap - n, f)) > 0;) {
            n += got;
            uint8_t *more = n == cap ? realloc(data, cap *= 2) : data;
            if (!more)
                free(data);
            data = more;
        }
        bool failed = ferror(f) != 0 || !data;
        fclose(f);
        if (failed) {
            free(data);
            fprintf(stderr, "replay: error: cannot read %s whole\n", argv[k]);
            return 1;
        }
        LLVMFuzzerTestOneInput(data, n);
        free(data);
    }
    return 0;
}
