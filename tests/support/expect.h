/* expect.h: checks on pixels, colours and counts whose failure says, in words
 * and decimal, what was expected and what came:
 *
 *   covered pixels: expected 9226, got 9230
 *   pixel (12, 40): expected face 3 (rgb 0,0,4), got face 2 (rgb 0,0,3)
 *
 * where cmocka's assert_int_equal would print "0x4010000 != 0x4000000".
 * Each check is a macro, so that a failure points at the test's own line
 * (variadic, so that an argument may be a compound literal, (Rgb){1, 2, 3}).
 * `what` names the value in the test's words ("covered pixels", "the red
 * triangle's tip"); it may be "" when the pixel or the number says enough.
 *
 * The *_message functions hold the wording: each returns true when the check
 * passes, else writes the message into msg and returns false. The checks are
 * these functions plus a failure; tests/common/test_test_support.c tests the
 * words. */
#ifndef EXPECT_H
#define EXPECT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "harness/image_io.h"
#include "target.h"

/* The face a pixel of an id picture (--id-out) shows, NO_FACE for
 * the black background. */
int32_t face_at(const Image *id_picture, int x, int y);
/* How many pixels of an id picture show a face. */
long faces_shown(const Image *id_picture);
/* What the target holds at pixel (x, y). */
int32_t target_face_at(const Target *t, int x, int y);
float target_depth_at(const Target *t, int x, int y);

/* expect_count(expected, actual, what): "what: expected 9226, got 9230".
 * Counts of any integer type (uint64_t fragment counts too) are compared as long. */
#define expect_count(e, a, what) expect_count_at((long)(e), (long)(a), (what), __FILE__, __LINE__)
/* expect_at_least(least, actual, what): "what: expected at least 1, got 0". */
#define expect_at_least(e, a, what) \
    expect_at_least_at((long)(e), (long)(a), (what), __FILE__, __LINE__)
/* expect_drawn(id_picture, what): at least 1 pixel in 100 shows a face,
 * "what: pixels with a face: expected at least 1200, got 0". A test that
 * compares a lesson's picture with another lesson's checks it first: a
 * lesson that draws nothing agrees with another that draws nothing (a
 * handout whose earlier lessons are stubbed too, EARLIER=stubbed). */
#define expect_drawn(id, what) expect_drawn_at((id), (what), __FILE__, __LINE__)
/* expect_at_most(most, actual, what): "what: expected at most 9, got 12". */
#define expect_at_most(e, a, what) \
    expect_at_most_at((long)(e), (long)(a), (what), __FILE__, __LINE__)

/* expect_colour(expected, actual, what):
 * "what: expected rgb 255,0,0, got rgb 0,0,3". */
#define expect_colour(...) expect_colour_at(__VA_ARGS__, __FILE__, __LINE__)
/* expect_colour_that(actual, ok, what, expected_words): a colour that must
 * satisfy ok, described in words:
 * expect_colour_that(c, c.r > 64 && c.g == 0, "pixel (3, 4)", "a shade of red")
 * fails with "pixel (3, 4): expected a shade of red, got rgb 0,200,0". */
#define expect_colour_that(...) expect_colour_that_at(__VA_ARGS__, __FILE__, __LINE__)
/* expect_pixel(image, x, y, expected_rgb, what):
 * "what: pixel (12, 40): expected rgb 255,0,0, got rgb 0,0,0". */
#define expect_pixel(...) expect_pixel_at(__VA_ARGS__, __FILE__, __LINE__)

/* expect_face_at(id_picture, x, y, face, what): the pixel shows face `face`
 * (NO_FACE: the background):
 * "pixel (12, 40): expected face 3 (rgb 0,0,4), got face 2 (rgb 0,0,3)". */
#define expect_face_at(...) expect_face_at_at(__VA_ARGS__, __FILE__, __LINE__)
/* expect_target_face(target, x, y, face, what): the target holds face `face`
 * at pixel (x, y): "pixel (3, 3): expected face 0, got no face". */
#define expect_target_face(...) expect_target_face_at(__VA_ARGS__, __FILE__, __LINE__)

bool count_message(char *msg, size_t size, long expected, long actual, const char *what);
bool at_least_message(char *msg, size_t size, long least, long actual, const char *what);
bool at_most_message(char *msg, size_t size, long most, long actual, const char *what);
bool colour_message(char *msg, size_t size, Rgb expected, Rgb actual, const char *what);
bool colour_that_message(char *msg, size_t size, Rgb actual, bool ok, const char *what,
                         const char *expected_words);
bool pixel_message(char *msg, size_t size, const Image *im, int x, int y, Rgb expected,
                   const char *what);
bool face_message(char *msg, size_t size, const Image *id_picture, int x, int y,
                  int32_t face, const char *what);
bool target_face_message(char *msg, size_t size, const Target *t, int x, int y,
                         int32_t face, const char *what);

void expect_count_at(long expected, long actual, const char *what, const char *file,
                     int line);
void expect_at_least_at(long least, long actual, const char *what, const char *file,
                        int line);
void expect_at_most_at(long most, long actual, const char *what, const char *file, int line);
void expect_drawn_at(const Image *id_picture, const char *what, const char *file, int line);
void expect_colour_at(Rgb expected, Rgb actual, const char *what, const char *file,
                      int line);
void expect_colour_that_at(Rgb actual, bool ok, const char *what, const char *expected_words,
                           const char *file, int line);
void expect_pixel_at(const Image *im, int x, int y, Rgb expected, const char *what,
                     const char *file, int line);
void expect_face_at_at(const Image *id_picture, int x, int y, int32_t face, const char *what,
                       const char *file, int line);
void expect_target_face_at(const Target *t, int x, int y, int32_t face, const char *what,
                           const char *file, int line);

#endif
