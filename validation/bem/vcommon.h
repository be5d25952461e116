/* Shared helpers of the BEM validation programs: meshes through gmsh, errors, orders. */
#ifndef GB_BEM_VCOMMON_H
#define GB_BEM_VCOMMON_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gembem/bem.h"

#define V_PI 3.14159265358979323846

static int v_failures = 0;

#define V_CHECK(cond, ...)                                                                                             \
    do {                                                                                                               \
        if (!(cond)) {                                                                                                 \
            fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond);                                   \
            fprintf(stderr, __VA_ARGS__);                                                                              \
            fprintf(stderr, "\n");                                                                                     \
            v_failures++;                                                                                              \
        }                                                                                                              \
    } while (0)

static inline void v_die(const gb_error *err)
{
    fprintf(stderr, "error: %s\n", err->msg);
    exit(1);
}

/* gmsh mesh of a .geo with element counts per group (name, count pairs, NULL-terminated). */
static inline void v_mesh(const char *geo, int unbounded, const char *g1, int n1, const char *g2, int n2,
                          gb_bem_mesh *m)
{
    gb_error err = {0};
    gb_bem_mesh_opts o = gb_bem_mesh_opts_default();
    o.unbounded = unbounded;
    if (g1) {
        snprintf(o.group_sizes[o.n_group_sizes].group, GB_BEM_NAME_MAX, "%s", g1);
        o.group_sizes[o.n_group_sizes++].count = n1;
    }
    if (g2) {
        snprintf(o.group_sizes[o.n_group_sizes].group, GB_BEM_NAME_MAX, "%s", g2);
        o.group_sizes[o.n_group_sizes++].count = n2;
    }
    if (gb_bem_mesh_load(geo, &o, m, &err)) v_die(&err);
}

/* Lamé's thick cylinder a < r < b, inner pressure p: u_r = A r + B / r,
 * s_rr = 2 (lam + mu) A - 2 mu B / r^2, lam = 2 mu nu / (1 - 2 nu) (plane strain) or
 * 2 mu nu / (1 - nu) (plane stress); outer fixed (A b + B / b = 0) or free (s_rr(b) = 0). */
typedef struct {
    double A, B, lam, mu;
} v_lame;

static inline v_lame v_lame_solve(double mu, double nu, int plane_stress, int outer_free, double a, double b, double p)
{
    v_lame L;
    L.mu = mu;
    L.lam = plane_stress ? 2 * mu * nu / (1 - nu) : 2 * mu * nu / (1 - 2 * nu);
    double k = 2 * (L.lam + mu);
    if (!outer_free) { /* B = -A b^2; k A + 2 mu A b^2 / a^2 = -p */
        L.A = -p / (k + 2 * mu * b * b / (a * a));
        L.B = -L.A * b * b;
    } else { /* k A = 2 mu B / b^2; k A - 2 mu B / a^2 = -p */
        L.B = -p / (2 * mu * (1 / (b * b) - 1 / (a * a)));
        L.A = 2 * mu * L.B / (b * b) / k;
    }
    return L;
}

static inline double v_lame_ur(const v_lame *L, double r)
{
    return L->A * r + L->B / r;
}
static inline double v_lame_srr(const v_lame *L, double r)
{
    return 2 * (L->lam + L->mu) * L->A - 2 * L->mu * L->B / (r * r);
}
static inline double v_lame_stt(const v_lame *L, double r)
{
    return 2 * (L->lam + L->mu) * L->A + 2 * L->mu * L->B / (r * r);
}

static inline double v_order(double e_coarse, double e_fine, double ratio)
{
    return log(e_coarse / e_fine) / log(ratio);
}

#endif
