/* Validation: the hybrid paper's host (docs/method.md section 11): a 10 x 10 cm square with a cavity
 * of radius 2.5 cm, mu = 95000 kgf/cm^2, nu = 0.1, plane strain, outer boundary fixed, the
 * cavity's condensed stiffness K. The paper used 20 elements outside and 24 on the cavity; how far
 * is that from the converged host? Modal stiffnesses of the cavity, k = u^t K u / sum L |u|^2, for
 * a rigid translation, a rigid rotation and the breathing mode (the cavity expanding), by mesh,
 * against the Richardson extrapolation of the two finest meshes with the observed order.
 * Sanity bounds for the breathing mode: 2 mu / a = 76000 (no outer boundary) and
 * 3.5 mu / a = 133000 (Lamé, a circle of radius 5 fixed, inscribed in the square).
 * Usage: bem_paper_host [--full] */
#include <lapacke.h>

#include "vcommon.h"

typedef struct {
    double k[3], asym;
    double sym_err[2]; /* |u_sym - u| / |u| under a pressure and under one element's normal force */
} modal;

/* u = K^-1 F against u_sym = ((K + K^t) / 2)^-1 F: what symmetrising the host costs (docs/method.md 10) */
static double sym_error(const gb_bem_stiffness *K, const double *F)
{
    size_t m = (size_t)K->m;
    double *A = malloc(sizeof(double) * m * m), *S = malloc(sizeof(double) * m * m);
    double *u = malloc(sizeof(double) * m), *us = malloc(sizeof(double) * m);
    int *ip = malloc(sizeof(int) * m);
    for (size_t i = 0; i < m; i++) {
        u[i] = us[i] = F[i];
        for (size_t j = 0; j < m; j++) {
            A[j * m + i] = K->K[j * m + i];
            S[j * m + i] = 0.5 * (K->K[j * m + i] + K->K[i * m + j]);
        }
    }
    LAPACKE_dgesv(LAPACK_COL_MAJOR, (int)m, 1, A, (int)m, ip, u, (int)m);
    LAPACKE_dgesv(LAPACK_COL_MAJOR, (int)m, 1, S, (int)m, ip, us, (int)m);
    double num = 0, den = 0;
    for (size_t i = 0; i < m; i++) num += (us[i] - u[i]) * (us[i] - u[i]), den += u[i] * u[i];
    free(A), free(S), free(u), free(us), free(ip);
    return sqrt(num / den);
}

static modal run(int nout, int ncav)
{
    gb_bem_mesh m;
    gb_bem_system sys;
    gb_bem_stiffness K;
    gb_error err = {0};
    gb_bem_material mat = {95000, 0.1, GB_BEM_PLANE_STRAIN};
    v_mesh("meshes/square_cavity.geo", 0, "outer", nout, "cavity", ncav, &m);
    if (gb_bem_assemble(&m, &mat, &sys, &err)) v_die(&err);
    gb_bem_problem p;
    memset(&p, 0, sizeof p);
    p.bc[gb_bem_mesh_group(&m, "outer")].kind = GB_BEM_BC_FIXED;
    p.bc[gb_bem_mesh_group(&m, "cavity")].kind = GB_BEM_BC_FREE;
    if (gb_bem_condense(&m, &sys, &p, gb_bem_mesh_group(&m, "cavity"), NULL, &K, &err)) v_die(&err);
    modal r;
    r.asym = K.asymmetry;
    double *u = malloc(sizeof(double) * (size_t)K.m);
    for (int mode = 0; mode < 3; mode++) {
        double den = 0, num = 0;
        for (int q = 0; q < K.m / 2; q++) {
            int e = K.elem[q];
            const double *x = m.mid + 2 * e, *n = m.normal + 2 * e;
            double uu[2] = {1, 0};
            if (mode == 1) uu[0] = -x[1], uu[1] = x[0];    /* rotation about the centre */
            if (mode == 2) uu[0] = -n[0], uu[1] = -n[1]; /* the cavity expands */
            u[2 * q] = uu[0], u[2 * q + 1] = uu[1];
            den += m.length[e] * (uu[0] * uu[0] + uu[1] * uu[1]);
        }
        for (int i = 0; i < K.m; i++)
            for (int j = 0; j < K.m; j++) num += u[i] * K.K[(size_t)j * (size_t)K.m + (size_t)i] * u[j];
        r.k[mode] = num / den;
    }
    /* a pressure on the cavity (F = -p L n) and a single element pushed along its normal */
    double *F = calloc((size_t)K.m, sizeof(double));
    for (int q = 0; q < K.m / 2; q++)
        for (int c = 0; c < 2; c++) F[2 * q + c] = -m.length[K.elem[q]] * m.normal[2 * K.elem[q] + c];
    r.sym_err[0] = sym_error(&K, F);
    for (int i = 0; i < K.m; i++) F[i] = 0;
    F[0] = -m.normal[2 * K.elem[0]], F[1] = -m.normal[2 * K.elem[0] + 1];
    r.sym_err[1] = sym_error(&K, F);
    free(F);
    free(u);
    gb_bem_stiffness_free(&K);
    gb_bem_system_free(&sys);
    gb_bem_mesh_free(&m);
    return r;
}

