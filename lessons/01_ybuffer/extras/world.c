/* world.c: the default scene, the segments file, --order, and the summary. */
#include "world.h"

#include <stdlib.h>
#include <string.h>

#include "harness/file.h"

static const Segment DEFAULT_SEGMENTS[] = {
    {20, 34, 744, 400, {255, 0, 0}},   /* red */
    {120, 434, 444, 400, {0, 255, 0}}, /* green */
    {330, 463, 594, 200, {0, 0, 255}}, /* blue */
};
#define DEFAULT_COUNT ((int)(sizeof DEFAULT_SEGMENTS / sizeof DEFAULT_SEGMENTS[0]))

static const char *const FIELD_NAMES[SEGMENT_FIELDS] = {"x0", "y0", "x1", "y1", "r", "g", "b"};
#define COLOUR_MAX 255
/* A token longer than this is shown cut short in a message. */
#define TOKEN_SHOWN_MAX 24
/* More digits than this is out of every range we accept. */
#define DIGITS_MAX 9

bool default_segments(Segment **segs, int *count, Error *err)
{
    *segs = malloc(sizeof DEFAULT_SEGMENTS);
    if (!*segs)
        return error_set(err, "out of memory");
    memcpy(*segs, DEFAULT_SEGMENTS, sizeof DEFAULT_SEGMENTS);
    *count = DEFAULT_COUNT;
    return true;
}

/* ---- the segments file ---------------------------------------------------- */

typedef struct {
    const char *start;
    size_t len;
} Token;

typedef enum { NUMBER_OK, NUMBER_NOT_INTEGER, NUMBER_TOO_LARGE } NumberStatus;

/* An optional sign and decimal digits, nothing else ("1.5", "1e3", "0x10" are
 * refused). Values with more than DIGITS_MAX digits are too large for any field. */
static NumberStatus parse_integer(Token t, long *value)
{
    size_t i = 0;
    bool negative = false;
    if (t.len > 0 && (t.start[0] == '+' || t.start[0] == '-')) {
        negative = t.start[0] == '-';
        i = 1;
    }
    if (i == t.len)
        return NUMBER_NOT_INTEGER;
    for (size_t k = i; k < t.len; k++) {
        if (t.start[k] < '0' || t.start[k] > '9')
            return NUMBER_NOT_INTEGER;
    }
    while (i + 1 < t.len && t.start[i] == '0')
        i++; /* leading zeros say nothing about the size */
    if (t.len - i > DIGITS_MAX)
        return NUMBER_TOO_LARGE;
    long v = 0;
    for (size_t k = i; k < t.len; k++)
        v = v * 10 + (t.start[k] - '0');
    *value = negative ? -v : v;
    return NUMBER_OK;
}

static bool is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/* Splits one line (comment already cut off) into tokens; returns how many there
 * were, keeping at most SEGMENT_FIELDS of them. */
static int split_line(const char *line, size_t len, Token tokens[SEGMENT_FIELDS])
{
    int n = 0;
    size_t i = 0;
    while (i < len) {
        while (i < len && is_blank(line[i]))
            i++;
        if (i == len)
            break;
        size_t start = i;
        while (i < len && !is_blank(line[i]))
            i++;
        if (n < SEGMENT_FIELDS)
            tokens[n] = (Token){line + start, i - start};
        n++;
    }
    return n;
}

/* The seven numbers of one line, checked against their ranges. */
static bool parse_segment_line(const Token tokens[SEGMENT_FIELDS], const char *source,
                               int line_no, Segment *s, Error *err)
{
    long v[SEGMENT_FIELDS] = {0};
    for (int f = 0; f < SEGMENT_FIELDS; f++) {
        bool colour = f >= 4;
        long lo = colour ? 0 : -COORD_LIMIT, hi = colour ? COLOUR_MAX : COORD_LIMIT;
        int shown = tokens[f].len > TOKEN_SHOWN_MAX ? TOKEN_SHOWN_MAX : (int)tokens[f].len;
        const char *more = tokens[f].len > TOKEN_SHOWN_MAX ? "..." : "";
        NumberStatus st = parse_integer(tokens[f], &v[f]);
        if (st == NUMBER_NOT_INTEGER)
            return error_set(err, "%s:%d: %s '%.*s%s' is not an integer "
                             "(coordinates and colours are whole numbers)",
                             source, line_no, FIELD_NAMES[f], shown, tokens[f].start, more);
        if (st == NUMBER_TOO_LARGE || v[f] < lo || v[f] > hi)
            return error_set(err, "%s:%d: %s %.*s%s is out of range %ld..%ld", source, line_no,
                             FIELD_NAMES[f], shown, tokens[f].start, more, lo, hi);
    }
    *s = (Segment){(int)v[0], (int)v[1], (int)v[2], (int)v[3],
                   {(uint8_t)v[4], (uint8_t)v[5], (uint8_t)v[6]}};
    return true;
}

