/* fuzz_quiet.h: for the targets that read a command line (fuzz_cli.c,
 * fuzz_flags.h): --help and --version print on stdout, so stdout goes to
 * /dev/null before the first input, and the fuzzer's output stays readable.
 * Included once, by the target's one source file. */
#ifndef FUZZ_QUIET_H
#define FUZZ_QUIET_H

#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    if (!freopen("/dev/null", "w", stdout))
        abort();
    return 0;
}

#endif
