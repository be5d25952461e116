/* Validation: nearly singular integrals. A thin annulus a = 1 < r < b (outer fixed, inner
 * pressure, Lamé) whose wall is a fraction of an element long, so that every collocation point
 * has the other boundary within 0.1 to 1 element length. The closed-form element integrals stay
 * at the discretisation error of a thick wall; for contrast, the same system with a fixed 4-point
 * Gauss rule for the off-diagonal elements (what docs/method.md warns against).
 * Usage: bem_ligament [--full] */
#include <lapacke.h>

#include "gembem/bem.h"
#include "vcommon.h"

/* u_r error on the cavity of the pressure problem, solving H u = G t with the library's H and G,
 * or with their off-diagonal blocks replaced by a 4-point Gauss rule */
static double solve_err(const gb_bem_mesh *m, const gb_bem_system *s, const v_lame *L, double a, double p)
{
    int nd = s->ndof;
    double *A = malloc(sizeof(double) * (size_t)nd * (size_t)nd), *b = calloc((size_t)nd, sizeof(double));
    int *ip = malloc(sizeof(int) * (size_t)nd);
    for (int d = 0; d < nd; d++) {
        int e = d / 2, cav = m->group[e] == 1;
        double *col = A + (size_t)d * (size_t)nd;
        const double *h = s->H + (size_t)d * (size_t)nd, *g = s->G + (size_t)d * (size_t)nd;
        for (int i = 0; i < nd; i++) col[i] = cav ? h[i] : -g[i]; /* cavity: u unknown; outer fixed: t unknown */
        if (cav) {
            double tv = -p * m->normal[d];
            for (int i = 0; i < nd; i++) b[i] += g[i] * tv;
        }
    }
    LAPACKE_dgesv(LAPACK_COL_MAJOR, nd, 1, A, nd, ip, b, nd);
    double err = 0, want = v_lame_ur(L, a);
    for (int e = 0; e < m->n; e++)
        if (m->group[e] == 1) {
            const double *x = m->mid + 2 * e;
            double r = hypot(x[0], x[1]);
            err = fmax(err, fabs((b[2 * e] * x[0] + b[2 * e + 1] * x[1]) / r - want) / fabs(want));
        }
    free(A), free(b), free(ip);
    return err;
}

static void gauss4(const gb_bem_mesh *m, const gb_bem_material *mat, gb_bem_system *s)
{
    static const double X[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
    static const double W[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
    gb_bem_kconst k;
    gb_error err = {0};
    gb_bem_kconst_init(mat, &k, &err);
    size_t nd = (size_t)s->ndof;
    for (int j = 0; j < m->n; j++)
        for (int i = 0; i < m->n; i++) {
            if (i == j) continue;
            double g[4] = {0}, h[4] = {0};
            for (int q = 0; q < 4; q++) {
                double sq = 0.5 * (1 + X[q]), w = 0.5 * m->length[j] * W[q], y[2], uu[4], pp[4];
                for (int c = 0; c < 2; c++) y[c] = m->p0[2 * j + c] + sq * (m->p1[2 * j + c] - m->p0[2 * j + c]);
                gb_bem_kelvin_u(&k, m->mid + 2 * i, y, uu);
                gb_bem_kelvin_p(&k, m->mid + 2 * i, y, m->normal + 2 * j, pp);
                for (int c = 0; c < 4; c++) g[c] += w * uu[c], h[c] += w * pp[c];
            }
            for (int l = 0; l < 2; l++)
                for (int c = 0; c < 2; c++) {
                    s->G[(size_t)(2 * j + c) * nd + (size_t)(2 * i + l)] = g[2 * l + c];
                    s->H[(size_t)(2 * j + c) * nd + (size_t)(2 * i + l)] = h[2 * l + c];
                }
        }
}

int main(int argc, char **argv)
{
    int full = argc > 1 && !strcmp(argv[1], "--full");
    double mu = 1.0, nu = 0.3, a = 1, p = 1e-3;
    gb_bem_material mat = {mu, nu, GB_BEM_PLANE_STRAIN};
    double walls[3] = {0.02, 0.05, 0.2};
    int ns[4] = {32, 64, 128, 256};
    printf("### Thin walls: annulus 1 < r < b, outer fixed, inner pressure; u_r error on the cavity\n\n");
    printf(
        "| b | N per circle | wall / element length | closed forms | 4-point Gauss | thick annulus b = 2, same N |\n");
    printf("|---:|---:|---:|---:|---:|---:|\n");
    for (int w = 0; w < 3; w++)
        for (int k = 0; k < (full ? 4 : 3); k++) {
            int n = ns[k];
            double b = a + walls[w];
            gb_bem_mesh m, m2;
            gb_bem_system s, s2;
            gb_error err = {0};
            double *xy = malloc(sizeof(double) * 4 * (size_t)n);
            int *g = malloc(sizeof(int) * 2 * (size_t)n), ln[2] = {n, n};
            for (int pass = 0; pass < 2; pass++) {
                double bb = pass ? 2.0 : b;
                for (int i = 0; i < n; i++) {
                    double t = 2 * V_PI * i / n;
                    xy[2 * i] = bb * cos(t), xy[2 * i + 1] = bb * sin(t), g[i] = 0;
                    xy[2 * (n + i)] = a * cos(t), xy[2 * (n + i) + 1] = a * sin(t), g[n + i] = 1;
                }
                if (gb_bem_mesh_from_polygons(2, ln, xy, g, 2, NULL, 0, pass ? &m2 : &m, &err)) v_die(&err);
            }
            if (gb_bem_assemble(&m, &mat, &s, &err) || gb_bem_assemble(&m2, &mat, &s2, &err)) v_die(&err);
            v_lame L = v_lame_solve(mu, nu, 0, 0, a, b, p), L2 = v_lame_solve(mu, nu, 0, 0, a, 2.0, p);
            double e_cf = solve_err(&m, &s, &L, a, p), e_thick = solve_err(&m2, &s2, &L2, a, p);
            gauss4(&m, &mat, &s);
            double e_g4 = solve_err(&m, &s, &L, a, p);
            double ratio = walls[w] * cos(V_PI / n) / m.length[n];
            printf("| %.2f | %d | %.2f | %.3e | %.3e | %.3e |\n", b, n, ratio, e_cf, e_g4, e_thick);
            /* the closed forms keep the thick wall's accuracy (within a factor 3) down to a wall
             * of a tenth of an element */
            V_CHECK(e_cf < 3 * e_thick, "b = %.2f N = %d: %.3e vs thick %.3e", b, n, e_cf, e_thick);
            free(xy), free(g);
            gb_bem_system_free(&s), gb_bem_system_free(&s2);
            gb_bem_mesh_free(&m), gb_bem_mesh_free(&m2);
        }
    printf("\n");
    fflush(stdout);
    if (v_failures) fprintf(stderr, "%d check(s) failed\n", v_failures);
    return v_failures ? 1 : 0;
}
