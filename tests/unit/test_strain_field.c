/* The strain field of grain centres (src/measure): references computed here.
 * - An affine displacement x = (I + A) X + b: in every triangle H = A and the strain
 *   -(A + A^t + A^t A)/2 (1e-12), every grain's mean the same (1e-12), D2min = 0 (1e-24 of the
 *   squared spacing), the zone's mean the same (1e-12), the localisation index of a uniform strain
 *   = the fraction (1e-12).
 * - A rigid rotation by 0.3 rad (and a translation): zero strain (1e-12), rotation 0.3 (1e-12).
 * - Two shear bands on a grid (displacement piecewise affine in y): the index from the bands' areas
 *   and shears (1e-12), on a regular grid (cocircular points) and a jittered one.
 * - The void criterion drops the triangles across a notch of a non-convex zone and a flat triangle
 *   along the convex hull, and nothing else there.
 * - Degenerate input: fewer than 3 points, collinear points, a non-finite point: GB_EINPUT, no
 *   triangles; D2min of collinear neighbours: ok = 0 and zeros, never NaN. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "gembem/strain_field.h"

static unsigned long long lcg = 12345;
static double rnd(void)
{
    lcg = lcg * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(lcg >> 11) / 9007199254740992.0;
}

/* Green-Lagrange strain of H, compression positive, and gamma. */
static void exact(const double H[4], double e[4])
{
    e[0] = -(H[0] + 0.5 * (H[0] * H[0] + H[2] * H[2]));
    e[1] = -(H[3] + 0.5 * (H[1] * H[1] + H[3] * H[3]));
    e[2] = -0.5 * (H[1] + H[2] + H[0] * H[1] + H[2] * H[3]);
    e[3] = 2 * sqrt(0.25 * (e[0] - e[1]) * (e[0] - e[1]) + e[2] * e[2]);
}

static void test_affine(void)
{
    enum { N = 400 };
    double x0[2 * N], x1[2 * N];
    const double A[4] = {0.012, -0.007, 0.004, -0.02}, b[2] = {0.3, -0.1};
    for (int i = 0; i < N; i++) {
        x0[2 * i] = 10 * rnd(), x0[2 * i + 1] = 5 * rnd();
        x1[2 * i] = x0[2 * i] + A[0] * x0[2 * i] + A[1] * x0[2 * i + 1] + b[0];
        x1[2 * i + 1] = x0[2 * i + 1] + A[2] * x0[2 * i] + A[3] * x0[2 * i + 1] + b[1];
    }
    gb_error err = {0};
    gb_triangulation t;
    CHECK(gb_triangulate(N, x0, NULL, 0, &t, &err) == GB_OK);
    CHECK(t.n > N && t.n == t.n_delaunay);
    gb_strain *tri = malloc((size_t)t.n * sizeof *tri), pt[N];
    int ntri[N];
    gb_strain_triangles(&t, x0, x1, tri);
    double e[4], area = 0, hmax = 0, emax = 0;
    exact(A, e);
    for (int k = 0; k < t.n; k++) {
        for (int q = 0; q < 4; q++) hmax = fmax(hmax, fabs(tri[k].H[q] - A[q]));
        emax = fmax(emax, fabs(tri[k].exx - e[0]) + fabs(tri[k].eyy - e[1]) + fabs(tri[k].exy - e[2]) +
                              fabs(tri[k].gamma - e[3]) + fabs(tri[k].ev - e[0] - e[1]));
        CHECK(tri[k].area > 0);
        area += tri[k].area;
    }
    printf("affine: %d triangles of %d points, |H - A| <= %.2g, strain off by <= %.2g\n", t.n, N, hmax, emax);
    CHECK_NEAR(hmax, 0, 1e-12);
    CHECK_NEAR(emax, 0, 1e-12);
    gb_strain_points(&t, tri, N, pt, ntri);
    double pmax = 0;
    for (int i = 0; i < N; i++) {
        CHECK(ntri[i] > 0);
        pmax = fmax(pmax, fabs(pt[i].exx - e[0]) + fabs(pt[i].eyy - e[1]) + fabs(pt[i].exy - e[2]) +
                              fabs(pt[i].gamma - e[3]));
    }
    CHECK_NEAR(pmax, 0, 1e-12);
    gb_strain mean;
    gb_strain_mean(t.n, tri, &mean);
    CHECK_NEAR(fabs(mean.exx - e[0]) + fabs(mean.eyy - e[1]) + fabs(mean.exy - e[2]) + fabs(mean.gamma - e[3]), 0, 1e-12);
    CHECK_NEAR(mean.area, area, 1e-12);
    gb_localisation loc;
    CHECK(gb_localisation_index(t.n, tri, 0.1, &loc, &err) == GB_OK);
    CHECK_NEAR(loc.index, 0.1, 1e-12);
    CHECK_NEAR(loc.mean_gamma, e[3], 1e-12);
    CHECK_NEAR(loc.area, area, 1e-12);
    gb_d2min d[N];
    CHECK(gb_d2min_points(N, x0, x1, 1.5, d, &err) == GB_OK);
    double dmax = 0, gmax = 0;
    for (int i = 0; i < N; i++) {
        CHECK(d[i].ok && d[i].neighbours >= 2);
        dmax = fmax(dmax, d[i].d2min);
        for (int q = 0; q < 4; q++) gmax = fmax(gmax, fabs(d[i].G[q] - A[q]));
    }
    printf("affine: D2min <= %.2g, |G - A| <= %.2g\n", dmax, gmax);
    CHECK_NEAR(dmax, 0, 1e-24);
    CHECK_NEAR(gmax, 0, 1e-12);
    free(tri);
    gb_triangulation_free(&t);
}

