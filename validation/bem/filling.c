/* An elastic body filling a cavity of a boundary element host: see filling.h. */
#include "filling.h"

#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* match[q]: the filling element whose midpoint is the host's q-th cavity element's. */
static gb_status match_elements(const gb_bem_mesh *host, int cavity, v_filling *f, gb_error *err)
{
    double tol = 1e-9 * (fabs(host->mid[0]) + fabs(host->mid[1]) + 1);
    int q = 0;
    for (int e = 0; e < host->n; e++) {
        if (host->group[e] != cavity) continue;
        int found = -1;
        for (int g = 0; g < f->mesh.n && found < 0; g++)
            if (fabs(f->mesh.mid[2 * g] - host->mid[2 * e]) < tol && fabs(f->mesh.mid[2 * g + 1] - host->mid[2 * e + 1]) < tol)
                found = g;
        if (found < 0) return gb_fail(err, GB_EINTERNAL, "cavity element %d has no matching filling element", e);
        f->match[q++] = found;
    }
    return GB_OK;
}

gb_status v_filling_setup(const gb_bem_mesh *host, int cavity, const gb_bem_material *mat, v_filling *f,
                          gb_error *err)
{
    memset(f, 0, sizeof *f);
    int loop = -1, nc = 0;
    for (int e = 0; e < host->n; e++)
        if (host->group[e] == cavity) loop = host->loop[e], nc++;
    if (loop < 0) return gb_fail(err, GB_EINPUT, "the cavity group has no element");
    int a = host->loop_start[loop], nv = host->loop_start[loop + 1] - a;
    if (nv != nc) return gb_fail(err, GB_EINPUT, "the cavity group must be one whole loop");
    f->m = 2 * nc;
    double *xy = malloc(2 * (size_t)nv * sizeof *xy);
    int *eg = calloc((size_t)nv, sizeof *eg);
    f->match = malloc((size_t)nc * sizeof *f->match);
    f->K_host = malloc((size_t)f->m * (size_t)f->m * sizeof *f->K_host);
    int *pos = malloc((size_t)nc * sizeof *pos);
    if (!xy || !eg || !f->match || !f->K_host || !pos) {
        free(xy), free(eg), free(pos);
        return gb_fail(err, GB_ENOMEM, "out of memory");
    }
    memcpy(xy, host->p0 + 2 * a, 2 * (size_t)nv * sizeof *xy);
    const char *names[1] = {"wall"};
    gb_bem_problem pr;
    memset(&pr, 0, sizeof pr);
    pr.bc[0].kind = GB_BEM_BC_FREE; /* ignored: the group condensed */
    gb_status st = gb_bem_mesh_from_polygons(1, &nv, xy, eg, 1, names, 0, &f->mesh, err);
    if (!st) st = gb_bem_assemble(&f->mesh, mat, &f->sys, err);
    if (!st) st = gb_bem_condense(&f->mesh, &f->sys, &pr, 0, NULL, &f->K, err);
    if (!st) st = match_elements(host, cavity, f, err);
    if (!st) { /* K_f's DOFs come in its elem[] order: through its inverse */
        int m = f->m;
        for (int q = 0; q < nc; q++) pos[f->K.elem[q]] = q;
        for (int j = 0; j < m; j++)
            for (int i = 0; i < m; i++) {
                size_t di = 2 * (size_t)pos[f->match[i / 2]] + i % 2, dj = 2 * (size_t)pos[f->match[j / 2]] + j % 2;
                f->K_host[i + (size_t)m * j] = f->K.K[di + (size_t)m * dj];
            }
    }
    free(xy), free(eg), free(pos);
    return st;
}

gb_status v_filling_couple(const v_filling *f, const gb_bem_stiffness *Kh, double *u, gb_error *err)
{
    int m = Kh->m;
    if (f && f->m != m) return gb_fail(err, GB_EINTERNAL, "the filling has %d DOFs, the cavity %d", f->m, m);
    for (int k = 1; k < m / 2; k++) /* the filling was matched in the cavity's mesh order */
        if (Kh->elem[k] <= Kh->elem[k - 1]) return gb_fail(err, GB_EINTERNAL, "cavity elements not in mesh order");
    double *A = malloc((size_t)m * (size_t)m * sizeof *A);
    int *ipiv = malloc((size_t)m * sizeof *ipiv);
    if (!A || !ipiv) {
        free(A), free(ipiv);
        return gb_fail(err, GB_ENOMEM, "out of memory");
    }
    for (size_t i = 0; i < (size_t)m * (size_t)m; i++) A[i] = Kh->K[i] + (f ? f->K_host[i] : 0);
    for (int i = 0; i < m; i++) u[i] = -Kh->f0[i];
    int info = LAPACKE_dgesv(LAPACK_COL_MAJOR, m, 1, A, m, ipiv, u, m);
    free(A), free(ipiv);
    return info ? gb_fail(err, GB_ENUMERIC, "singular coupled system (dgesv info %d)", info) : GB_OK;
}

gb_status v_filling_solve(const v_filling *f, const double *u, gb_bem_solution *sol, gb_error *err)
{
    double *uf = malloc((size_t)f->m * sizeof *uf);
    if (!uf) return gb_fail(err, GB_ENOMEM, "out of memory");
    for (int q = 0; q < f->m / 2; q++) /* the filling's group is all of it: its mesh order */
        uf[2 * f->match[q]] = u[2 * q], uf[2 * f->match[q] + 1] = u[2 * q + 1];
    gb_bem_problem pr;
    memset(&pr, 0, sizeof pr);
    pr.bc[0].kind = GB_BEM_BC_FREE; /* ignored: the group's displacement is given */
    memset(sol, 0, sizeof *sol);
    gb_status st = gb_bem_solve_group_displacement(&f->mesh, &f->sys, &pr, 0, uf, NULL, sol, err);
    free(uf);
    return st;
}

void v_filling_free(v_filling *f)
{
    gb_bem_stiffness_free(&f->K);
    gb_bem_system_free(&f->sys);
    gb_bem_mesh_free(&f->mesh);
    free(f->match), free(f->K_host);
    memset(f, 0, sizeof *f);
}
