/* state.h: what the lesson keeps besides the target, handed to its
 * rasterizer's functions (rasterizer.h): the depth buffer's format and
 * mapping, chosen once before the clear, then what each lesson adds. */
#ifndef STATE_H
#define STATE_H

#include "depth_bias.h"
#include "fast_raster.h"

struct LessonState {
    DepthSetup depth;
    DepthBias bias;
    FastRaster fast;
    HierarchicalZ *hiz; /* one tile per block, or NULL: none */
};

#endif
