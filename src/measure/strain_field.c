/* Strain of each triangle of grain centres, its mean per grain, and the localisation index. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gembem/strain_field.h"

/* Strain, shear and rotation from H (the displacement gradient; see gembem/strain_field.h). */
static void from_gradient(gb_strain *s)
{
    const double *H = s->H;
    /* E = (H + H^t + H^t H)/2, Green-Lagrange; reported compression positive. */
    double Exx = H[0] + 0.5 * (H[0] * H[0] + H[2] * H[2]);
    double Eyy = H[3] + 0.5 * (H[1] * H[1] + H[3] * H[3]);
    double Exy = 0.5 * (H[1] + H[2] + H[0] * H[1] + H[2] * H[3]);
    s->exx = -Exx, s->eyy = -Eyy, s->exy = -Exy;
    s->ev = s->exx + s->eyy;
    s->gamma = 2 * sqrt(0.25 * (s->exx - s->eyy) * (s->exx - s->eyy) + s->exy * s->exy);
    /* In 2D the rotation R of F = I + H = R U has angle atan2(F10 - F01, F00 + F11). */
    s->rotation = atan2(H[2] - H[1], 2 + H[0] + H[3]);
}

void gb_strain_triangles(const gb_triangulation *t, const double *x0, const double *x1, gb_strain *out)
{
    for (int k = 0; k < t->n; k++) {
        const int *v = &t->v[3 * k];
        gb_strain *s = &out[k];
        memset(s, 0, sizeof *s);
        /* Edges from vertex 0 in the reference (columns of D) and their displacement change (dU). */
        double D[4], dU[4];
        for (int c = 0; c < 2; c++) {
            int b = v[c + 1];
            D[c] = x0[2 * b] - x0[2 * v[0]], D[2 + c] = x0[2 * b + 1] - x0[2 * v[0] + 1];
            dU[c] = (x1[2 * b] - x0[2 * b]) - (x1[2 * v[0]] - x0[2 * v[0]]);
            dU[2 + c] = (x1[2 * b + 1] - x0[2 * b + 1]) - (x1[2 * v[0] + 1] - x0[2 * v[0] + 1]);
        }
        double det = D[0] * D[3] - D[1] * D[2];
        s->area = 0.5 * fabs(det);
        if (det == 0) continue; /* gb_triangulate keeps none such */
        /* H = dU D^-1 */
        double inv[4] = {D[3] / det, -D[1] / det, -D[2] / det, D[0] / det};
        s->H[0] = dU[0] * inv[0] + dU[1] * inv[2], s->H[1] = dU[0] * inv[1] + dU[1] * inv[3];
        s->H[2] = dU[2] * inv[0] + dU[3] * inv[2], s->H[3] = dU[2] * inv[1] + dU[3] * inv[3];
        from_gradient(s);
    }
}

/* Strain, shear and rotation of a mean: from sums of area x (H, strain). */
static void finish_mean(gb_strain *s)
{
    if (!(s->area > 0)) return;
    for (int q = 0; q < 4; q++) s->H[q] /= s->area;
    s->exx /= s->area, s->eyy /= s->area, s->exy /= s->area;
    s->ev = s->exx + s->eyy;
    s->gamma = 2 * sqrt(0.25 * (s->exx - s->eyy) * (s->exx - s->eyy) + s->exy * s->exy);
    s->rotation = atan2(s->H[2] - s->H[1], 2 + s->H[0] + s->H[3]);
}

static void add_weighted(gb_strain *s, const gb_strain *t)
{
    double a = t->area;
    for (int q = 0; q < 4; q++) s->H[q] += a * t->H[q];
    s->exx += a * t->exx, s->eyy += a * t->eyy, s->exy += a * t->exy;
    s->area += a;
}

void gb_strain_mean(int n, const gb_strain *tri, gb_strain *out)
{
    memset(out, 0, sizeof *out);
    for (int k = 0; k < n; k++) add_weighted(out, &tri[k]);
    finish_mean(out);
}

void gb_strain_points(const gb_triangulation *t, const gb_strain *tri, int n, gb_strain *out, int *n_tri)
{
    memset(out, 0, (size_t)n * sizeof *out);
    if (n_tri) memset(n_tri, 0, (size_t)n * sizeof *n_tri);
    /* Sums of area x (H, strain) first, then divided: the strain is averaged as a tensor, not
     * recomputed from the mean H, so that the mean of a grain is the mean of its triangles. */
    for (int k = 0; k < t->n; k++)
        for (int c = 0; c < 3; c++) {
            int i = t->v[3 * k + c];
            add_weighted(&out[i], &tri[k]);
            if (n_tri) n_tri[i]++;
        }
    for (int i = 0; i < n; i++) finish_mean(&out[i]);
}

typedef struct {
    double gamma, area;
} gamma_area;

static int by_gamma_desc(const void *a, const void *b)
{
    double x = ((const gamma_area *)a)->gamma, y = ((const gamma_area *)b)->gamma;
    return (x < y) - (x > y);
}

gb_status gb_localisation_index(int n, const gb_strain *tri, double fraction, gb_localisation *out, gb_error *err)
{
    memset(out, 0, sizeof *out);
    out->fraction = fraction;
    if (n <= 0) return gb_fail(err, GB_EINPUT, "localisation index: no triangles");
    if (!(fraction > 0 && fraction <= 1))
        return gb_fail(err, GB_EINPUT, "localisation index: fraction %g not in (0, 1]", fraction);
    gamma_area *ga = malloc((size_t)n * sizeof *ga);
    if (!ga) return gb_fail(err, GB_ENOMEM, "out of memory for %d triangles", n);
    double total = 0;
    for (int k = 0; k < n; k++) {
        ga[k].gamma = tri[k].gamma, ga[k].area = tri[k].area;
        out->area += tri[k].area;
        total += tri[k].gamma * tri[k].area;
        out->max_gamma = fmax(out->max_gamma, tri[k].gamma);
    }
    qsort(ga, (size_t)n, sizeof *ga, by_gamma_desc);
    double target = fraction * out->area, taken = 0, top = 0;
    for (int k = 0; k < n && taken < target; k++) {
        double a = fmin(ga[k].area, target - taken); /* the last triangle in part */
        taken += a;
        top += ga[k].gamma * a;
    }
    free(ga);
    if (out->area > 0) out->mean_gamma = total / out->area;
    out->index = total > 0 ? top / total : 0;
    return GB_OK;
}
