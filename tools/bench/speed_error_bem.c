/* Speed against error of the boundary element module (a benchmark, not a test): for N elements per
 * circle, the seconds of meshing, assembly and solution, and the error against
 *   Lame's annulus 1 < r < 2, inner pressure, outer fixed, plane strain, nu = 0.3: u_r on the cavity;
 *   Kirsch, a hole of radius 1 in an infinite plane under remote s_xx = 1: the hoop stress at
 *   r = 1.5 on the vertical axis, from interior points (analytic 1.9630, docs/method.md section 12).
 * Prints CSV lines: case,N,seconds,error. Run from the repository root. */
#define _POSIX_C_SOURCE 199309L
#include "bench_clock.h"

#include "vcommon.h"


static double lame(int n)
{
    double mu = 1, nu = 0.3, a = 1, b = 2, p = 1e-3;
    gb_error err = {0};
    gb_bem_mesh m;
    gb_bem_system sys;
    gb_bem_material mat = {mu, nu, GB_BEM_PLANE_STRAIN};
    v_mesh("meshes/annulus.geo", 0, "cavity", n, "outer", n, &m);
    if (gb_bem_assemble(&m, &mat, &sys, &err)) v_die(&err);
    gb_bem_problem pr;
    memset(&pr, 0, sizeof pr);
    int cav = gb_bem_mesh_group(&m, "cavity"), out = gb_bem_mesh_group(&m, "outer");
    pr.bc[out].kind = GB_BEM_BC_FIXED;
    pr.bc[cav].kind = GB_BEM_BC_PRESSURE;
    pr.bc[cav].value[0] = p;
    gb_bem_solution s;
    if (gb_bem_solve(&m, &sys, &pr, NULL, &s, &err)) v_die(&err);
    v_lame L = v_lame_solve(mu, nu, 0, 0, a, b, p);
    double worst = 0;
    for (int e = 0; e < m.n; e++) {
        if (m.group[e] != cav) continue;
        const double *x = m.mid + 2 * e;
        double r = hypot(x[0], x[1]), ur = (s.u[2 * e] * x[0] + s.u[2 * e + 1] * x[1]) / r;
        worst = fmax(worst, fabs(ur - v_lame_ur(&L, a)) / fabs(v_lame_ur(&L, a)));
    }
    gb_bem_solution_free(&s);
    gb_bem_system_free(&sys);
    gb_bem_mesh_free(&m);
    return worst;
}

static double kirsch(int n)
{
    gb_error err = {0};
    gb_bem_mesh m;
    gb_bem_system sys;
    gb_bem_material mat = {1, 0.3, GB_BEM_PLANE_STRAIN};
    v_mesh("meshes/hole_infinite.geo", 1, "cavity", n, NULL, 0, &m);
    if (gb_bem_assemble(&m, &mat, &sys, &err)) v_die(&err);
    gb_bem_problem pr;
    memset(&pr, 0, sizeof pr);
    pr.bc[0].kind = GB_BEM_BC_FREE;
    pr.remote_stress[0] = 1;
    gb_bem_solution s;
    if (gb_bem_solve(&m, &sys, &pr, NULL, &s, &err)) v_die(&err);
    double pt[2] = {0, 1.5}, st[3];
    if (gb_bem_interior(&m, &mat, &pr, &s, 1, pt, NULL, st, &err)) v_die(&err);
    double q = 1 / 2.25, exact = 0.5 * (1 + q) + 0.5 * (1 + 3 * q * q); /* cos(2 t) = -1 at t = 90 deg */
    gb_bem_solution_free(&s);
    gb_bem_system_free(&sys);
    gb_bem_mesh_free(&m);
    return fabs(st[0] - exact) / exact; /* on the vertical axis the hoop stress is s_xx */
}

/* One CSV line a mesh size: the fastest of 3 runs of a case, and its error. */
static void rows(const char *name, double (*error_at)(int n))
{
    for (int n = 16; n <= 1024; n *= 2) {
        double best = 1e300, e = 0;
        for (int rep = 0; rep < 3; rep++) {
            double t0 = bench_now();
            e = error_at(n);
            best = fmin(best, bench_now() - t0);
        }
        printf("%s,%d,%.6f,%.6e\n", name, n, best, e);
    }
}

int main(void)
{
    (void)v_failures;
    printf("case,N,seconds,error\n");
    rows("lame", lame);
    rows("kirsch", kirsch);
    return 0;
}
