/* Several load cases condensed with one factorisation (gb_bem_condense_loads), against one
 * condensation and one solve per case:
 *  - an annulus (outer loop in 4 groups of 6 elements: pressure, traction, component-wise, fixed)
 *    and an off-centre hole in an infinite plane under a remote stress;
 *  - load case 0 the full problem, the others one unit value each; f0 of every case equals
 *    gb_bem_condense's for that case alone (1e-12 of the largest), and so does K (not bitwise: the
 *    two pass different numbers of right-hand sides to dgetrs, and a threaded BLAS splits them
 *    differently, so the last digits may differ on another CPU or thread count);
 *  - outputs with identity weights return whole boundary states: for given cavity displacements,
 *    sum_j u_j column j + column m + i equals gb_bem_solve_group_displacement of case i (every u
 *    and t, 1e-10 of the largest);
 *  - cases that give different halves (a traction where case 0 gives a displacement) are refused. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "gembem/bem.h"

static void ring(double cx, double cy, double r, int n, double *xy)
{
    for (int i = 0; i < n; i++) {
        double a = 2 * 3.14159265358979323846 * (i + 0.25) / n;
        xy[2 * i] = cx + r * cos(a);
        xy[2 * i + 1] = cy + r * sin(a);
    }
}

static double max_abs(const double *v, int n)
{
    double m = 0;
    for (int k = 0; k < n; k++) m = fmax(m, fabs(v[k]));
    return m;
}

/* Checks the cases of probs on mesh m, cavity group `cav`. */
static void check_cases(const gb_bem_mesh *m, const gb_bem_system *sys, const gb_bem_problem *probs, int n, int cav)
{
    gb_error err = {0};
    int nd = 2 * m->n, mm = 0;
    for (int e = 0; e < m->n; e++) mm += 2 * (m->group[e] == cav);
    double *f0 = malloc(sizeof(double) * (size_t)mm * (size_t)n), *wu = calloc((size_t)(2 * nd) * (size_t)nd, sizeof(double)),
           *wt = calloc((size_t)(2 * nd) * (size_t)nd, sizeof(double)),
           *out = malloc(sizeof(double) * (size_t)(2 * nd) * (size_t)(mm + n)), *ucav = malloc(sizeof(double) * (size_t)mm);
    for (int d = 0; d < nd; d++) wu[(size_t)d * (size_t)nd + (size_t)d] = 1, wt[(size_t)(nd + d) * (size_t)nd + (size_t)d] = 1;
    for (int j = 0; j < mm; j++) ucav[j] = 1e-3 * sin(1.0 + 0.7 * j); /* any displacements */
    gb_bem_outputs outs = {2 * nd, wu, wt, out};
    gb_bem_stiffness k, k1;
    CHECK(gb_bem_condense_loads(m, sys, probs, n, cav, NULL, &k, f0, &outs, &err) == GB_OK);
    for (int i = 0; i < n; i++) {
        CHECK(gb_bem_condense(m, sys, &probs[i], cav, NULL, &k1, &err) == GB_OK);
        const double *fi = i ? f0 + (size_t)(i - 1) * (size_t)mm : k.f0;
        double d = 0;
        for (int q = 0; q < mm; q++) d = fmax(d, fabs(fi[q] - k1.f0[q]));
        CHECK(d <= 1e-12 * fmax(max_abs(k1.f0, mm), 1e-300));
        double dk = 0;
        for (size_t q = 0; q < (size_t)mm * (size_t)mm; q++) dk = fmax(dk, fabs(k.K[q] - k1.K[q]));
        CHECK(dk <= 1e-12 * max_abs(k1.K, mm * mm));
        gb_bem_stiffness_free(&k1);
        /* the whole state for ucav */
        gb_bem_solution sol;
        CHECK(gb_bem_solve_group_displacement(m, sys, &probs[i], cav, ucav, NULL, &sol, &err) == GB_OK);
        double du = 0, dt = 0;
        for (int r = 0; r < 2 * nd; r++) {
            double s = out[(size_t)(mm + i) * (size_t)(2 * nd) + (size_t)r];
            for (int j = 0; j < mm; j++) s += ucav[j] * out[(size_t)j * (size_t)(2 * nd) + (size_t)r];
            if (r < nd) du = fmax(du, fabs(s - sol.u[r]));
            else dt = fmax(dt, fabs(s - sol.t[r - nd]));
        }
        double umax = max_abs(sol.u, nd), tmax = max_abs(sol.t, nd);
        printf("  case %d: f0 - alone %.2g (of %.3g), K - alone %.2g; state: u %.2g (of %.3g), t %.2g (of %.3g)\n", i, d,
               max_abs(fi, mm), dk, du, umax, dt, tmax);
        CHECK(du <= 1e-10 * umax);
        CHECK(dt <= 1e-10 * tmax);
        gb_bem_solution_free(&sol);
    }
    gb_bem_stiffness_free(&k);
    free(f0), free(wu), free(wt), free(out), free(ucav);
}

