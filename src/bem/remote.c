#include "bem/remote.h"

int gb_bem_remote_active(const gb_bem_mesh *mesh, const gb_bem_problem *prob)
{
    const double *s = prob->remote_stress;
    return mesh->unbounded && (s[0] != 0 || s[1] != 0 || s[2] != 0);
}

void gb_bem_remote_u(const gb_bem_material *mat, const gb_bem_problem *prob, const double x[2], double u[2])
{
    double nu = mat->poisson, mu = mat->shear_modulus;
    if (mat->plane == GB_BEM_PLANE_STRESS) nu = nu / (1 + nu);
    const double *s = prob->remote_stress;
    double exx = ((1 - nu) * s[0] - nu * s[1]) / (2 * mu), eyy = ((1 - nu) * s[1] - nu * s[0]) / (2 * mu),
           exy = s[2] / (2 * mu);
    u[0] = exx * x[0] + exy * x[1];
    u[1] = exy * x[0] + eyy * x[1];
}

void gb_bem_remote_t(const gb_bem_problem *prob, const double n[2], double t[2])
{
    const double *s = prob->remote_stress;
    t[0] = s[0] * n[0] + s[2] * n[1];
    t[1] = s[2] * n[0] + s[1] * n[1];
}
