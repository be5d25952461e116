#include "hybrid/host.h"

#include <cblas.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/blas.h"

void gb_host_free_condensed(gb_host *h)
{
    gb_bem_stiffness_free(&h->K);
    free(h->loads), free(h->load0), free(h->f0_base), free(h->f0_unit), free(h->resultant_unit);
    h->loads = NULL, h->load0 = h->f0_base = h->f0_unit = h->resultant_unit = NULL;
}

void gb_host_symmetrise(gb_host *h)
{
    size_t m = (size_t)h->m;
    for (size_t c = 0; c < m; c++)
        for (size_t r = 0; r < m; r++) h->Ksym[r + c * m] = 0.5 * (h->K.K[r + c * m] + h->K.K[c + r * m]);
}

void gb_host_free(gb_host *h)
{
    if (!h) return;
    gb_host_free_condensed(h);
    gb_bem_system_free(&h->sys);
    gb_bem_mesh_free(&h->mesh);
    gb_bem_system_free(&h->rest_sys);
    gb_bem_mesh_free(&h->rest);
    free(h->u_acc), free(h->t_acc);
    free(h->Ksym);
    free(h->force);
    free(h);
}

gb_status gb_host_create(const gb_host_def *def, gb_host **out, gb_error *err)
{
    *out = NULL;
    gb_host *h = calloc(1, sizeof *h);
    if (!h) return gb_fail(err, GB_ENOMEM, "out of memory");
    gb_status st = gb_bem_mesh_load(def->mesh, &def->mesh_opts, &h->mesh, err);
    if (st) {
        gb_host_free(h);
        return st;
    }
    h->cavity = gb_bem_mesh_group(&h->mesh, def->cavity);
    if (h->cavity < 0) {
        gb_host_free(h);
        return gb_fail(err, GB_EINPUT, "%s: host.cavity: the mesh has no physical group '%s'", def->mesh, def->cavity);
    }
    /* Every group but the cavity needs a condition from the scene. */
    for (int g = 0; g < h->mesh.n_groups; g++) {
        if (g == h->cavity) continue;
        int found = -1;
        for (int k = 0; k < def->n_bcs; k++)
            if (!strcmp(def->bc_group[k], h->mesh.group_name[g])) found = k;
        if (found < 0) {
            gb_fail(err, GB_EINPUT, "%s: host.boundary: no condition for the group '%s'", def->mesh,
                    h->mesh.group_name[g]);
            gb_host_free(h);
            return GB_EINPUT;
        }
        h->prob.bc[g] = def->bc[found];
    }
    for (int k = 0; k < def->n_bcs; k++)
        if (gb_bem_mesh_group(&h->mesh, def->bc_group[k]) < 0 || !strcmp(def->bc_group[k], def->cavity)) {
            gb_host_free(h);
            return gb_fail(err, GB_EINPUT, "%s: host.boundary.%s: expected a group of the mesh other than the cavity",
                           def->mesh, def->bc_group[k]);
        }
    h->prob.bc[h->cavity].kind = GB_BEM_BC_FREE; /* replaced by the condensation */
    memcpy(h->prob.remote_stress, def->remote_stress, sizeof h->prob.remote_stress);
    if (!h->mesh.unbounded && (def->remote_stress[0] != 0 || def->remote_stress[1] != 0 || def->remote_stress[2] != 0)) {
        gb_host_free(h);
        return gb_fail(err, GB_EINPUT, "%s: host.remote_stress: applies to an unbounded host only", def->mesh);
    }
    if ((st = gb_bem_assemble(&h->mesh, &def->material, &h->sys, err)) ||
        (st = gb_host_condense(h, err))) {
        gb_host_free(h);
        return st;
    }
    int m = h->m = h->K.m;
    h->Ksym = malloc((size_t)m * m * sizeof(double));
    h->force = calloc((size_t)m, sizeof(double));
    if (!h->Ksym || !h->force) {
        gb_host_free(h);
        return gb_fail(err, GB_ENOMEM, "out of memory for the host stiffness");
    }
    gb_host_symmetrise(h);
    memcpy(h->force, h->K.f0, (size_t)m * sizeof(double)); /* u = 0 */
    *out = h;
    return GB_OK;
}

