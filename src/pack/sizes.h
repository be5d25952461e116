/* The grains' radii from a pack scene's size distribution. */
#ifndef GB_PACK_SIZES_H
#define GB_PACK_SIZES_H

#include <stdint.h>

#include "gembem/pack.h"

/* The mean area pi r^2 of one grain under the distribution (the expected one: a lognormal's by
 * quadrature of its cut density). */
double gb_sizes_mean_area(const gb_pack_sizes *z);
/* The largest radius the distribution can give. */
double gb_sizes_max_radius(const gb_pack_sizes *z);
/* n radii in the grains' order, reproducible from the seed. Discrete sizes: each size's count is
 * its ideal share of n (by number or by area) rounded by largest remainders, the list shuffled;
 * uniform and lognormal: n independent draws. */
void gb_sizes_draw(const gb_pack_sizes *z, long n, uint64_t seed, double *r);

#endif
