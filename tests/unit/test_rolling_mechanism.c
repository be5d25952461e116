/* The two-grain rolling mechanism (docs/limits.md): two touching grains whose other contacts all
 * slide can roll on each other, r0 dw0 = -r1 dw1 leaving their contact unstrained, at no
 * stiffness. Here two equal discs (r 1) side by side in a box whose frictionless walls touch each
 * of them on three sides (every wall contact slides, at no force), the discs' contact sticking
 * (pt 0) with its rolling moment at the limit eta R* pn (rolling on: no kr in the tangent). Every
 * normal force is kn d and balanced; only the rolling moment is not, and it drives the mechanism.
 *  1. The line search's Newton move on this state: the system has nothing against the rolling
 *     mode, so the solve turns the discs by 1.4e6 rad (taken as such before the fix); beyond
 *     10 max_move = 1 rad a grain is not turned by the move (src/solver/global.c), and nothing
 *     else moves either.
 *  2. Relaxed by the line search, whose smoother rolls the pair, it rolls until the moment has
 *     unloaded elastically (mr = -kr (theta0 - theta1) from the limit down to 0): theta0 - theta1
 *     = limit / kr, so |w0| = |w1| = limit / (2 kr) = 2.5e-3 rad, opposite, the discs where they
 *     were, pt = 0.
 * The damped solver (solver.newton: damped) still takes the solve's turn: on this pair it spins
 * by 3.4e7 rad and does not converge in 1e5 iterations (docs/limits.md); not tested here. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "scene_fixture.h"
#include "gembem/run.h"
#include "solver/global_impl.h"

static const double KN = 1e8, KT = 7e7, KR = 2e6, ETA = 0.2, D = 1e-3, R = 1;

static gb_pair *pair_of(gb_sim *sim, int i, int j)
{
    for (int k = 0; k < sim->state.pairs.n; k++)
        if (sim->state.pairs.p[k].i == i && sim->state.pairs.p[k].j == j) return &sim->state.pairs.p[k];
    return NULL;
}

/* Two discs at (0, 0) and (2R - D, 0) overlapping each other and the walls beside them by D. */
static gb_sim *pair_in_box(gb_scene *s, gb_grain *g, gb_contact_init *ci)
{
    g[0] = (gb_grain){0, 0, R, 0}, g[1] = (gb_grain){2 * R - D, 0, R, 0};
    gb_box box = {-(R - D), 3 * R - 2 * D, -(R - D), R - D};
    *s = fixture_scene(g, 2, box, KN, KT, 30);
    s->grain_wall.friction_deg = 0; /* the walls' contacts slide at no force */
    s->grain_grain.kr = KR, s->grain_grain.eta = ETA;
    /* the pair's contact: no tangential force, its rolling moment at the limit (pn = kn D, R* = R/2) */
    *ci = (gb_contact_init){0, 1, 0, ETA * 0.5 * R * KN * D};
    s->restart.contacts = ci, s->restart.n_contacts = 1;
    s->solver.method = GB_METHOD_GLOBAL;
    s->solver.linear = GB_LINEAR_UMFPACK;
    s->solver.newton = GB_NEWTON_LINE_SEARCH;
    s->solver.accuracy = 1e-3; /* dyn, against contact forces of 1e5 */
    gb_error err;
    gb_sim *sim = NULL;
    CHECK(gb_sim_create(s, &sim, &err) == GB_OK);
    if (!sim) {
        fprintf(stderr, "%s\n", err.msg);
        return NULL;
    }
    gb_gem_forces(sim);
    return sim;
}

static void newton_step(void)
{
    gb_scene s;
    gb_grain g[2];
    gb_contact_init ci;
    gb_sim *sim = pair_in_box(&s, g, &ci);
    if (!sim) return;
    CHECK(sim->scratch.nc[0] == 4 && sim->scratch.nc[1] == 4); /* three walls and each other */
    gb_pair *p = pair_of(sim, 0, 1);
    CHECK(p && p->pt == 0 && p->mr > 0);
    gb_error err;
    gb_wall_control wc = {GB_WALLS_FIXED, 0, 0, 0};
    unsigned char in_system[2] = {GB_IN_SYSTEM, GB_IN_SYSTEM};
    CHECK(gb_global_moves(sim->solver->global, sim, in_system, &wc, 0, &err) == GB_OK);
    const double *dX = sim->scratch.dX;
    printf("Newton step on the rolling pair: turns %.6g and %.6g rad, moves %.3g %.3g %.3g %.3g\n", dX[2] / R,
           dX[5] / R, dX[0], dX[1], dX[3], dX[4]);
    /* held: no turn (the solve's was 1.4e6 rad; the bound is 10 max_move = 1 rad), no move */
    CHECK(dX[2] == 0 && dX[5] == 0);
    for (int q = 0; q < 2; q++) CHECK(fabs(dX[q]) < 1e-9 * R && fabs(dX[3 + q]) < 1e-9 * R);
    gb_sim_free(sim);
}

static void relaxed(void)
{
    gb_scene s;
    gb_grain g[2];
    gb_contact_init ci;
    gb_sim *sim = pair_in_box(&s, g, &ci);
    if (!sim) return;
    double limit = ci.mr, w = limit / (2 * KR);
    gb_error err;
    gb_wall_control wc = {GB_WALLS_FIXED, 0, 0, 0};
    gb_solve_result r;
    gb_status st = gb_solver_relax(sim, &wc, 100000, &r, &err);
    long it = r.iterations;
    double mf = r.max_force;
    CHECK(st == GB_OK);
    if (st) fprintf(stderr, "%s\n", err.msg);
    gb_pair *p = pair_of(sim, 0, 1);
    printf("rolling pair relaxed: %ld iterations, largest force %.3g, turns %.10g %.10g (analytic +-%.10g), "
           "mr %.3g pt %.3g\n", it, mf, sim->state.g[0].rot, sim->state.g[1].rot, w, p->mr, p->pt);
    CHECK_NEAR(fabs(sim->state.g[0].rot), w, 1e-3 * w);
    CHECK_NEAR(sim->state.g[0].rot + sim->state.g[1].rot, 0, 1e-3 * w);
    CHECK_NEAR(p->mr, 0, 1e-3 * limit);
    CHECK_NEAR(p->pt, 0, 1e-3 * KN * D);
    for (int i = 0; i < 2; i++) {
        CHECK_NEAR(sim->state.g[i].x, g[i].x, 1e-6 * R);
        CHECK_NEAR(sim->state.g[i].y, g[i].y, 1e-6 * R);
    }
    gb_sim_free(sim);
}

int main(void)
{
    newton_step();
    relaxed();
    TEST_END();
}
