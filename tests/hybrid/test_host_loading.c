/* Loading the host: a square host's top pushed down in 3 steps, bottom
 * fixed, sides free, an empty granular zone (one grain in the cavity touching nothing). At every
 * step the coupled solution's cavity displacements equal the boundary element module's own
 * solution with a traction-free cavity (to 1e-9 of the largest), the forces on the top and the
 * bottom balance (1e-8), and the top's force grows in proportion to its displacement (1e-9). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "gem/sim.h"
#include "gembem/run.h"

static double first_force;

static gb_status check(void *user, const gb_sim *sim, const gb_step_report *r, gb_error *err)
{
    (void)user;
    if (r->step == 0) return GB_OK;
    gb_host *h = sim->host;
    /* The module alone: the same body, cavity traction-free, top displaced as far. */
    gb_bem_problem pr = gb_host_problem(h, &sim->state.host);
    pr.bc[h->cavity].kind = GB_BEM_BC_FREE;
    gb_bem_solution sol;
    memset(&sol, 0, sizeof sol);
    gb_status st = gb_bem_solve(&h->mesh, &h->sys, &pr, NULL, &sol, err);
    if (st) return st;
    double umax = 0, diff = 0;
    for (int k = 0; k < h->m / 2; k++) {
        int e = h->K.elem[k];
        for (int c = 0; c < 2; c++) {
            umax = fmax(umax, fabs(sol.u[2 * e + c]));
            diff = fmax(diff, fabs(sol.u[2 * e + c] - sim->state.host.u[2 * k + c]));
        }
    }
    gb_bem_solution_free(&sol);
    double ft[2], fb[2], dt[2], db[2];
    if ((st = gb_host_group_force(h, &sim->state.host, "top", ft, dt, err)) ||
        (st = gb_host_group_force(h, &sim->state.host, "bottom", fb, db, err)))
        return st;
    if (r->step == 1) first_force = ft[1];
    printf("step %d: top at %.4g cm carries %.6g kgf, bottom %.6g kgf; cavity moves %.4g cm, coupled - alone %.3g\n",
           r->step, dt[1], ft[1], fb[1], umax, diff);
    CHECK(umax > 1e-6);
    CHECK(diff <= 1e-9 * umax);
    CHECK(fabs(ft[1]) > 1);
    CHECK_NEAR(ft[1] + fb[1], 0, 1e-8 * fabs(ft[1]));
    CHECK_NEAR(ft[1], r->step * first_force, 1e-9 * fabs(ft[1]));
    return GB_OK;
}

int main(void)
{
    gb_error err = {0};
    gb_scene sc;
    gb_sim *sim = NULL;
    if (gb_scene_load("tests/hybrid/host_loading.yaml", &sc, &err) || gb_sim_create(&sc, &sim, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    gb_status st = gb_sim_run(sim, NULL, check, NULL, &err);
    if (st) fprintf(stderr, "%s\n", err.msg);
    CHECK(st == GB_OK);
    gb_sim_free(sim);
    gb_scene_free(&sc);
    TEST_END();
}
