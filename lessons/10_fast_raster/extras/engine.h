/* engine.h: what lesson 10's extras/ files share among themselves, besides
 * what fast_raster.h declares: the faces held back for the threads to set
 * up (held.c), the bins' memory (engine.c), the kernels' choice (kernels.c), the
 * windows 16 wide (wide.c). */
#ifndef ENGINE_H
#define ENGINE_H

#include "fast_raster.h"

void set_up_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx); /* now */
bool hold_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx);
void held_free(FastRaster *fr);
void pool_free(Pool *pool); /* its threads joined */
void bins_free(Bins *b);
/* The n bins, of tiles tiles each: their boxes hold 4 times the pixels of the tiles they touch. */
bool bins_heaped(int tiles, Bins *const *bins, int n);
/* Room for need items of size bytes in *items, of *cap; false (nothing changed) without. */
bool grow_array(void **items, size_t *cap, size_t need, size_t size);

extern const BlockKernels SSE2_KERNELS, AVX2_KERNELS, AVX512_KERNELS; /* simd.c, avx512.c */
WideKernel avx2_wide, avx512_wide;         /* wide.c */
WideKernel *wide_of(Simd simd);            /* NULL: a small polygon in windows of 8 x 8 */
Simd simd_best(void);                      /* the widest this machine has */
const BlockKernels *kernels_of(Simd simd); /* PLAIN_KERNELS without SIMD */

#endif
