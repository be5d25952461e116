/* Validation: Lamé's thick cylinder (docs/method.md section 12), annulus 1 < r < 2 meshed by gmsh
 * (meshes/annulus.geo), plane strain and plane stress, outer boundary fixed or traction-free.
 *   pressure problem:     cavity pressure p, error of u_r on the cavity;
 *   displacement problem: cavity displaced by the exact u_r(a), error of s_rr on the cavity
 *                         (the traction the BEM solves for; exact -p).
 * Errors are maxima over the cavity's elements, relative to |u_r(a)| and p, against the exact
 * values at r = a. Usage: bem_lame [--full] (--full: up to 1024 elements per circle, README). */
#include "vcommon.h"

typedef struct {
    double eu, es, ett;
    double rcond;
} result;

static result run(int n, int plane_stress, int outer_free, double nu)
{
    double mu = 1.0, a = 1, b = 2, p = 1e-3;
    gb_bem_mesh m;
    gb_bem_system sys;
    gb_error err = {0};
    gb_bem_material mat = {mu, nu, plane_stress ? GB_BEM_PLANE_STRESS : GB_BEM_PLANE_STRAIN};
    v_mesh("meshes/annulus.geo", 0, "cavity", n, "outer", n, &m);
    if (gb_bem_assemble(&m, &mat, &sys, &err)) v_die(&err);
    v_lame L = v_lame_solve(mu, nu, plane_stress, outer_free, a, b, p);
    int cav = gb_bem_mesh_group(&m, "cavity"), out = gb_bem_mesh_group(&m, "outer");
    gb_bem_problem pr;
    memset(&pr, 0, sizeof pr);
    pr.bc[out].kind = outer_free ? GB_BEM_BC_FREE : GB_BEM_BC_FIXED;
    result r = {0, 0, 0, 0};
    for (int problem = 0; problem < 2; problem++) {
        if (problem == 0) {
            pr.bc[cav].kind = GB_BEM_BC_PRESSURE;
            pr.bc[cav].value[0] = p;
        } else { /* u = u_r e_r = -u_r n on the cavity */
            pr.bc[cav].kind = GB_BEM_BC_NORMAL_DISPLACEMENT;
            pr.bc[cav].value[0] = -v_lame_ur(&L, a);
        }
        gb_bem_solution s;
        if (gb_bem_solve(&m, &sys, &pr, NULL, &s, &err)) v_die(&err);
        double *bs = malloc(sizeof(double) * 3 * (size_t)m.n);
        gb_bem_boundary_stress(&m, &mat, &s, bs, &err);
        for (int e = 0; e < m.n; e++) {
            if (m.group[e] != cav) continue;
            const double *x = m.mid + 2 * e, *n = m.normal + 2 * e;
            double rr = hypot(x[0], x[1]), er[2] = {x[0] / rr, x[1] / rr}, et[2] = {-er[1], er[0]};
            if (problem == 0) {
                double ur = s.u[2 * e] * er[0] + s.u[2 * e + 1] * er[1];
                r.eu = fmax(r.eu, fabs(ur - v_lame_ur(&L, a)) / fabs(v_lame_ur(&L, a)));
                const double *q = bs + 3 * e; /* hoop stress from the boundary displacement */
                double stt = q[0] * et[0] * et[0] + 2 * q[2] * et[0] * et[1] + q[1] * et[1] * et[1];
                r.ett = fmax(r.ett, fabs(stt - v_lame_stt(&L, a)) / p);
            } else {
                double tn = s.t[2 * e] * n[0] + s.t[2 * e + 1] * n[1];
                r.es = fmax(r.es, fabs(tn - v_lame_srr(&L, a)) / p);
            }
        }
        if (problem == 1) r.rcond = s.rcond;
        free(bs);
        gb_bem_solution_free(&s);
    }
    gb_bem_system_free(&sys);
    gb_bem_mesh_free(&m);
    return r;
}

int main(int argc, char **argv)
{
    int full = argc > 1 && !strcmp(argv[1], "--full");
    int levels = full ? 7 : 5; /* 16 .. 256 (ctest) or 16 .. 1024 (README) elements per circle */
    double nus[2] = {0.3, 0.499};
    printf("### Lamé annulus (a = 1, b = 2), elements per circle N; errors max over the cavity\n\n");
    for (int inu = 0; inu < 2; inu++) {
        for (int ps = 0; ps < 2; ps++) {
            if (inu == 1 && ps == 1) continue; /* nu = 0.499 matters in plane strain */
            for (int of = 0; of < 2; of++) {
                double nu = nus[inu];
                printf("**plane %s, nu = %g, outer %s**\n\n", ps ? "stress" : "strain", nu,
                       of ? "traction-free" : "fixed");
                printf("| N | err u_r (pressure) | order | err s_rr (displacement) | order | err s_tt (pressure, "
                       "boundary stress) | order | rcond |\n");
                printf("|---:|---:|---:|---:|---:|---:|---:|---:|\n");
                result prev = {0, 0, 0, 0};
                for (int l = 0; l < levels; l++) {
                    int n = 16 << l;
                    result r = run(n, ps, of, nu);
                    if (l == 0)
                        printf("| %d | %.3e | | %.3e | | %.3e | | %.2e |\n", n, r.eu, r.es, r.ett, r.rcond);
                    else {
                        double ou = v_order(prev.eu, r.eu, 2), os = v_order(prev.es, r.es, 2),
                               ot = v_order(prev.ett, r.ett, 2);
                        printf("| %d | %.3e | %.2f | %.3e | %.2f | %.3e | %.2f | %.2e |\n", n, r.eu, ou, r.es, os,
                               r.ett, ot, r.rcond);
                        /* constant elements converge at first order: asserted for the last refinements
                         * (nu = 0.499 with the outer boundary fixed: errors far smaller, no clean order) */
                        if (l >= 3 && !(inu && !of)) {
                            V_CHECK(ou > 0.85 && ou < 1.3, "order of u_r %.3f at N = %d", ou, n);
                            V_CHECK(os > 0.85 && os < 1.3, "order of s_rr %.3f at N = %d", os, n);
                        }
                        /* error constants of the study, N err < C (README.md): at most 0.42 (fixed),
                         * 0.85 (free); nu = 0.499 with the outer boundary fixed: 0.11 */
                        double C = inu ? (of ? 1.0 : 0.15) : (of ? 1.0 : 0.5);
                        V_CHECK(r.eu * n < C, "u_r error %.3e at N = %d", r.eu, n);
                        V_CHECK(r.es * n < C, "s_rr error %.3e at N = %d", r.es, n);
                    }
                    prev = r;
                }
                printf("\n");
            }
        }
    }
    fflush(stdout);
    if (v_failures) fprintf(stderr, "%d check(s) failed\n", v_failures);
    return v_failures ? 1 : 0;
}