gb_status gb_host_vars_create(const gb_host *h, gb_host_vars *v, gb_error *err)
{
    memset(v, 0, sizeof *v);
    size_t m = (size_t)(h->m > 0 ? h->m : 1);
    v->u = calloc(m, sizeof(double));
    v->f0 = malloc(m * sizeof(double));
    if (!v->u || !v->f0) {
        gb_host_vars_free(v);
        return gb_fail(err, GB_ENOMEM, "out of memory for the host's displacements");
    }
    memcpy(v->f0, h->K.f0, (size_t)h->m * sizeof(double));
    for (int g = 0; g < GB_BEM_MAX_GROUPS; g++)
        v->bc[g][0] = h->prob.bc[g].value[0], v->bc[g][1] = h->prob.bc[g].value[1];
    memcpy(v->remote, h->prob.remote_stress, sizeof v->remote);
    return GB_OK;
}

void gb_host_vars_free(gb_host_vars *v)
{
    free(v->u), free(v->f0);
    memset(v, 0, sizeof *v);
}

void gb_host_update_force(gb_host *h, const gb_host_vars *v)
{
    memcpy(h->force, v->f0, (size_t)h->m * sizeof(double));
    int threads = gb_blas_single(); /* OpenBLAS splits a square dgemv by columns on threads: core/blas.h */
    cblas_dgemv(CblasColMajor, CblasNoTrans, h->m, h->m, 1.0, h->K.K, h->m, v->u, 1, 1.0, h->force, 1);
    gb_blas_restore(threads);
}

gb_bem_problem gb_host_problem(const gb_host *h, const gb_host_vars *v)
{
    gb_bem_problem p = h->prob;
    for (int g = 0; g < GB_BEM_MAX_GROUPS; g++) p.bc[g].value[0] = v->bc[g][0], p.bc[g].value[1] = v->bc[g][1];
    memcpy(p.remote_stress, v->remote, sizeof p.remote_stress);
    return p;
}

gb_status gb_host_solve(const gb_host *h, const gb_host_vars *v, gb_bem_solution *sol, gb_error *err)
{
    memset(sol, 0, sizeof *sol);
    gb_bem_problem p = gb_host_problem_change(h, v);
    gb_status st = gb_bem_solve_group_displacement(&h->mesh, &h->sys, &p, h->cavity, v->u, NULL, sol, err);
    for (int k = 0; !st && h->rebases && k < 2 * h->mesh.n; k++) sol->u[k] += h->u_acc[k], sol->t[k] += h->t_acc[k];
    return st;
}

void gb_host_cavity_displacement(const gb_host *h, const gb_host_vars *v, int k, double u[2])
{
    int e = h->K.elem[k];
    u[0] = v->u[2 * k] + (h->rebases ? h->u_acc[2 * e] : 0);
    u[1] = v->u[2 * k + 1] + (h->rebases ? h->u_acc[2 * e + 1] : 0);
}

const gb_bem_mesh *gb_host_rest_mesh(const gb_host *h) { return h->rebases ? &h->rest : &h->mesh; }
const gb_bem_system *gb_host_rest_system(const gb_host *h) { return h->rebases ? &h->rest_sys : &h->sys; }

void gb_host_group_sum(const gb_host *h, const gb_bem_solution *sol, int g, double force[2], double disp[2])
{
    double len = 0;
    const gb_bem_mesh *mesh = gb_host_rest_mesh(h);
    force[0] = force[1] = disp[0] = disp[1] = 0;
    for (int e = 0; e < mesh->n; e++)
        if (mesh->group[e] == g) {
            double L = mesh->length[e];
            force[0] += sol->t[2 * e] * L, force[1] += sol->t[2 * e + 1] * L;
            disp[0] += sol->u[2 * e] * L, disp[1] += sol->u[2 * e + 1] * L;
            len += L;
        }
    if (len > 0) disp[0] /= len, disp[1] /= len;
}

gb_status gb_host_group_force(const gb_host *h, const gb_host_vars *v, const char *group, double force[2],
                              double disp[2], gb_error *err)
{
    int g = gb_bem_mesh_group(&h->mesh, group);
    if (g < 0) return gb_fail(err, GB_EINPUT, "host: no group '%s'", group);
    gb_bem_solution sol;
    gb_status st = gb_host_solve(h, v, &sol, err);
    if (!st) gb_host_group_sum(h, &sol, g, force, disp);
    gb_bem_solution_free(&sol);
    return st;
}
