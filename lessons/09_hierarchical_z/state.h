/* state.h: what the lesson keeps besides the target, handed to its
 * rasterizer's functions (rasterizer.h): the depth buffer's format and
 * mapping, chosen once before the clear, then what each lesson adds. */
#ifndef STATE_H
#define STATE_H

#include "depth_bias.h"
#include "early_z.h"
#include "hierarchical_z.h"

struct LessonState {
    DepthSetup depth;
    DepthBias bias;
    EarlyZ early_z;
    HierarchicalZ *hiz; /* NULL: none, every covered pixel tested */
};

#endif