static void test_rotation(void)
{
    enum { N = 200 };
    double x0[2 * N], x1[2 * N], th = 0.3, c = cos(th), s = sin(th);
    for (int i = 0; i < N; i++) {
        x0[2 * i] = 4 * rnd() - 2, x0[2 * i + 1] = 4 * rnd() - 2;
        x1[2 * i] = c * x0[2 * i] - s * x0[2 * i + 1] + 1.5;
        x1[2 * i + 1] = s * x0[2 * i] + c * x0[2 * i + 1] - 0.5;
    }
    gb_error err = {0};
    gb_triangulation t;
    CHECK(gb_triangulate(N, x0, NULL, 0, &t, &err) == GB_OK);
    gb_strain *tri = malloc((size_t)t.n * sizeof *tri);
    gb_strain_triangles(&t, x0, x1, tri);
    double emax = 0, rmax = 0;
    for (int k = 0; k < t.n; k++) {
        emax = fmax(emax, fabs(tri[k].exx) + fabs(tri[k].eyy) + fabs(tri[k].exy) + fabs(tri[k].gamma));
        rmax = fmax(rmax, fabs(tri[k].rotation - th));
    }
    printf("rotation by %.2f rad: strain <= %.2g, rotation off by <= %.2g\n", th, emax, rmax);
    CHECK_NEAR(emax, 0, 1e-12);
    CHECK_NEAR(rmax, 0, 1e-12);
    gb_localisation loc;
    CHECK(gb_localisation_index(t.n, tri, 0.1, &loc, &err) == GB_OK);
    CHECK(loc.index >= 0 && loc.index <= 1); /* rounding only: no shear to share */
    gb_d2min d[N];
    CHECK(gb_d2min_points(N, x0, x1, 0.8, d, &err) == GB_OK);
    double dmax = 0;
    for (int i = 0; i < N; i++) dmax = fmax(dmax, d[i].ok ? d[i].d2min : 0);
    CHECK_NEAR(dmax, 0, 1e-24);
    free(tri);
    gb_triangulation_free(&t);
}

/* Simple shear u_x = g(y) on the unit square (rows y_j = j/NY): g' = ga in band A (rows ja0..ja1),
 * gb in band B, 0 elsewhere. Each triangle spans one row of cells, so each lies in one band:
 * gamma of simple shear k (Green-Lagrange: exx = 0, eyy = -k^2/2, exy = -k/2) is sqrt(k^4/4 + k^2). */
