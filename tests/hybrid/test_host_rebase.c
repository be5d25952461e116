/* The host that follows its deformed cavity (gb_host_rebase): an annulus host (cavity free, outer
 * wall pushed outwards along its normal by 0.15 in 10 steps, rebased after each) against the body
 * alone solved the same way (gb_bem_solve_updated, 10 increments): the same cavity displacements
 * and moved mesh (1e-9). And a rebase under a force (the cavity displaced as grains would hold it):
 * the force is carried over exactly, u reset, the groups' resultants continued. */
#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "hybrid/host.h"

#define STEPS 10
#define PUSH 0.15

static gb_host_def annulus_host(int count)
{
    gb_host_def d;
    memset(&d, 0, sizeof d);
    d.present = 1;
    snprintf(d.mesh, sizeof d.mesh, "meshes/annulus.geo");
    d.mesh_opts = gb_bem_mesh_opts_default();
    d.mesh_opts.n_group_sizes = 2;
    snprintf(d.mesh_opts.group_sizes[0].group, GB_BEM_NAME_MAX, "cavity");
    snprintf(d.mesh_opts.group_sizes[1].group, GB_BEM_NAME_MAX, "outer");
    d.mesh_opts.group_sizes[0].count = d.mesh_opts.group_sizes[1].count = count;
    d.material = (gb_bem_material){1.0, 0.3, GB_BEM_PLANE_STRAIN};
    snprintf(d.cavity, sizeof d.cavity, "cavity");
    d.n_bcs = 1;
    snprintf(d.bc_group[0], GB_BEM_NAME_MAX, "outer");
    d.bc[0] = (gb_bem_bc){GB_BEM_BC_NORMAL_DISPLACEMENT, {0, 0}, 0};
    return d;
}

/* The free cavity's displacements: K u + f0 = 0. */
static void free_cavity(gb_host *h, gb_host_vars *v)
{
    int m = h->m;
    double *K = malloc(sizeof(double) * (size_t)m * (size_t)m);
    lapack_int *piv = malloc(sizeof(lapack_int) * (size_t)m);
    memcpy(K, h->K.K, sizeof(double) * (size_t)m * (size_t)m);
    for (int i = 0; i < m; i++) v->u[i] = -v->f0[i];
    CHECK(LAPACKE_dgesv(LAPACK_COL_MAJOR, m, 1, K, m, piv, v->u, m) == 0);
    gb_host_update_force(h, v);
    free(K), free(piv);
}

static double largest(const double *x, int n)
{
    double a = 0;
    for (int i = 0; i < n; i++) a = fmax(a, fabs(x[i]));
    return a;
}

int main(void)
{
    gb_error err = {0};
    gb_host_def d = annulus_host(32);
    gb_host *h = NULL;
    gb_host_vars v;
    if (gb_host_create(&d, &h, &err) || gb_host_vars_create(h, &v, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
    int m = h->m;
    double *total = calloc((size_t)m, sizeof(double)), inc[2] = {PUSH / STEPS, 0};
    for (int k = 0; k < STEPS; k++) {
        CHECK(gb_host_add_load(h, &v, "outer", inc, &err) == GB_OK);
        free_cavity(h, &v);
        CHECK(largest(h->force, m) < 1e-12 * largest(v.u, m));
        for (int i = 0; i < m; i++) total[i] += v.u[i];
        CHECK(gb_host_rebase(h, &v, 1, &err) == GB_OK);
    }
    /* the body alone, the same displacement in as many increments */
    gb_bem_mesh alone;
    CHECK(gb_bem_mesh_load(d.mesh, &d.mesh_opts, &alone, &err) == GB_OK);
    gb_bem_problem pr;
    memset(&pr, 0, sizeof pr);
    pr.bc[gb_bem_mesh_group(&alone, "cavity")].kind = GB_BEM_BC_FREE;
    pr.bc[gb_bem_mesh_group(&alone, "outer")] = (gb_bem_bc){GB_BEM_BC_NORMAL_DISPLACEMENT, {PUSH, 0}, 0};
    gb_bem_solution sol;
    CHECK(gb_bem_solve_updated(&alone, &d.material, &pr, STEPS, NULL, NULL, &sol, &err) == GB_OK);
    double du = 0, dx = 0, size = largest(total, m);
    for (int q = 0; q < m / 2; q++) {
        int e = h->K.elem[q];
        for (int c = 0; c < 2; c++) du = fmax(du, fabs(total[2 * q + c] - sol.u[2 * e + c]));
    }
    for (int i = 0; i < 2 * alone.n; i++) dx = fmax(dx, fabs(alone.p0[i] - h->mesh.p0[i]));
    printf("cavity moved %.4f (on a radius of 1): host rebased - body alone %.2e, meshes %.2e apart\n", size, du, dx);
    CHECK(size > 0.1);
    CHECK_NEAR(du, 0, 1e-9 * size);
    CHECK_NEAR(dx, 0, 1e-9 * size);

    /* a rebase under the grains' force: the cavity held displaced */
    for (int i = 0; i < m; i++) v.u[i] = 1e-3 * sin(1.0 + i);
    gb_host_update_force(h, &v);
    double *before = malloc(sizeof(double) * (size_t)m), r0[4], r1[4];
    memcpy(before, h->force, sizeof(double) * (size_t)m);
    gb_host_group_resultant(h, &v, gb_bem_mesh_group(&h->mesh, "outer"), r0, r0 + 2);
    CHECK(gb_host_rebase(h, &v, 1, &err) == GB_OK);
    gb_host_group_resultant(h, &v, gb_bem_mesh_group(&h->mesh, "outer"), r1, r1 + 2);
    CHECK(largest(before, m) > 1e-4);
    CHECK(largest(v.u, m) == 0);
    for (int i = 0; i < m; i++) CHECK(h->force[i] == before[i]);
    for (int c = 0; c < 4; c++) CHECK_NEAR(r1[c], r0[c], 1e-12 * fmax(fabs(r0[0]), fabs(r0[1])) + 1e-15);
    free(before), free(total);
    gb_bem_solution_free(&sol);
    gb_bem_mesh_free(&alone);
    gb_host_vars_free(&v);
    gb_host_free(h);
    return gb_test_failures;
}
