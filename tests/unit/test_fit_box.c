/* gb_sim_fit_box against the scaling laws of linear springs (src/gem/fit_box.c): five discs
 * pressed together and against the walls of a box, their contacts given tangential forces and
 * rolling moments (not balanced: a generic state), mapped onto a box s = 1.003 times as large and
 * shifted. Exact consequences of the law, independent of the code's bookkeeping:
 *  - the radii are s times theirs, the centres the map of theirs;
 *  - every stored overlap is the one the new positions make (ri + rj - |xj - xi|, r minus the
 *    distance to a wall), and every pn is kn times it;
 *  - every grain's fixing force (fx, fy, m/r) is s times its old one (forces scale by s, moments
 *    by s^2, radii by s), so a balanced state stays balanced;
 *  - the walls' stresses (forces over sides) are unchanged;
 *  - a box of another shape is refused. */
#include <math.h>

#include "check.h"
#include "scene_fixture.h"
#include "gem/sim.h"
#include "gembem/run.h"

static const double KN = 1e8, KT = 7e7, S = 1.003;

int main(void)
{
    gb_grain g[5] = {{1.0, 1.0, 1.0, 0}, {2.95, 1.1, 1.0, 0}, {4.9, 0.98, 1.0, 0}, {1.95, 2.7, 0.9, 0},
                     {3.9, 2.8, 1.1, 0}};
    gb_box box = {0.002, 5.9, 0.003, 3.85};
    gb_scene s = fixture_scene(g, 5, box, KN, KT, 30);
    s.grain_grain.kr = 1e6, s.grain_grain.eta = 0.2;
    gb_contact_init ci[3] = {{0, 1, 2e3, 50}, {1, 2, -1.5e3, -20}, {1, 3, 1e3, 0}};
    s.restart.contacts = ci, s.restart.n_contacts = 3;
    gb_error err;
    gb_sim *sim = NULL;
    CHECK(gb_sim_create(&s, &sim, &err) == GB_OK);
    if (!sim) return 1;
    gb_gem_forces(sim);
    double F0[5][3], s1, s2, t1, t2, largest = 0;
    gb_grain g0[5];
    for (int i = 0; i < 5; i++) {
        gb_sim_fixing_force(sim, i, F0[i]);
        g0[i] = gb_sim_grain(sim, i);
        largest = fmax(largest, fabs(F0[i][0]) + fabs(F0[i][1]) + fabs(F0[i][2]));
    }
    gb_sim_stress(sim, &s1, &s2);
    int contacts = gb_sim_contacts(sim, NULL, 0);
    CHECK(contacts >= 8 && largest > 1e3); /* pressed, and off balance */

    gb_box wrong = {0, 2 * (box.right - box.left), 0, box.top - box.bottom};
    CHECK(gb_sim_fit_box(sim, &wrong, &err) == GB_EINPUT);
    gb_box to = {-1.0, -1.0 + S * (box.right - box.left), 2.0, 2.0 + S * (box.top - box.bottom)};
    CHECK(gb_sim_fit_box(sim, &to, &err) == GB_OK);

    for (int i = 0; i < 5; i++) {
        gb_grain a = gb_sim_grain(sim, i);
        CHECK_NEAR(a.r, S * g0[i].r, 1e-15);
        CHECK_NEAR(a.x, to.left + S * (g0[i].x - box.left), 1e-14);
        CHECK_NEAR(a.y, to.bottom + S * (g0[i].y - box.bottom), 1e-14);
        double F[3];
        gb_sim_fixing_force(sim, i, F);
        for (int q = 0; q < 3; q++) CHECK_NEAR(F[q], S * F0[i][q], 1e-9 * largest);
    }
    gb_contact c[32];
    int m = gb_sim_contacts(sim, c, 32);
    CHECK(m == contacts);
    for (int k = 0; k < m && k < 32; k++) {
        gb_grain a = gb_sim_grain(sim, c[k].i);
        double d;
        if (c[k].j >= 0) {
            gb_grain b = gb_sim_grain(sim, c[k].j);
            d = a.r + b.r - hypot(b.x - a.x, b.y - a.y);
        } else {
            double gap[GB_N_WALLS] = {a.x - to.left, to.right - a.x, a.y - to.bottom, to.top - a.y};
            d = a.r - gap[-1 - c[k].j];
        }
        CHECK_NEAR(c[k].overlap, d, 1e-12);
        CHECK_NEAR(c[k].pn, KN * d, 1e-12 * KN);
    }
    gb_sim_stress(sim, &t1, &t2);
    CHECK_NEAR(t1, s1, 1e-12 * fabs(s1));
    CHECK_NEAR(t2, s2, 1e-12 * fabs(s2));
    printf("fit by %g: %d contacts, the walls' stresses %.9g %.9g (before %.9g %.9g)\n", S, m, t1, t2, s1, s2);
    gb_sim_free(sim);
    TEST_END();
}
