#include "bem/segment.h"

#include <math.h>

/* M_global = R M_local R^t with R = [t n] (columns): components in the element's (t, n) frame. */
static void to_global(const double t[2], const double n[2], const double ml[4], double mg[4])
{
    double R[2][2] = {{t[0], n[0]}, {t[1], n[1]}};
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++) {
            double v = 0;
            for (int p = 0; p < 2; p++)
                for (int q = 0; q < 2; q++) v += R[a][p] * ml[2 * p + q] * R[b][q];
            mg[2 * a + b] = v;
        }
}

/* With y - x = u t + h n, u in [u1, u2], r^2 = u^2 + h^2 and the subtended angle
 * theta = int h / r^2 du:
 *   int ln r du     = [u ln r - u] + h theta
 *   int u^2/r^2 du  = L - h theta,   int u h / r^2 du = h [ln r],   int h^2/r^2 du = h theta
 *   int h u^2/r^4   = theta/2 - P,   int h^2 u / r^4 = -Q,         int h^3 / r^4 = theta/2 + P
 *   with P = [u h / (2 r^2)], Q = [h^2 / (2 r^2)], and int u / r^2 du = [ln r]. */
void gb_bem_segment_gh(const gb_bem_kconst *k, const double x[2], const double a[2], const double b[2], int self,
                       double g[4], double h[4])
{
    double e[2] = {b[0] - a[0], b[1] - a[1]};
    double L = hypot(e[0], e[1]);
    double t[2] = {e[0] / L, e[1] / L}, n[2] = {t[1], -t[0]};
    double ax[2] = {a[0] - x[0], a[1] - x[1]};
    double u1 = ax[0] * t[0] + ax[1] * t[1], hh = ax[0] * n[0] + ax[1] * n[1];
    double u2 = u1 + L;
    double r1s = u1 * u1 + hh * hh, r2s = u2 * u2 + hh * hh;
    double lr1 = 0.5 * log(r1s), lr2 = 0.5 * log(r2s);
    double th, P, Q, dl;
    if (self) {
        th = P = Q = dl = 0; /* principal values: odd integrands vanish */
        hh = 0;
    } else {
        th = atan2(hh * L, u1 * u2 + hh * hh);
        P = 0.5 * hh * (u2 / r2s - u1 / r1s);
        Q = 0.5 * hh * hh * (1 / r2s - 1 / r1s);
        dl = lr2 - lr1;
    }
    double nu = k->nu, c34 = 3 - 4 * nu, c12 = 1 - 2 * nu;
    double I0 = u2 * lr2 - u1 * lr1 - L + hh * th;
    double gl[4], hl[4];
    gl[0] = k->cu * (-c34 * I0 + (L - hh * th));
    gl[1] = gl[2] = k->cu * hh * (lr2 - lr1);
    gl[3] = k->cu * (-c34 * I0 + hh * th);
    hl[0] = k->cp * (c12 * th + th - 2 * P);
    hl[1] = k->cp * (-2 * Q - c12 * dl);
    hl[2] = k->cp * (-2 * Q + c12 * dl);
    hl[3] = k->cp * (c12 * th + th + 2 * P);
    to_global(t, n, gl, g);
    to_global(t, n, hl, h);
}

static const double GL_X[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                               0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
static const double GL_W[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                               0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

static double seg_dist(const double x[2], const double a[2], const double b[2])
{
    double e[2] = {b[0] - a[0], b[1] - a[1]}, w[2] = {x[0] - a[0], x[1] - a[1]};
    double s = (w[0] * e[0] + w[1] * e[1]) / (e[0] * e[0] + e[1] * e[1]);
    if (s < 0) s = 0;
    if (s > 1) s = 1;
    return hypot(w[0] - s * e[0], w[1] - s * e[1]);
}

typedef void (*kernel_fn)(const gb_bem_kconst *k, const double x[2], const double y[2], const double n[2], double *o1,
                          double *o2);

static void adapt(const gb_bem_kconst *k, kernel_fn f, int m, const double x[2], const double a[2], const double b[2],
                  const double n[2], int depth, double *o1, double *o2)
{
    double L = hypot(b[0] - a[0], b[1] - a[1]);
    if (depth < 48 && L > 0.25 * seg_dist(x, a, b)) {
        double c[2] = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
        adapt(k, f, m, x, a, c, n, depth + 1, o1, o2);
        adapt(k, f, m, x, c, b, n, depth + 1, o1, o2);
        return;
    }
    double v1[6], v2[6];
    for (int q = 0; q < 8; q++) {
        double s = 0.5 * (1 + GL_X[q]), w = 0.5 * L * GL_W[q];
        double y[2] = {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])};
        f(k, x, y, n, v1, v2);
        for (int i = 0; i < m; i++) {
            o1[i] += w * v1[i];
            o2[i] += w * v2[i];
        }
    }
}

static void normal_of(const double a[2], const double b[2], double n[2])
{
    double L = hypot(b[0] - a[0], b[1] - a[1]);
    n[0] = (b[1] - a[1]) / L;
    n[1] = -(b[0] - a[0]) / L;
}

static void ds_fn(const gb_bem_kconst *k, const double x[2], const double y[2], const double n[2], double *o1,
                  double *o2)
{
    gb_bem_kelvin_ds(k, x, y, n, o1, o2);
}

static void gh_fn(const gb_bem_kconst *k, const double x[2], const double y[2], const double n[2], double *o1,
                  double *o2)
{
    gb_bem_kelvin_u(k, x, y, o1);
    gb_bem_kelvin_p(k, x, y, n, o2);
}

void gb_bem_segment_ds(const gb_bem_kconst *k, const double x[2], const double a[2], const double b[2], double d[6],
                       double s[6])
{
    double n[2];
    normal_of(a, b, n);
    for (int i = 0; i < 6; i++) d[i] = s[i] = 0;
    adapt(k, ds_fn, 6, x, a, b, n, 0, d, s);
}

void gb_bem_segment_gh_quadrature(const gb_bem_kconst *k, const double x[2], const double a[2], const double b[2],
                                  double g[4], double h[4])
{
    double n[2];
    normal_of(a, b, n);
    for (int i = 0; i < 4; i++) g[i] = h[i] = 0;
    adapt(k, gh_fn, 4, x, a, b, n, 0, g, h);
}
