#include "bem/mixed.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bem/kernel.h"

gb_bem_guard gb_bem_guard_default(void)
{
    gb_bem_guard g;
    g.rcond_min = 0; /* auto: 0.05 / n (a sound G of n unknowns: about 1 / n) */
    return g;
}

gb_status gb_bem_mixed_init(gb_bem_mixed *mx, const gb_bem_mesh *mesh, const gb_bem_system *sys,
                            const unsigned char *t_unknown, int border, gb_error *err)
{
    gb_bem_kconst k;
    gb_status st = gb_bem_kconst_init(&sys->material, &k, err);
    if (st) return st;
    if (sys->ndof != 2 * mesh->n) return gb_fail(err, GB_EINTERNAL, "the system does not belong to this mesh");
    mx->mesh = mesh;
    mx->sys = sys;
    mx->t_unknown = t_unknown;
    mx->border = border;
    mx->cdeg = (3 - 4 * k.nu) * k.cu;
    return GB_OK;
}

int gb_bem_mixed_size(const gb_bem_mixed *mx)
{
    return mx->sys->ndof + (mx->border ? 3 : 0);
}

void gb_bem_mixed_gcol(const gb_bem_mixed *mx, double lambda, int d, double f, double *y)
{
    size_t nd = (size_t)mx->sys->ndof;
    const double *g = mx->sys->G + (size_t)d * nd;
    for (size_t i = 0; i < nd; i++) y[i] += f * g[i];
    if (lambda != 0) {
        double s = -f * mx->cdeg * lambda * mx->mesh->length[d / 2];
        for (size_t i = (size_t)(d % 2); i < nd; i += 2) y[i] += s;
    }
}

void gb_bem_mixed_fill(const gb_bem_mixed *mx, double lambda, double *A)
{
    const gb_bem_mesh *m = mx->mesh;
    size_t nd = (size_t)mx->sys->ndof, na = (size_t)gb_bem_mixed_size(mx);
    for (size_t d = 0; d < nd; d++) {
        double *c = A + d * na;
        if (mx->t_unknown[d]) {
            memset(c, 0, nd * sizeof(double));
            gb_bem_mixed_gcol(mx, lambda, (int)d, -1.0, c);
        } else {
            memcpy(c, mx->sys->H + d * nd, nd * sizeof(double));
        }
        for (size_t r = nd; r < na; r++) c[r] = 0;
    }
    if (!mx->border) return;
    /* rigid-body modes weighted by element length: x, y translation, rotation about the centroid */
    double cx = 0, cy = 0, P = 0;
    for (int e = 0; e < m->n; e++) {
        cx += m->length[e] * m->mid[2 * e];
        cy += m->length[e] * m->mid[2 * e + 1];
        P += m->length[e];
    }
    cx /= P;
    cy /= P;
    for (size_t c = nd; c < na; c++) memset(A + c * na, 0, na * sizeof(double));
    for (int e = 0; e < m->n; e++) {
        double L = m->length[e] / P, rx = (m->mid[2 * e] - cx), ry = (m->mid[2 * e + 1] - cy);
        double modes[3][2] = {{L, 0}, {0, L}, {-L * ry, L * rx}};
        for (int k = 0; k < 3; k++)
            for (int c = 0; c < 2; c++) {
                size_t d = (size_t)(2 * e + c);
                A[(nd + (size_t)k) * na + d] = modes[k][c]; /* column: constraint forces */
                A[d * na + nd + (size_t)k] = modes[k][c];   /* row: the constraint itself */
            }
    }
}

static double half_diagonal(const gb_bem_mesh *m)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int e = 0; e < m->n; e++)
        for (int c = 0; c < 2; c++) {
            lo[c] = fmin(lo[c], m->p0[2 * e + c]);
            hi[c] = fmax(hi[c], m->p0[2 * e + c]);
        }
    return 0.5 * hypot(hi[0] - lo[0], hi[1] - lo[1]);
}

gb_status gb_bem_mixed_factor(const gb_bem_mixed *mx, const gb_bem_guard *guard, gb_bem_lu *lu, double *lambda,
                              double *rcond_first, gb_error *err)
{
    gb_bem_guard dg = gb_bem_guard_default();
    if (!guard) guard = &dg;
    int na = gb_bem_mixed_size(mx), has_g = 0;
    for (int d = 0; d < mx->sys->ndof; d++) has_g |= mx->t_unknown[d];
    gb_status st = gb_bem_lu_alloc(lu, na, err);
    if (st) return st;
    *lambda = 0;
    gb_bem_mixed_fill(mx, 0, lu->a);
    if ((st = gb_bem_lu_factor(lu, err))) return st;
    *rcond_first = lu->rcond;
    double rmin = guard->rcond_min > 0 ? guard->rcond_min : guard->rcond_min == 0 ? 0.05 / na : 0;
    if (has_g && lu->rcond < rmin) {
        /* near a degenerate scale: redo in lengths where the body's half-diagonal is 1/4 */
        double r0 = lu->rcond, l1 = log(0.25 / half_diagonal(mx->mesh));
        if (fabs(l1) < 0.5) l1 -= 1.5;
        gb_bem_mixed_fill(mx, l1, lu->a);
        if ((st = gb_bem_lu_factor(lu, err))) return st;
        if (lu->rcond > 10 * r0) {
            *lambda = l1;
        } else { /* not a scale problem: back to the problem's own lengths */
            gb_bem_mixed_fill(mx, 0, lu->a);
            if ((st = gb_bem_lu_factor(lu, err))) return st;
        }
    }
    if (lu->singular || lu->rcond < 1e-15)
        return gb_fail(err, GB_ENUMERIC,
                       "the boundary element system is singular (rcond %.3g): is the body held against rigid motion, "
                       "and is every boundary part given a condition?",
                       lu->rcond);
    return GB_OK;
}
