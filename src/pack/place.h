/* Random sequential addition of discs in a region. */
#ifndef GB_PACK_PLACE_H
#define GB_PACK_PLACE_H

#include <stdint.h>

#include "pack/region.h"

/* Places n discs of radii scale r[i] (into g, in the grains' order): the largest first, each at
 * uniform random points of the region's bounding box until one fits the region and overlaps no
 * disc placed before. GB_EINPUT when a disc finds no place in max_tries tries. */
gb_status gb_place_random(const gb_region *rg, const double *r, int n, double scale, uint64_t seed, int max_tries,
                          gb_grain *g, gb_error *err);

#endif
