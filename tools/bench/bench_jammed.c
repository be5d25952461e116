/* Benchmark of load steps on jammed random packings (not a test).
 *   bench_jammed SCENE.yaml STEPS reference|cholmod|umfpack|line_search [PREP_CAP (5000)] [ACCURACY]
 * ACCURACY: a in force units, or "target" for the tight accuracy 1e-6 kn r_mean (default: the scene's).
 * The scene's packing is jammed (tools/bench_gem.sh makes it with gb_jam): the grains are first
 * relaxed with the walls fixed by the global solver (CHOLMOD; no iteration if gb_jam's packing is
 * already within a), which leaves it under some isotropic-ish stress s_r; then STEPS load steps
 * of isotropic stress control, each adding 5 % of s_r, are run with the chosen solver. Prints one Markdown row: solver, grains, contacts,
 * preparation iterations and seconds, s_r, iterations per load step, seconds per iteration,
 * nanoseconds per contact and iteration, the load steps' seconds and the process's peak resident
 * memory; on stderr, where the load steps' time went, and with BENCH_PROGRESS=1 a line per iteration
 * (the largest fixing force, the share of Newton's step taken, the seconds so far): a 1e6-disc step
 * runs for an hour. */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include "bench_accuracy.h"
#include "bench_step.h"


static void progress(void *user, const gb_iteration_report *r)
{
    fprintf(stderr, "  iteration %ld of step %d: largest fixing force %.4g, length %g, %.0f s\n", r->iteration, r->step,
            r->max_fixing_force, r->length, bench_now() - *(const double *)user);
}

int main(int argc, char **argv)
{
    if (argc < 4) return fprintf(stderr, "usage: %s SCENE.yaml STEPS reference|cholmod|umfpack|line_search\n", argv[0]), 2;
    int steps = atoi(argv[2]);
    const char *method = argv[3];
    long prep_cap = argc > 4 ? atol(argv[4]) : 5000;
    gb_error err = {0};
    gb_scene sc;
    gb_sim *sim;
    if (gb_scene_load(argv[1], &sc, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
    bench_set_accuracy(&sc, argc > 5 ? argv[5] : NULL);
    sc.solver.method = GB_METHOD_GLOBAL;
    sc.solver.linear = GB_LINEAR_CHOLMOD;
    if (!strcmp(method, "line_search")) {
        /* the line search, preparation included, on the exact (unsymmetric) tangent: UMFPACK */
        sc.solver.linear = GB_LINEAR_UMFPACK;
        sc.solver.newton = GB_NEWTON_LINE_SEARCH;
    }
    if (gb_sim_create(&sc, &sim, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
    gb_wall_control wc = {GB_WALLS_FIXED, 0, 0, 0};
    gb_solve_result res;
    double t0 = bench_now();
    const char *verbose = getenv("BENCH_PROGRESS");
    if (verbose && !strcmp(verbose, "1")) gb_solver_on_iteration(sim, progress, &t0);
    gb_status st = gb_solver_relax(sim, &wc, prep_cap, &res, &err);
    double t_prep = bench_now() - t0;
    long prep = res.iterations;
    if (st) {
        printf("| %s | %d | | preparation not converged in %ld iterations (%.0f s), largest fixing force %g |\n", method,
               gb_sim_n_grains(sim), prep, t_prep, res.max_force);
        gb_sim_free(sim);
        gb_scene_free(&sc);
        return 3;
    }
    double s1, s2;
    gb_sim_stress(sim, &s1, &s2);
    double sr = 0.5 * (s1 + s2);
    /* The solver of the load steps. */
    gb_solver_settings steps_solver = sc.solver;
    if (!strcmp(method, "reference")) steps_solver.method = GB_METHOD_REFERENCE;
    if (!strcmp(method, "umfpack")) steps_solver.linear = GB_LINEAR_UMFPACK;
    if (strcmp(method, "cholmod") && strcmp(method, "line_search") && gb_solver_create(sim, &steps_solver, &err))
        return fprintf(stderr, "%s\n", err.msg), 1;
    /* The load steps' share of the solver's time accounts (the preparation's subtracted). */
    double detect0 = gb_sim_detect_seconds(sim);
    long sweeps0 = gb_solver_work_done(sim).sweeps;
    gb_global_stats g0 = {0};
    if (gb_solver_statistics(sim)) g0 = *gb_solver_statistics(sim);
    bench_totals load = {0, 0, 0, gb_sim_contacts(sim, NULL, 0)};
    int done = 0;
    double mf, wr;
    for (int k = 1; k <= steps; k++) {
        wc.mode = GB_WALLS_STRESS;
        wc.s1 = wc.s2 = sr * (1 + 0.05 * k);
        st = bench_load_step(sim, &wc, sc.solver.max_iterations, &load, &mf, &wr, &err);
        if (st) {
            fprintf(stderr, "  %s %d, load step %d: %s\n", method, gb_sim_n_grains(sim), k, err.msg);
            break;
        }
        done++;
    }
    double contact_its = load.contact_iterations, t_steps = load.seconds;
    long it = load.iterations;
    int contacts = load.contacts;
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    printf("| %s | %d | %d | %ld (%.1f s) | %.3g | %.3g | %s%.0f | %.3e | %.1f | %.3g | %.0f |\n", method, gb_sim_n_grains(sim), contacts,
           prep, t_prep, sr, sc.solver.accuracy, done < steps ? "not converged after " : "",
           done < steps ? (double)it : (double)it / steps, t_steps / (it ? it : 1),
           1e9 * t_steps / (contact_its ? contact_its : 1), t_steps, ru.ru_maxrss / 1024.0);
    double detect = gb_sim_detect_seconds(sim) - detect0;
    const gb_global_stats *g = gb_solver_statistics(sim);
    if (g) {
        double as = g->assemble - g0.assemble, an = g->analyse - g0.analyse, fa = g->factorise - g0.factorise,
               so = g->solve - g0.solve;
        fprintf(stderr, "  %s %d, load steps: contact detection %.2f s, assembly %.2f s, %ld analyses %.2f s, "
                "%ld factorisations %.2f s, solves %.2f s, the rest (forces, contact update, moves) %.2f s; %ld moves, "
                "%ld corrections, %ld systems by CG (%ld steps), %ld regularised, %ld smoother steps\n", method, gb_sim_n_grains(sim), detect, as,
                g->analyses - g0.analyses, an, g->factorisations - g0.factorisations, fa, so,
                t_steps - detect - as - an - fa - so, g->moves - g0.moves, g->corrections - g0.corrections,
                g->pcg_solves - g0.pcg_solves, g->pcg_steps - g0.pcg_steps, g->regularised - g0.regularised, gb_solver_work_done(sim).sweeps - sweeps0);
    } else {
        fprintf(stderr, "  %s %d, load steps: contact detection %.2f s, the rest (forces, moves, contact update) %.2f s\n",
                method, gb_sim_n_grains(sim), detect, t_steps - detect);
    }
    gb_sim_free(sim);
    gb_scene_free(&sc);
    return 0;
}
