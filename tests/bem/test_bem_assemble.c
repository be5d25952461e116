/* The assembled H and G (threaded, with shared logarithms) against the element integrals of
 * bem/segment.c entry by entry, on two loops of different sizes (loop boundaries and thread
 * boundaries inside them), and the material checks. */
#include <math.h>
#include <stdlib.h>

#include "bem/segment.h"
#include "check.h"

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
    double worst_h = 0, worst_g = 0;
    for (int i = 0; i < m.n; i++)
        for (int j = 0; j < m.n; j++) {
            double gg[4], hh[4];
            gb_bem_segment_gh(&k, m.mid + 2 * i, m.p0 + 2 * j, m.p1 + 2 * j, i == j, gg, hh);
            if (i == j) hh[0] += 0.5, hh[3] += 0.5;
            for (int l = 0; l < 2; l++)
                for (int c = 0; c < 2; c++) {
                    size_t at = (size_t)(2 * j + c) * nd + (size_t)(2 * i + l);
                    worst_h = fmax(worst_h, fabs(s.H[at] - hh[2 * l + c]));
                    worst_g = fmax(worst_g, fabs(s.G[at] - gg[2 * l + c]) / k.cu);
                }
        }
    CHECK(worst_h < 1e-13);
    CHECK(worst_g < 1e-13);
    gb_bem_system_free(&s);
    gb_bem_material bad = {-1, 0.3, GB_BEM_PLANE_STRAIN};
    CHECK(gb_bem_assemble(&m, &bad, &s, &err) == GB_EINPUT);
    bad.shear_modulus = 1;
    bad.poisson = 0.5;
    CHECK(gb_bem_assemble(&m, &bad, &s, &err) == GB_EINPUT);
    gb_bem_mesh_free(&m);
    free(xy);
    free(g);
    TEST_END();
}
