/* Closed-form element integrals of u* and p* against adaptive Gauss quadrature of the point
 * kernels, from far, near (down to 1e-6 element lengths) and nearly singular points; the
 * singular diagonal against docs/method.md's closed form; the stress kernels against finite
 * differences of the displacement kernel. */
#include <math.h>

#include "bem/segment.h"
#include "check.h"

static double maxabs4(const double *a, const double *b)
{
    double m = 0;
    for (int i = 0; i < 4; i++) m = fmax(m, fabs(a[i] - b[i]));
    return m;
}

int main(void)
{
    gb_error err = {0};
    gb_bem_kconst k;
    gb_bem_material mat = {2.5, 0.3, GB_BEM_PLANE_STRAIN};
    CHECK(gb_bem_kconst_init(&mat, &k, &err) == GB_OK);
    double a[2] = {0.3, -0.2}, b[2] = {1.1, 0.4}; /* L = 1 */
    double L = hypot(b[0] - a[0], b[1] - a[1]);
    double t[2] = {(b[0] - a[0]) / L, (b[1] - a[1]) / L}, n[2] = {t[1], -t[0]};
    /* points at (along, across) offsets in element lengths, both sides, near the ends too */
    double offs[][2] = {{0.5, 3.0},    {0.5, 0.1}, {0.5, -0.1}, {0.2, 1e-3}, {0.9, -1e-6}, {1.05, 0.01},
                        {-0.01, 0.02}, {2.0, 0.0}, {-1.5, 0.0}, {0.5, 1e-9}, {1.3, -0.4},  {0.0, 0.05}};
    for (size_t p = 0; p < sizeof offs / sizeof offs[0]; p++) {
        double x[2] = {a[0] + offs[p][0] * L * t[0] + offs[p][1] * L * n[0],
                       a[1] + offs[p][0] * L * t[1] + offs[p][1] * L * n[1]};
        double g[4], h[4], gq[4], hq[4];
        gb_bem_segment_gh(&k, x, a, b, 0, g, h);
        gb_bem_segment_gh_quadrature(&k, x, a, b, gq, hq);
        double gs = 0, hs = 0;
        for (int i = 0; i < 4; i++) gs = fmax(gs, fabs(gq[i])), hs = fmax(hs, fabs(hq[i]));
        CHECK(maxabs4(g, gq) <= 1e-12 * fmax(gs, k.cu));
        /* the quadrature itself loses digits as the point nears the element (sums of ~1/r terms) */
        double htol = (fabs(offs[p][1]) >= 1e-3 ? 1e-11 : 4e-9) * fmax(hs, 1e-3);
        CHECK(maxabs4(h, hq) <= htol);
        if (!(maxabs4(h, hq) <= htol) || !(maxabs4(g, gq) <= 1e-12 * fmax(gs, k.cu)))
            fprintf(stderr, "point %zu: |dg| %.3g |dh| %.3g (scale %.3g %.3g)\n", p, maxabs4(g, gq), maxabs4(h, hq), gs,
                    hs);
    }
    /* the singular element: G_ii = L [(3 - 4 nu)(1 - ln(L/2)) I + t t^t] / (8 pi mu (1 - nu)), PV of H = 0 */
    double mid[2] = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])}, g[4], h[4];
    gb_bem_segment_gh(&k, mid, a, b, 1, g, h);
    for (int l = 0; l < 2; l++)
        for (int m = 0; m < 2; m++) {
            double want =
                L * ((3 - 4 * k.nu) * (1 - log(L / 2)) * (l == m) + t[l] * t[m]) / (8 * GB_PI * k.mu * (1 - k.nu));
            CHECK_NEAR(g[2 * l + m], want, 1e-14);
            CHECK_NEAR(h[2 * l + m], 0, 1e-15);
        }
    /* and the singular G against the limit of points approaching the midpoint */
    double xn[2] = {mid[0] + 1e-9 * n[0], mid[1] + 1e-9 * n[1]}, gn[4], hn[4];
    gb_bem_segment_gh(&k, xn, a, b, 0, gn, hn);
    CHECK(maxabs4(g, gn) < 1e-8 * k.cu);

    /* stress kernels: sigma from int D t - int S u equals Hooke's law applied to finite
     * differences of u(x) = int u* t - int p* u, for a constant t and u on the element */
    double x0[2] = {0.6, 0.35}, tt[2] = {0.7, -1.3}, uu[2] = {0.4, 0.25};
    double d[6], s[6], sig[3] = {0, 0, 0};
    gb_bem_segment_ds(&k, x0, a, b, d, s);
    for (int c = 0; c < 3; c++)
        for (int kk = 0; kk < 2; kk++) sig[c] += d[3 * kk + c] * tt[kk] - s[3 * kk + c] * uu[kk];
    double hstep = 1e-4, grad[2][2]; /* grad[i][j] = du_i/dx_j */
    for (int j = 0; j < 2; j++) {
        double up[2], um[2];
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            double x[2] = {x0[0], x0[1]};
            x[j] += sgn * hstep;
            double gg[4], hh[4], u[2];
            gb_bem_segment_gh(&k, x, a, b, 0, gg, hh);
            for (int l = 0; l < 2; l++)
                u[l] = gg[2 * l] * tt[0] + gg[2 * l + 1] * tt[1] - hh[2 * l] * uu[0] - hh[2 * l + 1] * uu[1];
            for (int l = 0; l < 2; l++) (sgn > 0 ? up : um)[l] = u[l];
        }
        for (int i = 0; i < 2; i++) grad[i][j] = (up[i] - um[i]) / (2 * hstep);
    }
    double lam = 2 * k.mu * k.nu / (1 - 2 * k.nu), div = grad[0][0] + grad[1][1];
    double want[3] = {lam * div + 2 * k.mu * grad[0][0], lam * div + 2 * k.mu * grad[1][1],
                      k.mu * (grad[0][1] + grad[1][0])};
    for (int c = 0; c < 3; c++) CHECK_NEAR(sig[c], want[c], 1e-6 * (fabs(want[c]) + 1));
    TEST_END();
}
