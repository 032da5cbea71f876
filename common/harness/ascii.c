/* ascii.c: see ascii.h. */
#include "ascii.h"

#include <math.h>
#include <stdbool.h>
#include <stddef.h>

#define DIGIT_STEPS 10 /* digits 0 .. 9 */
#define DIGIT_MAX (DIGIT_STEPS - 1)

/* True when every drawn value is one of 0, 1, ..., 9: then it prints as itself. */
static bool all_single_digits(const float *values, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isnan(values[i]) && !(values[i] >= 0 && values[i] <= DIGIT_MAX &&
                                   values[i] == floorf(values[i])))
            return false;
    return true;
}

/* The nearest and the farthest drawn value by the rule; false when nothing was drawn. */
static bool value_range(const float *values, size_t n, const DepthRule *rule, double *nearest,
                        double *farthest)
{
    bool any = false;
    for (size_t i = 0; i < n; i++) {
        if (isnan(values[i]))
            continue;
        if (!any || rule_is_nearer(rule, values[i], *nearest))
            *nearest = values[i];
        if (!any || rule_is_nearer(rule, *farthest, values[i]))
            *farthest = values[i];
        any = true;
    }
    return any;
}

/* The step of v between nearest (0) and farthest (9), in ten equal parts. */
static int quantise(double v, double nearest, double farthest)
{
    double span = farthest - nearest;
    if (span == 0 || !isfinite(span))
        return 0;
    double step = floor(DIGIT_STEPS * ((v - nearest) / span));
    return step < 0 ? 0 : step > DIGIT_MAX ? DIGIT_MAX : (int)step;
}

static void print_legend(FILE *out, int width, int height, const DepthRule *rule, bool drawn,
                         bool as_is, double nearest, double farthest)
{
    char size[48], a[STORED_TEXT_MAX], b[STORED_TEXT_MAX];
    if (height == 1)
        snprintf(size, sizeof size, "%d column%s", width, width == 1 ? "" : "s");
    else
        snprintf(size, sizeof size, "%dx%d", width, height);
    if (!drawn)
        fprintf(out, "%s %s, nothing drawn; '.' = empty\n", rule->buffer, size);
    else if (as_is)
        fprintf(out, "%s %s, digit = %s itself (all values are whole numbers 0-9); "
                     "'.' = empty\n", rule->buffer, size, rule->value);
    else
        fprintf(out, "%s %s, stored %s in ten steps: 0 = nearest (%s=%s) .. "
                     "9 = farthest (%s=%s); '.' = empty\n",
                rule->buffer, size, rule->value, rule->value, format_stored((float)nearest, a),
                rule->value, format_stored((float)farthest, b));
}

void ascii_print(FILE *out, const float *values, int width, int height, const DepthRule *rule)
{
    size_t n = (size_t)width * (size_t)height;
    bool as_is = all_single_digits(values, n);
    double nearest = 0, farthest = 0;
    bool drawn = value_range(values, n, rule, &nearest, &farthest);
    print_legend(out, width, height, rule, drawn, as_is, nearest, farthest);
    for (int y = 0; y < height; y++) {
        for (int x = 0; x < width; x++) {
            float v = values[(size_t)y * (size_t)width + (size_t)x];
            if (isnan(v))
                fputc(ASCII_EMPTY, out);
            else
                fputc('0' + (as_is ? (int)v : quantise(v, nearest, farthest)), out);
        }
        fputc('\n', out);
    }
}