/* A byte no text file has (NUL, escape, ...): the first one, or -1. Tabs and
 * the CR of a CRLF line end are blanks. */
static int find_control_byte(const char *line, size_t len)
{
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)line[i];
        if ((c < 0x20 && !is_blank((char)c)) || c == 0x7f)
            return c;
    }
    return -1;
}

static bool append_segment(Segment **segs, int *count, int *cap, Segment s, Error *err)
{
    if (*count == *cap) {
        int new_cap = *cap ? *cap * 2 : 8;
        Segment *grown = realloc(*segs, (size_t)new_cap * sizeof *grown);
        if (!grown)
            return error_set(err, "out of memory for %d segments", new_cap);
        *segs = grown;
        *cap = new_cap;
    }
    (*segs)[(*count)++] = s;
    return true;
}

bool parse_segments(const char *text, size_t len, const char *source,
                    Segment **segs, int *count, Error *err)
{
    *segs = NULL;
    *count = 0;
    int cap = 0;
    size_t pos = 0;
    if (len >= 3 && memcmp(text, "\xef\xbb\xbf", 3) == 0)
        pos = 3; /* a UTF-8 byte order mark, as some editors write: not a segment */
    for (int line_no = 1; pos < len; line_no++) {
        const char *line = text + pos;
        const char *newline = memchr(line, '\n', len - pos);
        size_t line_len = newline ? (size_t)(newline - line) : len - pos;
        pos += line_len + 1;

        int control = find_control_byte(line, line_len);
        if (control >= 0) {
            error_set(err, "%s:%d: contains the control byte 0x%02x (not a text file?)",
                      source, line_no, control);
            goto fail;
        }
        const char *hash = memchr(line, '#', line_len); /* a comment runs to the end of the line */
        if (hash)
            line_len = (size_t)(hash - line);

        Token tokens[SEGMENT_FIELDS];
        int n = split_line(line, line_len, tokens);
        if (n == 0)
            continue; /* blank or comment only */
        if (n != SEGMENT_FIELDS) {
            error_set(err, "%s:%d: expected 7 numbers 'x0 y0 x1 y1 r g b', got %d",
                      source, line_no, n);
            goto fail;
        }
        Segment s = {0, 0, 0, 0, {0, 0, 0}};
        if (!parse_segment_line(tokens, source, line_no, &s, err) ||
            !append_segment(segs, count, &cap, s, err))
            goto fail;
    }
    return true;
fail:
    free(*segs);
    *segs = NULL;
    *count = 0;
    return false;
}

bool read_segments(const char *path, Segment **segs, int *count, Error *err)
{
    char *data;
    size_t len;
    if (!read_file(path, SEGMENTS_MAX_BYTES, &data, &len, err))
        return false;
    bool ok = parse_segments(data, len, path, segs, count, err);
    free(data);
    return ok;
}

/* ---- --order ---------------------------------------------------------------- */

bool parse_order(const char *s, int count, int *order, Error *err)
{
    if (!s) {
        for (int k = 0; k < count; k++)
            order[k] = k;
        return true;
    }
    bool *used = calloc((size_t)count + 1, sizeof *used);
    if (!used)
        return error_set(err, "out of memory");
    bool commas = strchr(s, ',') != NULL;
    int k = 0;
    const char *p = s;
    bool ok = *p != '\0';
    while (ok && *p) {
        long v = 0;
        if (commas) {
            size_t n = strcspn(p, ",");
            Token t = {p, n};
            ok = parse_integer(t, &v) == NUMBER_OK;
            p += n;
            if (*p == ',' && *++p == '\0')
                ok = false; /* a trailing comma */
        } else {
            ok = *p >= '1' && *p <= '9';
            v = *p++ - '0';
        }
        ok = ok && k < count && v >= 1 && v <= count && !used[v];
        if (ok) {
            used[v] = true;
            order[k++] = (int)v - 1;
        }
    }
    free(used);
    if (!ok || k != count) {
        if (count == 0)
            return error_set(err, "--order '%s': there are no segments to order", s);
        return error_set(err, "--order '%s': expected each of 1..%d exactly once, "
                         "as digits (e.g. %s) or separated by commas",
                         s, count, count >= 3 ? "312" : count == 2 ? "21" : "1");
    }
    return true;
}

