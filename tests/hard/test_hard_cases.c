/* Hard cases for both granular solvers (reference iteration, global CHOLMOD, global UMFPACK, and
 * the global solver's line search, solver.newton: line_search): each
 * either converges to the right answer or stops with a clear non-convergence status; never a
 * hang (every run is capped), never NaN.
 *  - three discs with kn from 1e6 to 1e12 dyn/cm at the same loading (s0 = 1.5e5 dyn/cm);
 *  - an initial overlap of 50 % of the smaller radius;
 *  - grains of size ratio 10;
 *  - rattlers (no contact) and a grain with a single contact under gravity;
 *  - kt = 0 (rotations without stiffness, case d): three discs give Table 2's frictionless answer;
 *  - friction angle 89 deg;
 *  - a load step far too large (d(e1 - e2) = 20 % in one step);
 *  - a row of grains on a frictionless floor, held by nothing sideways. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../unit/scene_fixture.h"
#include "check.h"
#include "gembem/run.h"

enum { N_SOLVERS = 4 };
static const char *const SOLVERS[N_SOLVERS] = {"reference", "global CHOLMOD", "global UMFPACK",
                                             "global line search"};

typedef struct {
    double last_ratio;
    int finite;
    double max_force;
} outcome;

static gb_status watch(void *user, const gb_sim *sim, const gb_step_report *r, gb_error *err)
{
    (void)err;
    outcome *o = user;
    o->last_ratio = r->stress_ratio;
    o->max_force = r->max_fixing_force;
    o->finite &= isfinite(r->s1) && isfinite(r->s2) && isfinite(r->stress_ratio) && isfinite(r->e1);
    for (int i = 0; i < gb_sim_n_grains(sim); i++) {
        gb_grain g = gb_sim_grain(sim, i);
        o->finite &= isfinite(g.x) && isfinite(g.y) && isfinite(g.rot);
    }
    return GB_OK;
}

/* Runs the scene with one solver; returns the status (GB_OK or GB_ENOCONV expected). */
static gb_status run(gb_scene *s, int solver, outcome *o, const char *name)
{
    s->solver.method = solver ? GB_METHOD_GLOBAL : GB_METHOD_REFERENCE;
    s->solver.linear = solver >= 2;
    s->solver.newton = solver == 3 ? GB_NEWTON_LINE_SEARCH : GB_NEWTON_DAMPED;
    gb_error err = {0};
    gb_sim *sim = NULL;
    memset(o, 0, sizeof *o);
    o->finite = 1;
    gb_status st = gb_sim_create(s, &sim, &err);
    if (!st) st = gb_sim_run(sim, NULL, watch, o, &err);
    printf("%-28s %-18s: %s%s%s\n", name, SOLVERS[solver], st ? "stopped: " : "converged", st ? err.msg : "",
           o->finite ? "" : " NON-FINITE");
    CHECK(st == GB_OK || st == GB_ENOCONV);
    if (st == GB_ENOCONV) CHECK(strstr(err.msg, "did not converge") != NULL || strstr(err.msg, "stalled") != NULL);
    CHECK(o->finite);
    if (st == GB_OK) CHECK(o->max_force <= s->solver.accuracy);
    gb_sim_free(sim);
    return st;
}

static gb_grain THREE[3] = {{1, 1, 1, 0}, {3, 1, 1, 0}, {2, 2.7320508075688772, 1, 0}};

static gb_scene three_discs(double kn, double kt, double phi, gb_stage *stages)
{
    gb_box box = {0, 4, 0, 3.7320508075688772};
    gb_scene s = fixture_scene(THREE, 3, box, kn, kt, phi);
    s.grain_wall.friction_deg = phi > 0 ? phi : 0;
    s.solver.accuracy = 100;
    s.solver.max_iterations = 200000;
    gb_stage iso = {.kind = GB_STAGE_ISOTROPIC, .steps = 10, .stress = 1.5e5};
    gb_stage shear = {.kind = GB_STAGE_SHEAR_MEAN, .steps = 40, .d_shear = 0.0005, .mean_stress = 1.5e5, .reset_strain = 1};
    stages[0] = iso, stages[1] = shear;
    s.stages = stages;
    s.n_stages = 2;
    return s;
}

