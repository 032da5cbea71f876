/* compare_naive.h: where the naive rule goes wrong (--compare-naive FILE.png).
 *
 * Lesson 03's extras give two rasterizers: the right one, which takes 1/d to
 * be linear on the screen, and the naive one, which takes d to be (lesson
 * 02's rule). The scene is drawn with each, and the picture of the right one
 * is written with every pixel where the naive rule shows another face (or a
 * face where there is none, or none where there is one) in magenta; every
 * other pixel keeps its colour at half brightness.
 *
 * Lesson 05's --compare-drop is the same comparison with other rasterizers:
 * its clipping one against lesson 04's, which drops a face at the near plane. */
#ifndef COMPARE_NAIVE_H
#define COMPARE_NAIVE_H

#include "render.h"

/* Draws r with both rasterizers, writes the picture to path (colours as opt->shade
 * says) and counts the marked pixels into *differing. r's face counts are
 * left as they were, so that the summary speaks of the main render only.
 * False (err set) when out of memory or the picture cannot be written. */
bool compare_with_naive(Render *r, const Options *opt, const Rasterizer *right,
                        const Rasterizer *naive, const char *path, long *differing, Error *err);

#endif
