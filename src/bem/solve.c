/* The mixed boundary value problem: one LU of the system H u = G t with the given halves moved
 * to the right-hand side. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bem/bc.h"
#include "bem/mixed.h"
#include "bem/remote.h"
#include "gembem/bem.h"

void gb_bem_solution_free(gb_bem_solution *sol)
{
    if (!sol) return;
    free(sol->u);
    free(sol->t);
    memset(sol, 0, sizeof *sol);
}

/* A traction-only bounded body: its loads must balance (force and moment). */
static gb_status check_equilibrium(const gb_bem_mesh *m, const double *t, gb_error *err)
{
    double F[2] = {0, 0}, M = 0, mag = 0, R = 0;
    for (int e = 0; e < m->n; e++) {
        double L = m->length[e], *x = m->mid + 2 * e;
        F[0] += L * t[2 * e];
        F[1] += L * t[2 * e + 1];
        M += L * (x[0] * t[2 * e + 1] - x[1] * t[2 * e]);
        mag += L * hypot(t[2 * e], t[2 * e + 1]);
        R = fmax(R, hypot(x[0], x[1]));
    }
    if (mag > 0 && (hypot(F[0], F[1]) > 1e-8 * mag || fabs(M) > 1e-8 * mag * R))
        return gb_fail(err, GB_EINPUT,
                       "the body is loaded by tractions only and they are not in equilibrium (resultant %.6g, %.6g; "
                       "moment %.6g): fix or prescribe a displacement somewhere",
                       F[0], F[1], M);
    return GB_OK;
}

/* The known half of each DOF (tu) and its value (given): the problem's conditions, or with a group
 * (>= 0) that group's displacements u_group instead of its own condition (less the remote field's,
 * which is added back at the end). */
static gb_status known_halves(const gb_bem_mesh *m, const gb_bem_system *sys, const gb_bem_problem *prob, int group,
                              const double *u_group, unsigned char *tu, double *given, gb_error *err)
{
    if (group < 0) return gb_bem_bc_dofs(m, &sys->material, prob, tu, given, err);
    gb_bem_problem p = *prob; /* the group's own condition is replaced: any valid kind will do */
    p.bc[group].kind = GB_BEM_BC_FIXED;
    gb_status st = gb_bem_bc_dofs(m, &sys->material, &p, tu, given, err);
    for (int e = 0, q = 0; !st && e < m->n; e++) {
        if (m->group[e] != group) continue;
        double ru[2] = {0, 0};
        if (gb_bem_remote_active(m, prob)) gb_bem_remote_u(&sys->material, prob, m->mid + 2 * e, ru);
        for (int c = 0; c < 2; c++) {
            tu[2 * e + c] = 1;
            given[2 * e + c] = u_group[2 * q + c] - ru[c];
        }
        q++;
    }
    return st;
}

/* The solution from the mixed system's b (the unknown halves) and the given ones, with the remote
 * field's displacements and tractions added; an error if it is not finite. */
static gb_status assemble_solution(const gb_bem_mesh *m, const gb_bem_system *sys, const gb_bem_problem *prob,
                                   const unsigned char *tu, const double *given, const double *b,
                                   gb_bem_solution *sol, gb_error *err)
{
    int nd = 2 * m->n;
    sol->ndof = nd;
    sol->u = malloc(sizeof(double) * (size_t)nd);
    sol->t = malloc(sizeof(double) * (size_t)nd);
    if (!sol->u || !sol->t) return gb_fail(err, GB_ENOMEM, "out of memory");
    for (int d = 0; d < nd; d++) {
        sol->u[d] = tu[d] ? given[d] : b[d];
        sol->t[d] = tu[d] ? b[d] : given[d];
    }
    if (gb_bem_remote_active(m, prob))
        for (int e = 0; e < m->n; e++) {
            double ru[2], rt[2];
            gb_bem_remote_u(&sys->material, prob, m->mid + 2 * e, ru);
            gb_bem_remote_t(prob, m->normal + 2 * e, rt);
            for (int c = 0; c < 2; c++) {
                sol->u[2 * e + c] += ru[c];
                sol->t[2 * e + c] += rt[c];
            }
        }
    for (int d = 0; d < nd; d++)
        if (!isfinite(sol->u[d]) || !isfinite(sol->t[d]))
            return gb_fail(err, GB_ENUMERIC, "the boundary solution is not finite");
    return GB_OK;
}

static gb_status solve(const gb_bem_mesh *m, const gb_bem_system *sys, const gb_bem_problem *prob, int group,
                       const double *u_group, const gb_bem_guard *guard, gb_bem_solution *sol, gb_error *err)
{
    memset(sol, 0, sizeof *sol);
    int nd = 2 * m->n;
    unsigned char *tu = malloc((size_t)nd);
    double *given = malloc(sizeof(double) * (size_t)nd), *b = NULL;
    gb_bem_lu lu;
    memset(&lu, 0, sizeof lu);
    gb_status st = (!tu || !given) ? gb_fail(err, GB_ENOMEM, "out of memory") : GB_OK;
    if (!st) st = known_halves(m, sys, prob, group, u_group, tu, given, err);
    int any_u = 0;
    for (int d = 0; !st && d < nd; d++) any_u |= tu[d];
    int border = !st && !m->unbounded && !any_u;
    if (border) st = check_equilibrium(m, given, err);
    gb_bem_mixed mx;
    double lambda = 0;
    if (!st) st = gb_bem_mixed_init(&mx, m, sys, tu, border, err);
    if (!st) st = gb_bem_mixed_factor(&mx, guard, &lu, &lambda, &sol->rcond_first, err);
    int na = lu.n;
    if (!st && !(b = calloc((size_t)na, sizeof(double)))) st = gb_fail(err, GB_ENOMEM, "out of memory");
    for (int d = 0; !st && d < nd; d++) {
        if (given[d] == 0) continue;
        if (tu[d]) { /* -H_d ubar */
            const double *h = sys->H + (size_t)d * (size_t)nd;
            for (int i = 0; i < nd; i++) b[i] -= h[i] * given[d];
        } else {
            gb_bem_mixed_gcol(&mx, lambda, d, given[d], b);
        }
    }
    if (!st) st = gb_bem_lu_solve(&lu, 1, b, err);
    if (!st) {
        sol->rcond = lu.rcond;
        sol->scale = exp(lambda);
        sol->rigid_constrained = border;
        st = assemble_solution(m, sys, prob, tu, given, b, sol, err);
    }
    if (st) gb_bem_solution_free(sol);
    gb_bem_lu_free(&lu);
    free(tu);
    free(given);
    free(b);
    return st;
}

gb_status gb_bem_solve(const gb_bem_mesh *m, const gb_bem_system *sys, const gb_bem_problem *prob,
                       const gb_bem_guard *guard, gb_bem_solution *sol, gb_error *err)
{
    return solve(m, sys, prob, -1, NULL, guard, sol, err);
}

gb_status gb_bem_solve_group_displacement(const gb_bem_mesh *m, const gb_bem_system *sys, const gb_bem_problem *prob,
                                          int group, const double *u_group, const gb_bem_guard *guard,
                                          gb_bem_solution *sol, gb_error *err)
{
    memset(sol, 0, sizeof *sol);
    if (group < 0 || group >= m->n_groups || !u_group)
        return gb_fail(err, GB_EINPUT, "no boundary group %d, or no displacements for it", group);
    return solve(m, sys, prob, group, u_group, guard, sol, err);
}
