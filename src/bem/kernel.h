/* Kelvin's fundamental solution for plane elasticity (H 1-2), private part: the constant pi of the
 * module's kernels and quadratures. */
#ifndef GB_BEM_KERNEL_H
#define GB_BEM_KERNEL_H

#include "gembem/bem.h"

#define GB_PI 3.14159265358979323846

/* gb_bem_kconst, gb_bem_kconst_init and the kernels: gembem/bem.h. */

#endif
