/* One iteration of the global solver on a scene's first state, for the linear solvers' costs
 * (docs/scaling.md; not a test): the walls under an isotropic stress 5 % above the packing's, as a
 * load step starts.
 *   [mpirun -np P] bench_linear SCENE.yaml cholmod|umfpack|petsc
 * The scene's solver.petsc section (or PETSC_OPTIONS) chooses PETSc's solver. The iteration's moves (normally one factorisation and solve) are timed; prints one Markdown
 * row: solver, ranks, grains, unknowns, matrix entries (both triangles), CHOLMOD's factor entries
 * and flops (its analysis; MUMPS's are in PETSC_OPTIONS=-ksp_view), factorisations, KSP iterations,
 * seconds of assembly, analysis, factorisation (PETSc: distribution and set-up) and solve, and
 * rank 0's peak resident memory (the workers': /usr/bin/time per rank). With GB_DUMP_FIRST_SOLVE
 * the solution is written, to compare the solvers (tests/petsc). */
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>

#include "gembem/gembem.h"

int main(int argc, char **argv)
{
    int code;
    if (gb_petsc_serve(&code)) return code;
    if (argc < 3) return fprintf(stderr, "usage: %s SCENE.yaml cholmod|umfpack|petsc\n", argv[0]), 2;
    const char *solver = argv[2];
    gb_error err = {0};
    gb_scene sc;
    gb_sim *sim;
    if (gb_scene_load(argv[1], &sc, &err)) return fprintf(stderr, "%s\n", err.msg), 2;
    sc.solver.method = GB_METHOD_GLOBAL;
    sc.solver.linear = !strcmp(solver, "petsc") ? GB_LINEAR_PETSC : !strcmp(solver, "umfpack") ? GB_LINEAR_UMFPACK
                                                                                                   : GB_LINEAR_CHOLMOD;
    if (sc.solver.linear == GB_LINEAR_PETSC && !gb_petsc_available())
        return fprintf(stderr, "this build has no PETSc\n"), 2;
    if (gb_sim_create(&sc, &sim, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
    /* The walls under stress control, 5 % above the packing's mean stress: a load step's first iteration. */
    double s1, s2;
    gb_sim_stress(sim, &s1, &s2);
    gb_wall_control wc = {GB_WALLS_STRESS, 0.525 * (s1 + s2), 0.525 * (s1 + s2), 0};
    gb_solve_result res;
    gb_solver_relax(sim, &wc, 1, &res, &err); /* one iteration: not converged, as expected */
    const gb_global_stats *g = gb_solver_statistics(sim);
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    printf("| %s | %d | %d | %d | %ld | %.4g | %.4g | %ld | %ld | %.3f | %.3f | %.3f | %.3f | %.0f |\n", solver,
           gb_petsc_ranks(), gb_sim_n_grains(sim), g->unknowns, g->entries, g->factor_entries, g->factor_flops, g->factorisations, g->ksp_iterations, g->assemble,
           g->analyse, g->factorise, g->solve, ru.ru_maxrss / 1024.0);
    gb_sim_free(sim);
    gb_scene_free(&sc);
    return 0;
}
