/* Kelvin's fundamental solution for plane elasticity (H 1-2) and its stress kernels, at a point.
 * Convention: x is the source (collocation or interior) point, y the field point on the boundary,
 * r = |y - x|, r_,i = (y_i - x_i)/r, n the outward normal at y. Plane stress uses nu/(1+nu). */
#ifndef GB_BEM_KERNEL_H
#define GB_BEM_KERNEL_H

#include "gembem/bem.h"

#define GB_PI 3.14159265358979323846

typedef struct {
    double mu, nu; /* shear modulus and the effective Poisson ratio of the kernels */
    double cu;     /* 1 / (8 pi mu (1 - nu)):  u* */
    double cp;     /* -1 / (4 pi (1 - nu)):    p* */
    double cd;     /* 1 / (4 pi (1 - nu)):     D */
    double cs;     /* mu / (2 pi (1 - nu)):    S */
} gb_bem_kconst;

/* Fails (GB_EINPUT) for mu <= 0 or nu outside (-1, 0.5). */
gb_status gb_bem_kconst_init(const gb_bem_material *mat, gb_bem_kconst *k, gb_error *err);

/* u*_lk and p*_lk as 2x2 row-major [l][k]: l the load direction at x, k the component at y. */
void gb_bem_kelvin_u(const gb_bem_kconst *k, const double x[2], const double y[2], double u[4]);
void gb_bem_kelvin_p(const gb_bem_kconst *k, const double x[2], const double y[2], const double n[2], double p[4]);

/* Stress kernels: sigma_ij(x) = int D_kij t_k - int S_kij u_k. Output [k][ij], ij = xx, yy, xy. */
void gb_bem_kelvin_ds(const gb_bem_kconst *k, const double x[2], const double y[2], const double n[2], double d[6],
                      double s[6]);

#endif
