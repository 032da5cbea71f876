/* font.h: a tiny built-in bitmap font, to label pictures (panels, plots,
 * legends) without a font file.
 *
 * Every printable ASCII character (' ' to '~') is a 5 x 7 glyph in a cell
 * FONT_ADVANCE pixels wide and FONT_LINE_HEIGHT tall: one empty column after
 * each glyph, two empty rows under each line. Any other byte draws as '?'.
 * Lower-case letters with a tail (g, j, p, q, y) keep it inside the 7 rows.
 *
 *     draw_text(&im, 10, 4, "near", (Rgb){255, 255, 255});
 *
 * (x, y) is the top-left pixel of the first glyph; '\n' starts a new line
 * under the first. Pixels outside the image are skipped, so a label may run
 * off an edge. Only the glyphs' pixels are set: the background shows through. */
#ifndef FONT_H
#define FONT_H

#include "image_io.h"

#define FONT_GLYPH_WIDTH 5
#define FONT_GLYPH_HEIGHT 7
#define FONT_ADVANCE 6      /* from one glyph's left column to the next one's */
#define FONT_LINE_HEIGHT 9  /* from one line's top row to the next one's */

void draw_text(Image *im, int x, int y, const char *text, Rgb colour);

/* The size in pixels of the box draw_text fills for text: its longest line's
 * glyphs without the trailing empty column, and its lines' rows without the
 * last line's empty rows; 0 x 0 for "". */
int text_width(const char *text);
int text_height(const char *text);

#endif
