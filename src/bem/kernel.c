#include "bem/kernel.h"

#include <math.h>

gb_status gb_bem_kconst_init(const gb_bem_material *mat, gb_bem_kconst *k, gb_error *err)
{
    double mu = mat->shear_modulus, nu = mat->poisson;
    if (!(mu > 0) || !isfinite(mu)) return gb_fail(err, GB_EINPUT, "shear modulus must be positive, found %g", mu);
    if (!(nu > -1 && nu < 0.5)) return gb_fail(err, GB_EINPUT, "Poisson ratio must lie in (-1, 0.5), found %g", nu);
    if (mat->plane != GB_BEM_PLANE_STRAIN && mat->plane != GB_BEM_PLANE_STRESS)
        return gb_fail(err, GB_EINPUT, "plane must be strain or stress");
    if (mat->plane == GB_BEM_PLANE_STRESS) nu = nu / (1 + nu);
    k->mu = mu;
    k->nu = nu;
    k->cu = 1 / (8 * GB_PI * mu * (1 - nu));
    k->cp = -1 / (4 * GB_PI * (1 - nu));
    k->cd = 1 / (4 * GB_PI * (1 - nu));
    k->cs = mu / (2 * GB_PI * (1 - nu));
    return GB_OK;
}

void gb_bem_kelvin_u(const gb_bem_kconst *k, const double x[2], const double y[2], double u[4])
{
    double d[2] = {y[0] - x[0], y[1] - x[1]};
    double r = hypot(d[0], d[1]), g[2] = {d[0] / r, d[1] / r};
    double lg = (3 - 4 * k->nu) * log(1 / r);
    for (int l = 0; l < 2; l++)
        for (int m = 0; m < 2; m++) u[2 * l + m] = k->cu * ((l == m ? lg : 0) + g[l] * g[m]);
}

void gb_bem_kelvin_p(const gb_bem_kconst *k, const double x[2], const double y[2], const double n[2], double p[4])
{
    double d[2] = {y[0] - x[0], y[1] - x[1]};
    double r = hypot(d[0], d[1]), g[2] = {d[0] / r, d[1] / r};
    double drdn = g[0] * n[0] + g[1] * n[1], a = 1 - 2 * k->nu;
    for (int l = 0; l < 2; l++)
        for (int m = 0; m < 2; m++)
            p[2 * l + m] = k->cp / r * (drdn * ((l == m ? a : 0) + 2 * g[l] * g[m]) - a * (g[l] * n[m] - g[m] * n[l]));
}

void gb_bem_kelvin_ds(const gb_bem_kconst *k, const double x[2], const double y[2], const double n[2], double d[6],
                      double s[6])
{
    static const int I[3] = {0, 1, 0}, J[3] = {0, 1, 1};
    double v[2] = {y[0] - x[0], y[1] - x[1]};
    double r = hypot(v[0], v[1]), g[2] = {v[0] / r, v[1] / r};
    double drdn = g[0] * n[0] + g[1] * n[1], nu = k->nu, a = 1 - 2 * nu;
    for (int kk = 0; kk < 2; kk++) {
        for (int c = 0; c < 3; c++) {
            int i = I[c], j = J[c];
            double dki = kk == i, dkj = kk == j, dij = i == j;
            d[3 * kk + c] = k->cd / r * (a * (g[j] * dki + g[i] * dkj - g[kk] * dij) + 2 * g[i] * g[j] * g[kk]);
            s[3 * kk + c] = k->cs / (r * r) *
                            (2 * drdn * (a * dij * g[kk] + nu * (g[j] * dki + g[i] * dkj) - 4 * g[i] * g[j] * g[kk]) +
                             2 * nu * (n[i] * g[j] * g[kk] + n[j] * g[i] * g[kk]) +
                             a * (2 * n[kk] * g[i] * g[j] + n[j] * dki + n[i] * dkj) - (1 - 4 * nu) * n[kk] * dij);
        }
    }
}
