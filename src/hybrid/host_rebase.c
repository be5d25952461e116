/* The host that follows its deformed cavity (updated Lagrangian, docs/hybrid.md "Large
 * displacements of the host"): its mesh moved by its displacements, K and the loads' unit
 * responses recomputed on it, the cavity's displacements reset with the grains' force carried over. */
#include <stdlib.h>
#include <string.h>

#include "hybrid/host.h"

/* Each group's resultant now (force and mean displacement, 4 per group), from the unit responses. */
static void resultants(const gb_host *h, const gb_host_vars *v, double *r)
{
    for (int g = 0; g < h->mesh.n_groups; g++) gb_host_group_resultant(h, v, g, r + 4 * g, r + 4 * g + 2);
}

/* Before the first rebase: the body at rest kept (the frame of the host's whole state), the sums
 * of the rebases started at zero. */
static gb_status keep_rest(gb_host *h, gb_error *err)
{
    if (h->rebases) return GB_OK;
    size_t n2 = 2 * (size_t)h->mesh.n;
    h->u_acc = calloc(n2, sizeof(double)), h->t_acc = calloc(n2, sizeof(double));
    if (!h->u_acc || !h->t_acc) return gb_fail(err, GB_ENOMEM, "out of memory");
    gb_status st = gb_bem_mesh_copy(&h->mesh, &h->rest, err);
    if (st) return st;
    h->rest_sys = h->sys; /* the assembly at rest becomes the rest's; the moved mesh gets its own */
    memset(&h->sys, 0, sizeof h->sys);
    return GB_OK;
}

/* On the mesh as it now is: G, H and the condensation assembled, the loads' values now (bc,
 * remote) taken as those at creation, f0 = force and u = 0 so that K 0 + f0 = the force before,
 * and the groups' resultants res (4 per group) to go on from. */
static gb_status rebuild(gb_host *h, gb_host_vars *v, const double *force, const double *res, gb_error *err)
{
    int m = h->m, no = 4 * h->mesh.n_groups;
    gb_bem_material mat = h->rest_sys.material;
    gb_bem_system_free(&h->sys);
    gb_status st = gb_bem_assemble(&h->mesh, &mat, &h->sys, err);
    if (!st) {
        /* later loads act through the moved body, as gb_bem_solve_updated's increments */
        h->prob = gb_host_problem(h, v);
        gb_host_free_condensed(h);
        st = gb_host_condense(h, err);
    }
    if (!st && h->K.m != m) st = gb_fail(err, GB_EINTERNAL, "the host's cavity changed its size in a rebase");
    if (st) return st;
    gb_host_symmetrise(h);
    memcpy(h->f0_base, force, sizeof(double) * (size_t)m);
    memcpy(h->K.f0, force, sizeof(double) * (size_t)m);
    if (v->f0) memcpy(v->f0, force, sizeof(double) * (size_t)m), memset(v->u, 0, sizeof(double) * (size_t)m);
    memcpy(h->resultant_unit + (size_t)m * (size_t)no, res, sizeof(double) * (size_t)no);
    return GB_OK;
}

gb_status gb_host_rebase(gb_host *h, gb_host_vars *v, int step, gb_error *err)
{
    int m = h->m, no = 4 * h->mesh.n_groups;
    double *force = malloc(sizeof(double) * (size_t)(m > 0 ? m : 1)), *res = malloc(sizeof(double) * (size_t)no);
    gb_bem_solution sol;
    memset(&sol, 0, sizeof sol);
    gb_status st = (!force || !res) ? gb_fail(err, GB_ENOMEM, "out of memory") : GB_OK;
    if (!st) {
        gb_host_update_force(h, v);
        memcpy(force, h->force, sizeof(double) * (size_t)m);
        resultants(h, v, res);
        /* every element's displacement since the last rebase: the cavity's u, the loads' changes */
        gb_bem_problem change = gb_host_problem_change(h, v);
        st = gb_bem_solve_group_displacement(&h->mesh, &h->sys, &change, h->cavity, v->u, NULL, &sol, err);
    }
    if (!st) st = keep_rest(h, err);
    if (!st) st = gb_bem_mesh_move(&h->mesh, sol.u, err);
    if (!st) {
        for (int k = 0; k < 2 * h->mesh.n; k++) h->u_acc[k] += sol.u[k], h->t_acc[k] += sol.t[k];
        st = rebuild(h, v, force, res, err);
    }
    if (!st) {
        h->rebases++, h->rebase_step = step;
        gb_host_update_force(h, v);
    }
    gb_bem_solution_free(&sol);
    free(force), free(res);
    return st;
}

gb_host_followed gb_host_followed_of(const gb_host *h)
{
    gb_host_followed r;
    memset(&r, 0, sizeof r);
    if (!h->rebases) return r;
    r.rebases = h->rebases, r.rebase_step = h->rebase_step;
    r.p0 = h->mesh.p0, r.p1 = h->mesh.p1;
    for (int g = 0; g < GB_BEM_MAX_GROUPS; g++) r.bc[g][0] = h->prob.bc[g].value[0], r.bc[g][1] = h->prob.bc[g].value[1];
    memcpy(r.remote, h->prob.remote_stress, sizeof r.remote);
    r.f0 = h->f0_base;
    r.resultant = h->resultant_unit + (size_t)h->m * (size_t)(4 * h->mesh.n_groups);
    r.u_acc = h->u_acc, r.t_acc = h->t_acc;
    return r;
}

gb_status gb_host_follow_again(gb_host *h, const gb_host_followed *r, gb_error *err)
{
    if (!r->rebases) return GB_OK;
    if (h->rebases) return gb_fail(err, GB_EINTERNAL, "a followed host put again where a record says");
    gb_status st = keep_rest(h, err);
    if (!st) st = gb_bem_mesh_place(&h->mesh, r->p0, r->p1, err);
    if (st) return st;
    size_t n2 = 2 * (size_t)h->mesh.n;
    memcpy(h->u_acc, r->u_acc, n2 * sizeof(double)), memcpy(h->t_acc, r->t_acc, n2 * sizeof(double));
    gb_host_vars at; /* the loads' values at the last rebase; no displacements to reset */
    memset(&at, 0, sizeof at);
    memcpy(at.bc, r->bc, sizeof at.bc), memcpy(at.remote, r->remote, sizeof at.remote);
    if ((st = rebuild(h, &at, r->f0, r->resultant, err))) return st;
    h->rebases = r->rebases, h->rebase_step = r->rebase_step;
    return GB_OK;
}
