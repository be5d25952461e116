/* Benchmark of the reference iteration (not a test): cost per iteration and iterations per load
 * step under isotropic stress control.
 *   bench_gem SCENE.yaml S0 PREP_CAP [STEPS [reference|cholmod|umfpack]]
 * The scene gives grains, box, materials and solver settings (its loading program is ignored).
 * Preparation: stress control at S0/2 from the scene's packing, at most PREP_CAP iterations.
 * Then STEPS (default 4) load steps of isotropic stress control from S0/2 to S0.
 * Prints one Markdown row: N, contacts, preparation iterations (converged or not), mean iterations
 * per load step, seconds per iteration and nanoseconds per contact and iteration. */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "bench_step.h"


int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: %s SCENE.yaml S0 PREP_CAP [STEPS]\n", argv[0]);
        return 2;
    }
    double s0 = atof(argv[2]);
    long prep_cap = atol(argv[3]);
    int steps = argc > 4 ? atoi(argv[4]) : 4;
    const char *method = argc > 5 ? argv[5] : "reference";
    gb_error err = {0};
    gb_scene sc;
    gb_sim *sim;
    if (gb_scene_load(argv[1], &sc, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    sc.solver.method = strcmp(method, "reference") ? GB_METHOD_GLOBAL : GB_METHOD_REFERENCE;
    sc.solver.linear = !strcmp(method, "umfpack") ? GB_LINEAR_UMFPACK : GB_LINEAR_CHOLMOD;
    if (gb_sim_create(&sc, &sim, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    gb_wall_control wc = {GB_WALLS_STRESS, 0.5 * s0, 0.5 * s0, 0};
    gb_solve_result prep;
    double t0 = bench_now();
    gb_status st = gb_solver_relax(sim, &wc, prep_cap, &prep, &err);
    long prep_it = prep.iterations;
    double max_force = prep.max_force, wall = prep.wall_residual;
    double t_prep = bench_now() - t0;
    int contacts = gb_sim_contacts(sim, NULL, 0);
    bench_totals load = {0, 0, (double)prep_it * contacts, contacts}; /* the preparation's contact-iterations too */
    int done = 0;
    if (st == GB_OK) {
        for (int k = 1; k <= steps && st == GB_OK; k++) {
            wc.s1 = wc.s2 = s0 * (0.5 + 0.5 * k / steps);
            st = bench_load_step(sim, &wc, sc.solver.max_iterations, &load, &max_force, &wall, &err);
            done += st == GB_OK;
        }
    }
    double t_steps = load.seconds, contact_iterations = load.contact_iterations;
    long it_total = load.iterations;
    contacts = load.contacts;
    double secs = t_prep + t_steps, iters = (double)(prep_it + it_total);
    const gb_global_stats *g = gb_solver_statistics(sim);
    if (g) {
        fprintf(stderr, "%s: assembly %.2f s, analysis %.2f s (%ld), factorisation %.2f s (%ld), solve %.2f s, "
                        "rest %.2f s; %ld regularised\n", method, g->assemble, g->analyse, g->analyses, g->factorise,
                g->factorisations, g->solve, t_prep + t_steps - g->assemble - g->analyse - g->factorise - g->solve,
                g->regularised);
    }
    printf("| %s | %d | %d | %ld%s (%.1f s) | %s | %.3e | %.1f | %.1f |\n", method, gb_sim_n_grains(sim), contacts, prep_it,
           prep_it >= prep_cap ? ", not converged" : "", t_prep, done ? "" : "not reached", secs / iters,
           1e9 * secs / contact_iterations, secs);
    if (done) {
        /* Re-print with the per-step figure filled in. */
        printf("| %s | %d | %d | %ld (%.1f s) | %.0f over %d steps (%.1f s) | %.3e | %.1f | %.1f |\n", method, gb_sim_n_grains(sim), contacts,
               prep_it, t_prep, (double)it_total / done, done, t_steps, secs / iters, 1e9 * secs / contact_iterations,
               secs);
    }
    gb_sim_free(sim);
    gb_scene_free(&sc);
    return 0;
}
