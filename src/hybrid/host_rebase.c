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

gb_status gb_host_rebase(gb_host *h, gb_host_vars *v, gb_error *err)
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
    if (!st) st = gb_bem_mesh_move(&h->mesh, sol.u, err);
    gb_bem_material mat = h->sys.material;
    if (!st) {
        gb_bem_system_free(&h->sys);
        st = gb_bem_assemble(&h->mesh, &mat, &h->sys, err);
    }
    if (!st) {
        /* the values now are the new values at creation: later loads act through the moved body */
        h->prob = gb_host_problem(h, v);
        gb_host_free_condensed(h);
        st = gb_host_condense(h, err);
    }
    if (!st && h->K.m != m) st = gb_fail(err, GB_EINTERNAL, "the host's cavity changed its size in a rebase");
    if (!st) {
        gb_host_symmetrise(h);
        /* K 0 + f0 = the force before: the grains' equilibrium carried over exactly */
        memcpy(h->f0_base, force, sizeof(double) * (size_t)m);
        memcpy(h->K.f0, force, sizeof(double) * (size_t)m);
        memcpy(v->f0, force, sizeof(double) * (size_t)m);
        memset(v->u, 0, sizeof(double) * (size_t)m);
        /* the groups' resultants go on from where they were */
        memcpy(h->resultant_unit + (size_t)m * (size_t)no, res, sizeof(double) * (size_t)no);
        gb_host_update_force(h, v);
    }
    gb_bem_solution_free(&sol);
    free(force), free(res);
    return st;
}
