/* The assembled H and G (threaded, with shared logarithms) against the element integrals of
 * bem/segment.c entry by entry, on two loops of different sizes (loop boundaries and thread
 * boundaries inside them); H with the breathing-mode correction rebuilt here from its definition
 * (the incompressible part of H from two Poisson ratios, its flux defects per loop, one rank-one
 * update per loop); and the material checks. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bem/segment.h"
#include "check.h"
#include "core/memory.h"

int main(void)
{
    gb_error err = {0};
    int n1 = 301, n2 = 217, ln[2] = {n1, n2};
    double *xy = malloc(sizeof(double) * 2 * (size_t)(n1 + n2));
    int *g = calloc((size_t)(n1 + n2), sizeof(int));
    for (int i = 0; i < n1; i++) { /* a wavy outer boundary, a shifted ellipse inside */
        double a = 2 * GB_PI * i / n1, r = 3 + 0.3 * cos(5 * a);
        xy[2 * i] = r * cos(a), xy[2 * i + 1] = r * sin(a);
    }
    for (int i = 0; i < n2; i++) {
        double a = 2 * GB_PI * i / n2;
        xy[2 * (n1 + i)] = 0.4 + 1.2 * cos(a), xy[2 * (n1 + i) + 1] = 0.7 * sin(a);
    }
    gb_bem_mesh m;
    CHECK(gb_bem_mesh_from_polygons(2, ln, xy, g, 1, NULL, 0, &m, &err) == GB_OK);
    gb_bem_material mat = {3.0, 0.27, GB_BEM_PLANE_STRESS};
    gb_bem_kconst k;
    CHECK(gb_bem_kconst_init(&mat, &k, &err) == GB_OK);
    CHECK_NEAR(k.nu, 0.27 / 1.27, 1e-15);
    gb_bem_system s;
    CHECK(gb_bem_assemble(&m, &mat, &s, &err) == GB_OK);
    size_t nd = (size_t)s.ndof;
    /* H(nu) = cp(nu) [X + (1 - 2 nu) Y] + c: X from nu = 0 and nu = 1/4, H_half = -X / (2 pi) + c */
    gb_bem_kconst k0, k4;
    gb_bem_material m0 = {3.0, 0.0, GB_BEM_PLANE_STRAIN}, m4 = {3.0, 0.25, GB_BEM_PLANE_STRAIN};
    CHECK(gb_bem_kconst_init(&m0, &k0, &err) == GB_OK && gb_bem_kconst_init(&m4, &k4, &err) == GB_OK);
    double *H = malloc(sizeof(double) * nd * nd), *flux = calloc(2 * nd, sizeof(double));
    double worst_g = 0;
    for (int i = 0; i < m.n; i++)
        for (int j = 0; j < m.n; j++) {
            double gg[4], hh[4], h0[4], h4[4], g0[4];
            gb_bem_segment_gh(&k, m.mid + 2 * i, m.p0 + 2 * j, m.p1 + 2 * j, i == j, gg, hh);
            gb_bem_segment_gh(&k0, m.mid + 2 * i, m.p0 + 2 * j, m.p1 + 2 * j, i == j, g0, h0);
            gb_bem_segment_gh(&k4, m.mid + 2 * i, m.p0 + 2 * j, m.p1 + 2 * j, i == j, g0, h4);
            for (int l = 0; l < 2; l++)
                for (int c = 0; c < 2; c++) {
                    size_t at = (size_t)(2 * j + c) * nd + (size_t)(2 * i + l);
                    double half = -(2 * h4[2 * l + c] / k4.cp - h0[2 * l + c] / k0.cp) / (2 * GB_PI) +
                                  (i == j && l == c ? 0.5 : 0);
                    H[at] = hh[2 * l + c] + (i == j && l == c ? 0.5 : 0);
                    flux[(size_t)m.loop[i] * nd + (size_t)(2 * j + c)] += m.length[i] * m.normal[2 * i + l] * half;
                    worst_g = fmax(worst_g, fabs(s.G[at] - gg[2 * l + c]) / k.cu);
                }
        }
    for (int L = 0; L < 2; L++) { /* targets: w^t for the outer loop, 0 for a cavity */
        double P = 0;
        for (int e = m.loop_start[L]; e < m.loop_start[L + 1]; e++) P += m.length[e];
        for (size_t c = 0; c < nd; c++) {
            double d = flux[(size_t)L * nd + c] - (m.loop_outer[L] ? m.length[c / 2] * m.normal[c] : 0);
            for (int e = m.loop_start[L]; e < m.loop_start[L + 1]; e++)
                for (int l = 0; l < 2; l++) H[c * nd + (size_t)(2 * e + l)] -= m.normal[2 * e + l] * d / P;
        }
    }
    double worst_h = 0;
    for (size_t i = 0; i < nd * nd; i++) worst_h = fmax(worst_h, fabs(s.H[i] - H[i]));
    CHECK(worst_h < 1e-12);
    CHECK(worst_g < 1e-13);
    free(H);
    free(flux);
    gb_bem_system_free(&s);
    gb_bem_material bad = {-1, 0.3, GB_BEM_PLANE_STRAIN};
    CHECK(gb_bem_assemble(&m, &bad, &s, &err) == GB_EINPUT);
    bad.shear_modulus = 1;
    bad.poisson = 0.5;
    CHECK(gb_bem_assemble(&m, &bad, &s, &err) == GB_EINPUT);
    gb_bem_mesh_free(&m);
    free(xy);
    free(g);
    /* a mesh whose dense matrices cannot fit in this machine is refused before allocation */
    double have = gb_memory_physical();
    CHECK(have > 0);
    int big = (int)(2 * sqrt(have / 128)) + 10;
    CHECK(gb_bem_mesh_circle(0, 0, 1, big, 0, &m, &err) == GB_OK);
    CHECK(gb_bem_assemble(&m, &mat, &s, &err) == GB_EINPUT);
    CHECK(strstr(err.msg, "this machine has available") != NULL);
    printf("%d elements: %s\n", big, err.msg);
    gb_bem_mesh_free(&m);
    TEST_END();
}
