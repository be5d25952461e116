/* A run of a loading program through the public API (gembem/run.h), on Kishino's (1989) three
 * discs, case 1 (validation/three_discs/case1.yaml: 10 isotropic steps, then 100 shear steps, 110 in
 * all, counted from the file; frictionless):
 *  - gb_sim_run takes the whole program each time it is called: twice on one simulation, steps 0 to
 *    110 twice, the second from the first's end state;
 *  - gb_run_advance takes the same steps one call at a time as gb_run_program, to the same grains,
 *    with gb_run_where and gb_run_finished telling where it stands, and refuses a step past the last;
 *  - the run's external work: frictionless discs dissipate nothing, so the walls' quasi-static work
 *    (the trapezoid rule over the converged steps) is the springs' energy gained since the start,
 *    to within the accuracy (1 %). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "gembem/run.h"

enum { STEPS = 110 };

typedef struct {
    int calls, next;   /* the step expected next */
} counter;

static gb_status count_step(void *user, const gb_sim *sim, const gb_step_report *r, gb_error *err)
{
    (void)sim, (void)err;
    counter *c = user;
    CHECK(r->step == c->next);
    c->next = r->step + 1, c->calls++;
    return GB_OK;
}

static int load(gb_scene *sc, gb_sim **sim)
{
    gb_error err = {0};
    if (gb_scene_load("validation/three_discs/case1.yaml", sc, &err) || gb_sim_create(sc, sim, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 0;
    }
    return 1;
}

/* gb_sim_run twice on one simulation: the whole program each time. */
static void sim_run_twice(void)
{
    gb_scene sc;
    gb_sim *sim;
    if (!load(&sc, &sim)) {
        CHECK(0);
        return;
    }
    gb_error err = {0};
    for (int k = 0; k < 2; k++) {
        counter c = {0, 0};
        CHECK(gb_sim_run(sim, NULL, count_step, &c, &err) == GB_OK);
        CHECK(c.calls == STEPS + 1);
    }
    gb_sim_free(sim);
    gb_scene_free(&sc);
}

/* A whole program and one taken step by step, on two simulations of the same scene. */
static void program_and_steps(void)
{
    gb_scene sa, sb;
    gb_sim *a, *b;
    if (!load(&sa, &a) || !load(&sb, &b)) {
        CHECK(0);
        return;
    }
    gb_error err = {0};
    gb_run *ra, *rb;
    CHECK(gb_run_create(a, &ra, &err) == GB_OK && gb_run_create(b, &rb, &err) == GB_OK);
    CHECK(gb_run_sim(rb) == b);
    double e0 = gb_sim_elastic_energy(a);
    counter c = {0, 0};
    CHECK(gb_run_program(ra, NULL, count_step, &c, &err) == GB_OK);
    CHECK(c.calls == STEPS + 1 && gb_run_finished(ra));

    gb_run_place p = gb_run_where(rb);
    CHECK(p.step == -1 && p.total_steps == STEPS && p.n_stages == 2 && !gb_run_finished(rb));
    gb_step_report rep;
    int calls = 0;
    while (!gb_run_finished(rb)) {
        CHECK(gb_run_advance(rb, NULL, &rep, &err) == GB_OK);
        CHECK(rep.step == calls);
        calls++;
        if (calls > STEPS + 1) break;
    }
    CHECK(calls == STEPS + 1);
    p = gb_run_where(rb);
    CHECK(p.step == STEPS && p.stage == 1 && p.stage_step == 100 && p.stage_steps == 100);
    CHECK(gb_run_advance(rb, NULL, &rep, &err) == GB_EINPUT);
    for (int i = 0; i < 3; i++) {
        gb_grain ga = gb_sim_grain(a, i), gb = gb_sim_grain(b, i);
        CHECK(ga.x == gb.x && ga.y == gb.y && ga.rot == gb.rot);
    }

    gb_work_accounts w = gb_run_work(ra);
    double gained = gb_sim_elastic_energy(a) - e0;
    printf("walls' work %.6g, body %.6g, springs' energy gained %.6g (from %.6g)\n", w.walls, w.body, gained, e0);
    CHECK(w.energy0 == e0 && w.body == 0);
    CHECK(gained > 0 && fabs(w.walls - gained) <= 0.01 * gained);
    gb_run_free(ra), gb_run_free(rb);
    gb_sim_free(a), gb_sim_free(b);
    gb_scene_free(&sa), gb_scene_free(&sb);
}

int main(void)
{
    sim_run_twice();
    program_and_steps();
    TEST_END();
}
