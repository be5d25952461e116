/* Displacement and stress inside the body (H 1 with c = 1) and stress on the boundary. */
#include <math.h>
#include <stdlib.h>

#include "bem/kernel.h"
#include "bem/remote.h"
#include "bem/segment.h"
#include "gembem/bem.h"

gb_status gb_bem_interior(const gb_bem_mesh *m, const gb_bem_material *mat, const gb_bem_problem *prob,
                          const gb_bem_solution *sol, int npts, const double *xy, double *u, double *stress,
                          gb_error *err)
{
    gb_bem_kconst k;
    gb_status st = gb_bem_kconst_init(mat, &k, err);
    if (st) return st;
    if (sol->ndof != 2 * m->n) return gb_fail(err, GB_EINTERNAL, "the solution does not belong to this mesh");
    double hmin = INFINITY;
    for (int e = 0; e < m->n; e++) hmin = fmin(hmin, m->length[e]);
    /* the perturbation of the remote field carries the boundary integrals */
    int remote = gb_bem_remote_active(m, prob);
    double *up = malloc(sizeof(double) * 2 * (size_t)m->n), *tp = malloc(sizeof(double) * 2 * (size_t)m->n);
    if (!up || !tp) {
        free(up);
        free(tp);
        return gb_fail(err, GB_ENOMEM, "out of memory");
    }
    for (int e = 0; e < m->n; e++) {
        double ru[2] = {0, 0}, rt[2] = {0, 0};
        if (remote) {
            gb_bem_remote_u(mat, prob, m->mid + 2 * e, ru);
            gb_bem_remote_t(prob, m->normal + 2 * e, rt);
        }
        for (int c = 0; c < 2; c++) {
            up[2 * e + c] = sol->u[2 * e + c] - ru[c];
            tp[2 * e + c] = sol->t[2 * e + c] - rt[c];
        }
    }
    for (int p = 0; p < npts && !st; p++) {
        const double *x = xy + 2 * p;
        if (!gb_bem_mesh_inside(m, x[0], x[1]) || gb_bem_mesh_distance(m, x[0], x[1]) < 1e-9 * hmin) {
            st = gb_fail(err, GB_EINPUT, "interior point %d (%.6g, %.6g) is not inside the body", p, x[0], x[1]);
            break;
        }
        double uu[2] = {0, 0}, ss[3] = {0, 0, 0};
        for (int e = 0; e < m->n; e++) {
            const double *a = m->p0 + 2 * e, *b = m->p1 + 2 * e, *te = tp + 2 * e, *ue = up + 2 * e;
            if (u) {
                double g[4], h[4];
                gb_bem_segment_gh(&k, x, a, b, 0, g, h);
                for (int l = 0; l < 2; l++)
                    uu[l] += g[2 * l] * te[0] + g[2 * l + 1] * te[1] - h[2 * l] * ue[0] - h[2 * l + 1] * ue[1];
            }
            if (stress) {
                double d[6], s[6];
                gb_bem_segment_ds(&k, x, a, b, d, s);
                for (int c = 0; c < 3; c++) ss[c] += d[c] * te[0] + d[3 + c] * te[1] - s[c] * ue[0] - s[3 + c] * ue[1];
            }
        }
        if (u) {
            double ru[2] = {0, 0};
            if (remote) gb_bem_remote_u(mat, prob, x, ru);
            u[2 * p] = uu[0] + ru[0];
            u[2 * p + 1] = uu[1] + ru[1];
        }
        if (stress)
            for (int c = 0; c < 3; c++) stress[3 * p + c] = ss[c] + (remote ? prob->remote_stress[c] : 0);
    }
    free(up);
    free(tp);
    return st;
}

gb_status gb_bem_boundary_stress(const gb_bem_mesh *m, const gb_bem_material *mat, const gb_bem_solution *sol,
                                 double *stress, gb_error *err)
{
    gb_bem_kconst k;
    gb_status st = gb_bem_kconst_init(mat, &k, err);
    if (st) return st;
    for (int l = 0; l < m->n_loops; l++) {
        int s0 = m->loop_start[l], c = m->loop_start[l + 1] - s0;
        for (int j = 0; j < c; j++) {
            int e = s0 + j, ep = s0 + (j + c - 1) % c, en = s0 + (j + 1) % c;
            const double *t = m->tangent + 2 * e, *n = m->normal + 2 * e;
            double ds = 0.5 * m->length[ep] + m->length[e] + 0.5 * m->length[en];
            double du[2] = {(sol->u[2 * en] - sol->u[2 * ep]) / ds, (sol->u[2 * en + 1] - sol->u[2 * ep + 1]) / ds};
            double ett = du[0] * t[0] + du[1] * t[1];
            double snn = sol->t[2 * e] * n[0] + sol->t[2 * e + 1] * n[1];
            double snt = sol->t[2 * e] * t[0] + sol->t[2 * e + 1] * t[1];
            double stt = (2 * k.mu * ett + k.nu * snn) / (1 - k.nu); /* Hooke, plane strain form */
            stress[3 * e] = snn * n[0] * n[0] + stt * t[0] * t[0] + 2 * snt * n[0] * t[0];
            stress[3 * e + 1] = snn * n[1] * n[1] + stt * t[1] * t[1] + 2 * snt * n[1] * t[1];
            stress[3 * e + 2] = snn * n[0] * n[1] + stt * t[0] * t[1] + snt * (n[0] * t[1] + n[1] * t[0]);
        }
    }
    return GB_OK;
}