int main(int argc, char **argv)
{
    int full = argc > 1 && !strcmp(argv[1], "--full");
    int levels = full ? 6 : 4; /* (20, 24) x 1, 2, 4, 8 (ctest) .. 32 (README) */
    modal r[6];
    for (int l = 0; l < levels; l++) r[l] = run(20 << l, 24 << l);
    const char *names[3] = {"translation", "rotation", "breathing"};
    double ext[3], ord[3];
    for (int k = 0; k < 3; k++) {
        double d1 = r[levels - 2].k[k] - r[levels - 3].k[k], d2 = r[levels - 1].k[k] - r[levels - 2].k[k];
        ord[k] = v_order(fabs(d1), fabs(d2), 2);
        ext[k] = r[levels - 1].k[k] + d2 / (pow(2, ord[k]) - 1);
    }
    printf("### The paper's host: modal stiffness of the cavity (outer fixed), kgf/cm^2 per cm\n\n");
    printf("| elements (outer + cavity) |");
    for (int k = 0; k < 3; k++) printf(" k %s | error |", names[k]);
    printf(" asymmetry of K | u error with (K + K^t)/2: pressure | one element |\n|---:|");
    for (int k = 0; k < 3; k++) printf("---:|---:|");
    printf("---:|---:|---:|\n");
    for (int l = 0; l < levels; l++) {
        printf("| %d + %d |", 20 << l, 24 << l);
        for (int k = 0; k < 3; k++) printf(" %.6g | %.2e |", r[l].k[k], fabs(r[l].k[k] - ext[k]) / ext[k]);
        printf(" %.2e | %.2e | %.2e |\n", r[l].asym, r[l].sym_err[0], r[l].sym_err[1]);
    }
    printf("| extrapolated |");
    for (int k = 0; k < 3; k++) printf(" %.6g | |", ext[k]);
    printf(" | | |\n\nObserved orders (successive differences): translation %.2f, rotation %.2f, breathing %.2f.\n\n",
           ord[0], ord[1], ord[2]);
    for (int k = 0; k < 3; k++) {
        V_CHECK(ord[k] > 0.8 && ord[k] < 2.5, "%s: order %.2f", names[k], ord[k]);
        /* the paper's 20 + 24 elements: within 6 % of the converged modal stiffness (measured: 1-3 %) */
        V_CHECK(fabs(r[0].k[k] - ext[k]) < 0.06 * ext[k], "%s: coarse host off by %.3f", names[k],
                fabs(r[0].k[k] - ext[k]) / ext[k]);
    }
    V_CHECK(ext[2] > 76000 && ext[2] < 133000, "breathing stiffness %.6g outside its bounds", ext[2]);
    /* symmetrising K changes the host's displacements by less than its asymmetry (measured: 1.1e-3
     * and 2.4e-3 at the paper's mesh), and less on finer meshes */
    V_CHECK(r[0].sym_err[0] < 0.05 && r[0].sym_err[1] < 0.05, "symmetrised K: %.2e %.2e", r[0].sym_err[0], r[0].sym_err[1]);
    V_CHECK(r[levels - 1].sym_err[1] < r[0].sym_err[1], "symmetrised K error does not fall with the mesh");
    fflush(stdout);
    if (v_failures) fprintf(stderr, "%d check(s) failed\n", v_failures);
    return v_failures ? 1 : 0;
}
