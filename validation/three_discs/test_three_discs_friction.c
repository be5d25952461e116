/* Validation A with friction (Kishino 1989, section 3 (3), Fig. 7): phi = 25 deg between discs and
 * phi' = 0, 5, 10, 15 deg against the walls. Checks that each curve has its knee where the two
 * bottom discs separate (the stress ratio peaks there) and that the peak ratio grows with phi'.
 *   test_three_discs_friction SCENE_0 SCENE_5 SCENE_10 SCENE_15 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "gembem/run.h"

typedef struct {
    double peak;
    int peak_step;
    int separation_step; /* first shear step without the bottom discs' contact (0-1) */
    int last_step;
} curve;

static gb_status watch(void *user, const gb_sim *sim, const gb_step_report *r, gb_error *err)
{
    (void)err;
    curve *c = user;
    if (r->stage != 1) return GB_OK;
    if (r->stress_ratio > c->peak) {
        c->peak = r->stress_ratio;
        c->peak_step = r->step;
    }
    gb_contact buf[16];
    int n = gb_sim_contacts(sim, buf, 16), bottom_pair = 0;
    for (int k = 0; k < n && k < 16; k++) bottom_pair |= buf[k].i == 0 && buf[k].j == 1;
    if (!bottom_pair && !c->separation_step) c->separation_step = r->step;
    c->last_step = r->step;
    return GB_OK;
}

int main(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: %s SCENE_0 SCENE_5 SCENE_10 SCENE_15\n", argv[0]);
        return 2;
    }
    double prev_peak = 0;
    for (int k = 1; k < 5; k++) {
        gb_error err = {0};
        gb_scene scene;
        gb_sim *sim = NULL;
        if (gb_scene_load(argv[k], &scene, &err) || gb_sim_create(&scene, &sim, &err)) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
        curve c = {-1, 0, 0, 0};
        gb_status st = gb_sim_run(sim, NULL, watch, &c, &err);
        if (st) fprintf(stderr, "%s\n", err.msg);
        CHECK(st == GB_OK);
        printf("%s: peak ratio %.4f at step %d, bottom discs separate at step %d\n", argv[k], c.peak, c.peak_step,
               c.separation_step);
        /* The knee: the peak lies inside the shear, at the step where the bottom discs separate. */
        CHECK(c.separation_step > 0);
        CHECK(c.peak_step < c.last_step);
        CHECK(abs(c.peak_step - c.separation_step) <= 1);
        CHECK(c.peak > prev_peak + 0.01);
        prev_peak = c.peak;
        gb_sim_free(sim);
        gb_scene_free(&scene);
    }
    TEST_END();
}