static void test_bands(double jitter)
{
    enum { NX = 21, NY = 41, N = NX * NY };
    const int ja0 = 10, ja1 = 12, jb0 = 20, jb1 = 30; /* areas 0.05 and 0.25 */
    const double ka = 0.04, kb = 0.01;
    double x0[2 * N], x1[2 * N];
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            int p = j * NX + i;
            double y = (double)j / (NY - 1), dx = (i > 0 && i < NX - 1) ? jitter * (rnd() - 0.5) / (NX - 1) : 0;
            x0[2 * p] = (double)i / (NX - 1) + dx, x0[2 * p + 1] = y;
            /* g(y) integrates the bands' shears up to row j */
            double g = 0;
            for (int q = 0; q < j; q++) g += (q >= ja0 && q < ja1 ? ka : q >= jb0 && q < jb1 ? kb : 0) / (NY - 1);
            x1[2 * p] = x0[2 * p] + g, x1[2 * p + 1] = y;
        }
    gb_error err = {0};
    gb_triangulation t;
    CHECK(gb_triangulate(N, x0, NULL, 0, &t, &err) == GB_OK);
    CHECK(t.n == 2 * (NX - 1) * (NY - 1));
    gb_strain *tri = malloc((size_t)t.n * sizeof *tri);
    gb_strain_triangles(&t, x0, x1, tri);
    gb_localisation loc;
    CHECK(gb_localisation_index(t.n, tri, 0.1, &loc, &err) == GB_OK);
    double Ga = sqrt(pow(ka, 4) / 4 + ka * ka), Gb = sqrt(pow(kb, 4) / 4 + kb * kb);
    double fa = (double)(ja1 - ja0) / (NY - 1), fb = (double)(jb1 - jb0) / (NY - 1);
    /* the top 10 %: all of band A (5 %), then 5 % of band B */
    double want = (Ga * fa + Gb * (0.1 - fa)) / (Ga * fa + Gb * fb);
    printf("bands (jitter %g): %d triangles, index %.15f, expected %.15f\n", jitter, t.n, loc.index, want);
    CHECK_NEAR(loc.index, want, 1e-12);
    CHECK_NEAR(loc.area, 1, 1e-12);
    CHECK_NEAR(loc.mean_gamma, Ga * fa + Gb * fb, 1e-12);
    CHECK_NEAR(loc.max_gamma, Ga, 1e-12);
    free(tri);
    gb_triangulation_free(&t);
}

/* An L-shaped zone of grains of radius 0.5 on a unit grid: the Delaunay triangles across the notch
 * (edges of length >= 2, longer than r + r + the largest diameter 1) go; those of the zone stay. */
static void test_notch(void)
{
    double xy[2 * 64], r[64];
    int n = 0;
    for (int j = 0; j < 8; j++)
        for (int i = 0; i < 8; i++)
            if (i < 3 || j < 3) xy[2 * n] = i + 0.001 * j * j, xy[2 * n + 1] = j + 0.0013 * i * i, r[n++] = 0.5;
    gb_error err = {0};
    gb_triangulation t, all;
    CHECK(gb_triangulate(n, xy, r, -1, &t, &err) == GB_OK);
    CHECK(gb_triangulate(n, xy, NULL, 0, &all, &err) == GB_OK);
    double area = 0;
    gb_strain *tri = malloc((size_t)all.n * sizeof *tri);
    gb_strain_triangles(&t, xy, xy, tri);
    for (int k = 0; k < t.n; k++) area += tri[k].area;
    /* The zone: the 7 x 7 hull less the 5 x 5 notch, and the notch's corner triangle (2,2), (3,2),
     * (2,3), whose edges are short enough: about 24.5 (the grid is slightly bent). */
    printf("notch: %d Delaunay triangles, %d kept, area %.4f (zone about 24.5)\n", all.n, t.n, area);
    CHECK(all.n > t.n);
    CHECK(t.n_delaunay == all.n);
    CHECK(fabs(area - 24.5) < 0.2);
    free(tri);
    gb_triangulation_free(&t);
    gb_triangulation_free(&all);
}

