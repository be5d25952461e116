/* The body that follows its deformed boundary: an updated-Lagrangian sequence of linear solves,
 * each assembled on the mesh the previous ones moved (gembem/bem.h, gb_bem_solve_updated). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gembem/bem.h"

/* One increment's problem: every value of prob divided by the number of increments. */
static gb_bem_problem part_of(const gb_bem_problem *prob, int increments)
{
    gb_bem_problem p = *prob;
    for (int g = 0; g < GB_BEM_MAX_GROUPS; g++)
        for (int c = 0; c < 2; c++) p.bc[g].value[c] /= increments;
    for (int c = 0; c < 3; c++) p.remote_stress[c] /= increments;
    return p;
}

static void add(double *sum, const double *part, size_t n)
{
    for (size_t i = 0; i < n; i++) sum[i] += part[i];
}

/* The followed points' part of one increment, before anything moves: displacement into du (2 per
 * point, always: the points move by it) and stress into ds (3 per point, when asked). */
static gb_status follow_part(const gb_bem_mesh *m, const gb_bem_material *mat, const gb_bem_problem *part,
                             const gb_bem_solution *dsol, gb_bem_follow *f, double *du, double *ds, gb_error *err)
{
    for (int p = 0; p < f->npts; p++)
        if (!gb_bem_mesh_inside(m, f->xy[2 * p], f->xy[2 * p + 1]))
            return gb_fail(err, GB_EINPUT, "followed point %d, now at (%.6g, %.6g), left the body", p, f->xy[2 * p],
                           f->xy[2 * p + 1]);
    gb_status st = gb_bem_interior(m, mat, part, dsol, f->npts, f->xy, du, f->stress ? ds : NULL, err);
    if (st) return st;
    if (f->u) add(f->u, du, 2 * (size_t)f->npts);
    if (f->stress) add(f->stress, ds, 3 * (size_t)f->npts);
    add(f->xy, du, 2 * (size_t)f->npts);
    return GB_OK;
}

/* Increment k: assembled and solved on the current mesh, summed into sol and f, then the mesh moved. */
static gb_status increment(gb_bem_mesh *m, const gb_bem_material *mat, const gb_bem_problem *part,
                           const gb_bem_guard *guard, gb_bem_follow *f, int k, double *scratch, gb_bem_solution *sol,
                           gb_error *err)
{
    gb_bem_system sys;
    gb_bem_solution dsol;
    memset(&dsol, 0, sizeof dsol);
    size_t nd = 2 * (size_t)m->n;
    gb_status st = gb_bem_assemble(m, mat, &sys, err);
    if (st) return st;
    st = gb_bem_solve(m, &sys, part, guard, &dsol, err);
    gb_bem_system_free(&sys);
    if (!st && f && f->boundary_stress) {
        st = gb_bem_boundary_stress(m, mat, &dsol, scratch, err);
        if (!st) add(f->boundary_stress, scratch, 3 * (size_t)m->n);
    }
    if (!st && f && f->npts > 0) st = follow_part(m, mat, part, &dsol, f, scratch, scratch + 2 * f->npts, err);
    if (!st) {
        add(sol->u, dsol.u, nd);
        add(sol->t, dsol.t, nd);
        if (k == 0 || dsol.rcond < sol->rcond) {
            sol->rcond = dsol.rcond;
            sol->rcond_first = dsol.rcond_first;
            sol->scale = dsol.scale;
        }
        sol->rigid_constrained = dsol.rigid_constrained;
        st = gb_bem_mesh_move(m, dsol.u, err);
    }
    gb_bem_solution_free(&dsol);
    return st;
}

gb_status gb_bem_solve_updated(gb_bem_mesh *mesh, const gb_bem_material *mat, const gb_bem_problem *prob,
                               int increments, const gb_bem_guard *guard, gb_bem_follow *follow, gb_bem_solution *sol,
                               gb_error *err)
{
    memset(sol, 0, sizeof *sol);
    if (increments < 1) return gb_fail(err, GB_EINPUT, "%d increments: expected at least 1", increments);
    int npts = follow ? follow->npts : 0;
    if (npts < 0 || (npts > 0 && !follow->xy)) return gb_fail(err, GB_EINPUT, "followed points without places");
    size_t nd = 2 * (size_t)mesh->n, nscratch = 3 * (size_t)(mesh->n > npts ? mesh->n : npts) + 2 * (size_t)npts;
    sol->ndof = (int)nd;
    sol->u = calloc(nd, sizeof(double));
    sol->t = calloc(nd, sizeof(double));
    double *scratch = malloc(sizeof(double) * nscratch);
    gb_status st = (!sol->u || !sol->t || !scratch) ? gb_fail(err, GB_ENOMEM, "out of memory") : GB_OK;
    if (!st && follow) {
        if (follow->u) memset(follow->u, 0, sizeof(double) * 2 * (size_t)npts);
        if (follow->stress) memset(follow->stress, 0, sizeof(double) * 3 * (size_t)npts);
        if (follow->boundary_stress) memset(follow->boundary_stress, 0, sizeof(double) * 3 * (size_t)mesh->n);
    }
    gb_bem_problem part = part_of(prob, increments);
    for (int k = 0; k < increments && !st; k++) {
        st = increment(mesh, mat, &part, guard, follow, k, scratch, sol, err);
        if (st && err && increments > 1) { /* which increment, for a mesh that folded or a point that left */
            char msg[GB_ERROR_MSG_MAX];
            snprintf(msg, sizeof msg, "%s", err->msg);
            gb_fail(err, st, "increment %d of %d: %s", k + 1, increments, msg);
        }
    }
    free(scratch);
    if (st) gb_bem_solution_free(sol);
    return st;
}
