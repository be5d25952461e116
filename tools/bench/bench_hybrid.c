/* Benchmark of the hybrid solver (not a test): a grains-in-cavity scene relaxed to equilibrium.
 *   bench_hybrid SCENE.yaml [umfpack|cholmod]
 * Prints one Markdown row: grains, cavity elements, host set-up seconds (meshing, assembly and
 * condensation), iterations, seconds per iteration, and the split of the solve into assembly,
 * analysis, factorisation, solution and the rest (contacts, moves, host forces). */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <string.h>
#include "bench_clock.h"

#include "gembem/gembem.h"


int main(int argc, char **argv)
{
    if (argc < 2) return fprintf(stderr, "usage: %s SCENE.yaml [umfpack|cholmod]\n", argv[0]), 2;
    gb_error err = {0};
    gb_scene sc;
    gb_sim *sim = NULL;
    if (gb_scene_load(argv[1], &sc, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
    if (argc > 2) sc.solver.linear = !strcmp(argv[2], "cholmod") ? GB_LINEAR_CHOLMOD : GB_LINEAR_UMFPACK;
    double t0 = bench_now();
    if (gb_sim_create(&sc, &sim, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
    double t_host = bench_now() - t0;
    t0 = bench_now();
    gb_solve_result res;
    gb_wall_control wc = {GB_WALLS_FIXED, 0, 0, 0};
    gb_status st = gb_solver_relax(sim, &wc, sc.solver.max_iterations, &res, &err);
    long it = res.iterations;
    double t_run = bench_now() - t0;
    const gb_global_stats *g = gb_solver_statistics(sim);
    double rest = t_run - g->assemble - g->analyse - g->factorise - g->solve;
    printf("| %s | %d | %d | %.2f | %ld%s | %.4f | %.3f | %.3f (%ld) | %.3f (%ld) | %.3f | %.3f | %.2f |\n",
           argc > 2 ? argv[2] : "umfpack", gb_sim_n_grains(sim), gb_sim_host_dofs(sim) / 2, t_host, it, st ? " (not converged)" : "",
           it ? t_run / it : 0, g->assemble, g->analyse, g->analyses, g->factorise, g->factorisations, g->solve,
           rest, t_run);
    gb_sim_free(sim);
    gb_scene_free(&sc);
    return st ? 3 : 0;
}