/* ---- names and the summary -------------------------------------------------- */

void segment_name(Rgb c, char name[SEGMENT_NAME_MAX])
{
    static const struct { Rgb c; const char *name; } PLAIN[] = {
        {{255, 0, 0}, "red"},     {{0, 255, 0}, "green"},   {{0, 0, 255}, "blue"},
        {{255, 255, 0}, "yellow"}, {{0, 255, 255}, "cyan"}, {{255, 0, 255}, "magenta"},
        {{255, 255, 255}, "white"}, {{0, 0, 0}, "black"},
    };
    for (size_t i = 0; i < sizeof PLAIN / sizeof PLAIN[0]; i++) {
        if (PLAIN[i].c.r == c.r && PLAIN[i].c.g == c.g && PLAIN[i].c.b == c.b) {
            snprintf(name, SEGMENT_NAME_MAX, "%s", PLAIN[i].name);
            return;
        }
    }
    snprintf(name, SEGMENT_NAME_MAX, "#%02x%02x%02x", c.r, c.g, c.b);
}

/* The runs of columns whose owner is `who`, as "20-119, 512-744"; a long list
 * is cut after RUNS_SHOWN_MAX runs. */
#define RUNS_SHOWN_MAX 8
static void print_runs(FILE *out, const YBuffer *yb, int who)
{
    int runs = 0;
    for (int x = 0; x < yb->width; x++) {
        if (yb->owner[x] != who)
            continue;
        int start = x;
        while (x + 1 < yb->width && yb->owner[x + 1] == who)
            x++;
        if (runs < RUNS_SHOWN_MAX) {
            fprintf(out, "%s%d", runs ? ", " : "", start);
            if (x > start)
                fprintf(out, "-%d", x);
        }
        runs++;
    }
    if (runs > RUNS_SHOWN_MAX)
        fprintf(out, ", ... (%d runs in all)", runs);
}

static int count_owned(const YBuffer *yb, int who)
{
    int n = 0;
    for (int x = 0; x < yb->width; x++)
        n += yb->owner[x] == who;
    return n;
}

void print_summary(FILE *out, const YBuffer *yb, const Segment *segs, int count,
                   const int *order)
{
    if (count == 0)
        fprintf(out, "no segments drawn into %d columns\n", yb->width);
    else
        fprintf(out, "%d segment%s drawn into %d columns, in the order", count,
                count == 1 ? "" : "s", yb->width);
    for (int k = 0; k < count; k++)
        fprintf(out, " %d%s", order[k] + 1, k == count - 1 ? "\n" : "");
    for (int i = 0; i < count; i++) {
        char name[SEGMENT_NAME_MAX];
        segment_name(segs[i].colour, name);
        const Segment *s = &segs[i];
        int won = count_owned(yb, i);
        fprintf(out, "  %d %-7s (%d,%d)-(%d,%d): won %d column%s%s", i + 1, name, s->x0,
                s->y0, s->x1, s->y1, won, won == 1 ? "" : "s", won ? ": " : "");
        print_runs(out, yb, i);
        fputc('\n', out);
    }
    int empty = count_owned(yb, NO_SEGMENT);
    fprintf(out, "  nothing: %d column%s%s", empty, empty == 1 ? "" : "s", empty ? ": " : "");
    print_runs(out, yb, NO_SEGMENT);
    fputc('\n', out);
    fprintf(out, "column tests: %llu made, %llu passed (y > stored), %llu failed\n",
            (unsigned long long)yb->stats.tested, (unsigned long long)yb->stats.passed,
            (unsigned long long)yb->stats.failed);
}
