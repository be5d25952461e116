/* The grain contact stiffness S (K 8) against finite differences of the fixing force F (K 5):
 * with vanishing contact forces the geometric terms (pn/distance, which (K 8) leaves out) vanish,
 * and dF = S dX holds column by column. */
#include <stdlib.h>

#include "check.h"
#include "gem/sim.h"
#include "gembem/run.h"
#include "scene_fixture.h"

int main(void)
{
    /* A grain surrounded by four neighbours and touching the bottom wall, overlaps ~1e-9. */
    double eps = 1e-9;
    gb_grain g[6] = {{0, 0, 1, 0}};
    double ang[4] = {0.3, 1.9, 3.4, 4.6};
    double rr[4] = {0.8, 1.2, 0.5, 1.0};
    for (int k = 0; k < 4; k++) {
        double d = 1 + rr[k] - eps;
        gb_grain n = {d * cos(ang[k]), d * sin(ang[k]), rr[k], 0};
        g[k + 1] = n;
    }
    gb_grain far = {5, 5, 0.3, 0};
    g[5] = far;
    gb_box box = {-10, 10, -1 + eps, 10};
    gb_scene s = fixture_scene(g, 6, box, 1e8, 7e7, 30);
    gb_error err;
    gb_sim *sim;
    CHECK(gb_sim_create(&s, &sim, &err) == GB_OK);
    gb_gem_forces(sim);
    /* the simulation keeps its grains in its own order (src/gem/sim.h): the scene's grain 0 is its a */
    int a = sim->grain_place[0];
    const double *S0 = &sim->scratch.S[6 * a], *F = &sim->scratch.F[3 * a];
    CHECK(sim->scratch.nc[a] == 5);
    double S[3][3] = {{S0[0], S0[1], S0[2]}, {S0[1], S0[3], S0[4]}, {S0[2], S0[4], S0[5]}};
    double F0[3] = {F[0], F[1], F[2]};
    /* A move small against the 1e-9 overlaps, so that no contact opens; coordinates of order 1 carry
     * it to about 1e-5 relative, hence the tolerance. */
    double dh = 1e-11;
    for (int c = 0; c < 3; c++) {
        /* Move grain 0 by h along DOF c, all others held; the contacts see it through (K 6). */
        gb_sim *t;
        gb_sim_create(&s, &t, &err);
        gb_gem_forces(t);
        for (int k = 0; k < 3 * t->state.n; k++) t->scratch.dX[k] = 0;
        t->scratch.dX[3 * a + c] = dh;
        CHECK(gb_gem_apply_moves(t, &err) == GB_OK);
        gb_gem_forces(t);
        for (int r = 0; r < 3; r++) {
            double fd = (t->scratch.F[3 * a + r] - F0[r]) / dh;
            CHECK_NEAR(fd, S[r][c], 1e-3 * 1e8);
        }
        gb_sim_free(t);
    }
    /* S is symmetric positive definite here (kt > 0, several contacts). */
    double det = S[0][0] * (S[1][1] * S[2][2] - S[1][2] * S[1][2]) - S[0][1] * (S[0][1] * S[2][2] - S[1][2] * S[0][2]) +
                 S[0][2] * (S[0][1] * S[1][2] - S[1][1] * S[0][2]);
    CHECK(det > 0);
    /* Trace = sum over contacts of kn + kt + kt (K 8: |n|^2 kn + (|t|^2 + 1) kt). */
    CHECK_NEAR(S[0][0] + S[1][1] + S[2][2], 5 * (1e8 + 2 * 7e7), 1e-6 * 5e8);
    gb_sim_free(sim);
    TEST_END();
}
