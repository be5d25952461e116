/* Integrals of the kernels over one straight constant element [a, b]. */
#ifndef GB_BEM_SEGMENT_H
#define GB_BEM_SEGMENT_H

#include "bem/kernel.h"

/* Closed forms of int u* and int p* (2x2 row-major [l][k]) over [a, b] seen from x, exact for any
 * x off the element (no quadrature, so nearly singular points lose nothing). self = 1: x is the
 * element's own midpoint; g gets the singular closed form (docs/method.md section 9) and h the
 * principal value, which is zero (the jump 1/2 I is not included). */
void gb_bem_segment_gh(const gb_bem_kconst *k, const double x[2], const double a[2], const double b[2], int self,
                       double g[4], double h[4]);

/* Adaptive Gauss-Legendre integration of int D and int S ([k][ij], ij = xx, yy, xy) over [a, b]
 * from an interior point x: pieces longer than a quarter of their distance to x are halved. */
void gb_bem_segment_ds(const gb_bem_kconst *k, const double x[2], const double a[2], const double b[2], double d[6],
                       double s[6]);

/* The same adaptive rule for u* and p* (to check the closed forms). */
void gb_bem_segment_gh_quadrature(const gb_bem_kconst *k, const double x[2], const double a[2], const double b[2],
                                  double g[4], double h[4]);

#endif