/* A 3 x 3 grid (radius 0.5) with the middle of its bottom row raised by 0.05: the flat triangle
 * of the bottom row along the hull has edges no longer than r + r + gap = 2 but a circumradius of
 * about 10, over r_max + gap/2 = 1, and goes; every other triangle stays. */
static void test_hull_sliver(void)
{
    double xy[18], r[9];
    for (int k = 0; k < 9; k++) xy[2 * k] = k % 3, xy[2 * k + 1] = k / 3, r[k] = 0.5;
    xy[3] = 0.05;
    gb_error err = {0};
    gb_triangulation t, all;
    CHECK(gb_triangulate(9, xy, r, -1, &t, &err) == GB_OK);
    CHECK(gb_triangulate(9, xy, NULL, 0, &all, &err) == GB_OK);
    int flat = 0;
    for (int k = 0; k < all.n; k++) {
        int has[9] = {0};
        for (int c = 0; c < 3; c++) has[all.v[3 * k + c]] = 1;
        flat += has[0] && has[1] && has[2];
    }
    for (int k = 0; k < t.n; k++) {
        int has[9] = {0};
        for (int c = 0; c < 3; c++) has[t.v[3 * k + c]] = 1;
        flat -= has[0] && has[1] && has[2];
    }
    printf("hull sliver: %d Delaunay triangles, %d kept\n", all.n, t.n);
    CHECK(t.n == all.n - 1 && flat == 1);
    gb_triangulation_free(&t);
    gb_triangulation_free(&all);
}

static void test_degenerate(void)
{
    gb_error err = {0};
    gb_triangulation t;
    double two[4] = {0, 0, 1, 1}, line[10] = {0, 0, 1, 1, 2, 2, 3, 3, 4, 4}, nan_[6] = {0, 0, 1, 0, NAN, 1};
    CHECK(gb_triangulate(2, two, NULL, 0, &t, &err) == GB_EINPUT && t.n == 0 && !t.v);
    printf("2 points: %s\n", err.msg);
    CHECK(gb_triangulate(5, line, NULL, 0, &t, &err) == GB_EINPUT && t.n == 0 && !t.v);
    printf("collinear: %s\n", err.msg);
    CHECK(gb_triangulate(3, nan_, NULL, 0, &t, &err) == GB_EINPUT && t.n == 0);
    gb_triangulation_free(&t);
    /* The smallest zone: one triangle. */
    double three[6] = {0, 0, 1, 0, 0, 1}, moved3[6] = {0, 0, 1.01, 0, 0.02, 1};
    CHECK(gb_triangulate(3, three, NULL, 0, &t, &err) == GB_OK && t.n == 1);
    gb_strain s3;
    if (t.n == 1) gb_strain_triangles(&t, three, moved3, &s3);
    CHECK(t.n == 1 && fabs(s3.H[0] - 0.01) < 1e-15 && fabs(s3.H[1] - 0.02) < 1e-15 && s3.area == 0.5);
    gb_triangulation_free(&t);
    gb_localisation loc;
    CHECK(gb_localisation_index(0, NULL, 0.1, &loc, &err) == GB_EINPUT && loc.index == 0);
    CHECK(gb_localisation_index(1, &s3, 1.5, &loc, &err) == GB_EINPUT);
    /* D2min: neighbours on a line through the point, none, or a single point: no fit, zeros. */
    double moved[10] = {0, 0.1, 1, 1.3, 2, 2, 3, 3, 4, 4.2};
    gb_d2min d[5];
    CHECK(gb_d2min_points(5, line, moved, 1.5, d, &err) == GB_OK);
    for (int i = 0; i < 5; i++) CHECK(!d[i].ok && d[i].d2min == 0 && isfinite(d[i].G[0]));
    CHECK(gb_d2min_points(1, line, moved, 1.5, d, &err) == GB_OK && !d[0].ok && d[0].neighbours == 0);
    CHECK(gb_d2min_points(5, line, moved, 0, d, &err) == GB_EINPUT);
}

int main(void)
{
    test_affine();
    test_rotation();
    test_bands(0);
    test_bands(0.2);
    test_notch();
    test_hull_sliver();
    test_degenerate();
    TEST_END();
}