/* Grains under their weight between fixed walls (frictionless; a strain stage of no strain, `steps`
 * steps, in *hold), to the accuracy a. */
static gb_scene under_weight(gb_grain *g, int n, gb_box box, double phi, double a, int steps, gb_stage *hold)
{
    gb_scene s = fixture_scene(g, n, box, 1e8, 7e7, phi);
    s.grain_wall.friction_deg = 0;
    s.body_force_per_area[1] = -1500;
    s.solver.accuracy = a;
    s.solver.max_iterations = 300000;
    gb_stage strain = {.kind = GB_STAGE_STRAIN, .steps = steps, .de1 = 0, .de2 = 0};
    *hold = strain;
    s.stages = hold;
    s.n_stages = 1;
    return s;
}

int main(void)
{
    gb_stage st2[2];
    outcome o;
    char name[64];
    for (int solver = 0; solver < N_SOLVERS; solver++) {
        /* kn over six decades at the same loading: 1e6 makes overlaps of about 40 % of r. */
        for (double kn = 1e6; kn <= 1e12; kn *= 100) {
            gb_scene s = three_discs(kn, 0.7 * kn, 0, st2);
            s.solver.max_iterations = 20000;
            snprintf(name, sizeof name, "three discs, kn = %.0e", kn);
            run(&s, solver, &o, name);
        }
        /* kt = 0: rotations carry no stiffness (case d); frictionless walls make the answer the
         * same as with kt: Table 2 case 1 at 2 % shear (step 50 of 50 here is 2 %). */
        {
            gb_scene s = three_discs(1e8, 0, 0, st2);
            if (run(&s, solver, &o, "three discs, kt = 0") == GB_OK) CHECK_NEAR(o.last_ratio, 0.5079, 0.0010);
        }
        {
            gb_scene s = three_discs(1e8, 7e7, 89, st2);
            run(&s, solver, &o, "three discs, friction 89 deg");
        }
        {   /* One shear step of 20 %: far beyond what the contact update can follow smoothly. */
            gb_scene s = three_discs(1e8, 7e7, 25, st2);
            s.stages[1].d_shear = 0.2;
            s.stages[1].steps = 1;
            s.solver.max_iterations = 50000;
            run(&s, solver, &o, "three discs, one 20 % step");
        }
        {   /* Two discs overlapping by half the smaller radius, a big one of radius 10 x the small
             * ones, a rattler with no contact and one grain with a single contact, under gravity. */
            gb_grain g[6] = {{5.0, 1.0, 1.0, 0}, {6.5, 1.0, 1.0, 0}, /* overlap 0.5 */
                             {12.0, 10.0, 10.0, 0},                  /* size ratio 10 */
                             {3.0, 15.0, 1.0, 0},                    /* rattler, falls */
                             {1.0, 1.0, 1.0, 0},                     /* one contact: the floor */
                             {5.75, 2.4, 0.5, 0}};
            gb_box box = {0, 22, 0, 25};
            gb_stage hold;
            gb_scene s = under_weight(g, 6, box, 25, 100, 2, &hold);
            run(&s, solver, &o, "overlap 50 %, ratio 10, rattler");
        }
        {   /* Three touching grains on a frictionless floor, far from the side walls, pressed into
             * each other and into the floor: nothing holds the row horizontally (a free rigid mode
             * of K): the system must still be solved, without a zero pivot or a NaN. */
            gb_grain g[3] = {{8.0, 0.999, 1.0, 0}, {9.99, 0.999, 1.0, 0}, {11.98, 0.999, 1.0, 0}};
            gb_box box = {0, 20, 0, 25};
            gb_stage hold;
            gb_scene s = under_weight(g, 3, box, 0, 1, 1, &hold);
            if (run(&s, solver, &o, "row held by nothing sideways") == GB_OK) CHECK(o.finite);
        }
    }
    TEST_END();
}
