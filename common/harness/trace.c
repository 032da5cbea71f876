/* trace.c: see trace.h. */
#include "trace.h"

void trace_print(FILE *out, const TraceLog *log, const DepthRule *rule, const char *where,
                 int winner, float stored)
{
    char value[STORED_TEXT_MAX], before[STORED_TEXT_MAX];
    if (log->count == 0 && !log->overflowed) {
        fprintf(out, "no fragment reached %s; stored: %s (cleared)\n", where,
                format_stored(stored, value));
        return;
    }
    fprintf(out, "trace %s: %d fragment%s%s\n", where, log->count, log->count == 1 ? "" : "s",
            log->overflowed ? " logged, then the log was full" : "");
    for (int k = 0; k < log->count; k++) {
        const TraceEntry *e = &log->entries[k];
        fprintf(out, TRACE_LINE_FORMAT, k + 1, rule->index, e->face, rule->value,
                format_stored(e->value, value), format_stored(e->stored, before),
                e->passed ? "passed" : "failed");
    }
    if (winner == NO_FACE)
        fprintf(out, "winner: none (no fragment passed), stored %s=%s\n", rule->value,
                format_stored(stored, value));
    else
        fprintf(out, "winner: %s %d, stored %s=%s\n", rule->index, winner, rule->value,
                format_stored(stored, value));
}
