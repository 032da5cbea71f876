/* plot.h: --precision-plot, a log-log chart of the depth step (depth_step,
 * in world units) against view distance d, from near to far, for every
 * format and mapping, with the ladder's gap as a line: where a curve rises
 * above it, the ladder's plates at that distance can no longer be told apart. */
#ifndef PLOT_H
#define PLOT_H

#include <stdbool.h>

#include "error.h"

bool precision_plot(const char *path, double near, double far, Error *err);

#endif
