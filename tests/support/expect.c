/* expect.c: see expect.h. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "expect.h"
#include "observe.h"

#include <stdio.h>

#include "harness/shade.h"

#define MESSAGE_MAX 1024

/* "what: " before the rest of a message, or nothing when what is empty. */
static const char *prefix(const char *what)
{
    return what && *what ? what : "";
}

static const char *separator(const char *what)
{
    return what && *what ? ": " : "";
}

/* "face 3 (rgb 0,0,4)", or "no face (rgb 0,0,0)" for the background. */
static void describe_face(char *out, size_t size, int32_t face, Rgb c)
{
    if (face == NO_FACE)
        snprintf(out, size, "no face (rgb %d,%d,%d)", c.r, c.g, c.b);
    else
        snprintf(out, size, "face %ld (rgb %d,%d,%d)", (long)face, c.r, c.g, c.b);
}

static bool inside(int x, int y, int width, int height)
{
    return x >= 0 && y >= 0 && x < width && y < height;
}

static bool outside_message(char *msg, size_t size, int x, int y, int width, int height,
                            const char *what)
{
    snprintf(msg, size, "%s%spixel (%d, %d) is outside the %d x %d picture", prefix(what),
             separator(what), x, y, width, height);
    return false;
}

int32_t face_at(const Image *id_picture, int x, int y)
{
    return id_colour_face(image_get(id_picture, x, y));
}

long faces_shown(const Image *id_picture)
{
    long n = 0;
    for (int y = 0; y < id_picture->height; y++)
        for (int x = 0; x < id_picture->width; x++)
            n += face_at(id_picture, x, y) != NO_FACE;
    return n;
}

int32_t target_face_at(const Target *t, int x, int y)
{
    return t->face[(size_t)y * (size_t)t->width + (size_t)x];
}

float target_depth_at(const Target *t, int x, int y)
{
    return t->depth[(size_t)y * (size_t)t->width + (size_t)x];
}

/* ---- the words ---- */

bool count_message(char *msg, size_t size, long expected, long actual, const char *what)
{
    if (actual == expected)
        return true;
    snprintf(msg, size, "%s%sexpected %ld, got %ld", prefix(what), separator(what), expected,
             actual);
    return false;
}

bool at_least_message(char *msg, size_t size, long least, long actual, const char *what)
{
    if (actual >= least)
        return true;
    snprintf(msg, size, "%s%sexpected at least %ld, got %ld", prefix(what), separator(what),
             least, actual);
    return false;
}

bool at_most_message(char *msg, size_t size, long most, long actual, const char *what)
{
    if (actual <= most)
        return true;
    snprintf(msg, size, "%s%sexpected at most %ld, got %ld", prefix(what), separator(what),
             most, actual);
    return false;
}

bool colour_message(char *msg, size_t size, Rgb expected, Rgb actual, const char *what)
{
    if (actual.r == expected.r && actual.g == expected.g && actual.b == expected.b)
        return true;
    snprintf(msg, size, "%s%sexpected rgb %d,%d,%d, got rgb %d,%d,%d", prefix(what),
             separator(what), expected.r, expected.g, expected.b, actual.r, actual.g, actual.b);
    return false;
}

bool colour_that_message(char *msg, size_t size, Rgb actual, bool ok, const char *what,
                         const char *expected_words)
{
    if (ok)
        return true;
    snprintf(msg, size, "%s%sexpected %s, got rgb %d,%d,%d", prefix(what), separator(what),
             expected_words, actual.r, actual.g, actual.b);
    return false;
}

bool pixel_message(char *msg, size_t size, const Image *im, int x, int y, Rgb expected,
                   const char *what)
{
    if (!inside(x, y, im->width, im->height))
        return outside_message(msg, size, x, y, im->width, im->height, what);
    Rgb got = image_get(im, x, y);
    if (got.r == expected.r && got.g == expected.g && got.b == expected.b)
        return true;
    snprintf(msg, size, "%s%spixel (%d, %d): expected rgb %d,%d,%d, got rgb %d,%d,%d",
             prefix(what), separator(what), x, y, expected.r, expected.g, expected.b, got.r,
             got.g, got.b);
    return false;
}

bool face_message(char *msg, size_t size, const Image *id_picture, int x, int y,
                  int32_t face, const char *what)
{
    if (!inside(x, y, id_picture->width, id_picture->height))
        return outside_message(msg, size, x, y, id_picture->width, id_picture->height, what);
    Rgb got = image_get(id_picture, x, y);
    int32_t got_face = id_colour_face(got);
    if (got_face == face)
        return true;
    char want_words[64], got_words[64];
    describe_face(want_words, sizeof want_words, face,
                  face == NO_FACE ? ID_BACKGROUND : face_id_colour(face));
    describe_face(got_words, sizeof got_words, got_face, got);
    snprintf(msg, size, "%s%spixel (%d, %d): expected %s, got %s", prefix(what),
             separator(what), x, y, want_words, got_words);
    return false;
}