int main(void)
{
    gb_error err = {0};
    gb_bem_material mat = {1000, 0.25, GB_BEM_PLANE_STRAIN};
    enum { NO = 24, NC = 16 };

    /* the annulus: outer groups pressure, traction, components, fixed; the cavity */
    double xy[2 * (NO + NC)];
    int ln[2] = {NO, NC}, g[NO + NC];
    ring(0, 0, 3, NO, xy);
    ring(0.3, -0.2, 1, NC, xy + 2 * NO);
    for (int i = 0; i < NO; i++) g[i] = i / 6;
    for (int i = 0; i < NC; i++) g[NO + i] = 4;
    const char *names[5] = {"p", "t", "c", "f", "cavity"};
    gb_bem_mesh m;
    gb_bem_system sys;
    CHECK(gb_bem_mesh_from_polygons(2, ln, xy, g, 5, names, 0, &m, &err) == GB_OK);
    CHECK(gb_bem_assemble(&m, &mat, &sys, &err) == GB_OK);
    gb_bem_problem pr[6];
    memset(pr, 0, sizeof pr);
    pr[0].bc[0].kind = GB_BEM_BC_PRESSURE, pr[0].bc[0].value[0] = 2;
    pr[0].bc[1].kind = GB_BEM_BC_TRACTION, pr[0].bc[1].value[0] = 0.5, pr[0].bc[1].value[1] = -1;
    pr[0].bc[2].kind = GB_BEM_BC_COMPONENTS, pr[0].bc[2].u_given = 1, pr[0].bc[2].value[0] = 1e-3,
    pr[0].bc[2].value[1] = 0.3;
    pr[0].bc[3].kind = GB_BEM_BC_FIXED;
    pr[0].bc[4].kind = GB_BEM_BC_FREE;
    for (int i = 1; i < 6; i++) {
        pr[i] = pr[0];
        for (int q = 0; q < 5; q++) pr[i].bc[q].value[0] = pr[i].bc[q].value[1] = 0;
    }
    pr[1].bc[0].value[0] = 1, pr[2].bc[1].value[0] = 1, pr[3].bc[1].value[1] = 1, pr[4].bc[2].value[0] = 1,
    pr[5].bc[2].value[1] = 1;
    printf("annulus, 5 loaded groups:\n");
    check_cases(&m, &sys, pr, 6, 4);
    /* different halves: refused */
    pr[1].bc[2].u_given = 2;
    gb_bem_stiffness k;
    double f0[2 * NC * 5];
    CHECK(gb_bem_condense_loads(&m, &sys, pr, 2, 4, NULL, &k, f0, NULL, &err) == GB_EINPUT);
    printf("different halves: %s\n", err.msg);
    gb_bem_system_free(&sys);
    gb_bem_mesh_free(&m);

    /* an off-centre hole in an infinite plane: remote stress (case 0) and its unit components */
    CHECK(gb_bem_mesh_circle(1.5, -0.7, 1, 20, 1, &m, &err) == GB_OK);
    CHECK(gb_bem_assemble(&m, &mat, &sys, &err) == GB_OK);
    memset(pr, 0, sizeof pr);
    pr[0].bc[0].kind = GB_BEM_BC_FREE;
    pr[0].remote_stress[0] = -3, pr[0].remote_stress[1] = 1, pr[0].remote_stress[2] = 0.5;
    for (int i = 1; i < 4; i++) {
        pr[i] = pr[0];
        memset(pr[i].remote_stress, 0, sizeof pr[i].remote_stress);
        pr[i].remote_stress[i - 1] = 1;
    }
    printf("off-centre hole, remote stress:\n");
    check_cases(&m, &sys, pr, 4, 0);
    gb_bem_system_free(&sys);
    gb_bem_mesh_free(&m);
    TEST_END();
}
