/* The global solver against the reference iteration: the three-disc cases
 * 1-4 run with the reference iteration, the global solver with CHOLMOD and with UMFPACK; the
 * stress ratios agree within 0.0005 at e1 - e2 = 1..5 %. Prints the iterations and seconds of each.
 *   test_three_discs_solvers CASE1.yaml CASE2.yaml ... */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "check.h"
#include "gembem/run.h"

typedef struct {
    double ratio[5];
    long iterations;
} result;

static gb_status collect(void *user, const gb_sim *sim, const gb_step_report *r, gb_error *err)
{
    (void)sim, (void)err;
    result *a = user;
    a->iterations += r->iterations;
    for (int k = 0; k < 5; k++)
        if (r->stage == 1 && fabs(r->e1 - r->e2 - 0.01 * (k + 1)) < 1e-9) a->ratio[k] = r->stress_ratio;
    return GB_OK;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv)
{
    static const char *const names[3] = {"reference", "global CHOLMOD", "global UMFPACK"};
    for (int f = 1; f < argc; f++) {
        result res[3] = {{{0}, 0}, {{0}, 0}, {{0}, 0}};
        for (int m = 0; m < 3; m++) {
            gb_error err = {0};
            gb_scene scene;
            gb_sim *sim = NULL;
            if (gb_scene_load(argv[f], &scene, &err)) {
                fprintf(stderr, "%s\n", err.msg);
                return 1;
            }
            scene.solver.method = m == 0 ? GB_METHOD_REFERENCE : GB_METHOD_GLOBAL;
            scene.solver.linear = m == 2;
            double t0 = now();
            gb_status st = gb_sim_create(&scene, &sim, &err);
            if (!st) st = gb_sim_run(sim, NULL, collect, &res[m], &err);
            if (st) fprintf(stderr, "%s: %s\n", names[m], err.msg);
            CHECK(st == GB_OK);
            printf("%s, %-15s: %6ld iterations, %.4f s; ratios", argv[f], names[m], res[m].iterations, now() - t0);
            for (int k = 0; k < 5; k++) printf(" %.4f", res[m].ratio[k]);
            printf("\n");
            gb_sim_free(sim);
            gb_scene_free(&scene);
        }
        for (int m = 1; m < 3; m++)
            for (int k = 0; k < 5; k++) CHECK_NEAR(res[m].ratio[k], res[0].ratio[k], 0.0005);
    }
    TEST_END();
}