bool target_face_message(char *msg, size_t size, const Target *t, int x, int y,
                         int32_t face, const char *what)
{
    if (!inside(x, y, t->width, t->height))
        return outside_message(msg, size, x, y, t->width, t->height, what);
    int32_t got = target_face_at(t, x, y);
    if (got == face)
        return true;
    char want_words[32], got_words[32];
    if (face == NO_FACE)
        snprintf(want_words, sizeof want_words, "no face");
    else
        snprintf(want_words, sizeof want_words, "face %ld", (long)face);
    if (got == NO_FACE)
        snprintf(got_words, sizeof got_words, "no face");
    else
        snprintf(got_words, sizeof got_words, "face %ld", (long)got);
    snprintf(msg, size, "%s%spixel (%d, %d): expected %s, got %s", prefix(what),
             separator(what), x, y, want_words, got_words);
    return false;
}

/* ---- the checks: the words, then a failure at the test's line ---- */

static void fail_with(const char *msg, const char *file, int line)
{
    print_error("%s\n", msg);
    observed_fail(file, line);
}

void expect_count_at(long expected, long actual, const char *what, const char *file,
                     int line)
{
    char msg[MESSAGE_MAX];
    observe_exact(file, line, "count %ld %ld", expected, actual);
    if (!count_message(msg, sizeof msg, expected, actual, what))
        fail_with(msg, file, line);
}

void expect_at_least_at(long least, long actual, const char *what, const char *file,
                        int line)
{
    char msg[MESSAGE_MAX];
    observe_bound(file, line, '>', actual, least);
    if (!at_least_message(msg, sizeof msg, least, actual, what))
        fail_with(msg, file, line);
}

void expect_drawn_at(const Image *id_picture, const char *what, const char *file, int line)
{
    char words[MESSAGE_MAX];
    snprintf(words, sizeof words, "%s%spixels with a face", prefix(what), separator(what));
    expect_at_least_at((long)id_picture->width * id_picture->height / 100,
                       faces_shown(id_picture), words, file, line);
}

void expect_at_most_at(long most, long actual, const char *what, const char *file, int line)
{
    char msg[MESSAGE_MAX];
    observe_bound(file, line, '<', actual, most);
    if (!at_most_message(msg, sizeof msg, most, actual, what))
        fail_with(msg, file, line);
}

void expect_colour_at(Rgb expected, Rgb actual, const char *what, const char *file,
                      int line)
{
    char msg[MESSAGE_MAX];
    observe_exact(file, line, "colour %d,%d,%d %d,%d,%d", expected.r, expected.g, expected.b,
                  actual.r, actual.g, actual.b);
    if (!colour_message(msg, sizeof msg, expected, actual, what))
        fail_with(msg, file, line);
}

void expect_colour_that_at(Rgb actual, bool ok, const char *what, const char *expected_words,
                           const char *file, int line)
{
    char msg[MESSAGE_MAX];
    observe_exact(file, line, "colour that %d", ok);
    if (!colour_that_message(msg, sizeof msg, actual, ok, what, expected_words))
        fail_with(msg, file, line);
}

void expect_pixel_at(const Image *im, int x, int y, Rgb expected, const char *what,
                     const char *file, int line)
{
    char msg[MESSAGE_MAX];
    Rgb got = inside(x, y, im->width, im->height) ? image_get(im, x, y) : (Rgb){0, 0, 0};
    observe_exact(file, line, "pixel %d %d %d,%d,%d %d,%d,%d", x, y, expected.r, expected.g,
                  expected.b, got.r, got.g, got.b);
    if (!pixel_message(msg, sizeof msg, im, x, y, expected, what))
        fail_with(msg, file, line);
}

void expect_face_at_at(const Image *id_picture, int x, int y, int32_t face, const char *what,
                       const char *file, int line)
{
    char msg[MESSAGE_MAX];
    observe_exact(file, line, "face %d %d %ld %ld", x, y, (long)face,
                  inside(x, y, id_picture->width, id_picture->height)
                      ? (long)face_at(id_picture, x, y) : -2L);
    if (!face_message(msg, sizeof msg, id_picture, x, y, face, what))
        fail_with(msg, file, line);
}

void expect_target_face_at(const Target *t, int x, int y, int32_t face, const char *what,
                           const char *file, int line)
{
    char msg[MESSAGE_MAX];
    observe_exact(file, line, "target face %d %d %ld %ld", x, y, (long)face,
                  inside(x, y, t->width, t->height) ? (long)target_face_at(t, x, y) : -2L);
    if (!target_face_message(msg, sizeof msg, t, x, y, face, what))
        fail_with(msg, file, line);
}
