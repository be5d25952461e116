/* The equilibrium of a deposit under its own weight (not a test; tools/settle_packing.sh makes the
 * scene; docs/limits.md: the global solver does not converge on it).
 *   bench_settle SCENE.yaml reference|cholmod|umfpack|line_search [CAP (1000000)] [ACCURACY]
 * ACCURACY: a in force units, or "target" for 1e-6 kn r_mean (default: the scene's).
 * The scene holds a deposit (gb_packgen: every disc resting on others, no force yet) and a body
 * force; the walls stay fixed and the chosen solver brings the grains to equilibrium. Prints one
 * Markdown row: solver, grains, contacts at the end, iterations, seconds, seconds per iteration,
 * peak resident memory, and the time split: contact detection, assembly, analysis, factorisation,
 * solves, the rest (forces, contact update, moves). Exit status 3 if not converged. */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include "bench_accuracy.h"
#include "bench_clock.h"

#include "gembem/gembem.h"

int main(int argc, char **argv)
{
    if (argc < 3) return fprintf(stderr, "usage: %s SCENE.yaml reference|cholmod|umfpack|line_search [CAP] [ACCURACY]\n", argv[0]), 2;
    const char *method = argv[2];
    long cap = argc > 3 ? atol(argv[3]) : 1000000;
    gb_error err = {0};
    gb_scene sc;
    gb_sim *sim;
    if (gb_scene_load(argv[1], &sc, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
    bench_set_accuracy(&sc, argc > 4 ? argv[4] : NULL);
    sc.solver.method = strcmp(method, "reference") ? GB_METHOD_GLOBAL : GB_METHOD_REFERENCE;
    sc.solver.linear = strcmp(method, "umfpack") ? GB_LINEAR_CHOLMOD : GB_LINEAR_UMFPACK;
    if (!strcmp(method, "line_search")) { /* the default global solver: UMFPACK's exact tangent */
        sc.solver.linear = GB_LINEAR_UMFPACK;
        sc.solver.newton = GB_NEWTON_LINE_SEARCH;
    }
    double t0 = bench_now();
    if (gb_sim_create(&sc, &sim, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
    double t_create = bench_now() - t0;
    gb_wall_control wc = {GB_WALLS_FIXED, 0, 0, 0};
    gb_solve_result res;
    t0 = bench_now();
    gb_status st = gb_solver_relax(sim, &wc, cap, &res, &err);
    long it = res.iterations;
    double t = bench_now() - t0;
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    int contacts = gb_sim_contacts(sim, NULL, 0);
    printf("| %s | %d | %d | %.3g | %s%ld | %.1f | %.3e | %.0f |", method, gb_sim_n_grains(sim), contacts, sc.solver.accuracy,
           st ? "not converged: " : "", it, t, t / (it ? it : 1), ru.ru_maxrss / 1024.0);
    double detect = gb_sim_detect_seconds(sim);
    const gb_global_stats *g = gb_solver_statistics(sim);
    if (g) {
        printf(" %.2f | %.2f | %.2f | %.2f (%ld) | %.2f | %.2f |\n", detect, g->assemble, g->analyse, g->factorise,
               g->factorisations, g->solve, t - detect - g->assemble - g->analyse - g->factorise - g->solve);
    } else {
        printf(" %.2f | | | | | %.2f |\n", detect, t - detect);
    }
    fprintf(stderr, "  %s %d: set-up (pair list) %.2f s, largest fixing force %.3g, status %d; %ld trials, %ld smoother steps\n",
            method, gb_sim_n_grains(sim), t_create, res.max_force, (int)st, res.work.trials, res.work.sweeps);
    gb_sim_free(sim);
    gb_scene_free(&sc);
    return st ? 3 : 0;
}
