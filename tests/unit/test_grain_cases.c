/* The four cases of a grain's move (K section 2.5): a) det S != 0, b) no contact, c) one contact,
 * d) det S = 0 with two or more contacts (kt = 0), plus d) with parallel normals. Walls keep the
 * contact normals fixed, so the springs are exactly linear and the expected moves are exact. */
#include "check.h"
#include "gem/sim.h"
#include "gembem/run.h"
#include "scene_fixture.h"

static const double KN = 1e8, KT = 7e7;

static gb_sim *make(gb_grain *g, int n, gb_box box, double kt, double bx, double by, gb_scene *s,
                    gb_contact_init *ci, int nci)
{
    *s = fixture_scene(g, n, box, KN, kt, 60);
    s->body_force_per_area[0] = bx / (3.14159265358979323846 * g[0].r * g[0].r);
    s->body_force_per_area[1] = by / (3.14159265358979323846 * g[0].r * g[0].r);
    s->restart.contacts = ci;
    s->restart.n_contacts = nci;
    gb_error err;
    gb_sim *sim = NULL;
    if (gb_sim_create(s, &sim, &err)) fprintf(stderr, "%s\n", err.msg);
    gb_gem_forces(sim);
    return sim;
}

int main(void)
{
    gb_error err;
    gb_scene s;
    double dX[3];
    {   /* a) a grain in the corner against two walls, tangential forces preloaded, body force. */
        gb_grain g[1] = {{1 - 2e-3, 1 - 1e-3, 1, 0}};
        gb_box box = {0, 10, 0, 10};
        gb_contact_init ci[2] = {{0, -1 - GB_WALL_LEFT, 3e4, 0}, {0, -1 - GB_WALL_BOTTOM, -5e4, 0}};
        gb_sim *sim = make(g, 1, box, KT, 2e4, -7e4, &s, ci, 2);
        CHECK(sim->scratch.nc[0] == 2);
        double F0[3] = {sim->scratch.F[0], sim->scratch.F[1], sim->scratch.F[2]};
        CHECK(fabs(F0[0]) + fabs(F0[1]) + fabs(F0[2]) > 1e4);
        gb_gem_grain_move(sim, 0, sim->scratch.dX);
        CHECK(gb_gem_apply_moves(sim, &err) == GB_OK);
        gb_gem_forces(sim);
        /* dX = -alpha S^-1 F (K 9) on linear springs leaves (1 - alpha) F. */
        double alpha = s.solver.alpha;
        for (int k = 0; k < 3; k++) CHECK_NEAR(sim->scratch.F[k], (1 - alpha) * F0[k], 1e-7 * 1e5);
        gb_sim_free(sim);
    }
    {   /* b) no contact: dX = beta B / kn (K 10). */
        gb_grain g[1] = {{5, 5, 1, 0}};
        gb_box box = {0, 10, 0, 10};
        gb_sim *sim = make(g, 1, box, KT, 300, -1500, &s, NULL, 0);
        CHECK(sim->scratch.nc[0] == 0);
        gb_gem_grain_move(sim, 0, dX);
        CHECK_NEAR(dX[0], s.solver.beta * 300 / KN, 1e-18);
        CHECK_NEAR(dX[1], s.solver.beta * -1500 / KN, 1e-18);
        CHECK_NEAR(dX[2], 0, 0);
        gb_sim_free(sim);
    }
    {   /* c) one contact, on the bottom wall, with a sideways body force: the normal move cancels
         * the normal fixing force by alpha', the grain rolls (du_t = 0) by beta' (b.t)/kn (K 11). */
        gb_grain g[1] = {{5, 1 - 1e-3, 1, 0}};
        gb_box box = {0, 10, 0, 10};
        gb_sim *sim = make(g, 1, box, KT, 400, -2000, &s, NULL, 0);
        CHECK(sim->scratch.nc[0] == 1);
        gb_gem_grain_move(sim, 0, dX);
        double nx = 0, ny = -1, tx = -ny, ty = nx; /* normal towards the wall, tangent (K 2) */
        double fn = sim->scratch.F[0] * nx + sim->scratch.F[1] * ny;
        CHECK_NEAR(dX[0] * nx + dX[1] * ny, -s.solver.alpha1 * fn / KN, 1e-18);
        CHECK_NEAR(dX[0] * tx + dX[1] * ty, s.solver.beta1 * (400 * tx - 2000 * ty) / KN, 1e-18);
        CHECK_NEAR(dX[0] * tx + dX[1] * ty + dX[2], 0, 1e-18); /* rolling: du_t = 0 */
        gb_sim_free(sim);
    }
    {   /* d) kt = 0, two walls: rotation locked, translation by the 2x2 block (K 12). */
        gb_grain g[1] = {{1 - 2e-3, 1 - 1e-3, 1, 0}};
        gb_box box = {0, 10, 0, 10};
        gb_sim *sim = make(g, 1, box, 0, 0, -500, &s, NULL, 0);
        gb_gem_grain_move(sim, 0, dX);
        CHECK_NEAR(dX[2], 0, 0);
        CHECK_NEAR(dX[0], -s.solver.alpha * sim->scratch.F[0] / KN, 1e-18);
        CHECK_NEAR(dX[1], -s.solver.alpha * sim->scratch.F[1] / KN, 1e-18);
        gb_sim_free(sim);
    }
    {   /* d) kt = 0 squeezed between two parallel walls: the block has rank one; along the normal the
         * stiffness, along the free direction the body force as in b). No NaN. */
        gb_grain g[1] = {{1, 5, 1, 0}};
        gb_box box = {0.002, 1.998, 0, 10};
        g[0].x = 1.0005;
        gb_sim *sim = make(g, 1, box, 0, 0, -500, &s, NULL, 0);
        CHECK(sim->scratch.nc[0] == 2);
        gb_gem_grain_move(sim, 0, dX);
        CHECK_NEAR(dX[0], -s.solver.alpha * sim->scratch.F[0] / (2 * KN), 1e-15);
        CHECK_NEAR(dX[1], s.solver.beta * -500 / KN, 1e-15);
        CHECK_NEAR(dX[2], 0, 0);
        gb_sim_free(sim);
    }
    TEST_END();
}
