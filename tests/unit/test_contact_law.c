/* The contact law after a move (K 6, 13): tangential increments, the Coulomb limit with
 * cohesion, and opening. */
#include "check.h"
#include "contact/pairs.h"

int main(void)
{
    gb_grain g[2] = {{0, 0, 1, 0}, {1.99, 0, 1, 0}};
    gb_box box = {-100, 100, -100, 100};
    gb_material m = {1e8, 7e7, 30, 0, 0, 0};
    double tan_phi = tan(30 * 3.14159265358979323846 / 180);
    double walls[8] = {0};
    double dX[6] = {0};
    gb_pair p = {.i = 0, .j = 1};
    gb_world world = {g, 2, &box, NULL};
    gb_pair_geometry(&p, &world);
    CHECK_NEAR(p.d, 0.01, 1e-15);
    p.pn = m.kn * p.d;

    /* A small tangential move of grain 0 (along t = (0, 1)) and a rotation: pt += kt du_t, with
     * du_t = dx.t + r dw + r' dw' (K 25). */
    dX[1] = 1e-6, dX[2] = 2e-6, dX[5] = 3e-6;
    g[0].y += dX[1];
    double stick = gb_pair_update(&p, &world, dX, walls, &m, tan_phi);
    CHECK_NEAR(p.pt, m.kt * (1e-6 + 2e-6 + 3e-6), 1e-6);
    CHECK_NEAR(p.pn, m.kn * (2 - hypot(1.99, 1e-6)), 1e-3);
    /* below the cap a move is all elastic: du_d = du_t - dpt/kt = 0 (K 26), nothing dissipated
     * (exactly: computed, du_d was a rounding of either sign) */
    CHECK(stick == 0);
    double stick_pt = p.pt;
    dX[1] = 1.3e-6, dX[2] = 0.7e-6, dX[5] = -0.1e-6;
    g[0].y += dX[1];
    stick = gb_pair_update(&p, &world, dX, walls, &m, tan_phi);
    CHECK_NEAR(p.pt, stick_pt + m.kt * (1.3e-6 + 0.7e-6 - 0.1e-6), 1e-6);
    CHECK(stick == 0);

    /* A large tangential move: |pt| is capped at pn tan(phi) (K 13); the slip beyond the elastic
     * part dissipates mean(pt) x (du_t - dpt/kt) (K 26-28). */
    double pt_before = p.pt;
    dX[1] = 1e-2, dX[2] = dX[5] = 0;
    g[0].y += dX[1];
    double du_t = 1e-2; /* along t = (-ny, nx) = (0, 1) of the previous normal (1, 0) */
    double diss = gb_pair_update(&p, &world, dX, walls, &m, tan_phi);
    CHECK_NEAR(p.pt, p.pn * tan_phi, 1e-9 * p.pn);
    CHECK_NEAR(diss, 0.5 * (pt_before + p.pt) * (du_t - (p.pt - pt_before) / m.kt), 1e-9 * diss);
    CHECK(diss > 0);
    /* and the other way */
    dX[1] = -3e-2;
    g[0].y += dX[1];
    gb_pair_update(&p, &world, dX, walls, &m, tan_phi);
    CHECK_NEAR(p.pt, -p.pn * tan_phi, 1e-9 * p.pn);

    /* With cohesion c the limit is pn tan(phi) + c. */
    gb_material mc = m;
    mc.cohesion = 5e4;
    dX[1] = 3e-2;
    g[0].y += dX[1];
    gb_pair_update(&p, &world, dX, walls, &mc, tan_phi);
    CHECK_NEAR(p.pt, p.pn * tan_phi + 5e4, 1e-9 * p.pn);

    /* Opening: a move apart drops both forces; touching again starts with pt = 0. */
    dX[0] = -0.02, dX[1] = 0;
    g[0].x += dX[0];
    pt_before = p.pt;
    diss = gb_pair_update(&p, &world, dX, walls, &m, tan_phi);
    CHECK(p.d < 0);
    /* Opening releases the tangential spring's energy. */
    CHECK_NEAR(diss, pt_before * pt_before / (2 * m.kt), 1e-12 * diss);
    CHECK_NEAR(p.pn, 0, 0);
    CHECK_NEAR(p.pt, 0, 0);
    /* Staying apart (gb_pair_stays_apart: no update): still no force, nothing dissipated. */
    dX[0] = -1e-3, dX[1] = 0;
    g[0].x += dX[0];
    diss = gb_pair_update(&p, &world, dX, walls, &m, tan_phi);
    CHECK(p.d <= 0 && diss == 0 && p.pn == 0 && p.pt == 0);
    dX[0] = 0.015 + 1e-3, dX[1] = 1e-4;
    g[0].x += dX[0];
    g[0].y += dX[1];
    gb_pair_update(&p, &world, dX, walls, &m, tan_phi);
    CHECK(p.d > 0);
    CHECK_NEAR(p.pn, m.kn * p.d, 1e-6);
    CHECK_NEAR(p.pt, 0, 0);

    /* A wall contact: the wall's own translation enters du_t and du_n. */
    gb_grain w[1] = {{0, 0.999, 1, 0}};
    gb_box b2 = {-100, 100, 0, 100};
    gb_pair q = {.i = 0, .j = -1 - GB_WALL_BOTTOM};
    gb_world wworld = {w, 1, &b2, NULL};
    gb_pair_geometry(&q, &wworld);
    CHECK_NEAR(q.d, 1e-3, 1e-15);
    CHECK(q.nx == 0 && q.ny == -1);
    double dw[3] = {0, 0, 0};
    walls[2 * GB_WALL_BOTTOM] = 2e-5;     /* the wall slides by 2e-5 along x */
    walls[2 * GB_WALL_BOTTOM + 1] = 1e-4; /* and rises by 1e-4 */
    b2.bottom += 1e-4;
    gb_pair_update(&q, &wworld, dw, walls, &m, tan_phi);
    CHECK_NEAR(q.d, 1.1e-3, 1e-15);
    /* t = (-ny, nx) = (1, 0); du_t = (dx - dx_wall).t = -2e-5 */
    CHECK_NEAR(q.pt, m.kt * -2e-5, 1e-6);
    TEST_END();
}
